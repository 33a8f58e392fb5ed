// diagnosis/signal: every check is against a closed form (Parseval, white-noise PSD 2σ²/fs,
// coherence 1/(1 + noise/signal), exact linear maps, injected signatures and bursts).
#include "diagnosis/signal.hpp"

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace {

using namespace dtwin::diag;
constexpr double kPi = 3.14159265358979323846;

std::vector<double> whiteNoise(size_t n, double sigma, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> nd(0.0, sigma);
  std::vector<double> x(n);
  for (double& v : x) v = nd(rng);
  return x;
}

std::vector<double> sine(size_t n, double amplitude, double f0, double fs, double phase = 0.3) {
  std::vector<double> x(n);
  for (size_t i = 0; i < n; ++i) x[i] = amplitude * std::sin(2 * kPi * f0 * i / fs + phase);
  return x;
}

std::vector<double> add(std::vector<double> a, const std::vector<double>& b) {
  for (size_t i = 0; i < a.size(); ++i) a[i] += b[i];
  return a;
}

double variance(const std::vector<double>& x) {
  double m = 0, s = 0;
  for (double v : x) m += v;
  m /= x.size();
  for (double v : x) s += (v - m) * (v - m);
  return s / x.size();
}

void expectInvalid(const std::function<void()>& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no exception, expected one mentioning '" << fragment << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Signal, SinePsdIntegratesToHalfSquaredAmplitudeAndPeaksAtItsFrequency) {
  const double fs = 200, A = 2.0, f0 = 10.0;
  const Spectrum s = welchPsd(sine(24000, A, f0, fs), fs, 512);
  ASSERT_EQ(s.freq_hz.size(), 257u);
  EXPECT_DOUBLE_EQ(s.freq_hz.back(), fs / 2);
  EXPECT_NEAR(bandIntegral(s, 0, fs / 2), A * A / 2, 0.01 * A * A / 2);
  size_t peak = 0;
  for (size_t k = 0; k < s.value.size(); ++k)
    if (s.value[k] > s.value[peak]) peak = k;
  EXPECT_NEAR(s.freq_hz[peak], f0, fs / 512);
  // Almost all of it within ±1 Hz of f0 (Hann main lobe = ±2 bins).
  EXPECT_GT(bandIntegral(s, f0 - 1, f0 + 1), 0.99 * A * A / 2);
}

TEST(Signal, WhiteNoisePsdIsTwoSigmaSquaredOverFs) {
  const double fs = 200, sigma = 0.5;
  const Spectrum s = welchPsd(whiteNoise(1 << 17, sigma, 1), fs, 256);
  EXPECT_NEAR(bandMean(s, 5, 95), 2 * sigma * sigma / fs, 0.03 * 2 * sigma * sigma / fs);
  EXPECT_TRUE(std::isnan(bandMean(s, 150, 160)));
  EXPECT_EQ(bandIntegral(s, 150, 160), 0.0);
}

TEST(Signal, ParsevalAndBandAdditivity) {
  const double fs = 200;
  std::vector<double> ar = whiteNoise(1 << 17, 1.0, 2);
  for (size_t i = 1; i < ar.size(); ++i) ar[i] += 0.5 * ar[i - 1];  // AR(1), coloured
  const std::vector<double> x = add(add(ar, sine(ar.size(), 1.5, 23.3, fs)), whiteNoise(ar.size(), 0.7, 3));
  const Spectrum s = welchPsd(x, fs, 1024);
  const double total = bandIntegral(s, 0, fs / 2);
  EXPECT_NEAR(total, variance(x), 0.01 * variance(x));
  double parts = bandIntegral(s, 0, 0.5);
  for (const Band& b : vehicleBands(fs)) parts += bandIntegral(s, b.lo_hz, b.hi_hz);
  EXPECT_NEAR(parts, total, 1e-12 * total);
}

TEST(Signal, SegmentIsClampedToTheRecord) {
  const Spectrum s = welchPsd(whiteNoise(101, 1.0, 4), 10, 4096);  // L = 100 (even), one segment
  EXPECT_EQ(s.freq_hz.size(), 51u);
  EXPECT_DOUBLE_EQ(s.freq_hz[1], 0.1);
}

TEST(Signal, CoherenceClosedForms) {
  const double fs = 200;
  const size_t n = 1 << 17;
  const std::vector<double> x = whiteNoise(n, 1.0, 5), e = whiteNoise(n, 1.0, 6);
  // y = x + e with var e = var x: |Pxy|² / (Pxx Pyy) = Pxx² / (Pxx · 2Pxx) = 1/2.
  EXPECT_NEAR(bandMean(coherence(x, add(x, e), fs, 512), 1, 99), 0.5, 0.03);
  const Spectrum self = coherence(x, x, fs, 512);
  for (size_t k = 0; k < self.value.size(); ++k) EXPECT_NEAR(self.value[k], 1.0, 1e-9) << k;
  // Independent: only the estimator's bias floor ≈ 1/K (K = 511 here).
  const double indep = bandMean(coherence(x, e, fs, 512), 1, 99);
  EXPECT_LT(indep, 0.01);
  EXPECT_GT(indep, 0.0);
}

TEST(Signal, VehicleBandsAreClippedAtNyquist) {
  const auto b = vehicleBands(100);
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[0].name, "body");
  EXPECT_EQ(b[2].name, "wheel_hop");
  EXPECT_EQ(b[3].name, "high");
  EXPECT_DOUBLE_EQ(b[3].hi_hz, 50);
  const auto c = vehicleBands(30);  // Nyquist 15 Hz: wheel hop clipped, high gone
  ASSERT_EQ(c.size(), 3u);
  EXPECT_DOUBLE_EQ(c[2].hi_hz, 15);
}

