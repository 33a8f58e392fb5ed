// twin: the command-line front end. Parses, validates, calls the libraries. Nothing else.
// Each subcommand lives in its own <name>_command.cpp and registers itself here.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "dtwin/version.hpp"
#include "subsystems/errors.hpp"

using namespace dtwin;
using namespace dtwin::cli;

int main(int argc, char** argv) {
  const std::string command = joinArgs(argc, argv);
  CLI::App app{"twin: a multibody digital twin of a ground vehicle (Simbody), with Bayesian choice of subsystem fidelity"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(kVersion) + " (" + kGitDescribe + ")");

  std::vector<CommandHandle> commands;
  commands.push_back(addSimulateCommand(app, command));
  commands.push_back(addListCommand(app));
  commands.push_back(addBenchCommand(app));
  commands.push_back(addGenerateCommand(app, command));
  commands.push_back(addCalibrateCommand(app, command));
  commands.push_back(addSynthesizeCommand(app, command));
  commands.push_back(addClassifyCommand(app, command));
  commands.push_back(addStudyCommand(app, command));
  commands.push_back(addReportCommand(app, command));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    for (auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const InputError& e) {
    std::fprintf(stderr, "twin: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "twin: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
