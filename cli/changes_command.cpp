// `twin changes`: what changed between two calibrations of one car (two drives). Parses, calls
// study/changes.hpp (which writes changes.json and the page) and prints the list.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "study/changes.hpp"

namespace dtwin::cli {
namespace {

struct ChangesConfig {
  std::string before, after, out;
  std::vector<std::string> calibrations, dates;
  double level = 0.05;
  bool quiet = false;
};

int runChanges(const ChangesConfig& cfg, const std::string& command) {
  ChangesRequest req;
  req.before = cfg.before;
  req.after = cfg.after;
  req.out = cfg.out;
  req.level = cfg.level;
  req.command = command;
  req.calibrations = cfg.calibrations;
  req.dates = cfg.dates;
  const std::string text =
      cfg.calibrations.empty() ? detectChanges(req).text() : detectChangesOverDrives(req).text();
  if (!cfg.quiet) {
    std::printf("%s", text.c_str());
    if (!cfg.out.empty())
      std::printf("wrote %s, %s\n",
                  (std::filesystem::path(cfg.out) / "changes.json").string().c_str(),
                  (std::filesystem::path(cfg.out) / "changes.html").string().c_str());
  }
  return 0;
}

}  // namespace

CommandHandle addChangesCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<ChangesConfig>();
  auto* c = addSubcommand(root, "changes");
  c->add_option("--before", cfg->before,
                "The first drive's calibration folder (twin calibrate's OUT/<id>)");
  c->add_option("--after", cfg->after, "The second drive's calibration folder, of the same car");
  c->add_option("--calibrations", cfg->calibrations,
                "Instead of --before/--after: three or more calibration folders of one car, in "
                "any order (comma separated or repeated); ordered by their drives' dates")
      ->delimiter(',');
  c->add_option("--dates", cfg->dates,
                "With --calibrations: each drive's date YYYY-MM-DD[THH:MM:SS], in their order; "
                "default: the date of each calibration's data (twin import of a log with dated "
                "clock times)")
      ->delimiter(',');
  c->add_option(
      "--out", cfg->out,
      "Output folder: changes.json and changes.html (the list as a page); default: print only");
  c->add_option("--level", cfg->level,
                "Family-wise error rate of the significance rule (Holm over every value both "
                "calibrations hold)")
      ->capture_default_str()
      ->check(CLI::Range(1e-6, 0.49));
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  addExamples(c, {"twin changes --before out/coverage/M3/seed_1001 --after "
                  "out/coverage/M3/seed_1002 --out out/changes"});
  return CommandHandle{c, [cfg, command_line] { return runChanges(*cfg, command_line); }, {}};
}

}  // namespace dtwin::cli
