// `twin calibrate`: Griddy Gibbs calibration of one or every assembly against a lab data file.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "calibration/calibrate.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/json.hpp"
#include "common/errors.hpp"
#include "twin/distributed.hpp"
#include "io/measurement.hpp"
#include "io/provenance.hpp"
#include "io/study.hpp"

namespace fs = std::filesystem;

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
  study.scenario(cfg.scenario);  // validates the name
  if (!fs::exists(cfg.data)) throw InputError(cfg.data, "lab data file not found (--data)");
  const LabData data = readLabCsv(cfg.data, measurableChannels(study.sensors));
  std::vector<AssemblySpec> targets;
  if (cfg.assembly == "all") targets = study.assemblies();
  else targets.push_back(study.assembly(cfg.assembly));
  if (fs::exists(cfg.out) && !fs::is_directory(cfg.out)) throw InputError("--out", "'" + cfg.out + "' exists and is not a folder");
  {
    Study sized = study;
    overrideSize(sized, "lhs_points", cfg.lhs_points, "--lhs-points");
    overrideSize(sized, "gibbs_iterations", cfg.iterations, "--iterations");
    overrideSize(sized, "optimizer_starts", cfg.starts, "--starts");
    std::vector<std::string> stages;
    for (const auto& a : targets) stages.push_back("calibrate " + a.id);
    checkCommandWork(sized, stages, cfg.force);
  }

  calib::CalibrationOptions opt = calib::CalibrationOptions::fromStudy(study);
  opt.threads = cfg.threads;
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
  opt.command = command;
  opt.data_path = cfg.data;
  opt.validate();  // before anything is printed; main() shows a field as its flag (field_flags below)
  const std::string data_hash = std::to_string(calib::fnv1a64(readTextFile(cfg.data)));

  const bool bar_on = progressOn(cfg.quiet);
  if (!cfg.quiet) {
    const std::string rounds = opt.design.adaptive ? " + up to " + std::to_string(opt.design.max_rounds) + " adaptive rounds of " +
                                                         std::to_string(opt.designOptions().round_points)
                                                   : std::string();
    std::printf("calibrating %zu assembl%s against %s (%zu records): %d starts, %s region, %d design points%s, %d Gibbs iterations (%d burn-in)\n",
                targets.size(), targets.size() == 1 ? "y" : "ies", cfg.data.c_str(), data.records.size(), opt.optimizer_starts,
                opt.region.c_str(), opt.lhs_points, rounds.c_str(), opt.gibbs_iterations, opt.gibbs_burn_in);
  }
  nlohmann::json index;
  index["program"] = programInfo();
  index["command"] = command;
  index["created_utc"] = utcNow();
  index["study"] = study.path;
  index["data"] = cfg.data;
  for (const auto& a : targets) {
    ProgressBar bar(a.id, bar_on, stderrIsTerminal());
    std::string current;
    auto progress = [&](const std::string& stage, std::size_t done, std::size_t total) {
      if (stage != current) {
        current = stage;
        bar.restart(a.id + " " + stage);
      }
      bar.update(done, total);
    };
    const std::string dir = (fs::path(cfg.out) / a.id).string();
    const calib::CalibrationResult r = calibrateAssembly(study, a, data, cfg.scenario, opt, dir, data_hash, progress);
    bar.finish();
    index["assemblies"].push_back({{"assembly", a.id}, {"label", a.label()}, {"summary", (fs::path(a.id) / "summary.json").string()}});
    if (!cfg.quiet) {
      std::printf("%-4s %-26s SSE_min %.4g  tau %.3g (noise var %.0f N^2)  design %ld points in %zu round%s (importance ESS %.0f)  "
                  "distinct points %d  top share %.2f  failures %ld  %.1f s\n",
                  a.id.c_str(), a.label().c_str(), r.optimum.sse, r.posterior.tau.mean,
                  r.posterior.tau.mean > 0 ? 1.0 / r.posterior.tau.mean : 0.0, static_cast<long>(r.design.rows()),
                  r.rounds.rounds.size(), r.rounds.rounds.size() == 1 ? "" : "s", r.rounds.ess, r.posterior.distinct_points,
                  r.posterior.top_share, r.design_failures, r.stage_wall_s.back().second);
      for (std::size_t k = 0; k < r.names.size(); ++k) {
        const auto& p = r.posterior.parameters[k];
        const std::string truth = r.truth[k] ? " truth " + formatExact(*r.truth[k]) : std::string();
        if (k < r.profile.lower.size())
          std::printf("       %-22s mean %-11.5g sd %-10.4g 95%% %s [%.5g, %.5g], %s [%.5g, %.5g]%s\n", r.names[k].c_str(), p.mean, p.sd,
                      r.interval == "profile" ? "profile" : "posterior", r.interval == "profile" ? r.profile.lower[k] : p.q025,
                      r.interval == "profile" ? r.profile.upper[k] : p.q975, r.interval == "profile" ? "posterior" : "profile",
                      r.interval == "profile" ? p.q025 : r.profile.lower[k], r.interval == "profile" ? p.q975 : r.profile.upper[k],
                      truth.c_str());
        else
          std::printf("       %-22s mean %-11.5g sd %-10.4g 95%% [%.5g, %.5g]%s\n", r.names[k].c_str(), p.mean, p.sd, p.q025, p.q975, truth.c_str());
      }
      if (r.posterior.design_too_coarse) std::printf("       note: %s\n", r.posterior.message.c_str());
      for (const auto& w : r.rounds.warnings) std::printf("       note: %s\n", w.c_str());
      for (const auto& m : r.region.messages) std::printf("       note: %s\n", m.c_str());
      if (r.design_failures) std::printf("       note: %ld design simulations failed (SSE = inf, weight 0)\n", r.design_failures);
      if (!r.integrator.ok) std::printf("       note: %s\n", r.integrator.message.c_str());
    }
  }
  rootWrites([&] { writeFileAtomic((fs::path(cfg.out) / "calibration.json").string(), index.dump(2) + "\n"); });
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
