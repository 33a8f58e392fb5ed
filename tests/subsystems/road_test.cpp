// Tests of road profiles: the one-cosine bump, the gridded (Catmull-Rom) road, ISO 8608 random
// roads (against the analytic PSD with a Welch estimate, and Parseval over one period) and the
// CSV loader's error messages.
#include "subsystems/road.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include <unistd.h>

#include <unsupported/Eigen/FFT>

#include "common/errors.hpp"

namespace dtwin {
namespace {

constexpr Track kTracks[] = {Track::Left, Track::Right};

// ------------------------------------------------------------------ helpers

/// Composite Simpson rule of f over [a, b] with n (even) sub-intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  if (n % 2) ++n;
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

double centralDifference(const std::function<double(double)>& f, double x, double h) {
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n;
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double saa = 0, sbb = 0, sab = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
    sab += (a[i] - ma) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

std::vector<double> differences(const std::vector<double>& v) {
  std::vector<double> d(v.size() - 1);
  for (std::size_t i = 0; i + 1 < v.size(); ++i) d[i] = v[i + 1] - v[i];
  return d;
}

/// Welch estimate of the one-sided displacement PSD [m^2/(cycles/m) = m^3] of samples x with
/// spacing dx: Hann window of M samples, 50 % overlap, averaged periodograms. Bin k is at
/// spatial frequency k / (M dx); the estimate integrates (sum PSD * dn) to the windowed mean
/// square.
std::vector<double> welchPsd(const std::vector<double>& x, double dx, std::size_t M) {
  std::vector<double> w(M);
  double w2 = 0.0;
  for (std::size_t j = 0; j < M; ++j) {
    w[j] = 0.5 * (1.0 - std::cos(2.0 * M_PI * static_cast<double>(j) / static_cast<double>(M)));
    w2 += w[j] * w[j];
  }
  std::vector<double> psd(M / 2 + 1, 0.0), seg(M);
  std::vector<std::complex<double>> X;
  Eigen::FFT<double> fft;
  int segments = 0;
  for (std::size_t start = 0; start + M <= x.size(); start += M / 2) {
    for (std::size_t j = 0; j < M; ++j) seg[j] = x[start + j] * w[j];
    fft.fwd(X, seg);
    for (std::size_t k = 0; k <= M / 2; ++k) psd[k] += std::norm(X[k]);
    ++segments;
  }
  for (std::size_t k = 0; k <= M / 2; ++k)
    psd[k] *= (k == 0 || k == M / 2 ? 1.0 : 2.0) * dx / (w2 * segments);
  return psd;
}

/// Integral of a Welch PSD over [lo, hi]: bin k covers [(k - 1/2) dn, (k + 1/2) dn] and is
/// weighted by its overlap with the band.
double bandIntegral(const std::vector<double>& psd, double dn, double lo, double hi) {
  double s = 0.0;
  for (std::size_t k = 1; k < psd.size(); ++k) {
    const double a = std::max(lo, (static_cast<double>(k) - 0.5) * dn);
    const double b = std::min(hi, (static_cast<double>(k) + 0.5) * dn);
    if (b > a) s += psd[k] * (b - a);
  }
  return s;
}

/// Integral of Gd(n) = Gd0 (n/n0)^-2 over [lo, hi], n0 = 0.1 cycles/m.
double gdBandIntegral(double gd0, double lo, double hi) {
  return gd0 * 0.01 * (1.0 / lo - 1.0 / hi);
}

// ------------------------------------------------------------------ flat & bump

TEST(FlatRoad, IsZeroEverywhere) {
  FlatRoad road;
  for (Track t : kTracks)
    for (double x : {-100.0, 0.0, 3.7, 1e6}) {
      EXPECT_EQ(road.sample(t, x).height_m, 0.0);
      EXPECT_EQ(road.sample(t, x).slope, 0.0);
      EXPECT_EQ(road.integral(t, x), 0.0);
    }
  EXPECT_LT(road.extent().lo, -1e6);
  EXPECT_GT(road.extent().hi, 1e6);
}

class BumpRoadTest : public ::testing::Test {
 protected:
  static constexpr double x0 = 5.0, H = 0.2, L = 0.1;
  BumpRoad road{x0, H, L};
};

TEST_F(BumpRoadTest, HeightIsHAtCentreAndZeroOutside) {
  for (Track t : kTracks) {
    EXPECT_NEAR(road.sample(t, x0 + 0.5 * L).height_m, H, 1e-15);
    EXPECT_NEAR(road.sample(t, x0 + 0.5 * L).slope, 0.0, 1e-12);
    for (double x : {-10.0, x0 - 1e-9, x0, x0 + L, x0 + L + 1e-9, 100.0}) {
      EXPECT_EQ(road.sample(t, x).height_m, 0.0) << "x = " << x;
      EXPECT_EQ(road.sample(t, x).slope, 0.0) << "x = " << x;
    }
    // One-cosine shape: half height at the quarter points.
    EXPECT_NEAR(road.sample(t, x0 + 0.25 * L).height_m, 0.5 * H, 1e-14);
    EXPECT_NEAR(road.sample(t, x0 + 0.75 * L).height_m, 0.5 * H, 1e-14);
    // Inside, strictly positive and never above H.
    for (int i = 1; i < 100; ++i) {
      const double h = road.sample(t, x0 + L * i / 100.0).height_m;
      EXPECT_GT(h, 0.0);
      EXPECT_LE(h, H);
    }
  }
  ASSERT_EQ(road.obstacles().size(), 1u);
  EXPECT_EQ(road.obstacles()[0].lo, x0);
  EXPECT_EQ(road.obstacles()[0].hi, x0 + L);
  EXPECT_EQ(road.describe().at("height_m").get<double>(), H);
}

TEST_F(BumpRoadTest, SlopeEqualsFiniteDifferenceOfHeight) {
  const auto h = [&](double x) { return road.sample(Track::Left, x).height_m; };
  for (int i = 1; i < 50; ++i) {
    const double x = x0 + L * i / 50.0;
    const double fd = centralDifference(h, x, 1e-7);
    EXPECT_NEAR(road.sample(Track::Left, x).slope, fd, 1e-6 * (H * 2 * M_PI / L)) << "x = " << x;
  }
}

TEST_F(BumpRoadTest, IntegralEqualsQuadratureOfHeight) {
  for (Track t : kTracks) {
    const auto h = [&](double x) { return road.sample(t, x).height_m; };
    const double a = x0 - 0.3;
    for (double x : {x0 - 0.1, x0 + 0.013, x0 + 0.05, x0 + 0.0777, x0 + L, x0 + 0.4}) {
      // Split at the bump's ends so that Simpson sees a smooth integrand.
      double q = 0.0;
      const double cuts[] = {a, x0, x0 + L, x};
      for (int k = 0; k < 3; ++k) {
        const double lo = std::min(cuts[k], x), hi = std::min(cuts[k + 1], x);
        if (hi > lo) q += simpson(h, lo, hi, 2000);
      }
      EXPECT_NEAR(road.integral(t, x) - road.integral(t, a), q, 1e-12) << "x = " << x;
    }
    // Closed form of the whole bump: H L / 2.
    EXPECT_NEAR(road.integral(t, x0 + 10.0) - road.integral(t, x0 - 10.0), 0.5 * H * L, 1e-15);
  }
}

TEST_F(BumpRoadTest, SampleAveragedEqualsBruteForceMean) {
  for (double window : {0.03, 0.1, 0.3}) {
    for (double x : {x0 - 0.2, x0 - 0.04, x0, x0 + 0.02, x0 + 0.05, x0 + 0.09, x0 + 0.16}) {
      // Brute-force mean: midpoint rule on a fine grid.
      const int n = 200000;
      double s = 0.0;
      for (int i = 0; i < n; ++i)
        s += road.sample(Track::Left, x - 0.5 * window + window * (i + 0.5) / n).height_m;
      const RoadSample avg = road.sampleAveraged(Track::Left, x, window);
      EXPECT_NEAR(avg.height_m, s / n, 1e-9) << "L = " << window << ", x = " << x;
      // Its slope is the derivative of the averaged height.
      const auto mean = [&](double y) {
        return road.sampleAveraged(Track::Left, y, window).height_m;
      };
      EXPECT_NEAR(avg.slope, centralDifference(mean, x, 1e-7), 1e-5)
          << "L = " << window << ", x = " << x;
    }
  }
}

// ------------------------------------------------------------------ grid

class GridRoadTest : public ::testing::Test {
 protected:
  static constexpr double x0 = -1.0, dx = 0.25;
  static constexpr int n = 41;
  static std::vector<double> leftNodes() {
    std::vector<double> h(n);
    for (int i = 0; i < n; ++i) h[i] = 0.05 * std::sin(0.9 * i) + 0.002 * i;
    return h;
  }
  static std::vector<double> rightNodes() {
    std::vector<double> h(n);
    for (int i = 0; i < n; ++i) h[i] = 0.03 * std::cos(1.3 * i) - 0.01;
    return h;
  }
  GridRoad road{x0, dx, leftNodes(), rightNodes(), {{"type", "test"}}};
  const std::vector<double>& nodes(Track t) const { return road.heights(t); }
};

TEST_F(GridRoadTest, InterpolatesNodesExactly) {
  EXPECT_EQ(road.heights(Track::Left), leftNodes());
  EXPECT_EQ(road.heights(Track::Right), rightNodes());
  for (Track t : kTracks)
    for (int i = 0; i < n; ++i)
      EXPECT_DOUBLE_EQ(road.sample(t, x0 + i * dx).height_m, nodes(t)[i]) << "node " << i;
  EXPECT_DOUBLE_EQ(road.extent().lo, x0);
  EXPECT_DOUBLE_EQ(road.extent().hi, x0 + (n - 1) * dx);
  EXPECT_EQ(road.x0(), x0);
  EXPECT_EQ(road.dx(), dx);
}

TEST_F(GridRoadTest, InteriorNodeSlopesAreCatmullRom) {
  for (Track t : kTracks)
    for (int i = 1; i + 1 < n; ++i)
      EXPECT_NEAR(road.sample(t, x0 + i * dx).slope, (nodes(t)[i + 1] - nodes(t)[i - 1]) / (2 * dx),
                  1e-12)
          << "node " << i;
}

TEST_F(GridRoadTest, ReproducesLinearProfileExactly) {
  std::vector<double> lin(n);
  for (int i = 0; i < n; ++i) lin[i] = 0.3 + 0.02 * (x0 + i * dx);
  GridRoad line(x0, dx, lin, lin, {});
  for (double x = x0 + 1e-3; x < x0 + (n - 1) * dx; x += 0.0371) {
    EXPECT_NEAR(line.sample(Track::Left, x).height_m, 0.3 + 0.02 * x, 1e-14) << "x = " << x;
    EXPECT_NEAR(line.sample(Track::Left, x).slope, 0.02, 1e-12) << "x = " << x;
  }
}

TEST_F(GridRoadTest, SlopeEqualsFiniteDifferenceOfHeight) {
  for (Track t : kTracks) {
    const auto h = [&](double x) { return road.sample(t, x).height_m; };
    // Includes points on nodes (the interpolant is C1 there).
    for (double x = x0 + 0.01; x < x0 + (n - 1) * dx - 0.01; x += 0.0613) {
      EXPECT_NEAR(road.sample(t, x).slope, centralDifference(h, x, 1e-6), 1e-7) << "x = " << x;
    }
    // On nodes the second derivative jumps, so the FD step must be small (its error is
    // h/4 times the jump).
    for (int i = 1; i + 1 < n; i += 7)
      EXPECT_NEAR(road.sample(t, x0 + i * dx).slope, centralDifference(h, x0 + i * dx, 1e-8), 1e-7);
  }
}

TEST_F(GridRoadTest, IntegralEqualsSimpsonQuadratureOfInterpolant) {
  for (Track t : kTracks) {
    const auto h = [&](double x) { return road.sample(t, x).height_m; };
    for (double x : {x0 + 0.1, x0 + 0.25, x0 + 1.337, x0 + 4.0, x0 + 7.91, x0 + (n - 1) * dx}) {
      // Piecewise Simpson, each piece inside one interpolation interval (fine: 64 sub-intervals).
      double q = 0.0;
      for (double a = x0; a < x - 1e-15; a += dx) q += simpson(h, a, std::min(a + dx, x), 64);
      EXPECT_NEAR(road.integral(t, x) - road.integral(t, x0), q, 1e-9) << "x = " << x;
    }
    // The integral's derivative is the height.
    const auto I = [&](double x) { return road.integral(t, x); };
    for (double x : {x0 + 0.3, x0 + 2.2, x0 + 5.55})
      EXPECT_NEAR(centralDifference(I, x, 1e-5), h(x), 1e-9);
  }
}

TEST_F(GridRoadTest, HoldsEndValuesOutsideExtent) {
  const double end = x0 + (n - 1) * dx;
  for (Track t : kTracks) {
    EXPECT_EQ(road.sample(t, x0 - 3.0).height_m, nodes(t).front());
    EXPECT_EQ(road.sample(t, x0 - 3.0).slope, 0.0);
    EXPECT_EQ(road.sample(t, end + 3.0).height_m, nodes(t).back());
    EXPECT_EQ(road.sample(t, end + 3.0).slope, 0.0);
    // Integral consistent with the held values.
    EXPECT_NEAR(road.integral(t, x0) - road.integral(t, x0 - 2.0), 2.0 * nodes(t).front(), 1e-14);
    EXPECT_NEAR(road.integral(t, end + 2.0) - road.integral(t, end), 2.0 * nodes(t).back(), 1e-14);
  }
}

// A run that ends exactly on the last node of a logged road (a drive's last record) reads the
// interpolant's slope there: the hold's zero slope made the hubs stop dead on the last sample.
TEST_F(GridRoadTest, TheFirstAndLastNodesKeepTheirSlopes) {
  const double end = x0 + (n - 1) * dx;
  for (Track t : kTracks) {
    const auto h = [&](double x) { return road.sample(t, x).height_m; };
    const double last = (nodes(t)[n - 1] - nodes(t)[n - 2]) / dx;
    const double first = (nodes(t)[1] - nodes(t)[0]) / dx;
    EXPECT_NEAR(road.sample(t, end).slope, last, 1e-12);
    EXPECT_NEAR(road.sample(t, x0).slope, first, 1e-12);
    EXPECT_EQ(road.sample(t, end).height_m, nodes(t).back());
    EXPECT_EQ(road.sample(t, x0).height_m, nodes(t).front());
    // The one-sided difference from inside agrees (the interpolant is C1 up to its ends).
    EXPECT_NEAR(road.sample(t, end).slope, (h(end) - h(end - 1e-7)) / 1e-7, 1e-5);
    EXPECT_NEAR(road.sample(t, x0).slope, (h(x0 + 1e-7) - h(x0)) / 1e-7, 1e-5);
  }
}

TEST_F(GridRoadTest, SampleAveragedEqualsBruteForceMean) {
  for (Track t : kTracks)
    for (double x : {x0 + 0.6, x0 + 3.03, x0 + 8.0}) {
      const double window = 0.4;
      const int m = 100000;
      double s = 0.0;
      for (int i = 0; i < m; ++i)
        s += road.sample(t, x - 0.5 * window + window * (i + 0.5) / m).height_m;
      EXPECT_NEAR(road.sampleAveraged(t, x, window).height_m, s / m, 1e-10);
    }
}

// ------------------------------------------------------------------ ISO 8608

TEST(IsoRoad, ClassGd0ValuesAreGeometricMeans) {
  // docs/method.md §2: 16, 64, ..., 262144 e-6 m^3 for A..H, i.e. 16e-6 * 4^k.
  const double expected[] = {16e-6, 64e-6, 256e-6, 1024e-6, 4096e-6, 16384e-6, 65536e-6, 262144e-6};
  for (int k = 0; k < 8; ++k) {
    const char c = static_cast<char>('A' + k);
    EXPECT_DOUBLE_EQ(isoClassGd0(c), expected[k]) << c;
    EXPECT_DOUBLE_EQ(isoClassGd0(c), 16e-6 * std::pow(4.0, k)) << c;
  }
  for (char bad : {'I', 'a', '@', 'd'}) {
    try {
      isoClassGd0(bad);
      ADD_FAILURE() << "class '" << bad << "' accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("A..H"), std::string::npos) << e.what();
    }
  }
}

TEST(IsoRoad, RmsHeightFormula) {
  // sqrt(Gd(n0) n0^2 (1/n_min - 1/n_max)): the integral of Gd(n0) (n/n0)^-2 over the band.
  EXPECT_DOUBLE_EQ(isoRmsHeight('D', 0.011, 2.83),
                   std::sqrt(1024e-6 * 0.01 * (1 / 0.011 - 1 / 2.83)));
  // Each class up doubles the RMS.
  for (char c = 'A'; c < 'H'; ++c)
    EXPECT_NEAR(isoRmsHeight(c + 1, 0.011, 2.83) / isoRmsHeight(c, 0.011, 2.83), 2.0, 1e-14) << c;
}

TEST(IsoRoad, MeanSquareOverOnePeriodEqualsBandIntegralOfGd) {
  // Parseval: over one full period of the sum of cosines the mean square is the integral of Gd
  // over the band, exactly. dx = 1/128 m and 2^16 points (the last at 65535 dx) make one period.
  IsoRoadSpec s;
  s.road_class = 'D';
  s.seed = 7;
  s.dx_m = 1.0 / 128.0;
  s.length_m = 65535.0 / 128.0;
  auto road = makeIsoRoad(s);
  const auto& h = road->heights(Track::Left);
  ASSERT_NEAR(road->describe().at("period_m").get<double>(), static_cast<double>(h.size()) * s.dx_m,
              1e-9)
      << "the profile must cover exactly one period for this check";
  for (Track t : kTracks)
    EXPECT_NEAR(rms(road->heights(t)) / isoRmsHeight('D', s.n_min, s.n_max), 1.0, 1e-10);

  // Same with a non-default waviness w = 2.5: integral of Gd0 (n/n0)^-w over the band.
  s.waviness = 2.5;
  auto wavy = makeIsoRoad(s);
  const double w = 2.5, gd0 = isoClassGd0('D');
  const double ms =
      gd0 * std::pow(0.1, w) * (std::pow(s.n_max, 1 - w) - std::pow(s.n_min, 1 - w)) / (1 - w);
  const double r = rms(wavy->heights(Track::Left));
  EXPECT_NEAR(r * r / ms, 1.0, 1e-10);
}

/// A long class-D profile shared by the statistical tests: 20 km at dx = 0.05 m (7 points per
/// shortest wavelength). With only 2 km the scatter over seeds reaches about 13 % in RMS and in
/// octave-band power and 0.3 in left/right correlation, too wide for the tolerances below.
class IsoRoadStatistics : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    spec_.road_class = 'D';
    spec_.seed = 7;
    spec_.dx_m = 0.05;
    spec_.length_m = 20000.0;
    road_ = makeIsoRoad(spec_);
  }
  static void TearDownTestSuite() { road_.reset(); }
  static const GridRoad& road() { return *road_; }
  static const IsoRoadSpec& spec() { return spec_; }

