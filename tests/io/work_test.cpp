// The work estimate (io/work.hpp): closed-form counts from the sizes, the stage selection, and
// the refusal above the limits unless forced.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "io/work.hpp"

namespace {

const std::string kSrc = DTWIN_SOURCE_DIR;

double total(const std::vector<dtwin::StageWork>& w, double dtwin::StageWork::*field) {
  double s = 0;
  for (const auto& x : w) s += x.*field;
  return s;
}

TEST(Work, CountsFollowTheSizes) {
  dtwin::Study s = dtwin::loadStudy(kSrc + "/data/studies/demo.toml");
  s.sizes.field_runs = 37;
  s.sizes.posterior_draws = 11;
  s.sizes.roads_per_draw = 3;
  s.sizes.lhs_points = 100;
  s.calibration.max_rounds = 2;
  s.calibration.round_points = 50;
  const auto all = dtwin::estimateStudyWork(s);
  ASSERT_EQ(all.size(),
            2u + 2u * s.assemblies().size());  // lab, field, then calibrate/synthesize each
  const double field_s = s.scenario("field").duration_s, lab_s = s.scenario("lab").duration_s;
  const auto field = dtwin::selectStages(all, {"field"});
  ASSERT_EQ(field.size(), 1u);
  EXPECT_EQ(field[0].simulations, 37);
  EXPECT_DOUBLE_EQ(field[0].simulated_s, 37 * field_s);
  EXPECT_DOUBLE_EQ(field[0].memory_bytes, 8.0 * 37 * field_s * s.simulation.output_rate_hz);
  const auto synth = dtwin::selectStages(all, {"synthesize"});
  ASSERT_EQ(synth.size(), s.assemblies().size());
  for (const auto& w : synth) EXPECT_DOUBLE_EQ(w.simulated_s, 11 * 3 * field_s);
  const auto cal = dtwin::selectStages(all, {"calibrate M2"});
  ASSERT_EQ(cal.size(), 1u);
  EXPECT_EQ(cal[0].stage, "calibrate M2");
  // design 100 + 2 rounds x 50, the optimiser's and the profile's budgets
  EXPECT_DOUBLE_EQ(cal[0].simulations,
                   200 + s.sizes.optimizer_starts * 500.0 + s.calibrated.size() * 2400.0);
  EXPECT_DOUBLE_EQ(cal[0].simulated_s, cal[0].simulations * lab_s);
}

TEST(Work, StageNamesMatchWholeWordsOnly) {
  const std::vector<dtwin::StageWork> all = {
      {"calibrate M1", 1, 1, 0}, {"calibrate M10", 1, 1, 0}, {"labx", 1, 1, 0}};
  EXPECT_EQ(dtwin::selectStages(all, {"calibrate M1"}).size(), 1u);
  EXPECT_EQ(dtwin::selectStages(all, {"calibrate"}).size(), 2u);
  EXPECT_EQ(dtwin::selectStages(all, {"lab"}).size(), 0u);
}

TEST(Work, RefusedAboveTheLimitsUnlessForced) {
  const dtwin::WorkLimits lim{100.0, 1000.0};
  const std::vector<dtwin::StageWork> small = {{"lab", 1, 60, 10}, {"field", 1, 40, 999}};
  EXPECT_NO_THROW(dtwin::checkWork(small, "s.toml", false, lim));  // 100 s, 999 B: at the limits
  const std::vector<dtwin::StageWork> slow = {{"lab", 1, 60, 10}, {"field", 2, 41, 10}};
  try {
    dtwin::checkWork(slow, "s.toml", false, lim);
    FAIL() << "expected a refusal";
  } catch (const dtwin::InputError& e) {
    EXPECT_EQ(e.where(), "s.toml");
    EXPECT_NE(e.rule().find("largest stage: lab"), std::string::npos) << e.rule();
    EXPECT_NE(e.rule().find("--force"), std::string::npos) << e.rule();
  }
  EXPECT_NO_THROW(dtwin::checkWork(slow, "s.toml", true, lim));
  const std::vector<dtwin::StageWork> big = {{"field", 1, 1, 1001}};
  EXPECT_THROW(dtwin::checkWork(big, "s.toml", false, lim), dtwin::InputError);
}

TEST(Work, ThePaperSizeStudyRunsWithoutForce) {
  const dtwin::Study paper = dtwin::loadStudy(kSrc + "/data/studies/paper.toml");
  const auto all = dtwin::estimateStudyWork(paper);
  const double sim_s = total(all, &dtwin::StageWork::simulated_s);
  EXPECT_GT(sim_s, 1e6);                                  // the paper's sizes are large ...
  EXPECT_LT(sim_s, dtwin::WorkLimits{}.simulated_s / 2);  // ... and well inside the limit
  EXPECT_NO_THROW(dtwin::checkWork(all, paper.path, false));
  std::printf("paper-size study: %.3g simulated s, %.3g simulations\n", sim_s,
              total(all, &dtwin::StageWork::simulations));
}

}  // namespace
