// User-defined strut effects (subsystems/user_effect.hpp): an expression parsed once, equal to the
// closed form and to the built-in effect of the same form; every bad definition is one line.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <thread>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
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
  EXPECT_EQ(e->calcStrutForce(state(0.01, 0.4), std::vector<double>{0.0, 0.2}), 0.0)
      << "off at c2 = 0";
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
      EXPECT_DOUBLE_EQ(user->calcStrutForce(state(-0.02, v), p),
                       builtin->calcStrutForce(state(-0.02, v), p))
          << ratio << " " << v;
    }
}

// Each thread compiles its own copy: two threads evaluating at once agree with one thread.
TEST(UserEffect, ThreadsEvaluateIndependently) {
  const auto e = makeUserEffect(digressive());
  auto run = [&](double scale, std::vector<double>& out) {
    for (int i = 0; i < 20000; ++i)
      out.push_back(e->calcStrutForce(state(0.0, scale * std::sin(0.001 * i)),
                                      std::vector<double>{1000.0 * scale, 0.3}));
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
      {[](UserEffectSpec& s) { s.force = "c2 * sign(w)"; },
       "user_effects.digressive_damper: force: 'c2 * sign(w)': Unexpected token \"w\""},
      {[](UserEffectSpec& s) { s.force = "c2 * (v"; },
       "user_effects.digressive_damper: force: 'c2 * (v': "},
      {[](UserEffectSpec& s) { s.force = ""; }, "force: is required"},
      {[](UserEffectSpec& s) { s.element = "wheel"; },
       "element: unknown element 'wheel' (known: strut, tire, axle_roll, chassis)"},
      {[](UserEffectSpec& s) { s.element = "tire"; },
       "force: 'c2 * sign(v) * sqrt(abs(v) * v0)': Unexpected token \"v\""},
      {[](UserEffectSpec& s) { s.parameters[0].unit = "Ns/m"; },
       "parameters.c2.unit: unit 'Ns/m': unknown symbol 'Ns'"},
      {[](UserEffectSpec& s) { s.parameters[1].unit = "mm/s"; },
       "parameters.v0.unit: unit 'mm/s': unknown symbol 'mm' (prefixes are not allowed: values are "
       "SI)"},
      {[](UserEffectSpec& s) { s.parameters[0].unit = "N/m"; },
       "force: 'c2 * sign(v) * sqrt(abs(v) * v0)' gives N/s, not N"},
      {[](UserEffectSpec& s) { s.force = "c2 * v * v"; }, "force: 'c2 * v * v' gives N*m/s, not N"},
      {[](UserEffectSpec& s) { s.force = "c2 * sign(v) * sqrt(abs(v) * 0.1)"; },
       "force: 'c2 * sign(v) * sqrt(abs(v) * 0.1)' gives N*s^0.5/m^0.5, not N, with the variables' "
       "units (docs/extending.md) and the parameters' own (a bare number counts as dimensionless"},
      {[](UserEffectSpec& s) { s.force = "c2 * v + c2 * q"; },
       "force: 'c2 * v + c2 * q' mixes units"},
      {[](UserEffectSpec& s) { s.force = "c2 * v * exp(q)"; }, "mixes units"},
      {[](UserEffectSpec& s) { s.parameters[1].upper = s.parameters[1].lower; },
       "parameters.v0: needs a prior range with finite lower < upper"},
      {[](UserEffectSpec& s) { s.parameters[1].lower = std::nan(""); },
       "parameters.v0: needs a prior range"},
      {[](UserEffectSpec& s) { s.parameters[1].value = 5; },
       "parameters.v0.value: must lie in [lower, upper] = [0.01, 1], got 5"},
      {[](UserEffectSpec& s) { s.parameters[0].name = "v"; }, "parameters.v: the name is taken"},
      {[](UserEffectSpec& s) { s.parameters[0].name = "dq"; },
       "parameters.dq: the name is taken (state variables of a strut element: q, v, dq, dv, k, c, "
       "t, u, front"},
      {[](UserEffectSpec& s) { s.parameters[0].name = "2x"; },
       "parameters.2x: a parameter's name must be letters"},
      {[](UserEffectSpec& s) { s.parameters[0].unit = ""; }, "parameters.c2.unit: is required"},
      {[](UserEffectSpec& s) { s.force = "c2 * v + 5"; },
       "force: must be 0 with every parameter at its value (the effect off); at q = -0.08 m, v = "
       "-1 m/s it is 5 N"},
      {[](UserEffectSpec& s) { s.force = "c2 * v / (q - 0.02)"; },
       "force: must be 0 with every parameter at its value"},
      {[](UserEffectSpec& s) { s.force = "c2 * v / v0 / (v0 - 0.01) * 1e-3"; },
       "force: is not finite"},
  };
  for (const auto& c : cases) {
    UserEffectSpec s = digressive();
    c.spoil(s);
    const std::string what = errorOf(s);
    EXPECT_NE(what.find(c.expect), std::string::npos)
        << "expected [" << c.expect << "] in [" << what << "]";
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind("study.toml:30: user_effects.digressive_damper", 0), 0u) << what;
  }
}

