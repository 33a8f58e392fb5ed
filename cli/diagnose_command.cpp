// `twin compare` and `twin diagnose` (diagnosis/compare.hpp, diagnosis/diagnose.hpp,
// docs/diagnosis.md): the model against measurements, where it fails, which effect is missing.
#include <cstdio>
#include <limits>
#include <memory>

#include "cli/calibration_flags.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/folder_lock.hpp"
#include "common/format.hpp"
#include "study/diagnose.hpp"
#include "study/request.hpp"

namespace dtwin::cli {
namespace {

// ------------------------------------------------------------------ compare
struct CompareConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string study = defaultStudy(), calibration, out;
  std::vector<std::string> data, baseline, discrepancy;
  int draws = 30, threads = 0;
  bool quiet = false, force = false;
};

int runCompare(const CompareConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  CompareRequest req;
  req.calibration = cfg.calibration;
  req.data = cfg.data;
  req.baseline = cfg.baseline;
  req.discrepancy = cfg.discrepancy;
  req.out = cfg.out;
  req.draws = cfg.draws;
  req.threads = cfg.threads;
  req.processes = cfg.processes;
  req.force = cfg.force;
  req.command = command;
  const auto say = [&](const std::string& line) {
    if (!cfg.quiet) std::printf("%s\n", line.c_str());
  };
  const CompareRun run = compareMeasurements(study, req, say);
  if (!cfg.quiet) std::printf("%s", run.text().c_str());
  if (!run.written.empty()) say("wrote " + run.written);
  for (const auto& line : run.pages) say(line);
  return 0;
}

// ------------------------------------------------------------------ diagnose
struct DiagnoseConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string study = defaultStudy(), assembly = "M1", out;
  std::vector<std::string> data, holdout, effects, apply;
  int threads = 0, candidates = 6, causes = 3, draws = 20, propose = 3;
  double confirm_within = 2.0;
  CalibrationFlags calibration;
  bool quiet = false, force = false, all_intervals = false;
};

std::vector<std::string> splitCommas(const std::vector<std::string>& v) {
  std::vector<std::string> out;
  for (const auto& s : v)
    for (auto& part : splitOn(s, ','))
      if (!part.empty()) out.push_back(std::move(part));
  return out;
}

int runDiagnose(const DiagnoseConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  DiagnoseRequest req;
  req.assembly = cfg.assembly;
  req.data = cfg.data;
  req.holdout = cfg.holdout;
  req.out = cfg.out;
  req.force = cfg.force;
  diag::DiagnoseOptions& o = req.options;
  o.calibration = calib::CalibrationOptions::fromStudy(study);
  cfg.calibration.applyTo(o.calibration);
  if (o.calibration.gibbs_burn_in >= o.calibration.gibbs_iterations)
    throw InputError("--burn-in", "must be below the number of iterations (" +
                                      std::to_string(o.calibration.gibbs_iterations) + ")");
  o.candidates = cfg.candidates;
  o.confirm_within = cfg.confirm_within;
  o.causes = cfg.causes;
  if (cfg.all_intervals) o.full_within = std::numeric_limits<double>::infinity();
  o.propose_terms = cfg.propose;
  o.compare_draws = cfg.draws;
  o.effects = splitCommas(cfg.effects);
  o.apply = splitCommas(cfg.apply);  // a .toml item (a proposal.toml) adds its [user_effects]
  o.threads = cfg.threads;
  o.processes = cfg.processes;
  o.command = command;
  // One run at a time in the folder (none without --out); on the root alone (command registry).
  const FolderLock lock(cfg.out, "--out", nullptr);
  ProgressBar bar("diagnose", progressOn(cfg.quiet, cfg.processes), stderrIsTerminal());
  std::string current;
  const auto progress = [&](const std::string& stage, std::size_t d, std::size_t t) {
    if (stage != current) {
      current = stage;
      bar.restart(stage);
    }
    bar.update(d, t);
  };
  const auto say = [&](const std::string& line) {
    if (!cfg.quiet) std::printf("%s\n", line.c_str());
  };
  const DiagnoseRun run = diagnoseMeasurements(study, req, say, progress);
  bar.finish();
  if (!cfg.quiet) std::printf("%s", run.result.text().c_str());
  if (run.written.empty()) return 0;
  if (!cfg.quiet) std::printf("\nwrote %s\n", run.written.c_str());
  for (const auto& line : run.pages)
    if (!cfg.quiet || line.rfind("note:", 0) == 0) std::printf("%s\n", line.c_str());
  return 0;
}

}  // namespace

