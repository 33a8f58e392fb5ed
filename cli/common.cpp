#include <unistd.h>

#include <filesystem>
#include <string>

#include "cli/commands.hpp"
#include "twin/distributed.hpp"

namespace fs = std::filesystem;

namespace dtwin::cli {

std::string defaultStudy() {
  for (const char* dir : {DTWIN_SOURCE_DATA_DIR, DTWIN_INSTALL_DATA_DIR}) {
    const fs::path p = fs::path(dir) / "studies" / "demo.toml";
    if (fs::exists(p)) return p.string();
  }
  return "data/studies/demo.toml";
}

std::string joinArgs(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

bool stderrIsTerminal() { return ::isatty(STDERR_FILENO) != 0; }

bool isRootRank() { return Distributed::instance().isRoot(); }

}  // namespace dtwin::cli
