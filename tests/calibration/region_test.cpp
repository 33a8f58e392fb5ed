// The joint region against the analytic 1 % contour of a correlated quadratic SSE: its axes are
// the Hessian's eigenvectors, its extents margin x the ellipsoid's semi-axes, it holds the whole
// contour (not only the axis-wise cross-sections the paper's box holds); the ray sweep, the
// Gaussian guess, clipping at the bounds, failed stencil runs and the JSON round trip.
#include <gtest/gtest.h>

#include <random>

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
  const Region r =
      calcJointRegion([&](const std::vector<double>& t) { return q.sse(t); },
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
    EXPECT_NEAR(r.t_upper(i), o.margin * semi, o.margin * o.relative_tolerance * semi * 1.01)
        << "axis " << i;
    EXPECT_NEAR(-r.t_lower(i), o.margin * semi, o.margin * o.relative_tolerance * semi * 1.01)
        << "axis " << i;
    EXPECT_GE(r.t_upper(i), o.margin * semi * 0.999);  // the outer end of the bracket: conservative
    // The Gaussian guess has the contour's semi-axis as its 3.03-sigma point.
    EXPECT_NEAR(r.guess_sd(i), semi / std::sqrt(2 * std::log(100.0)), 0.06 * semi);
  }
  // Every point of the analytic contour lies in the region; the paper's box misses most of it.
  const Eigen::Matrix3d L = (q.H / dT).llt().matrixL();
  BoxProblem bp = q.problem();
  const FeasibleBox box =
      calcFeasibleBox([&](const std::vector<double>& t) { return q.sse(t); }, bp);
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
  const Region r =
      calcJointRegion([&](const std::vector<double>& t) { return q.sse(t); },
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
  for (std::size_t k = 0; k < stencil.size(); ++k)
    res.push_back(k == 4 ? std::vector<double>{} : q.residuals(stencil[k]));
  const JointRegionPlan plan = planJointRegion(bp, res, {});
  ASSERT_EQ(plan.messages.size(), 1u);
  EXPECT_NE(plan.messages[0].find("parameter 2: a simulation of the Jacobian stencil failed"),
            std::string::npos)
      << plan.messages[0];
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
  const RaySweep f =
      sweepRay([](double t) { return t > 0.3 ? std::numeric_limits<double>::infinity() : 1.0; },
               10.0, 2.0, 1.0, o, 0.01, 1e-3);
  EXPECT_TRUE(f.bracketed);
  EXPECT_NEAR(f.t_edge, 0.3, 1e-3);
}

TEST(Region, JsonRoundTripKeepsEverything) {
  const Quadratic q;
  const Region r =
      calcJointRegion([&](const std::vector<double>& t) { return q.sse(t); },
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
  const FeasibleBox box =
      calcFeasibleBox([&](const std::vector<double>& t) { return q.sse(t); }, bp);
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

// The region of a first-order low-pass candidate on null data (τ's optimum on its lower bound,
// 0): a clipped sweep took the bounds' whole reach along an axis that leaves the cube steeply, so
// only 4e-5 of P lay inside the bounds and the first design round drew none of 2560 points there.
// Narrowed, P ∩ [0, 1]^d is unchanged (every inside point of P is in the narrowed region) and
// enough of the narrowed region is inside for a round to fill (3 % here, not 0.004 %).
TEST(Region, NarrowingToTheCubeKeepsEveryInsidePointAndDropsTheOutside) {
  Region r;
  r.kind = "joint";
  r.lower.assign(5, 0.0);
  r.upper.assign(5, 1.0);
  r.centre = (Eigen::VectorXd(5) << 0.08877413463783913, 0.38435170252447104, 0.11754107502685072,
              0.06774368808923359, 0.0009445007594765247)
                 .finished();
  const double cols[5][5] = {{0.26712290933346494, 0.9600538513766921, 0.01713319610429118,
                              -0.010802052682654106, 0.08081907581195638},
                             {0.8423096274602613, -0.26991726337730676, -0.11872599186803139,
                              -0.14046622896892394, 0.4287569705472597},
                             {-0.41548832031108046, 0.03895161274766554, 0.1099822071752355,
                              0.08263521582057747, 0.8982914687119005},
                             {0.14085767965724175, -0.05305123259782617, 0.9865800955220901,
                              -0.03911709300107349, -0.0497418230083927},
                             {0.16336588555643028, -0.03331083865490487, 0.013199305689742693,
                              0.985796037889443, -0.015294622429337526}};
  r.axes.resize(5, 5);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) r.axes(j, i) = cols[i][j];
  r.t_lower = (Eigen::VectorXd(5) << -0.4048724071720531, -0.4770757129335271, -0.4129487010243425,
               -0.0019234446530410594, -0.0009849412048386773)
                  .finished();
  r.t_upper = (Eigen::VectorXd(5) << 0.059416519268255495, 0.006026251066001799,
               0.003488107629418721, 0.35931745146947547, 0.11092731175566213)
                  .finished();
  const Region n = narrowedToCube(r);
  for (int i = 0; i < 5; ++i) {
    EXPECT_LE(n.t_lower(i), 0.0);
    EXPECT_GE(n.t_upper(i), 0.0);
    EXPECT_GE(n.t_lower(i), r.t_lower(i));
    EXPECT_LE(n.t_upper(i), r.t_upper(i));
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto share = [&](const Region& g, int draws, int* kept_outside) {
    int in = 0;
    for (int k = 0; k < draws; ++k) {
      Eigen::VectorXd t(5);
      for (int i = 0; i < 5; ++i) t(i) = g.t_lower(i) + u(rng) * (g.t_upper(i) - g.t_lower(i));
      const Eigen::VectorXd z = g.at(t);
      if (!insideUnitCube(z)) continue;
      ++in;
      if (kept_outside && !n.contains(z)) ++*kept_outside;
    }
    return static_cast<double>(in) / draws;
  };
  int lost = 0;
  const double before = share(r, 400000, &lost);
  EXPECT_EQ(lost, 0) << "an inside point of P fell outside the narrowed region";
  EXPECT_LT(before, 1e-3);
  // drawRound draws at most 64 points for each it needs inside: a share above 1/64 fills a round.
  const double after = share(n, 20000, nullptr);
  EXPECT_GT(after, 1.0 / 64.0);
  EXPECT_GT(n.logVolume(), -1e9);
  // A region inside the cube is left as it is.
  Region inner = r;
  inner.centre = Eigen::VectorXd::Constant(5, 0.5);
  inner.axes = Eigen::MatrixXd::Identity(5, 5);
  inner.t_lower = Eigen::VectorXd::Constant(5, -0.1);
  inner.t_upper = Eigen::VectorXd::Constant(5, 0.2);
  const Region same = narrowedToCube(inner);
  EXPECT_EQ(same.t_lower, inner.t_lower);
  EXPECT_EQ(same.t_upper, inner.t_upper);
}