CommandHandle addCompareCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<CompareConfig>();
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "compare");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option("--calibration", cfg->calibration,
                "Calibration folder (summary.json + posterior.csv) from `twin calibrate` "
                "(OUT/<id>) or `twin diagnose` "
                "(OUT/calibrations/<name>)")
      ->required();
  c->add_option("--data", cfg->data,
                "Measurement file FILE[@SCENARIO] (tidy lab layout); repeatable")
      ->required();
  c->add_option("--draws", cfg->draws, "Posterior rows (evenly spaced) for the predictive band")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  c->add_option("--baseline", cfg->baseline,
                "Also fit an FIR from the road under the wheels to each channel on this "
                "measurement file FILE[@SCENARIO] (the "
                "calibration drive), and print its fit % on --data beside the model's; repeatable");
  c->add_option("--discrepancy", cfg->discrepancy,
                "Also fit a filter from the road under the wheels (and the model's own prediction) "
                "to the model's residual on this "
                "measurement file FILE[@SCENARIO] "
                "(the calibration drive; its form chosen by cross-validation there), and print "
                "what the model misses band by band "
                "and the fit % of model + filter on --data beside the model's and the FIR "
                "baseline's (fitted on the same file "
                "unless --baseline names another); a prediction aid, not physics; repeatable");
  c->add_option("--threads", cfg->threads, "Worker threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  c->add_option("--out", cfg->out,
                "Folder for compare.json (the figures and the overlay series) and compare.html (an "
                "interactive page of every "
                "channel); default: print only");
  addForceOption(c, cfg->force);
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  addExamples(c, {"twin compare --study data/studies/demo.toml --calibration out/calibration/M3 "
                  "--data out/lab.csv --draws 5 --out out/compare"});
  return {c, [cfg, command_line] { return runCompare(*cfg, command_line); }};
}

CommandHandle addDiagnoseCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<DiagnoseConfig>();
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "diagnose");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option("--assembly", cfg->assembly, "Assembly id (M1, M2, ...)")->capture_default_str();
  c->add_option("--data", cfg->data,
                "Measurement file FILE[@SCENARIO] to fit (tidy lab layout); repeatable")
      ->required();
  c->add_option(
      "--holdout", cfg->holdout,
      "Held-out measurement file FILE[@SCENARIO] (not fitted; error reported); repeatable");
  c->add_option("--effects", cfg->effects,
                "Only rank these candidates (comma separated): effects, an effect at one corner "
                "(e.g. bump_stop@rr), "
                "free:<vehicle value> (e.g. free:wheel.mass_kg), a per-corner or per-axle factor "
                "(e.g. free:suspension.damping@rr) or "
                "<lowpass|lowpass2|gain|delay>:<channel group> (e.g. lowpass:hub_force), "
                "place:<sensor> (where a body sensor acts, "
                "e.g. place:seat) or a place of the road signal (e.g. free:road.fl_only); default: "
                "every effect not installed, "
                "every freeable vehicle value, the per-corner and per-axle factors, the effects of "
                "a part that wears at one strut at "
                "each corner, every sensor model, the place of each sensor not declared measured, "
                "and on a logged road its gain, "
                "delay and places (docs/diagnosis.md)");
  c->add_option("--apply", cfg->apply,
                "Add these candidates in turn (comma separated) and print the before/after table; "
                "a .toml file (e.g. a diagnosis's "
                "proposal.toml) adds its [user_effects]");
  c->add_option("--candidates", cfg->candidates,
                "The confirmation's budget: at most this many screened candidates re-calibrated "
                "(those within --confirm-within of the best "
                "screening score, then the best of each kind)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  c->add_option("--causes", cfg->causes,
                "At most this many causes named: while a significant lack of fit remains, the best "
                "cause is installed and the others "
                "screened and confirmed on top of it (1: the best candidate alone)")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  c->add_option("--confirm-within", cfg->confirm_within,
                "Confirm side by side every candidate whose screening score is within this factor "
                "of the best")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 1e6));
  c->add_flag("--all-intervals", cfg->all_intervals,
              "Calibrate every confirmed candidate in full (intervals, posterior comparison); by "
              "default only those within 10 of "
              "the best candidate's log evidence are, the others stop at their optimum");
  c->add_option("--propose", cfg->propose,
                "When unexplained: propose at most this many library terms (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 3));
  c->add_option("--draws", cfg->draws, "Posterior rows per comparison")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  c->add_option("--threads", cfg->threads, "Worker threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cfg->calibration.addTo(c, CalibrationFlags::kSizes | CalibrationFlags::kSteps);
  c->add_option("--out", cfg->out,
                "Folder (a rerun into it resumes): diagnosis.json, comparisons/, calibrations/, "
                "proposal.toml when unexplained, "
                "compare.html (the models overlaid) and report.html (needs gnuplot); without it "
                "the calibrations go to a temporary "
                "folder and only the printout remains");
  addForceOption(c, cfg->force);
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  addExamples(c, {"twin diagnose --study data/studies/demo.toml --assembly M1 --data "
                  "out/diag_bump.csv --lhs-points 20 --iterations 600 --burn-in 200 --starts 1 "
                  "--candidates 1 --causes 1 --propose 0 --out out/diagnosis"});
  CommandHandle handle{c, [cfg, command_line] { return runDiagnose(*cfg, command_line); }, {}};
  // Library errors name DiagnoseOptions fields and diagnose()'s arguments
  // ("diagnose.compare_draws"); the fields whose flag is not "--" + the field with '_' as '-':
  handle.field_flags["compare_draws"] = "--draws";
  CalibrationFlags::addFieldFlags(handle);
  handle.field_flags["fit"] = "--data";
  return handle;
}

}  // namespace dtwin::cli
