// The joint region against the analytic 1 % contour of a correlated quadratic SSE: its axes are
// the Hessian's eigenvectors, its extents margin x the ellipsoid's semi-axes, it holds the whole
// contour (not only the axis-wise cross-sections the paper's box holds); the ray sweep, the
// Gaussian guess, clipping at the bounds, failed stencil runs and the JSON round trip.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "calibration/feasible_box.hpp"
#include "calibration/lhs.hpp"
#include "calibration/region.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::calib;

namespace {

// SSE(θ) = SSE_min + (z − ẑ)ᵀ H (z − ẑ) in scaled z, as weighted residuals r = sqrt(2)... :
// r(z) = R (z − ẑ) plus a constant block so that |r|² = SSE. R is the Cholesky factor of H.
struct Quadratic {
  std::vector<double> lower{100.0, -5.0, 0.0}, upper{300.0, 5.0, 1.0};
  Eigen::Matrix3d H;
  Eigen::Vector3d zhat{0.5, 0.45, 0.6};
  double sse_min = 500.0;
  int n = 100;
  Quadratic() {
    // Strong correlation between the first two parameters (a ridge), the third independent.
    H << 4.0e4, -3.96e4, 0.0, -3.96e4, 4.0e4, 0.0, 0.0, 0.0, 1.0e5;
  }
  Eigen::Vector3d scaled(const std::vector<double>& th) const {
    Eigen::Vector3d z;
    for (int j = 0; j < 3; ++j) z(j) = (th[j] - lower[j]) / (upper[j] - lower[j]);
    return z;
  }
  double sse(const std::vector<double>& th) const {
    const Eigen::Vector3d e = scaled(th) - zhat;
    return sse_min + e.dot(H * e);
  }
  std::vector<double> residuals(const std::vector<double>& th) const {
    const Eigen::Matrix3d R = H.llt().matrixU();
    const Eigen::Vector3d r = R * (scaled(th) - zhat);
    return {r(0), r(1), r(2), std::sqrt(sse_min)};
  }
  BoxProblem problem() const {
    BoxProblem p;
    for (int j = 0; j < 3; ++j) p.theta_hat.push_back(lower[j] + zhat(j) * (upper[j] - lower[j]));
    p.sse_min = sse_min;
    p.n_data = n;
    p.lower = lower;
    p.upper = upper;
    return p;
  }
};

}  // namespace

TEST(Region, JointRegionHoldsTheAnalyticContourOnItsPrincipalAxes) {
  const Quadratic q;
  JointRegionOptions o;
  const Region r = calcJointRegion([&](const std::vector<double>& t) { return q.sse(t); },
                                   [&](const std::vector<double>& t) { return q.residuals(t); }, q.problem(), o);
  EXPECT_EQ(r.kind, "joint");
  const double dT = r.threshold - q.sse_min;
  EXPECT_DOUBLE_EQ(r.threshold, q.sse_min * (1 + 2 * std::log(100.0) / q.n));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(q.H);
  for (int i = 0; i < 3; ++i) {
    // Axis i is an eigenvector of H (up to sign) ...
    const Eigen::Vector3d a = r.axes.col(i);
    const double lam = a.dot(q.H * a);
    EXPECT_NEAR((q.H * a - lam * a).norm() / lam, 0.0, 1e-6) << "axis " << i;
    // ... and its extents are margin x the semi-axis sqrt(ΔT/λ), to the bisection tolerance.
    const double semi = std::sqrt(dT / lam);
    EXPECT_NEAR(r.t_upper(i), o.margin * semi, o.margin * o.relative_tolerance * semi * 1.01) << "axis " << i;
    EXPECT_NEAR(-r.t_lower(i), o.margin * semi, o.margin * o.relative_tolerance * semi * 1.01) << "axis " << i;
    EXPECT_GE(r.t_upper(i), o.margin * semi * 0.999);  // the outer end of the bracket: conservative
    // The Gaussian guess has the contour's semi-axis as its 3.03-sigma point.
    EXPECT_NEAR(r.guess_sd(i), semi / std::sqrt(2 * std::log(100.0)), 0.06 * semi);
  }
  // Every point of the analytic contour lies in the region; the paper's box misses most of it.
  const Eigen::Matrix3d L = (q.H / dT).llt().matrixL();
  BoxProblem bp = q.problem();
  const FeasibleBox box = calcFeasibleBox([&](const std::vector<double>& t) { return q.sse(t); }, bp);
  const Region paper = regionFromBox(box, bp);
  int outside_paper = 0, total = 0;
  const Eigen::MatrixXd u = latinHypercube(2000, {-1, -1, -1}, {1, 1, 1}, 5);
  for (Eigen::Index k = 0; k < u.rows(); ++k) {
    Eigen::Vector3d x = u.row(k).transpose();
    x.normalize();  // a direction; the contour point along it
    const Eigen::Vector3d z = q.zhat + L.transpose().triangularView<Eigen::Upper>().solve(x);
    ++total;
    EXPECT_TRUE(r.contains(z)) << "contour point " << z.transpose() << " outside the joint region";
    outside_paper += paper.contains(z) ? 0 : 1;
  }
  EXPECT_GT(outside_paper, total / 2) << "the paper's box should miss most of a ridge's contour";
  // Its bounding box holds the contour's bounding box (θ_j ± sqrt(ΔT [H⁻¹]_jj) in scaled units).
  std::vector<double> lo, hi;
  r.boundingBox(lo, hi);
  const Eigen::Matrix3d Hi = q.H.inverse();
  for (int j = 0; j < 3; ++j) {
    const double half = std::sqrt(dT * Hi(j, j)) * (q.upper[j] - q.lower[j]);
    EXPECT_LE(lo[j], q.problem().theta_hat[j] - half);
    EXPECT_GE(hi[j], q.problem().theta_hat[j] + half);
  }
}

