// diagnosis/frequency_response: the H1 estimate and its stated random error against closed forms —
// a quarter car's analytic response to a random road, a pure gain and delay, the same on a
// jittering clock — and the test of measured against predicted: its false alarms at the level it
// states, and a gain error found.
#include "diagnosis/frequency_response.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

using namespace dtwin::diag;
using cd = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

double wrapDeg(double d) {
  while (d > 180) d -= 360;
  while (d <= -180) d += 360;
  return d;
}

// A quarter car: sprung mass ms on a strut (ks, cs) over an unsprung mass mu on a tire spring kt,
// the road height zr under the tire.
struct QuarterCar {
  double ms = 350, mu = 40, ks = 22000, cs = 1800, kt = 200000;
  /// Body acceleration over road height at s = j 2π f: s² kt B / (A C − B²), A = ms s² + B,
  /// B = cs s + ks, C = mu s² + B + kt.
  cd bodyAcceleration(double f_hz) const {
    const cd s(0.0, 2 * kPi * f_hz), B = cs * s + ks, A = ms * s * s + B, C = mu * s * s + B + kt;
    return s * s * kt * B / (A * C - B * B);
  }
};

// The quarter car driven by a random road: white noise (held over each step) through two
// second-order low-passes at 15 Hz (ζ = 0.707) makes the road height, all one linear ODE
// integrated by RK4 at 10 kHz; road height and body acceleration kept every 100th step (100 Hz),
// the acceleration with white noise of sd `noise_sd` added.
struct Drive {
  std::vector<double> road, accel;
};
Drive quarterCarDrive(const QuarterCar& q, double seconds, double noise_sd, std::uint64_t seed) {
  const double h = 1e-4, wf = 2 * kPi * 15.0, zf = 0.707;
  const int per_sample = 100;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> white(0.0, 1.0);
  using State = std::array<double, 8>;  // xs, vs, xu, vu, z1, z1', zr, zr'
  double w = 0;
  const auto rate = [&](const State& x) {
    const double strut = q.ks * (x[0] - x[2]) + q.cs * (x[1] - x[3]);
    return State{x[1], -strut / q.ms,
                 x[3], (strut - q.kt * (x[2] - x[6])) / q.mu,
                 x[5], wf * wf * (w - x[4]) - 2 * zf * wf * x[5],
                 x[7], wf * wf * (x[4] - x[6]) - 2 * zf * wf * x[7]};
  };
  const auto axpy = [](const State& x, double a, const State& k) {
    State y;
    for (int i = 0; i < 8; ++i) y[i] = x[i] + a * k[i];
    return y;
  };
  State x{};
  Drive d;
  // NOLINTNEXTLINE(bugprone-incorrect-roundings): seconds / h > 0, rounded half up
  const long steps = static_cast<long>(seconds / h + 0.5);
  const long warmup = 20000;  // 2 s for the filters' start to die away
  for (long n = -warmup; n < steps; ++n) {
    if (n >= 0 && n % per_sample == 0) {
      d.road.push_back(x[6]);
      d.accel.push_back(-(q.ks * (x[0] - x[2]) + q.cs * (x[1] - x[3])) / q.ms +
                        noise_sd * white(rng));
    }
    w = 0.01 * white(rng);
    const State k1 = rate(x), k2 = rate(axpy(x, h / 2, k1)), k3 = rate(axpy(x, h / 2, k2)),
                k4 = rate(axpy(x, h, k3));
    for (int i = 0; i < 8; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return d;
}

double sd(const std::vector<double>& x) {
  double m = 0, s = 0;
  for (double v : x) m += v;
  m /= x.size();
  for (double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / x.size());
}

TEST(FrfEstimate, QuarterCarOnARandomRoadMatchesItsAnalyticResponseWithinTheStatedError) {
  const QuarterCar q;
  const double fs = 100;
  Drive clean = quarterCarDrive(q, 300, 0.0, 7);
  const double noise = 0.1 * sd(clean.accel);
  const Drive d = quarterCarDrive(q, 300, noise, 7);
  ASSERT_EQ(d.road.size(), 30000u);
  const FrequencyResponse r = frequencyResponse(d.road, d.accel, fs, 1024);
  EXPECT_EQ(r.segments, 57);
  EXPECT_NEAR(r.averages / r.segments, 0.946,
              0.005);  // Hann at 50 % overlap: ν_W = 2K / (1 + 2 (1 − 1/K) / 36)
  int bins = 0, within_mag = 0, within_phase = 0;
  double z2 = 0;
  for (std::size_t k = 0; k < r.freq_hz.size(); ++k) {
    const double f = r.freq_hz[k];
    if (f < 0.5 || f > 25 || r.coherence[k] <= 0.5) continue;
    const cd H = q.bodyAcceleration(f);
    const double eps = r.magnitude_error[k];
    const double z =
        std::abs(r.h[k] - H) / (eps * std::abs(H));  // both parts of Ĥ − H have sd ε|H|
    ++bins;
    z2 += z * z;
    within_mag += std::abs(r.magnitude[k] - std::abs(H)) <= 3 * eps * std::abs(H);
    within_phase +=
        std::abs(wrapDeg(r.phase_deg[k] - std::arg(H) * 180 / kPi)) <= 3 * r.phase_sd_deg[k];
  }
  ASSERT_GT(bins, 200);  // 0.5–25 Hz at 0.098 Hz: about 250 bins, nearly all coherent
  EXPECT_GE(within_mag, 0.95 * bins) << within_mag << " of " << bins;
  EXPECT_GE(within_phase, 0.95 * bins) << within_phase << " of " << bins;
  // The stated error is neither too narrow nor absurdly wide: E|Ĥ − H|² = 2 ε²|H|².
  const double calibration = z2 / bins / 2;
  EXPECT_GT(calibration, 0.6) << calibration;
  EXPECT_LT(calibration, 1.6) << calibration;
  std::printf(
      "quarter car: %d bins with coherence > 0.5 in 0.5-25 Hz; magnitude within 3 sd: %d, phase: "
      "%d; "
      "mean |H^-H|^2/(2 eps^2 |H|^2) = %.3f\n",
      bins, within_mag, within_phase, calibration);
  // At the body mode and at wheel hop the estimate is close in plain numbers too.
  for (double f : {1.2, 11.9}) {
    const std::size_t k = static_cast<std::size_t>(std::lround(f / (fs / 1024)));
    EXPECT_NEAR(r.magnitude[k] / std::abs(q.bodyAcceleration(r.freq_hz[k])), 1.0, 0.05)
        << f << " Hz";
  }
}

TEST(FrfEstimate, APureGainAndDelayAreRecovered) {
  const double fs = 100, gain = 2.5;
  const int delay = 3;  // samples: 30 ms
  std::mt19937_64 rng(11);
  std::normal_distribution<double> white(0.0, 1.0);
  const std::size_t n = 20000;
  std::vector<double> u(n), y(n);
  for (double& v : u) v = white(rng);
  for (std::size_t i = 0; i < n; ++i)
    y[i] = (i >= delay ? gain * u[i - delay] : 0.0) + 0.1 * gain * white(rng);
  const FrequencyResponse r = frequencyResponse(u, y, fs, 256);
  // Gain: every bin but DC within 3 stated sd (plus the Hann segments' misalignment by 3 of 256
  // samples, 0.2 %); the delay from the unwrapped phase's least-squares slope through the origin.
  double sxy = 0, sxx = 0, prev = 0, turns = 0;
  int within = 0;
  for (std::size_t k = 1; k + 1 < r.freq_hz.size(); ++k) {
    within += std::abs(r.magnitude[k] / gain - 1) <= 3 * r.magnitude_error[k] + 0.002;
    const double p = r.phase_deg[k];
    if (k > 1 && p - prev > 180) turns -= 360;
    if (k > 1 && p - prev < -180) turns += 360;
    prev = p;
    const double unwrapped = (p + turns) * kPi / 180, w = 2 * kPi * r.freq_hz[k];
    sxy += w * unwrapped, sxx += w * w;
  }
  EXPECT_GE(within, 0.95 * (r.freq_hz.size() - 2));
  const double tau = -sxy / sxx;
  EXPECT_NEAR(tau, delay / fs, 2e-4) << tau;
  EXPECT_GT(r.coherence[20], 0.98);
  EXPECT_NEAR(r.magnitude_error[20],
              std::sqrt((1 - r.coherence[20]) / (2 * r.averages * r.coherence[20])), 1e-12);
}

// u(t), a sum of sinusoids 0.3–20 Hz with random phases, at any time.
struct Multisine {
  std::vector<double> f, a, phi;
  explicit Multisine(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ph(0, 2 * kPi);
    for (double x = 0.3; x < 20; x += 0.0731)
      f.push_back(x), a.push_back(0.01 / std::sqrt(1 + x * x / 25)), phi.push_back(ph(rng));
  }
  double operator()(double t) const {
    double s = 0;
    for (std::size_t j = 0; j < f.size(); ++j) s += a[j] * std::cos(2 * kPi * f[j] * t + phi[j]);
    return s;
  }
};

TEST(FrfEstimate, AJitteredClockIsResampledAndTheGainAndDelayStillRead) {
  const double dt = 0.01, gain = 0.8, tau = 0.02;
  const Multisine road(3);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jit(-0.3, 0.3);
  std::normal_distribution<double> white(0.0, 1.0);
  std::vector<double> t, u, measured, predicted, off;
  for (int i = 0; i < 8000; ++i) {
    t.push_back((i + jit(rng)) * dt);
    u.push_back(road(t.back()));
    predicted.push_back(gain * road(t.back() - tau));
    measured.push_back(predicted.back() + 2e-4 * white(rng));
    off.push_back(1.25 * predicted.back());
  }
  const SeriesResponse sr = seriesResponse(t, u, "road_fl_m", measured, predicted);
  ASSERT_TRUE(sr.computed) << sr.note;
  EXPECT_NE(sr.note.find("resampled to a uniform 100.0 Hz grid"), std::string::npos) << sr.note;
  const FrequencyResponse& m = sr.response.measured;
  int bins = 0, within = 0;
  for (std::size_t k = 0; k < m.freq_hz.size(); ++k) {
    const double f = m.freq_hz[k];
    if (f < 0.5 || f > 15) continue;
    ++bins;
    const bool gain_ok = std::abs(m.magnitude[k] / gain - 1) < 0.02;
    const bool phase_ok = std::abs(wrapDeg(m.phase_deg[k] + 360 * f * tau)) < 1.5;
    within += gain_ok && phase_ok;
  }
  EXPECT_GE(within, 0.95 * bins) << within << " of " << bins;
  // Predicted = the truth: every band's χ²₂ below its 99.9 % point (at 95 % one band in twenty
  // differs by chance). Predicted 25 % too large: every band up to 20 Hz differs, with the gain
  // ratio 0.8 inside its own 3 sd.
  ASSERT_EQ(sr.response.bands.size(), 4u);
  for (const auto& b : sr.response.bands) EXPECT_LT(b.chi2, -2 * std::log(0.001)) << b.band;
  const SeriesResponse wrong = seriesResponse(t, u, "road_fl_m", measured, off);
  for (const auto& b : wrong.response.bands) {
    if (b.lo_hz >= 20) continue;  // the multisine stops at 20 Hz
    EXPECT_TRUE(b.differs) << b.band;
    EXPECT_NEAR(b.gain_ratio, 0.8, 3 * 0.8 * b.gain_ratio_error + 1e-3) << b.band;
    EXPECT_NEAR(b.phase_difference_deg, 0.0, 3 * b.phase_difference_sd_deg + 0.1) << b.band;
  }
}

TEST(FrfEstimate, AgreeingResponsesDifferAtAboutTheStatedRate) {
  // Predicted: a filtered road; measured: the same plus white noise. Over 100 seeds the bins and
  // the bands flagged at 95 % should be about 5 %.
  const double fs = 100;
  long bins = 0, bins_flagged = 0, bands = 0, bands_flagged = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> white(0.0, 1.0);
    const std::size_t n = 6000;
    std::vector<double> u(n), p(n), m(n);
    double s1 = 0, s2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      u[i] = white(rng);
      s1 = 0.7 * s1 + u[i];
      s2 = 0.5 * s2 + s1;
      p[i] = s2 + 0.3 * (i ? u[i - 1] : 0.0);
      m[i] = p[i] + 0.5 * white(rng);
    }
    const ResponseComparison c = compareResponses(u, m, p, fs, 512);
    for (std::size_t k = 1; k < c.differs.size(); ++k) bins += 1, bins_flagged += c.differs[k];
    for (const auto& b : c.bands) bands += 1, bands_flagged += b.differs;
  }
  const double bin_rate = static_cast<double>(bins_flagged) / bins,
               band_rate = static_cast<double>(bands_flagged) / bands;
  std::printf("agreeing responses: %.2f %% of %ld bins and %.1f %% of %ld bands flagged at 95 %%\n",
              100 * bin_rate, bins, 100 * band_rate, bands);
  EXPECT_GT(bin_rate, 0.03);
  EXPECT_LT(bin_rate, 0.08);
  EXPECT_GT(band_rate, 0.015);
  EXPECT_LT(band_rate, 0.10);
}

