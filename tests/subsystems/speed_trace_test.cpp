// The measured speed trace (subsystems/speed_trace.hpp) against closed forms: it reproduces a
// linear speed exactly (and its distance, a quadratic), never overshoots monotone or stop-and-go
// data, integrates to what a fine quadrature of its own speed gives, differentiates to its
// acceleration, inverts its distance, and refuses bad samples naming the first one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "common/errors.hpp"
#include "io/speed_trace_file.hpp"

using dtwin::InputError;
using dtwin::SpeedTrace;

namespace {
/// ∫_a^b f by composite Simpson on n (even) panels.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(a + i * h);
  return s * h / 3;
}

/// The message of the InputError `f` throws ("" if none).
std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string errorOf(std::vector<double> t, std::vector<double> v) {
  return messageOf([&] { SpeedTrace(std::move(t), std::move(v), "speed.csv"); });
}
}  // namespace

TEST(SpeedTrace, ReproducesALinearSpeedAndItsQuadraticDistanceExactly) {
  // v = 2 + 0.5 t sampled at uneven times: PCHIP's slopes are the secant slope everywhere.
  const std::vector<double> t = {-1.0, 0.3, 0.7, 2.0, 2.1, 5.0};
  std::vector<double> v;
  for (double x : t) v.push_back(2 + 0.5 * x);
  const SpeedTrace s(t, v, "linear");
  for (double x = -0.9; x < 4.95; x += 0.037) {
    EXPECT_NEAR(s.speed(x), 2 + 0.5 * x, 1e-12) << x;
    EXPECT_NEAR(s.accel(x), 0.5, 1e-12) << x;
    EXPECT_NEAR(s.distance(x), 2 * x + 0.25 * x * x, 1e-12) << x;
    if (x > 0) {
      EXPECT_NEAR(s.timeAtDistance(2 * x + 0.25 * x * x), x, 1e-9) << x;
    }
  }
  // Beyond the samples the end speed is held.
  EXPECT_DOUBLE_EQ(s.speed(7.0), 4.5);
  EXPECT_NEAR(s.distance(7.0), s.distance(5.0) + 2 * 4.5, 1e-12);
}

TEST(SpeedTrace, NeverOvershootsStopAndGoData) {
  // Stop, pull away, cruise, brake to a stop, wait, pull away again: the interpolant stays within
  // the neighbouring samples on every interval, so it is never negative and never above 20 m/s.
  const std::vector<double> t = {0, 2, 3, 4, 8, 9, 10, 14, 15, 16};
  const std::vector<double> v = {0, 0, 5, 20, 20, 6, 0, 0, 10, 10};
  const SpeedTrace s(t, v, "stop_and_go");
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const double lo = std::min(v[k], v[k + 1]), hi = std::max(v[k], v[k + 1]);
    double prev = v[k];
    for (int i = 0; i <= 200; ++i) {
      const double x = t[k] + (t[k + 1] - t[k]) * i / 200.0;
      const double sp = s.speed(x);
      EXPECT_GE(sp, lo - 1e-12) << x;
      EXPECT_LE(sp, hi + 1e-12) << x;
      // monotone between samples, in the direction of the data
      if (v[k + 1] >= v[k])
        EXPECT_GE(sp, prev - 1e-12) << x;
      else
        EXPECT_LE(sp, prev + 1e-12) << x;
      prev = sp;
    }
  }
  // At rest, no distance is covered; the first time a point 1 mm past the stop is reached is
  // after the car pulls away again.
  EXPECT_NEAR(s.distance(14.0) - s.distance(10.0), 0.0, 1e-12);
  EXPECT_GT(s.timeAtDistance(s.distance(10.0) + 1e-3), 14.0);
  // The first time it got there: t = 10 s. Coming to rest the speed falls as (10 − t)², the
  // distance as (10 − t)³, so a distance exact to 1e-12 m fixes the time only to ~1e-5 s.
  const double x_stop = s.distance(12.0), t_stop = s.timeAtDistance(x_stop);
  EXPECT_NEAR(t_stop, 10.0, 1e-4);
  EXPECT_NEAR(s.distance(t_stop), x_stop, 1e-10);
}