 private:
  static inline IsoRoadSpec spec_;
  static inline std::shared_ptr<const GridRoad> road_;
};

TEST_F(IsoRoadStatistics, ProfileCoversRequestedLength) {
  const auto& h = road().heights(Track::Left);
  EXPECT_EQ(h.size(), static_cast<std::size_t>(std::llround(spec().length_m / spec().dx_m)) + 1);
  EXPECT_EQ(road().extent().lo, spec().x_begin_m);
  EXPECT_NEAR(road().extent().hi, spec().x_begin_m + spec().length_m, 1e-9);
  const auto d = road().describe();
  EXPECT_EQ(d.at("type"), "iso8608");
  EXPECT_EQ(d.at("class"), "D");
  EXPECT_EQ(d.at("seed").get<unsigned long long>(), 7u);
  EXPECT_EQ(d.at("band_cycles_per_m")[0].get<double>(), spec().n_min);
  EXPECT_EQ(d.at("band_cycles_per_m")[1].get<double>(), spec().n_max);
}

TEST_F(IsoRoadStatistics, RmsMatchesFormula) {
  const double target = isoRmsHeight('D', spec().n_min, spec().n_max);
  for (Track t : kTracks) {
    const double ratio = rms(road().heights(t)) / target;
    RecordProperty(t == Track::Left ? "rms_ratio_left" : "rms_ratio_right", std::to_string(ratio));
    EXPECT_NEAR(ratio, 1.0, 0.05) << "track " << static_cast<int>(t);
  }
}

TEST(WelchEstimator, RecoversPowerOfASinusoid) {
  // Self-check of the test's own estimator: a cosine of amplitude A has band power A^2/2.
  const double dx = 0.05, A = 0.03;
  const std::size_t M = 4096;
  const double n_sig = 300.0 / (M * dx);  // on bin 300
  std::vector<double> x(20 * M);
  for (std::size_t j = 0; j < x.size(); ++j) x[j] = A * std::cos(2 * M_PI * n_sig * j * dx + 0.4);
  const auto psd = welchPsd(x, dx, M);
  const double dn = 1.0 / (M * dx);
  EXPECT_NEAR(bandIntegral(psd, dn, n_sig - 5 * dn, n_sig + 5 * dn) / (0.5 * A * A), 1.0, 1e-12);
  EXPECT_LT(bandIntegral(psd, dn, n_sig + 5 * dn, 0.5 / dx), 1e-20);
}

TEST_F(IsoRoadStatistics, WelchPsdMatchesGdInEveryOctaveBand) {
  const std::size_t M = 16384;  // 819 m segments: dn = 1.2e-3 cycles/m, 41 bins in the lowest band
  const double dn = 1.0 / (static_cast<double>(M) * spec().dx_m);
  const double gd0 = isoClassGd0('D');
  double worst = 0.0;
  for (Track t : kTracks) {
    const auto psd = welchPsd(road().heights(t), spec().dx_m, M);
    int bands = 0;
    for (double lo = 0.05; 2.0 * lo <= 2.0 + 1e-12; lo *= 2.0, ++bands) {
      const double hi = 2.0 * lo;
      const double est = bandIntegral(psd, dn, lo, hi), exact = gdBandIntegral(gd0, lo, hi);
      worst = std::max(worst, std::abs(est / exact - 1.0));
      EXPECT_NEAR(est / exact, 1.0, 0.10)
          << "band [" << lo << ", " << hi << "] cycles/m, track " << static_cast<int>(t);
    }
    EXPECT_EQ(bands, 5);
  }
  RecordProperty("worst_octave_band_error", std::to_string(worst));
  // Outside the generated band (above n_max = 2.83) there is no power.
  const auto psd = welchPsd(road().heights(Track::Left), spec().dx_m, M);
  EXPECT_LT(bandIntegral(psd, dn, 3.2, 9.0), 1e-4 * gdBandIntegral(gd0, 1.6, 2.83));
}

TEST_F(IsoRoadStatistics, TracksAreIndependentAndUncorrelated) {
  const auto& l = road().heights(Track::Left);
  const auto& r = road().heights(Track::Right);
  ASSERT_EQ(l.size(), r.size());
  EXPECT_NE(l, r);
  const double c = correlation(l, r);
  RecordProperty("left_right_correlation", std::to_string(c));
  EXPECT_LT(std::abs(c), 0.1);
  // The slopes are nearly white over the band: many more independent samples, much tighter.
  EXPECT_LT(std::abs(correlation(differences(l), differences(r))), 0.03);
  EXPECT_EQ(road().describe().at("tracks"), "independent");
}

TEST(IsoRoad, CoversRequestedLengthEvenWhenItIsAPowerOfTwoGrid) {
  // 655.36 m = 2^16 * 0.01 m needs 2^16 + 1 points (both ends); the profile must still reach it.
  IsoRoadSpec s;
  s.seed = 3;
  s.dx_m = 0.01;
  s.length_m = 655.36;
  auto road = makeIsoRoad(s);
  EXPECT_GE(road->extent().hi, s.x_begin_m + s.length_m - 1e-9);
  EXPECT_LT(road->extent().hi, s.x_begin_m + s.length_m + s.dx_m + 1e-9);
}

TEST(IsoRoad, IdenticalCoherenceGivesIdenticalTracks) {
  IsoRoadSpec s;
  s.seed = 7;
  s.length_m = 300.0;
  s.coherence = IsoRoadSpec::Coherence::Identical;
  auto road = makeIsoRoad(s);
  EXPECT_EQ(road->heights(Track::Left), road->heights(Track::Right));
  EXPECT_GT(rms(road->heights(Track::Left)), 0.0);
  EXPECT_EQ(road->describe().at("tracks"), "identical");
  // The left track does not depend on the coherence option.
  s.coherence = IsoRoadSpec::Coherence::Independent;
  EXPECT_EQ(makeIsoRoad(s)->heights(Track::Left), road->heights(Track::Left));
}

TEST(IsoRoad, SameSeedIsBitIdenticalDifferentSeedDiffers) {
  IsoRoadSpec s;
  s.seed = 7;
  s.length_m = 500.0;
  auto a = makeIsoRoad(s), b = makeIsoRoad(s);
  for (Track t : kTracks) EXPECT_EQ(a->heights(t), b->heights(t));
  s.seed = 8;
  auto c = makeIsoRoad(s);
  for (Track t : kTracks) {
    const auto& ha = a->heights(t);
    const auto& hc = c->heights(t);
    ASSERT_EQ(ha.size(), hc.size());
    std::size_t same = 0;
    for (std::size_t i = 0; i < ha.size(); ++i) same += ha[i] == hc[i];
    EXPECT_LT(same, ha.size() / 100) << "seeds 7 and 8 give nearly the same profile";
  }
}

TEST(IsoRoad, ClassCHasHalfTheRmsOfClassD) {
  IsoRoadSpec s;
  s.seed = 7;
  s.dx_m = 0.05;
  s.length_m = 5000.0;
  s.road_class = 'D';
  const double rms_d = rms(makeIsoRoad(s)->heights(Track::Left));
  s.road_class = 'C';
  const double rms_c = rms(makeIsoRoad(s)->heights(Track::Left));
  RecordProperty("rms_ratio_C_over_D", std::to_string(rms_c / rms_d));
  EXPECT_NEAR(rms_c / rms_d, 0.5, 0.025);
  EXPECT_DOUBLE_EQ(isoRmsHeight('C', s.n_min, s.n_max) / isoRmsHeight('D', s.n_min, s.n_max), 0.5);
}

TEST(IsoRoad, SmoothUntilGivesZeroThenFullAmplitude) {
  IsoRoadSpec s;
  s.seed = 7;
  s.dx_m = 0.01;
  s.x_begin_m = -20.0;
  s.length_m = 200.0;
  auto full = makeIsoRoad(s);
  s.smooth_until_m = 50.0;
  s.taper_m = 1.5;
  auto smooth = makeIsoRoad(s);
  EXPECT_EQ(smooth->describe().at("smooth_until_m").get<double>(), 50.0);
  for (Track t : kTracks) {
    const auto& hf = full->heights(t);
    const auto& hs = smooth->heights(t);
    ASSERT_EQ(hf.size(), hs.size());
    double before_max = 0.0;
    int in_taper = 0, after = 0;
    for (std::size_t j = 0; j < hs.size(); ++j) {
      const double x = s.x_begin_m + s.dx_m * static_cast<double>(j);
      if (x < s.smooth_until_m - 1e-9) {
        EXPECT_EQ(hs[j], 0.0) << "x = " << x;
        before_max = std::max(before_max, std::abs(hf[j]));
      } else if (x > s.smooth_until_m + s.taper_m + 1e-9) {
        EXPECT_EQ(hs[j], hf[j]) << "x = " << x;
        ++after;
      } else {
        // Raised-cosine taper between the two.
        const double w = 0.5 * (1.0 - std::cos(M_PI * (x - s.smooth_until_m) / s.taper_m));
        EXPECT_NEAR(hs[j], w * hf[j], 1e-9 * std::abs(hf[j]) + 1e-15) << "x = " << x;
        EXPECT_LE(std::abs(hs[j]), std::abs(hf[j]));
        ++in_taper;
      }
    }
    EXPECT_GT(before_max, 0.005)
        << "the untapered profile is not flat there, so the zeros mean something";
    EXPECT_GT(in_taper, 100);
    EXPECT_GT(after, 10000);
    // The interpolated road is flat before the start too.
    EXPECT_EQ(smooth->sample(t, 10.0).height_m, 0.0);
    EXPECT_EQ(smooth->sample(t, 10.0).slope, 0.0);
  }
}

TEST(IsoRoad, RejectsInvalidSpecs) {
  const auto expectRule = [](IsoRoadSpec s, const std::string& rule) {
    try {
      makeIsoRoad(s);
      ADD_FAILURE() << "accepted; expected: " << rule;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
    }
  };
  IsoRoadSpec s;
  s.length_m = 100.0;
  IsoRoadSpec bad = s;
  bad.n_min = 0.0;
  expectRule(bad, "0 < n_min < n_max");
  bad = s;
  bad.n_max = 0.005;
  expectRule(bad, "0 < n_min < n_max");
  bad = s;
  bad.dx_m = 0.1;  // 2.83 cycles/m needs dx < 0.088 m
  expectRule(bad, "points per wavelength");
  bad = s;
  bad.length_m = 0.0;
  expectRule(bad, "length must be > 0");
  bad = s;
  bad.road_class = 'Z';
  expectRule(bad, "A..H");
}

// ------------------------------------------------------------------ CSV

class RoadCsv : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    // The process id keeps concurrent runs (ctest -j, several build trees) apart.
    const std::string path = ::testing::TempDir() + "dtwin_road_test_" +
                             std::to_string(::getpid()) + "_" + name + ".csv";
    std::ofstream out(path, std::ios::binary);
    out << text;
    paths_.push_back(path);
    return path;
  }
  void TearDown() override {
    for (const auto& p : paths_) std::remove(p.c_str());
  }
  /// Loading `path` must throw InputError naming `where` (the path, maybe with ":line") and
  /// containing `rule`.
  static void expectError(const std::string& path, const std::string& where,
                          const std::string& rule) {
    try {
      loadRoadCsv(path);
      ADD_FAILURE() << path << " loaded; expected: " << rule;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.where(), where) << what;
      EXPECT_EQ(what.rfind(where + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(rule), std::string::npos) << what;
    }
  }

 private:
  std::vector<std::string> paths_;
};

