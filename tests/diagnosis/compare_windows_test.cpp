// The comparison's windows and spectrum on long logged records, without a simulation: a series
// (times, standardised residual, measured and predicted means) is built by hand, as a logger at
// 110 Hz with a jittering clock would give it, and addWindows / addResidualBands are checked
// against what the record holds (docs/diagnosis.md, "twin compare").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "diagnosis/compare.hpp"

using namespace dtwin;
using namespace dtwin::diag;

namespace {

constexpr double kStep = 1.0 / 110.0;

/// `n` times of a 110 Hz logger whose stamps are jittered uniformly by ±30 % of a step.
std::vector<double> jitteredTimes(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = (static_cast<double>(i) + jitter(rng)) * kStep;
  return t;
}

struct Burst {
  double t0, t1, z;
};

/// A fitted series with standardised residual `z` at times `t`.
SeriesComparison series(const std::vector<double>& t, const std::vector<double>& z) {
  SeriesComparison sc;
  sc.data_set = "drive.csv";
  sc.scenario = "drive";
  sc.channel = "seat_mps2";
  sc.fitted = true;
  sc.noise_variance = 1.0;
  sc.t = t;
  sc.z = z;
  return sc;
}

/// Labels a window by the burst whose middle it holds ("burst 2"), or "background".
std::function<LabelledWindow(const Window&)> labeller(const std::vector<Burst>& bursts) {
  return [bursts](const Window& w) {
    LabelledWindow lw{w, "background", 10.0};
    for (std::size_t k = 0; k < bursts.size(); ++k)
      if (w.t_begin <= 0.5 * (bursts[k].t0 + bursts[k].t1) &&
          w.t_end >= 0.5 * (bursts[k].t0 + bursts[k].t1))
        lw.label = "burst " + std::to_string(k);
    return lw;
  };
}

/// Σ z² over the samples of [t0, t1] / Σ z² over the record.
double shareIn(const std::vector<double>& t, const std::vector<double>& z, double t0, double t1) {
  double in = 0, all = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    all += z[i] * z[i];
    if (t[i] >= t0 && t[i] <= t1) in += z[i] * z[i];
  }
  return in / all;
}

}  // namespace

