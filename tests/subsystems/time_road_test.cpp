// Roads logged against time: the CSV forms, the zero-phase drift removal against its closed-form
// gain, and the mapping to distance (constant speed: a sinusoid in time is a sinusoid in space;
// a stop leaves the profile unchanged).
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "subsystems/time_road.hpp"
#include "time_road_util.hpp"

using namespace dtwin;

namespace {
using dtwin_test::kPi;
std::string errorOf(const std::string& text) { return dtwin_test::timeRoadError(text); }
}  // namespace

TEST(TimeRoad, ParsesEveryForm) {
  auto a = parseTimeRoadCsv("\xEF\xBB\xBFtime_s,height_mm\r\n0,1\r\n\r\n0.01, 2\r\n", "a.csv");
  EXPECT_EQ(a.form, TimeRoadLog::Form::Height);
  EXPECT_TRUE(a.identical_tracks);
  EXPECT_DOUBLE_EQ(a.left[1], 0.002);
  EXPECT_EQ(a.left, a.right);
  auto b = parseTimeRoadCsv("time_s,left_m,right_m\n0,0.1,0.2\n1,0.3,0.4\n", "b.csv");
  EXPECT_FALSE(b.identical_tracks);
  EXPECT_DOUBLE_EQ(b.right[1], 0.4);
  auto c = parseTimeRoadCsv("time_s,velocity_mps\n0,0.1\n1,0.3\n", "c.csv");
  EXPECT_EQ(c.form, TimeRoadLog::Form::Velocity);
  auto d =
      parseTimeRoadCsv("\"time_s\",\"left_mps\",\"right_mps\"\n0,0.1,0.2\n1,0.3,0.4\n", "d.csv");
  EXPECT_EQ(d.form, TimeRoadLog::Form::Velocity);
  EXPECT_FALSE(d.identical_tracks);
  // Centimetres and millimetres per second, as loggers write them.
  auto e = parseTimeRoadCsv("time_s,left_cm,right_cm\n0,1,2\n1,3,4\n", "e.csv");
  EXPECT_DOUBLE_EQ(e.right[1], 0.04);
  auto f = parseTimeRoadCsv("time_s,velocity_mmps\n0,10\n1,30\n", "f.csv");
  EXPECT_EQ(f.form, TimeRoadLog::Form::Velocity);
  EXPECT_DOUBLE_EQ(f.left[1], 0.03);
}

TEST(TimeRoad, BadFilesNameTheLineAndColumn) {
  EXPECT_NE(errorOf("").find("road.csv:1: empty file"), std::string::npos);
  EXPECT_NE(errorOf("time_s,height_ft\n0,1\n1,2\n").find("road.csv:1: header must be"),
            std::string::npos);
  EXPECT_NE(errorOf("time_s,height_m\n0,1\n0.1,x\n")
                .find("road.csv:3: height_m: 'x' is not a finite number"),
            std::string::npos);
  EXPECT_NE(errorOf("time_s,height_m\n0,1\n0.1,nan\n").find("road.csv:3: height_m"),
            std::string::npos);
  EXPECT_NE(errorOf("time_s,height_m\n0,1\n0,2\n").find("road.csv:3: time_s: must increase"),
            std::string::npos);
  EXPECT_NE(errorOf("time_s,left_m,right_m\n0,1\n").find("road.csv:2: expected 3 columns, got 2"),
            std::string::npos);
  EXPECT_NE(errorOf("time_s,height_m\n0,1\n").find("at least 2 rows"), std::string::npos);
  EXPECT_NE(errorOf("time_s,height_m\n0,\"1\n").find("road.csv:2: a double quote is not closed"),
            std::string::npos);
}