TEST_F(RoadCsv, GoodFileLoadsAndInterpolates) {
  std::string text = "distance_m,left_m,right_m\n";
  std::vector<double> l, r;
  for (int i = 0; i <= 20; ++i) {
    l.push_back(0.01 * std::sin(0.5 * i));
    r.push_back(-0.002 * i);
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.6f,%.17g,%.17g\n", 10.0 + 0.1 * i, l.back(), r.back());
    text += buf;
  }
  const std::string path = write("good", text);
  auto road = loadRoadCsv(path);
  ASSERT_TRUE(road);
  EXPECT_NEAR(road->x0(), 10.0, 1e-12);
  EXPECT_NEAR(road->dx(), 0.1, 1e-12);
  EXPECT_NEAR(road->extent().hi, 12.0, 1e-12);
  EXPECT_EQ(road->describe().at("type"), "csv");
  EXPECT_EQ(road->describe().at("path"), path);
  EXPECT_EQ(road->describe().at("rows").get<int>(), 21);
  for (int i = 0; i <= 20; ++i) {
    EXPECT_NEAR(road->sample(Track::Left, 10.0 + 0.1 * i).height_m, l[i], 1e-15) << i;
    EXPECT_NEAR(road->sample(Track::Right, 10.0 + 0.1 * i).height_m, r[i], 1e-15) << i;
  }
  // Between nodes: the right track is linear, so its interpolant is exact.
  EXPECT_NEAR(road->sample(Track::Right, 10.537).height_m, -0.002 * 5.37, 1e-12);
  EXPECT_NEAR(road->sample(Track::Right, 10.537).slope, -0.02, 1e-9);
}

