// diagnosis/signal: every check is against a closed form (Parseval, white-noise PSD 2σ²/fs,
// coherence 1/(1 + noise/signal), exact linear maps, injected signatures and bursts).
#include "diagnosis/signal.hpp"

#include <cmath>
#include <cstdio>
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
  const std::vector<double> x =
      add(add(ar, sine(ar.size(), 1.5, 23.3, fs)), whiteNoise(ar.size(), 0.7, 3));
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
    EXPECT_NEAR(b.noise_power, 2 * sigma * sigma / fs * (b.hi_hz - b.lo_hz),
                2 * sigma * sigma / fs * 0.2)
        << b.band;
    EXPECT_EQ(b.significant, b.band == "mid") << b.band << " ratio " << b.ratio;
    EXPECT_GE(b.coherence, 0.0);
    EXPECT_LE(b.coherence, 1.0);
  }
  EXPECT_NEAR(rep[1].residual_power - rep[1].noise_power, 0.05 * 0.05 / 2, 0.2 * 0.05 * 0.05 / 2);
  EXPECT_GT(rep[1].coherence, 3 * rep[0].coherence);
  EXPECT_NEAR(rep[3].ratio, 1.0, 0.05);  // 80 Hz of white noise: ratio ≈ 1
  EXPECT_TRUE(std::isnan(bandAnalysis(r, fs, sigma * sigma, nullptr, 1024)[0].coherence));
  // The noise variance too small by 30 %: all bands flagged.
  for (const BandReport& b : bandAnalysis(r, fs, 0.7 * sigma * sigma, nullptr, 1024))
    EXPECT_TRUE(b.significant) << b.band;
}

