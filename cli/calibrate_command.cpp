// `twin calibrate`: Griddy Gibbs calibration of one or every assembly against a lab data file.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "study/calibrate.hpp"

namespace dtwin::cli {
namespace {

struct CalibrateConfig {
  std::string study = defaultStudy(), data, assembly = "all", scenario = "lab", out, region, design, interval, steps;
  int threads = 0;
  long lhs_points = -1, iterations = -1, burn_in = -1, starts = -1, max_rounds = -1, ridge_steps = -1;
  std::optional<std::uint64_t> seed;  ///< unset: the study's
  bool quiet = false, force = false;
};

int runCalibrate(const CalibrateConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  CalibrateRequest req;
  req.data = cfg.data;
  if (cfg.assembly != "all") req.assemblies = {cfg.assembly};
  req.scenario = cfg.scenario;
  req.out = cfg.out;
  req.command = command;
  calib::CalibrationOptions& opt = req.options;
  opt = calib::CalibrationOptions::fromStudy(study);
  opt.threads = cfg.threads;
  opt.processes = commandProcesses();
  if (cfg.lhs_points > 0) opt.lhs_points = static_cast<int>(cfg.lhs_points);
  if (cfg.iterations > 0) opt.gibbs_iterations = static_cast<int>(cfg.iterations);
  if (cfg.burn_in >= 0) opt.gibbs_burn_in = static_cast<int>(cfg.burn_in);
  if (cfg.starts > 0) opt.optimizer_starts = static_cast<int>(cfg.starts);
  if (cfg.seed) opt.seed = *cfg.seed;
  if (!cfg.region.empty()) {
    opt.region = cfg.region;
    if (cfg.design.empty()) opt.design.adaptive = cfg.region == "joint";  // the region's default design
  }
  if (!cfg.design.empty()) opt.design.adaptive = cfg.design == "adaptive";
  if (!cfg.interval.empty()) opt.interval = cfg.interval;
  if (!cfg.steps.empty()) opt.steps = cfg.steps;
  if (cfg.max_rounds >= 0) opt.design.max_rounds = static_cast<int>(cfg.max_rounds);
  if (cfg.ridge_steps >= 0) opt.joint.ridge_steps = static_cast<int>(cfg.ridge_steps);
  req.validate(study);  // before anything is printed; main() shows a field as its flag (field_flags below)
  {
    Study sized = study;
    overrideSize(sized, "lhs_points", cfg.lhs_points, "--lhs-points");
    overrideSize(sized, "gibbs_iterations", cfg.iterations, "--iterations");
    overrideSize(sized, "optimizer_starts", cfg.starts, "--starts");
    std::vector<std::string> stages;
    for (const auto& a : calibrationTargets(study, req)) stages.push_back("calibrate " + a.id);
    checkCommandWork(sized, stages, cfg.force);
  }
  const bool bar_on = progressOn(cfg.quiet);
  std::unique_ptr<ProgressBar> bar;
  std::string current;
  const auto progress_of = [&](const AssemblySpec& a) -> StageProgress {
    bar = std::make_unique<ProgressBar>(a.id, bar_on, stderrIsTerminal());
    current.clear();
    return [&, id = a.id](const std::string& stage, std::size_t done, std::size_t total) {
      if (stage != current) {
        current = stage;
        bar->restart(id + " " + stage);
      }
      bar->update(done, total);
    };
  };
  const auto say = [&](const std::string& line) {
    if (!cfg.quiet) std::printf("%s\n", line.c_str());
  };
  calibrateAssemblies(study, req, say, progress_of, [&](const CalibrateRun& run) {
    bar->finish();
    if (!cfg.quiet) std::printf("%s", run.text().c_str());
  });
  return 0;
}

}  // namespace

CommandHandle addCalibrateCommand(CLI::App& root, const std::string& command_line) {
  auto cfg = std::make_shared<CalibrateConfig>();
  auto* c = addSubcommand(root, "calibrate");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option("--data", cfg->data, "Lab data CSV (repetition,time_s,channel,value), e.g. from `twin generate lab`")->required();
  c->add_option("--assembly", cfg->assembly, "Assembly id (M1, M2, ...) or 'all'")->capture_default_str();
  c->add_option("--scenario", cfg->scenario, "Scenario the lab data was measured on")->capture_default_str();
  c->add_option("--out", cfg->out, "Output folder; each assembly writes OUT/<id>/")->required();
  c->add_option("--threads", cfg->threads, "Worker threads per process (0: all cores, shared among the MPI ranks of a machine)")->capture_default_str()->check(CLI::Range(0, 1024));
  c->add_option("--lhs-points", cfg->lhs_points, "Design points (default: the study's sizes.lhs_points)")->check(CLI::Range(2L, 10000000L));
  c->add_option("--iterations", cfg->iterations, "Gibbs iterations incl. burn-in (default: sizes.gibbs_iterations)")
      ->check(CLI::Range(1L, 100000000L));
  c->add_option("--burn-in", cfg->burn_in, "Gibbs burn-in (default: sizes.gibbs_burn_in)")->check(CLI::Range(0L, 100000000L));
  c->add_option("--starts", cfg->starts, "Optimiser starts (default: sizes.optimizer_starts)")->check(CLI::Range(1L, 10000L));
  c->add_option("--region", cfg->region,
                 "Region the design covers: joint (the joint 1 % likelihood-ratio contour, default) or paper (the paper's "
                 "one-at-a-time box); default: the study's [calibration] region")
      ->check(CLI::IsMember({"joint", "paper"}));
  c->add_option("--interval", cfg->interval,
                "The 95 % interval printed as ci95: profile (the profile-likelihood interval, default) or posterior (the "
                "posterior's central interval); both are in summary.json. Default: the study's [calibration] interval")
      ->check(CLI::IsMember({"profile", "posterior"}));
  c->add_option("--design", cfg->design,
                "adaptive (a Latin hypercube, then rounds where the posterior lies) or lhs (one Latin hypercube); "
                "default: the study's [calibration] design (adaptive for joint, lhs for paper)")
      ->check(CLI::IsMember({"adaptive", "lhs"}));
  c->add_option("--max-rounds", cfg->max_rounds, "Adaptive design rounds after the first Latin hypercube (default: the study's "
                                                 "[calibration] max_rounds)")
      ->check(CLI::Range(0L, 100L));
  c->add_option("--steps", cfg->steps,
                "frozen (one integrator step sequence per stage: a smooth SSE, the accuracy chosen from the data) or adaptive "
                "(each run chooses its steps); default: the study's [calibration] steps")
      ->check(CLI::IsMember({"frozen", "adaptive"}));
  c->add_option("--ridge-steps", cfg->ridge_steps, "Steps per ridge trace of the joint region, 0: none (default: the study's "
                                                   "[calibration] ridge_steps)")
      ->check(CLI::Range(0L, 1000L));
  addSeedOption(c, cfg->seed, "Seed of the design and the sampler (default: the study's seed)");
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success (no progress bar)");
  addForceOption(c, cfg->force);
  CommandHandle handle{c, [cfg, command_line] { return runCalibrate(*cfg, command_line); }, {}};
  // Library errors name CalibrationOptions fields ("calibration.gibbs_burn_in"); the fields whose
  // flag is not "--" + the field with '_' as '-':
  handle.field_flags["gibbs_iterations"] = "--iterations";
  handle.field_flags["gibbs_burn_in"] = "--burn-in";
  handle.field_flags["optimizer_starts"] = "--starts";
  return handle;
}

}  // namespace dtwin::cli
