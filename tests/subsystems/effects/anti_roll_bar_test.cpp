// The `anti_roll_bar` effect's closed form (subsystems/effects/anti_roll_bar.hpp); the contract
// every effect keeps is checked over the registry in tests/subsystems/effect_test.cpp.
#include "subsystems/effects/anti_roll_bar.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "../effect_fixture.hpp"

namespace dtwin {
namespace {

using dtwin_test::strut;
using dtwin_test::valuesWith;

TEST(AntiRollBar, ForceIsAxleRateTimesDeflectionDifference) {
  auto e = makeEffect("anti_roll_bar", "t");
  const double kf = 20000.0, kr = 8000.0;
  const auto v = valuesWith(*e, {{"stiffness_front_N_per_m", kf}, {"stiffness_rear_N_per_m", kr}});
  for (double ql : {-0.1, 0.0, 0.04, 0.2})
    for (double qr : {-0.05, 0.0, 0.04}) {
      EXPECT_NEAR(e->calcAxleCouplingForce(ql, qr, true, v), kf * (ql - qr), 1e-12 * kf);
      EXPECT_NEAR(e->calcAxleCouplingForce(ql, qr, false, v), kr * (ql - qr), 1e-12 * kr);
      // Antisymmetric: swapping the sides negates the force (the right strut gets -F).
      EXPECT_EQ(e->calcAxleCouplingForce(qr, ql, true, v),
                -e->calcAxleCouplingForce(ql, qr, true, v));
    }
  // Identical deflections: nothing, whatever the stiffness.
  for (double q : {-0.1, 0.0, 0.07}) EXPECT_EQ(e->calcAxleCouplingForce(q, q, true, v), 0.0);
  // Stated stiffness by finite differences (d/dq_left = k, d/dq_right = -k), monotone in q_left.
  const double h = 1e-6;
  EXPECT_NEAR((e->calcAxleCouplingForce(0.03 + h, 0.01, true, v) -
               e->calcAxleCouplingForce(0.03 - h, 0.01, true, v)) /
                  (2 * h) / kf,
              1.0, 1e-6);
  EXPECT_NEAR((e->calcAxleCouplingForce(0.03, 0.01 + h, false, v) -
               e->calcAxleCouplingForce(0.03, 0.01 - h, false, v)) /
                  (2 * h) / kr,
              -1.0, 1e-6);
  // Only one axle's bar installed: the other exerts nothing.
  const auto front_only = valuesWith(*e, {{"stiffness_front_N_per_m", kf}});
  EXPECT_EQ(e->calcAxleCouplingForce(0.05, -0.05, false, front_only), 0.0);
}

}  // namespace
}  // namespace dtwin
