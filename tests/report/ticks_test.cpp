// The reports' axis ticks (report/ticks.hpp): steps of 1, 2, 2.5 or 5 × 10^k, human labels with
// one SI suffix per axis, and the gnuplot commands that set them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "report/ticks.hpp"

using dtwin::report::gnuplotTics;
using dtwin::report::niceStep;
using dtwin::report::niceTicks;
using dtwin::report::tickLabel;

TEST(Ticks, StepsAreOneTwoTwoAndAHalfOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(niceStep(0.0, 153970.0), 50000.0);  // raw 25 662 -> 50 000 (2.5 × 10⁴ is below)
  EXPECT_DOUBLE_EQ(niceStep(0.0, 6.0), 1.0);
  EXPECT_DOUBLE_EQ(niceStep(0.0, 1.4), 0.25);           // raw 0.2333
  EXPECT_DOUBLE_EQ(niceStep(-3.6e6, -3.5e6), 20000.0);  // raw 16 667
  EXPECT_EQ(niceStep(1.0, 1.0), 0.0);
  EXPECT_EQ(niceStep(NAN, 1.0), 0.0);
  for (double span : {1e-7, 3e-3, 0.7, 13.0, 4.2e5, 9.9e9}) {
    const double st = niceStep(0.0, span),
                 m = st / std::pow(10.0, std::floor(std::log10(st) + 1e-12));
    EXPECT_TRUE(std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 2.5) < 1e-9 ||
                std::abs(m - 5) < 1e-9)
        << span;
    const auto t = niceTicks(0.0, span);
    EXPECT_GE(t.size(), 3u) << span;
    EXPECT_LE(t.size(), 7u) << span;
  }
}

TEST(Ticks, TicksAreMultiplesOfTheStepInsideTheRange) {
  const std::vector<double> t = niceTicks(-0.013, 0.047);  // step 0.01
  ASSERT_EQ(t.size(), 6u);
  EXPECT_DOUBLE_EQ(t.front(), -0.01);
  EXPECT_DOUBLE_EQ(t.back(), 0.04);
  EXPECT_EQ(t[1], 0.0);  // exactly zero, never 1e-18
  EXPECT_EQ(niceTicks(2.0, 2.0), std::vector<double>{2.0});
  EXPECT_TRUE(niceTicks(3.0, 2.0).empty());
}

TEST(Ticks, LabelsAreHuman) {
  EXPECT_EQ(tickLabel(150000.0, 50000.0), "150k");
  EXPECT_EQ(tickLabel(-3.5e6, 5e5), "-3.5M");
  EXPECT_EQ(tickLabel(500000.0, 5e5, 3.5e6), "0.5M");  // the axis's suffix
  EXPECT_EQ(tickLabel(2500.0, 500.0), "2500");
  EXPECT_EQ(tickLabel(0.0125, 0.0025), "0.0125");
  EXPECT_EQ(tickLabel(0.58, 0.01), "0.58");
  EXPECT_EQ(tickLabel(1.0, 0.25), "1.00");
  EXPECT_EQ(tickLabel(2e-5, 1e-5), "2e-05");
  EXPECT_EQ(tickLabel(1e-17, 0.1), "0");
  EXPECT_EQ(tickLabel(-0.0, 1.0), "0");
  EXPECT_EQ(tickLabel(2.0e9, 5e8), "2.0G");
}

TEST(Ticks, GnuplotCommandsSetTheRangeAndLabelledTicks) {
  const std::string s = gnuplotTics("y", 140000.0, 160000.0);
  EXPECT_NE(s.find("set yrange [140000:160000]"), std::string::npos) << s;
  EXPECT_NE(s.find("\"150k\" 150000"), std::string::npos) << s;
  EXPECT_EQ(s.find("e+05"), std::string::npos) << s;
  // A degenerate range is widened, never left empty.
  EXPECT_NE(gnuplotTics("x", 5.0, 5.0).find("set xrange [4.99"), std::string::npos);
  EXPECT_NE(gnuplotTics("x", 5.0, 5.0).find("\"5.000\" 5"), std::string::npos)
      << gnuplotTics("x", 5.0, 5.0);
  EXPECT_EQ(dtwin::report::axisLabel("tire.stiffness", "N/m"), "tire.stiffness [N/m]");
  EXPECT_EQ(dtwin::report::axisLabel("ratio", "1"), "ratio");
}