TEST_F(RoadCsv, AcceptsDistancesRoundedToMicrometres) {
  // A uniform grid whose step (1/30 m) is not a whole number of micrometres, written with 6
  // decimals as any export would: the steps then differ by 1 um. That is a uniform grid.
  std::string text = "distance_m,left_m,right_m\n";
  for (int i = 0; i <= 300; ++i) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f,%.6f,0\n", i / 30.0, 0.001 * i);
    text += buf;
  }
  const std::string path = write("rounded", text);
  std::shared_ptr<const GridRoad> road;
  ASSERT_NO_THROW(road = loadRoadCsv(path));
  EXPECT_NEAR(road->dx(), 1.0 / 30.0, 1e-8);
  EXPECT_NEAR(road->sample(Track::Left, 5.0).height_m, 0.15, 1e-6);
}

TEST_F(RoadCsv, AcceptsCrlfAndBlankLines) {
  const std::string path =
      write("crlf", "distance_m,left_m,right_m\r\n0,0,1\r\n\r\n0.5,0.1,1\r\n1.0,0.2,1\r\n");
  auto road = loadRoadCsv(path);
  EXPECT_EQ(road->heights(Track::Left).size(), 3u);
  EXPECT_NEAR(road->sample(Track::Left, 0.75).height_m, 0.15, 1e-12);
}

