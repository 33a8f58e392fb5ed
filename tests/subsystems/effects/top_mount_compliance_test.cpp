// The `top_mount_compliance` effect's closed form (subsystems/effects/top_mount_compliance.hpp);
// the contract every effect keeps is checked over the registry in tests/subsystems/effect_test.cpp.
#include "subsystems/effects/top_mount_compliance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../effect_fixture.hpp"

namespace dtwin {
namespace {

using dtwin_test::strut;
using dtwin_test::valuesWith;

TEST(TopMountCompliance, FirstOrderFilterOfTheDampingForce) {
  auto e = makeEffect("top_mount_compliance", "t");
  const double C = 4e-6, c = 2500.0, tau = c * C;
  const auto v = valuesWith(*e, {{"compliance_m_per_N", C}});
  EXPECT_TRUE(e->filterActive(v));
  // Steady state: z = c qdot gives no extra force and no change.
  for (double qdot : {-1.0, 0.0, 0.3}) {
    EXPECT_EQ(e->calcFilteredStrutForce(strut(0.01, qdot), c * qdot, v), 0.0);
    EXPECT_EQ(e->calcFilterRate(strut(0.01, qdot), c * qdot, v), 0.0);
  }
  // The extra force replaces c qdot by z; the rate is (c qdot - z) / tau (d rate / dz = -1/tau).
  EXPECT_NEAR(e->calcFilteredStrutForce(strut(0.0, 0.2), 100.0, v), 100.0 - c * 0.2, 1e-9);
  const double h = 1e-3;
  const double fd = (e->calcFilterRate(strut(0, 0.2), 100.0 + h, v) -
                     e->calcFilterRate(strut(0, 0.2), 100.0 - h, v)) /
                    (2 * h);
  EXPECT_NEAR(fd * tau, -1.0, 1e-9);
  // Frequency response of the transmitted damping force z to qdot = sin(w t): gain
  // c / sqrt(1 + (w tau)^2) (RK4 integration to a periodic steady state).
  for (double f_hz : {1.0, 12.0, 40.0}) {
    const double w = 2 * M_PI * f_hz, dt = std::min(tau, 1 / f_hz) / 200.0;
    double z = 0.0, t = 0.0, amp = 0.0;
    auto rate = [&](double tt, double zz) {
      return e->calcFilterRate(strut(0.0, std::sin(w * tt)), zz, v);
    };
    const double t_end = 10 * tau + 5.0 / f_hz;
    while (t < t_end) {
      const double k1 = rate(t, z), k2 = rate(t + dt / 2, z + dt / 2 * k1),
                   k3 = rate(t + dt / 2, z + dt / 2 * k2), k4 = rate(t + dt, z + dt * k3);
      z += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      t += dt;
      if (t > t_end - 2.0 / f_hz) amp = std::max(amp, std::abs(z));
    }
    EXPECT_NEAR(amp / (c / std::sqrt(1 + w * w * tau * tau)), 1.0, 2e-3) << f_hz << " Hz";
  }
  // No damping: nothing to filter.
  StrutState s0 = strut(0.0, 0.5);
  s0.base_damping = 0.0;
  EXPECT_EQ(e->calcFilteredStrutForce(s0, 0.0, v), 0.0);
  EXPECT_EQ(e->calcFilterRate(s0, 0.0, v), 0.0);
}

}  // namespace
}  // namespace dtwin