TEST(Region, ExtentsStopAtTheReachOfTheBounds) {
  Quadratic q;
  q.H *= 1e-4;  // a flat SSE: the contour is far wider than the bounds
  const Region r = calcJointRegion([&](const std::vector<double>& t) { return q.sse(t); },
                                   [&](const std::vector<double>& t) { return q.residuals(t); }, q.problem());
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.t_upper(i), r.reach_upper(i), 1e-12);
    EXPECT_NEAR(-r.t_lower(i), r.reach_lower(i), 1e-12);
    EXPECT_FALSE(r.openUpper(i));
    EXPECT_FALSE(r.openLower(i));
  }
  // The region then spans the whole cube.
  std::vector<double> lo, hi;
  r.boundingBox(lo, hi);
  for (int j = 0; j < 3; ++j) {
    EXPECT_DOUBLE_EQ(lo[j], q.lower[j]);
    EXPECT_DOUBLE_EQ(hi[j], q.upper[j]);
  }
}

TEST(Region, FailedStencilRunLeavesTheParameterUnidentifiedAndSaysSo) {
  const Quadratic q;
  const BoxProblem bp = q.problem();
  const auto stencil = jacobianStencil(bp, {});
  ASSERT_EQ(stencil.size(), 6u);
  std::vector<std::vector<double>> res;
  for (std::size_t k = 0; k < stencil.size(); ++k) res.push_back(k == 4 ? std::vector<double>{} : q.residuals(stencil[k]));
  const JointRegionPlan plan = planJointRegion(bp, res, {});
  ASSERT_EQ(plan.messages.size(), 1u);
  EXPECT_NE(plan.messages[0].find("parameter 2: a simulation of the Jacobian stencil failed"), std::string::npos) << plan.messages[0];
  EXPECT_NEAR(plan.eigenvalues(0), 0.0, 1e-9);  // the zero column
}

TEST(Region, RaySweepFindsTheCrossingWithRelativeTolerance) {
  FeasibleBoxOptions o;
  o.max_evaluations = 60;
  // SSE = 1 + t²: crossing of 2 at t = 1.
  const RaySweep s = sweepRay([](double t) { return 1 + t * t; }, 10.0, 2.0, 1.0, o, 0.01, 1e-3);
  EXPECT_TRUE(s.bracketed);
  EXPECT_FALSE(s.clipped);
  EXPECT_GE(s.t_edge, 1.0);
  EXPECT_LE(s.t_edge - 1.0, 1.1e-3);
  // A contour past t_max is clipped there; a non-finite SSE counts as outside.
  const RaySweep c = sweepRay([](double t) { return 1 + t * t; }, 0.5, 2.0, 1.0, o, 0.01);
  EXPECT_TRUE(c.clipped);
  EXPECT_DOUBLE_EQ(c.t_edge, 0.5);
  const RaySweep f = sweepRay([](double t) { return t > 0.3 ? std::numeric_limits<double>::infinity() : 1.0; }, 10.0, 2.0, 1.0, o, 0.01, 1e-3);
  EXPECT_TRUE(f.bracketed);
  EXPECT_NEAR(f.t_edge, 0.3, 1e-3);
}

TEST(Region, JsonRoundTripKeepsEverything) {
  const Quadratic q;
  const Region r = calcJointRegion([&](const std::vector<double>& t) { return q.sse(t); },
                                   [&](const std::vector<double>& t) { return q.residuals(t); }, q.problem());
  const Region b = Region::fromJson(nlohmann::json::parse(r.toJson().dump()));
  EXPECT_EQ(b.kind, r.kind);
  EXPECT_EQ(b.lower, r.lower);
  EXPECT_TRUE(b.axes.isApprox(r.axes, 0));
  EXPECT_TRUE(b.t_lower.isApprox(r.t_lower, 0));
  EXPECT_TRUE(b.t_upper.isApprox(r.t_upper, 0));
  EXPECT_TRUE(b.guess_sd.isApprox(r.guess_sd, 0));
  EXPECT_DOUBLE_EQ(b.logVolume(), r.logVolume());
}

TEST(Region, PaperRegionIsTheAxisAlignedBox) {
  const Quadratic q;
  const BoxProblem bp = q.problem();
  const FeasibleBox box = calcFeasibleBox([&](const std::vector<double>& t) { return q.sse(t); }, bp);
  const Region r = regionFromBox(box, bp);
  EXPECT_EQ(r.kind, "paper");
  EXPECT_TRUE(r.axes.isIdentity());
  std::vector<double> lo, hi;
  r.boundingBox(lo, hi);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(lo[j], box.lower[j], 1e-9 * (q.upper[j] - q.lower[j]));
    EXPECT_NEAR(hi[j], box.upper[j], 1e-9 * (q.upper[j] - q.lower[j]));
  }
}

TEST(Region, BadOptionsAreNamed) {
  JointRegionOptions o;
  o.margin = 0.5;
  try {
    o.validate();
    FAIL() << "margin 0.5 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "joint_region.margin");
    EXPECT_EQ(e.rule(), "must be a finite number >= 1, got 0.5");
  }
}
