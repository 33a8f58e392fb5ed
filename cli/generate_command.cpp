// `twin generate lab|field`: synthetic measurements made by one assembly at the study's true
// parameters, plus noise. Thin: parse, call study/generate.hpp, print.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "io/provenance.hpp"
#include "study/generate.hpp"
#include "twin/trace.hpp"

namespace dtwin::cli {
namespace {

namespace fs = std::filesystem;

struct GenerateConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string study = defaultStudy(), out, assembly, scenario, channel = "hub_force_fl_N";
  std::optional<std::uint64_t> seed;  ///< unset: the study's
  long repetitions = 0, runs = 0;
  int threads = 0;
  std::vector<double> window;
  std::vector<std::string> hidden_effects;  ///< --hidden-effect NAME[:param=value,...], repeatable
  std::vector<std::string> hidden_values;   ///< lab: --hidden-value NAME=VALUE, repeatable
  std::vector<std::string> hidden_sensor;   ///< lab: --hidden-sensor KIND=VALUE, repeatable
  std::string times = "auto";               ///< lab: --times auto|all
  double rate = 0;                          ///< lab: --rate HZ (0: not given)
  bool force = false;
  std::vector<std::string> channels;  ///< lab: --channels a,b,c
  bool quiet = false;
  CLI::Option* rate_opt = nullptr;
};

AssemblySpec chooseAssembly(const Study& study, const std::string& id) {
  if (!id.empty()) return study.assembly(id);
  const auto all = study.assemblies();
  if (all.empty()) throw InputError(study.path + ": assemblies", "the study defines no assembly");
  return all.front();  // M1: the highest fidelity by convention (docs/method.md §1)
}

std::vector<EffectSetting> parseHidden(const std::vector<std::string>& texts,
                                       const EffectCatalog& catalog) {
  std::vector<EffectSetting> out;
  out.reserve(texts.size());
  for (const auto& t : texts) out.push_back(parseEffectSetting(t, "--hidden-effect", catalog));
  return out;
}

/// NAME=VALUE texts of `flag` (a finite number after the first '=').
std::vector<std::pair<std::string, double>> parseAssignments(const std::vector<std::string>& texts,
                                                             const std::string& flag) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& t : texts) {
    const auto eq = t.find('=');
    double v = 0;
    if (eq == std::string::npos || eq == 0 || !parseNumber(t.substr(eq + 1), v) ||
        !std::isfinite(v))
      throw InputError(flag, "expects NAME=VALUE with a finite number, got '" + t + "'");
    for (const auto& [name, _] : out)
      if (name == t.substr(0, eq)) throw InputError(flag, "'" + name + "' given twice");
    out.push_back({t.substr(0, eq), v});
  }
  return out;
}

/// "twin: hidden effect: ..." on stdout (one line), unless quiet or none.
void printHidden(const nlohmann::json& provenance, const EffectCatalog& catalog) {
  if (provenance.contains("hidden_effects"))
    std::printf("hidden effect used to make the data: %s\n",
                hiddenEffectsSummary(provenance["hidden_effects"], catalog).c_str());
  if (provenance.contains("hidden_values"))
    for (const auto& [name, v] : provenance["hidden_values"].items())
      std::printf("hidden vehicle value used to make the data: %s = %s\n", name.c_str(),
                  formatExact(v.get<double>()).c_str());
  if (provenance.contains("hidden_sensor"))
    for (const auto& [kind, v] : provenance["hidden_sensor"].items())
      std::printf("hidden sensor model applied to the data: %s %s\n", kind.c_str(),
                  v.dump().c_str());
}

