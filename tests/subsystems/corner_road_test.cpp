// Each wheel's own motion logged against time (a four-corner time road): the layouts and their
// errors, the heights read back at each wheel's own time (the rear without the wheelbase's lag),
// an acceleration integrated twice against its closed form, and the road's corners against
// its columns; an ordinary road's corners read their tracks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "subsystems/road.hpp"
#include "subsystems/time_road.hpp"
#include "time_road_util.hpp"

using namespace dtwin;

namespace {
using dtwin_test::kPi;
std::string errorOf(const std::string& text) { return dtwin_test::timeRoadError(text); }
/// Each wheel's height at time t: a different sum of sines per corner.
double wheel(int c, double t) {
  return 1e-3 * (std::sin(2 * kPi * (0.7 + 0.4 * c) * t + c) + 0.3 * std::cos(2 * kPi * 3.1 * t));
}
}  // namespace

TEST(CornerRoad, ParsesTheFourCornerLayouts) {
  auto h = parseTimeRoadCsv("time_s,fl_mm,fr_mm,rl_mm,rr_mm\n0,1,2,3,4\n0.01,5,6,7,8\n", "h.csv");
  EXPECT_TRUE(h.four_corners);
  EXPECT_FALSE(h.identical_tracks);
  EXPECT_EQ(h.form, TimeRoadLog::Form::Height);
  EXPECT_DOUBLE_EQ(h.left[1], 0.005);
  EXPECT_DOUBLE_EQ(h.right[1], 0.006);
  EXPECT_DOUBLE_EQ(h.rear_left[1], 0.007);
  EXPECT_DOUBLE_EQ(h.rear_right[1], 0.008);
  auto v = parseTimeRoadCsv("time_s,fl_mps,fr_mps,rl_mps,rr_mps\n0,1,2,3,4\n1,5,6,7,8\n", "v.csv");
  EXPECT_EQ(v.form, TimeRoadLog::Form::Velocity);
  auto a =
      parseTimeRoadCsv("time_s,fl_mps2,fr_mps2,rl_mps2,rr_mps2\n0,1,2,3,4\n1,5,6,7,8\n", "a.csv");
  EXPECT_EQ(a.form, TimeRoadLog::Form::Acceleration);
  EXPECT_DOUBLE_EQ(a.rear_right[0], 4.0);
  // A two-track log has no rear columns.
  auto b = parseTimeRoadCsv("time_s,left_m,right_m\n0,0.1,0.2\n1,0.3,0.4\n", "b.csv");
  EXPECT_FALSE(b.four_corners);
  EXPECT_TRUE(b.rear_left.empty());
}

TEST(CornerRoad, BadFourCornerFilesNameTheLineAndColumn) {
  EXPECT_NE(errorOf("time_s,fl_m,fr_m,rl_m,rr_m\n0,1,2,3,4\n0.1,1,2,x,4\n")
                .find("road.csv:3: rl_m: 'x' is not a finite number"),
            std::string::npos);
  EXPECT_NE(errorOf("time_s,fl_mps2,fr_mps2,rl_mps2,rr_mps2\n0,1,2,3,inf\n")
                .find("road.csv:2: rr_mps2: 'inf' is not a finite number"),
            std::string::npos);
  EXPECT_NE(errorOf("time_s,fl_m,fr_m,rl_m,rr_m\n0,1,2,3\n").find("road.csv:2: expected 5 columns"),
            std::string::npos);
  // Mixed or missing corners are not a layout: the header error lists the four-corner ones.
  const std::string e = errorOf("time_s,fl_m,fr_m,rl_m,rr_mm\n0,1,2,3,4\n1,1,2,3,4\n");
  EXPECT_NE(e.find("road.csv:1: header must be"), std::string::npos) << e;
  EXPECT_NE(e.find("fl_mps2"), std::string::npos) << e;
  EXPECT_NE(errorOf("time_s,fl_m,fr_m,rl_m\n0,1,2,3\n1,1,2,3\n").find("header must be"),
            std::string::npos);
}

