// `twin study --study STUDY.toml --out DIR`: the whole method end to end, resumable.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/errors.hpp"
#include "common/folder_lock.hpp"
#include "study/request.hpp"
#include "study/run.hpp"

namespace dtwin::cli {
namespace {

struct StudyConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string study = defaultStudy(), positional, out = "out/study", lab, field;
  int threads = 0;
  bool quiet = false, force = false;
};

int runStudyCommand(const StudyConfig& cfg, const std::string& command,
                    const CLI::Option* study_flag) {
  std::string study_file = cfg.study;
  if (!cfg.positional.empty()) {  // the older shape `twin study FILE`
    if (study_flag->count() > 0)
      throw InputError("--study", "give the study file once (--study FILE)");
    deprecationNote("twin study FILE", "twin study --study FILE", cfg.processes);
    study_file = cfg.positional;
  }
  const Study study = loadStudy(study_file);
  study::StudyRunOptions o;
  o.threads = cfg.threads;
  o.processes = cfg.processes;
  o.lab_file = cfg.lab;
  o.field_file = cfg.field;
  o.command = command;
  study::checkStudyWork(study, o, cfg.force);
  const FolderLock lock(cfg.out, "--out", cfg.processes);  // one run at a time in the folder
  ProgressBar bar("study", progressOn(cfg.quiet, cfg.processes), stderrIsTerminal());
  std::string current;
  auto progress = [&](const std::string& stage, std::size_t d, std::size_t t) {
    if (stage != current) {
      current = stage;
      bar.restart(stage);
    }
    bar.update(d, t);
  };
  auto log = [&](const std::string& line) {
    if (cfg.quiet) return;
    bar.finish();
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  };
  const auto s = study::runStudy(study, o, cfg.out, progress, log);
  bar.finish();
  if (!cfg.quiet &&
      isRootProcess(cfg.processes)) {  // under MPI the other ranks do not run the classification
    std::fputs(study::summaryText(s, cfg.out).c_str(), stdout);
  }
  return 0;
}

}  // namespace

CommandHandle addStudyCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<StudyConfig>();
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "study");
  auto* study_flag =
      c->add_option("--study", cfg->study, "Study file (TOML); default: the embedded demo study")
          ->capture_default_str();
  c->add_option("study_file", cfg->positional, "Deprecated: give --study FILE");
  c->add_option("--out", cfg->out,
                "Study folder (created; a rerun into it resumes): summary.json, study.json, lab/, "
                "field/, calibration/, synthetic/, "
                "classification/")
      ->capture_default_str();
  c->add_option("--lab", cfg->lab, "Use these lab data (CSV) instead of generating them");
  c->add_option("--field", cfg->field,
                "Use these field records (CSV matrix) instead of generating them");
  c->add_option("--threads", cfg->threads,
                "Worker threads (0: all cores; never changes the numbers)")
      ->check(CLI::Range(0, 1024));
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success (no progress bar)");
  addForceOption(c, cfg->force);
  addExamples(c, {"twin study --study data/studies/demo.toml --out out/study"});
  return {c, [cfg, command_line, study_flag] {
            return runStudyCommand(*cfg, command_line, study_flag);
          }};
}

}  // namespace dtwin::cli
