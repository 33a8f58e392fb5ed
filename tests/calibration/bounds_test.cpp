// Values on their bounds (calibration/bounds.hpp): which values are findings, and what the
// sentence says.
#include "calibration/bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace dtwin::calib;

namespace {

BoundInputs twoValues() {
  BoundInputs in;
  in.names = {"tire.damping", "chassis.mass_kg"};
  in.units = {"N*s/m", "kg"};
  in.lower = {500.0, 1000.0};
  in.upper = {7000.0, 2000.0};
  in.optimum = {3000.0, 1500.0};
  in.limit_lower = {0.0, 150.0};
  in.limit_upper = {2e4, 8000.0};
  in.limit_basis = {"tire damping", "sprung masses"};
  return in;
}

}  // namespace

TEST(Bounds, AnInteriorOptimumIsNoFinding) { EXPECT_TRUE(findBounds(twoValues()).empty()); }

TEST(Bounds, AnOptimumOnItsUpperBoundSaysTheDataWantMoreAndHowFarToWiden) {
  BoundInputs in = twoValues();
  in.optimum[0] = 6999.0;  // within 0.1 % of the range (6.5) of the bound
  const auto f = findBounds(in);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].name, "tire.damping");
  EXPECT_EQ(f[0].side, "upper");
  EXPECT_TRUE(f[0].optimum_on_bound);
  EXPECT_EQ(f[0].bound, 7000.0);
  EXPECT_EQ(f[0].limit, 2e4);
  EXPECT_FALSE(f[0].at_limit());
  const std::string s = f[0].sentence();
  EXPECT_NE(s.find("tire.damping is at its upper bound 7000 N*s/m"), std::string::npos) << s;
  EXPECT_NE(s.find("the data want more"), std::string::npos) << s;
  EXPECT_NE(s.find("may reach 20000 N*s/m"), std::string::npos) << s;
  EXPECT_NE(s.find("or the structure differs"), std::string::npos) << s;
  // 7 units inside is not on the bound.
  in.optimum[0] = 6993.0;
  EXPECT_TRUE(findBounds(in).empty());
}

TEST(Bounds, ALowerBoundAtThePhysicalLimitSaysTheStructureDiffers) {
  BoundInputs in = twoValues();
  in.lower[1] = 150.0;  // the physical limit itself
  in.optimum[1] = 150.0;
  const auto f = findBounds(in);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].side, "lower");
  EXPECT_TRUE(f[0].at_limit());
  const std::string s = f[0].sentence();
  EXPECT_NE(s.find("the data want less"), std::string::npos) << s;
  EXPECT_NE(s.find("physical limit"), std::string::npos) << s;
  EXPECT_NE(s.find("the structure differs"), std::string::npos) << s;
  EXPECT_EQ(s.find("widen the range"), std::string::npos) << s;
}

TEST(Bounds, APosteriorPiledAgainstABoundIsAFindingEvenWithTheOptimumInside) {
  BoundInputs in = twoValues();
  Eigen::MatrixXd design(4, 2);
  design << 3000, 1990, 3000, 1995, 3000, 1999, 3000,
      1500;  // mass: 3 of 4 draws within 2 % (20 kg) of 2000
  in.design = &design;
  in.draws = {0, 1, 2, 3};
  in.optimum[1] = 1900.0;
  in.interval_lo = {2500, 1400};
  in.interval_hi = {3500, 2000};
  auto f = findBounds(in);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].name, "chassis.mass_kg");
  EXPECT_EQ(f[0].side, "upper");
  EXPECT_FALSE(f[0].optimum_on_bound);
  EXPECT_DOUBLE_EQ(f[0].posterior_share, 0.75);
  EXPECT_TRUE(f[0].interval_reaches);
  EXPECT_NE(f[0].sentence().find("75 % of the posterior"), std::string::npos) << f[0].sentence();
  in.draws = {0, 3};  // half of 2 draws: 0.5 is the threshold
  design(0, 1) = 1500;
  f = findBounds(in);
  EXPECT_TRUE(f.empty());
}

TEST(Bounds, AnIntervalOverMostOfTheRangeIsUndetermined) {
  BoundInputs in = twoValues();
  in.interval_lo = {600, 1200};
  in.interval_hi = {6900, 1800};
  const auto f = findBounds(in);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].name, "tire.damping");
  EXPECT_EQ(f[0].side, "none");
  EXPECT_NEAR(f[0].interval_span, 6300.0 / 6500.0, 1e-12);
  EXPECT_NE(f[0].sentence().find("do not determine it"), std::string::npos) << f[0].sentence();
}

TEST(Bounds, FindingsRoundTripThroughJson) {
  BoundInputs in = twoValues();
  in.optimum[0] = 500.0;
  in.limit_lower[0] = std::numeric_limits<double>::quiet_NaN();
  const auto f = findBounds(in);
  ASSERT_EQ(f.size(), 1u);
  const BoundFinding back = BoundFinding::fromJson(f[0].toJson());
  EXPECT_EQ(back.sentence(), f[0].sentence());
  EXPECT_TRUE(std::isnan(back.limit));
  EXPECT_NE(back.sentence().find("no physical limit is known"), std::string::npos)
      << back.sentence();
}
