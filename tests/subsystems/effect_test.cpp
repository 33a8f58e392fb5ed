// Tests of the optional physical effects: the contract every registered effect keeps, and the
// registry. Each effect's closed form is tested in tests/subsystems/effects/<name>_test.cpp.
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
#include "effect_fixture.hpp"
#include "subsystems/road.hpp"
#include "subsystems/strut_law.hpp"

namespace dtwin {
namespace {

using dtwin_test::kTracks;
using dtwin_test::offValues;
using dtwin_test::strut;

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
    EXPECT_EQ(checkParameterValue(spec, spec.default_value), "")
        << spec.name << ": the off value is invalid";
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
    const auto it = std::find_if(specs.begin(), specs.end(),
                                 [&](const ParameterSpec& p) { return p.name == th; });
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
    for (double qdot : {-50.0, -1e-9, 1e-9, 50.0})
      EXPECT_EQ(e.calcStrutForce(strut(q, qdot), off), 0.0);

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
    EXPECT_TRUE(seen.insert(registry.entries()[i].name).second) << registry.entries()[i].name;
    EXPECT_EQ(effectNames()[i], registry.entries()[i].name);
    EXPECT_EQ(registry.entries()[i].value()->name(), registry.entries()[i].name);
    EXPECT_EQ(makeEffect(registry.entries()[i].name, "t")->name(), registry.entries()[i].name);
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

}  // namespace
}  // namespace dtwin
