// Sensors where they are mounted: the exact kinematics of a chassis point, and the loggers'
// low-pass filters against their closed-form responses.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/errors.hpp"
#include "subsystems/sensor.hpp"

using namespace dtwin;

namespace {

// A smooth test motion: heave, pitch and roll as sinusoids of time.
struct Path {
  double h(double t) const { return 0.02 * std::sin(3.0 * t) + 0.5; }
  double th(double t) const { return 0.15 * std::sin(2.0 * t + 0.4); }
  double ph(double t) const { return -0.2 * std::cos(5.0 * t); }
  Motion motion(double (Path::*f)(double) const, double t) const {
    const double e = 1e-4;
    return {(this->*f)(t), ((this->*f)(t + e) - (this->*f)(t - e)) / (2 * e),
            ((this->*f)(t + e) - 2 * (this->*f)(t) + (this->*f)(t - e)) / (e * e)};
  }
  // The point's height from the rotation itself (Eigen), not from the formula under test.
  double height(double t, const std::array<double, 3>& p) const {
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(ph(t), Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(th(t), Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
    return h(t) + (R * Eigen::Vector3d(p[0], p[1], p[2]))(2);
  }
};
}  // namespace

// Position, velocity and acceleration of a chassis point agree with the rotation matrix and its
// numerical derivatives, at large angles where a small-angle formula would not.
TEST(Sensor, ChassisPointMotionIsTheExactKinematics) {
  const Path path;
  const std::array<double, 3> p{1.2, -0.7, 0.35};
  for (double t : {0.0, 0.3, 1.1, 2.5}) {
    const Motion m = chassisPointMotion(path.motion(&Path::h, t), path.motion(&Path::th, t),
                                        path.motion(&Path::ph, t), p);
    const double e = 1e-4;
    EXPECT_NEAR(m.q, path.height(t, p), 1e-12) << t;
    EXPECT_NEAR(m.qd, (path.height(t + e, p) - path.height(t - e, p)) / (2 * e), 1e-6) << t;
    EXPECT_NEAR(m.qdd,
                (path.height(t + e, p) - 2 * path.height(t, p) + path.height(t - e, p)) / (e * e),
                2e-4)
        << t;
  }
}

// The signs of the conventions: at level attitude and rest, a point forward of the centre of mass
// sees -x times the pitch acceleration (pitch positive nose down) and a point to the left +y times
// the roll acceleration (roll positive right side down).
TEST(Sensor, SignsFollowThePitchAndRollConventions) {
  const Motion heave{0, 0, 0.5}, pitch{0, 0, 2.0}, roll{0, 0, -3.0};
  const Motion m = chassisPointMotion(heave, pitch, roll, {1.5, 0.8, 0.0});
  EXPECT_DOUBLE_EQ(m.qdd, 0.5 - 1.5 * 2.0 + 0.8 * -3.0);
  EXPECT_LT(chassisPointMotion({}, {0.01, 0, 0}, {}, {1.0, 0, 0}).q,
            0.0);  // nose down: the front goes down
  EXPECT_LT(chassisPointMotion({}, {}, {0.01, 0, 0}, {0, -0.7, 0}).q, 0.0);  // right side down
}

// A wheel's height in chassis axes is the inverse of chassisPointMotion: for a point fixed in
// the chassis, it returns the point's own z and no rate, at large angles; for a point sliding
// along the chassis z axis, its z(t) and ż(t).
TEST(Sensor, ChassisAxisHeightInvertsThePointsWorldHeight) {
  const Path path;
  for (double t : {0.0, 0.3, 1.1, 2.5}) {
    const std::array<double, 3> p{1.4, 0.75, -0.28};
    const Motion world = chassisPointMotion(path.motion(&Path::h, t), path.motion(&Path::th, t),
                                            path.motion(&Path::ph, t), p);
    const Motion m = chassisAxisHeight(world, path.motion(&Path::h, t), path.motion(&Path::th, t),
                                       path.motion(&Path::ph, t), p[0], p[1]);
    EXPECT_NEAR(m.q, p[2], 1e-12) << t;
    EXPECT_NEAR(m.qd, 0.0, 1e-6) << t;
    // Sliding: z(t) = −0.28 + 0.05 sin 7t.
    auto zOf = [](double s) { return -0.28 + 0.05 * std::sin(7.0 * s); };
    auto worldOf = [&](double s) { return path.height(s, {p[0], p[1], zOf(s)}); };
    const double e = 1e-5;
    const Motion wz{worldOf(t), (worldOf(t + e) - worldOf(t - e)) / (2 * e), 0.0};
    const Motion s = chassisAxisHeight(wz, path.motion(&Path::h, t), path.motion(&Path::th, t),
                                       path.motion(&Path::ph, t), p[0], p[1]);
    EXPECT_NEAR(s.q, zOf(t), 1e-12) << t;
    EXPECT_NEAR(s.qd, 0.35 * std::cos(7.0 * t), 1e-5) << t;
  }
}

// First order, ramp input (linear between samples, so the step is exact): y = t − τ(1 − e^(−t/τ)).
TEST(Sensor, FirstOrderFilterIsExactForARamp) {
  const double rate = 1000.0, fc = 25.0, tau = 1.0 / (2 * kPi * fc);
  std::vector<double> u(500);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = static_cast<double>(k) / rate;
  const auto y = lowPass(u, rate, {1, fc});
  for (std::size_t k = 0; k < u.size(); k += 7) {
    const double t = static_cast<double>(k) / rate;
    EXPECT_NEAR(y[k], t - tau * (1 - std::exp(-t / tau)), 1e-12) << t;
  }
}

// Both orders in steady state on a sinusoid: amplitude |H(jω)| and phase arg H(jω), within the
// error of reading the sampled input as linear between samples: at most max|H| (ωh)²/8.
TEST(Sensor, FilterSteadyStateMatchesItsFrequencyResponse) {
  const double rate = 1000.0;
  for (const SensorFilter f :
       {SensorFilter{1, 20.0}, SensorFilter{2, 20.0}, SensorFilter{2, 8.0, 0.3}}) {
    for (double fin : {3.0, 20.0, 45.0}) {
      const double w = 2 * kPi * fin, wc = 2 * kPi * f.cutoff_hz;
      const std::complex<double> s(0.0, w);
      const std::complex<double> H = f.order == 1
                                         ? 1.0 / (1.0 + s / wc)
                                         : wc * wc / (s * s + 2.0 * f.damping * wc * s + wc * wc);
      std::vector<double> u(4000);
      for (std::size_t k = 0; k < u.size(); ++k) u[k] = std::sin(w * static_cast<double>(k) / rate);
      const auto y = lowPass(u, rate, f);
      double worst = 0.0;
      for (std::size_t k = 3000; k < u.size(); ++k) {
        const double t = static_cast<double>(k) / rate;
        worst = std::max(worst, std::abs(y[k] - std::abs(H) * std::sin(w * t + std::arg(H))));
      }
      const double peak = f.order == 2 && f.damping < 0.7
                              ? 1.0 / (2 * f.damping * std::sqrt(1 - f.damping * f.damping))
                              : 1.0;
      EXPECT_LT(worst, peak * std::pow(w / rate, 2) / 8)
          << "order " << f.order << ", fc " << f.cutoff_hz << ", input " << fin << " Hz";
    }
  }
}

// No filter: the input unchanged. A filter starts at rest at the first value.
TEST(Sensor, NoFilterPassesTheInputAndFiltersStartAtRest) {
  const std::vector<double> u = {3.0, 3.0, 3.0, 3.0};
  EXPECT_EQ(lowPass(u, 100.0, {}), u);
  for (double v : lowPass(u, 100.0, {2, 5.0})) EXPECT_NEAR(v, 3.0, 1e-12);
}

// Channels carry the unit suffix; bad specifications name the field.
TEST(Sensor, ChannelsAndValidation) {
  SensorSpec s;
  s.name = "seat";
  EXPECT_EQ(s.channel(), "seat_mps2");
  s.quantity = SensorQuantity::VelocityZ;
  EXPECT_EQ(s.channel(), "seat_mps");
  s.quantity = SensorQuantity::DisplacementZ;
  EXPECT_EQ(s.channel(), "seat_m");
  EXPECT_NO_THROW(s.validate("sensors.seat"));
  auto whereOf = [](SensorSpec x) {
    try {
      x.validate("sensors.x");
    } catch (const InputError& e) {
      return e.where();
    }
    return std::string("(accepted)");
  };
  SensorSpec b = s;
  b.name = "Seat";
  EXPECT_EQ(whereOf(b), "sensors.x");
  b = s;
  b.mount = "wheel_xx";
  EXPECT_EQ(whereOf(b), "sensors.x.body");
  b = s;
  b.mount = "wheel_rl";
  EXPECT_EQ(b.corner(), 2);
  EXPECT_EQ(whereOf(b), "(accepted)");
  b.position_m = {0.1, 0, 0};
  EXPECT_EQ(whereOf(b), "sensors.x.position_m");
  b = s;
  b.position_m = {NAN, 0, 0};
  EXPECT_EQ(whereOf(b), "sensors.x.position_m");
  b = s;
  b.filter = {3, 10.0};
  EXPECT_EQ(whereOf(b), "sensors.x.filter.order");
  b.filter = {1, 0.0};
  EXPECT_EQ(whereOf(b), "sensors.x.filter.cutoff_hz");
  b.filter = {2, 10.0, -1.0};
  EXPECT_EQ(whereOf(b), "sensors.x.filter.damping");
  b = s;
  b.noise_sd = -1;
  EXPECT_EQ(whereOf(b), "sensors.x.noise_sd");
  EXPECT_THROW(parseSensorQuantity("acceleration_x", "q"), InputError);
  EXPECT_EQ(parseSensorQuantity("velocity_z", "q"), SensorQuantity::VelocityZ);
}

// ------------------------------------------------------------------ sensor models (twin diagnose)

namespace {
std::vector<double> sampled(double (*f)(double), double rate, double t_end) {
  std::vector<double> v;
  for (int k = 0; k <= static_cast<int>(std::lround(t_end * rate)); ++k) v.push_back(f(k / rate));
  return v;
}
double wave(double t) { return std::sin(2 * kPi * 3.0 * t) + 0.3 * std::cos(2 * kPi * 7.0 * t); }
}  // namespace

TEST(SensorModel, OffIsTheIdentityExactlyOnTheGrid) {
  const double rate = 1000;
  const auto u = sampled(wave, rate, 2.0);
  std::vector<double> times;
  for (int k = 0; k < 2000; k += 5) times.push_back(k / rate);
  SensorDistortion d;
  for (const auto& kind : sensorModelKinds())
    d.set(kind, sensorModelParameter(kind, "t").default_value);
  EXPECT_TRUE(d.identity());
  const auto y = distortChannel(u, rate, times, d);
  for (std::size_t i = 0; i < times.size(); ++i)
    EXPECT_EQ(y[i], u[static_cast<std::size_t>(5 * i)]);
}

TEST(SensorModel, GainAndDelayAreTheScaledShiftedSignal) {
  const double rate = 1000, delay = 0.0123, gain = 1.17;  // the delay is off the grid
  const auto u = sampled(wave, rate, 2.0);
  SensorDistortion d;
  d.set("gain", gain);
  d.set("delay", delay);
  std::vector<double> times;
  for (double t = 0.1; t < 1.9; t += 0.0317) times.push_back(t);
  const auto y = distortChannel(u, rate, times, d);
  // Four-point cubic error bound: h⁴ max|u''''| 3/128 with |u''''| ≤ (2π·3)⁴ + 0.3 (2π·7)⁴.
  const double bound = std::pow(1 / rate, 4) *
                       (std::pow(2 * kPi * 3, 4) + 0.3 * std::pow(2 * kPi * 7, 4)) * 3.0 / 128.0;
  for (std::size_t i = 0; i < times.size(); ++i)
    EXPECT_NEAR(y[i], gain * wave(times[i] - delay), gain * bound + 1e-12) << times[i];
}

TEST(SensorModel, FirstOrderLowPassHasItsClosedFormSteadyState) {
  // u = sin ωt through 1/(1 + sτ): amplitude 1/√(1 + (ωτ)²), phase −atan(ωτ), after the transient
  // e^{−t/τ}.
  const double rate = 1000, f = 5.0, w = 2 * kPi * f, tau = 1.0 / (2 * kPi * 25.0);  // 25 Hz
  std::vector<double> u;
  for (int k = 0; k <= 3000; ++k) u.push_back(std::sin(w * k / rate));
  SensorDistortion d;
  d.set("lowpass", tau);
  EXPECT_EQ(d.filter.order, 1);
  EXPECT_NEAR(d.filter.cutoff_hz, 25.0, 1e-12);
  std::vector<double> times;
  for (int k = 2000; k <= 3000; k += 7) times.push_back(k / rate);
  const auto y = distortChannel(u, rate, times, d);
  const double amp = 1 / std::sqrt(1 + w * w * tau * tau), ph = -std::atan(w * tau);
  for (std::size_t i = 0; i < times.size(); ++i)
    EXPECT_NEAR(y[i], amp * std::sin(w * times[i] + ph), 1e-4);
}

TEST(SensorModel, UnknownKindIsAnInputErrorNamingTheKnownOnes) {
  try {
    sensorModelParameter("highpass", "here");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lowpass"), std::string::npos) << e.what();
  }
}