TEST(Signal, BandAnalysisFlagsOnlyTheBandWithAMissingSinusoid) {
  const double fs = 200, sigma = 0.1;
  const size_t n = 60000;
  const std::vector<double> input = sine(n, 1.0, 5.0, fs);
  std::vector<double> r = whiteNoise(n, sigma, 7);
  for (size_t i = 0; i < n; ++i) r[i] += 0.05 * input[i];  // residual power 0.05²/2 in "mid"
  const auto rep = bandAnalysis(r, fs, sigma * sigma, &input, 1024);
  ASSERT_EQ(rep.size(), 4u);
  for (const BandReport& b : rep) {
    EXPECT_NEAR(b.noise_power, 2 * sigma * sigma / fs * (b.hi_hz - b.lo_hz), 2 * sigma * sigma / fs * 0.2) << b.band;
    EXPECT_EQ(b.significant, b.band == "mid") << b.band << " ratio " << b.ratio;
    EXPECT_GE(b.coherence, 0.0);
    EXPECT_LE(b.coherence, 1.0);
  }
  EXPECT_NEAR(rep[1].residual_power - rep[1].noise_power, 0.05 * 0.05 / 2, 0.2 * 0.05 * 0.05 / 2);
  EXPECT_GT(rep[1].coherence, 3 * rep[0].coherence);
  EXPECT_NEAR(rep[3].ratio, 1.0, 0.05);  // 80 Hz of white noise: ratio ≈ 1
  EXPECT_TRUE(std::isnan(bandAnalysis(r, fs, sigma * sigma, nullptr, 1024)[0].coherence));
  // The noise variance too small by 30 %: all bands flagged.
  for (const BandReport& b : bandAnalysis(r, fs, 0.7 * sigma * sigma, nullptr, 1024)) EXPECT_TRUE(b.significant) << b.band;
}

TEST(Signal, BandAnalysisFalseAlarmRateOnWhiteNoiseIsSmall) {
  const double fs = 200, sigma = 0.3;
  int flagged = 0, tests = 0;
  double mean_ratio = 0;
  for (uint64_t seed = 100; seed < 150; ++seed) {
    for (const BandReport& b : bandAnalysis(whiteNoise(30000, sigma, seed), fs, sigma * sigma, nullptr, 1024, 0.01)) {
      flagged += b.significant;
      mean_ratio += b.ratio;
      ++tests;
    }
  }
  EXPECT_EQ(tests, 200);
  EXPECT_NEAR(mean_ratio / tests, 1.0, 0.03);
  EXPECT_LE(flagged, 6) << "false alarms over 200 band tests at alpha = 0.01 (expected 2)";
}

