// Values on their bounds from the command line: a study whose strut stiffness range stops short of
// the truth (25 kN/m against 30) is calibrated by `twin calibrate`, which says in words that the
// value sits on its upper bound and how far the range could be widened; summary.json records it,
// and `twin compare` of that calibration repeats it.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include <nlohmann/json.hpp>

#include "test_util.hpp"

namespace fs = std::filesystem;

TEST(BoundsCli, CalibrateAndCompareSayAValueSitsOnItsBound) {
  const fs::path dir = dtwin_test::freshDir("bounds_cli");
  // The data: the demo study's truth (30 kN/m). The calibration: the same study with the strut
  // stiffness's range [10, 180] kN/m cut to [10, 25] (and no truth, which would lie outside).
  const fs::path truth = dtwin_test::writeDemoStudy(dir / "truth.toml", "lab_repetitions = 3\n");
  const fs::path study = dir / "study.toml";
  std::string s = dtwin_test::slurp(truth);
  s = std::regex_replace(s, std::regex("lower = 10e3\nupper = 180e3\ntruth = 30e3"),
                         "lower = 10e3\nupper = 25e3");
  ASSERT_NE(s.find("upper = 25e3"), std::string::npos);
  dtwin_test::writeText(study, s);
  const std::string lab = (dir / "lab.csv").string();
  auto r =
      dtwin_test::runTwin("generate lab --quiet --study " + truth.string() + " --out " + lab, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  r = dtwin_test::runTwin("calibrate --quiet --study " + study.string() + " --data " + lab +
                              " --assembly M3 --out " + (dir / "cal").string() +
                              " --lhs-points 20 --iterations 400 --burn-in 100 --starts 1 "
                              "--max-rounds 0 --ridge-steps 0",
                          dir);
  ASSERT_EQ(r.code, 0) << r.err;
  r = dtwin_test::runTwin("calibrate --study " + study.string() + " --data " + lab +
                              " --assembly M3 --out " + (dir / "cal").string() +
                              " --lhs-points 20 --iterations 400 --burn-in 100 --starts 1 "
                              "--max-rounds 0 --ridge-steps 0",
                          dir);  // resumed: prints the result
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("FINDING: suspension.stiffness is at its upper bound 25000 N/m"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(
                "the data want more; widen the range (a road vehicle's value may reach 400000 N/m"),
            std::string::npos)
      << r.out;
  const auto summary =
      nlohmann::json::parse(dtwin_test::slurp(dir / "cal" / "M3" / "summary.json"));
  bool recorded = false;
  for (const auto& f : summary.at("bound_findings"))
    recorded = recorded || (f.at("name") == "suspension.stiffness" && f.at("side") == "upper" &&
                            f.at("optimum_on_bound") == true);
  EXPECT_TRUE(recorded) << summary.at("bound_findings").dump(2);
  // Only the value pushed out of its range: the tire values, whose ranges hold the truth, are no
  // findings.
  for (const auto& f : summary.at("bound_findings"))
    EXPECT_NE(f.at("name"), "tire.stiffness") << f.dump();
  r = dtwin_test::runTwin("compare --study " + study.string() + " --calibration " +
                              (dir / "cal" / "M3").string() + " --data " + lab + " --draws 3",
                          dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(
      r.out.find("note: the calibration: suspension.stiffness is at its upper bound 25000 N/m"),
      std::string::npos)
      << r.out;
}
