// Profile-likelihood intervals: the threshold against its definition, the refinement of the ends
// on a narrow ridge the design misses, and the case that made them the default: a valley of equal
// fits from a steep wall to a bound, with the truth just inside the wall, where the posterior's
// central interval (prior volume along the valley) excludes the truth and the profile holds it.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "calibration/adaptive_design.hpp"
#include "calibration/gibbs.hpp"
#include "calibration/lhs.hpp"
#include "calibration/profile.hpp"
#include "calibration/summary.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::calib;

namespace {

// SSE(z) = SSE0 + K max(w − z1, 0)² + B (z2 − 0.5)² on the unit square: flat in z1 from the wall
// at w up to the bound 1.
constexpr double kSse0 = 46.0, kK = 5e5, kB = 2e4, kWall = 0.3;
constexpr int kN = 48;  // n − d = 46: s² = 1
double valley(const std::vector<double>& z) {
  const double a = std::max(kWall - z[0], 0.0), b = z[1] - 0.5;
  return kSse0 + kK * a * a + kB * b * b;
}
std::vector<double> valleyResiduals(const std::vector<double>& z) {
  return {std::sqrt(kK) * std::max(kWall - z[0], 0.0), std::sqrt(kB) * (z[1] - 0.5),
          std::sqrt(kSse0)};
}

}  // namespace

TEST(Profile, ThresholdIsTheFQuantileOfTheEstimatedVariance) {
  Eigen::MatrixXd pts(3, 1);
  pts << 0.2, 0.5, 0.9;
  const ProfilePlan p = planProfile(pts, {50.0, 46.0, 1e9}, kN, {0.0}, {1.0}, {});
  EXPECT_EQ(p.dof, 47);
  EXPECT_DOUBLE_EQ(p.sse_best, 46.0);
  EXPECT_NEAR(p.s2, 46.0 / 47.0, 1e-15);
  const double t = studentQuantile(0.975, 47.0);
  EXPECT_NEAR(p.c, t * t, 1e-12);
  EXPECT_NEAR(p.threshold, 46.0 + t * t * 46.0 / 47.0, 1e-9);
  // Inside (<= 46 + 3.95): 0.2 (SSE 50 > threshold? 50 > 49.95, outside) and 0.5.
  EXPECT_DOUBLE_EQ(p.low_point[0][0], 0.5);
  EXPECT_DOUBLE_EQ(p.high_point[0][0], 0.5);
  // The point of the best SSE, which a calibration takes as its optimum when it beats the
  // optimiser's.
  ASSERT_EQ(p.best_point.size(), 1u);
  EXPECT_DOUBLE_EQ(p.best_point[0], 0.5);
  EXPECT_THROW(planProfile(pts, {INFINITY, NAN, INFINITY}, kN, {0.0}, {1.0}, {}), InputError);
}

TEST(Profile, ValleyToABoundThePosteriorMissesAndTheProfileHolds) {
  // A uniform design over the square (the paper's Griddy Gibbs over it is the flat-prior
  // posterior).
  const Eigen::MatrixXd x = latinHypercube(20000, {0.0, 0.0}, {1.0, 1.0}, 5);
  std::vector<double> sse;
  for (Eigen::Index k = 0; k < x.rows(); ++k) sse.push_back(valley({x(k, 0), x(k, 1)}));
  GibbsOptions go;
  go.iterations = 30000;
  go.burn_in = 2000;
  const GibbsChains chains = runGriddyGibbs(sse, kN, go);
  const PosteriorSummary post = summarisePosterior(x, chains, {"z1", "z2"});
  const double truth = kWall + 0.01;  // a truth just inside the wall: SSE there is SSE0
  EXPECT_GT(post.parameters[0].q025, truth)
      << "the posterior spreads over the valley and its central interval misses the wall end";
  const ProfileOptions po;
  const ProfilePlan plan = planProfile(x, sse, kN, {0.0, 0.0}, {1.0, 1.0}, po);
  std::vector<ProfileEnd> ends;
  for (int i = 0; i < 4; ++i) ends.push_back(refineProfileEnd(valleyResiduals, plan, i, po));
  const ProfileIntervals prof = collectProfile(plan, ends, po);
  // Exact: z1 from w − sqrt((threshold − SSE0)/K) up to the bound.
  const double exact_lo = kWall - std::sqrt((plan.threshold - kSse0) / kK);
  EXPECT_LE(prof.lower[0], truth);
  EXPECT_NEAR(prof.lower[0], exact_lo, 0.01 * (1.0 - exact_lo));
  EXPECT_GE(prof.lower[0], exact_lo - 1e-12);
  EXPECT_DOUBLE_EQ(prof.upper[0], 1.0);
  EXPECT_TRUE(prof.upper_at_bound[0]);
  // z2: 0.5 ± sqrt((threshold − SSE0)/B).
  const double half = std::sqrt((plan.threshold - kSse0) / kB);
  EXPECT_NEAR(prof.lower[1], 0.5 - half, 0.02 * half);
  EXPECT_NEAR(prof.upper[1], 0.5 + half, 0.02 * half);
}

