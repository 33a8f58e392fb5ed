#pragma once
// A command-line parse error in the program's own words: which flag, what it takes, and the near
// name when a flag or value is misspelt. No text of the parsing library reaches a user.
#include <CLI/CLI.hpp>

#include <string>

namespace dtwin::cli {

/// One line for a parse error `e` raised while parsing `app` (the deepest subcommand chosen),
/// without the "(see twin ... --help)" tail.
std::string parseErrorText(const CLI::App& app, const CLI::ParseError& e);

}  // namespace dtwin::cli
