// The layering of the libraries (docs/architecture.md): each folder includes only the folders
// beneath it, and no library includes the CLI. Read from the source tree, so that an upward
// include fails the suite instead of waiting for a reviewer.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

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
      // report/ draws the result types of the folders below it; study/ finishes each use case,
      // its pages included, so it sits above report/.
      {"report",
       {"common", "subsystems", "twin", "io", "calibration", "classification", "diagnosis",
        "report"}},
      {"study",
       {"common", "subsystems", "twin", "io", "calibration", "classification", "diagnosis",
        "report", "study"}},
      // The front ends translate arguments and print; the work is study/'s: they include study/
      // and common/ alone, beside their own folder (and the generated "dtwin/version.hpp", which
      // names no project folder). The Python module sits at the level of cli/, beside it
      // (neither includes the other).
      {"cli", {"common", "study", "cli"}},
      {"python", {"common", "study", "python"}},
      // The runtime of the FMU `twin export-fmu` writes: FMI calls translated into study/'s
      // co-simulation twin (study/cosim.hpp), at the level of cli/.
      {"fmu", {"common", "study", "fmu"}},
  };
  return a;
}

const std::set<std::string>& projectFolders() {
  static const std::set<std::string> f = {
      "common",    "subsystems", "twin",   "io",  "calibration", "classification",
      "diagnosis", "study",      "report", "cli", "python",      "fmu"};
  return f;
}

}  // namespace

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
        EXPECT_TRUE(ok.count(target))
            << fs::relative(e.path(), root).string() << ":" << n << " includes " << target
            << "/, which is not beneath " << folder << "/";
      }
    }
  }
  EXPECT_GT(files, 50);  // the walk found the sources
}

