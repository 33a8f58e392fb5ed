// `twin calibrate`: Griddy Gibbs calibration of one or every assembly against a lab data file.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <utility>

#include "cli/calibration_flags.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/errors.hpp"
#include "common/folder_lock.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "study/calibrate.hpp"
#include "study/request.hpp"

namespace dtwin::cli {
namespace {

struct CalibrateConfig {
  std::string study = defaultStudy(), assembly = "all";
  CalibrateSettings settings;  ///< the flags bound to its fields; processes from CommandContext
  CalibrationFlags calibration;
  bool quiet = false;
};

int runCalibrate(const CalibrateConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  CalibrateSettings settings = cfg.settings;
  if (!settings.scenario.empty()) {  // the older shape --data FILE --scenario NAME
    checkDataScenario(settings.data, settings.scenario);
    deprecationNote("twin calibrate --data FILE --scenario NAME", "twin calibrate --data FILE@NAME",
                    settings.processes);
  }
  if (cfg.assembly != "all")
    for (auto& id : splitOn(cfg.assembly, ','))
      if (!id.empty()) settings.assemblies.push_back(std::move(id));
  settings.overrides = cfg.calibration;
  settings.command = command;
  // validated before anything is printed; main() shows a field as its flag (field_flags below)
  const CalibrateRequest req = calibrateRequest(study, settings);
  const FolderLock lock(settings.out, "--out",
                        settings.processes);  // one run at a time in the folder
  const bool bar_on = progressOn(cfg.quiet, settings.processes);
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

CommandHandle addCalibrateCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<CalibrateConfig>();
  cfg->settings.processes = context.processes;
  auto* c = addSubcommand(root, "calibrate");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option(
       "--data", cfg->settings.data,
       "Lab data FILE[@SCENARIO] (repetition,time_s,channel,value), e.g. from `twin generate lab`; "
       "SCENARIO: the "
       "study's scenario it was measured on (default: the one its JSON sidecar names, else lab)")
      ->required();
  c->add_option("--assembly", cfg->assembly,
                "Assembly ids (M1, M2, ...; comma separated or repeated) or 'all'")
      ->capture_default_str()
      ->delimiter(',')
      ->multi_option_policy(CLI::MultiOptionPolicy::Join);
  c->add_option("--scenario", cfg->settings.scenario, "Deprecated: give --data FILE@SCENARIO");
  c->add_option("--out", cfg->settings.out,
                "Output folder; each assembly writes OUT/<id>/ (summary.json, posterior.csv, "
                "design.csv, the stages' files); "
                "a rerun into it resumes")
      ->required();
  c->add_option(
       "--threads", cfg->settings.threads,
       "Worker threads per process (0: all cores, shared among the MPI ranks of a machine)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  c->add_option("--free", cfg->settings.free,
                "A fixed value calibrated too, over the range `twin diagnose` gives it (comma "
                "separated or repeated): a per-corner or "
                "per-axle factor such as suspension.damping@rr (over [0.2, 2]), or a vehicle value "
                "such as wheel.mass_kg (±50 %)")
      ->delimiter(',');
  cfg->calibration.addTo(c, CalibrationFlags::kSizes | CalibrationFlags::kRegion |
                                CalibrationFlags::kRounds | CalibrationFlags::kSteps);
  addSeedOption(c, cfg->settings.seed,
                "Seed of the design and the sampler (default: the study's seed)");
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success (no progress bar)");
  addForceOption(c, cfg->settings.force);
  addExamples(c, {"twin calibrate --study data/studies/demo.toml --data out/lab.csv --assembly M3 "
                  "--lhs-points 20 --iterations 600 --burn-in 200 --max-rounds 0 --ridge-steps 0 "
                  "--out out/calibration",
                  "twin calibrate --study data/studies/demo.toml --data out/lab.csv@lab --assembly "
                  "M4 --lhs-points 20 --iterations 600 --burn-in 200 --max-rounds 0 --ridge-steps "
                  "0 --out out/calibration",
                  "twin calibrate --study data/studies/demo.toml --data out/lab.csv --assembly M1 "
                  "--free suspension.damping@rr --lhs-points 20 --iterations 600 --burn-in 200 "
                  "--max-rounds 0 --ridge-steps 0 --out out/calibration_rr"});
  CommandHandle handle{c, [cfg, command_line] { return runCalibrate(*cfg, command_line); }, {}};
  CalibrationFlags::addFieldFlags(handle);
  return handle;
}

}  // namespace dtwin::cli