// A narrow tilted ridge the design samples sparsely: the refinement walks the ends out to the
// exact profile interval of the quadratic.
TEST(Profile, RefinementReachesTheEndsTheDesignMissed) {
  // SSE = 46 + (z − m)ᵀ H (z − m), correlation −0.995 in H's inverse.
  Eigen::Matrix2d H;
  H << 1e4, 0.995e4, 0.995e4, 1e4;
  const Eigen::Vector2d m(0.5, 0.5);
  const Eigen::Matrix2d R = H.llt().matrixU();
  auto f = [&](const std::vector<double>& z) {
    const Eigen::Vector2d e = Eigen::Vector2d(z[0], z[1]) - m;
    return 46.0 + e.dot(H * e);
  };
  auto res = [&](const std::vector<double>& z) {
    const Eigen::Vector2d e = R * (Eigen::Vector2d(z[0], z[1]) - m);
    return std::vector<double>{e(0), e(1), std::sqrt(46.0)};
  };
  const Eigen::MatrixXd x = latinHypercube(100, {0.4, 0.4}, {0.6, 0.6}, 3);
  std::vector<double> sse;
  for (Eigen::Index k = 0; k < x.rows(); ++k) sse.push_back(f({x(k, 0), x(k, 1)}));
  const ProfileOptions po;
  const ProfilePlan plan = planProfile(x, sse, kN, {0.0, 0.0}, {1.0, 1.0}, po);
  const double exact_half = std::sqrt((plan.threshold - 46.0) * H.inverse()(0, 0));
  const double design_half = 0.5 * (plan.high_point[0][0] - plan.low_point[0][0]);
  EXPECT_LT(design_half, 0.8 * exact_half) << "the design alone should fall short";
  std::vector<ProfileEnd> ends;
  for (int i = 0; i < 4; ++i) ends.push_back(refineProfileEnd(res, plan, i, po));
  const ProfileIntervals prof = collectProfile(plan, ends, po);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(prof.lower[static_cast<std::size_t>(j)], 0.5 - exact_half, 0.02 * exact_half) << j;
    EXPECT_NEAR(prof.upper[static_cast<std::size_t>(j)], 0.5 + exact_half, 0.02 * exact_half) << j;
    EXPECT_GE(prof.lower[static_cast<std::size_t>(j)], 0.5 - exact_half - 1e-9);
    EXPECT_LE(prof.upper[static_cast<std::size_t>(j)], 0.5 + exact_half + 1e-9);
  }
  EXPECT_GT(prof.evaluations, 0);
  const auto back = ProfileIntervals::fromJson(nlohmann::json::parse(prof.toJson().dump()));
  EXPECT_EQ(back.lower, prof.lower);
  EXPECT_EQ(back.upper_at_bound, prof.upper_at_bound);
}

