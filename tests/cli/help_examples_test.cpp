// `twin --help` lists the commands by task; `twin help CMD` is `twin CMD --help`; and every
// example at the end of a command's --help runs as written from the root of the source tree.
// The examples run in the order `twin --help` lists the commands, in one fresh folder that holds
// `data` -> the source tree's data/, so that `data/...` and `out/...` work as written.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using dtwin_test::runTwin;

/// The commands of `twin --help`, in its order: the first word of each indented line under a
/// heading that ends in ':' (the "Options:" section aside).
std::vector<std::string> listedCommands(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream in(help);
  std::string line;
  bool in_group = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != ' ') {
      in_group = line.back() == ':' && line != "Options:";
      continue;
    }
    if (in_group && line.size() > 2 && line[2] != ' ')
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
  }
  return names;
}

/// The lines of the "Examples:" section of a help text, without their indentation.
std::vector<std::string> examplesOf(const std::string& help) {
  std::vector<std::string> out;
  const auto at = help.find("\nExamples:\n");
  if (at == std::string::npos) return out;
  std::istringstream in(help.substr(at + 11));
  std::string line;
  while (std::getline(in, line) && line.rfind("  ", 0) == 0) out.push_back(line.substr(2));
  return out;
}

/// The words of a command line (the examples quote nothing).
std::vector<std::string> wordsOf(const std::string& line) {
  std::vector<std::string> w;
  std::istringstream in(line);
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

/// The examples of the commands `twin --help` lists (in its order) for which `take` is true.
std::vector<std::string> examples(bool (*take)(const std::string&)) {
  const auto top = runTwin("--help");
  EXPECT_EQ(top.code, 0) << top.err;
  std::vector<std::string> all;
  for (const auto& cmd : listedCommands(top.out)) {
    if (!take(cmd)) continue;
    const auto h = runTwin(cmd + " --help");
    EXPECT_EQ(h.code, 0) << cmd << ": " << h.err;
    const auto ex = examplesOf(h.out);
    EXPECT_FALSE(ex.empty()) << "twin " << cmd << " --help has no examples";
    EXPECT_LE(ex.size(), 3u) << cmd;
    for (const auto& e : ex) {
      EXPECT_EQ(e.rfind("twin " + cmd + " ", 0) == 0 || e == "twin " + cmd, true)
          << cmd << " example: " << e;
      all.push_back(e);
    }
  }
  return all;
}

/// Runs each example in a fresh folder with data -> the source tree's data/ (`twin` replaced by
/// the built program); each must exit 0 and leave what it names after --out.
void runExamples(const std::string& folder, const std::vector<std::string>& list) {
  const fs::path dir = dtwin_test::freshDir(folder);
  fs::create_directory_symlink(fs::path(DTWIN_SOURCE_DIR) / "data", dir / "data");
  for (const auto& e : list) {
    SCOPED_TRACE(e);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string cmd =
        "cd '" + dir.string() + "' && " + DTWIN_TWIN_EXE + e.substr(4) + " > log.txt 2>&1";
    const int st = std::system(cmd.c_str());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%6.1f s  %s\n", s, e.c_str());
    ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << dtwin_test::slurp(dir / "log.txt");
    const auto w = wordsOf(e);
    for (std::size_t i = 0; i + 1 < w.size(); ++i)
      if (w[i] == "--out") {
        EXPECT_TRUE(fs::exists(dir / w[i + 1])) << w[i + 1] << " was not written";
      }
  }
}

/// The commands whose examples take minutes (a whole study, and its report): label slow.
bool slowCommand(const std::string& c) { return c == "study" || c == "report"; }

}  // namespace

TEST(HelpText, GroupsTheCommandsByTask) {
  const auto r = runTwin("--help");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* s : {"Simulate, calibrate and choose an assembly:", "Measured drives:", "Tools:",
                        "share/doc/dtwin", "docs/"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << " in\n" << r.out;
  const std::vector<std::string> expected = {
      "simulate", "generate", "calibrate", "coverage", "synthesize", "classify", "study", "report",
      "import",   "compare",  "diagnose",  "changes",  "export-fmu", "list",     "bench", "help"};
  EXPECT_EQ(listedCommands(r.out), expected) << r.out;
  EXPECT_EQ(r.out.find("Griddy"), std::string::npos) << "tasks, not internals";
  // `twin` alone and `twin help` print the same overview.
  EXPECT_EQ(runTwin("").out, r.out);
  const auto h = runTwin("help");
  EXPECT_EQ(h.code, 0);
  EXPECT_EQ(h.out, r.out);
}

TEST(HelpText, HelpCommandIsTheCommandsOwnHelp) {
  const auto top = runTwin("--help");
  for (const auto& cmd : listedCommands(top.out)) {
    SCOPED_TRACE(cmd);
    const auto a = runTwin("help " + cmd), b = runTwin(cmd + " --help");
    EXPECT_EQ(a.code, 0) << a.err;
    EXPECT_EQ(a.out, b.out);
  }
  const auto a = runTwin("help generate lab"), b = runTwin("generate lab --help");
  EXPECT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
}

TEST(HelpText, HelpOfAnUnknownCommandSaysWhatIsMeant) {
  const auto r = runTwin("help calibrat");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("twin: error: unknown command 'calibrat'", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("did you mean 'calibrate'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const auto far = runTwin("help nosuch");
  EXPECT_EQ(far.code, 2);
  EXPECT_NE(far.err.find("unknown command 'nosuch'"), std::string::npos) << far.err;
  EXPECT_EQ(std::count(far.err.begin(), far.err.end(), '\n'), 1) << far.err;
}

TEST(HelpText, NoIssueOrSessionWording) {
  const auto top = runTwin("--help");
  std::string all = top.out;
  for (const auto& cmd : listedCommands(top.out)) all += runTwin(cmd + " --help").out;
  all += runTwin("generate lab --help").out + runTwin("generate field --help").out;
  for (const char* s : {"issue ", "Issue ", "session", "Session"})
    EXPECT_EQ(all.find(s), std::string::npos) << s;
}

// Every command's examples but those of the slow commands, in order.
TEST(HelpExamples, RunAsWritten) {
  runExamples("examples", examples([](const std::string& c) { return !slowCommand(c); }));
}

// The slow commands' examples (they read only shipped files and each other's output).
TEST(HelpExamplesSlow, RunAsWritten) { runExamples("examples_slow", examples(slowCommand)); }