TEST(Signal, BandAnalysisFalseAlarmRateOnWhiteNoiseIsSmall) {
  const double fs = 200, sigma = 0.3;
  int flagged = 0, tests = 0;
  double mean_ratio = 0;
  for (uint64_t seed = 100; seed < 150; ++seed) {
    for (const BandReport& b :
         bandAnalysis(whiteNoise(30000, sigma, seed), fs, sigma * sigma, nullptr, 1024, 0.01)) {
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
  for (size_t i = 0; i < n; ++i)
    r[i] = 200.0 * ((v[i] > 0) - (v[i] < 0)) + e[i];  // Coulomb friction
  const auto coulomb = fitRateSignatures(v, r);
  ASSERT_EQ(coulomb.size(), 4u);
  EXPECT_EQ(coulomb[0].feature, "step");
  EXPECT_NEAR(coulomb[0].coefficient, 200, 10);
  EXPECT_GT(coulomb[0].explained_fraction, 0.95);

  for (size_t i = 0; i < n; ++i)
    r[i] = 1500.0 * (v[i] < 0 ? v[i] : 0.0) + e[i];  // rebound damping error
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
  EXPECT_NEAR(w[1].share, (20 * 3.5 * 3.5 + 5 * 0.01) / total,
              1e-12);  // includes the 5 gap samples
  EXPECT_DOUBLE_EQ(w[2].t_begin, 12.00);
  EXPECT_DOUBLE_EQ(w[2].t_end, 12.99);
  EXPECT_DOUBLE_EQ(w[2].peak_z, 6.0);
  EXPECT_NEAR(w[2].share, (99 * 16.0 + 36.0) / total, 1e-12);
  // Without merging the close pair splits in two; with no minimum length the short ones stay.
  EXPECT_EQ(exceedanceWindows(t, z, 3.0, 0.0, 0.1).size(),
            2u);  // the two 0.09 s halves are dropped
  EXPECT_EQ(exceedanceWindows(t, z, 3.0, 0.0, 0.0).size(), 6u);
}

// rankWindows: few windows are all listed, largest share first; many are merged (never into a
// window longer than 2 span / max_merged) and only the fewest holding listed_share are listed.
TEST(Signal, RankWindowsListsFewAsTheyAreAndCutsManyToTheLargest) {
  const size_t n = 10000;
  std::vector<double> t(n), z(n, 0.5);
  for (size_t i = 0; i < n; ++i) t[i] = i / 100.0;  // 0–99.99 s
  // Five windows of one sample each, |z| 5, 9, 6, 8, 7 in time order.
  const double peaks[] = {5, 9, 6, 8, 7};
  for (int k = 0; k < 5; ++k) z[1000 + 1000 * k] = (k % 2 ? -1 : 1) * peaks[k];
  double total = 0;
  for (double v : z) total += v * v;
  const WindowRanking few = rankWindows(t, z, 4.0, 0.05, 0.0);
  ASSERT_EQ(few.found.size(), 5u);
  EXPECT_EQ(few.summary.found, 5u);
  EXPECT_EQ(few.summary.merged, 5u);
  EXPECT_EQ(few.summary.listed, 5u);
  EXPECT_DOUBLE_EQ(few.summary.merge_gap_s, 0.05);
  EXPECT_DOUBLE_EQ(few.found[1].t_begin, 20.0);  // chronological
  const double order[] = {9, 8, 7, 6, 5};
  for (int k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(few.ranked[k].peak_z, order[k]) << k;
    EXPECT_NEAR(few.ranked[k].share, order[k] * order[k] / total, 1e-12);
  }
  EXPECT_NEAR(few.summary.time_share, 5.0 / n, 1e-15);
  EXPECT_NEAR(few.summary.listed_share, (81 + 64 + 49 + 36 + 25) / total, 1e-12);
  // The same windows found by exceedanceWindows.
  const auto ex = exceedanceWindows(t, z, 4.0, 0.05, 0.0);
  ASSERT_EQ(ex.size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_DOUBLE_EQ(ex[k].share, few.found[k].share);

  // 60 windows, every 1.6 s: more than max_listed (5), so only the fewest holding 80 % of their
  // share are listed; with max_merged = 10 the gap doubles until at most 10 remain, none longer
  // than 2 × 99.99 / 10 s.
  std::vector<double> z2(n, 0.5);
  for (int k = 0; k < 60; ++k) z2[50 + 160 * k] = 5.0;
  z2[50 + 160 * 30] = 40.0;  // one window holds most of it
  // The large window holds 1600 of 5560 (29 %), the 59 others 25 each (0.45 %): half of the
  // windows' share (55 %) is held by the large one alone; 80 % would need 36, capped at 5.
  const WindowRanking many = rankWindows(t, z2, 4.0, 0.05, 0.0, {100, 5, 0.5});
  EXPECT_EQ(many.summary.found, 60u);
  EXPECT_EQ(many.summary.merged, 60u) << "at most 100: not merged";
  EXPECT_DOUBLE_EQ(many.ranked[0].peak_z, 40.0);
  double all = 0;
  for (const auto& w : many.ranked) all += w.share;
  EXPECT_NEAR(many.summary.merged_share, all, 1e-12);
  EXPECT_NEAR(all, (1600 + 59 * 25) / 5560.0, 1e-12);
  EXPECT_EQ(many.summary.listed, 1u);
  EXPECT_NEAR(many.summary.listed_share, 1600 / 5560.0, 1e-12);
  const WindowRanking capped = rankWindows(t, z2, 4.0, 0.05, 0.0, {100, 5, 0.8});
  EXPECT_EQ(capped.summary.listed, 5u);
  EXPECT_NEAR(capped.summary.listed_share, (1600 + 4 * 25) / 5560.0, 1e-12);
  const double held = capped.summary.listed_share;
  const WindowRanking merged = rankWindows(t, z2, 4.0, 0.05, 0.0, {10, 5, 0.8});
  EXPECT_LE(merged.summary.merged, 11u);
  EXPECT_LT(merged.summary.merged, 60u);
  EXPECT_GT(merged.summary.merge_gap_s, 1.5);  // the windows are 1.6 s apart
  for (const auto& w : merged.ranked) EXPECT_LE(w.t_end - w.t_begin, 2 * 99.99 / 10 + 1e-9);
  double sum = 0;
  for (const auto& w : merged.ranked) sum += w.share;
  EXPECT_GT(sum, held) << "a merged window holds the samples between its parts";
  EXPECT_NEAR(merged.summary.time_share, 60.0 / n, 1e-15) << "counted on the found windows";
}

// A clock whose offset against the grid sweeps evenly across the step (a triangle wave of one
// step over 4000 samples): the grid times fall evenly across the steps, so linear interpolation
// keeps sinc²(f dt) of a sinusoid's amplitude (its mean gain) and (2 + cos 2πf dt)/3 of its power
// (the mean of |gain|², the band's power): the closed forms of docs/diagnosis.md.
TEST(Signal, LinearResamplingKeepsSincSquaredOfASinusoid) {
  const double h = 1.0 / 110, A = 2.0;
  const size_t n = 100000, P = 4000;
  std::vector<double> t(n);
  for (size_t i = 0; i < n; ++i)
    t[i] = (i + std::abs(std::fmod(static_cast<double>(i) / P, 1.0) * 2 - 1)) * h;
  const UniformGrid g = uniformGrid(t);
  EXPECT_TRUE(g.resampled);
  EXPECT_TRUE(g.steady);
  EXPECT_EQ(g.gaps, 0u);
  EXPECT_EQ(g.size(), n);
  EXPECT_NEAR(g.dt, h, 1e-7 * h);
  EXPECT_NEAR(g.jitter, 2.0 / P, 1e-6);
  for (const auto& [f, band] : std::vector<std::pair<double, std::string>>{
           {5.0, "mid"}, {15.0, "wheel_hop"}, {40.0, "high"}}) {
    std::vector<double> x(n);
    for (size_t i = 0; i < n; ++i) x[i] = A * std::sin(2 * kPi * f * t[i] + 0.3);
    const std::vector<double> y = onGrid(g, x);
    ASSERT_EQ(y.size(), n);
    // The coherent amplitude: the projection on the sinusoid at the grid times.
    double c = 0, s = 0;
    for (size_t k = 0; k < n; ++k) {
      const double tau = t[0] + k * g.dt;
      c += y[k] * std::cos(2 * kPi * f * tau), s += y[k] * std::sin(2 * kPi * f * tau);
    }
    const double amplitude = 2.0 / n * std::hypot(c, s);
    const double x_ = kPi * f * h, sinc2 = std::pow(std::sin(x_) / x_, 2);
    EXPECT_NEAR(amplitude / A, sinc2, 1e-3) << f << " Hz";
    EXPECT_GT(1.0 - sinc2, 0.005) << "the loss itself is well above the tolerance";
    // The band's power in the Welch spectrum, and the band it lands in.
    const Spectrum psd = welchPsd(y, 1.0 / g.dt, 1024);
    const double power = (2.0 + std::cos(2 * kPi * f * h)) / 3.0 * A * A / 2;
    std::string best;
    double most = 0;
    for (const Band& b : vehicleBands(1.0 / g.dt)) {
      const double p = bandIntegral(psd, b.lo_hz, b.hi_hz);
      if (p > most) most = p, best = b.name;
    }
    EXPECT_EQ(best, band) << f << " Hz";
    EXPECT_NEAR(most / power, 1.0, 0.01) << f << " Hz";
  }
}

// White noise at times jittered by ±30 % of a step: resampled, its spectrum is no longer white
// (interpolation averages neighbours); with the noise's own autocorrelation on the grid the floor
// matches it in every band, while the white floor would call the high band far below the noise.
TEST(Signal, ResampledWhiteNoiseMatchesItsInterpolatedFloor) {
  const double h = 1.0 / 110, sigma = 0.5;
  const size_t n = 60000;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<double> t(n);
  for (size_t i = 0; i < n; ++i) t[i] = (i + jitter(rng)) * h;
  const UniformGrid g = uniformGrid(t);
  ASSERT_TRUE(g.resampled);
  ASSERT_EQ(g.size(), n);
  const std::vector<double> acf = gridNoiseAutocorrelation(g);
  ASSERT_GE(acf.size(), 2u);
  double c0 = 0;
  for (double u : g.weight) c0 += (1 - u) * (1 - u) + u * u;
  EXPECT_NEAR(acf[0], c0 / n, 1e-12);
  EXPECT_LT(acf[0], 0.95);
  const std::vector<double> y = onGrid(g, whiteNoise(n, sigma, 4));
  EXPECT_NEAR(variance(y) / (sigma * sigma), acf[0], 0.02);
  const auto fitted = bandAnalysis(y, 1.0 / g.dt, sigma * sigma, nullptr, 1024, 0.01, acf);
  const auto white = bandAnalysis(y, 1.0 / g.dt, sigma * sigma, nullptr, 1024, 0.01);
  ASSERT_EQ(fitted.size(), 4u);
  for (const BandReport& b : fitted) {
    EXPECT_NEAR(b.ratio, 1.0, 0.12) << b.band;
    EXPECT_FALSE(b.significant) << b.band;
  }
  EXPECT_LT(white[3].ratio, 0.85) << "the white floor overstates the resampled noise near Nyquist";
  std::printf(
      "[ floor ] high band of resampled white noise: %.3f of the interpolated floor, %.3f of the "
      "white floor\n",
      fitted[3].ratio, white[3].ratio);
  EXPECT_THROW(bandAnalysis(y, 1.0 / g.dt, 1.0, nullptr, 1024, 0.01, {0.0}), std::invalid_argument);
}

// The grid: uniform times are used as they are; jitter of ±30 % of a step is not a gap (a gap at
// 1.5 times the median step alone would cut such a record every few hundred samples); a hole is; a
// change of rate is not steady.
TEST(Signal, UniformGridTellsJitterFromGapsAndRateChanges) {
  std::vector<double> t(1000);
  for (size_t i = 0; i < t.size(); ++i) t[i] = 0.01 * i;
  UniformGrid g = uniformGrid(t);
  EXPECT_FALSE(g.resampled);
  EXPECT_EQ(g.gaps, 0u);
  EXPECT_EQ(gridNoiseAutocorrelation(g), std::vector<double>{1.0});
  std::vector<double> x(t.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = 0.5 * i;
  EXPECT_EQ(onGrid(g, x), x);
  // A hole of 30 steps after 0.4 s: the longest stretch is after it.
  std::vector<double> holed;
  for (double v : t)
    if (v < 0.4 - 1e-9 || v > 0.7 + 1e-9) holed.push_back(v);
  g = uniformGrid(holed);
  EXPECT_EQ(g.gaps, 1u);
  EXPECT_NEAR(g.gap_step_s, 0.015, 1e-12);
  EXPECT_EQ(g.begin, 40u);
  EXPECT_EQ(g.end, holed.size());
  EXPECT_FALSE(g.resampled);

  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<double> j(100000);
  for (size_t i = 0; i < j.size(); ++i) j[i] = (i + jitter(rng)) / 110.0;
  size_t old_gaps = 0;
  for (size_t i = 1; i < j.size(); ++i) old_gaps += j[i] - j[i - 1] > 1.5 / 110.0;
  EXPECT_GT(old_gaps, 100u);
  g = uniformGrid(j);
  EXPECT_EQ(g.gaps, 0u);
  EXPECT_TRUE(g.steady);
  EXPECT_TRUE(g.resampled);
  EXPECT_GT(g.jitter, 0.5);
  EXPECT_LT(g.jitter, 0.6);
  // The same jittered clock with a 1 s hole: one gap, the longer side kept.
  std::vector<double> jh;
  for (double v : j)
    if (v < 200.0 || v > 201.0) jh.push_back(v);
  g = uniformGrid(jh);
  EXPECT_EQ(g.gaps, 1u);
  EXPECT_GT(jh[g.begin], 200.0);
  EXPECT_TRUE(g.resampled);
  // A change from 100 to 125 Hz half way: no gap, but not steady.
  std::vector<double> r;
  for (int i = 0; i < 5000; ++i) r.push_back(0.01 * i);
  for (int i = 1; i <= 5000; ++i) r.push_back(49.99 + 0.008 * i);
  g = uniformGrid(r);
  EXPECT_EQ(g.gaps, 0u);
  EXPECT_FALSE(g.steady);
  EXPECT_NEAR(g.rate_lo_hz, 100.0, 1e-6);
  EXPECT_NEAR(g.rate_hi_hz, 125.0, 1e-6);
  EXPECT_FALSE(g.resampled);
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
  expectInvalid([&] { rankWindows(x, y, 3, 0, 0); }, "same length");
  std::vector<double> inc(64);
  for (size_t i = 0; i < inc.size(); ++i) inc[i] = 0.1 * i;
  expectInvalid([&] { rankWindows(inc, x, 3, 0, 0, {200, 0, 0.8}); }, "max_listed must be >= 1");
  expectInvalid(
      [&] {
        rankWindows(inc, x, 3, 0, 0, {200, 20, 1.5});
      },
      "listed share must lie in (0, 1]");
  expectInvalid([&] { uniformGrid(x); }, "strictly increasing");
  expectInvalid([&] { uniformGrid({1.0}); }, "at least 2 times");
  expectInvalid([&] { onGrid(uniformGrid(inc), y); }, "one value per time");
  expectInvalid([&] { bandIntegral(Spectrum{{0, 1}, {1}}, 0, 1); }, "same length");
  expectInvalid([&] { bandIntegral(Spectrum{{0, 1}, {1, 1}}, 1, 0); }, "f_hi >= f_lo");
}

}  // namespace
