// Unit strings as dimensions (common/units.hpp).
#include <gtest/gtest.h>

#include "common/units.hpp"

using namespace dtwin;

namespace {
Dimension parse(const std::string& u) {
  std::string rule;
  const auto d = parseUnit(u, rule);
  EXPECT_TRUE(d.has_value()) << u << ": " << rule;
  return d.value_or(Dimension{99, 99, 99});
}
std::string ruleOf(const std::string& u) {
  std::string rule;
  EXPECT_FALSE(parseUnit(u, rule).has_value()) << u;
  return rule;
}
}  // namespace

TEST(Units, DerivedSymbolsAndPowersReduceToMassLengthTime) {
  EXPECT_EQ(parse("N"), (Dimension{1, 1, -2}));
  EXPECT_EQ(parse("N*s/m"), (Dimension{1, 0, -1}));
  EXPECT_EQ(parse("kg/s"), parse("N*s/m"));
  EXPECT_EQ(parse("J"), parse("N*m"));
  EXPECT_EQ(parse("W"), parse("J/s"));
  EXPECT_EQ(parse("Pa"), parse("N/m^2"));
  EXPECT_EQ(parse("Hz"), parse("1/s"));
  EXPECT_EQ(parse("rad"), parse("1"));
  EXPECT_EQ(parse("m/s^2"), (Dimension{0, 1, -2}));
  EXPECT_EQ(parse("(m/s)^0.5"), (Dimension{0, 0.5, -0.5}));
  EXPECT_EQ(parse("m^-1"), (Dimension{0, -1, 0}));
  EXPECT_EQ(parse(" N * s / m "), parse("N*s/m"));
  // a/b*c is (a/b)*c, as in arithmetic.
  EXPECT_EQ(parse("N/m*s"), (Dimension{1, 0, -1}));
}

TEST(Units, FormatReadsBack) {
  for (const char* u : {"N", "N*s/m", "N/m^2", "N*s^2/m^2", "kg", "m/s", "1", "N*s^0.5/m^0.5",
                        "kg*m^2", "m^-1", "1/s"}) {
    const Dimension d = parse(u);
    EXPECT_EQ(parse(formatUnit(d)), d) << u << " -> " << formatUnit(d);
  }
  EXPECT_EQ(formatUnit(parse("N*s/m")), "N*s/m");
  EXPECT_EQ(formatUnit(parse("kg*m^2/s^2")), "N*m");
  EXPECT_EQ(formatUnit(parse("m/s")), "m/s");
  EXPECT_EQ(formatUnit(parse("1")), "1");
}

TEST(Units, ScalingMultipliesByEachBasePower) {
  EXPECT_DOUBLE_EQ(scaleFactor(parse("N"), 2, 3, 5), 2.0 * 3.0 / 25.0);
  EXPECT_DOUBLE_EQ(scaleFactor(parse("1"), 2, 3, 5), 1.0);
}

TEST(Units, BadUnitsAreOneSentence) {
  EXPECT_NE(ruleOf("").find("a unit is required"), std::string::npos);
  EXPECT_NE(ruleOf("Ns").find("unknown symbol 'Ns'"), std::string::npos);
  EXPECT_NE(ruleOf("kN").find("prefixes are not allowed"), std::string::npos);
  EXPECT_NE(ruleOf("N/").find("expected a symbol at the end"), std::string::npos);
  EXPECT_NE(ruleOf("(N/m").find("a '(' is not closed"), std::string::npos);
  EXPECT_NE(ruleOf("m^x").find("'^' must be followed by a number"), std::string::npos);
  EXPECT_NE(ruleOf("m s").find("unexpected 's'"), std::string::npos);
  for (const char* u : {"", "Ns", "kN", "N/", "(N/m", "m^x", "m s"})
    EXPECT_EQ(ruleOf(u).find('\n'), std::string::npos);
}
