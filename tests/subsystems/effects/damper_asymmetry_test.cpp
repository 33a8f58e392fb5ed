// The `damper_asymmetry` effect's closed form (subsystems/effects/damper_asymmetry.hpp); the
// contract every effect keeps is checked over the registry in tests/subsystems/effect_test.cpp.
#include "subsystems/effects/damper_asymmetry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../effect_fixture.hpp"

namespace dtwin {
namespace {

using dtwin_test::strut;
using dtwin_test::valuesWith;

TEST(DamperAsymmetry, AddsOnlyInRebound) {
  auto e = makeEffect("damper_asymmetry", "t");
  for (double ratio : {0.6, 1.8, 3.0}) {
    const auto v = valuesWith(*e, {{"ratio", ratio}});
    for (double q : {-0.05, 0.0, 0.08}) {
      for (double qdot : {1e-9, 0.1, 1.0, 3.0})  // compression: no change
        EXPECT_EQ(e->calcStrutForce(strut(q, qdot), v), 0.0)
            << "ratio " << ratio << " qdot " << qdot;
      EXPECT_EQ(e->calcStrutForce(strut(q, 0.0), v), 0.0);
      for (double qdot : {-1e-3, -0.2, -1.5}) {  // rebound: (ratio - 1) c qdot
        const double expected = (ratio - 1.0) * 2500.0 * qdot;
        EXPECT_NEAR(e->calcStrutForce(strut(q, qdot), v), expected, 1e-12 * std::abs(expected))
            << "ratio " << ratio << " qdot " << qdot;
      }
    }
    // Total damping in rebound is ratio * c: the slope of main + extra force vs rate.
    const auto total = [&](double qdot) {
      return 2500.0 * qdot + e->calcStrutForce(strut(0.0, qdot), v);
    };
    EXPECT_NEAR((total(-0.3) - total(-0.5)) / 0.2, ratio * 2500.0, 1e-9);
    EXPECT_NEAR((total(0.5) - total(0.3)) / 0.2, 2500.0, 1e-9);
  }
  // The extra force scales with the main damper's coefficient.
  const auto v = valuesWith(*e, {{"ratio", 2.0}});
  StrutState s = strut(0.0, -0.4);
  s.base_damping = 4000.0;
  EXPECT_NEAR(e->calcStrutForce(s, v), 4000.0 * -0.4, 1e-9);
}

}  // namespace
}  // namespace dtwin
