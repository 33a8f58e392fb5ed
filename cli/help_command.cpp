// `twin help [COMMAND [SUBCOMMAND]]` and the grouped overview `twin --help` prints: the commands by
// task, as the registry lists them (cli/command_registry.cpp).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "common/names.hpp"

namespace dtwin::cli {

std::string topLevelHelp() {
  std::string s =
      "twin: a multibody digital twin of a ground vehicle (Simbody), with Bayesian choice of "
      "subsystem fidelity\n"
      "Usage: twin COMMAND [OPTIONS]\n";
  std::size_t width = 0;
  for (const auto& e : commandRegistry()) width = std::max(width, e.name.size());
  for (const char* group : kCommandGroups) {
    s += std::string("\n") + group + ":\n";
    for (const auto& e : commandRegistry())
      if (std::string(e.value.group) == group)
        s += "  " + e.name + std::string(width + 3 - e.name.size(), ' ') + e.value.task + "\n";
  }
  s += "\nOptions:\n"
       "  -h,--help      this overview; a command's options and examples: twin COMMAND --help (or "
       "twin help COMMAND)\n"
       "  --version      the version, the build and the Simbody it runs on\n"
       "\nThe examples in each command's help run as written from the root of the source tree with "
       "twin on\n"
       "PATH (else write ./build/cli/twin for twin); they read data/ and write under out/.\n"
       "Documentation: docs/ in the source tree (README.md first); installed under " +
       installedDocDir() + ".\n";
  return s;
}

CommandHandle addHelpCommand(CLI::App& root, const CommandContext& /*context*/) {
  auto words = std::make_shared<std::vector<std::string>>();
  auto* h = addSubcommand(root, "help");
  h->add_option("command", *words,
                "The command (and its subcommand, e.g. generate lab) whose help to show");
  h->footer("Examples:\n  twin help\n  twin help calibrate\n  twin help generate lab");
  CLI::App* top = &root;
  return {h, [top, words] {
            if (words->empty()) {
              std::printf("%s", topLevelHelp().c_str());
              return 0;
            }
            const CLI::App* app = top;
            std::string path =
                top->get_name();  // "twin", then "twin generate": the usage line's prefix
            for (std::size_t i = 0; i < words->size(); ++i) {
              const std::string& word = (*words)[i];
              std::vector<std::string> names;
              for (const CLI::App* sub : app->get_subcommands([](const CLI::App*) { return true; }))
                names.push_back(sub->get_name());
              if (std::find(names.begin(), names.end(), word) == names.end()) {
                throw InputError(i == 0 ? std::string() : app->get_name(),
                                 unknownNameRule("command", word, names));
              }
              if (i > 0) path += " " + app->get_name();
              app = app->get_subcommand(word);
            }
            std::printf("%s", app->help(path).c_str());
            return 0;
          }};
}

}  // namespace dtwin::cli