int runLab(const GenerateConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  const AssemblySpec a = chooseAssembly(study, cfg.assembly);
  LabOptions opt;
  if (!cfg.scenario.empty()) opt.scenario = cfg.scenario;
  opt.hidden_effects = parseHidden(cfg.hidden_effects, study.effectCatalog());
  for (const auto& [name, v] : parseAssignments(cfg.hidden_values, "--hidden-value"))
    opt.hidden_values.push_back({name, v, "--hidden-value", "--hidden-value"});
  opt.hidden_sensor = parseAssignments(cfg.hidden_sensor, "--hidden-sensor");
  opt.times_mode = cfg.times == "all" ? LabTimesMode::All : LabTimesMode::Study;
  if (!cfg.window.empty()) {
    if (cfg.window.size() != 2) throw InputError("--window", "expects T0,T1 with T0 < T1");
    opt.window = std::make_pair(cfg.window[0], cfg.window[1]);
  }
  if (cfg.rate_opt && cfg.rate_opt->count()) opt.rate_hz = cfg.rate;
  opt.channels = cfg.channels;
  opt.processes = cfg.processes;
  opt.repetitions = cfg.repetitions;
  {
    Study sized = study;
    overrideSize(sized, "lab_repetitions", cfg.repetitions, "--repetitions");
    checkCommandWork(sized, {"lab"}, cfg.force);
  }
  if (cfg.seed) opt.seed = *cfg.seed;
  opt.command = command;
  LabResult r;
  {
    ProgressBar bar("generate lab", progressOn(cfg.quiet, cfg.processes), stderrIsTerminal());
    r = generateLabFile(study, a, opt, cfg.out,
                        [&](std::size_t d, std::size_t t) { bar.update(d, t); });
  }
  if (!cfg.quiet) {
    for (const auto& c : r.provenance["noise"]["not_applied_to"])
      std::fprintf(stderr, "twin: note: channel %s is not in N; it is written without noise\n",
                   c.get<std::string>().c_str());
    std::string times;
    if (opt.times_mode == LabTimesMode::All)
      times = "times: " + r.times_rule + " (" + std::to_string(r.times_s.size()) + " times)";
    else {
      for (double t : r.times_s) times += (times.empty() ? "" : ", ") + formatExact(t);
      times = "times " + times + " s (" +
              r.provenance["lab"]["times"]["source"].get<std::string>() + ")";
    }
    std::printf("%s (%s): %ld repetitions x %zu times x %zu channel(s), %s -> %s, %s\n",
                a.id.c_str(), a.label().c_str(), r.provenance["lab"]["repetitions"].get<long>(),
                r.times_s.size(), r.provenance["lab"]["channels"].size(), times.c_str(),
                cfg.out.c_str(), sidecarPath(cfg.out).c_str());
    printHidden(r.provenance, study.effectCatalog());
  }
  return 0;
}

int runField(const GenerateConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  const AssemblySpec a = chooseAssembly(study, cfg.assembly);
  FieldOptions opt;
  if (!cfg.scenario.empty()) opt.scenario = cfg.scenario;
  opt.channel = cfg.channel;
  if (!cfg.window.empty()) {
    if (cfg.window.size() != 2 || !(cfg.window[0] < cfg.window[1]))
      throw InputError("--window", "expects T0,T1 with T0 < T1");
    opt.t_begin_s = cfg.window[0];
    opt.t_end_s = cfg.window[1];
  }
  opt.hidden_effects = parseHidden(cfg.hidden_effects, study.effectCatalog());
  opt.runs = cfg.runs;
  {
    Study sized = study;
    overrideSize(sized, "field_runs", cfg.runs, "--runs");
    checkCommandWork(sized, {"field"}, cfg.force);
  }
  opt.threads = cfg.threads;
  opt.processes = cfg.processes;
  if (cfg.seed) opt.seed = *cfg.seed;
  opt.command = command;
  FieldResult r;
  {
    ProgressBar bar("generate field", progressOn(cfg.quiet, cfg.processes), stderrIsTerminal());
    r = generateFieldFile(study, a, opt, cfg.out,
                          [&](std::size_t d, std::size_t t) { bar.update(d, t); });
  }
  if (!cfg.quiet && !r.provenance["noise"]["applied"].get<bool>())
    std::fprintf(stderr, "twin: note: channel %s is not in N; it is written without noise\n",
                 opt.channel.c_str());
  if (!cfg.quiet)
    std::printf("%s (%s): %zu runs x %zu samples of %s (%g..%g s), %d threads, %.1f s -> %s, %s\n",
                a.id.c_str(), a.label().c_str(), r.data.rowCount(), r.data.columnCount(),
                opt.channel.c_str(), r.data.times_s.front(), r.data.times_s.back(),
                r.provenance["field"]["threads"].get<int>(),
                r.provenance["stats"]["wall_s"].get<double>(), cfg.out.c_str(),
                sidecarPath(cfg.out).c_str());
  if (!cfg.quiet) printHidden(r.provenance, study.effectCatalog());
  return 0;
}

