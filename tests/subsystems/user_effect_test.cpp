// User-defined strut effects (subsystems/user_effect.hpp): an expression parsed once, equal to the
// closed form and to the built-in effect of the same form; every bad definition is one line.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <thread>
#include <vector>

#include "common/errors.hpp"
#include "subsystems/user_effect.hpp"

using namespace dtwin;

namespace {

UserEffectSpec digressive() {
  UserEffectSpec s;
  s.name = "digressive_damper";
  s.element = "strut";
  s.force = "c2 * sign(v) * sqrt(abs(v) * v0)";
  s.parameters = {{"c2", "N*s/m", 0.0, 0.0, 2e4}, {"v0", "m/s", 0.1, 0.01, 1.0}};
  s.where = "study.toml:30: user_effects.digressive_damper";
  return s;
}

StrutState state(double q, double v) {
  StrutState s;
  s.deflection_m = q;
  s.rate_mps = v;
  s.base_stiffness = 3e4;
  s.base_damping = 2500;
  return s;
}

std::string errorOf(const UserEffectSpec& s) {
  try {
    makeUserEffect(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(UserEffect, ADigressiveDamperMatchesItsClosedForm) {
  const auto e = makeUserEffect(digressive());
  EXPECT_EQ(e->name(), "digressive_damper");
  EXPECT_EQ(e->kind(), EffectKind::Strut);
  ASSERT_EQ(e->parameters().size(), 2u);
  EXPECT_EQ(e->parameters()[0].unit, "N*s/m");
  EXPECT_EQ(e->parameters()[0].default_value, 0.0);
  EXPECT_EQ(e->parameters()[1].prior_lower, 0.01);
  EXPECT_EQ(e->parameters()[1].prior_upper, 1.0);
  const std::vector<double> p = {3000.0, 0.2};
  for (double v : {-0.7, -0.05, 0.0, 0.03, 0.4}) {
    const double expect = v == 0 ? 0.0 : 3000.0 * (v > 0 ? 1 : -1) * std::sqrt(std::abs(v) * 0.2);
    EXPECT_NEAR(e->calcStrutForce(state(0.01, v), p), expect, 1e-9 * (1 + std::abs(expect))) << v;
  }
  EXPECT_EQ(e->calcStrutForce(state(0.01, 0.4), std::vector<double>{0.0, 0.2}), 0.0) << "off at c2 = 0";
}

// The built-in damper asymmetry, (ratio − 1) c v on rebound (v < 0), written as an expression.
TEST(UserEffect, EqualsTheBuiltInEffectOfTheSameForm) {
  UserEffectSpec s;
  s.name = "my_asymmetry";
  s.element = "strut";
  s.force = "v < 0 ? (ratio - 1) * c * v : 0";
  s.parameters = {{"ratio", "1", 1.0, 0.5, 3.0}};
  s.where = "study.toml:40: user_effects.my_asymmetry";
  const auto user = makeUserEffect(s);
  const auto builtin = makeEffect("damper_asymmetry", "");
  for (double ratio : {0.7, 1.0, 2.2})
    for (double v : {-1.2, -0.01, 0.0, 0.02, 0.9}) {
      const std::vector<double> p = {ratio};
      EXPECT_DOUBLE_EQ(user->calcStrutForce(state(-0.02, v), p), builtin->calcStrutForce(state(-0.02, v), p)) << ratio << " " << v;
    }
}

// Each thread compiles its own copy: two threads evaluating at once agree with one thread.
TEST(UserEffect, ThreadsEvaluateIndependently) {
  const auto e = makeUserEffect(digressive());
  auto run = [&](double scale, std::vector<double>& out) {
    for (int i = 0; i < 20000; ++i) out.push_back(e->calcStrutForce(state(0.0, scale * std::sin(0.001 * i)), std::vector<double>{1000.0 * scale, 0.3}));
  };
  std::vector<double> a, b, a1, b1;
  std::thread ta([&] { run(1.0, a); }), tb([&] { run(2.0, b); });
  ta.join();
  tb.join();
  run(1.0, a1);
  run(2.0, b1);
  EXPECT_EQ(a, a1);
  EXPECT_EQ(b, b1);
}

TEST(UserEffect, BadDefinitionsAreOneLineErrors) {
  struct Case {
    std::function<void(UserEffectSpec&)> spoil;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {[](UserEffectSpec& s) { s.force = "c2 * sign(w)"; }, "user_effects.digressive_damper: force: 'c2 * sign(w)': Unexpected token \"w\""},
      {[](UserEffectSpec& s) { s.force = "c2 * (v"; }, "user_effects.digressive_damper: force: 'c2 * (v': "},
      {[](UserEffectSpec& s) { s.force = ""; }, "force: is required"},
      {[](UserEffectSpec& s) { s.element = "chassis"; }, "element: unknown element 'chassis' (known: strut)"},
      {[](UserEffectSpec& s) { s.parameters[1].upper = s.parameters[1].lower; }, "parameters.v0: needs a prior range with finite lower < upper"},
      {[](UserEffectSpec& s) { s.parameters[1].lower = std::nan(""); }, "parameters.v0: needs a prior range"},
      {[](UserEffectSpec& s) { s.parameters[1].value = 5; }, "parameters.v0.value: must lie in [lower, upper] = [0.01, 1], got 5"},
      {[](UserEffectSpec& s) { s.parameters[0].name = "v"; }, "parameters.v: the name is taken"},
      {[](UserEffectSpec& s) { s.parameters[0].name = "2x"; }, "parameters.2x: a parameter's name must be letters"},
      {[](UserEffectSpec& s) { s.parameters[0].unit = ""; }, "parameters.c2.unit: is required"},
      {[](UserEffectSpec& s) { s.force = "c2 * v + 5"; }, "force: must be 0 with every parameter at its value (the effect off); at q = -0.08 m, v = -1 m/s it is 5 N"},
      {[](UserEffectSpec& s) { s.force = "c2 * v / (q - 0.02)"; }, "force: must be 0 with every parameter at its value"},
      {[](UserEffectSpec& s) { s.force = "c2 * v / v0 / (v0 - 0.01) * 1e-3"; }, "force: is not finite"},
  };
  for (const auto& c : cases) {
    UserEffectSpec s = digressive();
    c.spoil(s);
    const std::string what = errorOf(s);
    EXPECT_NE(what.find(c.expect), std::string::npos) << "expected [" << c.expect << "] in [" << what << "]";
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind("study.toml:30: user_effects.digressive_damper", 0), 0u) << what;
  }
}
