// Every example in the docs holds as written: each TOML block of docs/*.md and README.md parses,
// and each `twin` command in their shell blocks names a real command and only flags that command
// takes. The shell blocks that run in seconds (listing, generating, importing, simulating) run as
// written, in order, in a scratch folder beside the repository's data; the long walks
// (calibrations, diagnoses) run under the label `docs` (DocsExamplesLong).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <toml++/toml.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
const fs::path kSrc = DTWIN_SOURCE_DIR;

struct Block {
  std::string file;  // docs/usage.md
  int line = 0;      // of the opening fence
  std::string lang;  // bash, toml, "" ...
  std::string body;
};

std::vector<Block> blocksOf(const fs::path& md) {
  std::vector<Block> out;
  std::istringstream in(dtwin_test::slurp(md));
  std::string l;
  int n = 0;
  Block* open = nullptr;
  Block cur;
  while (std::getline(in, l)) {
    ++n;
    if (l.rfind("```", 0) == 0) {
      if (!open) {
        cur = Block{fs::relative(md, kSrc).string(), n, l.substr(3), ""};
        open = &cur;
      } else {
        out.push_back(cur);
        open = nullptr;
      }
      continue;
    }
    if (open) cur.body += l + "\n";
  }
  return out;
}

std::vector<Block> allBlocks() {
  std::vector<fs::path> files = {kSrc / "README.md"};
  for (const auto& e : fs::directory_iterator(kSrc / "docs"))
    if (e.path().extension() == ".md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<Block> out;
  for (const auto& f : files)
    for (auto& b : blocksOf(f)) out.push_back(b);
  return out;
}

/// The logical lines of a shell block: continuations joined, comments dropped.
std::vector<std::string> shellLines(const std::string& body) {
  std::vector<std::string> out;
  std::istringstream in(body);
  std::string joined;
  for (std::string l; std::getline(in, l);) {
    const auto hash = l.find(" #");
    if (l.rfind("#", 0) == 0)
      l.clear();
    else if (hash != std::string::npos)
      l = l.substr(0, hash);
    while (!l.empty() && l.back() == ' ') l.pop_back();
    if (!l.empty() && l.back() == '\\') {
      joined += l.substr(0, l.size() - 1) + " ";
      continue;
    }
    joined += l;
    if (!joined.empty()) out.push_back(joined);
    joined.clear();
  }
  return out;
}

struct TwinCall {
  std::string command;  // "generate lab", "calibrate"
  std::vector<std::string> flags;
};

/// The `twin` calls of a logical line (`twin`, `$B`, `./build/cli/twin`).
std::vector<TwinCall> twinCalls(const std::string& line) {
  std::vector<TwinCall> out;
  std::istringstream in(std::regex_replace(line, std::regex("[;|&()\\[\\]]"), " ; "));
  std::vector<std::string> tok;
  for (std::string t; in >> t;) tok.push_back(t);
  for (std::size_t i = 0; i + 1 < tok.size(); ++i) {
    const std::string& t = tok[i];
    if (t != "twin" && t != "$B" && t != "${B}" && t != "./build/cli/twin") continue;
    if (i > 0 && (tok[i - 1] == "run" || tok[i - 1] == "`")) continue;
    TwinCall c;
    std::size_t j = i + 1;
    if (tok[j].empty() || tok[j][0] == '-' || tok[j] == ";") continue;
    c.command = tok[j++];
    if (c.command == "generate" && j < tok.size() && tok[j][0] != '-') c.command += " " + tok[j++];
    for (; j < tok.size() && tok[j] != ";"; ++j)
      if (tok[j].rfind("--", 0) == 0 && tok[j].size() > 2)
        c.flags.push_back(tok[j].substr(0, tok[j].find('=')));
    out.push_back(c);
  }
  return out;
}

int shell(const std::string& cmd) {
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/// A shell block: tagged so, or untagged and starting with a `twin` command.
bool isShell(const Block& b) {
  if (b.lang == "bash" || b.lang == "sh") return true;
  return b.lang.empty() && (b.body.rfind("twin ", 0) == 0 || b.body.rfind("$B ", 0) == 0);
}

/// Commands that finish in seconds on the shipped data.
bool isShort(const Block& b) {
  const std::set<std::string> quick = {"list",     "generate lab", "import",
                                       "simulate", "help",         "changes"};
  bool any = false;
  for (const auto& l : shellLines(b.body)) {
    if (l.find("mpirun") != std::string::npos || l.find("cmake") != std::string::npos ||
        l.find("scripts/") != std::string::npos || l.find("python") != std::string::npos ||
        l.find("ctest") != std::string::npos)
      return false;
    for (const auto& c : twinCalls(l)) {
      if (!quick.count(c.command)) return false;
      any = true;
    }
  }
  return any;
}

}  // namespace

TEST(DocsExamples, EveryTomlBlockParses) {
  int n = 0;
  for (const auto& b : allBlocks()) {
    if (b.lang != "toml") continue;
    ++n;
    try {
      (void)toml::parse(b.body);
    } catch (const toml::parse_error& e) {
      ADD_FAILURE() << b.file << ":" << b.line + static_cast<int>(e.source().begin.line) << ": "
                    << e.description();
    }
  }
  EXPECT_GE(n, 5);
}

TEST(DocsExamples, EveryTwinCommandTakesTheFlagsItIsGiven) {
  std::map<std::string, std::string> help;  // command -> its --help text
  int calls = 0;
  for (const auto& b : allBlocks()) {
    if (!isShell(b)) continue;
    for (const auto& line : shellLines(b.body))
      for (const auto& c : twinCalls(line)) {
        if (c.command.find_first_of("$<") != std::string::npos || c.command == "CMD")
          continue;  // a placeholder
        ++calls;
        if (!help.count(c.command)) {
          const fs::path out = fs::temp_directory_path() / "dtwin_docs_help.txt";
          const int code = shell(std::string(DTWIN_TWIN_EXE) + " " + c.command + " --help > " +
                                 out.string() + " 2>&1");
          ASSERT_EQ(code, 0) << b.file << ":" << b.line << ": `twin " << c.command
                             << "` is not a command";
          help[c.command] = dtwin_test::slurp(out);
        }
        for (const auto& f : c.flags)
          EXPECT_TRUE(std::regex_search(help[c.command], std::regex(f + "([^a-z-]|$)")))
              << b.file << ":" << b.line << ": twin " << c.command << " takes no flag " << f
              << "\n  in: " << line;
      }
  }
  EXPECT_GE(calls, 40);
}

namespace {

/// Runs the shell blocks of each page in order in one scratch folder per page (`data` and `build`
/// link to the repository's); `all`: every block, else the short ones up to the first long one.
void runBlocks(bool all) {
  std::map<std::string, std::vector<Block>> pages;
  for (const auto& b : allBlocks())
    if ((b.lang == "bash" || b.lang == "sh") && !shellLines(b.body).empty())
      pages[b.file].push_back(b);
  int ran = 0;
  for (const auto& [page, blocks] : pages) {
    const fs::path dir = dtwin_test::freshDir(
        "docs_" + std::regex_replace(page, std::regex("[/.]"), "_") + (all ? "_all" : ""));
    fs::create_symlink(kSrc / "data", dir / "data");
    fs::create_symlink(fs::path(DTWIN_TWIN_EXE).parent_path().parent_path(), dir / "build");
    for (const auto& b : blocks) {
      if (!all && !isShort(b)) break;  // later blocks may read what this one writes
      bool runnable = true;
      for (const auto& l : shellLines(b.body))
        for (const auto& c : twinCalls(l)) runnable = runnable && c.command != "CMD";
      // A placeholder the reader fills in ("<the causes' folder>") is not a command to run as
      // written.
      if (std::regex_search(b.body, std::regex("<[a-z][a-z' ]*>"))) runnable = false;
      if (!runnable || b.body.find("mpirun") != std::string::npos ||
          b.body.find("cmake") != std::string::npos ||
          b.body.find("scripts/") != std::string::npos ||
          b.body.find("ctest") != std::string::npos ||
          b.body.find("#!/bin/bash") != std::string::npos)
        continue;
      dtwin_test::writeText(dir / "block.sh", "set -euo pipefail\nexport PATH=\"" +
                                                  fs::path(DTWIN_TWIN_EXE).parent_path().string() +
                                                  ":$PATH\"\n" + b.body);
      const int code = shell("cd " + dir.string() + " && bash block.sh > block.out 2>&1");
      EXPECT_EQ(code, 0) << page << ":" << b.line << " fails as written:\n"
                         << dtwin_test::slurp(dir / "block.out");
      std::printf("ran %s:%d\n", page.c_str(), b.line);
      ++ran;
    }
  }
  EXPECT_GE(ran, all ? 20 : 1);
}

}  // namespace

TEST(DocsExamples, ShortShellBlocksRunAsWritten) { runBlocks(false); }

TEST(DocsExamplesLong, EveryShellBlockRunsAsWritten) { runBlocks(true); }
