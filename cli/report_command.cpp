// `twin report STUDY_DIR [--out FILE.html]`: a self-contained HTML report of a study folder.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "classification/report.hpp"
#include "cli/commands.hpp"

namespace dtwin::cli {
namespace {

struct ReportConfig {
  std::string dir, out;
  int draws = 50, threads = 0;
  bool quiet = false;
};

int runReportCommand(const ReportConfig& cfg, const std::string& command) {
  const std::string out = cfg.out.empty() ? (std::filesystem::path(cfg.dir) / "report.html").string() : cfg.out;
  classify::ReportOptions o;
  o.draws = cfg.draws;
  o.threads = cfg.threads;
  const auto r = classify::writeStudyReport(cfg.dir, out, command, o);
  for (const auto& w : r["warnings"]) std::fprintf(stderr, "twin report: warning: %s\n", w.get<std::string>().c_str());
  if (!cfg.quiet) std::printf("report: %s (%d plots, %.1f s)\n", out.c_str(), r["svg_count"].get<int>(), r["wall_s"].get<double>());
  return 0;
}

}  // namespace

CommandHandle addReportCommand(CLI::App& root, const std::string& command_line) {
  auto cfg = std::make_shared<ReportConfig>();
  auto* c = root.add_subcommand("report",
                                "Write a self-contained HTML report of a study folder (lab data vs posterior predictive bands, "
                                "posteriors, field-record selection, evidence vs cost, provenance); needs gnuplot");
  c->add_option("study_dir", cfg->dir, "Study folder written by `twin study`")->required()->check(CLI::ExistingDirectory);
  c->add_option("--out", cfg->out, "HTML file (default: STUDY_DIR/report.html)");
  c->add_option("--draws", cfg->draws, "Posterior rows per assembly for the predictive band (evenly spaced)")
      ->capture_default_str()->check(CLI::Range(2, 100000));
  c->add_option("--threads", cfg->threads, "Simulations in parallel (0: all cores; never changes the page)")->check(CLI::Range(0, 1024));
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  return {c, [cfg, command_line] { return runReportCommand(*cfg, command_line); }};
}

}  // namespace dtwin::cli