TEST(FrfEstimate, SkipsWithANoteAndRefusesBadArguments) {
  std::vector<double> t(50), v(50, 1.0);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = 0.01 * i;
  EXPECT_EQ(seriesResponse(t, {}, "road_fl_m", v, v).note, "no frequency response: no road input");
  EXPECT_FALSE(seriesResponse(t, v, "road_fl_m", v, v).computed);
  EXPECT_EQ(seriesResponse(t, v, "road_fl_m", v, v).note,
            "no frequency response: fewer than 64 times");
  std::vector<double> t2(200), flat(200, 0.0), x(200);
  for (std::size_t i = 0; i < t2.size(); ++i) t2[i] = 0.01 * i, x[i] = std::sin(0.3 * i);
  const SeriesResponse s = seriesResponse(t2, flat, "road_fl_m", x, x);
  EXPECT_EQ(s.note, "no frequency response: the road input does not vary");
  EXPECT_EQ(s.toJson(), (nlohmann::json{{"input", "road_fl_m"}, {"note", s.note}}));
  EXPECT_THROW(compareResponses(x, x, flat, 100, 64, 1.0), std::invalid_argument);
  EXPECT_THROW(compareResponses(x, std::vector<double>(199), x, 100, 64), std::invalid_argument);
  EXPECT_THROW(frequencyResponse(x, x, 0.0, 64), std::invalid_argument);
  EXPECT_THROW(seriesResponse(t2, x, "road_fl_m", x, std::vector<double>(3)),
               std::invalid_argument);
}

}  // namespace