// The gain of the zero-phase high-pass is (f/fc)²/(1 + (f/fc)²) and its phase 0; a linear drift
// is removed away from the ends.
TEST(TimeRoad, ZeroPhaseHighPassHasItsClosedFormGain) {
  const double fc = 0.2, dt = 0.01;
  std::vector<double> t(20000);
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = dt * static_cast<double>(k);
  for (double f : {0.05, 0.2, 1.0, 3.0}) {
    std::vector<double> u(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) u[k] = std::sin(2 * kPi * f * t[k]);
    const auto y = zeroPhaseHighPass(t, u, fc);
    // In-phase and quadrature parts over the middle half (away from the ends' transients).
    double s = 0, c = 0, n = 0;
    for (std::size_t k = t.size() / 4; k < 3 * t.size() / 4; ++k) {
      s += y[k] * std::sin(2 * kPi * f * t[k]);
      c += y[k] * std::cos(2 * kPi * f * t[k]);
      n += 1;
    }
    const double r = (f / fc) * (f / fc);
    EXPECT_NEAR(2 * s / n, r / (1 + r), 0.01) << f;
    EXPECT_NEAR(2 * c / n, 0.0, 0.01) << f;
  }
  std::vector<double> ramp(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) ramp[k] = 0.3 * t[k] + 1.0;
  const auto y = zeroPhaseHighPass(t, ramp, fc);
  for (std::size_t k = 5000; k < 15000; k += 100) EXPECT_NEAR(y[k], 0.0, 1e-6) << k;
}

// A road velocity with a sensor bias integrates to the road's height, the bias's drift removed.
TEST(TimeRoad, VelocityIntegratesToHeightWithoutDrift) {
  const double f = 1.5, A = 0.01, dt = 0.01;
  std::vector<double> t(6000), v(6000);
  for (std::size_t k = 0; k < t.size(); ++k) {
    t[k] = dt * static_cast<double>(k);
    v[k] = A * 2 * kPi * f * std::cos(2 * kPi * f * t[k]) +
           0.004;  // height A sin(2π f t), plus a bias
  }
  const auto h = roadHeightFromVelocity(t, v, 0.1);
  const double r = (f / 0.1) * (f / 0.1), gain = r / (1 + r);
  for (std::size_t k = 1500; k < 4500; k += 37)
    EXPECT_NEAR(h[k], gain * A * std::sin(2 * kPi * f * t[k]), 2e-3 * A + 1e-6) << t[k];
}

