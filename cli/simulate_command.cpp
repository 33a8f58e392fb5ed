#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "study/request.hpp"
#include "study/simulate.hpp"

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

int runSimulate(const SimulateConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  SimulateRequest req;
  req.assembly = cfg.assembly;
  req.scenario = cfg.scenario;
  req.out = cfg.out;
  for (const auto& s : cfg.sets) req.sets.push_back(parseSetting(s, "--set"));
  for (const auto& e : cfg.effects)
    req.effects.push_back(parseEffectSetting(e, "--effect", study.effectCatalog()));
  req.channels = cfg.channels;
  if (!cfg.window.empty()) {
    if (cfg.window.size() != 2) throw InputError("--window", "expects T0,T1 with T0 < T1");
    req.window = std::make_pair(cfg.window[0], cfg.window[1]);
  }
  req.seed = cfg.seed;
  req.simulation = study.simulation;
  if (!cfg.integrator.empty()) req.simulation.integrator = cfg.integrator;
  req.simulation.accuracy = cfg.accuracy.value_or(req.simulation.accuracy);
  req.simulation.max_step_s = cfg.max_step.value_or(req.simulation.max_step_s);
  req.simulation.obstacle_max_step_s =
      cfg.obstacle_step.value_or(req.simulation.obstacle_max_step_s);
  req.simulation.output_rate_hz = cfg.rate.value_or(req.simulation.output_rate_hz);
  req.command = command;
  int failures = 0;
  simulateScenario(study, req, [&](const SimulateRun& r) {
    if (!cfg.quiet) {
      for (const auto& note : r.off_effects) std::cerr << "twin: note: " << note << "\n";
      std::printf("%-4s %-34s %s  peak FL hub force %8.0f N  %6ld steps  %7.1f ms  -> %s\n",
                  r.assembly.c_str(), r.label.c_str(), r.ok ? "ok    " : "FAILED",
                  r.peak_hub_force_fl_N, r.steps, 1e3 * r.wall_s,
                  r.ok ? r.trace.c_str() : "(no trace written)");
    }
    if (!r.ok) {
      ++failures;
      std::cerr << "twin: " << r.assembly << ": " << r.message << "\n";
    }
  });
  return failures ? 1 : 0;
}

}  // namespace

CommandHandle addSimulateCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<SimulateConfig>();
  SimulateConfig& sim = *cfg;
  auto* s = addSubcommand(root, "simulate");
  s->add_option("--study", sim.study, "Study file (TOML)")->capture_default_str();
  s->add_option("--assembly", sim.assembly, "Assembly id from `twin list` (M1, M2, ...), or 'all'")
      ->capture_default_str();
  s->add_option("--scenario", sim.scenario, "Scenario name from the study (e.g. lab, field)")
      ->capture_default_str();
  s->add_option(
       "--out", sim.out,
       "Output CSV file (a folder with --assembly all); the sidecar is written next to it as .json")
      ->required();
  s->add_option("--set", sim.sets,
                "Override a parameter: NAME=VALUE (e.g. tire.stiffness=2.0e5); repeatable; `twin "
                "list --parameters` lists names");
  s->add_option("--effect", sim.effects,
                "Add an effect: NAME[:param=value,...] (e.g. bump_stop:stiffness=5e6,gap_m=0.04); "
                "repeatable");
  addSeedOption(s, sim.seed, "Seed of random roads (default: the study's seed)");
  s->add_option("--channels", sim.channels,
                "Only these channels (comma separated); time_s is always written")
      ->delimiter(',');
  s->add_option("--window", sim.window, "Only rows with T0 <= time_s <= T1 (T0,T1)")
      ->delimiter(',')
      ->expected(2);
  s->add_option(
      "--integrator", sim.integrator,
      "Override the study's integrator: rk-merson, rk3, rk-feldberg, cpodes, semi-explicit-euler2");
  s->add_option("--accuracy", sim.accuracy, "Override the integrator accuracy");
  s->add_option("--max-step", sim.max_step, "Override the largest step [s]");
  s->add_option("--obstacle-step", sim.obstacle_step,
                "Override the largest step while crossing an obstacle [s]");
  s->add_option("--output-rate", sim.rate, "Override the output rate [Hz]");
  s->add_flag("--quiet", sim.quiet, "Print nothing on success");
  addExamples(s, {"twin simulate --study data/studies/demo.toml --assembly M1 --scenario lab --out "
                  "out/simulate/m1_lab.csv",
                  "twin simulate --study data/studies/paper.toml --assembly M3 --scenario field "
                  "--seed 7 --out out/simulate/m3_field.csv",
                  "twin simulate --study data/studies/demo.toml --assembly all --scenario lab "
                  "--effect bump_stop:stiffness=5e6,gap_m=0.03 --out out/simulate/bump_stop"});

  CommandHandle handle{s, [cfg, command_line] { return runSimulate(*cfg, command_line); }};
  handle.field_flags = {{"effects", "--effect"},
                        {"max_step_s", "--max-step"},
                        {"obstacle_max_step_s", "--obstacle-step"},
                        {"output_rate_hz", "--output-rate"}};
  return handle;
}

}  // namespace dtwin::cli
