// Strut laws: the registry's contract, run over every registered law, and each law against its
// closed form.
#include "subsystems/strut_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "effect_fixture.hpp"

namespace dtwin {
namespace {

using dtwin_test::strut;

/// Values a law accepts: the contract's stiffness and damping at realistic figures, the other
/// parameters at their default when valid, else one unit above their lower bound.
std::vector<double> typicalValues(const StrutLaw& law) {
  std::vector<double> v;
  for (const auto& s : law.parameters()) {
    double x = s.default_value;
    if (s.name == "stiffness") x = 30000.0;
    if (s.name == "damping") x = 2500.0;
    if (!checkParameterValue(s, x).empty()) x = s.min_value + 1.0;
    EXPECT_EQ(checkParameterValue(s, x), "") << law.name() << "." << s.name;
    v.push_back(x);
  }
  return v;
}

// ------------------------------------------------------------------ registry contract

TEST(StrutRegistry, NamesAreUniqueAndEveryNameMakesItsLaw) {
  const auto names = strutLawNames();
  ASSERT_FALSE(names.empty());
  EXPECT_EQ(names.front(), "linear");  // the default of studies that name no strut option
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  for (const auto& n : names) {
    const auto law = makeStrutLaw(n, "here");
    EXPECT_EQ(law->name(), n);
    EXPECT_FALSE(law->description().empty()) << n;
  }
}

TEST(StrutRegistry, UnknownNameIsAnInputErrorThatListsTheLaws) {
  try {
    makeStrutLaw("lineer", "study.toml: subsystems.strut");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("study.toml: subsystems.strut"), std::string::npos) << m;
    EXPECT_NE(m.find("linear"), std::string::npos) << m;
  }
}

TEST(StrutRegistry, EveryLawKeepsTheContract) {
  for (const auto& n : strutLawNames()) {
    const auto law = makeStrutLaw(n, "");
    const auto& specs = law->parameters();
    ASSERT_GE(specs.size(), 2u) << n;
    // The calibrated pair comes first and is shared by every suspension option.
    EXPECT_EQ(specs[0].name, "stiffness") << n;
    EXPECT_EQ(specs[0].unit, "N/m") << n;
    EXPECT_TRUE(specs[0].shared) << n;
    EXPECT_EQ(specs[1].name, "damping") << n;
    EXPECT_EQ(specs[1].unit, "N*s/m") << n;
    EXPECT_TRUE(specs[1].shared) << n;
    std::set<std::string> seen;
    for (const auto& s : specs) {
      EXPECT_TRUE(seen.insert(s.name).second) << n << ": " << s.name << " twice";
      EXPECT_FALSE(s.unit.empty()) << n << "." << s.name;
      EXPECT_FALSE(s.description.empty()) << n << "." << s.name;
    }
    const auto v = typicalValues(*law);
    // Design ride height is the static equilibrium: the force at rest is the preload.
    for (double preload : {0.0, 2907.0, -150.0})
      EXPECT_DOUBLE_EQ(law->calcForce(StrutState{0.0, 0.0, preload, v[0], v[1]}, v), preload) << n;
    // Finite everywhere a strut can go, and a spring: more compression, more force.
    double last = -std::numeric_limits<double>::infinity();
    for (double q = -0.4; q <= 0.4; q += 0.01) {
      const double F = law->calcForce(strut(q, 0.0), v);
      EXPECT_TRUE(std::isfinite(F)) << n << " q " << q;
      EXPECT_GT(F, last) << n << " q " << q;
      last = F;
    }
    // A damper: compressing faster pushes harder.
    EXPECT_GT(law->calcForce(strut(0.01, 0.5), v), law->calcForce(strut(0.01, -0.5), v)) << n;
  }
}

// ------------------------------------------------------------------ linear strut (paper eq. 4 and
// 5)

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
      EXPECT_NEAR(law.calcForce(strut(q, qdot), p), expected, 1e-9)
          << "q " << q << " qdot " << qdot;
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
    const double fd =
        (law.calcForce(strut(q + h, 0), p) - law.calcForce(strut(q - h, 0), p)) / (2 * h);
    EXPECT_NEAR(fd / (k + k_hs), 1.0, 1e-6) << q;
  }
  const double fd_in =
      (law.calcForce(strut(0.2 + h, 0), p) - law.calcForce(strut(0.2 - h, 0), p)) / (2 * h);
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
