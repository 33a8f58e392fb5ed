// `twin report [--study-dir DIR] [--diagnosis DIR]... [--out DIR]`: a self-contained HTML report
// (DIR/report.html) of a study folder, with the diagnosis sections appended; or of diagnosis
// folders alone.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "study/report.hpp"

namespace dtwin::cli {
namespace {

struct ReportConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string dir, positional, out;
  std::vector<std::string> diagnoses;
  int draws = 50, threads = 0;
  bool quiet = false;
};

/// The page's path: OUT/report.html for --out OUT; the older --out FILE.html as is (with a
/// note); without --out, report.html in `default_dir`.
std::string reportPath(const std::string& out, const std::string& default_dir,
                       const Distributed* processes) {
  if (out.empty()) return (std::filesystem::path(default_dir) / "report.html").string();
  if (std::filesystem::path(out).extension() == ".html") {
    deprecationNote("twin report --out FILE.html", "twin report --out DIR (writes DIR/report.html)",
                    processes);
    return out;
  }
  if (std::filesystem::exists(out) && !std::filesystem::is_directory(out))
    throw InputError("--out", "'" + out + "' exists and is not a folder");
  return (std::filesystem::path(out) / "report.html").string();
}

int runReportCommand(ReportConfig cfg, const std::string& command) {
  if (!cfg.positional.empty()) {  // the older shape `twin report STUDY_DIR`
    if (!cfg.dir.empty())
      throw InputError("--study-dir", "give the study folder once (--study-dir DIR)");
    deprecationNote("twin report STUDY_DIR", "twin report --study-dir STUDY_DIR", cfg.processes);
    cfg.dir = cfg.positional;
  }
  study::ReportRequest req;
  req.study_dir = cfg.dir;
  req.diagnoses = cfg.diagnoses;
  if (!cfg.dir.empty() || !cfg.diagnoses.empty())
    req.page = reportPath(cfg.out, cfg.dir.empty() ? cfg.diagnoses[0] : cfg.dir, cfg.processes);
  req.draws = cfg.draws;
  req.threads = cfg.threads;
  req.command = command;
  const study::ReportRun r = study::writeReport(req);
  for (const auto& w : r.warnings) std::fprintf(stderr, "twin report: warning: %s\n", w.c_str());
  if (!cfg.quiet) {
    std::printf("report: %s (%d plots, %.1f s)\n", r.page.c_str(), r.svg_count, r.wall_s);
    if (!r.interactive.empty()) std::printf("interactive lab view: %s\n", r.interactive.c_str());
  }
  return 0;
}

}  // namespace

CommandHandle addReportCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<ReportConfig>();
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "report");
  c->add_option("--study-dir", cfg->dir,
                "Study folder written by `twin study --out` (optional with --diagnosis)")
      ->check(CLI::ExistingDirectory);
  c->add_option("study_dir", cfg->positional, "Deprecated: give --study-dir DIR")
      ->check(CLI::ExistingDirectory);
  c->add_option("--diagnosis", cfg->diagnoses,
                "Folder written by `twin diagnose --out` (repeatable): its section is appended to "
                "the study report, or, "
                "without --study-dir, makes a diagnosis-only report")
      ->take_all()
      ->allow_extra_args(false);
  c->add_option("--out", cfg->out,
                "Output folder: OUT/report.html and, with a study, OUT/report_lab.html (the "
                "interactive lab view); default: "
                "the study folder, or the first --diagnosis folder");
  c->add_option("--draws", cfg->draws,
                "Posterior rows per assembly for the predictive band (evenly spaced)")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  c->add_option("--threads", cfg->threads,
                "Simulations in parallel (0: all cores; never changes the page)")
      ->check(CLI::Range(0, 1024));
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  addExamples(c, {"twin report --study-dir out/study --draws 4 --out out/report"});
  CommandHandle handle{c, [cfg, command_line] { return runReportCommand(*cfg, command_line); }, {}};
  // Library errors name fields ("lab_bands.draws" is --draws); the ones whose flag is not "--" +
  // the field with '_' as '-':
  handle.field_flags["diag_dirs"] = "--diagnosis";
  return handle;
}

}  // namespace dtwin::cli
