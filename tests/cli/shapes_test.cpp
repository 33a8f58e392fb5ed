// The same argument shapes in every command (`--study FILE`, `--data FILE[@SCENARIO]`, `--log
// FILE`,
// `--study-dir DIR`, `--out DIR`): the older shapes are still accepted with a one-line note on
// stderr, and give the same results (the files' bytes; the provenance records the command as typed
// and when it ran, so those are left out of the comparison).
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using dtwin_test::runTwin;
using dtwin_test::slurp;

const std::string kSrc = DTWIN_SOURCE_DIR;
const std::string kDemo = kSrc + "/data/studies/demo.toml";

/// The one note line an older shape prints.
void expectNote(const std::string& err, const std::string& note) {
  EXPECT_NE(err.find("twin: note: " + note + "\n"), std::string::npos) << err;
}

void expectSameFile(const fs::path& a, const fs::path& b) {
  ASSERT_TRUE(fs::exists(a)) << a;
  ASSERT_TRUE(fs::exists(b)) << b;
  EXPECT_TRUE(slurp(a) == slurp(b)) << a << " and " << b << " differ";
}

std::vector<std::string> sortedLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  std::sort(lines.begin(), lines.end());
  return lines;
}

/// A page without what says when and by which command line it was made.
std::string withoutProvenance(std::string html) {
  html = std::regex_replace(
      html, std::regex("[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}Z"), "TIME");
  return std::regex_replace(html, std::regex("twin report [^<]*"), "twin report COMMAND");
}

}  // namespace

TEST(CliShapes, StudyFileIsAFlag) {
  const fs::path d = dtwin_test::freshDir("shape_study");
  const std::string missing = (d / "nosuch.toml").string();
  const auto now = runTwin("study --study " + missing + " --out " + (d / "a").string(), d);
  const auto old = runTwin("study " + missing + " --out " + (d / "b").string(), d);
  EXPECT_EQ(now.code, 2);
  EXPECT_EQ(old.code, 2);
  EXPECT_NE(now.err.find(missing + ": study file not found"), std::string::npos) << now.err;
  EXPECT_EQ(now.err.find("note:"), std::string::npos) << now.err;
  expectNote(old.err, "`twin study FILE` is deprecated; use `twin study --study FILE`");
  EXPECT_EQ(old.err.substr(old.err.find('\n') + 1), now.err) << "the same error after the note";
  const auto both =
      runTwin("study --study " + kDemo + " " + missing + " --out " + (d / "c").string(), d);
  EXPECT_EQ(both.code, 2);
  EXPECT_NE(both.err.find("--study: give the study file once"), std::string::npos) << both.err;
}

TEST(CliShapes, CalibrateDataNamesItsScenario) {
  const fs::path d = dtwin_test::freshDir("shape_calibrate");
  const std::string lab = (d / "lab.csv").string();
  ASSERT_EQ(
      runTwin("generate lab --study " + kDemo + " --repetitions 2 --quiet --out " + lab, d).code,
      0);
  const std::string sizes =
      " --assembly M3 --lhs-points 12 --iterations 300 --burn-in 100 --max-rounds 0 --ridge-steps "
      "0 --quiet";
  const auto now = runTwin("calibrate --study " + kDemo + " --data " + lab + "@lab" + sizes +
                               " --out " + (d / "a").string(),
                           d);
  ASSERT_EQ(now.code, 0) << now.err;
  EXPECT_EQ(now.err.find("note:"), std::string::npos) << now.err;
  const auto old = runTwin("calibrate --study " + kDemo + " --data " + lab + " --scenario lab" +
                               sizes + " --out " + (d / "b").string(),
                           d);
  ASSERT_EQ(old.code, 0) << old.err;
  expectNote(old.err,
             "`twin calibrate --data FILE --scenario NAME` is deprecated; use `twin calibrate "
             "--data FILE@NAME`");
  for (const char* f : {"posterior.csv", "design.csv", "optimum.json", "box.json"})
    expectSameFile(d / "a" / "M3" / f, d / "b" / "M3" / f);
  // The journal holds the same points in the order the threads finished them.
  EXPECT_EQ(sortedLines(slurp(d / "a" / "M3" / "design_journal.csv")),
            sortedLines(slurp(d / "b" / "M3" / "design_journal.csv")));
  // The scenario given twice, differently: refused before any run.
  const auto clash = runTwin("calibrate --study " + kDemo + " --data " + lab +
                                 "@lab --scenario field" + sizes + " --out " + (d / "c").string(),
                             d);
  EXPECT_EQ(clash.code, 2);
  EXPECT_NE(clash.err.find("--scenario: 'field' differs from the scenario of --data"),
            std::string::npos)
      << clash.err;
  EXPECT_FALSE(fs::exists(d / "c"));
}

