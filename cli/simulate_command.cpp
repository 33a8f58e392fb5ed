#include <algorithm>
#include <optional>
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

struct SimulateConfig {
  std::string study = defaultStudy(), assembly = "M1", scenario = "lab", out;
  std::vector<std::string> sets, effects, channels;
  std::vector<double> window;
  std::optional<std::uint64_t> seed;  ///< unset: the study's
  std::string integrator;
  std::optional<double> accuracy, max_step, obstacle_step, rate;  ///< unset: the study's
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
  for (auto& e : cfg.effects) effects.push_back(parseEffectSetting(e, "--effect", study.effectCatalog()));
  SimulationOptions opt = study.simulation;
  if (!cfg.integrator.empty()) opt.integrator = cfg.integrator;
  opt.accuracy = cfg.accuracy.value_or(opt.accuracy);
  opt.max_step_s = cfg.max_step.value_or(opt.max_step_s);
  opt.obstacle_max_step_s = cfg.obstacle_step.value_or(opt.obstacle_max_step_s);
  opt.output_rate_hz = cfg.rate.value_or(opt.output_rate_hz);
  opt.validate();  // errors name the flag (field_flags below)
  if (!cfg.window.empty() && (cfg.window.size() != 2 || !(cfg.window[0] < cfg.window[1])))
    throw InputError("--window", "expects T0,T1 with T0 < T1");
  for (auto& c : cfg.channels) {
    bool ok = false;
    for (auto& ch : Simulator::channels(study.sensors)) ok |= ch.name == c;
    if (!ok) throw InputError("--channels", "unknown channel '" + c + "' (see `twin list --channels`)");
  }
  std::vector<std::string> channels = cfg.channels;
  if (!channels.empty() && std::find(channels.begin(), channels.end(), "time_s") == channels.end())
    channels.insert(channels.begin(), "time_s");
  const std::uint64_t seed = cfg.seed.value_or(study.seed);

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
    // A failed run writes no trace (a partial trace would pass for a result): only the summary
    // of --assembly all records it.
    if (r.stats.ok) {
      writeFileAtomic(csv, r.trace.toCsv(channels, t_lo, t_hi));
      const auto rec = runRecord(study, *model, sc, road->describe(), seed, values, opt, r.stats, Simulator::channels(study.sensors), command);
      writeFileAtomic(sidecarPath(csv), rec.dump(2) + "\n");
    }
    const double peak = peakOf(r.trace, "hub_force_fl_N");
    if (!cfg.quiet)
      std::printf("%-4s %-34s %s  peak FL hub force %8.0f N  %6ld steps  %7.1f ms  -> %s\n", a.id.c_str(),
                  model->assembly().label().c_str(), r.stats.ok ? "ok    " : "FAILED", peak, r.stats.steps,
                  1e3 * r.stats.wall_s, r.stats.ok ? csv.c_str() : "(no trace written)");
    if (!r.stats.ok) {
      ++failures;
      std::cerr << "twin: " << a.id << ": " << r.stats.message << "\n";
    }
    summary["runs"].push_back({{"assembly", a.id}, {"label", model->assembly().label()}, {"ok", r.stats.ok},
                               {"message", r.stats.message}, {"peak_hub_force_fl_N", peak},
                               {"static_hub_force_fl_N", r.trace.column("hub_force_fl_N").front()},
                               {"integrator_steps", r.stats.steps}, {"wall_s", r.stats.wall_s},
                               {"trace", r.stats.ok ? nlohmann::json(csv) : nlohmann::json()}});
  }
  if (all) writeFileAtomic((fs::path(cfg.out) / "summary.json").string(), summary.dump(2) + "\n");
  return failures ? 1 : 0;
}

}  // namespace

CommandHandle addSimulateCommand(CLI::App& root, const std::string& command_line) {
  auto cfg = std::make_shared<SimulateConfig>();
  SimulateConfig& sim = *cfg;
  auto* s = addSubcommand(root, "simulate");
  s->add_option("--study", sim.study, "Study file (TOML)")->capture_default_str();
  s->add_option("--assembly", sim.assembly, "Assembly id from `twin list` (M1, M2, ...), or 'all'")->capture_default_str();
  s->add_option("--scenario", sim.scenario, "Scenario name from the study (e.g. lab, field)")->capture_default_str();
  s->add_option("--out", sim.out, "Output CSV file (a folder with --assembly all); the sidecar is written next to it as .json")->required();
  s->add_option("--set", sim.sets, "Override a parameter: NAME=VALUE (e.g. tire.stiffness=2.0e5); repeatable; `twin list --parameters` lists names");
  s->add_option("--effect", sim.effects, "Add an effect: NAME[:param=value,...] (e.g. bump_stop:stiffness=5e6,gap_m=0.04); repeatable");
  addSeedOption(s, sim.seed, "Seed of random roads (default: the study's seed)");
  s->add_option("--channels", sim.channels, "Only these channels (comma separated); time_s is always written")->delimiter(',');
  s->add_option("--window", sim.window, "Only rows with T0 <= time_s <= T1 (T0,T1)")->delimiter(',')->expected(2);
  s->add_option("--integrator", sim.integrator, "Override the study's integrator: rk-merson, rk3, rk-feldberg, cpodes, semi-explicit-euler2");
  s->add_option("--accuracy", sim.accuracy, "Override the integrator accuracy");
  s->add_option("--max-step", sim.max_step, "Override the largest step [s]");
  s->add_option("--obstacle-step", sim.obstacle_step, "Override the largest step while crossing an obstacle [s]");
  s->add_option("--output-rate", sim.rate, "Override the output rate [Hz]");
  s->add_flag("--quiet", sim.quiet, "Print nothing on success");

  CommandHandle handle{s, [cfg, command_line] { return runSimulate(*cfg, command_line); }};
  handle.field_flags = {{"effects", "--effect"}, {"max_step_s", "--max-step"}, {"obstacle_max_step_s", "--obstacle-step"}, {"output_rate_hz", "--output-rate"}};
  return handle;
}

}  // namespace dtwin::cli