TEST_F(RoadCsv, HeightsInMillimetresOrCentimetresAreConverted) {
  const std::string mm = write("mm", "distance_m,left_mm,right_mm\n0,0,10\n0.5,25,10\n1.0,50,10\n");
  auto road = loadRoadCsv(mm);
  EXPECT_DOUBLE_EQ(road->sample(Track::Left, 0.5).height_m, 0.025);
  EXPECT_DOUBLE_EQ(road->sample(Track::Right, 0.75).height_m, 0.01);
  const std::string cm = write("cm", "distance_m,left_cm,right_cm\n0,0,1\n0.5,2.5,1\n1.0,5,1\n");
  EXPECT_DOUBLE_EQ(loadRoadCsv(cm)->sample(Track::Left, 1.0).height_m, 0.05);
  // One unit for both tracks.
  const std::string mixed = write("mixed", "distance_m,left_mm,right_m\n0,0,0\n1,0,0\n");
  expectError(
      mixed, mixed + ":1",
      "header must be 'distance_m,left_m,right_m' (or left_mm,right_mm or left_cm,right_cm)");
}

TEST_F(RoadCsv, WrongHeader) {
  const std::string path = write("header", "x,left,right\n0,0,0\n1,0,0\n");
  expectError(path, path + ":1", "header must be 'distance_m,left_m,right_m'");
}

