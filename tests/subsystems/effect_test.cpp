// Tests of the optional physical effects (one contract run on every effect of the factory, then
// each effect's closed form) and of the linear strut law they are added to.
#include "subsystems/effect.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/errors.hpp"
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
    // The prior range: finite, non-empty, valid, and containing the off value.
    EXPECT_TRUE(std::isfinite(spec.prior_lower) && std::isfinite(spec.prior_upper)) << spec.name;
    EXPECT_LT(spec.prior_lower, spec.prior_upper) << spec.name;
    EXPECT_EQ(checkParameterValue(spec, spec.prior_lower), "") << spec.name;
    EXPECT_EQ(checkParameterValue(spec, spec.prior_upper), "") << spec.name;
    EXPECT_LE(spec.prior_lower, spec.default_value) << spec.name;
    EXPECT_GE(spec.prior_upper, spec.default_value) << spec.name;
  }
  // The diagnosis' hints: a signature names both a state map and a feature, or neither; an
  // engagement threshold is one of the effect's length parameters.
  const ResidualSignature sig = e.residualSignature();
  EXPECT_EQ(sig.state_map.empty(), sig.feature.empty()) << sig.state_map << " / " << sig.feature;
  if (const std::string th = e.engagementThreshold(); !th.empty()) {
    const auto& specs = e.parameters();
    const auto it = std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& p) { return p.name == th; });
    ASSERT_NE(it, specs.end()) << "engagementThreshold() names no parameter: " << th;
    EXPECT_EQ(it->unit, "m") << th;
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

  // Tire force factor exactly 1; no axle coupling force; no auxiliary state and no filtered force.
  for (double rho : {-0.01, 0.0, 0.02, 0.2})
    for (double v : {0.0, 1.0, 8.9408, 40.0}) {
      TireState ts;
      ts.deflection_m = rho;
      ts.forward_speed_mps = v;
      ts.wheel_speed_radps = v / 0.3;
      EXPECT_EQ(e.tireForceFactor(ts, off), 1.0) << "rho " << rho << " v " << v;
    }
  for (double ql : {-0.2, 0.0, 0.03, 0.3})
    for (double qr : {-0.1, 0.0, 0.05})
      for (bool front : {true, false}) EXPECT_EQ(e.calcAxleCouplingForce(ql, qr, front, off), 0.0);
  EXPECT_FALSE(e.filterActive(off));
  for (double qdot : {-2.0, 0.0, 0.5})
    for (double z : {-1000.0, 0.0, 300.0}) {
      EXPECT_EQ(e.calcFilteredStrutForce(strut(0.02, qdot), z, off), 0.0);
      EXPECT_EQ(e.calcFilterRate(strut(0.02, qdot), z, off), 0.0);
    }

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
  ASSERT_GE(names.size(), 8u);
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
  EXPECT_EQ(makeEffect("progressive_spring", "t")->kind(), EffectKind::Strut);
  EXPECT_EQ(makeEffect("speed_dependent_tire_stiffness", "t")->kind(), EffectKind::TireForce);
  EXPECT_EQ(makeEffect("anti_roll_bar", "t")->kind(), EffectKind::AxleCoupling);
  EXPECT_EQ(makeEffect("top_mount_compliance", "t")->kind(), EffectKind::StrutFilter);
}

TEST(EffectRegistry, NamesAreUniqueAndEachEntryMakesItsEffect) {
  const auto& registry = effectRegistry();
  ASSERT_EQ(effectNames().size(), registry.size());
  std::set<std::string> seen;
  for (std::size_t i = 0; i < registry.size(); ++i) {
    EXPECT_TRUE(seen.insert(registry[i].name).second) << registry[i].name;
    EXPECT_EQ(effectNames()[i], registry[i].name);
    EXPECT_EQ(registry[i].make()->name(), registry[i].name);
    EXPECT_EQ(makeEffect(registry[i].name, "t")->name(), registry[i].name);
  }
}