TEST(SpeedTrace, DistanceIsTheIntegralAndAccelerationTheDerivativeOfTheSpeed) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> dt(0.005, 0.02), dv(-1.5, 1.5);
  std::vector<double> t = {0.0}, v = {3.0};
  while (t.back() < 5.0) {  // a 100 Hz log with clock jitter and a noisy speed
    t.push_back(t.back() + dt(rng));
    v.push_back(std::max(0.2, v.back() + dv(rng)));  // never at rest: distance strictly increasing
  }
  const SpeedTrace s(t, v, "jittered");
  for (double b : {0.5, 1.234, 3.0, 4.9}) {
    // Simpson on panels aligned to nothing: the cubic pieces make it converge at h⁴ except at the
    // knots, so a fine grid is within 1e-7 m.
    EXPECT_NEAR(s.distance(b), simpson([&](double x) { return s.speed(x); }, 0.0, b, 200000), 1e-7)
        << b;
  }
  for (double x = 0.01; x < 4.9; x += 0.0731) {
    const double h = 1e-7;
    EXPECT_NEAR(s.accel(x), (s.speed(x + h) - s.speed(x - h)) / (2 * h),
                1e-4 * (1 + std::abs(s.accel(x))))
        << x;
    EXPECT_NEAR(s.timeAtDistance(s.distance(x)), x, 1e-8) << x;
  }
}

TEST(SpeedTrace, RefusesBadSamplesNamingTheFirst) {
  EXPECT_EQ(errorOf({0.0}, {1.0}), "speed.csv: a speed trace needs at least 2 samples, got 1");
  EXPECT_EQ(errorOf({0.0, 1.0}, {1.0}), "speed.csv: has 2 times but 1 speeds");
  EXPECT_EQ(errorOf({0.0, 1.0, 1.0}, {1, 2, 3}),
            "speed.csv: sample 2: time must increase, got 1 after 1");
  EXPECT_EQ(errorOf({0.0, 2.0, 1.0}, {1, 2, 3}),
            "speed.csv: sample 2: time must increase, got 1 after 2");
  EXPECT_EQ(errorOf({0.0, 1.0}, {1.0, -0.5}), "speed.csv: sample 1: speed must be >= 0, got -0.5");
  EXPECT_EQ(errorOf({0.0, NAN}, {1.0, 1.0}), "speed.csv: sample 1: time must be finite, got nan");
  EXPECT_EQ(errorOf({0.0, 1.0}, {INFINITY, 1.0}),
            "speed.csv: sample 0: speed must be finite, got inf");
}

TEST(SpeedTrace, StartsAfterTimeZeroAndEndsAtRest) {
  // Samples from t = 1 s: the first speed holds before; ending at rest, a distance beyond the
  // last is never reached.
  const SpeedTrace s({1.0, 2.0, 3.0}, {4.0, 2.0, 0.0}, "late");
  EXPECT_DOUBLE_EQ(s.speed(0.0), 4.0);
  EXPECT_NEAR(s.distance(1.0), 4.0, 1e-12);
  EXPECT_NEAR(s.timeAtDistance(2.0), 0.5, 1e-9);
  EXPECT_TRUE(std::isinf(s.timeAtDistance(s.distance(3.0) + 1.0)));
  EXPECT_NEAR(s.timeAtDistance(s.distance(2.5)), 2.5, 1e-9);
}

namespace {
std::string csvError(const std::string& text) {
  return messageOf([&] { dtwin::parseSpeedTraceCsv(text, "drive.csv"); });
}
}  // namespace

TEST(SpeedTraceCsv, ReadsEveryUnitWithABomCrlfAndBlankLines) {
  const auto kmh = dtwin::parseSpeedTraceCsv(
      "\xEF\xBB\xBFtime_s,speed_kmh\r\n0,36\r\n\r\n1.5,72\r\n", "kmh.csv");
  ASSERT_EQ(kmh.times().size(), 2u);
  EXPECT_DOUBLE_EQ(kmh.speed(0.0), 10.0);
  EXPECT_DOUBLE_EQ(kmh.speed(1.5), 20.0);
  EXPECT_NEAR(kmh.distance(1.5), 1.5 * 15.0, 1e-12);  // linear between two samples
  EXPECT_DOUBLE_EQ(dtwin::parseSpeedTraceCsv("time_s,speed_mph\n0,10\n1,10\n", "m").speed(0.5),
                   4.4704);
  EXPECT_DOUBLE_EQ(dtwin::parseSpeedTraceCsv("time_s,speed_mps\n-1,+3\n1,3\n", "m").speed(0.0),
                   3.0);
}

