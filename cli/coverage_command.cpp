// `twin coverage`: how often the calibration's 95 % intervals hold the truth, over noise seeds
// (study/coverage.hpp, docs/calibration.md).
#include <cstdio>
#include <memory>

#include "cli/calibration_flags.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/errors.hpp"
#include "common/folder_lock.hpp"
#include "study/coverage.hpp"
#include "study/request.hpp"

namespace dtwin::cli {
namespace {

struct CoverageConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string study = defaultStudy(), out;
  std::vector<std::string> assemblies;
  int seeds = 20, threads = 0;
  long long first_seed = 1001;
  CalibrationFlags calibration;
  bool quiet = false, force = false;
};

int runCoverage(const CoverageConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  calib::CoverageOptions given;
  given.seeds = cfg.seeds;
  given.first_seed = static_cast<std::uint64_t>(cfg.first_seed);
  given.assemblies = cfg.assemblies;
  given.out_dir = cfg.out;
  given.command = command;
  given.calibration.threads = cfg.threads;
  given.calibration.processes = cfg.processes;
  // checked before anything is printed; main() shows a field as its flag (field_flags below)
  const calib::CoverageOptions o = calib::coverageOptions(study, given, cfg.calibration, cfg.force);
  const FolderLock lock(
      cfg.out, "--out",
      nullptr);  // one run at a time in the folder (on the root alone: command registry)
  if (!cfg.quiet) std::fputs(calib::coveragePlan(study, o).c_str(), stdout);
  const bool bar_on = progressOn(cfg.quiet, cfg.processes);
  ProgressBar bar("coverage", bar_on, stderrIsTerminal());
  std::string current;
  const calib::CoverageResult r =
      calib::runCoverage(study, o,
                         [&](const std::string& a, std::uint64_t seed, int index, int count,
                             const std::string& stage, std::size_t done, std::size_t total) {
                           const std::string label = a + " seed " + std::to_string(seed) + " (" +
                                                     std::to_string(index + 1) + "/" +
                                                     std::to_string(count) + ") " + stage;
                           if (label != current) {
                             current = label;
                             bar.restart(label);
                             if (!stderrIsTerminal() && !cfg.quiet && stage == "lab data")
                               std::printf("  %s\n", label.c_str()), std::fflush(stdout);
                           }
                           bar.update(done, total);
                         });
  bar.finish();
  if (!cfg.quiet) std::fputs(calib::coverageText(r, cfg.out).c_str(), stdout);
  return 0;
}

}  // namespace

CommandHandle addCoverageCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<CoverageConfig>();
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "coverage");
  c->add_option("--study", cfg->study,
                "Study file (TOML); its calibrated truths are what is covered")
      ->capture_default_str();
  c->add_option("--out", cfg->out,
                "Output folder (a rerun into it resumes): <id>/lab_<seed>.csv + .json, "
                "<id>/seed_<seed>/, coverage.json, coverage.md")
      ->required();
  c->add_option("--assembly", cfg->assemblies,
                "Assembly ids (comma separated or repeated; default: all)")
      ->delimiter(',');
  c->add_option("--seeds", cfg->seeds, "Number of noise seeds N")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  c->add_option("--first-seed", cfg->first_seed,
                "Noise seed of the first data set (seeds first .. first + N - 1)")
      ->capture_default_str()
      ->check(CLI::Range(0LL, (1LL << 62)));
  c->add_option("--threads", cfg->threads, "Worker threads (0: all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cfg->calibration.addTo(c, CalibrationFlags::kSizes | CalibrationFlags::kRegion);
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  addForceOption(c, cfg->force);
  addExamples(c, {"twin coverage --study data/studies/demo.toml --assembly M3 --seeds 2 --region "
                  "paper --lhs-points 20 --iterations 600 --burn-in 200 --out out/coverage"});
  CommandHandle handle{c, [cfg, command_line] { return runCoverage(*cfg, command_line); }, {}};
  // Library errors name CoverageOptions and CalibrationOptions fields ("coverage.out_dir",
  // "calibration.gibbs_burn_in"); the fields whose flag is not "--" + the field with '_' as '-':
  handle.field_flags["out_dir"] = "--out";
  CalibrationFlags::addFieldFlags(handle);
  return handle;
}

}  // namespace dtwin::cli
