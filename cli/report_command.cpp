// `twin report [--study-dir DIR] [--diagnosis DIR]... [--out DIR]`: a self-contained HTML report
// (DIR/report.html) of a study folder, with the diagnosis sections appended; or of diagnosis
// folders alone.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "report/diagnosis_report.hpp"
#include "report/study_report.hpp"
#include "report/svg_plot.hpp"
#include "study/lab_bands.hpp"

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
  if (cfg.dir.empty() && cfg.diagnoses.empty())
    throw InputError("twin report",
                     "give a study folder (--study-dir DIR), --diagnosis DIR, or both");
  if (cfg.dir.empty()) {  // diagnosis-only page
    const std::string out = reportPath(cfg.out, cfg.diagnoses[0], cfg.processes);
    const auto r = report::writeDiagnosisReport(cfg.diagnoses, out, command);
    for (const auto& w : r["warnings"])
      std::fprintf(stderr, "twin report: warning: %s\n", w.get<std::string>().c_str());
    if (!cfg.quiet)
      std::printf("report: %s (%d plots, %.1f s)\n", out.c_str(), r["svg_count"].get<int>(),
                  r["wall_s"].get<double>());
    return 0;
  }
  const std::string out = reportPath(cfg.out, cfg.dir, cfg.processes);
  report::requireGnuplot("`twin report`");  // before any simulation
  report::ReportOptions o;
  std::vector<std::string> diag_warnings;
  for (std::size_t k = 0; k < cfg.diagnoses.size();
       ++k) {  // read (and checked) before the study's simulations
    report::DiagnosisSectionOptions so;
    so.anchor = "diagnosis-" + std::to_string(k + 1);
    so.id_prefix = "d" + std::to_string(k + 1) + "p";
    so.heading_prefix = std::to_string(6 + k) + ". ";
    nlohmann::json drawn;
    report::ReportSection s;
    s.html = report::diagnosisSectionHtml(cfg.diagnoses[k], so, &drawn);
    s.id = so.anchor;
    s.title = "Diagnosis: " + cfg.diagnoses[k];
    s.svg_count = drawn["svg_count"].get<int>();
    for (const auto& w : drawn["warnings"]) diag_warnings.push_back(w.get<std::string>());
    o.appendix.push_back(std::move(s));
  }
  study::LabBandOptions bo;
  bo.draws = cfg.draws;
  bo.threads = cfg.threads;
  const study::LabBands bands = study::predictLabBands(cfg.dir, bo);
  const auto r = report::writeStudyReport(bands, cfg.dir, out, command, o);
  for (const auto& w : r["warnings"])
    std::fprintf(stderr, "twin report: warning: %s\n", w.get<std::string>().c_str());
  for (const auto& w : diag_warnings) std::fprintf(stderr, "twin report: warning: %s\n", w.c_str());
  if (!cfg.quiet) {
    std::printf("report: %s (%d plots, %.1f s)\n", out.c_str(), r["svg_count"].get<int>(),
                r["wall_s"].get<double>());
    if (r["interactive"].is_string())
      std::printf("interactive lab view: %s\n", r["interactive"].get<std::string>().c_str());
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
