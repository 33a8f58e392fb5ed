// twin: the command-line front end. Parses, validates, calls the libraries. Nothing else.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "subsystems/errors.hpp"
#include "twin/bench.hpp"
#include "twin/provenance.hpp"
#include "twin/simulator.hpp"
#include "twin/study.hpp"
#include "dtwin/version.hpp"

namespace fs = std::filesystem;
using namespace dtwin;

namespace {

std::string defaultStudy() {
  for (const char* dir : {DTWIN_SOURCE_DATA_DIR, DTWIN_INSTALL_DATA_DIR}) {
    const fs::path p = fs::path(dir) / "studies" / "demo.toml";
    if (fs::exists(p)) return p.string();
  }
  return "data/studies/demo.toml";
}

std::string joinArgs(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

struct SimulateConfig {
  std::string study = defaultStudy(), assembly = "M1", scenario = "lab", out;
  std::vector<std::string> sets, effects, channels;
  std::vector<double> window;
  long long seed = -1;
  std::string integrator;
  double accuracy = 0, max_step = 0, obstacle_step = 0, rate = 0;
  bool quiet = false;
};

double peakOf(const Trace& t, const std::string& ch) {
  const auto& c = t.column(ch);
  return *std::max_element(c.begin(), c.end());
}

int runSimulate(const SimulateConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  const ScenarioSpec& sc = study.scenario(cfg.scenario);
  std::vector<ParameterSetting> sets;
  for (auto& s : cfg.sets) sets.push_back(parseSetting(s, "--set"));
  std::vector<EffectSetting> effects;
  for (auto& e : cfg.effects) effects.push_back(parseEffectSetting(e, "--effect"));
  SimulationOptions opt = study.simulation;
  if (!cfg.integrator.empty()) opt.integrator = cfg.integrator;
  if (cfg.accuracy > 0) opt.accuracy = cfg.accuracy;
  if (cfg.max_step > 0) opt.max_step_s = cfg.max_step;
  if (cfg.obstacle_step > 0) opt.obstacle_max_step_s = cfg.obstacle_step;
  if (cfg.rate > 0) opt.output_rate_hz = cfg.rate;
  if (auto rule = opt.check(); !rule.empty()) throw InputError("command line", rule);
  if (!cfg.window.empty() && (cfg.window.size() != 2 || !(cfg.window[0] < cfg.window[1])))
    throw InputError("--window", "expects T0,T1 with T0 < T1");
  for (auto& c : cfg.channels) {
    bool ok = false;
    for (auto& ch : Simulator::channels()) ok |= ch.name == c;
    if (!ok) throw InputError("--channels", "unknown channel '" + c + "' (see `twin list --channels`)");
  }
  std::vector<std::string> channels = cfg.channels;
  if (!channels.empty() && std::find(channels.begin(), channels.end(), "time_s") == channels.end())
    channels.insert(channels.begin(), "time_s");
  const std::uint64_t seed = cfg.seed >= 0 ? static_cast<std::uint64_t>(cfg.seed) : study.seed;

  std::vector<AssemblySpec> targets;
  const bool all = cfg.assembly == "all";
  if (all) targets = study.assemblies();
  else targets.push_back(study.assembly(cfg.assembly));
  if (all && fs::path(cfg.out).has_extension())
    throw InputError("--out", "with --assembly all, --out must be a folder, got '" + cfg.out + "'");
  if (!all && fs::path(cfg.out).extension() != ".csv") throw InputError("--out", "must name a .csv file, got '" + cfg.out + "'");

  nlohmann::json summary;
  summary["program"] = programInfo();
  summary["command"] = command;
  summary["created_utc"] = utcNow();
  summary["study"] = study.path;
  summary["scenario"] = sc.name;
  summary["seed"] = seed;
  int failures = 0;
  for (const auto& a : targets) {
    auto model = study.makeModel(a, effects, sets);
    for (std::size_t i = 0; i < model->assembly().effects.size(); ++i) {
      bool off = true;
      for (std::size_t k = 0; k < model->effects()[i]->parameters().size(); ++k) {
        const auto& n = model->runParameterNames()[static_cast<std::size_t>(model->effectSlots()[i][k])];
        off = off && model->table().value(n) == model->table().at(n).spec.default_value;
      }
      if (off && !cfg.quiet)
        std::cerr << "twin: note: effect " << model->assembly().effects[i]
                  << " is installed at its off values; set its parameters to switch it on, e.g. --effect "
                  << model->assembly().effects[i] << ":" << model->effects()[i]->parameters()[0].name << "=...\n";
    }
    auto road = makeRoad(sc, model->vehicle(), seed);
    Simulator sim(model, opt);
    const auto values = model->defaultRunValues();
    RunResult r = sim.run(values, *road, sc);
    const std::string csv = all ? (fs::path(cfg.out) / (a.id + "_" + sc.name + ".csv")).string() : cfg.out;
    const double t_lo = cfg.window.empty() ? -1e300 : cfg.window[0], t_hi = cfg.window.empty() ? 1e300 : cfg.window[1];
    writeFileAtomic(csv, r.trace.toCsv(channels, t_lo, t_hi));
    const auto rec = runRecord(study, *model, sc, *road, seed, values, opt, r.stats, Simulator::channels(), command);
    writeFileAtomic(sidecarPath(csv), rec.dump(2) + "\n");
    const double peak = peakOf(r.trace, "hub_force_fl_N");
    if (!cfg.quiet)
      std::printf("%-4s %-34s %s  peak FL hub force %8.0f N  %6ld steps  %7.1f ms  -> %s\n", a.id.c_str(),
                  model->assembly().label().c_str(), r.stats.ok ? "ok    " : "FAILED", peak, r.stats.steps,
                  1e3 * r.stats.wall_s, csv.c_str());
    if (!r.stats.ok) {
      ++failures;
      std::cerr << "twin: " << a.id << ": " << r.stats.message << "\n";
    }
    summary["runs"].push_back({{"assembly", a.id}, {"label", model->assembly().label()}, {"ok", r.stats.ok},
                               {"message", r.stats.message}, {"peak_hub_force_fl_N", peak},
                               {"static_hub_force_fl_N", r.trace.column("hub_force_fl_N").front()},
                               {"integrator_steps", r.stats.steps}, {"wall_s", r.stats.wall_s}, {"trace", csv}});
  }
  if (all) writeFileAtomic((fs::path(cfg.out) / "summary.json").string(), summary.dump(2) + "\n");
  return failures ? 1 : 0;
}

int runList(const std::string& study_path, bool params) {
  const Study study = loadStudy(study_path);
  std::printf("study %s (%s)\n  vehicle: %s\n\nassemblies:\n", study.name.c_str(), study.path.c_str(), study.vehicle_path.c_str());
  for (const auto& a : study.assemblies()) std::printf("  %-4s %s\n", a.id.c_str(), a.label().c_str());
  std::printf("\nscenarios:\n");
  for (const auto& s : study.scenarios) std::printf("  %-10s %s\n", s.name.c_str(), s.toJson()["road"].dump().c_str());
  std::printf("\ncalibrated parameters:\n");
  for (const auto& c : study.calibrated)
    std::printf("  %-24s [%g, %g] %s%s\n", c.name.c_str(), c.lower, c.upper, c.unit.c_str(),
                c.truth ? (" truth " + std::to_string(*c.truth)).c_str() : "");
  std::printf("\neffects (add with --effect NAME:param=value,...; all default to off):\n");
  for (const auto& n : effectNames()) {
    auto e = makeEffect(n, "");
    std::printf("  %-18s %s\n", n.c_str(), e->description().c_str());
    for (const auto& p : e->parameters())
      std::printf("      %-24s [%s] off = %g  %s\n", (n + "." + p.name).c_str(), p.unit.c_str(), p.default_value, p.description.c_str());
    std::printf("      signature: %s\n", e->signature().c_str());
  }
  if (!study.effects.empty()) {
    std::printf("\neffects installed by this study:");
    for (const auto& e : study.effects) std::printf(" %s", e.name.c_str());
    std::printf("\n");
  }
  std::printf("\noutput channels:\n");
  for (const auto& c : Simulator::channels()) std::printf("  %-26s %s\n", c.name.c_str(), c.description.c_str());
  if (params) {
    std::printf("\nparameters (value, unit, source):\n");
    const auto t = study.parameterTable();
    for (const auto& n : t.names()) {
      const auto& e = t.at(n);
      std::printf("  %-48s %12g %-8s %s\n", n.c_str(), e.value, e.spec.unit.c_str(), e.source.c_str());
    }
  }
  return 0;
}

int runBench(const std::string& study_path, int runs, bool markdown, const std::vector<std::string>& ids) {
  const Study study = loadStudy(study_path);
  const ScenarioSpec *bump = nullptr, *rough = nullptr;
  for (const auto& s : study.scenarios) {
    if (!bump && s.road.type == RoadSpec::Type::Bump) bump = &s;
    if (!rough && s.road.type == RoadSpec::Type::Iso) rough = &s;
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

int main(int argc, char** argv) {
  const std::string command = joinArgs(argc, argv);
  CLI::App app{"twin: a multibody digital twin of a ground vehicle (Simbody), with Bayesian choice of subsystem fidelity"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(kVersion) + " (" + kGitDescribe + ")");

  SimulateConfig sim;
  auto* s = app.add_subcommand("simulate", "Simulate one assembly (or all) over one scenario; writes a CSV trace and a JSON sidecar");
  s->add_option("--study", sim.study, "Study file (TOML)")->capture_default_str();
  s->add_option("--assembly", sim.assembly, "Assembly id from `twin list` (M1, M2, ...), or 'all'")->capture_default_str();
  s->add_option("--scenario", sim.scenario, "Scenario name from the study (e.g. lab, field)")->capture_default_str();
  s->add_option("--out", sim.out, "Output CSV file (a folder with --assembly all); the sidecar is written next to it as .json")->required();
  s->add_option("--set", sim.sets, "Override a parameter: NAME=VALUE (e.g. tire.stiffness=2.0e5); repeatable; `twin list --parameters` lists names");
  s->add_option("--effect", sim.effects, "Add an effect: NAME[:param=value,...] (e.g. bump_stop:stiffness=5e6,gap_m=0.04); repeatable");
  s->add_option("--seed", sim.seed, "Seed of random roads (default: the study's seed)");
  s->add_option("--channels", sim.channels, "Only these channels (comma separated); time_s is always written")->delimiter(',');
  s->add_option("--window", sim.window, "Only rows with T0 <= time_s <= T1 (T0,T1)")->delimiter(',')->expected(2);
  s->add_option("--integrator", sim.integrator, "Override the study's integrator: rk-merson, rk3, rk-feldberg, cpodes, semi-explicit-euler2");
  s->add_option("--accuracy", sim.accuracy, "Override the integrator accuracy");
  s->add_option("--max-step", sim.max_step, "Override the largest step [s]");
  s->add_option("--obstacle-step", sim.obstacle_step, "Override the largest step while crossing an obstacle [s]");
  s->add_option("--output-rate", sim.rate, "Override the output rate [Hz]");
  s->add_flag("--quiet", sim.quiet, "Print nothing on success");

  std::string list_study = defaultStudy();
  bool list_params = false;
  auto* l = app.add_subcommand("list", "Show the assemblies, scenarios, calibrated parameters, effects and channels a study defines");
  l->add_option("--study", list_study, "Study file (TOML)")->capture_default_str();
  l->add_flag("--parameters", list_params, "Also list every parameter with its value, unit and source");

  std::string bench_study = defaultStudy();
  int bench_runs = 5;
  bool bench_md = false;
  std::vector<std::string> bench_ids;
  auto* b = app.add_subcommand("bench", "Measure wall time per 15 s run for every assembly on the bump and the rough road");
  b->add_option("--study", bench_study, "Study file (TOML)")->capture_default_str();
  b->add_option("--runs", bench_runs, "Timed runs per case (median reported)")->capture_default_str()->check(CLI::Range(1, 1000));
  b->add_option("--assembly", bench_ids, "Only these assemblies")->delimiter(',');
  b->add_flag("--markdown", bench_md, "Print a markdown table (for docs/performance.md)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    if (*s) return runSimulate(sim, command);
    if (*l) return runList(list_study, list_params);
    if (*b) return runBench(bench_study, bench_runs, bench_md, bench_ids);
  } catch (const InputError& e) {
    std::fprintf(stderr, "twin: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "twin: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