// Each element binds its documented variables in order: a weighted sum of them (units unchecked)
// against the same sum of the state's fields.
TEST(UserEffect, EachElementReadsItsDocumentedVariables) {
  auto make = [](const std::string& element) {
    UserEffectSpec s;
    s.name = "probe_" + element;
    s.element = element;
    s.where = "t";
    s.check_units = false;
    std::string sum;
    double w = 1;
    for (const auto& v : userEffectVariables(element)) {
      sum += (sum.empty() ? "" : " + ") + formatNumber(w) + " * " + v.name;
      w *= 3;
    }
    // Off at a = 0: the sum times a.
    s.force = "a * (" + sum + ")";
    s.parameters = {{"a", "1", 0.0, -10.0, 10.0}};
    return makeUserEffect(s);
  };
  const std::vector<double> a = {2.0};
  {
    StrutState s = state(0.03, -0.4);
    s.other_deflection_m = 0.01;
    s.other_rate_mps = 0.1;
    s.time_s = 1.5;
    s.speed_mps = 12.0;
    s.front = false;
    const double expect = 2 * (0.03 + 3 * -0.4 + 9 * 0.02 + 27 * -0.5 + 81 * 3e4 + 243 * 2500 +
                               729 * 1.5 + 2187 * 12.0 + 6561 * 0.0);
    EXPECT_NEAR(make("strut")->calcStrutForce(s, a), expect, 1e-9 * std::abs(expect));
    EXPECT_EQ(make("strut")->kind(), EffectKind::Strut);
  }
  {
    TireState s;
    s.deflection_m = 0.02;
    s.deflection_rate_mps = 0.3;
    s.normal_force_N = 4000;
    s.road_height_m = -0.01;
    s.time_s = 2.0;
    s.forward_speed_mps = 10.0;
    s.front = true;
    const double expect =
        2 * (0.02 + 3 * 0.3 + 9 * 4000 + 27 * -0.01 + 81 * 2.0 + 243 * 10.0 + 729 * 1.0);
    EXPECT_NEAR(make("tire")->calcTireLoad(s, a), expect, 1e-9 * std::abs(expect));
    EXPECT_EQ(make("tire")->kind(), EffectKind::TireLoad);
  }
  {
    AxleState s;
    s.q_left = 0.02;
    s.q_right = -0.01;
    s.v_left = 0.5;
    s.v_right = 0.2;
    s.front = true;
    s.time_s = 3.0;
    s.speed_mps = 8.0;
    const double expect = 2 * (0.03 + 3 * 0.3 + 9 * 3.0 + 27 * 8.0 + 81 * 1.0);
    EXPECT_NEAR(make("axle_roll")->calcAxleForce(s, a), expect, 1e-9 * std::abs(expect));
    EXPECT_EQ(make("axle_roll")->kind(), EffectKind::AxleCoupling);
  }
  {
    ChassisState s;
    s.heave_m = 0.01;
    s.heave_rate_mps = -0.2;
    s.pitch_rad = 0.004;
    s.roll_rad = -0.002;
    s.time_s = 4.0;
    s.speed_mps = 20.0;
    const double expect = 2 * (0.01 + 3 * -0.2 + 9 * 0.004 + 27 * -0.002 + 81 * 4.0 + 243 * 20.0);
    EXPECT_NEAR(make("chassis")->calcChassisForce(s, a), expect, 1e-9 * std::abs(expect));
    EXPECT_EQ(make("chassis")->kind(), EffectKind::ChassisForce);
  }
}

// The unit check accepts what is homogeneous on every element, whatever the unit's spelling.
TEST(UserEffect, HomogeneousExpressionsPassTheUnitCheck) {
  struct Ok {
    std::string element, force;
    std::vector<UserEffectParameter> parameters;
  };
  const std::vector<Ok> ok = {
      {"strut", "kb * max(q - g, 0)^2", {{"kb", "N/m^2", 0, 0, 1e7}, {"g", "m", 0.02, 0.0, 0.1}}},
      {"strut",
       "F0 * (max(q - g, 0) / g)^n",
       {{"F0", "N", 0, 0, 1e4}, {"g", "m", 0.02, 0.01, 0.1}, {"n", "1", 2, 1, 3}}},
      {"strut",
       "c2 * v0 * tanh(v / v0) + ka * dq + cr * dv",
       {{"c2", "N*s/m", 0, 0, 1e4},
        {"v0", "m/s", 0.1, 0.01, 1},
        {"ka", "N/m", 0, 0, 1e4},
        {"cr", "kg/s", 0, 0, 1e3}}},
      {"strut",
       "mu * k * q * (u / u0)^2 + a * sin(2 * _pi * f * t) * front",
       {{"mu", "1", 0, 0, 1},
        {"u0", "m/s", 10, 1, 30},
        {"a", "N", 0, 0, 100},
        {"f", "Hz", 2, 1, 10}}},
      {"tire",
       "kt * qt + ct * vt + r * fz + kz * zr",
       {{"kt", "N/m", 0, 0, 1e5},
        {"ct", "N*s/m", 0, 0, 1e3},
        {"r", "1", 0, -0.5, 0.5},
        {"kz", "N/m", 0, 0, 1e5}}},
      {"axle_roll", "kr * dq + cr * dv", {{"kr", "N/m", 0, 0, 4e4}, {"cr", "N*s/m", 0, 0, 1e3}}},
      {"chassis",
       "cl * u^2 + kz * z + cz * w + mp * pitch",
       {{"cl", "kg/m", 0, -5, 5},
        {"kz", "N/m", 0, 0, 1e4},
        {"cz", "N*s/m", 0, 0, 1e3},
        {"mp", "N/rad", 0, 0, 1e3}}},
  };
  for (const auto& c : ok) {
    UserEffectSpec s;
    s.name = "ok";
    s.element = c.element;
    s.force = c.force;
    s.parameters = c.parameters;
    s.where = "t";
    EXPECT_NO_THROW(makeUserEffect(s)) << c.force << ": " << errorOf(s);
  }
}