// At constant speed v a height sin(2π f t) is the profile sin(2π f x / v); a stop in between
// (samples at one distance) leaves the profile as it was, and before the first sample the first
// height is held.
TEST(TimeRoad, MapsToDistanceThroughTheSpeed) {
  const double f = 2.0, speed = 10.0, dt = 0.01;
  TimeRoadLog log;
  log.name = "x.csv";
  log.identical_tracks = true;
  auto dist = [&](double t) {
    return t < 2.0 ? speed * t : t < 3.0 ? 2.0 * speed : speed * (t - 1.0);
  };
  for (int k = 0; k <= 600; ++k) {
    const double t = dt * k, x = dist(t);
    const double h = 0.02 * std::sin(2 * kPi * f * x / speed) +
                     (t > 2.0 && t < 3.0 ? 0.5 : 0.0);  // junk while standing
    log.t_s.push_back(t);
    log.left.push_back(h);
    log.right.push_back(h);
  }
  TimeRoadOptions o;
  o.x_from_m = -4.0;
  const auto road = roadFromTimeLog(log, dist, o, {{"type", "test"}});
  double worst = 0;
  for (double x = 0.05; x < 49.0; x += 0.0137) {
    const double want = 0.02 * std::sin(2 * kPi * f * x / speed);
    worst = std::max(worst, std::abs(road->sample(Track::Left, x).height_m - want));
  }
  EXPECT_LT(worst, 0.01 * 0.02);
  EXPECT_NEAR(road->sample(Track::Right, -3.0).height_m, log.left.front(), 1e-15);
  EXPECT_LE(road->extent().lo, -4.0);
  EXPECT_GE(road->extent().hi, 49.0);
  // A height beyond 10 m: a wrong unit.
  TimeRoadLog tall = log;
  tall.left[100] = 12.0;
  try {
    roadFromTimeLog(tall, dist, o, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("time_s = 1 is 12 m"), std::string::npos) << e.what();
  }
  // Never moving: no profile.
  try {
    roadFromTimeLog(log, [](double) { return 0.0; }, o, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.csv"), std::string::npos);
  }
}

// A velocity log's detail between its samples: at 100 Hz, a 10 Hz content integrates to its height
// within 0.5 % (the trapezoid rule loses (ωΔt)²/12 = 3.3 %), and mapped to distance with the
// velocity's own slopes the profile holds a 10 Hz content to 0.6 % and a 20 Hz one to 4 % (the
// trapezoid alone loses 13 % of it).
TEST(TimeRoad, AVelocityLogKeepsItsDetailBetweenSamples) {
  const double dt = 0.01, speed = 12.0, A = 0.005;
  for (double f : {10.0, 20.0}) {
    SCOPED_TRACE("f = " + std::to_string(f) + " Hz");
    const double w = 2 * kPi * f;
    TimeRoadLog log;
    log.name = "v.csv";
    log.form = TimeRoadLog::Form::Velocity;
    log.identical_tracks = true;
    for (int k = 0; k <= 6000;
         ++k) {  // 60 s: the drift removal's start-up (0.05 Hz) has died out after 30 s
      const double t = dt * k;
      log.t_s.push_back(t);
      log.left.push_back(A * w * std::cos(w * t));
      log.right.push_back(log.left.back());
    }
    const auto h = roadHeightFromVelocity(log.t_s, log.left, 0.05);
    double worst_h = 0;
    for (std::size_t k = 3000; k < 4000; ++k)
      worst_h = std::max(worst_h, std::abs(h[k] - A * std::sin(w * log.t_s[k])));
    if (f == 10.0) {
      EXPECT_LT(worst_h, 0.005 * A);
    }
    TimeRoadOptions o;
    o.dx_m = 0.005;
    o.highpass_hz = 0.05;
    const auto road =
        roadFromTimeLog(log, [&](double t) { return speed * t; }, o, {{"type", "test"}});
    double worst = 0;
    for (double x = 360.0; x < 480.0; x += 0.00731)
      worst = std::max(
          worst, std::abs(road->sample(Track::Left, x).height_m - A * std::sin(w * x / speed)));
    EXPECT_LT(worst, (f == 10.0 ? 0.006 : 0.04) * A) << "worst " << worst / A;
  }
}

// A logger's velocity at 110 Hz on a clock that jitters by ±1.5 ms: each step integrates the
// polynomial through eight samples, so the height keeps its amplitude (the least-squares sine
// through the middle of the record) to 0.3 % at 20 Hz and 1 % at 25 Hz, where the cubic Hermite
// interpolant with three-point slopes kept 97.4 % and 93.8 %: content a hub input passes whole to
// the body. Exact for a polynomial of degree 7 at any spacing.
TEST(TimeRoad, AVelocityLogOnAJitteredClockKeepsItsHeightToAFifthOfItsRate) {
  const double rate = 110.0;
  std::vector<double> t;
  unsigned state = 12345u;
  auto uniform = [&] {  // a fixed linear congruential sequence in [−1, 1]
    state = state * 1103515245u + 12345u;
    return static_cast<double>((state >> 8) & 0xFFFF) / 32767.5 - 1.0;
  };
  for (int k = 0; k <= 6600; ++k)
    t.push_back(k / rate + (k > 0 && k < 6600 ? 0.0015 * uniform() : 0.0));
  for (auto [f, loss] : {std::pair{10.0, 0.0005}, {20.0, 0.003}, {25.0, 0.01}}) {
    SCOPED_TRACE("f = " + std::to_string(f) + " Hz");
    const double w = 2 * kPi * f;
    std::vector<double> v(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) v[k] = std::cos(w * t[k]);
    const auto h = roadHeightFromVelocity(t, v, 0.05);
    // h ≈ a sin(wt) + b cos(wt) over 20–40 s (the drift removal's start-up has died out).
    double ss = 0, cc = 0, sc = 0, sh = 0, ch = 0;
    for (std::size_t k = 2200; k < 4400; ++k) {
      const double s = std::sin(w * t[k]), c = std::cos(w * t[k]);
      ss += s * s, cc += c * c, sc += s * c, sh += s * h[k], ch += c * h[k];
    }
    const double det = ss * cc - sc * sc;
    const double a = (sh * cc - ch * sc) / det, b = (ch * ss - sh * sc) / det;
    EXPECT_NEAR(std::hypot(a, b) * w, 1.0, loss);
    EXPECT_LT(std::abs(b / a), loss);  // no phase
  }
}

// A gap in the log (the logger paused for two seconds): no polynomial spans it (one through four
// samples on each side swings by 10^4 times the road's height over it); the step across it is the
// Hermite integral, which misses what the gap hides (a step in the heights, no more).
TEST(TimeRoad, AGapInAVelocityLogIsNotSpannedByAPolynomial) {
  const double f = 5.0, w = 2 * kPi * f, A = 0.01;
  std::vector<double> t, v;
  for (int k = 0; k <= 6000; ++k) {
    const double x = 0.01 * k;
    if (x > 30.0 && x < 32.0) continue;
    t.push_back(x);
    v.push_back(A * w * std::cos(w * x));
  }
  const auto h = roadHeightFromVelocity(t, v, 0.05);
  double worst = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] > 20.0 && t[k] < 40.0) worst = std::max(worst, std::abs(h[k]));
  EXPECT_LT(worst, 100 * A) << worst / A;
}

