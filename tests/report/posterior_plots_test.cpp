// The study report's posterior figures and lab view (report/posterior_plots.hpp,
// report/lab_page.hpp) against closed forms: the weighted density integrates to one and is the
// Gaussian of its bandwidth for one atom; the region's projection is the box for an axis-aligned
// region and a zonogon of the right area for a rotated one; the lab view places every repetition
// at its time and counts the points inside the band.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/errors.hpp"
#include "report/lab_page.hpp"
#include "report/posterior_plots.hpp"

using namespace dtwin;
using namespace dtwin::report;

namespace {
constexpr double kPiTest = 3.14159265358979323846;

double trapezoid(const Density& d) {
  double s = 0.0;
  for (std::size_t k = 1; k < d.x.size(); ++k)
    s += 0.5 * (d.f[k] + d.f[k - 1]) * (d.x[k] - d.x[k - 1]);
  return s;
}

/// Shoelace area of a closed polygon.
double area(const std::vector<std::array<double, 2>>& p) {
  double a = 0.0;
  for (std::size_t k = 1; k < p.size(); ++k) a += p[k - 1][0] * p[k][1] - p[k][0] * p[k - 1][1];
  return 0.5 * a;
}

calib::Region region2(double angle, double lo0, double hi0, double lo1, double hi1) {
  calib::Region r;
  r.kind = "joint";
  r.lower = {100.0, -1.0};
  r.upper = {300.0, 1.0};  // scaled widths 200 and 2
  r.centre = Eigen::Vector2d(0.5, 0.5);
  r.axes.resize(2, 2);
  r.axes << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  r.t_lower = Eigen::Vector2d(lo0, lo1);
  r.t_upper = Eigen::Vector2d(hi0, hi1);
  return r;
}
}  // namespace

TEST(PosteriorPlots, DensityIntegratesToOneAndIsTheKernelForOneAtom) {
  const std::vector<double> v{1.0, 1.0, 2.0,
                              2.0, 2.0, 5.0};  // three design points, masses 2/6, 3/6, 1/6
  const Density d = weightedDensity(v, -20.0, 30.0, 2001);
  ASSERT_EQ(d.atoms.size(), 3u);
  EXPECT_DOUBLE_EQ(d.mass[1], 0.5);
  EXPECT_NEAR(trapezoid(d), 1.0, 1e-6);
  EXPECT_GE(d.bandwidth, 1.0 - 1e-12)
      << "never narrower than the design's spacing (median gap 1.0 + 3.0 -> 2.0)";
  EXPECT_DOUBLE_EQ(d.bandwidth, std::max(2.0, d.bandwidth));
  // One atom: the Gaussian N(3, h²) with h the range's 1/200.
  const Density one = weightedDensity({3.0, 3.0, 3.0}, 2.0, 4.0, 201);
  EXPECT_DOUBLE_EQ(one.bandwidth, 0.01);
  EXPECT_NEAR(one.f[100], 1.0 / (0.01 * std::sqrt(2 * kPiTest)), 1e-9);  // at x = 3
  EXPECT_TRUE(weightedDensity({}, 0.0, 1.0).x.empty());
}

TEST(PosteriorPlots, RegionProjectionIsTheBoxOrAZonogonOfItsArea) {
  // Axis-aligned: the rectangle [0.5 - 0.1, 0.5 + 0.2] x [0.5 - 0.3, 0.5 + 0.1], in physical units.
  const auto box = projectedRegion(region2(0.0, -0.1, 0.2, -0.3, 0.1), 0, 1);
  ASSERT_EQ(box.size(), 5u);
  EXPECT_DOUBLE_EQ(box.front()[0], box.back()[0]);
  EXPECT_NEAR(area(box), (0.3 * 200.0) * (0.4 * 2.0), 1e-9);
  double xmin = 1e9, xmax = -1e9;
  for (const auto& p : box) {
    xmin = std::min(xmin, p[0]);
    xmax = std::max(xmax, p[0]);
  }
  EXPECT_NEAR(xmin, 100.0 + 0.4 * 200.0, 1e-9);
  EXPECT_NEAR(xmax, 100.0 + 0.7 * 200.0, 1e-9);
  // Rotated by 30°: a parallelogram (here a rotated rectangle) of the same area, counter-clockwise.
  const auto rot = projectedRegion(region2(kPiTest / 6, -0.1, 0.2, -0.3, 0.1), 0, 1);
  EXPECT_NEAR(area(rot), (0.3 * 200.0) * (0.4 * 2.0), 1e-9);
  // The swapped pair (1, 0) is the mirror image: the same area, clockwise... drawn the same way.
  EXPECT_NEAR(std::abs(area(projectedRegion(region2(kPiTest / 6, -0.1, 0.2, -0.3, 0.1), 1, 0))),
              (0.3 * 200.0) * (0.4 * 2.0), 1e-9);
}