// 100 000 samples (909 s at 110 Hz, stamps jittered by ±30 %) whose residual fails nearly
// everywhere (a 1.5 Hz oscillation of 9 noise sd the model misses: |z| above 4 for 70 % of the
// time, in two windows a period) with three big bursts: thousands of windows, merged to at most
// 200, the 20 largest listed, the bursts first, biggest first, and the sentence counts them right.
TEST(CompareWindows, ALongRecordThatFailsThroughoutListsTheBurstsFirst) {
  const std::size_t n = 100000;
  const std::vector<double> t = jitteredTimes(n, 21);
  const std::vector<Burst> bursts{{420.0, 420.5, 60.0}, {150.0, 150.5, 80.0}, {700.0, 700.5, 45.0}};
  std::mt19937_64 rng(22);
  std::normal_distribution<double> noise(0.0, 0.5);
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) {
    z[i] = 9.0 * std::sin(2 * kPi * 1.5 * t[i]) + noise(rng);
    for (const auto& b : bursts)
      if (t[i] >= b.t0 && t[i] <= b.t1) z[i] = b.z * (i % 2 ? 1 : -1);
  }
  SeriesComparison sc = series(t, z);
  addWindows(sc, CompareOptions{}, labeller(bursts));
  const WindowSummary& s = sc.window_summary;
  const auto found = exceedanceWindows(t, z, 4.0, 0.05, 0.0);
  EXPECT_EQ(s.found, found.size());
  EXPECT_GT(s.found, 2000u) << "the record fails nearly everywhere";
  EXPECT_EQ(sc.all_windows.size(), s.found);
  EXPECT_GT(s.time_share, 0.5);
  EXPECT_LE(s.merged, 201u);
  EXPECT_LT(s.merged, s.found);
  ASSERT_EQ(sc.windows.size(), 20u) << "capped";
  EXPECT_EQ(s.listed, 20u);
  // Ranked by share; the bursts first, the biggest first.
  EXPECT_EQ(sc.windows[0].label, "burst 1");
  EXPECT_EQ(sc.windows[1].label, "burst 0");
  EXPECT_EQ(sc.windows[2].label, "burst 2");
  for (std::size_t k = 3; k < sc.windows.size(); ++k)
    EXPECT_EQ(sc.windows[k].label, "background") << k;
  for (std::size_t k = 1; k < sc.windows.size(); ++k)
    EXPECT_GE(sc.windows[k - 1].window.share, sc.windows[k].window.share) << k;
  // Each window's share is what the record holds between its ends; none is longer than
  // 2 × 909 s / 200.
  double held = 0;
  for (const auto& w : sc.windows) {
    EXPECT_NEAR(w.window.share, shareIn(t, z, w.window.t_begin, w.window.t_end), 1e-9);
    EXPECT_LE(w.window.t_end - w.window.t_begin, 2 * (t.back() - t.front()) / 200 + 1e-9);
    held += w.window.share;
  }
  EXPECT_NEAR(s.listed_share, held, 1e-12);
  // The sentence.
  const std::string& note = sc.windows_note;
  std::printf("[ note ] %s\n", note.c_str());
  EXPECT_NE(note.find(std::to_string(found.size()) + " windows over "), std::string::npos) << note;
  EXPECT_NE(note.find("the model misses throughout, not in a few places"), std::string::npos)
      << note;
  EXPECT_NE(note.find("merged to " + std::to_string(s.merged) + " "), std::string::npos) << note;
  EXPECT_NE(note.find("the 20 largest, listed, hold " + formatPrintf("%.0f", 100 * held) +
                      " % of the residual"),
            std::string::npos)
      << note;
  // compare.json: the listed windows, their counts, and every window found.
  Comparison c;
  c.series.push_back(sc);
  const auto j = c.toJson(false);
  const auto& e = j.at("series").at(0);
  EXPECT_EQ(e.at("windows").size(), 20u);
  EXPECT_EQ(e.at("windows").at(0).at("label"), "burst 1");
  EXPECT_EQ(e.at("windows_summary").at("found").get<std::size_t>(), found.size());
  EXPECT_EQ(e.at("windows_summary").at("merged").get<std::size_t>(), s.merged);
  EXPECT_EQ(e.at("windows_note"), note);
  ASSERT_EQ(e.at("all_windows").at("rows").size(), found.size());
  EXPECT_DOUBLE_EQ(e.at("all_windows").at("rows").at(7).at(0).get<double>(), found[7].t_begin);
  EXPECT_DOUBLE_EQ(e.at("all_windows").at("rows").at(7).at(3).get<double>(), found[7].share);
}

