// Reading a trace at times off its output grid (twin/trace.hpp GridSample): exact on the grid,
// exact for cubics, and inside the stated error bound for sinusoids.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "twin/trace.hpp"

using namespace dtwin;

namespace {
constexpr double kPi = 3.14159265358979323846;
std::vector<double> sampled(double rate, std::size_t rows, double (*f)(double)) {
  std::vector<double> v(rows);
  for (std::size_t k = 0; k < rows; ++k) v[k] = f(static_cast<double>(k) / rate);
  return v;
}
}  // namespace

// A time on the grid reads its row with weight 1: the value is bit-for-bit the row's.
TEST(GridSample, OnTheGridReadsTheRowExactly) {
  const double rate = 1000.0;
  const auto col = sampled(rate, 2001, [](double t) { return std::sin(7.3 * t) + 0.1 * t * t; });
  for (double t : {0.0, 0.001, 0.5, 1.234, 2.0}) {
    const GridSample g = gridSample(t, rate, col.size());
    EXPECT_EQ(g.count, 1);
    EXPECT_EQ(g.of(col), col[static_cast<std::size_t>(std::lround(t * rate))]) << t;
  }
  EXPECT_TRUE(onGrid(1.234, rate));
  EXPECT_FALSE(onGrid(1.2345, rate));
}

// The four-point Lagrange cubic reproduces any cubic exactly, inside and at both ends.
TEST(GridSample, ReproducesCubicsExactly) {
  const double rate = 100.0;
  auto cubic = [](double t) { return 2.0 - 3.0 * t + 0.5 * t * t - 1.25 * t * t * t; };
  const auto col = sampled(rate, 51, cubic);
  for (double t : {0.0013, 0.0099, 0.123, 0.2571, 0.4917, 0.4999}) {
    const GridSample g = gridSample(t, rate, col.size());
    EXPECT_EQ(g.count, 4);
    EXPECT_NEAR(g.of(col), cubic(t), 1e-12) << t;
  }
}

// For a sinusoid of frequency f the error stays below (3/128)(2 pi f h)^4 inside and
// (1/24)(2 pi f h)^4 on the first and last intervals (amplitude 1), and the bound is not slack
// by orders of magnitude: the worst error seen is above a tenth of it.
TEST(GridSample, SinusoidErrorIsInsideTheStatedBound) {
  const double rate = 1000.0, h = 1.0 / rate;
  for (double f : {2.0, 20.0, 80.0}) {
    const double w = 2 * kPi * f;
    std::vector<double> col(1001);
    for (std::size_t k = 0; k < col.size(); ++k)
      col[k] = std::sin(w * static_cast<double>(k) * h + 0.3);
    const double interior = 3.0 / 128.0 * std::pow(w * h, 4), edge = std::pow(w * h, 4) / 24.0;
    double worst_interior = 0.0;
    for (int i = 0; i < 20000; ++i) {
      const double t = (static_cast<double>(i) + 0.37) * 1e-3 / 20.0;  // off the grid
      if (t > 1.0) break;
      const double e = std::abs(gridSample(t, rate, col.size()).of(col) - std::sin(w * t + 0.3));
      const bool at_end = t < h || t > 1.0 - h;
      EXPECT_LE(e, (at_end ? edge : interior) * (1 + 1e-9) + 1e-15) << "f = " << f << ", t = " << t;
      if (!at_end) worst_interior = std::max(worst_interior, e);
    }
    EXPECT_GT(worst_interior, 0.1 * interior) << f;
  }
}

// Too short for a cubic: linear between the rows around the time.
TEST(GridSample, ShortTracesAreReadLinearly) {
  const std::vector<double> col = {1.0, 3.0, 2.0};
  const GridSample g = gridSample(0.015, 100.0, col.size());
  EXPECT_EQ(g.count, 2);
  EXPECT_DOUBLE_EQ(g.of(col), 2.5);  // half way between rows 1 and 2
}

// Times outside the grid are a programming error (the callers check them against the scenario).
TEST(GridSample, TimesOutsideTheGridAreRefused) {
  EXPECT_THROW(gridSample(-0.5, 100.0, 10), std::logic_error);
  EXPECT_THROW(gridSample(0.095, 100.0, 10), std::logic_error);
  EXPECT_NO_THROW(gridSample(0.09, 100.0, 10));
  EXPECT_THROW(gridSample(0.01, 0.0, 10), std::logic_error);
}