TEST(CliShapes, ImportLogIsAFlag) {
  const fs::path d = dtwin_test::freshDir("shape_import");
  const std::string log = kSrc + "/data/drives/stop_and_go.csv",
                    map = kSrc + "/data/drives/stop_and_go_map.toml";
  const auto now =
      runTwin("import --log " + log + " --map " + map + " --quiet --out " + (d / "a").string(), d);
  ASSERT_EQ(now.code, 0) << now.err;
  EXPECT_EQ(now.err.find("note:"), std::string::npos) << now.err;
  const auto old =
      runTwin("import " + log + " --map " + map + " --quiet --out " + (d / "b").string(), d);
  ASSERT_EQ(old.code, 0) << old.err;
  expectNote(old.err, "`twin import FILE` is deprecated; use `twin import --log FILE`");
  for (const char* f : {"measurements.csv", "speed.csv", "road.csv"})
    expectSameFile(d / "a" / f, d / "b" / f);
  const auto none = runTwin("import --map " + map + " --out " + (d / "c").string(), d);
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("--log: is required"), std::string::npos) << none.err;
}

// A diagnosis folder (a small diagnosis, about half a minute), then its report both ways.
TEST(CliShapesSlow, ReportOutIsAFolder) {
  const fs::path d = dtwin_test::freshDir("shape_report");
  const std::string data = (d / "bump.csv").string();
  ASSERT_EQ(runTwin("generate lab --study " + kDemo +
                        " --scenario diag_bump --times all --rate 100 --repetitions 2 "
                        "--channels hub_force_fl_N,hub_force_fr_N --hidden-effect "
                        "bump_stop:stiffness=5e6,gap_m=0.02 --quiet --out " +
                        data,
                    d)
                .code,
            0);
  const auto diag =
      runTwin("diagnose --study " + kDemo + " --assembly M1 --data " + data +
                  " --lhs-points 12 --iterations 300 "
                  "--burn-in 100 --starts 1 --candidates 1 --causes 1 --propose 0 --quiet --out " +
                  (d / "diag").string(),
              d);
  ASSERT_EQ(diag.code, 0) << diag.err;
  const std::string diag_dir = (d / "diag").string();
  const auto now = runTwin("report --diagnosis " + diag_dir + " --out " + (d / "a").string(), d);
  ASSERT_EQ(now.code, 0) << now.err;
  EXPECT_EQ(now.err.find("note:"), std::string::npos) << now.err;
  const auto old =
      runTwin("report --diagnosis " + diag_dir + " --out " + (d / "b.html").string(), d);
  ASSERT_EQ(old.code, 0) << old.err;
  expectNote(old.err,
             "`twin report --out FILE.html` is deprecated; use `twin report --out DIR (writes "
             "DIR/report.html)`");
  ASSERT_TRUE(fs::exists(d / "a" / "report.html"));
  ASSERT_TRUE(fs::exists(d / "b.html"));
  EXPECT_TRUE(withoutProvenance(slurp(d / "a" / "report.html")) ==
              withoutProvenance(slurp(d / "b.html")));
  // An --out that is a file but not a page is refused.
  dtwin_test::writeText(d / "taken", "x");
  const auto taken =
      runTwin("report --diagnosis " + diag_dir + " --out " + (d / "taken").string(), d);
  EXPECT_EQ(taken.code, 2);
  EXPECT_NE(taken.err.find("exists and is not a folder"), std::string::npos) << taken.err;
}