TEST_F(RoadCsv, EmptyFile) {
  const std::string path = write("empty", "");
  expectError(path, path + ":1", "empty file");
}

TEST_F(RoadCsv, NanValueNamesItsLine) {
  const std::string path = write("nan", "distance_m,left_m,right_m\n0,0,0\n0.1,nan,0\n0.2,0,0\n");
  expectError(path, path + ":3", "value 'nan' is not a finite number");
  const std::string path2 = write("text", "distance_m,left_m,right_m\n0,0,0\n0.1,0,0\n0.2,0,abc\n");
  expectError(path2, path2 + ":4", "value 'abc' is not a finite number");
  const std::string path3 = write("inf", "distance_m,left_m,right_m\ninf,0,0\n0.1,0,0\n");
  expectError(path3, path3 + ":2", "not a finite number");
}

TEST_F(RoadCsv, NonIncreasingDistance) {
  const std::string path = write("order", "distance_m,left_m,right_m\n0,0,0\n0.1,0,0\n0.1,0,0\n");
  expectError(path, path + ":4", "distance_m must increase strictly");
  const std::string path2 =
      write("order2", "distance_m,left_m,right_m\n0,0,0\n0.1,0,0\n0.2,0,0\n0.15,0,0\n");
  expectError(path2, path2 + ":5", "distance_m must increase strictly");
}