// On a quadratic profile the secant through two profile points lands on the crossing: the end
// stops there, within 1 % of the width, without an outside point to bracket it (whose polish and
// restarts would cost more than the end's other points together).
TEST(Profile, AnEndTheSecantPutsOnTheCrossingStopsWithoutAnOutsidePoint) {
  Eigen::Matrix2d H;
  H << 1e4, 0.6e4, 0.6e4, 1e4;
  const Eigen::Vector2d m(0.5, 0.5);
  const Eigen::Matrix2d R = H.llt().matrixU();
  auto res = [&](const std::vector<double>& z) {
    const Eigen::Vector2d e = R * (Eigen::Vector2d(z[0], z[1]) - m);
    return std::vector<double>{e(0), e(1), std::sqrt(46.0)};
  };
  // The design and the optimum, as a calibration's evaluated points hold it.
  Eigen::MatrixXd x(61, 2);
  x.topRows(60) = latinHypercube(60, {0.45, 0.45}, {0.55, 0.55}, 4);
  x.row(60) << m(0), m(1);
  std::vector<double> sse;
  for (Eigen::Index k = 0; k < x.rows(); ++k) {
    const auto r = res({x(k, 0), x(k, 1)});
    sse.push_back(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  }
  const ProfileOptions po;
  const ProfilePlan plan = planProfile(x, sse, kN, {0.0, 0.0}, {1.0, 1.0}, po);
  const double exact_half = std::sqrt((plan.threshold - 46.0) * H.inverse()(0, 0));
  for (int i = 0; i < 4; ++i) {
    const ProfileEnd e = refineProfileEnd(res, plan, i, po);
    const int j = i / 2;
    const double exact = 0.5 + (i % 2 == 0 ? -exact_half : exact_half);
    EXPECT_NEAR(e.theta[static_cast<std::size_t>(j)], exact, 0.01 * 2 * exact_half) << "end " << i;
    EXPECT_LE(std::abs(e.theta[static_cast<std::size_t>(j)] - 0.5), exact_half + 1e-9)
        << "end " << i << " overshoots";
    EXPECT_GE(e.steps_taken, 1) << "end " << i;
    EXPECT_EQ(e.outside_points, 0) << "end " << i << " (" << e.evaluations << " runs)";
  }
}

// A profile whose √(SSE − SSE*) curves (a cubic term in the residual of θ_0): the secant
// overshoots, and the bracket's interpolation, each point aimed half a tolerance short of the
// predicted crossing, closes it. The end lands within 1 % of the width of the exact crossing
// (found by bisection on the closed-form profile), never past it, with at most one outside point
// (aimed at the crossing itself, the lower end took two and 30 runs, not one and 18).
TEST(Profile, ACurvedProfileIsBracketedWithFewOutsidePoints) {
  const double a = 100.0, b = 4e4, rho = 0.6;
  auto res = [&](const std::vector<double>& z) {
    const double e0 = z[0] - 0.5, e1 = z[1] - 0.5;
    return std::vector<double>{a * e0 + b * e0 * e0 * e0,
                               a * (e1 - rho * e0) / std::sqrt(1 - rho * rho), std::sqrt(46.0)};
  };
  auto sseOf = [&](double z0, double z1) {
    const auto r = res({z0, z1});
    return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  };
  Eigen::MatrixXd x(61, 2);
  x.topRows(60) = latinHypercube(60, {0.48, 0.48}, {0.52, 0.52}, 5);
  x.row(60) << 0.5, 0.5;
  std::vector<double> sse;
  for (Eigen::Index k = 0; k < x.rows(); ++k) sse.push_back(sseOf(x(k, 0), x(k, 1)));
  const ProfileOptions po;
  const ProfilePlan plan = planProfile(x, sse, kN, {0.0, 0.0}, {1.0, 1.0}, po);
  // The profile in θ_0 is 46 + (a e + b e³)² (θ_1 takes up the rest): its crossing of the
  // threshold.
  auto crossing = [&](double sign) {
    double lo = 0.0, hi = 0.5;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi), g = a * mid + b * mid * mid * mid;
      (46.0 + g * g > plan.threshold ? hi : lo) = mid;
    }
    return 0.5 + sign * lo;
  };
  const double width = crossing(1) - crossing(-1);
  for (int i = 0; i < 2; ++i) {
    const ProfileEnd e = refineProfileEnd(res, plan, i, po);
    const double exact = crossing(i == 0 ? -1 : 1);
    EXPECT_NEAR(e.theta[0], exact, 0.01 * width) << "end " << i;
    EXPECT_LE(e.sse, plan.threshold) << "end " << i;
    EXPECT_LE(e.outside_points, 1) << "end " << i << " (" << e.evaluations << " runs)";
  }
}