// The same long record with a residual mostly inside the noise (|z| above 4 now and then) and
// three bursts: a few dozen windows, not merged; the bursts alone hold 80 % of the windows' share,
// so only they are listed, and the sentence says so without "throughout".
TEST(CompareWindows, ScatteredExceedancesAndThreeBurstsListTheBursts) {
  const std::size_t n = 100000;
  const std::vector<double> t = jitteredTimes(n, 31);
  const std::vector<Burst> bursts{{100.0, 100.5, 30.0}, {500.0, 500.5, 35.0}, {800.0, 800.5, 25.0}};
  std::mt19937_64 rng(32);
  std::normal_distribution<double> noise(0.0, 1.2);
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) {
    z[i] = noise(rng);
    for (const auto& b : bursts)
      if (t[i] >= b.t0 && t[i] <= b.t1) z[i] = b.z;
  }
  SeriesComparison sc = series(t, z);
  addWindows(sc, CompareOptions{}, labeller(bursts));
  const WindowSummary& s = sc.window_summary;
  EXPECT_GT(s.found, 20u);
  EXPECT_LE(s.found, 200u);
  EXPECT_EQ(s.merged, s.found);
  EXPECT_LT(s.time_share, 0.01);
  ASSERT_EQ(sc.windows.size(), 3u);
  EXPECT_EQ(sc.windows[0].label, "burst 1");
  EXPECT_EQ(sc.windows[1].label, "burst 0");
  EXPECT_EQ(sc.windows[2].label, "burst 2");
  const double bursts_share =
      shareIn(t, z, 100.0, 100.5) + shareIn(t, z, 500.0, 500.5) + shareIn(t, z, 800.0, 800.5);
  EXPECT_NEAR(s.listed_share, bursts_share, 1e-9);
  std::printf("[ note ] %s\n", sc.windows_note.c_str());
  EXPECT_EQ(sc.windows_note.find("throughout"), std::string::npos) << sc.windows_note;
  EXPECT_NE(sc.windows_note.find(std::to_string(s.found) + " windows over "), std::string::npos)
      << sc.windows_note;
  EXPECT_NE(sc.windows_note.find("; the 3 largest, listed, hold " +
                                 formatPrintf("%.0f", 100 * bursts_share) + " % of the residual"),
            std::string::npos)
      << sc.windows_note;
}

// A few windows: every one listed, largest share first, nothing merged.
TEST(CompareWindows, FewWindowsAreAllListedLargestFirst) {
  std::vector<double> t(2000), z(2000, 0.3);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = 0.01 * static_cast<double>(i);
  for (std::size_t i = 200; i < 210; ++i) z[i] = 5.0;   // 2.00–2.09 s
  for (std::size_t i = 900; i < 950; ++i) z[i] = -7.0;  // 9.00–9.49 s: the largest
  for (std::size_t i = 1500; i < 1520; ++i) z[i] = 6.0;
  SeriesComparison sc = series(t, z);
  addWindows(sc, CompareOptions{}, labeller({}));
  ASSERT_EQ(sc.windows.size(), 3u);
  EXPECT_DOUBLE_EQ(sc.windows[0].window.t_begin, 9.0);
  EXPECT_DOUBLE_EQ(sc.windows[1].window.t_begin, 15.0);
  EXPECT_DOUBLE_EQ(sc.windows[2].window.t_begin, 2.0);
  EXPECT_EQ(sc.window_summary.found, 3u);
  EXPECT_EQ(sc.window_summary.listed, 3u);
  EXPECT_DOUBLE_EQ(sc.all_windows[0].t_begin, 2.0) << "every window, in time order";
  EXPECT_EQ(sc.windows_note, "3 windows over 4 % of the record; together they hold " +
                                 formatPrintf("%.0f", 100 * sc.window_summary.listed_share) +
                                 " % of the residual");
  SeriesComparison none = series(t, std::vector<double>(t.size(), 0.5));
  addWindows(none, CompareOptions{}, labeller({}));
  EXPECT_TRUE(none.windows.empty());
  EXPECT_EQ(none.windows_note, "");
}

TEST(CompareWindows, BadWindowOptionsAreOneLineInputErrors) {
  SeriesComparison sc = series({0.0, 0.01, 0.02}, {5.0, 5.0, 0.0});
  CompareOptions o;
  o.window_max_listed = 0;
  try {
    addWindows(sc, o, labeller({}));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "compare.window_max_listed: must be >= 1, got 0");
  }
  o = CompareOptions{};
  o.window_listed_share = 1.5;
  try {
    addWindows(sc, o, labeller({}));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "compare.window_listed_share: must lie in (0, 1], got 1.5");
  }
}

