// The `bump_stop` effect's closed form (subsystems/effects/bump_stop.hpp); the contract every
// effect keeps is checked over the registry in tests/subsystems/effect_test.cpp.
#include "subsystems/effects/bump_stop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../effect_fixture.hpp"

namespace dtwin {
namespace {

using dtwin_test::strut;
using dtwin_test::valuesWith;

TEST(BumpStop, ZeroBelowGapPowerLawAbove) {
  auto e = makeEffect("bump_stop", "t");
  const double k = 2.0e6, gap = 0.06;
  for (double n : {1.0, 1.5, 2.0, 3.0}) {
    const auto v = valuesWith(*e, {{"stiffness", k}, {"gap_m", gap}, {"exponent", n}});
    for (double q : {-0.2, 0.0, 0.03, gap - 1e-9, gap})
      EXPECT_EQ(e->calcStrutForce(strut(q, 0.3), v), 0.0) << q;
    for (double q : {gap + 1e-4, 0.07, 0.1, 0.25})
      for (double qdot : {-1.0, 0.0, 2.0}) {  // independent of the rate
        const double expected = k * std::pow(q - gap, n);
        EXPECT_NEAR(e->calcStrutForce(strut(q, qdot), v), expected, 1e-12 * expected)
            << "n " << n << " q " << q;
      }
    // Monotone non-decreasing in deflection, continuous at the gap.
    double prev = 0.0;
    for (int i = 0; i <= 500; ++i) {
      const double q = -0.1 + 0.4 * i / 500.0;
      const double f = e->calcStrutForce(strut(q, 0.0), v);
      EXPECT_GE(f, prev) << "n " << n << " q " << q;
      prev = f;
    }
    EXPECT_LT(e->calcStrutForce(strut(gap + 1e-9, 0.0), v), k * 1e-9 * 1.0000001);
  }
}

TEST(BumpStop, LinearStopHasStiffnessKJustAboveGap) {
  auto e = makeEffect("bump_stop", "t");
  const double k = 5.0e5, gap = 0.04;
  const auto v = valuesWith(*e, {{"stiffness", k}, {"gap_m", gap}, {"exponent", 1.0}});
  const double q = gap + 1e-3, h = 1e-6;
  const double fd =
      (e->calcStrutForce(strut(q + h, 0), v) - e->calcStrutForce(strut(q - h, 0), v)) / (2 * h);
  EXPECT_NEAR(fd / k, 1.0, 1e-6);
  // Below the gap there is no stiffness.
  const double fd_below = (e->calcStrutForce(strut(gap - 1e-3 + h, 0), v) -
                           e->calcStrutForce(strut(gap - 1e-3 - h, 0), v)) /
                          (2 * h);
  EXPECT_EQ(fd_below, 0.0);
}

}  // namespace
}  // namespace dtwin