TEST(PosteriorPlots, CorrelationOfALineIsOne) {
  EXPECT_NEAR(sampleCorrelation({1, 2, 3, 4}, {2, 4, 6, 8}), 1.0, 1e-12);
  EXPECT_NEAR(sampleCorrelation({1, 2, 3, 4}, {8, 6, 4, 2}), -1.0, 1e-12);
  EXPECT_EQ(sampleCorrelation({1, 1, 1}, {1, 2, 3}), 0.0);
}

TEST(LabPage, EveryRepetitionAtItsTimeAndTheBandsCoverage) {
  classify::LabBands b;
  b.draws = 10;
  for (long rep : {1L, 2L})
    for (double t : {0.5, 1.0})
      b.lab.records.push_back(
          LabRecord{rep, t, "hub_force_fl_N", t * 100.0 + (rep == 1 ? 1.0 : 30.0)});
  classify::AssemblyBands a;
  a.assembly.id = "M1";
  classify::ChannelBand g;
  g.channel = "hub_force_fl_N";
  g.times = {0.0, 0.25, 0.5, 0.75, 1.0};
  for (double t : g.times) {
    g.med.push_back(t * 100.0);
    g.lo.push_back(t * 100.0 - 1.0);
    g.hi.push_back(t * 100.0 + 1.0);
    g.plo.push_back(t * 100.0 - 10.0);
    g.phi.push_back(t * 100.0 + 10.0);
  }
  a.channels = {g};
  b.assemblies.push_back(a);
  const auto data = labPageData(b, "lab view");
  const auto& c = data["sets"][0]["channels"][0];
  // One series of points: the grid's 5 times, and repetition 2 a step after each of the 2 lab
  // times.
  ASSERT_EQ(c["points"].size(), 1u);
  EXPECT_EQ(c["points"][0]["label"], "lab data (2 repetitions)");
  const auto& v = c["points"][0]["v"];
  ASSERT_EQ(c["t"].size(), 7u);
  ASSERT_EQ(v.size(), 7u);
  EXPECT_EQ(v[2], 51.0);  // repetition 1 at t = 0.5
  EXPECT_EQ(v[3], 80.0);  // repetition 2 just after
  EXPECT_GT(c["t"][3].get<double>(), 0.5);
  EXPECT_LT(c["t"][3].get<double>(), 0.5 + 1e-6);
  EXPECT_TRUE(v[1].is_null());
  EXPECT_EQ(v[6], 130.0);
  EXPECT_EQ(c["models"][0]["p"][3], 50.0);  // the model at the repeated time is its value at 0.5
  ASSERT_EQ(c["models"].size(), 1u);
  EXPECT_DOUBLE_EQ(c["models"][0]["coverage"].get<double>(),
                   0.5);  // repetition 1 inside (±1), 2 outside (30 > 10)
  EXPECT_NEAR(c["models"][0]["rms"].get<double>(), std::sqrt((1.0 + 1.0 + 900.0 + 900.0) / 4.0),
              1e-12);
  EXPECT_TRUE(data["no_windows"].get<bool>());
  b.assemblies[0].channels.clear();
  EXPECT_THROW(labPageData(b, "x"), InputError);
}