// A velocity log's profile keeps the velocity between its grid's nodes: the grid's slopes are the
// interpolant's own, not central differences of its heights (those lose (k dx)²/6 of a wave's
// slope: 1.1 % of a 10 Hz content at 12 m/s on a 5 cm grid).
TEST(TimeRoad, AVelocityLogsGridKeepsItsOwnSlopes) {
  const double dt = 0.01, speed = 12.0, A = 0.005, f = 10.0, w = 2 * kPi * f;
  TimeRoadLog log;
  log.name = "v.csv";
  log.form = TimeRoadLog::Form::Velocity;
  log.identical_tracks = true;
  for (int k = 0; k <= 6000; ++k) {
    log.t_s.push_back(dt * k);
    log.left.push_back(A * w * std::cos(w * dt * k));
    log.right.push_back(log.left.back());
  }
  TimeRoadOptions o;
  o.dx_m = 0.05;
  o.highpass_hz = 0.05;
  const auto road = roadFromTimeLog(log, [&](double t) { return speed * t; }, o, {});
  double worst = 0;
  for (double x = 360.0; x < 480.0; x += 0.00731)
    worst = std::max(worst, std::abs(road->sample(Track::Left, x).slope -
                                     A * w / speed * std::cos(w * x / speed)));
  EXPECT_LT(worst, 0.003 * A * w / speed) << worst / (A * w / speed);
}

// Past the log's last sample the profile runs on along its last slope for x_past_m, then holds:
// a wheel a few centimetres ahead of its static place at the run's last time still reads the
// road's motion (the hold's zero slope stopped the hub dead on a drive's last record, a 17-sigma
// miss of the body accelerometer there). Closed form: a road rising at a constant rate.
TEST(TimeRoad, TheProfileRunsOnAlongItsLastSlopePastTheLogsEnd) {
  const double dt = 0.01, speed = 10.0, rate = 0.03;  // m/s of vertical velocity
  for (const auto form : {TimeRoadLog::Form::Height, TimeRoadLog::Form::Velocity}) {
    TimeRoadLog log;
    log.name = "end.csv";
    log.form = form;
    log.identical_tracks = true;
    for (int k = 0; k <= 6000; ++k) {
      const double t = dt * k;
      log.t_s.push_back(t);
      // The height form a ramp; the velocity form a 1 Hz sine (a constant velocity is drift).
      log.left.push_back(form == TimeRoadLog::Form::Height ? rate * t
                                                           : rate * std::cos(2 * kPi * t + 0.3));
      log.right.push_back(log.left.back());
    }
    TimeRoadOptions o;
    o.highpass_hz = 0.05;  // (a height log has none)
    const auto road = roadFromTimeLog(log, [&](double t) { return speed * t; }, o, {});
    const double end = speed * 60.0, slope = rate / speed;
    const RoadSample at_end = road->sample(Track::Left, end);
    for (const double past : {0.01, 0.05, 0.3}) {
      const RoadSample s = road->sample(Track::Left, end + past);
      EXPECT_NEAR(s.slope, at_end.slope, 1e-9 + 1e-6 * slope) << past;
      EXPECT_NEAR(s.height_m, at_end.height_m + at_end.slope * past, 1e-9) << past;
    }
    const double last =
        form == TimeRoadLog::Form::Height ? slope : slope * std::cos(120 * kPi + 0.3);
    EXPECT_NEAR(at_end.slope, last, 0.02 * slope);
    // Held from x_past_m on.
    EXPECT_EQ(road->sample(Track::Left, end + 2.0).slope, 0.0);
    EXPECT_NEAR(road->sample(Track::Left, end + 2.0).height_m, at_end.height_m + at_end.slope * 0.5,
                0.02 * slope * 0.5 + 1e-6);
  }
}