TEST_F(RoadCsv, NonUniformSpacingNamesTheIrregularLine) {
  // Lines 2..5 are spaced 0.1 m; the step onto line 6 is 0.15 m. The error must name line 6
  // (the row whose step is irregular), not the first row.
  const std::string path =
      write("spacing", "distance_m,left_m,right_m\n0,0,0\n0.1,0,0\n0.2,0,0\n0.3,0,0\n0.45,0,0\n");
  expectError(path, path + ":6", "distance_m must be uniformly spaced");
}

TEST_F(RoadCsv, NonUniformSpacingLineCountsBlankLines) {
  // Line 3 is blank; lines 2, 4, 5 are spaced 0.1 m and the step onto line 6 is 0.15 m.
  const std::string path =
      write("spacing_blank", "distance_m,left_m,right_m\n0,0,0\n\n0.1,0,0\n0.2,0,0\n0.35,0,0\n");
  expectError(path, path + ":6", "distance_m must be uniformly spaced");
}

TEST_F(RoadCsv, TooFewOrTooManyColumns) {
  const std::string path = write("cols", "distance_m,left_m,right_m\n0,0,0\n0.1,0\n");
  expectError(path, path + ":3", "expected 3 columns, got 2");
  const std::string path2 = write("cols2", "distance_m,left_m,right_m\n0,0,0,7\n0.1,0,0\n");
  expectError(path2, path2 + ":2", "expected 3 columns, got more");
}

TEST_F(RoadCsv, TooFewRows) {
  const std::string path = write("rows", "distance_m,left_m,right_m\n0,0,0\n");
  expectError(path, path, "at least 2 rows");
}

TEST_F(RoadCsv, MissingFile) {
  const std::string path = ::testing::TempDir() + "dtwin_road_test_does_not_exist.csv";
  expectError(path, path, "cannot be read (a road profile)");
}

}  // namespace
}  // namespace dtwin
