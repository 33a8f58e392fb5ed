// The layering of the libraries (docs/architecture.md): each folder includes only the folders
// beneath it, and no library includes the CLI. Read from the source tree, so that an upward
// include fails the suite instead of waiting for a reviewer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

namespace fs = std::filesystem;

namespace {

/// Folder -> the project folders its sources may include (itself included).
const std::map<std::string, std::set<std::string>>& allowed() {
  static const std::map<std::string, std::set<std::string>> a = {
      {"common", {"common"}},
      {"subsystems", {"common", "subsystems"}},
      {"twin", {"common", "subsystems", "twin"}},
      {"io", {"common", "subsystems", "twin", "io"}},
      {"calibration", {"common", "subsystems", "twin", "io", "calibration"}},
      {"classification", {"common", "subsystems", "twin", "io", "calibration", "classification"}},
      {"diagnosis", {"common", "subsystems", "twin", "io", "calibration", "diagnosis"}},
      {"study", {"common", "subsystems", "twin", "io", "calibration", "classification", "diagnosis", "study"}},
      {"report", {"common", "subsystems", "twin", "io", "calibration", "classification", "diagnosis", "study", "report"}},
  };
  return a;
}

const std::set<std::string>& projectFolders() {
  static const std::set<std::string> f = {"common",    "subsystems", "twin",  "io",     "calibration",
                                          "classification", "diagnosis",  "study", "report", "cli"};
  return f;
}

}  // namespace

TEST(Layering, NoLibraryIncludesAFolderAboveIt) {
  const fs::path root(DTWIN_SOURCE_DIR);
  const std::regex inc(R"(^\s*#\s*include\s*"([a-z_]+)/[^"]+")");
  int files = 0;
  for (const auto& [folder, ok] : allowed()) {
    ASSERT_TRUE(fs::is_directory(root / folder)) << folder;
    for (const auto& e : fs::recursive_directory_iterator(root / folder)) {
      const auto ext = e.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp") continue;
      ++files;
      std::ifstream in(e.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        std::smatch m;
        if (!std::regex_search(line, m, inc)) continue;
        const std::string target = m[1];
        if (!projectFolders().count(target)) continue;  // e.g. "dtwin/version.hpp" (generated)
        EXPECT_TRUE(ok.count(target)) << fs::relative(e.path(), root).string() << ":" << n << " includes " << target
                                      << "/, which is not beneath " << folder << "/";
      }
    }
  }
  EXPECT_GT(files, 50);  // the walk found the sources
}

namespace {

/// The project headers `header` includes, directly or through others (paths from the source root).
void includesOf(const fs::path& root, const std::string& header, std::set<std::string>& seen) {
  if (!seen.insert(header).second || !fs::exists(root / header)) return;
  std::ifstream in(root / header);
  const std::regex inc(R"re(^\s*#\s*include\s*"([^"]+)")re");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, inc)) includesOf(root, m[1], seen);
  }
}

}  // namespace

// The calibration's mathematics (docs/architecture.md: it sees the simulations only through an
// SSE callback) compiles without the simulator, the model and the study reader: its headers reach
// no twin/ or io/ header but the study's sizes.
TEST(Layering, TheCalibrationsMathematicsDoesNotIncludeTheSimulator) {
  const fs::path root(DTWIN_SOURCE_DIR);
  for (const char* h : {"common.hpp", "gibbs.hpp", "region.hpp", "optimize.hpp", "profile.hpp", "summary.hpp", "adaptive_design.hpp",
                        "feasible_box.hpp", "lhs.hpp", "subspace_lm.hpp", "design_journal.hpp"}) {
    std::set<std::string> seen;
    includesOf(root, std::string("calibration/") + h, seen);
    ASSERT_TRUE(fs::exists(root / "calibration" / h)) << h;
    for (const auto& s : seen)
      EXPECT_TRUE(s.rfind("twin/", 0) != 0 || s == "io/study_sizes.hpp") << "calibration/" << h << " reaches " << s;
  }
}

// twin/ holds the model, the simulator, the integrators, scenarios and roads; the files of a study
// (its reader, measurements, log import, provenance, data generation) are io/'s. No twin/ source
// includes io/ (the first test), and none of those modules is left behind in twin/.
TEST(Layering, TheFilesOfAStudyLiveInIo) {
  const fs::path root(DTWIN_SOURCE_DIR);
  for (const char* m : {"study", "study_sizes", "measurement", "log_import", "provenance", "generate", "work"}) {
    EXPECT_TRUE(fs::exists(root / "io" / (std::string(m) + ".hpp"))) << m;
    EXPECT_FALSE(fs::exists(root / "twin" / (std::string(m) + ".hpp"))) << m;
  }
}
