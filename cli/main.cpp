// twin: the command-line front end. Parses, validates, calls the libraries. Nothing else.
// Each subcommand lives in its own <name>_command.cpp and has one line in commandRegistry()
// (cli/command_registry.cpp).
#include <CLI/CLI.hpp>

#include <unistd.h>
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "cli/commands.hpp"
#include "cli/parse_error_text.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/names.hpp"
#include "dtwin/version.hpp"

using namespace dtwin;
using namespace dtwin::cli;

namespace {

/// The names of an app's subcommands.
std::vector<std::string> subcommandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

/// "unknown command 'simulat' (known: ...; did you mean 'simulate'?)" when a word where a
/// subcommand must stand names none; "" otherwise (CLI11 then reports what else is wrong).
std::string unknownCommand(const CLI::App& root, int argc, char** argv) {
  const CLI::App* app = &root;
  std::string path;  // the subcommands chosen so far ("generate")
  for (int i = 1; i < argc && app->get_require_subcommand_min() > 0; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') return "";  // an option: CLI11 checks it
    const std::vector<std::string> names = subcommandNames(*app);
    const auto found = std::find(names.begin(), names.end(), word);
    if (found == names.end())
      return (path.empty() ? "" : path + ": ") + unknownNameRule("command", word, names);
    app = app->get_subcommand(word);
    path += (path.empty() ? "" : " ") + word;
  }
  return "";
}

// Ctrl-C, a scheduler's SIGTERM or mpirun stopping the job: one line from the root process, then
// death by the same signal (so a shell or scheduler sees it). Every file is written whole or not at
// all (atomic renames, a journal whose cut last line is dropped), so nothing half-written remains.
extern "C" void stoppedResumable(int sig) {
  const char line[] =
      "\ntwin: stopped by a signal; the finished work is kept: rerun the same command to resume "
      "where it stopped\n";
  (void)!::write(STDERR_FILENO, line, sizeof line - 1);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}
extern "C" void stoppedPlain(int sig) {
  const char line[] = "\ntwin: stopped by a signal; no file was left half-written\n";
  (void)!::write(STDERR_FILENO, line, sizeof line - 1);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

/// The stop handlers of the root process (the other ranks die silently: one line per job).
void sayWhenStopped(bool root, bool resumable) {
  if (!root) return;
  for (int sig : {SIGINT, SIGTERM, SIGHUP})
    ::signal(sig, resumable ? stoppedResumable : stoppedPlain);
}

/// A CLI11 parse error as one line: "<what> (see twin <command> --help)", naming the deepest
/// subcommand that was chosen.
std::string parseErrorLine(const CLI::App& root, const CLI::ParseError& e) {
  std::string path = "twin";
  const CLI::App* app = &root;
  while (!app->get_subcommands().empty()) {
    app = app->get_subcommands().front();
    path += " " + app->get_name();
  }
  std::string what = parseErrorText(*app, e);
  if (dynamic_cast<const CLI::RequiredError*>(&e) &&
      oneLine(e.what()) == "A subcommand is required") {
    what = "a subcommand is required (";
    for (const auto& n : subcommandNames(*app)) what += n + ", ";
    what.resize(what.size() - 2);
    what += ")";
  }
  return what + " (see " + path + " --help)";
}

int runTwin(int argc, char** argv, const Distributed& dist, std::string& error) {
  const CommandContext context{joinArgs(argc, argv), &dist};
  CLI::App app{
      "twin: a multibody digital twin of a ground vehicle (Simbody), with Bayesian choice of "
      "subsystem fidelity",
      "twin"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(kVersion) + " (" + kGitDescribe + ")\n" + kSimbody);

  std::vector<CommandHandle> commands;
  std::vector<bool> distributed, resumable;
  for (const auto& e : commandRegistry()) {
    commands.push_back(e.value.add(app, context));
    distributed.push_back(e.value.distributed);
    resumable.push_back(e.value.resumable);
    if (commands.back().app->get_name() != e.name)
      throw std::logic_error("command registry: the entry '" + e.name + "' adds '" +
                             commands.back().app->get_name() + "'");
  }

  // The overview lists the commands by task (the registry's groups), not as CLI11 would; the
  // subcommands keep CLI11's formatter (each took a copy when it was added).
  app.formatter_fn(
      [](const CLI::App*, const std::string&, CLI::AppFormatMode) { return topLevelHelp(); });
  if (argc < 2) {  // `twin` alone: the overview
    if (dist.isRoot()) std::printf("%s", topLevelHelp().c_str());
    return 0;
  }

  if (const std::string unknown = unknownCommand(app, argc, argv); !unknown.empty()) {
    error = "error: " + unknown;
    std::fprintf(stderr, "twin: %s\n", error.c_str());
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success))
      return app.exit(e);  // --help, --version
    error = "error: " + parseErrorLine(app, e);
    std::fprintf(stderr, "twin: %s\n", error.c_str());
    return 2;
  }
  // Under MPI (mpirun -n K twin ...) the commands that simulate in bulk run on every rank and
  // spread their simulations (common/distributed.hpp); the others run on the root alone.
  const CommandHandle* chosen = nullptr;
  bool resumes = false;
  try {
    for (std::size_t i = 0; i < commands.size(); ++i) {
      if (!commands[i].app->parsed()) continue;
      chosen = &commands[i];
      resumes = resumable[i];
      if (!distributed[i] && !dist.isRoot()) return 0;
      sayWhenStopped(dist.isRoot(), resumes);
      return commands[i].run();
    }
  } catch (const InputError& e) {
    error =
        oneLine(std::string("error: ") +
                (chosen ? messageForCommand(*chosen, e.where(), e.rule()) : std::string(e.what())));
    std::fprintf(stderr, "twin: %s\n", error.c_str());
    return 2;
  } catch (const StorageError& e) {  // the disk filled: what to do, not an internal error
    error = oneLine(std::string(e.what()) + "; free space and rerun the same command" +
                    (resumes ? " — it resumes where it stopped" : ""));
    std::fprintf(stderr, "twin: %s\n", error.c_str());
    return 1;
  } catch (const std::exception& e) {
    error = oneLine(internalErrorText(e.what()));
    std::fprintf(stderr, "twin: %s\n", error.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // Every run allocates its output trace (about 5 MB for 15 s at 1 kHz) and frees it. glibc would
  // hand freed memory back to the system and fault it in again on the next run (about 10 % of a
  // run's time, docs/performance.md "One run"): keep up to 256 MB of freed memory for reuse.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
  Distributed dist;         // the process context, passed down explicitly (CommandContext)
  dist.init(&argc, &argv);  // MPI when started by mpirun; otherwise one process
  std::string error;
  const int rc = runTwin(argc, argv, dist, error);
  return dist.finish(rc, error);
}
