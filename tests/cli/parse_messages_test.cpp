// Slips of the hand on the command line get one line in the program's own words: the flag, what it
// takes, and the near name when one is misspelt. No text of the parsing library reaches a user.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using dtwin_test::runTwin;

const std::string kSrc = DTWIN_SOURCE_DIR;
const std::string kDemo = kSrc + "/data/studies/demo.toml";

struct Case {
  std::string args;      // after `twin`
  std::string expected;  // a part of the one error line
};

/// Phrases of the parsing library that must never reach a user.
const std::vector<std::string> kLibraryText = {"Could not convert",
                                               "not in range",
                                               "The following argument",
                                               "not expected",
                                               "FAILED",
                                               "Value ",
                                               "required but received",
                                               "Expected exactly",
                                               "does not exist:",
                                               "Failed parsing",
                                               "Should be true/false"};

void expectOneLine(const Case& c, const fs::path& dir) {
  const auto r = runTwin(c.args, dir);
  EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
  ASSERT_EQ(r.err.rfind("twin: error: ", 0), 0u) << c.args << "\n" << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
  EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << "\n" << r.err;
  for (const auto& t : kLibraryText)
    EXPECT_EQ(r.err.find(t), std::string::npos) << "library text '" << t << "' in: " << r.err;
}

TEST(ParseMessages, EachSlipNamesTheFlagAndTheRule) {
  const fs::path d = fs::temp_directory_path() / "dtwin_parse_messages";
  fs::remove_all(d);
  fs::create_directories(d);
  const std::string out = " --out " + (d / "o").string();
  const std::vector<Case> cases = {
      {"changes --level five --before a --after b" + out,
       "--level: 'five' is not a number (it takes a number in [1e-06, 0.49])"},
      {"changes --level 0.7 --before a --after b" + out,
       "--level: 0.7 is out of range (it takes a number in [1e-06, 0.49])"},
      {"calibrate --study " + kDemo + " --data x.csv --assembli M1" + out,
       "unknown option '--assembli' (did you mean '--assembly'?)"},
      {"calibrate --study " + kDemo + " --data x.csv M1" + out, "unexpected argument 'M1'"},
      {"simulate --study " + kDemo + " --accuracy abc" + out, "--accuracy: 'abc' is not a number"},
      {"calibrate --study " + kDemo + " --data x.csv --region jont" + out,
       "--region: unknown value 'jont' (known: joint, paper; did you mean 'joint'?)"},
      {"calibrate --study " + kDemo + " --data x.csv --threads -3" + out,
       "--threads: -3 is out of range (it takes a whole number in [0, 1024])"},
      {"calibrate --study " + kDemo + " --data x.csv --threads many" + out,
       "--threads: 'many' is not a whole number"},
      {"calibrate --study " + kDemo + out + " --data", "--data needs a value"},
      {"simulate --study " + kDemo + " --out", "--out needs a value"},
      {"report --study-dir " + (d / "nowhere").string() + out,
       "--study-dir: folder '" + (d / "nowhere").string() + "' not found"},
      {"calibrate --study " + kDemo + " --data x.csv", "the option --out is required"},
  };
  for (const auto& c : cases) expectOneLine(c, d);
  EXPECT_FALSE(fs::exists(d / "o")) << "a refused command wrote its output";
}

TEST(ParseMessages, AFreedValueTakesNoValue) {
  const fs::path d = fs::temp_directory_path() / "dtwin_parse_messages_free";
  fs::remove_all(d);
  fs::create_directories(d);
  const std::string lab = (d / "lab.csv").string();
  ASSERT_EQ(
      runTwin("generate lab --study " + kDemo + " --repetitions 1 --quiet --out " + lab, d).code,
      0);
  expectOneLine({"calibrate --study " + kDemo + " --data " + lab +
                     " --assembly M1 --free suspension.damping@rr=0.5 --out " + (d / "o").string(),
                 "--free: 'suspension.damping@rr=0.5': a freed value is searched over its range "
                 "and takes no value; give "
                 "'suspension.damping@rr' alone"},
                d);
  EXPECT_FALSE(fs::exists(d / "o"));
}

}  // namespace
