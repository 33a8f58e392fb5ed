// Tests of the optional physical effects (one contract run on every effect of the factory, then
// each effect's closed form) and of the linear strut law they are added to.
#include "subsystems/effect.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "subsystems/errors.hpp"
#include "subsystems/road.hpp"
#include "subsystems/strut_law.hpp"

namespace dtwin {
namespace {

constexpr Track kTracks[] = {Track::Left, Track::Right};

/// The "off" values of an effect (each ParameterSpec's default_value).
std::vector<double> offValues(const Effect& e) {
  std::vector<double> v;
  for (const auto& s : e.parameters()) v.push_back(s.default_value);
  return v;
}

/// The off values with some parameters replaced by name.
std::vector<double> valuesWith(const Effect& e, const std::map<std::string, double>& on) {
  std::vector<double> v = offValues(e);
  for (const auto& [name, value] : on) v[parameterIndex(e.parameters(), name)] = value;
  return v;
}

StrutState strut(double q, double qdot) {
  StrutState s;
  s.deflection_m = q;
  s.rate_mps = qdot;
  s.preload_N = 2907.0;
  s.base_stiffness = 30000.0;
  s.base_damping = 2500.0;
  return s;
}

/// A gridded road with some shape on both tracks (different per track).
GridRoad testGridRoad() {
  std::vector<double> l(200), r(200);
  for (int i = 0; i < 200; ++i) {
    l[i] = 0.02 * std::sin(0.37 * i) + 0.01 * std::cos(1.1 * i);
    r[i] = 0.015 * std::sin(0.53 * i + 1.0);
  }
  return GridRoad(-2.0, 0.05, l, r, {{"type", "test"}});
}

// ------------------------------------------------------------------ contract

/// Every effect: described, valid "off" values, and at them no trace at all: zero strut force and
/// the unmodified road.
void checkEffectContract(const Effect& e) {
  EXPECT_FALSE(e.description().empty());
  EXPECT_FALSE(e.signature().empty());
  ASSERT_FALSE(e.parameters().empty());
  for (const auto& spec : e.parameters()) {
    EXPECT_FALSE(spec.unit.empty()) << spec.name;
    EXPECT_FALSE(spec.description.empty()) << spec.name;
    EXPECT_EQ(checkParameterValue(spec, spec.default_value), "") << spec.name << ": the off value is invalid";
  }
  const std::vector<double> off = offValues(e);

  // Exactly zero strut force on a grid of deflections and rates (including beyond any gap).
  for (int i = -30; i <= 30; ++i)
    for (int j = -20; j <= 20; ++j) {
      const double q = 0.01 * i, qdot = 0.1 * j;
      EXPECT_EQ(e.calcStrutForce(strut(q, qdot), off), 0.0) << "q " << q << " qdot " << qdot;
    }
  for (double q : {-1.0, 0.5, 2.0})
    for (double qdot : {-50.0, -1e-9, 1e-9, 50.0}) EXPECT_EQ(e.calcStrutForce(strut(q, qdot), off), 0.0);

  // The road seen by the tire is exactly the road.
  BumpRoad bump(5.0, 0.2, 0.1);
  const GridRoad grid = testGridRoad();
  for (Track t : kTracks) {
    for (double x = 4.6; x <= 5.4; x += 0.0037) {
      const RoadSample a = e.filterRoad(bump, t, x, off), b = bump.sample(t, x);
      EXPECT_EQ(a.height_m, b.height_m) << "x " << x;
      EXPECT_EQ(a.slope, b.slope) << "x " << x;
    }
    for (double x = -2.5; x <= 8.5; x += 0.0173) {
      const RoadSample a = e.filterRoad(grid, t, x, off), b = grid.sample(t, x);
      EXPECT_EQ(a.height_m, b.height_m) << "x " << x;
      EXPECT_EQ(a.slope, b.slope) << "x " << x;
    }
  }
}

TEST(EffectContract, EveryEffectIsInertAtItsOffValues) {
  const auto names = effectNames();
  ASSERT_GE(names.size(), 4u);
  for (const auto& name : names) {
    SCOPED_TRACE("effect " + name);
    auto e = makeEffect(name, "test");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->name(), name);
    checkEffectContract(*e);
  }
}

TEST(EffectContract, KindsAreAsDocumented) {
  EXPECT_EQ(makeEffect("bump_stop", "t")->kind(), EffectKind::Strut);
  EXPECT_EQ(makeEffect("damper_asymmetry", "t")->kind(), EffectKind::Strut);
  EXPECT_EQ(makeEffect("strut_friction", "t")->kind(), EffectKind::Strut);
  EXPECT_EQ(makeEffect("tire_enveloping", "t")->kind(), EffectKind::TireInput);
}

TEST(EffectFactory, UnknownNameThrowsInputError) {
  try {
    makeEffect("foo", "study.toml: effects");
    FAIL() << "unknown effect accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("unknown effect 'foo'"), std::string::npos) << what;
    EXPECT_EQ(e.where(), "study.toml: effects");
    EXPECT_EQ(what.rfind("study.toml: effects: ", 0), 0u) << what;
    for (const auto& known : effectNames()) EXPECT_NE(what.find(known), std::string::npos) << what;
  }
}

// ------------------------------------------------------------------ bump stop

TEST(BumpStop, ZeroBelowGapPowerLawAbove) {
  auto e = makeEffect("bump_stop", "t");
  const double k = 2.0e6, gap = 0.06;
  for (double n : {1.0, 1.5, 2.0, 3.0}) {
    const auto v = valuesWith(*e, {{"stiffness", k}, {"gap_m", gap}, {"exponent", n}});
    for (double q : {-0.2, 0.0, 0.03, gap - 1e-9, gap}) EXPECT_EQ(e->calcStrutForce(strut(q, 0.3), v), 0.0) << q;
    for (double q : {gap + 1e-4, 0.07, 0.1, 0.25})
      for (double qdot : {-1.0, 0.0, 2.0}) {  // independent of the rate
        const double expected = k * std::pow(q - gap, n);
        EXPECT_NEAR(e->calcStrutForce(strut(q, qdot), v), expected, 1e-12 * expected) << "n " << n << " q " << q;
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
  const double fd = (e->calcStrutForce(strut(q + h, 0), v) - e->calcStrutForce(strut(q - h, 0), v)) / (2 * h);
  EXPECT_NEAR(fd / k, 1.0, 1e-6);
  // Below the gap there is no stiffness.
  const double fd_below =
      (e->calcStrutForce(strut(gap - 1e-3 + h, 0), v) - e->calcStrutForce(strut(gap - 1e-3 - h, 0), v)) / (2 * h);
  EXPECT_EQ(fd_below, 0.0);
}

// ------------------------------------------------------------------ damper asymmetry

TEST(DamperAsymmetry, AddsOnlyInRebound) {
  auto e = makeEffect("damper_asymmetry", "t");
  for (double ratio : {0.6, 1.8, 3.0}) {
    const auto v = valuesWith(*e, {{"ratio", ratio}});
    for (double q : {-0.05, 0.0, 0.08}) {
      for (double qdot : {1e-9, 0.1, 1.0, 3.0})  // compression: no change
        EXPECT_EQ(e->calcStrutForce(strut(q, qdot), v), 0.0) << "ratio " << ratio << " qdot " << qdot;
      EXPECT_EQ(e->calcStrutForce(strut(q, 0.0), v), 0.0);
      for (double qdot : {-1e-3, -0.2, -1.5}) {  // rebound: (ratio - 1) c qdot
        const double expected = (ratio - 1.0) * 2500.0 * qdot;
        EXPECT_NEAR(e->calcStrutForce(strut(q, qdot), v), expected, 1e-12 * std::abs(expected))
            << "ratio " << ratio << " qdot " << qdot;
      }
    }
    // Total damping in rebound is ratio * c: the slope of main + extra force vs rate.
    const auto total = [&](double qdot) { return 2500.0 * qdot + e->calcStrutForce(strut(0.0, qdot), v); };
    EXPECT_NEAR((total(-0.3) - total(-0.5)) / 0.2, ratio * 2500.0, 1e-9);
    EXPECT_NEAR((total(0.5) - total(0.3)) / 0.2, 2500.0, 1e-9);
  }
  // The extra force scales with the main damper's coefficient.
  const auto v = valuesWith(*e, {{"ratio", 2.0}});
  StrutState s = strut(0.0, -0.4);
  s.base_damping = 4000.0;
  EXPECT_NEAR(e->calcStrutForce(s, v), 4000.0 * -0.4, 1e-9);
}

// ------------------------------------------------------------------ strut friction

TEST(StrutFriction, OddTanhOfRateSaturatingAtCoulombLevel) {
  auto e = makeEffect("strut_friction", "t");
  const double Fc = 150.0, vs = 0.02;
  const auto v = valuesWith(*e, {{"force_N", Fc}, {"smoothing_velocity_mps", vs}});
  EXPECT_EQ(e->calcStrutForce(strut(0.03, 0.0), v), 0.0);
  for (double qdot : {1e-4, 0.005, 0.02, 0.05, 0.3, 2.0}) {
    const double f = e->calcStrutForce(strut(0.01, qdot), v);
    EXPECT_EQ(e->calcStrutForce(strut(0.01, -qdot), v), -f) << qdot;  // odd
    EXPECT_NEAR(f, Fc * std::tanh(qdot / vs), 1e-12 * Fc) << qdot;     // tanh shape
    EXPECT_GT(f, 0.0);                                                  // opposes compression
    EXPECT_LE(f, Fc);
  }
  // tanh(1) at the smoothing velocity; saturates at +-Fc for |rate| >> v_s.
  EXPECT_NEAR(e->calcStrutForce(strut(0, vs), v) / Fc, std::tanh(1.0), 1e-14);
  EXPECT_NEAR(e->calcStrutForce(strut(0, 20 * vs), v), Fc, 1e-12 * Fc);
  EXPECT_NEAR(e->calcStrutForce(strut(0, -20 * vs), v), -Fc, 1e-12 * Fc);
  // Small-rate slope Fc / v_s (a viscous-like region).
  const double h = 1e-7;
  EXPECT_NEAR((e->calcStrutForce(strut(0, h), v) - e->calcStrutForce(strut(0, -h), v)) / (2 * h), Fc / vs, 1e-6 * Fc / vs);
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

// ------------------------------------------------------------------ tire enveloping

TEST(TireEnveloping, AveragesTheBumpOverTheContactLength) {
  auto e = makeEffect("tire_enveloping", "t");
  const double x0 = 5.0, H = 0.2, L = 0.1, window = 0.3;
  BumpRoad bump(x0, H, L);
  const auto v = valuesWith(*e, {{"length_m", window}});
  const double plateau = 0.5 * H * L / window;  // whole bump area / window length
  double peak = 0.0;
  for (Track t : kTracks) {
    for (double x = x0 - 0.3; x <= x0 + L + 0.3; x += 0.001) {
      const RoadSample s = e->filterRoad(bump, t, x, v);
      peak = std::max(peak, s.height_m);
      EXPECT_GE(s.height_m, -1e-17);
      EXPECT_LE(s.height_m, plateau * (1 + 1e-12));
      // Slope is the derivative of the averaged height.
      const double h = 1e-6;
      const double fd = (e->filterRoad(bump, t, x + h, v).height_m - e->filterRoad(bump, t, x - h, v).height_m) / (2 * h);
      EXPECT_NEAR(s.slope, fd, 1e-6) << "x " << x;
    }
    // While the window covers the whole bump ([x - 0.15, x + 0.15] contains [x0, x0 + L]):
    for (double x : {x0 - 0.05 + 1e-6, x0, x0 + 0.05, x0 + 0.1, x0 + 0.15 - 1e-6}) {
      EXPECT_NEAR(e->filterRoad(bump, t, x, v).height_m, plateau, 1e-15) << "x " << x;
      EXPECT_NEAR(e->filterRoad(bump, t, x, v).slope, 0.0, 1e-15) << "x " << x;
    }
    // Far from the bump: flat.
    EXPECT_EQ(e->filterRoad(bump, t, x0 - 1.0, v).height_m, 0.0);
    EXPECT_EQ(e->filterRoad(bump, t, x0 + 1.0, v).height_m, 0.0);
    // Partly covered: the window [x - 0.15, x + 0.15] holds the bump's first half.
    const double xa = x0 + 0.05 - 0.15;
    EXPECT_NEAR(e->filterRoad(bump, t, xa, v).height_m, 0.25 * H * L / window, 1e-15);
  }
  EXPECT_NEAR(peak, plateau, 1e-12);
  EXPECT_LT(peak, H);  // far lower than the point-contact peak
  EXPECT_NEAR(peak / H, L / (2 * window), 1e-12);
}

TEST(TireEnveloping, ShortWindowTendsToPointContact) {
  auto e = makeEffect("tire_enveloping", "t");
  BumpRoad bump(5.0, 0.2, 0.1);
  const auto v = valuesWith(*e, {{"length_m", 1e-4}});
  for (double x = 5.001; x < 5.1; x += 0.0071) {
    EXPECT_NEAR(e->filterRoad(bump, Track::Left, x, v).height_m, bump.sample(Track::Left, x).height_m, 1e-5);
    EXPECT_NEAR(e->filterRoad(bump, Track::Left, x, v).slope, bump.sample(Track::Left, x).slope, 1e-3);
  }
}

// ------------------------------------------------------------------ linear strut

class LinearStrutTest : public ::testing::Test {
 protected:
  LinearStrut law;
  std::vector<double> p = values(30000.0, 2500.0, 0.25, 1.0e7);
  std::vector<double> values(double k, double c, double limit, double k_hs) const {
    std::vector<double> v(law.parameters().size());
    v[parameterIndex(law.parameters(), "stiffness")] = k;
    v[parameterIndex(law.parameters(), "damping")] = c;
    v[parameterIndex(law.parameters(), "travel_limit_m")] = limit;
    v[parameterIndex(law.parameters(), "hardstop_stiffness")] = k_hs;
    return v;
  }
};

TEST_F(LinearStrutTest, PreloadPlusSpringPlusDamperWithinTravel) {
  for (double q : {-0.25, -0.1, 0.0, 0.037, 0.2, 0.25})
    for (double qdot : {-1.2, 0.0, 0.4}) {
      const double expected = 2907.0 + 30000.0 * q + 2500.0 * qdot;
      EXPECT_NEAR(law.calcForce(strut(q, qdot), p), expected, 1e-9) << "q " << q << " qdot " << qdot;
    }
  // The effects' base_* fields do not enter the law: its parameters do.
  StrutState s = strut(0.1, 0.2);
  s.base_stiffness = 1.0;
  s.base_damping = 1.0;
  EXPECT_NEAR(law.calcForce(s, p), 2907.0 + 3000.0 + 500.0, 1e-9);
}

TEST_F(LinearStrutTest, HardstopEngagesBeyondTravelLimit) {
  const double k = 30000.0, k_hs = 1.0e7, H = 0.25;
  for (double q : {0.26, 0.3})
    EXPECT_NEAR(law.calcForce(strut(q, 0.0), p), 2907.0 + k * q + k_hs * (q - H), 1e-6) << q;
  for (double q : {-0.26, -0.3})
    EXPECT_NEAR(law.calcForce(strut(q, 0.0), p), 2907.0 + k * q + k_hs * (q + H), 1e-6) << q;
  // Stated stiffness beyond the limit: k + k_hs, by finite differences on both sides.
  const double h = 1e-6;
  for (double q : {0.27, -0.27}) {
    const double fd = (law.calcForce(strut(q + h, 0), p) - law.calcForce(strut(q - h, 0), p)) / (2 * h);
    EXPECT_NEAR(fd / (k + k_hs), 1.0, 1e-6) << q;
  }
  const double fd_in = (law.calcForce(strut(0.2 + h, 0), p) - law.calcForce(strut(0.2 - h, 0), p)) / (2 * h);
  EXPECT_NEAR(fd_in / k, 1.0, 1e-6);
  // Continuous at the limits.
  EXPECT_NEAR(law.calcForce(strut(H + 1e-12, 0), p), law.calcForce(strut(H, 0), p), 1e-3);
  EXPECT_NEAR(law.calcForce(strut(-H - 1e-12, 0), p), law.calcForce(strut(-H, 0), p), 1e-3);
  // The static helper.
  EXPECT_EQ(LinearStrut::hardstop(0.1, H, k_hs), 0.0);
  EXPECT_EQ(LinearStrut::hardstop(-H, H, k_hs), 0.0);
  EXPECT_NEAR(LinearStrut::hardstop(0.3, H, k_hs), k_hs * 0.05, 1e-6);
  EXPECT_NEAR(LinearStrut::hardstop(-0.3, H, k_hs), -k_hs * 0.05, 1e-6);
}

TEST_F(LinearStrutTest, InfiniteTravelLimitNeverEngages) {
  // Paper eq. 5: the wheel/axle interface is the same law with no hardstop.
  const auto v = values(138031.61, 11490.97, std::numeric_limits<double>::infinity(), 1.0e7);
  for (double q : {-2.0, 0.0, 0.4, 5.0}) {
    const double expected = 2907.0 + 138031.61 * q + 11490.97 * 0.1;
    EXPECT_NEAR(law.calcForce(strut(q, 0.1), v), expected, 1e-9 * std::abs(expected)) << q;
  }
}

TEST_F(LinearStrutTest, ParametersAreNamedWithUnits) {
  const auto& specs = law.parameters();
  ASSERT_EQ(specs.size(), 4u);
  EXPECT_EQ(specs[0].name, "stiffness");
  EXPECT_EQ(specs[1].name, "damping");
  EXPECT_EQ(specs[2].name, "travel_limit_m");
  EXPECT_EQ(specs[3].name, "hardstop_stiffness");
  EXPECT_EQ(specs[0].unit, "N/m");
  EXPECT_EQ(specs[1].unit, "N*s/m");
  EXPECT_TRUE(specs[0].shared);  // calibrated θ3, θ4
  EXPECT_TRUE(specs[1].shared);
  EXPECT_NE(checkParameterValue(specs[0], 0.0).find("must be > 0"), std::string::npos);
  EXPECT_EQ(checkParameterValue(specs[1], 0.0), "");
  EXPECT_NE(checkParameterValue(specs[2], 0.0).find("must be > 0"), std::string::npos);
}

}  // namespace
}  // namespace dtwin
