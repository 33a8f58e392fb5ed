// The `speed_dependent_tire_stiffness` effect's closed form
// (subsystems/effects/speed_dependent_tire_stiffness.hpp); the contract every effect keeps is
// checked over the registry in tests/subsystems/effect_test.cpp.
#include "subsystems/effects/speed_dependent_tire_stiffness.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "../effect_fixture.hpp"

namespace dtwin {
namespace {

using dtwin_test::valuesWith;

TEST(SpeedDependentTireStiffness, FactorIsOnePlusCvTimesSpeed) {
  auto e = makeEffect("speed_dependent_tire_stiffness", "t");
  const double cv = 0.006;
  const auto v = valuesWith(*e, {{"c_v", cv}});
  TireState ts;
  ts.deflection_m = 0.02;
  EXPECT_EQ(e->tireForceFactor(ts, v), 1.0);  // none at rest
  double prev = 1.0;
  for (double speed : {0.5, 2.0, 8.9408, 20.0, 40.0}) {
    ts.forward_speed_mps = speed;
    ts.wheel_speed_radps = speed / 0.3;
    const double f = e->tireForceFactor(ts, v);
    EXPECT_NEAR(f, 1.0 + cv * speed, 1e-15) << speed;
    EXPECT_GT(f, prev);  // monotone in speed
    prev = f;
    // Independent of the deflection: the stiffness is scaled by the same factor. Finite
    // differences on a linear law k rho scaled by the factor give k (1 + c_v v).
    const double k = 2.0e5, h = 1e-7;
    auto force = [&](double rho) {
      TireState s2 = ts;
      s2.deflection_m = rho;
      return k * rho * e->tireForceFactor(s2, v);
    };
    EXPECT_NEAR((force(0.02 + h) - force(0.02 - h)) / (2 * h) / (k * (1 + cv * speed)), 1.0, 1e-6);
  }
}

}  // namespace
}  // namespace dtwin
