// twin: the command-line front end. Parses, validates, calls the libraries. Nothing else.
// Each subcommand lives in its own <name>_command.cpp and registers itself here.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "dtwin/version.hpp"
#include "common/errors.hpp"
#include "twin/distributed.hpp"

using namespace dtwin;
using namespace dtwin::cli;

namespace {

int runTwin(int argc, char** argv, std::string& error) {
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
  commands.push_back(addCoverageCommand(app, command));
  commands.push_back(addSynthesizeCommand(app, command));
  commands.push_back(addClassifyCommand(app, command));
  commands.push_back(addStudyCommand(app, command));
  commands.push_back(addReportCommand(app, command));
  commands.push_back(addCompareCommand(app, command));
  commands.push_back(addDiagnoseCommand(app, command));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  // Under MPI (mpirun -n K twin ...) the commands that simulate in bulk run on every rank and
  // spread their simulations (twin/distributed.hpp); the others run on the root alone.
  const Distributed& dist = Distributed::instance();
  const CommandHandle* chosen = nullptr;
  try {
    for (auto& c : commands) {
      if (!c.app->parsed()) continue;
      chosen = &c;
      const std::string name = c.app->get_name();
      const bool distributed = name == "calibrate" || name == "synthesize" || name == "study" || name == "generate";
      if (!distributed && !dist.isRoot()) return 0;
      return c.run();
    }
  } catch (const InputError& e) {
    error = std::string("error: ") + (chosen ? messageForCommand(*chosen, e.where(), e.rule()) : std::string(e.what()));
    std::fprintf(stderr, "twin: %s\n", error.c_str());
    return 2;
  } catch (const std::exception& e) {
    error = std::string("internal error: ") + e.what();
    std::fprintf(stderr, "twin: %s\n", error.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Distributed& dist = Distributed::instance();
  dist.init(&argc, &argv);  // MPI when started by mpirun; otherwise one process
  std::string error;
  const int rc = runTwin(argc, argv, error);
  return dist.finish(rc, error);
}