TEST(Signal, BinByStateHasEqualCountsAndReproducesALinearMap) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> q(1003), r(1003);
  for (size_t i = 0; i < q.size(); ++i) q[i] = u(rng), r[i] = 2.0 + 3.0 * q[i];
  const auto bins = binByState(q, r, 10);
  ASSERT_EQ(bins.size(), 10u);
  long total = 0;
  for (size_t b = 0; b < bins.size(); ++b) {
    EXPECT_TRUE(bins[b].count == 100 || bins[b].count == 101) << bins[b].count;
    total += bins[b].count;
    EXPECT_NEAR(bins[b].mean, 2.0 + 3.0 * bins[b].centre, 1e-12);
    EXPECT_LE(bins[b].lo, bins[b].centre);
    EXPECT_GE(bins[b].hi, bins[b].centre);
    if (b) {
      EXPECT_LE(bins[b - 1].hi, bins[b].lo);
    }
  }
  EXPECT_EQ(total, 1003);
  // Noisy residual: the standard error is σ/√n.
  const std::vector<double> noise = whiteNoise(20000, 0.5, 9);
  std::vector<double> s(20000);
  for (size_t i = 0; i < s.size(); ++i) s[i] = u(rng);
  for (const Bin& b : binByState(s, noise, 4)) {
    EXPECT_EQ(b.count, 5000);
    EXPECT_NEAR(b.se, 0.5 / std::sqrt(5000.0), 0.1 * 0.5 / std::sqrt(5000.0));
    EXPECT_NEAR(b.mean, 0.0, 4 * b.se);
  }
}

TEST(Signal, DeflectionSignatures) {
  const size_t n = 20000;
  const std::vector<double> q = whiteNoise(n, 0.02, 10), e = whiteNoise(n, 0.5, 11);
  const double g = 0.015, k = 1e5;
  std::vector<double> r(n);
  for (size_t i = 0; i < n; ++i) r[i] = k * std::pow(std::max(q[i] - g, 0.0), 2) + e[i];
  const auto fits = fitDeflectionSignatures(q, r);
  ASSERT_EQ(fits.size(), 3u);
  EXPECT_EQ(fits[0].feature, "knee");
  EXPECT_NEAR(fits[0].knee_at, g, 0.002);
  EXPECT_NEAR(fits[0].coefficient, k, 0.1 * k);
  EXPECT_GT(fits[0].explained_fraction, fits[1].explained_fraction);
  EXPECT_TRUE(std::isnan(fits[1].knee_at));

  for (size_t i = 0; i < n; ++i) r[i] = 1e6 * q[i] * q[i] * q[i] + e[i];
  const auto cubic = fitDeflectionSignatures(q, r);
  EXPECT_EQ(cubic[0].feature, "cubic");
  EXPECT_NEAR(cubic[0].coefficient, 1e6, 0.02e6);
  EXPECT_GT(cubic[0].explained_fraction, 0.95);
}

TEST(Signal, RateSignatures) {
  const size_t n = 20000;
  const std::vector<double> v = whiteNoise(n, 0.3, 12), e = whiteNoise(n, 10.0, 13);
  std::vector<double> r(n);
  for (size_t i = 0; i < n; ++i) r[i] = 200.0 * ((v[i] > 0) - (v[i] < 0)) + e[i];  // Coulomb friction
  const auto coulomb = fitRateSignatures(v, r);
  ASSERT_EQ(coulomb.size(), 4u);
  EXPECT_EQ(coulomb[0].feature, "step");
  EXPECT_NEAR(coulomb[0].coefficient, 200, 10);
  EXPECT_GT(coulomb[0].explained_fraction, 0.95);

  for (size_t i = 0; i < n; ++i) r[i] = 1500.0 * (v[i] < 0 ? v[i] : 0.0) + e[i];  // rebound damping error
  const auto rebound = fitRateSignatures(v, r);
  EXPECT_EQ(rebound[0].feature, "rebound_slope");
  EXPECT_NEAR(rebound[0].coefficient, 1500, 30);
  EXPECT_GT(rebound[0].explained_fraction, rebound[1].explained_fraction + 0.05);
}