TEST(SpeedTraceCsv, BadFilesGetOneLineNamingTheLineAndColumn) {
  const std::string known = "(speed_mps, speed_kmh, speed_mph)";
  EXPECT_EQ(csvError(""),
            "drive.csv:1: empty file; expected the header 'time_s,speed_<unit>' " + known);
  EXPECT_EQ(csvError("t,speed_kmh\n"),
            "drive.csv:1: header must be 'time_s,speed_<unit>' " + known + ", got 't,speed_kmh'");
  EXPECT_EQ(csvError("time_s,speed_kmh,x\n"), "drive.csv:1: header must be 'time_s,speed_<unit>' " +
                                                  known + ", got 'time_s,speed_kmh,x'");
  EXPECT_EQ(
      csvError("time_s,speed_knots\n"),
      "drive.csv:1: unknown speed column 'speed_knots'; known: speed_mps, speed_kmh, speed_mph");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\n\n1\n"),
            "drive.csv:4: expected 2 columns (time_s,speed_kmh), got '1'");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\n1,2,3\n"),
            "drive.csv:3: expected 2 columns (time_s,speed_kmh), got '1,2,3'");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\nx,2\n"),
            "drive.csv:3: time_s: 'x' is not a finite number");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\n1,nan\n"),
            "drive.csv:3: speed_kmh: 'nan' is not a finite number");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\n1,1e999\n"),
            "drive.csv:3: speed_kmh: '1e999' is not a finite number");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\n1,-2\n"),
            "drive.csv:3: speed_kmh: must be >= 0, got -2");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\n0,2\n"),
            "drive.csv:3: time_s: must increase, got 0 after 0");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\n"),
            "drive.csv: a speed trace needs at least 2 rows, got 1");
  EXPECT_EQ(csvError("time_s,speed_kmh\n0,1\n1,2\r\r\n"),
            "drive.csv:3: speed_kmh: '2\\r' is not a finite number");
}

// The interval lookup (a bucket table, then a step or two) finds the interval a binary search
// finds: on 5000 jittered samples of a random speed, the speed at any time lies between the two
// samples around it (the monotone interpolant's property, which a wrong interval breaks) and is
// the sample itself at a sample time, including the times one rounding step before and after.
TEST(SpeedTrace, FindsTheIntervalOfAnyTimeOnAJitteredClock) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.004, 0.004), speed(0.0, 30.0), where(-1.0, 52.0);
  std::vector<double> t, v;
  for (int k = 0; k < 5000; ++k) {
    t.push_back(0.3 + 0.01 * k + (k > 0 && k < 4999 ? jitter(rng) : 0.0));
    v.push_back(speed(rng));
  }
  const SpeedTrace s(t, v, "jittered");
  auto between = [&](double time) {
    const auto it = std::upper_bound(t.begin(), t.end(), time);
    if (it == t.begin() || it == t.end()) return;
    const std::size_t k = static_cast<std::size_t>(it - t.begin()) - 1;
    const double lo = std::min(v[k], v[k + 1]), hi = std::max(v[k], v[k + 1]);
    const double x = s.speed(time);
    EXPECT_GE(x, lo - 1e-12) << "t = " << time;
    EXPECT_LE(x, hi + 1e-12) << "t = " << time;
  };
  for (int i = 0; i < 20000; ++i) between(where(rng));
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    EXPECT_EQ(s.speed(t[k]), v[k]) << k;
    between(std::nextafter(t[k], -1e9));
    between(std::nextafter(t[k], 1e9));
  }
  EXPECT_EQ(s.speed(-5.0), v.front());
  EXPECT_EQ(s.speed(1e30), v.back());
}
