#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/commands.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"

namespace fs = std::filesystem;

namespace dtwin::cli {

CLI::Option* addSeedOption(CLI::App* app, std::optional<std::uint64_t>& seed,
                           const std::string& help) {
  return app
      ->add_option_function<std::string>(
          "--seed",
          [&seed](const std::string& v) {
            std::uint64_t x = 0;
            const char* end = v.data() + v.size();
            const auto [p, ec] = std::from_chars(v.data(), end, x);
            if (v.empty() || ec != std::errc() || p != end)
              throw CLI::ValidationError(
                  "--seed", "must be an integer in [0, 18446744073709551615], got '" + v + "'");
            seed = x;
          },
          help)
      ->type_name("UINT64");
}

void addForceOption(CLI::App* app, bool& force) {
  app->add_flag("--force", force,
                "Run even when the estimated work exceeds the limits (docs/study-file.md, Limits); "
                "the sizes' own limits still hold");
}

fs::path installPrefix() {
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  if (ec || !exe.has_parent_path()) return {};
  return exe.parent_path().parent_path();  // <prefix>/bin/twin
}

std::string defaultStudy() {
  const fs::path prefix = installPrefix();
  const std::string beside =
      prefix.empty() ? std::string() : (prefix / "share" / "dtwin" / "data").string();
  for (const std::string& dir :
       {std::string(DTWIN_SOURCE_DATA_DIR), beside, std::string(DTWIN_INSTALL_DATA_DIR)}) {
    if (dir.empty()) continue;
    const fs::path p = fs::path(dir) / "studies" / "demo.toml";
    if (fs::exists(p)) return p.string();
  }
  return "data/studies/demo.toml";
}

std::string installedDocDir() {
  const fs::path prefix = installPrefix();
  std::error_code ec;
  if (!prefix.empty() && fs::is_directory(prefix / "share" / "doc" / "dtwin", ec))
    return (prefix / "share" / "doc" / "dtwin").string();
  return DTWIN_INSTALL_DOC_DIR;
}

std::string joinArgs(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

void deprecationNote(const std::string& old_shape, const std::string& new_shape,
                     const Distributed* processes) {
  if (isRootProcess(processes))
    std::fprintf(stderr, "twin: note: `%s` is deprecated; use `%s`\n", old_shape.c_str(),
                 new_shape.c_str());
}

void addExamples(CLI::App* app, const std::vector<std::string>& examples) {
  std::string text = "Examples:";
  for (const auto& e : examples) text += "\n  " + e;
  app->footer(text);
}

bool stderrIsTerminal() { return ::isatty(STDERR_FILENO) != 0; }

bool progressOn(bool quiet, const Distributed* processes) {
  return !quiet && isRootProcess(processes);
}

}  // namespace dtwin::cli

namespace dtwin::cli {

std::string messageForCommand(const CommandHandle& handle, const std::string& where,
                              const std::string& rule) {
  std::string plain = where.empty() ? rule : where + ": " + rule;
  const auto dot = where.rfind('.');
  // Only "<options>.<field>" (no path, no spaces) is an option field.
  if (dot == std::string::npos || where.find_first_of(" /:") != std::string::npos ||
      handle.app == nullptr)
    return plain;
  const std::string field = where.substr(dot + 1);
  std::string flag;
  if (auto it = handle.field_flags.find(field); it != handle.field_flags.end()) {
    flag = it->second;
  } else {
    flag = "--" + field;
    for (char& ch : flag)
      if (ch == '_') ch = '-';
    if (handle.app->get_option_no_throw(flag) == nullptr) return plain;
  }
  return flag + ": " + rule;
}

}  // namespace dtwin::cli
