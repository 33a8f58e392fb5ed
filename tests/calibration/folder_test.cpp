// The calibration folder's reader and writer (calibration/folder.hpp): posterior.csv parsed with
// every rule named by file:line, written so that it reads back exactly, and summary.json checked
// field by field.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "calibration/folder.hpp"
#include "common/checksum.hpp"
#include "common/errors.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::calib;

namespace {

std::string errorOf(const std::string& text) {
  try {
    parsePosteriorCsv(text, "post.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

fs::path tempDir(const std::string& name) { return dtwin_test::freshDir("dtwin_folder_" + name); }
using dtwin_test::writeText;

std::string folderError(const fs::path& dir) {
  try {
    readCalibrationFolder(dir.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kPosterior = "a,b,tau,design_index\n1,2,0.5,3\n";

}  // namespace

TEST(CalibrationFolder, ReadsPosteriorCsv) {
  const auto ps = parsePosteriorCsv(
      std::string("\xEF\xBB\xBF") + "a,b,tau,design_index\r\n1,2,0.5,3\r\n\r\n4,5e3,1e-4,0\n",
      "p.csv");
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps.names, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(ps.theta[1], (std::vector<double>{4, 5000}));
  EXPECT_EQ(ps.tau[1], 1e-4);
  EXPECT_EQ(ps.design_index[0], 3);
}

TEST(CalibrationFolder, PosteriorCsvErrorsNameFileLineAndRule) {
  EXPECT_EQ(errorOf(""),
            "post.csv: empty file (expected the header <parameters>,tau,design_index)");
  EXPECT_NE(errorOf("a,b,design_index\n1,2,3\n").find("post.csv:1: header must be"),
            std::string::npos);
  EXPECT_NE(errorOf("tau,design_index\n1,2\n").find("post.csv:1: header must be"),
            std::string::npos);
  EXPECT_NE(errorOf("a,a,tau,design_index\n").find("post.csv:1: header: column 'a' appears twice"),
            std::string::npos);
  EXPECT_EQ(errorOf("a,tau,design_index\n"), "post.csv: no rows after the header (line 1)");
  EXPECT_EQ(errorOf("a,tau,design_index\n1,2,3\n1,2\n"), "post.csv:3: expected 3 fields, got 2");
  EXPECT_EQ(errorOf("a,tau,design_index\nx,2,3\n"), "post.csv:2: a: must be a number, got 'x'");
  EXPECT_EQ(errorOf("a,tau,design_index\nnan,2,3\n"), "post.csv:2: a: must be finite, got nan");
  EXPECT_EQ(errorOf("a,tau,design_index\n1,0,3\n"),
            "post.csv:2: tau: must be a finite number > 0 (a precision), got 0");
  EXPECT_EQ(errorOf("a,tau,design_index\n1,2,-1\n"),
            "post.csv:2: design_index: must be an integer >= 0, got '-1'");
  EXPECT_EQ(errorOf("a,tau,design_index\n1,2,1.5\n"),
            "post.csv:2: design_index: must be an integer >= 0, got '1.5'");
  EXPECT_THROW(readPosteriorCsv("/nonexistent/posterior.csv"), InputError);
}

TEST(CalibrationFolder, PosteriorCsvRoundTripsExactly) {
  const std::vector<std::string> names{"tire.stiffness", "tire.damping"};
  const std::vector<std::vector<double>> theta{{180000.0 + 1.0 / 3.0, 2999.999999999},
                                               {1e-300, 0.1 + 0.2}};
  const std::vector<double> tau{5.5e-5, std::numeric_limits<double>::denorm_min()};
  const std::vector<long> index{0, 1234567};
  const auto back = parsePosteriorCsv(posteriorCsv(names, theta, tau, index), "rt.csv");
  EXPECT_EQ(back.names, names);
  EXPECT_EQ(back.theta, theta);  // bit for bit
  EXPECT_EQ(back.tau, tau);
  EXPECT_EQ(back.design_index, index);
}

TEST(CalibrationFolder, ReadsSummaryAndPosterior) {
  const fs::path dir = tempDir("ok");
  writeText(
      dir / "summary.json",
      R"({"assembly": "M3", "setup": {"extra_effects": [], "extra_calibrated": [], "channel_weights": {}}})");
  writeText(dir / "posterior.csv", kPosterior);
  const auto f = readCalibrationFolder(dir.string());
  EXPECT_EQ(f.assembly, "M3");
  EXPECT_TRUE(f.setup.extra_effects.empty());
  EXPECT_EQ(f.posterior.size(), 1u);
  EXPECT_EQ(f.posterior.names, (std::vector<std::string>{"a", "b"}));
}

// posterior.csv's checksum in summary.json: the file as written reads; a value changed in the
// middle (still a well-formed file) is refused, naming the file and the rule; no checksum recorded
// (a folder written before they were): read as before.
TEST(CalibrationFolder, APosteriorChangedAfterItWasWrittenIsRefused) {
  const fs::path dir = tempDir("checksum");
  const std::string text = "a,b,tau,design_index\n1,2,0.5,3\n4,5,0.25,1\n6,7,0.5,2\n";
  const std::string sum = contentChecksum(text);
  writeText(dir / "summary.json", R"({"assembly": "M3", "posterior_checksum": ")" + sum + "\"}");
  writeText(dir / "posterior.csv", text);
  EXPECT_EQ(readCalibrationFolder(dir.string()).posterior.size(), 3u);
  std::string changed = text;
  changed[changed.find("4,5")] = '8';  // the middle row's first value
  writeText(dir / "posterior.csv", changed);
  const std::string rule = (dir / "posterior.csv").string() + ": fails its checksum (" +
                           (dir / "summary.json").string() + " records " + sum +
                           "): it changed after the calibration wrote it and is not used; rerun "
                           "that calibration into its folder to write it again";
  EXPECT_EQ(folderError(dir), rule);
  try {
    readPosteriorCsv((dir / "posterior.csv").string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), rule);
  }
  writeText(dir / "summary.json", R"({"assembly": "M3"})");
  EXPECT_EQ(readCalibrationFolder(dir.string()).posterior.theta[1][0],
            8.0);  // nothing recorded to check against
}

TEST(CalibrationFolder, EveryBrokenPartIsNamed) {
  const fs::path dir = tempDir("broken");
  EXPECT_EQ(folderError(dir / "missing"),
            (dir / "missing").string() +
                ": is not a folder (give one written by `twin calibrate` or `twin diagnose`)");
  EXPECT_EQ(
      folderError(dir),
      dir.string() +
          ": has no summary.json (give a folder written by `twin calibrate` or `twin diagnose`)");
  writeText(dir / "optimum.json", "{}");  // a diagnosis candidate calibrated to its optimum only
  EXPECT_NE(folderError(dir).find("holds only an optimum"), std::string::npos) << folderError(dir);
  fs::remove(dir / "optimum.json");
  writeText(dir / "summary.json", "{\"assembly\": ");
  EXPECT_NE(folderError(dir).find((dir / "summary.json").string() + ": is not valid JSON"),
            std::string::npos);
  writeText(dir / "summary.json", "[1, 2]");
  EXPECT_EQ(folderError(dir), (dir / "summary.json").string() + ": must hold a JSON object");
  writeText(dir / "summary.json", "{}");
  EXPECT_EQ(folderError(dir), (dir / "summary.json").string() + ": assembly: is missing");
  writeText(dir / "summary.json", R"({"assembly": 3})");
  EXPECT_EQ(folderError(dir), (dir / "summary.json").string() +
                                  ": assembly: must be a non-empty string (an assembly id), got 3");
  writeText(dir / "summary.json", R"({"assembly": "M1", "setup": {"extra_effects": 7}})");
  EXPECT_NE(folderError(dir).find((dir / "summary.json").string() + ": setup: is malformed"),
            std::string::npos);
  writeText(dir / "summary.json", R"({"assembly": "M1"})");
  EXPECT_EQ(folderError(dir), (dir / "posterior.csv").string() + ": posterior file not found");
}

TEST(CalibrationFolder, AnAssemblyTheStudyLacksIsBlamedOnTheSummary) {
  const fs::path dir = tempDir("assembly");
  writeText(dir / "summary.json", R"({"assembly": "M9"})");
  writeText(dir / "posterior.csv", kPosterior);
  const auto f = readCalibrationFolder(dir.string());
  const Study study = loadStudy(std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml");
  try {
    calibratedAssembly(study, f);
    FAIL() << "M9 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), (dir / "summary.json").string() + ": assembly");
    EXPECT_NE(e.rule().find("'M9' is not an assembly of the study"), std::string::npos) << e.rule();
  }
  writeText(dir / "summary.json", R"({"assembly": "M2"})");
  EXPECT_EQ(calibratedAssembly(study, readCalibrationFolder(dir.string())).id, "M2");
}
