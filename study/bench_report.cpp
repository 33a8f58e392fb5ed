// `twin bench` as one call: the timings of the twin, printed as tables (study/bench.hpp).
#include <algorithm>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/study.hpp"
#include "study/bench.hpp"
#include "study/bench_accumulation.hpp"
#include "study/hand_ode.hpp"
#include "twin/simulator.hpp"

namespace dtwin {
namespace {

/// A table's head: in Markdown the header `columns` ("| a | b |") and its rule, else `plain`.
void printHead(const TextSink& print, bool markdown, const std::string& columns,
               const std::string& plain) {
  if (!markdown) return print(plain);
  std::string rule = "|";
  const auto bars = std::count(columns.begin(), columns.end(), '|');
  for (long i = 1; i < bars; ++i) rule += "---|";
  print(columns + "\n" + rule + "\n");
}

/// The bump and the rough road of every chosen assembly, as a table.
void assemblyTable(const std::string& study_path, int runs, bool markdown,
                   const std::vector<std::string>& ids, const TextSink& print,
                   const TextSink& note) {
  const Study study = loadStudy(study_path);
  const ScenarioSpec *bump = nullptr, *rough = nullptr;
  for (const auto& s : study.scenarios) {
    if (!bump && s.road->obstacle()) bump = &s;
    if (!rough && s.road->random()) rough = &s;
  }
  std::vector<BenchRow> rows;
  note(formatPrintf("twin bench: %d timed runs per case (after one warm-up), median reported\n",
                    runs));
  for (const auto& a : study.assemblies()) {
    if (!ids.empty() && std::find(ids.begin(), ids.end(), a.id) == ids.end()) continue;
    for (const ScenarioSpec* sc : {bump, rough}) {
      if (!sc) continue;
      rows.push_back(benchAssembly(study, a, *sc, runs, sc == bump));
      const auto& r = rows.back();
      note(formatPrintf("  %s %-6s median %.1f ms\n", r.assembly.c_str(), r.scenario.c_str(),
                        1e3 * r.median_wall_s));
    }
  }
  printHead(
      print, markdown,
      "| assembly | options | scenario | median wall per run [ms] | min..max [ms] | real-time "
      "factor | steps | peak FL force [N] | tight-tolerance peak [N] | peak error |",
      formatPrintf("%-4s %-24s %-6s %10s %16s %8s %7s %10s %10s %8s\n", "id", "options", "scen",
                   "median_ms", "min..max_ms", "RTF", "steps", "peak_N", "ref_N", "err_%"));
  for (const auto& r : rows) {
    const double err = r.reference_peak_fl_N > 0
                           ? 100.0 * (r.peak_fl_N - r.reference_peak_fl_N) / r.reference_peak_fl_N
                           : 0.0;
    char ref[32] = "-", errs[32] = "-";
    if (r.reference_peak_fl_N > 0) {
      std::snprintf(ref, sizeof ref, "%.0f", r.reference_peak_fl_N);
      std::snprintf(errs, sizeof errs, "%+.2f%%", err);
    }
    if (markdown)
      print(formatPrintf("| %s | %s | %s | %.1f | %.1f..%.1f | %.0f | %ld | %.0f | %s | %s |\n",
                         r.assembly.c_str(), r.label.c_str(), r.scenario.c_str(),
                         1e3 * r.median_wall_s, 1e3 * r.min_wall_s, 1e3 * r.max_wall_s,
                         r.real_time_factor, r.steps, r.peak_fl_N, ref, errs));
    else
      print(formatPrintf("%-4s %-24s %-6s %10.1f %7.1f..%-7.1f %8.0f %7ld %10.0f %10s %8s%s\n",
                         r.assembly.c_str(), r.label.c_str(), r.scenario.c_str(),
                         1e3 * r.median_wall_s, 1e3 * r.min_wall_s, 1e3 * r.max_wall_s,
                         r.real_time_factor, r.steps, r.peak_fl_N, ref, errs,
                         r.ok ? "" : "  FAILED"));
  }
}

/// `--hand-ode`: the Simbody twin against the hand-written 7-DOF ODE on the study's bump
/// (study/hand_ode.hpp), both integrated by ROS34PW2 at the study's accuracy.
void handOdeTable(const std::string& study_path, int runs, bool markdown,
                  std::vector<std::string> ids, const TextSink& print, const TextSink& note) {
  const Study study = loadStudy(study_path);
  const ScenarioSpec* bump = nullptr;
  for (const auto& s : study.scenarios)
    if (!bump && s.road->obstacle()) bump = &s;
  if (!bump)
    throw InputError(study_path,
                     "twin bench --hand-ode needs a scenario with an obstacle (a bump)");
  if (ids.empty()) ids = {"M3"};
  for (const auto& id : ids) {
    std::fprintf(stderr,
                 "twin bench --hand-ode: %s on '%s', %d timed runs each (after one warm-up), "
                 "median reported\n",
                 id.c_str(), bump->name.c_str(), runs);
    const HandOdeBench r = benchHandOde(study, study.assembly(id), *bump, runs);
    struct Row {
      const char* name;
      double med, lo, hi;
      long steps, attempts, evals, jacs;
    };
    const Row rows[] = {
        {"Simbody twin", r.simbody_median_s, r.simbody_min_s, r.simbody_max_s, r.simbody_steps,
         r.simbody_attempts, r.simbody_evaluations, r.simbody_jacobians},
        {"Simbody twin, output at 0.1 Hz", r.simbody_integration_s, -1, -1, r.simbody_steps,
         r.simbody_attempts, r.simbody_evaluations, r.simbody_jacobians},
        {"hand-written 7-DOF ODE", r.hand_median_s, r.hand_min_s, r.hand_max_s, r.hand_steps,
         r.hand_attempts, r.hand_evaluations, r.hand_jacobians},
        {"hand ODE, output at 0.1 Hz", r.hand_integration_s, -1, -1, r.hand_steps, r.hand_attempts,
         r.hand_evaluations, r.hand_jacobians}};
    print(formatPrintf(
        markdown ? "%s (%s) on '%s', ROS34PW2 at accuracy %g, %d runs each (median)\n\n"
                 : "%s (%s) on '%s', ROS34PW2 at accuracy %g, %d runs each (median)\n",
        r.assembly.c_str(), r.label.c_str(), r.scenario.c_str(), r.accuracy, r.runs));
    printHead(print, markdown,
              "| model | median wall per run [ms] | min..max [ms] | steps | rejected | f "
              "evaluations | Jacobians | wall per evaluation [us] |",
              formatPrintf("%-31s %10s %16s %7s %8s %7s %5s %9s\n", "model", "median_ms",
                           "min..max_ms", "steps", "rejected", "evals", "jacs", "us/eval"));
    for (const Row& w : rows) {
      char range[48] = "-";
      if (w.lo >= 0) std::snprintf(range, sizeof range, "%.1f..%.1f", 1e3 * w.lo, 1e3 * w.hi);
      const double per = 1e6 * w.med / static_cast<double>(w.evals);
      if (markdown)
        print(formatPrintf("| %s | %.2f | %s | %ld | %ld | %ld | %ld | %.2f |\n", w.name,
                           1e3 * w.med, range, w.steps, w.attempts - w.steps, w.evals, w.jacs,
                           per));
      else
        print(formatPrintf("%-31s %10.2f %16s %7ld %8ld %7ld %5ld %9.2f\n", w.name, 1e3 * w.med,
                           range, w.steps, w.attempts - w.steps, w.evals, w.jacs, per));
    }
    if (markdown) print(formatPrintf("\n"));
    print(formatPrintf(
        "ratio Simbody / hand ODE: %.1fx (target: <= 3x); with the output at 0.1 Hz: %.1fx\n",
        r.ratio(), r.simbody_integration_s / r.hand_integration_s));
    print(formatPrintf("one hand right-hand side alone: %.2f us\n", 1e6 * r.hand_rhs_s));
    print(formatPrintf(
        "front-left hub force: peak %.0f N; max |Simbody - hand| %.2g N (%.2g %% of the peak) at t "
        "= %.3f s; "
        "both at accuracy 1e-8: %.2g N (%.2g %%)\n",
        r.peak_fl_N, r.max_diff_fl_N, 100 * r.max_diff_fl_N / r.peak_fl_N, r.max_diff_time_s,
        r.tight_max_diff_fl_N, 100 * r.tight_max_diff_fl_N / r.peak_fl_N));
  }
}

/// `--accumulation`: the measured costs of a synthesis and its modelled wall time on K ranks.
void accumulationTable(const std::string& study_path, int runs, double link_gb,
                       const std::vector<std::string>& ids, const TextSink& print,
                       const TextSink& note) {
  const Study study = loadStudy(study_path);
  const AssemblySpec a = ids.empty() ? study.assemblies().front() : study.assembly(ids.front());
  note(formatPrintf(
      "twin bench --accumulation: %s, %d timed draws (after one warm-up), median reported\n",
      a.id.c_str(), runs));
  const AccumulationBench r = benchAccumulation(study, a, runs, link_gb);
  const AccumulationCosts& c = r.costs;
  print(formatPrintf(
      "%s (%s): %ld draws x %ld roads, blocks of %ld draws, leaves of %ld blocks (%ld leaves), "
      "vectors of %d samples\n",
      r.assembly.c_str(), r.label.c_str(), c.draws, c.roads, c.block, c.leaf_blocks, c.leaves,
      c.p));
  print(formatPrintf(
      "measured on one core: a draw (%ld runs) %.3f s; addBlock %.2f ms per vector; merge of two "
      "nodes %.1f ms; "
      "node to doubles %.1f ms, back %.1f ms, to a file %.1f ms (%.0f MB); assumed link %.0f "
      "GB/s\n",
      c.roads, c.draw_s, 1e3 * c.add_per_vector_s, 1e3 * c.merge_s, 1e3 * c.pack_s,
      1e3 * c.unpack_s, 1e3 * c.save_s, c.node_bytes / 1e6, c.link_bytes_per_s / 1e9));
  print(formatPrintf("%6s %7s %12s %9s %11s %14s %22s\n", "ranks", "rounds", "wall_s", "speed-up",
                     "efficiency", "of it combine", "every rank adds all [s]"));
  for (const ScalingRow& w : r.rows)
    print(formatPrintf("%6d %7ld %12.1f %9.1f %11.2f %14.1f %22.1f\n", w.ranks, w.rounds, w.wall_s,
                       w.speedup, w.efficiency, w.combine_s, w.ordered_wall_s));
}

}  // namespace

void runBench(const BenchRequest& request, const TextSink& print, const TextSink& note) {
  if (request.import_rows > 0) {
    const BenchImport r = benchImport(request.study, request.import_rows, request.runs);
    print(
        formatPrintf("twin import: %ld rows (%.1f MB), %d runs: median %.2f s (%.2f..%.2f s), %.0f "
                     "rows/s\n",
                     r.rows, r.bytes / 1e6, request.runs, r.median_s, r.min_s, r.max_s,
                     static_cast<double>(r.rows) / r.median_s));
    print(
        formatPrintf("twin import, MF4: %ld rows (%.1f MB), %d runs: median %.2f s (%.2f..%.2f s), "
                     "%.0f rows/s\n",
                     r.rows, r.mf4_bytes / 1e6, request.runs, r.mf4_median_s, r.mf4_min_s,
                     r.mf4_max_s, static_cast<double>(r.rows) / r.mf4_median_s));
    print(
        formatPrintf("twin import, MF4 with DZ blocks: %ld rows (%.1f MB), %d runs: median %.2f s "
                     "(%.2f..%.2f s), %.0f rows/s\n",
                     r.rows, r.mf4z_bytes / 1e6, request.runs, r.mf4z_median_s, r.mf4z_min_s,
                     r.mf4z_max_s, static_cast<double>(r.rows) / r.mf4z_median_s));
    return;
  }
  if (request.user_effect > 0) {
    const Study study = loadStudy(request.study);
    const BenchUserEffect r =
        benchUserEffect(study, request.scenario, request.user_effect, request.runs);
    print(formatPrintf(
        "strut force, %ld evaluations, %d runs (median): built-in damper_asymmetry %.1f "
        "ns, user-defined \"v < 0 ? (ratio - 1) * c * v : 0\" %.1f ns "
        "(%.1fx); largest difference %.3g N\n",
        r.evaluations, request.runs, r.builtin_ns, r.user_ns, r.user_ns / r.builtin_ns,
        r.max_abs_difference));
    print(formatPrintf(
        "whole runs of %s on '%s' (%ld steps), %d runs each (median): built-in %.3f s, "
        "user-defined %.3f s (%.2fx); traces %s\n",
        study.assemblies().front().id.c_str(), r.scenario.c_str(), r.steps, request.runs,
        r.builtin_run_s, r.user_run_s, r.user_run_s / r.builtin_run_s,
        r.identical_traces ? "identical" : "DIFFER"));
    return;
  }
  if (request.accumulation)
    return accumulationTable(request.study, request.runs, request.link_gb_per_s, request.assemblies,
                             print, note);
  if (request.hand_ode)
    return handOdeTable(request.study, request.runs, request.markdown, request.assemblies, print,
                        note);
  assemblyTable(request.study, request.runs, request.markdown, request.assemblies, print, note);
}

}  // namespace dtwin
