#pragma once
// The `twin` subcommands. Each lives in its own file and registers itself on the root CLI::App;
// main() parses once and runs the chosen one. The CLI only parses, validates and calls.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "common/distributed.hpp"
#include "common/registry.hpp"

namespace dtwin::cli {

/// A registered subcommand: `run` is called when `app` was chosen on the command line.
/// Library errors name option fields ("diagnose.effects", common/validate.hpp), never flags;
/// main() shows them as the flag the user typed: the field's entry in `field_flags` if any
/// (field name -> flag), else "--" + the field with '_' as '-' when the command has that flag.
struct CommandHandle {
  CLI::App* app = nullptr;
  std::function<int()> run;
  std::map<std::string, std::string> field_flags = {};
};

/// A registry entry of a subcommand: what adds it to the root application (its options and what it
/// runs), and whether it runs on every MPI rank (the commands that spread simulations,
/// common/distributed.hpp) rather than on the root alone.
/// What a command runs in, passed to it explicitly: the command line as typed (recorded in every
/// output) and the process context main() created (common/distributed.hpp: the MPI ranks).
struct CommandContext {
  std::string command_line;
  const Distributed* processes = nullptr;  ///< nullptr: this process alone
};

struct CommandEntry {
  CommandHandle (*add)(CLI::App& root, const CommandContext& context);
  bool distributed = false;
  const char* group =
      "";  ///< the heading `twin --help` lists the command under (a task, kCommandGroups)
  const char* task = "";   ///< one line: what the command is for, as `twin --help` shows it
  bool resumable = false;  ///< a rerun of the same command continues where a stopped one ended
};
/// The headings of `twin --help`, in order.
inline const char* const kCommandGroups[] = {"Simulate, calibrate and choose an assembly",
                                             "Measured drives", "Tools"};
/// Every subcommand, in the order `twin --help` lists them (cli/command_registry.cpp).
const Registry<CommandEntry>& commandRegistry();
/// The grouped overview `twin --help`, `twin help` and `twin` alone print.
std::string topLevelHelp();
/// The subcommand `name` on `root`, with its registry description.
CLI::App* addSubcommand(CLI::App& root, const std::string& name);

/// The message of an InputError as the user of command `handle` should read it: where() of the
/// form "<options>.<field>" becomes the flag that sets the field, when there is one.
std::string messageForCommand(const CommandHandle& handle, const std::string& where,
                              const std::string& rule);

/// The embedded default study (data/studies/demo.toml in the source tree, else in the install
/// prefix this program runs from: <prefix>/share/dtwin/data, found beside bin/twin wherever the
/// prefix was moved, else the prefix it was configured for).
std::string defaultStudy();
/// Where the installed documentation is: <prefix>/share/doc/dtwin beside the running program when
/// it is there, else the configured prefix's.
std::string installedDocDir();
/// The command line as one string, recorded in every output.
std::string joinArgs(int argc, char** argv);
/// The `--seed` option of every command: an integer in [0, 2^64 - 1], written as digits (anything
/// else, a sign or an overflow included, is a one-line parse error); unset means the study's seed.
CLI::Option* addSeedOption(CLI::App* app, std::optional<std::uint64_t>& seed,
                           const std::string& help);
/// The `--force` flag of the commands that run many simulations (io/work.hpp).
void addForceOption(CLI::App* app, bool& force);
/// "twin: note: `OLD` is deprecated; use `NEW`" on stderr (by the root rank): an older shape of
/// a command line that is still accepted, and gives the same results.
void deprecationNote(const std::string& old_shape, const std::string& new_shape,
                     const Distributed* processes);
/// The "Examples:" section at the end of a command's --help: one command a line, each runnable as
/// written from the root of the source tree (tests/cli/help_examples_test.cpp runs them).
void addExamples(CLI::App* app, const std::vector<std::string>& examples);
/// True when stderr is a terminal (progress bars are drawn only then).
bool stderrIsTerminal();
/// Progress is shown unless --quiet, and only by the root rank under MPI (cli/progress.hpp).
bool progressOn(bool quiet, const Distributed* processes);

CommandHandle addSimulateCommand(CLI::App& root, const CommandContext& context);
CommandHandle addListCommand(CLI::App& root, const CommandContext& context);
CommandHandle addExportFmuCommand(CLI::App& root, const CommandContext& context);
CommandHandle addBenchCommand(CLI::App& root, const CommandContext& context);
/// `twin generate lab|field`: synthetic measurements (study/generate.hpp, docs/data-files.md).
CommandHandle addGenerateCommand(CLI::App& root, const CommandContext& context);
/// `twin calibrate`: Griddy Gibbs calibration of assemblies against lab data
/// (calibration/calibrate.hpp).
CommandHandle addCalibrateCommand(CLI::App& root, const CommandContext& context);
/// `twin coverage`: how often the calibration's 95 % intervals hold the truth (study/coverage.hpp).
CommandHandle addCoverageCommand(CLI::App& root, const CommandContext& context);
/// `twin synthesize`: synthetic field data per calibrated assembly as moments
/// (classification/synthesis.hpp).
CommandHandle addSynthesizeCommand(CLI::App& root, const CommandContext& context);
/// `twin classify`: field records among synthesized assemblies, cost-aware choice
/// (classification/classify_field.hpp).
CommandHandle addClassifyCommand(CLI::App& root, const CommandContext& context);
/// `twin study`: the whole method end to end, resumable (study/run.hpp).
CommandHandle addStudyCommand(CLI::App& root, const CommandContext& context);
/// `twin report`: a self-contained HTML report of a study folder (report/study_report.hpp).
CommandHandle addReportCommand(CLI::App& root, const CommandContext& context);
/// `twin compare`: a calibrated assembly against measurements, where it fails
/// (diagnosis/compare.hpp).
CommandHandle addCompareCommand(CLI::App& root, const CommandContext& context);
/// `twin import`: a logger's CSV into measurements, speed, road and a study (io/log_import.hpp).
CommandHandle addImportCommand(CLI::App& root, const CommandContext& context);
/// `twin diagnose`: which catalogue effect the assembly misses; --apply adds effects
/// (diagnosis/diagnose.hpp).
CommandHandle addDiagnoseCommand(CLI::App& root, const CommandContext& context);
/// `twin changes`: what changed between two calibrations of one car (study/changes.hpp).
CommandHandle addChangesCommand(CLI::App& root, const CommandContext& context);
/// `twin help [COMMAND [SUBCOMMAND]]`: the overview, or a command's help (as `twin COMMAND
/// --help`).
CommandHandle addHelpCommand(CLI::App& root, const CommandContext& context);

}  // namespace dtwin::cli