namespace {

/// Every source file (.cpp, .hpp) under the project's source folders, tests included.
std::vector<fs::path> sourceFiles(const fs::path& root, bool with_tests) {
  std::vector<fs::path> out;
  auto folders = projectFolders();
  if (with_tests) folders.insert("tests");
  for (const auto& f : folders)
    for (const auto& e : fs::recursive_directory_iterator(root / f)) {
      const auto ext = e.path().extension().string();
      if (ext == ".cpp" || ext == ".hpp") out.push_back(e.path());
    }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

// Every folder of the source tree that holds C++ is a layer of the map above (or the tests): a
// new folder fails here until it is placed.
TEST(Layering, EveryFolderWithSourcesIsPlaced) {
  const fs::path root(DTWIN_SOURCE_DIR);
  const std::set<std::string> not_code = {"build", "data", "docs",        "scripts",
                                          "cmake", "out",  "third_party", "tests"};
  for (const auto& e : fs::directory_iterator(root)) {
    if (!e.is_directory()) continue;
    const std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.' || not_code.count(name) || name.rfind("build", 0) == 0)
      continue;
    bool has_code = false;
    for (const auto& f : fs::recursive_directory_iterator(e.path())) {
      const auto ext = f.path().extension().string();
      if (ext == ".cpp" || ext == ".hpp") {
        has_code = true;
        break;
      }
    }
    if (has_code) {
      EXPECT_TRUE(allowed().count(name))
          << name << "/ holds C++ sources but has no place in the layering";
    }
  }
  for (const auto& f : projectFolders()) EXPECT_TRUE(allowed().count(f)) << f;
}

// io/ reads and writes files and runs nothing: none of its files reaches the simulator, the
// integrators or the process layer, directly or through the headers it includes.
TEST(Layering, IoRunsNothing) {
  const fs::path root(DTWIN_SOURCE_DIR);
  int files = 0;
  for (const auto& e : fs::directory_iterator(root / "io")) {
    const auto ext = e.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp") continue;
    ++files;
    std::set<std::string> seen;
    const std::string self = "io/" + e.path().filename().string();
    includesOf(root, self, seen);
    for (const auto& s : seen)
      for (const char* banned : {"twin/simulator.hpp", "twin/rosenbrock.hpp",
                                 "common/distributed.hpp", "common/parallel.hpp"})
        EXPECT_NE(s, banned) << self << " reaches " << banned;
  }
  EXPECT_GT(files, 8);
}

// The process context (threads, MPI ranks) is passed to the library explicitly: only the program
// (cli/) creates it; no library file reaches for a process-wide instance.
TEST(Layering, NoLibraryReadsAProcessWideInstance) {
  const fs::path root(DTWIN_SOURCE_DIR);
  const std::regex global(R"(Distributed::instance\s*\()");
  for (const auto& p : sourceFiles(root, false)) {
    const std::string rel = fs::relative(p, root).string();
    if (rel.rfind("cli/", 0) == 0) continue;
    std::ifstream in(p);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      EXPECT_FALSE(std::regex_search(line, global))
          << rel << ":" << n << " reads Distributed::instance()";
  }
}

// No source file grows past about 800 lines: a file that does is holding two responsibilities.
TEST(Layering, NoSourceFileIsOverEightHundredLines) {
  const fs::path root(DTWIN_SOURCE_DIR);
  for (const auto& p : sourceFiles(root, true)) {
    if (p.extension() != ".cpp") continue;
    std::ifstream in(p);
    std::size_t lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    EXPECT_LE(lines, 800u) << fs::relative(p, root).string() << " has " << lines
                           << " lines; split it by responsibility";
  }
}

// Headers stay short (an interface, not an implementation: at most 500 lines), open with
// `#pragma once`, and every file names a project header by its folder in quotes
// ("twin/model.hpp", or "dtwin/version.hpp" generated by the build), never bare or in angle
// brackets, so that an include says which layer it reaches.
TEST(Layering, HeadersAreShortGuardedAndIncludesNameTheirFolder) {
  const fs::path root(DTWIN_SOURCE_DIR);
  const std::regex quoted(R"re(^\s*#\s*include\s*"([^"]+)")re");
  const std::regex angled(R"re(^\s*#\s*include\s*<([a-z_]+)/)re");
  auto folders = projectFolders();
  folders.insert("dtwin");
  for (const auto& p : sourceFiles(root, false)) {
    const std::string rel = fs::relative(p, root).string();
    std::ifstream in(p);
    std::size_t lines = 0;
    bool guarded = false;
    for (std::string line; std::getline(in, line);) {
      ++lines;
      guarded = guarded || line.rfind("#pragma once", 0) == 0;
      std::smatch m;
      if (std::regex_search(line, m, quoted)) {
        const std::string inc = m[1];
        const auto slash = inc.find('/');
        EXPECT_TRUE(slash != std::string::npos && folders.count(inc.substr(0, slash)))
            << rel << ":" << lines << ": #include \"" << inc << "\" does not name a project folder";
      }
      if (std::regex_search(line, m, angled)) {
        EXPECT_FALSE(folders.count(m[1]))
            << rel << ":" << lines << ": a project header in angle brackets";
      }
    }
    if (p.extension() != ".hpp") continue;
    EXPECT_TRUE(guarded) << rel << " has no #pragma once";
    EXPECT_LE(lines, 500u) << rel << " has " << lines << " lines; a header holds an interface";
  }
}

// The calibration's mathematics (docs/architecture.md: it sees the simulations only through an
// SSE callback) compiles without the simulator, the model and the study reader: its headers reach
// no twin/ or io/ header but the study's sizes.
TEST(Layering, TheCalibrationsMathematicsDoesNotIncludeTheSimulator) {
  const fs::path root(DTWIN_SOURCE_DIR);
  for (const char* h : {"common.hpp", "gibbs.hpp", "region.hpp", "optimize.hpp", "profile.hpp",
                        "summary.hpp", "adaptive_design.hpp", "feasible_box.hpp", "lhs.hpp",
                        "subspace_lm.hpp", "design_journal.hpp"}) {
    std::set<std::string> seen;
    includesOf(root, std::string("calibration/") + h, seen);
    ASSERT_TRUE(fs::exists(root / "calibration" / h)) << h;
    for (const auto& s : seen)
      EXPECT_TRUE(s.rfind("twin/", 0) != 0 || s == "io/study_sizes.hpp")
          << "calibration/" << h << " reaches " << s;
  }
}

// twin/ holds the model, the simulator, the integrators, scenarios and roads; the files of a study
// (its reader, the vehicle file, speed traces, measurements, log import, provenance) are io/'s; the
// use cases (generate, coverage, synthesize, calibrate, diagnose, the whole study) are study/'s.
TEST(Layering, EachConcernHasOneHome) {
  const fs::path root(DTWIN_SOURCE_DIR);
  for (const char* m :
       {"study", "study_sizes", "measurement", "log_import", "provenance", "work"}) {
    EXPECT_TRUE(fs::exists(root / "io" / (std::string(m) + ".hpp"))) << m;
    EXPECT_FALSE(fs::exists(root / "twin" / (std::string(m) + ".hpp"))) << m;
  }
  for (const char* m : {"generate", "coverage", "synthesize", "calibrate", "diagnose", "run",
                        "bench", "hand_ode"}) {
    EXPECT_TRUE(fs::exists(root / "study" / (std::string(m) + ".hpp"))) << m;
    for (const char* below : {"twin", "io", "calibration", "classification", "diagnosis"})
      if (std::string(m) != "calibrate" && std::string(m) != "diagnose") {
        EXPECT_FALSE(fs::exists(root / below / (std::string(m) + ".hpp"))) << below << "/" << m;
      }
  }
  for (const char* m : {"distributed", "parallel", "run_error"})
    EXPECT_TRUE(fs::exists(root / "common" / (std::string(m) + ".hpp"))) << m;
}
