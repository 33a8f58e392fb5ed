// The coverage benchmark: the Wilson interval against known values, and a tiny run end to end
// (files, counts that add up, a rerun that resumes to the same table).
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <filesystem>

#include "common/errors.hpp"
#include "study/coverage.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::calib;

TEST(Coverage, WilsonIntervalMatchesReferenceValues) {
  // The roots p of (19/20 - p)^2 = z^2 p (1 - p) / 20 with z = 1.959964 (the quadratic solved
  // by hand): 0.7638688 and 0.9911186.
  auto [lo, hi] = wilsonInterval(19, 20);
  EXPECT_NEAR(lo, 0.7638688, 1e-6);
  EXPECT_NEAR(hi, 0.9911186, 1e-6);
  std::tie(lo, hi) = wilsonInterval(0, 10);
  EXPECT_DOUBLE_EQ(lo, 0.0);
  EXPECT_NEAR(hi, 0.2775328, 1e-6);
  std::tie(lo, hi) = wilsonInterval(72, 80);
  EXPECT_LT(lo, 0.9);
  EXPECT_GT(hi, 0.9);
}

TEST(Coverage, TinyRunCountsAndResumes) {
  const Study study =
      loadStudy(dtwin_test::writeTinyStudy(fs::path(::testing::TempDir()) / "tiny.toml").string());
  CoverageOptions o;
  o.seeds = 2;
  o.assemblies = {"M3"};
  o.out_dir = (fs::path(::testing::TempDir()) / "cov").string();
  o.calibration = CalibrationOptions::fromStudy(study);
  o.calibration.threads = 2;
  o.calibration.optimizer.maxeval = 40;
  o.calibration.lhs_points = 8;
  o.calibration.design.round_points = 8;
  o.calibration.design.max_rounds = 1;
  o.calibration.joint.ridge_steps = 3;
  o.calibration.gibbs_iterations = 300;
  o.calibration.gibbs_burn_in = 100;
  const CoverageResult r = runCoverage(study, o);
  ASSERT_EQ(r.rows.size(), 4u);
  int covered = 0;
  for (const auto& row : r.rows) {
    EXPECT_EQ(row.assembly, "M3");
    EXPECT_EQ(row.seeds, 2);
    EXPECT_GE(row.covered, 0);
    EXPECT_LE(row.covered, 2);
    EXPECT_GT(row.mean_width, 0.0);
    EXPECT_GT(row.mean_sd, 0.0);
    covered += row.covered;
  }
  ASSERT_EQ(r.totals.size(), 1u);
  EXPECT_EQ(r.totals[0].second.first, covered);
  EXPECT_EQ(r.totals[0].second.second, 8);
  for (const char* f : {"coverage.json", "coverage.md", "M3/lab_1001.csv", "M3/lab_1002.json",
                        "M3/seed_1001/summary.json", "M3/seed_1002/posterior.csv"})
    EXPECT_TRUE(fs::exists(fs::path(o.out_dir) / f)) << f;
  const auto j = nlohmann::json::parse(dtwin_test::slurp(fs::path(o.out_dir) / "coverage.json"));
  EXPECT_TRUE(j.contains("program"));
  EXPECT_EQ(j["seeds"]["first"], 1001);
  // The two seeds' data differ (independent noise), so do their calibrations.
  EXPECT_NE(dtwin_test::slurp(fs::path(o.out_dir) / "M3/lab_1001.csv"),
            dtwin_test::slurp(fs::path(o.out_dir) / "M3/lab_1002.csv"));
  // A rerun resumes every calibration and gives the same table.
  const CoverageResult again = runCoverage(study, o);
  EXPECT_EQ(again.markdown(), r.markdown());
  o.seeds = 1;
  EXPECT_THROW(o.validate(), InputError);
}

// Errors name the options' fields, never command-line flags (common/validate.hpp).
TEST(Coverage, BadOptionsNameTheField) {
  auto whereOf = [](const CoverageOptions& o) {
    try {
      o.validate();
    } catch (const InputError& e) {
      return e.where();
    }
    return std::string("(accepted)");
  };
  CoverageOptions o;
  o.out_dir = "cov";
  EXPECT_EQ(whereOf(o), "(accepted)");
  o.seeds = 1;
  EXPECT_EQ(whereOf(o), "coverage.seeds");
  o.seeds = 2;
  o.out_dir.clear();
  EXPECT_EQ(whereOf(o), "coverage.out_dir");
  o.out_dir = "cov";
  o.calibration.gibbs_burn_in = o.calibration.gibbs_iterations;
  EXPECT_EQ(whereOf(o), "calibration.gibbs_burn_in");
}
