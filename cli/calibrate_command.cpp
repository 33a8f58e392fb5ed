// `twin calibrate`: Griddy Gibbs calibration of one or every assembly against a lab data file.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <tuple>
#include <utility>

#include "cli/calibration_flags.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/errors.hpp"
#include "common/folder_lock.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "diagnosis/measurements.hpp"
#include "io/provenance.hpp"
#include "study/calibrate.hpp"

namespace dtwin::cli {
namespace {

struct CalibrateConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string study = defaultStudy(), data, assembly = "all", scenario, out;
  std::vector<std::string> free;  ///< --free: fixed values calibrated too
  int threads = 0;
  CalibrationFlags calibration;
  std::optional<std::uint64_t> seed;  ///< unset: the study's
  bool quiet = false, force = false;
};

/// The lab data file and its scenario: --data FILE[@SCENARIO] (calibrationData,
/// study/calibrate.hpp). The older --scenario NAME is still accepted, with a note.
std::pair<std::string, std::string> calibrationDataOf(const CalibrateConfig& cfg) {
  if (cfg.scenario.empty()) return calibrationData(cfg.data, "--data");
  const diag::MeasurementSpec spec = diag::parseMeasurementArg(cfg.data, "--data");
  if (!spec.scenario.empty() && spec.scenario != cfg.scenario)
    throw InputError("--scenario", "'" + cfg.scenario + "' differs from the scenario of --data " +
                                       cfg.data + ": give it once, as --data FILE@SCENARIO");
  deprecationNote("twin calibrate --data FILE --scenario NAME", "twin calibrate --data FILE@NAME",
                  cfg.processes);
  return calibrationData(cfg.data, "--data", cfg.scenario);
}

int runCalibrate(const CalibrateConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  CalibrateRequest req;
  std::tie(req.data, req.scenario) = calibrationDataOf(cfg);
  if (cfg.assembly != "all")
    for (auto& id : splitOn(cfg.assembly, ','))
      if (!id.empty()) req.assemblies.push_back(std::move(id));
  req.out = cfg.out;
  req.free = cfg.free;
  req.command = command;
  calib::CalibrationOptions& opt = req.options;
  opt = calib::CalibrationOptions::fromStudy(study);
  opt.threads = cfg.threads;
  opt.processes = cfg.processes;
  if (cfg.seed) opt.seed = *cfg.seed;
  cfg.calibration.applyTo(opt);
  req.validate(
      study);  // before anything is printed; main() shows a field as its flag (field_flags below)
  checkCalibrateWork(study, req, cfg.calibration, cfg.force);
  const FolderLock lock(cfg.out, "--out", cfg.processes);  // one run at a time in the folder
  const bool bar_on = progressOn(cfg.quiet, cfg.processes);
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
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "calibrate");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option(
       "--data", cfg->data,
       "Lab data FILE[@SCENARIO] (repetition,time_s,channel,value), e.g. from `twin generate lab`; "
       "SCENARIO: the "
       "study's scenario it was measured on (default: the one its JSON sidecar names, else lab)")
      ->required();
  c->add_option("--assembly", cfg->assembly,
                "Assembly ids (M1, M2, ...; comma separated or repeated) or 'all'")
      ->capture_default_str()
      ->delimiter(',')
      ->multi_option_policy(CLI::MultiOptionPolicy::Join);
  c->add_option("--scenario", cfg->scenario, "Deprecated: give --data FILE@SCENARIO");
  c->add_option("--out", cfg->out,
                "Output folder; each assembly writes OUT/<id>/ (summary.json, posterior.csv, "
                "design.csv, the stages' files); "
                "a rerun into it resumes")
      ->required();
  c->add_option(
       "--threads", cfg->threads,
       "Worker threads per process (0: all cores, shared among the MPI ranks of a machine)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  c->add_option("--free", cfg->free,
                "A fixed value calibrated too, over the range `twin diagnose` gives it (comma "
                "separated or repeated): a per-corner or "
                "per-axle factor such as suspension.damping@rr (over [0.2, 2]), or a vehicle value "
                "such as wheel.mass_kg (±50 %)")
      ->delimiter(',');
  cfg->calibration.addTo(c, CalibrationFlags::kSizes | CalibrationFlags::kRegion |
                                CalibrationFlags::kRounds | CalibrationFlags::kSteps);
  addSeedOption(c, cfg->seed, "Seed of the design and the sampler (default: the study's seed)");
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success (no progress bar)");
  addForceOption(c, cfg->force);
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
