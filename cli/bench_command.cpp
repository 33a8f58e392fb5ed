#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "twin/bench.hpp"
#include "twin/provenance.hpp"
#include "twin/simulator.hpp"
#include "twin/study.hpp"

namespace fs = std::filesystem;

namespace dtwin::cli {
namespace {

int runBench(const std::string& study_path, int runs, bool markdown, const std::vector<std::string>& ids) {
  const Study study = loadStudy(study_path);
  const ScenarioSpec *bump = nullptr, *rough = nullptr;
  for (const auto& s : study.scenarios) {
    if (!bump && s.road->obstacle()) bump = &s;
    if (!rough && s.road->random()) rough = &s;
  }
  std::vector<BenchRow> rows;
  std::fprintf(stderr, "twin bench: %d timed runs per case (after one warm-up), median reported\n", runs);
  for (const auto& a : study.assemblies()) {
    if (!ids.empty() && std::find(ids.begin(), ids.end(), a.id) == ids.end()) continue;
    for (const ScenarioSpec* sc : {bump, rough}) {
      if (!sc) continue;
      rows.push_back(benchAssembly(study, a, *sc, runs, sc == bump));
      const auto& r = rows.back();
      std::fprintf(stderr, "  %s %-6s median %.1f ms\n", r.assembly.c_str(), r.scenario.c_str(), 1e3 * r.median_wall_s);
    }
  }
  if (markdown) {
    std::printf("| assembly | options | scenario | median wall per run [ms] | min..max [ms] | real-time factor | steps | peak FL force [N] | tight-tolerance peak [N] | peak error |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  } else {
    std::printf("%-4s %-24s %-6s %10s %16s %8s %7s %10s %10s %8s\n", "id", "options", "scen", "median_ms", "min..max_ms", "RTF",
                "steps", "peak_N", "ref_N", "err_%");
  }
  for (const auto& r : rows) {
    const double err = r.reference_peak_fl_N > 0 ? 100.0 * (r.peak_fl_N - r.reference_peak_fl_N) / r.reference_peak_fl_N : 0.0;
    char ref[32] = "-", errs[32] = "-";
    if (r.reference_peak_fl_N > 0) {
      std::snprintf(ref, sizeof ref, "%.0f", r.reference_peak_fl_N);
      std::snprintf(errs, sizeof errs, "%+.2f%%", err);
    }
    if (markdown)
      std::printf("| %s | %s | %s | %.1f | %.1f..%.1f | %.0f | %ld | %.0f | %s | %s |\n", r.assembly.c_str(), r.label.c_str(),
                  r.scenario.c_str(), 1e3 * r.median_wall_s, 1e3 * r.min_wall_s, 1e3 * r.max_wall_s, r.real_time_factor, r.steps,
                  r.peak_fl_N, ref, errs);
    else
      std::printf("%-4s %-24s %-6s %10.1f %7.1f..%-7.1f %8.0f %7ld %10.0f %10s %8s%s\n", r.assembly.c_str(), r.label.c_str(),
                  r.scenario.c_str(), 1e3 * r.median_wall_s, 1e3 * r.min_wall_s, 1e3 * r.max_wall_s, r.real_time_factor,
                  r.steps, r.peak_fl_N, ref, errs, r.ok ? "" : "  FAILED");
  }
  return 0;
}


}  // namespace

CommandHandle addBenchCommand(CLI::App& root) {
  struct Cfg { std::string study = defaultStudy(); int runs = 5; bool md = false; std::vector<std::string> ids; long import_rows = 0; long user_effect = 0; std::string scenario = "field"; };
  auto cfg = std::make_shared<Cfg>();
  std::string& bench_study = cfg->study;
  int& bench_runs = cfg->runs;
  bool& bench_md = cfg->md;
  std::vector<std::string>& bench_ids = cfg->ids;
  auto* b = root.add_subcommand("bench", "Measure wall time per 15 s run for every assembly on the bump and the rough road");
  b->add_option("--study", bench_study, "Study file (TOML)")->capture_default_str();
  b->add_option("--runs", bench_runs, "Timed runs per case (median reported)")->capture_default_str()->check(CLI::Range(1, 1000));
  b->add_option("--assembly", bench_ids, "Only these assemblies")->delimiter(',');
  b->add_flag("--markdown", bench_md, "Print a markdown table (for docs/performance.md)");
  b->add_option("--import", cfg->import_rows, "Instead: time `twin import` on a synthetic 100 Hz log of this many rows (360000: one hour)")
      ->check(CLI::Range(2L, 100000000L));
  b->add_option("--user-effect", cfg->user_effect, "Instead: time a user-defined strut effect against the built-in one of the same form, over this many evaluations")
      ->check(CLI::Range(1000L, 1000000000L));
  auto* scen = b->add_option("--scenario", cfg->scenario, "With --user-effect: the study's scenario of the whole runs timed")->capture_default_str();
  scen->needs("--user-effect");

  return {b, [cfg] {
            if (cfg->import_rows > 0) {
              const BenchImport r = benchImport(cfg->study, cfg->import_rows, cfg->runs);
              std::printf("twin import: %ld rows (%.1f MB), %d runs: median %.2f s (%.2f..%.2f s), %.0f rows/s\n", r.rows, r.bytes / 1e6,
                          cfg->runs, r.median_s, r.min_s, r.max_s, static_cast<double>(r.rows) / r.median_s);
              return 0;
            }
            if (cfg->user_effect > 0) {
              const Study study = loadStudy(cfg->study);
              const BenchUserEffect r = benchUserEffect(study, cfg->scenario, cfg->user_effect, cfg->runs);
              std::printf("strut force, %ld evaluations, %d runs (median): built-in damper_asymmetry %.1f ns, user-defined \"v < 0 ? (ratio - 1) * c * v : 0\" %.1f ns "
                          "(%.1fx); largest difference %.3g N\n",
                          r.evaluations, cfg->runs, r.builtin_ns, r.user_ns, r.user_ns / r.builtin_ns, r.max_abs_difference);
              std::printf("whole runs of %s on '%s' (%ld steps), %d runs each (median): built-in %.3f s, user-defined %.3f s (%.2fx); traces %s\n",
                          study.assemblies().front().id.c_str(), r.scenario.c_str(), r.steps, cfg->runs, r.builtin_run_s, r.user_run_s,
                          r.user_run_s / r.builtin_run_s, r.identical_traces ? "identical" : "DIFFER");
              return 0;
            }
            return runBench(cfg->study, cfg->runs, cfg->md, cfg->ids);
          }};
}

}  // namespace dtwin::cli