// Heights at 100 Hz, 10 m/s: each wheel reads its own column at its own time (a rear wheel at
// time t sits at distance(t) − wheelbase and reads its sample of time t), at the nodes exactly.
TEST(CornerRoad, EachWheelReadsItsOwnColumnAtItsOwnTime) {
  const double v = 10.0, wb = 2.5, dt = 0.01;
  TimeRoadLog log;
  log.four_corners = true;
  log.name = "four.csv";
  for (int k = 0; k <= 300; ++k) {
    const double t = k * dt;
    log.t_s.push_back(t);
    log.left.push_back(wheel(0, t));
    log.right.push_back(wheel(1, t));
    log.rear_left.push_back(wheel(2, t));
    log.rear_right.push_back(wheel(3, t));
  }
  TimeRoadOptions o;
  o.x_from_m = -wb - 1.0;  // as the csv_time road lays it out; v dt = 5 dx: samples on nodes
  const auto road =
      cornerRoadFromTimeLog(log, [v](double t) { return v * t; }, wb, o, {{"type", "test"}});
  double worst = 0;
  for (int k = 0; k <= 300; ++k) {
    const double t = k * dt;
    for (int c = 0; c < 4; ++c) {
      const double x = v * t - (c < 2 ? 0.0 : wb);
      worst = std::max(worst, std::abs(road->sampleAt(c, x).height_m - wheel(c, t)));
    }
  }
  EXPECT_LT(worst, 1e-15);
  // Between the nodes the interpolant stays near each wheel's own signal (200 samples per period
  // of its fastest content).
  double between = 0;
  for (double t = 0.2; t < 2.8; t += 0.0037)
    for (int c = 0; c < 4; ++c)
      between = std::max(
          between, std::abs(road->sampleAt(c, v * t - (c < 2 ? 0.0 : wb)).height_m - wheel(c, t)));
  EXPECT_LT(between, 1e-6);
  // sample(track) is the front wheel of that side.
  for (double x : {0.0, 3.3, 17.2}) {
    EXPECT_EQ(road->sample(Track::Left, x).height_m, road->sampleAt(0, x).height_m);
    EXPECT_EQ(road->sample(Track::Right, x).slope, road->sampleAt(1, x).slope);
  }
  // A corner's view (what a tire-input effect reads) is that corner on both tracks.
  const CornerView rl(*road, 2);
  EXPECT_EQ(rl.sample(Track::Right, 4.0).height_m, road->sampleAt(2, 4.0).height_m);
  EXPECT_EQ(rl.sampleAveraged(Track::Left, 4.0, 0.3).height_m,
            (road->integralAt(2, 4.0 + 0.5 * 0.3) - road->integralAt(2, 4.0 - 0.5 * 0.3)) / 0.3);
}

// a(t) = −A ω² sin(ωt), integrated twice (the eight-point quadrature, each integration's drift
// removed by the zero-phase high-pass at fc = 0.1 Hz, ω/2π = 2 Hz): A sin(ωt) times the
// high-pass's gain twice, ((f/fc)² / (1 + (f/fc)²))² = 0.99503, within 1e-4 A once the
// filter's start has decayed (25 s = 15.7 time constants from either end of a 60 s log).
TEST(CornerRoad, AnAccelerationIntegratesTwiceToItsHeight) {
  const double A = 0.01, f = 2.0, w = 2 * kPi * f, fc = 0.1, v = 10.0, wb = 2.5;
  TimeRoadLog log;
  log.form = TimeRoadLog::Form::Acceleration;
  log.four_corners = true;
  log.name = "acc.csv";
  for (int k = 0; k <= 6000; ++k) {
    const double t = 0.01 * k, a = -A * w * w * std::sin(w * t);
    log.t_s.push_back(t);
    for (auto* col : {&log.left, &log.right, &log.rear_left, &log.rear_right}) col->push_back(a);
  }
  TimeRoadOptions o;
  o.highpass_hz = fc;
  o.x_from_m = -wb - 1.0;
  const auto road =
      cornerRoadFromTimeLog(log, [v](double t) { return v * t; }, wb, o, {{"type", "test"}});
  const double r = (f / fc) * (f / fc), gain = (r / (1 + r)) * (r / (1 + r));
  double worst = 0;
  for (double t = 25.0; t <= 35.0; t += 0.013)
    for (int c = 0; c < 4; ++c) {
      const double h = road->sampleAt(c, v * t - (c < 2 ? 0.0 : wb)).height_m;
      worst = std::max(worst, std::abs(h - gain * A * std::sin(w * t)));
    }
  std::printf("twice-integrated sine: worst |h - G A sin| = %.3g A\n", worst / A);
  EXPECT_LT(worst, 1e-4 * A);
}

// Every road but the four-corner one reads a corner's track, bit for bit.
TEST(CornerRoad, AnOrdinaryRoadsCornersReadTheirTracks) {
  std::vector<double> l, r;
  for (int i = 0; i < 200; ++i) {
    l.push_back(1e-2 * std::sin(0.1 * i));
    r.push_back(1e-2 * std::cos(0.07 * i));
  }
  const GridRoad grid(-1.0, 0.05, l, r, {{"type", "test"}});
  const BumpRoad bump(1.0, 0.1, 0.5);
  for (const Road* road : {static_cast<const Road*>(&grid), static_cast<const Road*>(&bump)})
    for (int c = 0; c < 4; ++c)
      for (double x = -2.0; x < 12.0; x += 0.0137) {
        const RoadSample a = road->sampleAt(c, x), b = road->sample(cornerTrack(c), x);
        EXPECT_EQ(a.height_m, b.height_m);
        EXPECT_EQ(a.slope, b.slope);
        EXPECT_EQ(road->integralAt(c, x), road->integral(cornerTrack(c), x));
      }
}
