// `twin generate lab|field`: synthetic measurements made by one assembly at the study's true
// parameters, plus noise. Thin: parse, call study/generate_request.hpp, print.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/run_error.hpp"
#include "study/generate_request.hpp"
#include "study/request.hpp"

namespace dtwin::cli {
namespace {

struct GenerateConfig {
  std::string study = defaultStudy();
  GenerateRequest request;     ///< the flags bound to its fields; processes from CommandContext
  std::string times = "auto";  ///< lab: --times auto|all
  double rate = 0;             ///< lab: --rate HZ (when rate_opt counts it)
  bool quiet = false;
  CLI::Option* rate_opt = nullptr;
};

/// `twin generate lab` (`lab`) or `twin generate field`: the data made and written, then the
/// notes on stderr and the lines on stdout, unless quiet.
int runGenerate(const GenerateConfig& cfg, const std::string& command, bool lab) {
  const Study study = loadStudy(cfg.study);
  GenerateRequest req = cfg.request;
  req.all_times = cfg.times == "all";
  if (cfg.rate_opt && cfg.rate_opt->count()) req.rate_hz = cfg.rate;
  req.command = command;
  GenerateRun run;
  {
    ProgressBar bar(lab ? "generate lab" : "generate field", progressOn(cfg.quiet, req.processes),
                    stderrIsTerminal());
    const ProgressFn progress = [&](std::size_t d, std::size_t t) { bar.update(d, t); };
    run = lab ? generateLabData(study, req, progress) : generateFieldData(study, req, progress);
  }
  if (cfg.quiet) return 0;
  for (const auto& note : run.notes) std::fprintf(stderr, "twin: note: %s\n", note.c_str());
  std::fputs(run.text.c_str(), stdout);
  return 0;
}

void commonOptions(CLI::App* s, GenerateConfig& cfg, const char* default_scenario) {
  s->add_option("--study", cfg.study, "Study file (TOML)")->capture_default_str();
  s->add_option("--out", cfg.request.out,
                "Output CSV file; the JSON sidecar is written next to it (.json)")
      ->required();
  s->add_option("--assembly", cfg.request.assembly,
                "Assembly that makes the data (default: the study's first, M1)");
  s->add_option("--scenario", cfg.request.scenario,
                std::string("Scenario of the study (default: ") + default_scenario + ")");
  addSeedOption(s, cfg.request.seed, "Seed of noise and roads (default: the study's seed)");
  s->add_option("--hidden-effect", cfg.request.hidden_effects,
                "Make the data with this effect switched on (the study's assemblies lack it; for "
                "testing a diagnosis): "
                "NAME[:param=value,...], e.g. bump_stop:stiffness=2e6,gap_m=0.02; repeatable; "
                "recorded in the sidecar")
      ->allow_extra_args(false);
  s->add_flag("--quiet", cfg.quiet, "Print nothing on success (no progress line)");
  addForceOption(s, cfg.request.force);
}

}  // namespace

CommandHandle addGenerateCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto* g = addSubcommand(root, "generate");
  g->require_subcommand(1);
  auto lab = std::make_shared<GenerateConfig>();
  lab->request.processes = context.processes;
  auto field = std::make_shared<GenerateConfig>();
  field->request.processes = context.processes;

  auto* l = g->add_subcommand(
      "lab",
      "Lab data: the assembly at the study's true parameters over the lab scenario, plus noise, R "
      "repetitions, at a few significant times (tidy CSV repetition,time_s,channel,value; "
      "docs/data-files.md)");
  commonOptions(l, *lab, "lab");
  l->add_option("--repetitions", lab->request.repetitions,
                "Repetitions (default: the study's sizes.lab_repetitions)")
      ->check(CLI::Range(1L, StudySizes::maximum("lab_repetitions")));
  l->add_option("--times", lab->times,
                "auto: the study's [lab] times_s, else the automatic times (default); all: every "
                "output sample of the "
                "noise-free run in --window at --rate")
      ->check(CLI::IsMember({"auto", "all"}))
      ->capture_default_str();
  l->add_option("--window", lab->request.window,
                "With --times all: time window T0,T1 [s] (default: the whole scenario)")
      ->delimiter(',')
      ->expected(2);
  lab->rate_opt = l->add_option("--rate", lab->rate,
                                "With --times all: samples per second kept [Hz] (default: the "
                                "output rate; must divide it into an integer step)");
  l->add_option("--channels", lab->request.channels,
                "Channels, a,b,c (default: the study's [lab] channels)")
      ->delimiter(',');
  l->add_option("--hidden-value", lab->request.hidden_values,
                "Make the data with this fixed vehicle value changed (for testing a diagnosis): "
                "NAME=VALUE, e.g. "
                "wheel.mass_kg=35.35, or a per-corner factor, e.g. suspension.damping@rr=0.5; "
                "repeatable; recorded in the sidecar")
      ->allow_extra_args(false);
  l->add_option("--hidden-sensor", lab->request.hidden_sensor,
                "Distort every data channel by this sensor model before the noise (for testing a "
                "diagnosis): KIND=VALUE with "
                "KIND lowpass|lowpass2 (time constant [s]), gain or delay [s], e.g. lowpass=0.0064 "
                "(25 Hz); repeatable")
      ->allow_extra_args(false);

  auto* f = g->add_subcommand(
      "field",
      "Field data: N runs on independent random roads of the field scenario, a window of one "
      "channel at "
      "the output rate, plus noise (CSV matrix run,road_seed,t_10.000,...; docs/data-files.md)");
  commonOptions(f, *field, "field");
  f->add_option("--runs", field->request.runs, "Runs (default: the study's sizes.field_runs)")
      ->check(CLI::Range(1L, StudySizes::maximum("field_runs")));
  f->add_option("--threads", field->request.threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 4096));
  f->add_option("--channel", field->request.channel, "Channel to keep")->capture_default_str();
  f->add_option("--window", field->request.window, "Time window kept, T0,T1 [s] (default 10,15)")
      ->delimiter(',')
      ->expected(2);

  addExamples(g,
              {"twin generate lab --study data/studies/demo.toml --repetitions 3 --out out/lab.csv",
               "twin generate field --study data/studies/demo.toml --runs 20 --window 10,10.05 "
               "--out out/field.csv",
               "twin generate lab --study data/studies/demo.toml --scenario diag_bump --times all "
               "--rate 100 --repetitions 2 "
               "--channels hub_force_fl_N,hub_force_fr_N --hidden-effect "
               "bump_stop:stiffness=5e6,gap_m=0.02 --out out/diag_bump.csv"});
  addExamples(
      l, {"twin generate lab --study data/studies/demo.toml --repetitions 3 --out out/lab.csv"});
  addExamples(f, {"twin generate field --study data/studies/demo.toml --runs 20 --window 10,10.05 "
                  "--out out/field.csv"});
  CommandHandle h;
  h.app = g;
  h.field_flags = {{"out", "--out"},
                   {"channels", "--channels"},
                   {"window", "--window"},
                   {"rate_hz", "--rate"},
                   {"hidden_effects", "--hidden-effect"},
                   {"hidden_values", "--hidden-value"},
                   {"hidden_sensor", "--hidden-sensor"}};
  h.run = [=]() -> int {
    try {
      if (*l) return runGenerate(*lab, command_line, true);
      return runGenerate(*field, command_line, false);
    } catch (const RunFailedError& e) {
      std::fprintf(stderr, "twin: error: %s\n", e.what());
      return 1;
    }
  };
  return h;
}

}  // namespace dtwin::cli