TEST(Signal, ExceedanceWindowsFindMergeAndDrop) {
  const size_t n = 2001;
  std::vector<double> t(n), z(n, 0.1);
  for (size_t i = 0; i < n; ++i) t[i] = i / 100.0;
  for (size_t i = 300; i < 350; ++i) z[i] = 5.0;     // burst 1: 3.00–3.49 s
  for (size_t i = 1200; i < 1300; ++i) z[i] = -4.0;  // burst 2: 12.00–12.99 s, peak 6
  z[1250] = -6.0;
  for (size_t i = 500; i < 510; ++i) z[i] = 3.5;  // two runs 0.06 s apart: merged into 5.00–5.24 s
  for (size_t i = 515; i < 525; ++i) z[i] = 3.5;
  z[1500] = 9.0;                                  // single-sample spike: dropped
  for (size_t i = 1700; i < 1705; ++i) z[i] = 4;  // 0.04 s: dropped
  double total = 0;
  for (double v : z) total += v * v;

  const auto w = exceedanceWindows(t, z, 3.0, 0.2, 0.1);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_DOUBLE_EQ(w[0].t_begin, 3.00);
  EXPECT_DOUBLE_EQ(w[0].t_end, 3.49);
  EXPECT_DOUBLE_EQ(w[0].peak_z, 5.0);
  EXPECT_NEAR(w[0].share, 50 * 25.0 / total, 1e-12);
  EXPECT_DOUBLE_EQ(w[1].t_begin, 5.00);
  EXPECT_DOUBLE_EQ(w[1].t_end, 5.24);
  EXPECT_NEAR(w[1].share, (20 * 3.5 * 3.5 + 5 * 0.01) / total, 1e-12);  // includes the 5 gap samples
  EXPECT_DOUBLE_EQ(w[2].t_begin, 12.00);
  EXPECT_DOUBLE_EQ(w[2].t_end, 12.99);
  EXPECT_DOUBLE_EQ(w[2].peak_z, 6.0);
  EXPECT_NEAR(w[2].share, (99 * 16.0 + 36.0) / total, 1e-12);
  // Without merging the close pair splits in two; with no minimum length the short ones stay.
  EXPECT_EQ(exceedanceWindows(t, z, 3.0, 0.0, 0.1).size(), 2u);  // the two 0.09 s halves are dropped
  EXPECT_EQ(exceedanceWindows(t, z, 3.0, 0.0, 0.0).size(), 6u);
}

TEST(Signal, BadInputsThrowWithAClearMessage) {
  const std::vector<double> x(64, 1.0), y(63, 1.0), t5(5, 0.0);
  expectInvalid([&] { welchPsd(x, 0.0, 16); }, "sampling frequency must be > 0");
  expectInvalid([&] { welchPsd(t5, 10.0, 16); }, "at least 8 samples");
  expectInvalid([&] { welchPsd(x, 10.0, 4); }, "segment must be >= 8");
  expectInvalid([&] { coherence(x, y, 10.0, 16); }, "same length, got 64 and 63");
  expectInvalid([&] { bandAnalysis(x, 10.0, 1.0, &y, 16); }, "same length");
  expectInvalid([&] { bandAnalysis(x, 10.0, 0.0, nullptr, 16); }, "noise variance must be > 0");
  expectInvalid([&] { bandAnalysis(x, -1.0, 1.0, nullptr, 16); }, "sampling frequency");
  expectInvalid([&] { vehicleBands(0.0); }, "sampling frequency");
  expectInvalid([&] { binByState(x, x, 0); }, "bins must be >= 1");
  expectInvalid([&] { binByState(x, y, 4); }, "same length");
  expectInvalid([&] { fitDeflectionSignatures(x, y); }, "same length");
  expectInvalid([&] { fitRateSignatures(t5, y); }, "same length");
  expectInvalid([&] { exceedanceWindows(x, y, 3, 0, 0); }, "same length");
  expectInvalid([&] { exceedanceWindows(x, x, 3, 0, 0); }, "strictly increasing");
  expectInvalid([&] { bandIntegral(Spectrum{{0, 1}, {1}}, 0, 1); }, "same length");
  expectInvalid([&] { bandIntegral(Spectrum{{0, 1}, {1, 1}}, 1, 0); }, "f_hi >= f_lo");
}

}  // namespace
