// Tests of the vertical tire laws: one contract run on every law of the factory, then the
// closed forms of each law (Fiala, PAC2002) and the parameter-value checks.
#include "subsystems/tire_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "common/errors.hpp"

namespace dtwin {
namespace {

using Values = std::map<std::string, double>;

/// Nominal values by name (docs/method.md §1 true θ1, θ2; PAC2002 defaults of
/// data/vehicle/midsize_sedan.toml).
Values nominalValues() {
  return {{"stiffness", 180000.0},
          {"damping", 3000.0},
          {"unloaded_radius_m", 0.31},
          {"qfz2", 10.0},
          {"qfz3", 0.0},
          {"qv2", 0.04},
          {"qfcx", 0.0},
          {"qfcy", 0.0},
          {"ppfz1", 0.7},
          {"fnomin_N", 4000.0},
          {"longvl_mps", 16.7},
          {"inflation_pressure_Pa", 220000.0},
          {"nompres_Pa", 220000.0},
          {"link_stiffness", 1e8},
          {"link_damping", 1e5}};
}

/// The parameter vector of `law`, filled by name from `values` (every parameter must be there).
std::vector<double> paramsFor(const TireLaw& law, const Values& values) {
  const auto& specs = law.parameters();
  std::vector<double> p(specs.size(), std::numeric_limits<double>::quiet_NaN());
  for (const auto& spec : specs) {
    const auto it = values.find(spec.name);
    if (it == values.end()) {
      ADD_FAILURE() << law.name() << ": no test value for parameter '" << spec.name << "'";
      continue;
    }
    p[parameterIndex(specs, spec.name)] = it->second;
  }
  return p;
}

/// Sets one named parameter of `law` in `p`.
void set(const TireLaw& law, std::vector<double>& p, const std::string& name, double v) {
  p[parameterIndex(law.parameters(), name)] = v;
}

TireState at(double deflection, double rate = 0.0) {
  TireState s;
  s.deflection_m = deflection;
  s.deflection_rate_mps = rate;
  return s;
}

/// Parameter sets the contract is run on: nominal, off-nominal pressure, no damping, linear.
std::vector<std::pair<std::string, Values>> contractCases() {
  std::vector<std::pair<std::string, Values>> cases;
  cases.emplace_back("nominal", nominalValues());
  Values v = nominalValues();
  v["inflation_pressure_Pa"] = 250000.0;
  cases.emplace_back("pressure 250 kPa", v);
  v = nominalValues();
  v["damping"] = 0.0;
  v["stiffness"] = 400000.0;
  cases.emplace_back("stiff, undamped", v);
  v = nominalValues();
  v["qfz2"] = 0.0;
  v["unloaded_radius_m"] = 0.33;
  cases.emplace_back("qfz2 = 0", v);
  return cases;
}

// ------------------------------------------------------------------ contract

/// What every vertical tire law must satisfy for valid parameters p.
void checkTireLawContract(const TireLaw& law, const std::vector<double>& p) {
  // Valid parameters (the test's own premise).
  for (std::size_t i = 0; i < p.size(); ++i)
    ASSERT_EQ(checkParameterValue(law.parameters()[i], p[i]), "") << law.parameters()[i].name;
  ASSERT_EQ(law.checkCombination(p), "");
  const double k = law.statedStiffness(p);
  ASSERT_GT(k, 0.0);

  // Out of contact: exactly zero, whatever the rate, speed or forces.
  for (double rho : {0.0, -1e-12, -1e-3, -0.05, -0.4})
    for (double rate : {-20.0, -1.0, 0.0, 1.0, 20.0}) {
      TireState s = at(rho, rate);
      EXPECT_EQ(law.calcNormalForce(s, p), 0.0) << "rho " << rho << " rate " << rate;
      s.wheel_speed_radps = 30.0;
      s.fx_N = 1000.0;
      s.fy_N = -500.0;
      s.camber_rad = 0.02;
      EXPECT_EQ(law.calcNormalForce(s, p), 0.0) << "rho " << rho << " rate " << rate;
    }

  // Never negative: a large rebound rate clamps to zero.
  const double c = p[parameterIndex(law.parameters(), "damping")];
  for (double rho : {1e-6, 0.005, 0.02, 0.08}) {
    if (c > 0.0) {
      const double rebound = -(10.0 * law.calcNormalForce(at(rho), p) / c + 1.0);
      EXPECT_EQ(law.calcNormalForce(at(rho, rebound), p), 0.0) << "rho " << rho;
    }
    for (double rate : {-3.0, -0.3, 0.0, 0.3, 3.0})
      EXPECT_GE(law.calcNormalForce(at(rho, rate), p), 0.0);
  }

  // Continuous at touch-down: the damping ramps in (kContactDampingRamp_m), so a wheel landing
  // fast meets a force that starts from zero, not a jump to c * rate.
  for (double rate : {0.3, 3.0}) {
    EXPECT_LT(law.calcNormalForce(at(1e-9, rate), p), 1e-6 * k + 1e-3 * c * rate * 1e-3)
        << "rate " << rate;
    const double half = law.calcNormalForce(at(0.5 * kContactDampingRamp_m, rate), p);
    const double full_damping = law.calcNormalForce(at(0.5 * kContactDampingRamp_m), p) + c * rate;
    EXPECT_NEAR(half, law.calcNormalForce(at(0.5 * kContactDampingRamp_m), p) + 0.5 * c * rate,
                1e-9 * full_damping)
        << "rate " << rate;
  }

  // Monotone non-decreasing in deflection, at several rates; positive in contact at zero rate.
  for (double rate : {0.0, -0.2, 0.5}) {
    double prev = law.calcNormalForce(at(0.0, rate), p);
    for (int i = 1; i <= 400; ++i) {
      const double rho = 0.15 * i / 400.0;
      const double f = law.calcNormalForce(at(rho, rate), p);
      EXPECT_GE(f, prev) << "rho " << rho << " rate " << rate;
      if (rate == 0.0) {
        EXPECT_GT(f, 0.0) << "rho " << rho;
      }
      prev = f;
    }
  }

  // The finite-difference stiffness at the operating point equals the stated stiffness.
  const double rho0 = law.operatingDeflection(p);
  ASSERT_GT(rho0, 0.0);
  const double h = 1e-6;
  const double fd =
      (law.calcNormalForce(at(rho0 + h), p) - law.calcNormalForce(at(rho0 - h), p)) / (2 * h);
  EXPECT_NEAR(fd / k, 1.0, 1e-6) << "FD stiffness " << fd << " N/m, stated " << k << " N/m at rho "
                                 << rho0;

  // Damping acts linearly on the deflection rate with the "damping" parameter (while unclamped).
  for (double rate : {-0.1, 0.05, 0.4}) {
    const double df = law.calcNormalForce(at(rho0, rate), p) - law.calcNormalForce(at(rho0), p);
    EXPECT_NEAR(df, c * rate, 1e-9 * (1.0 + std::abs(c * rate))) << "rate " << rate;
  }

  // calcStaticDeflection inverts the law at zero rate.
  EXPECT_EQ(law.calcStaticDeflection(0.0, p), 0.0);
  for (double load : {50.0, 1000.0, 4000.0, 9000.0, 30000.0}) {
    const double rho = law.calcStaticDeflection(load, p);
    EXPECT_GT(rho, 0.0);
    EXPECT_NEAR(law.calcNormalForce(at(rho), p) / load, 1.0, 1e-9) << "load " << load;
  }

  EXPECT_DOUBLE_EQ(law.unloadedRadius(p), p[parameterIndex(law.parameters(), "unloaded_radius_m")]);
}

/// What a law that holds the wheel to the road signal (followsSignal) must satisfy: a two-sided
/// linear link, k rho + c (road rate + deflection rate), with no clamp.
void checkFollowerContract(const TireLaw& law, const std::vector<double>& p) {
  for (std::size_t i = 0; i < p.size(); ++i)
    ASSERT_EQ(checkParameterValue(law.parameters()[i], p[i]), "") << law.parameters()[i].name;
  const double k = law.statedStiffness(p);
  ASSERT_GT(k, 0.0);
  // It may pull: the wheel cannot leave the signal.
  EXPECT_LT(law.calcNormalForce(at(-1e-3), p), 0.0);
  EXPECT_NEAR(law.calcNormalForce(at(-1e-3), p), -k * 1e-3, 1e-9 * k);
  // Its damping acts on the full deflection rate: the signal's rate counts as much as the hub's.
  TireState s = at(1e-4, -0.2);
  const double f_hub = law.calcNormalForce(s, p);
  s.deflection_rate_mps = 0.0;
  s.road_rate_mps = -0.2;
  EXPECT_DOUBLE_EQ(law.calcNormalForce(s, p), f_hub);
  const double rho0 = law.operatingDeflection(p);
  const double h = 1e-7;
  const double fd =
      (law.calcNormalForce(at(rho0 + h), p) - law.calcNormalForce(at(rho0 - h), p)) / (2 * h);
  EXPECT_NEAR(fd / k, 1.0, 1e-6);
  for (double load : {1000.0, 4000.0, 9000.0}) {
    const double rho = law.calcStaticDeflection(load, p);
    EXPECT_NEAR(law.calcNormalForce(at(rho), p) / load, 1.0, 1e-9) << "load " << load;
  }
  EXPECT_DOUBLE_EQ(law.unloadedRadius(p), p[parameterIndex(law.parameters(), "unloaded_radius_m")]);
}

TEST(TireLawContract, HoldsForEveryLawAndParameterSet) {
  const auto names = tireLawNames();
  ASSERT_GE(names.size(), 3u);
  int followers = 0;
  for (const auto& name : names) {
    SCOPED_TRACE("tire law " + name);
    auto law = makeTireLaw(name, "test");
    ASSERT_TRUE(law);
    EXPECT_EQ(law->name(), name);
    if (law->followsSignal()) {
      ++followers;
      checkFollowerContract(*law, paramsFor(*law, nominalValues()));
      continue;
    }
    for (const auto& [label, values] : contractCases()) {
      SCOPED_TRACE("parameters: " + label);
      checkTireLawContract(*law, paramsFor(*law, values));
    }
  }
  EXPECT_EQ(followers, 1);  // the hub input
}

// The road enters at the hub: a 1 mm step of the signal under a wheel held by the link returns the
// static force plus k * 1 mm, and the force at rest is the static load at its static deflection.
TEST(HubInput, IsATwoSidedLinkToTheSignal) {
  auto law = makeTireLaw("hub", "test");
  ASSERT_TRUE(law->followsSignal());
  const std::vector<double> p = paramsFor(*law, nominalValues());
  EXPECT_DOUBLE_EQ(law->statedStiffness(p), 1e8);
  const double rho = law->calcStaticDeflection(4000.0, p);
  EXPECT_NEAR(rho, 4e-5, 1e-12);
  EXPECT_NEAR(law->calcNormalForce(at(rho + 1e-3), p), 4000.0 + 1e5, 1e-6);
  TireState s = at(rho);
  s.road_rate_mps = 0.1;  // the signal rises at 0.1 m/s under a still hub
  EXPECT_NEAR(law->calcNormalForce(s, p), 4000.0 + 1e5 * 0.1, 1e-6);
  // No shared tire compliance: the study's calibrated tire.stiffness and tire.damping do not apply.
  for (const auto& spec : law->parameters()) {
    if (spec.name == "stiffness" || spec.name == "damping")
      ADD_FAILURE() << "the hub input has a tire " << spec.name;
  }
}

TEST(TireLawContract, SharedParametersAreCommonToAllLaws) {
  // Calibrated θ1, θ2 map to "stiffness" and "damping" whatever the tire option; R0 exists for
  // all. A law that follows the signal has no tire compliance, only R0.
  for (const auto& name : tireLawNames()) {
    auto law = makeTireLaw(name, "test");
    const auto& specs = law->parameters();
    if (law->followsSignal()) {
      EXPECT_TRUE(specs[parameterIndex(specs, "unloaded_radius_m")].shared) << name;
      continue;
    }
    for (const char* shared : {"stiffness", "damping", "unloaded_radius_m"}) {
      const auto& spec = specs[parameterIndex(specs, shared)];
      EXPECT_TRUE(spec.shared) << name << "." << shared;
      EXPECT_FALSE(spec.unit.empty()) << name << "." << shared;
    }
    EXPECT_EQ(specs[parameterIndex(specs, "stiffness")].unit, "N/m") << name;
    EXPECT_EQ(specs[parameterIndex(specs, "damping")].unit, "N*s/m") << name;
    for (const auto& spec : specs) {
      EXPECT_FALSE(spec.unit.empty()) << name << "." << spec.name;
      EXPECT_FALSE(spec.description.empty()) << name << "." << spec.name;
    }
  }
}

TEST(TireLawFactory, UnknownOptionNamesWhereAndWhat) {
  try {
    makeTireLaw("michelin", "study.toml: subsystems.tire");
    FAIL() << "unknown option accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("study.toml: subsystems.tire"), std::string::npos) << what;
    EXPECT_NE(what.find("unknown tire option 'michelin'"), std::string::npos) << what;
    EXPECT_EQ(e.where(), "study.toml: subsystems.tire");
    for (const auto& known : tireLawNames()) EXPECT_NE(what.find(known), std::string::npos) << what;
  }
  EXPECT_THROW(makeTireLaw("", "x"), InputError);
  EXPECT_THROW(makeTireLaw("Fiala", "x"), InputError);  // names are case-sensitive
}

// ------------------------------------------------------------------ Fiala

TEST(FialaTire, IsExactlyLinearSpringAndDamper) {
  auto law = makeTireLaw("fiala", "test");
  auto p = paramsFor(*law, nominalValues());
  const double k = 180000.0, b = 3000.0;
  for (double rho : {1e-4, 0.004, 0.0123, 0.03, 0.1})
    for (double rate : {-0.5, -0.01, 0.0, 0.2, 1.5}) {
      // The damping ramps in over the first kContactDampingRamp_m of deflection (tire_law.hpp).
      const double expected =
          std::max(0.0, k * rho + b * rate * std::min(1.0, rho / kContactDampingRamp_m));
      EXPECT_NEAR(law->calcNormalForce(at(rho, rate), p), expected, 1e-12 * (1.0 + expected))
          << "rho " << rho << " rate " << rate;
    }
  // Speed, Fx, Fy and camber do not enter the Fiala vertical law.
  TireState s = at(0.02, 0.1);
  s.wheel_speed_radps = 40.0;
  s.fx_N = 3000.0;
  s.fy_N = 2000.0;
  s.camber_rad = 0.05;
  EXPECT_DOUBLE_EQ(law->calcNormalForce(s, p), k * 0.02 + b * 0.1);
  EXPECT_EQ(law->statedStiffness(p), k);
  EXPECT_NEAR(law->calcStaticDeflection(4000.0, p), 4000.0 / k, 1e-12);
  EXPECT_EQ(law->checkCombination(p), "");
}

// ------------------------------------------------------------------ PAC2002

class Pac2002 : public ::testing::Test {
 protected:
  std::unique_ptr<TireLaw> law = makeTireLaw("pac2002", "test");
  std::vector<double> p = paramsFor(*law, nominalValues());
  void setp(const std::string& name, double v) { set(*law, p, name, v); }
  double force(const TireState& s) const { return law->calcNormalForce(s, p); }
};

TEST_F(Pac2002, WithoutQuadraticAndSpeedTermsIsLinearSpring) {
  setp("qfz2", 0.0);
  setp("qv2", 0.0);
  const double k = 180000.0, c = 3000.0;
  for (double rho : {1e-4, 0.005, 0.0222, 0.05, 0.12})
    for (double rate : {-0.3, 0.0, 0.7}) {
      const double expected =
          std::max(0.0, k * rho + c * rate * std::min(1.0, rho / kContactDampingRamp_m));
      EXPECT_NEAR(force(at(rho, rate)), expected, 1e-12 * expected)
          << "rho " << rho << " rate " << rate;
    }
  // ... and then the operating point is where the nominal load is carried.
  EXPECT_NEAR(law->operatingDeflection(p), 4000.0 / k, 1e-15);
}

TEST_F(Pac2002, StaticDeflectionAtNominalLoadIsOperatingPoint) {
  // With dpi = 0 the operating point is where the static force equals Fz0 (MFeval convention).
  EXPECT_NEAR(law->calcStaticDeflection(4000.0, p), law->operatingDeflection(p), 1e-12);
  EXPECT_NEAR(force(at(law->operatingDeflection(p))), 4000.0, 1e-9);
  // The law is progressive for qfz2 > 0: stiffer above the operating point than below.
  const double rho0 = law->operatingDeflection(p), h = 1e-6;
  const auto kAt = [&](double r) { return (force(at(r + h)) - force(at(r - h))) / (2 * h); };
  EXPECT_LT(kAt(0.5 * rho0), kAt(rho0));
  EXPECT_GT(kAt(2.0 * rho0), kAt(rho0));
}

TEST_F(Pac2002, SpeedTermScalesStaticForce) {
  const double R0 = 0.31, V0 = 16.7, qv2 = 0.04;
  for (double rho : {0.01, 0.03})
    for (double omega : {10.0, -28.8, 60.0}) {
      TireState s = at(rho);
      const double f0 = force(s);
      s.wheel_speed_radps = omega;
      EXPECT_NEAR(force(s) / f0, 1.0 + qv2 * std::abs(omega) * R0 / V0, 1e-13) << "omega " << omega;
      // Damping is not scaled by the speed term.
      s.deflection_rate_mps = 0.2;
      EXPECT_NEAR(force(s), f0 * (1.0 + qv2 * std::abs(omega) * R0 / V0) + 3000.0 * 0.2, 1e-9);
    }
}

TEST_F(Pac2002, LongitudinalAndLateralForceTermsReduceForce) {
  setp("qfcx", 0.4);
  setp("qfcy", 0.25);
  const double Fz0 = 4000.0;
  const TireState s0 = at(0.025);
  const double f0 = force(s0);
  for (double fx : {-3000.0, 1500.0, 2500.0}) {
    TireState s = s0;
    s.fx_N = fx;
    const double a = 0.4 * fx / Fz0;
    EXPECT_NEAR(force(s) / f0, 1.0 - a * a, 1e-13) << "Fx " << fx;
  }
  TireState s = s0;
  s.fy_N = -2000.0;
  const double b = 0.25 * -2000.0 / Fz0;
  EXPECT_NEAR(force(s) / f0, 1.0 - b * b, 1e-13);
  // The bracket is additive: [1 + qV2 |Omega| R0/V0 - (qFcx Fx/Fz0)^2 - (qFcy Fy/Fz0)^2].
  s.fx_N = 2000.0;
  s.wheel_speed_radps = 25.0;
  const double a = 0.4 * 2000.0 / Fz0;
  EXPECT_NEAR(force(s) / f0, 1.0 + 0.04 * 25.0 * 0.31 / 16.7 - a * a - b * b, 1e-13);
}

TEST_F(Pac2002, PressureTermScalesForceAndStatedStiffness) {
  const TireState s = at(0.02);
  const double f0 = force(s);
  for (double pressure : {180000.0, 250000.0, 300000.0}) {
    setp("inflation_pressure_Pa", pressure);
    const double dpi = (pressure - 220000.0) / 220000.0;
    EXPECT_NEAR(force(s) / f0, 1.0 + 0.7 * dpi, 1e-13) << "p " << pressure;
    EXPECT_NEAR(law->statedStiffness(p), 180000.0 * (1.0 + 0.7 * dpi), 1e-9) << "p " << pressure;
  }
}

TEST_F(Pac2002, CamberTermAddsToLinearCoefficient) {
  setp("qfz3", 15.0);
  const double rho = 0.02, gamma = 0.05, R0 = 0.31, Fz0 = 4000.0;
  TireState s = at(rho);
  const double f0 = force(s);
  s.camber_rad = gamma;
  EXPECT_NEAR(force(s) - f0, 15.0 * gamma * gamma * (rho / R0) * Fz0, 1e-9);
  s.camber_rad = -gamma;  // even in camber
  EXPECT_NEAR(force(s) - f0, 15.0 * gamma * gamma * (rho / R0) * Fz0, 1e-9);
}

TEST_F(Pac2002, MatchesPaperEquationThreeAtAGeneralPoint) {
  // Eq. 3 with qFz1 = sqrt((Cz R0/Fz0)^2 - 4 qFz2), everything switched on.
  setp("qfz3", 5.0);
  setp("qfcx", 0.3);
  setp("qfcy", 0.2);
  setp("inflation_pressure_Pa", 240000.0);
  TireState s;
  s.deflection_m = 0.027;
  s.deflection_rate_mps = -0.15;
  s.wheel_speed_radps = 27.0;
  s.fx_N = 1200.0;
  s.fy_N = -800.0;
  s.camber_rad = 0.03;
  const double Cz = 180000, R0 = 0.31, Fz0 = 4000, qfz2 = 10, x = s.deflection_m / R0;
  const double qfz1 = std::sqrt(std::pow(Cz * R0 / Fz0, 2) - 4 * qfz2);
  const double bracket =
      1 + 0.04 * 27.0 * R0 / 16.7 - std::pow(0.3 * 1200 / Fz0, 2) - std::pow(0.2 * -800 / Fz0, 2);
  const double expected = bracket * ((qfz1 + 5.0 * 0.03 * 0.03) * x + qfz2 * x * x) *
                              (1 + 0.7 * (240000.0 - 220000.0) / 220000.0) * Fz0 +
                          3000.0 * -0.15;
  EXPECT_NEAR(force(s), expected, 1e-9 * expected);
}

TEST_F(Pac2002, CheckCombinationRejectsImaginaryQfz1) {
  EXPECT_EQ(law->checkCombination(p), "");
  const double a = 180000.0 * 0.31 / 4000.0;  // Cz R0 / Fz0
  setp("qfz2", 0.25 * a * a);                 // (Cz R0/Fz0)^2 == 4 qfz2: qFz1 = 0, not allowed
  EXPECT_NE(law->checkCombination(p), "");
  setp("qfz2", 60.0);  // 4 * 60 > 194.6
  const std::string msg = law->checkCombination(p);
  EXPECT_NE(msg, "");
  EXPECT_NE(msg.find("qfz2"), std::string::npos) << msg;
  setp("qfz2", 48.0);  // 192 < 194.6: still valid
  EXPECT_EQ(law->checkCombination(p), "");
  // Lowering the stiffness instead breaks it too.
  setp("qfz2", 10.0);
  setp("stiffness", 40000.0);  // (40000*0.31/4000)^2 = 9.61 <= 40
  EXPECT_NE(law->checkCombination(p), "");
}

// ------------------------------------------------------------------ parameter values

TEST(TireParameters, CheckParameterValueMessages) {
  for (const auto& name : tireLawNames()) {
    SCOPED_TRACE(name);
    auto law = makeTireLaw(name, "test");
    if (law->followsSignal()) continue;  // no tire stiffness or damping
    const auto& specs = law->parameters();
    const auto& k = specs[parameterIndex(specs, "stiffness")];
    EXPECT_EQ(checkParameterValue(k, 180000.0), "");
    const std::string neg = checkParameterValue(k, -5.0);
    EXPECT_NE(neg.find("must be > 0"), std::string::npos) << neg;
    EXPECT_NE(neg.find("N/m"), std::string::npos) << neg;
    EXPECT_NE(neg.find("got -5"), std::string::npos) << neg;
    EXPECT_NE(checkParameterValue(k, 0.0).find("must be > 0"),
              std::string::npos);  // exclusive bound
    const auto& c = specs[parameterIndex(specs, "damping")];
    EXPECT_EQ(checkParameterValue(c, 0.0), "");  // undamped is allowed
    const std::string negc = checkParameterValue(c, -1.0);
    EXPECT_NE(negc.find("must be >= 0"), std::string::npos) << negc;
    const auto& r0 = specs[parameterIndex(specs, "unloaded_radius_m")];
    EXPECT_NE(checkParameterValue(r0, 0.0).find("must be > 0"), std::string::npos);
    for (double bad :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
      EXPECT_NE(checkParameterValue(k, bad).find("must be a finite number"), std::string::npos);
    EXPECT_THROW(parameterIndex(specs, "no_such_parameter"), std::logic_error);
  }
  auto pac = makeTireLaw("pac2002", "test");
  const auto& specs = pac->parameters();
  EXPECT_NE(checkParameterValue(specs[parameterIndex(specs, "qfz2")], -0.1).find("must be >= 0"),
            std::string::npos);
  EXPECT_EQ(checkParameterValue(specs[parameterIndex(specs, "qfcx")], -3.0), "");  // unbounded
  EXPECT_NE(checkParameterValue(specs[parameterIndex(specs, "fnomin_N")], 0.0).find("must be > 0"),
            std::string::npos);

  ParameterSpec bounded;
  bounded.name = "ratio";
  bounded.unit = "1";
  bounded.min_value = 1.0;
  bounded.max_value = 5.0;
  EXPECT_EQ(checkParameterValue(bounded, 1.0), "");
  EXPECT_EQ(checkParameterValue(bounded, 5.0), "");
  const std::string hi = checkParameterValue(bounded, 6.5);
  EXPECT_NE(hi.find("must be <= 5"), std::string::npos) << hi;
  EXPECT_NE(hi.find("got 6.5"), std::string::npos) << hi;
  EXPECT_NE(checkParameterValue(bounded, 0.5).find("must be >= 1"), std::string::npos);
}

}  // namespace
}  // namespace dtwin