void commonOptions(CLI::App* s, GenerateConfig& cfg, const char* default_scenario) {
  s->add_option("--study", cfg.study, "Study file (TOML)")->capture_default_str();
  s->add_option("--out", cfg.out, "Output CSV file; the JSON sidecar is written next to it (.json)")
      ->required();
  s->add_option("--assembly", cfg.assembly,
                "Assembly that makes the data (default: the study's first, M1)");
  s->add_option("--scenario", cfg.scenario,
                std::string("Scenario of the study (default: ") + default_scenario + ")");
  addSeedOption(s, cfg.seed, "Seed of noise and roads (default: the study's seed)");
  s->add_option("--hidden-effect", cfg.hidden_effects,
                "Make the data with this effect switched on (the study's assemblies lack it; for "
                "testing a diagnosis): "
                "NAME[:param=value,...], e.g. bump_stop:stiffness=2e6,gap_m=0.02; repeatable; "
                "recorded in the sidecar")
      ->allow_extra_args(false);
  s->add_flag("--quiet", cfg.quiet, "Print nothing on success (no progress line)");
  addForceOption(s, cfg.force);
}

}  // namespace

CommandHandle addGenerateCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto* g = addSubcommand(root, "generate");
  g->require_subcommand(1);
  auto lab = std::make_shared<GenerateConfig>();
  lab->processes = context.processes;
  auto field = std::make_shared<GenerateConfig>();
  field->processes = context.processes;

  auto* l = g->add_subcommand(
      "lab",
      "Lab data: the assembly at the study's true parameters over the lab scenario, plus noise, R "
      "repetitions, at a few significant times (tidy CSV repetition,time_s,channel,value; "
      "docs/data-files.md)");
  commonOptions(l, *lab, "lab");
  l->add_option("--repetitions", lab->repetitions,
                "Repetitions (default: the study's sizes.lab_repetitions)")
      ->check(CLI::Range(1L, StudySizes::maximum("lab_repetitions")));
  l->add_option("--times", lab->times,
                "auto: the study's [lab] times_s, else the automatic times (default); all: every "
                "output sample of the "
                "noise-free run in --window at --rate")
      ->check(CLI::IsMember({"auto", "all"}))
      ->capture_default_str();
  l->add_option("--window", lab->window,
                "With --times all: time window T0,T1 [s] (default: the whole scenario)")
      ->delimiter(',')
      ->expected(2);
  lab->rate_opt = l->add_option("--rate", lab->rate,
                                "With --times all: samples per second kept [Hz] (default: the "
                                "output rate; must divide it into an integer step)");
  l->add_option("--channels", lab->channels,
                "Channels, a,b,c (default: the study's [lab] channels)")
      ->delimiter(',');
  l->add_option("--hidden-value", lab->hidden_values,
                "Make the data with this fixed vehicle value changed (for testing a diagnosis): "
                "NAME=VALUE, e.g. "
                "wheel.mass_kg=35.35, or a per-corner factor, e.g. suspension.damping@rr=0.5; "
                "repeatable; recorded in the sidecar")
      ->allow_extra_args(false);
  l->add_option("--hidden-sensor", lab->hidden_sensor,
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
  f->add_option("--runs", field->runs, "Runs (default: the study's sizes.field_runs)")
      ->check(CLI::Range(1L, StudySizes::maximum("field_runs")));
  f->add_option("--threads", field->threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 4096));
  f->add_option("--channel", field->channel, "Channel to keep")->capture_default_str();
  f->add_option("--window", field->window, "Time window kept, T0,T1 [s] (default 10,15)")
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
      if (*l) return runLab(*lab, command_line);
      return runField(*field, command_line);
    } catch (const RunFailedError& e) {
      std::fprintf(stderr, "twin: error: %s\n", e.what());
      return 1;
    }
  };
  return h;
}

}  // namespace dtwin::cli
