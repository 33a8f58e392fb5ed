// The `strut_friction` effect's closed form (subsystems/effects/strut_friction.hpp); the contract
// every effect keeps is checked over the registry in tests/subsystems/effect_test.cpp.
#include "subsystems/effects/strut_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../effect_fixture.hpp"

namespace dtwin {
namespace {

using dtwin_test::strut;
using dtwin_test::valuesWith;

TEST(StrutFriction, OddTanhOfRateSaturatingAtCoulombLevel) {
  auto e = makeEffect("strut_friction", "t");
  const double Fc = 150.0, vs = 0.02;
  const auto v = valuesWith(*e, {{"force_N", Fc}, {"smoothing_velocity_mps", vs}});
  EXPECT_EQ(e->calcStrutForce(strut(0.03, 0.0), v), 0.0);
  for (double qdot : {1e-4, 0.005, 0.02, 0.05, 0.3, 2.0}) {
    const double f = e->calcStrutForce(strut(0.01, qdot), v);
    EXPECT_EQ(e->calcStrutForce(strut(0.01, -qdot), v), -f) << qdot;  // odd
    EXPECT_NEAR(f, Fc * std::tanh(qdot / vs), 1e-12 * Fc) << qdot;    // tanh shape
    EXPECT_GT(f, 0.0);                                                // opposes compression
    EXPECT_LE(f, Fc);
  }
  // tanh(1) at the smoothing velocity; saturates at +-Fc for |rate| >> v_s.
  EXPECT_NEAR(e->calcStrutForce(strut(0, vs), v) / Fc, std::tanh(1.0), 1e-14);
  EXPECT_NEAR(e->calcStrutForce(strut(0, 20 * vs), v), Fc, 1e-12 * Fc);
  EXPECT_NEAR(e->calcStrutForce(strut(0, -20 * vs), v), -Fc, 1e-12 * Fc);
  // Small-rate slope Fc / v_s (a viscous-like region).
  const double h = 1e-7;
  EXPECT_NEAR((e->calcStrutForce(strut(0, h), v) - e->calcStrutForce(strut(0, -h), v)) / (2 * h),
              Fc / vs, 1e-6 * Fc / vs);
  // Monotone in rate, independent of the deflection.
  double prev = -Fc;
  for (int i = -100; i <= 100; ++i) {
    const double qdot = 0.002 * i;
    const double f = e->calcStrutForce(strut(0.0, qdot), v);
    EXPECT_GE(f, prev);
    EXPECT_EQ(f, e->calcStrutForce(strut(0.2, qdot), v));
    prev = f;
  }
}

}  // namespace
}  // namespace dtwin