TEST(EffectFactory, AMisspeltNameGetsTheNearestAsAHint) {
  try {
    makeEffect("bumpstop", "study.toml: effects");
    FAIL() << "unknown effect accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.rule().rfind("unknown effect 'bumpstop' (known: bump_stop, ", 0), 0u) << e.rule();
    EXPECT_NE(e.rule().find("; did you mean 'bump_stop'?)"), std::string::npos) << e.rule();
  }
  try {
    makeEffect("warp_drive", "t");
    FAIL() << "unknown effect accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("did you mean"), std::string::npos) << e.what();
  }
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

// ------------------------------------------------------------------ progressive spring

TEST(ProgressiveSpring, CubicOddMonotoneWithStatedTangentStiffness) {
  auto e = makeEffect("progressive_spring", "t");
  const double k3 = 2.0e6;
  const auto v = valuesWith(*e, {{"stiffness3", k3}});
  for (double q : {-0.3, -0.1, -0.01, 0.0, 0.02, 0.1, 0.25})
    for (double qdot : {-1.0, 0.0, 2.0}) {  // independent of the rate
      const double expected = k3 * q * q * q;
      EXPECT_NEAR(e->calcStrutForce(strut(q, qdot), v), expected, 1e-12 * std::abs(expected) + 1e-300) << q;
      EXPECT_EQ(e->calcStrutForce(strut(-q, qdot), v), -e->calcStrutForce(strut(q, qdot), v)) << q;  // odd
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
    const double fd = (e->calcStrutForce(strut(q + h, 0), v) - e->calcStrutForce(strut(q - h, 0), v)) / (2 * h);
    EXPECT_NEAR(fd / (3 * k3 * q * q), 1.0, 1e-6) << q;
  }
  const double fd0 = (e->calcStrutForce(strut(h, 0), v) - e->calcStrutForce(strut(-h, 0), v)) / (2 * h);
  EXPECT_NEAR(fd0, 0.0, 1e-5);
}

// ------------------------------------------------------------------ speed-dependent tire stiffness

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

// ------------------------------------------------------------------ anti-roll bar

TEST(AntiRollBar, ForceIsAxleRateTimesDeflectionDifference) {
  auto e = makeEffect("anti_roll_bar", "t");
  const double kf = 20000.0, kr = 8000.0;
  const auto v = valuesWith(*e, {{"stiffness_front_N_per_m", kf}, {"stiffness_rear_N_per_m", kr}});
  for (double ql : {-0.1, 0.0, 0.04, 0.2})
    for (double qr : {-0.05, 0.0, 0.04}) {
      EXPECT_NEAR(e->calcAxleCouplingForce(ql, qr, true, v), kf * (ql - qr), 1e-12 * kf);
      EXPECT_NEAR(e->calcAxleCouplingForce(ql, qr, false, v), kr * (ql - qr), 1e-12 * kr);
      // Antisymmetric: swapping the sides negates the force (the right strut gets -F).
      EXPECT_EQ(e->calcAxleCouplingForce(qr, ql, true, v), -e->calcAxleCouplingForce(ql, qr, true, v));
    }
  // Identical deflections: nothing, whatever the stiffness.
  for (double q : {-0.1, 0.0, 0.07}) EXPECT_EQ(e->calcAxleCouplingForce(q, q, true, v), 0.0);
  // Stated stiffness by finite differences (d/dq_left = k, d/dq_right = -k), monotone in q_left.
  const double h = 1e-6;
  EXPECT_NEAR((e->calcAxleCouplingForce(0.03 + h, 0.01, true, v) - e->calcAxleCouplingForce(0.03 - h, 0.01, true, v)) / (2 * h) / kf,
              1.0, 1e-6);
  EXPECT_NEAR((e->calcAxleCouplingForce(0.03, 0.01 + h, false, v) - e->calcAxleCouplingForce(0.03, 0.01 - h, false, v)) / (2 * h) / kr,
              -1.0, 1e-6);
  // Only one axle's bar installed: the other exerts nothing.
  const auto front_only = valuesWith(*e, {{"stiffness_front_N_per_m", kf}});
  EXPECT_EQ(e->calcAxleCouplingForce(0.05, -0.05, false, front_only), 0.0);
}

// ------------------------------------------------------------------ top-mount compliance

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
  const double fd = (e->calcFilterRate(strut(0, 0.2), 100.0 + h, v) - e->calcFilterRate(strut(0, 0.2), 100.0 - h, v)) / (2 * h);
  EXPECT_NEAR(fd * tau, -1.0, 1e-9);
  // Frequency response of the transmitted damping force z to qdot = sin(w t): gain
  // c / sqrt(1 + (w tau)^2) (RK4 integration to a periodic steady state).
  for (double f_hz : {1.0, 12.0, 40.0}) {
    const double w = 2 * M_PI * f_hz, dt = std::min(tau, 1 / f_hz) / 200.0;
    double z = 0.0, t = 0.0, amp = 0.0;
    auto rate = [&](double tt, double zz) { return e->calcFilterRate(strut(0.0, std::sin(w * tt)), zz, v); };
    const double t_end = 10 * tau + 5.0 / f_hz;
    while (t < t_end) {
      const double k1 = rate(t, z), k2 = rate(t + dt / 2, z + dt / 2 * k1), k3 = rate(t + dt / 2, z + dt / 2 * k2),
                   k4 = rate(t + dt, z + dt * k3);
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