// A 110 Hz log with a jittering clock: its residual's spectrum is made on a uniform 110 Hz grid,
// resampled, and the note says so; a sinusoid of the residual at 5 Hz fails the mid band, and the
// noise elsewhere sits on the floor (which follows the interpolation).
TEST(CompareSpectrum, AJitteredRecordIsResampledAndHasASpectrum) {
  const std::size_t n = 30000;
  const std::vector<double> t = jitteredTimes(n, 41);
  std::mt19937_64 rng(42);
  const double sigma = 0.2;
  std::normal_distribution<double> noise(0.0, sigma);
  SeriesComparison sc = series(t, std::vector<double>(n, 0.0));
  sc.noise_variance = sigma * sigma;
  for (std::size_t i = 0; i < n; ++i) {
    sc.predicted_mean.push_back(std::sin(0.3 * t[i]));
    sc.measured_mean.push_back(sc.predicted_mean.back() + 0.1 * std::sin(2 * kPi * 5.0 * t[i]) +
                               noise(rng));
    sc.repetitions.push_back(1);
  }
  addResidualBands(sc, {});
  ASSERT_EQ(sc.bands.size(), 4u) << sc.bands_note;
  std::printf("[ note ] %s\n", sc.bands_note.c_str());
  for (const auto& b : sc.bands)
    std::printf("[ band ] %s: residual / noise power %.3f\n", b.band.c_str(), b.ratio);
  EXPECT_EQ(sc.bands_note.rfind("resampled to a uniform 110.0 Hz grid by linear interpolation: the "
                                "clock jitters by up to ",
                                0),
            0u)
      << sc.bands_note;
  EXPECT_EQ(sc.bands_note.find("longest stretch"), std::string::npos)
      << "jitter is no gap: " << sc.bands_note;
  for (const auto& b : sc.bands) {
    EXPECT_EQ(b.significant, b.band == "mid") << b.band << " " << b.ratio;
    if (b.band != "mid") {
      EXPECT_NEAR(b.ratio, 1.0, 0.15) << b.band;
    }
    EXPECT_TRUE(std::isnan(b.coherence)) << "no road given";
  }
  // The sinusoid's power in the mid band: 0.1²/2, less what interpolation takes at 5 Hz
  // (under 1 %), over the noise there.
  const auto& mid = sc.bands[1];
  EXPECT_NEAR(mid.residual_power - mid.noise_power, 0.01 / 2, 0.15 * 0.01 / 2);
}

// A change of rate within the record (100 Hz, then 125 Hz) gives no spectrum, and the note says
// why; too few times, and gaps every few samples, say so too.
TEST(CompareSpectrum, ARateChangeOrTooFewTimesGiveNoSpectrumAndSayWhy) {
  std::vector<double> t;
  for (int i = 0; i < 5000; ++i) t.push_back(0.01 * i);
  for (int i = 1; i <= 5000; ++i) t.push_back(49.99 + 0.008 * i);
  SeriesComparison sc = series(t, std::vector<double>(t.size(), 0.0));
  sc.measured_mean.assign(t.size(), 0.0);
  sc.predicted_mean.assign(t.size(), 0.0);
  sc.repetitions.assign(t.size(), 1);
  addResidualBands(sc, {});
  EXPECT_TRUE(sc.bands.empty());
  EXPECT_EQ(sc.bands_note,
            "no spectrum: the sampling rate changes within the record, from 100 to 125 Hz");
  SeriesComparison few = series({0.0, 0.1, 0.2}, {0.0, 0.0, 0.0});
  addResidualBands(few, {});
  EXPECT_EQ(few.bands_note, "no spectrum: fewer than 64 times");
  std::vector<double> holes;
  for (int k = 0; k < 20; ++k)
    for (int i = 0; i < 10; ++i) holes.push_back(k + 0.01 * i);
  SeriesComparison gappy = series(holes, std::vector<double>(holes.size(), 0.0));
  gappy.measured_mean.assign(holes.size(), 0.0);
  gappy.predicted_mean.assign(holes.size(), 0.0);
  gappy.repetitions.assign(holes.size(), 1);
  addResidualBands(gappy, {});
  EXPECT_TRUE(gappy.bands.empty());
  EXPECT_EQ(gappy.bands_note,
            "no spectrum: 19 gaps in the times (steps longer than 0.015 s), and no stretch between "
            "gaps holds 64 times");
}
