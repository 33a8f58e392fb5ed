// The `progressive_spring` effect's closed form (subsystems/effects/progressive_spring.hpp); the
// contract every effect keeps is checked over the registry in tests/subsystems/effect_test.cpp.
#include "subsystems/effects/progressive_spring.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../effect_fixture.hpp"

namespace dtwin {
namespace {

using dtwin_test::strut;
using dtwin_test::valuesWith;

TEST(ProgressiveSpring, CubicOddMonotoneWithStatedTangentStiffness) {
  auto e = makeEffect("progressive_spring", "t");
  const double k3 = 2.0e6;
  const auto v = valuesWith(*e, {{"stiffness3", k3}});
  for (double q : {-0.3, -0.1, -0.01, 0.0, 0.02, 0.1, 0.25})
    for (double qdot : {-1.0, 0.0, 2.0}) {  // independent of the rate
      const double expected = k3 * q * q * q;
      EXPECT_NEAR(e->calcStrutForce(strut(q, qdot), v), expected,
                  1e-12 * std::abs(expected) + 1e-300)
          << q;
      EXPECT_EQ(e->calcStrutForce(strut(-q, qdot), v), -e->calcStrutForce(strut(q, qdot), v))
          << q;  // odd
    }
  double prev = -1e300;
  for (int i = -300; i <= 300; ++i) {  // monotone increasing
    const double f = e->calcStrutForce(strut(0.001 * i, 0.0), v);
    EXPECT_GE(f, prev);
    prev = f;
  }
  // Finite-difference stiffness = 3 k3 q^2 (zero at the design height).
  const double h = 1e-6;
  for (double q : {-0.15, 0.05, 0.1, 0.2}) {
    const double fd =
        (e->calcStrutForce(strut(q + h, 0), v) - e->calcStrutForce(strut(q - h, 0), v)) / (2 * h);
    EXPECT_NEAR(fd / (3 * k3 * q * q), 1.0, 1e-6) << q;
  }
  const double fd0 =
      (e->calcStrutForce(strut(h, 0), v) - e->calcStrutForce(strut(-h, 0), v)) / (2 * h);
  EXPECT_NEAR(fd0, 0.0, 1e-5);
}

}  // namespace
}  // namespace dtwin
