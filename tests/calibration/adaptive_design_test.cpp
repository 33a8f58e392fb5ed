// The adaptive design: the normal quantile, the mixture density against direct formulas, the
// design-weighted Griddy Gibbs against exact frequencies, importance weights that recover a known
// posterior from a curved (banana) ridge, determinism, and one round = the paper's sampler.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "calibration/adaptive_design.hpp"
#include "calibration/gibbs.hpp"
#include "calibration/lhs.hpp"
#include "calibration/region.hpp"
#include "calibration/summary.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::calib;

namespace {

/// A region: the unit square's centre part, axes rotated by 30 degrees.
Region square() {
  Region r;
  r.kind = "joint";
  r.lower = {0.0, 0.0};
  r.upper = {2.0, 4.0};
  r.centre = Eigen::Vector2d(0.5, 0.5);
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  r.axes.resize(2, 2);
  r.axes << c, -s, s, c;
  r.t_lower = Eigen::Vector2d(-0.3, -0.2);
  r.t_upper = Eigen::Vector2d(0.4, 0.2);
  r.reach_lower = r.reach_upper = Eigen::Vector2d(0.7, 0.7);
  r.guess_mean = r.centre;
  r.guess_sd = Eigen::Vector2d(0.1, 0.05);
  return r;
}

}  // namespace

TEST(NormalQuantile, MatchesReferenceValues) {
  EXPECT_DOUBLE_EQ(normalQuantile(0.5), 0.0);
  EXPECT_NEAR(normalQuantile(0.975), 1.959963984540054, 1e-14);
  EXPECT_NEAR(normalQuantile(0.025), -1.959963984540054, 1e-14);
  EXPECT_NEAR(normalQuantile(0.8413447460685429), 1.0, 1e-13);
  EXPECT_NEAR(normalQuantile(1e-10), -6.361340902404056, 1e-12);
  EXPECT_NEAR(normalQuantile(1e-12), -7.0344838253011, 1e-9);
  EXPECT_NEAR(normalQuantile(0.3), -normalQuantile(0.7), 1e-15);
  EXPECT_THROW(normalQuantile(0.0), InputError);
  EXPECT_THROW(normalQuantile(1.0), InputError);
}

TEST(AdaptiveDesign, MixtureDensityMatchesDirectFormulas) {
  DesignRound u;
  u.kind = "uniform";
  u.region = square();
  u.drawn = 300;
  const double vol = 0.7 * 0.4;
  const Eigen::Vector2d inside = u.region.at(Eigen::Vector2d(0.1, 0.1)),
                        outside = u.region.at(Eigen::Vector2d(0.5, 0.0));
  EXPECT_NEAR(logMixtureDensity({u}, inside), std::log(300 / vol), 1e-12);
  EXPECT_EQ(logMixtureDensity({u}, outside), -std::numeric_limits<double>::infinity());
  DesignRound g;
  g.index = 1;
  g.kind = "gaussian";
  g.centres.resize(2, 2);
  g.centres << 0.4, 0.5, 0.6, 0.55;
  g.cov.resize(2, 2);
  g.cov << 0.01, 0.004, 0.004, 0.02;
  g.drawn = 100;
  g.prepare();
  auto normal = [&](const Eigen::Vector2d& x, const Eigen::Vector2d& m) {
    const Eigen::Vector2d e = x - m;
    return std::exp(-0.5 * e.dot(g.cov.inverse() * e)) /
           (2 * M_PI * std::sqrt(g.cov.determinant()));
  };
  const Eigen::Vector2d x(0.45, 0.52);
  const double q =
      300 / vol * (u.region.contains(x) ? 1.0 : 0.0) +
      100 * 0.5 *
          (normal(x, g.centres.row(0).transpose()) + normal(x, g.centres.row(1).transpose()));
  EXPECT_NEAR(logMixtureDensity({u, g}, x), std::log(q), 1e-12);
}

TEST(AdaptiveDesign, WeightedGibbsDrawsInProportionToTheDesignWeights) {
  // Two points with equal SSE: P(k) ∝ exp(ω_k) whatever τ, so 3 : 1.
  GibbsOptions o;
  o.iterations = 40000;
  o.burn_in = 1000;
  const GibbsChains c = runGriddyGibbs({10.0, 10.0, 1e9}, 5, o, {std::log(3.0), 0.0, 0.0});
  double share = 0;
  for (int k : c.index) share += k == 0 ? 1.0 : 0.0;
  share /= static_cast<double>(c.index.size());
  EXPECT_NEAR(share, 0.75, 4 * std::sqrt(0.75 * 0.25 / c.index.size()));
  // Equal weights are the unweighted sampler, bit for bit.
  const std::vector<double> sse = {10.0, 12.0, 15.0, 30.0};
  const GibbsChains a = runGriddyGibbs(sse, 5, o),
                    b = runGriddyGibbs(sse, 5, o, {-2.0, -2.0, -2.0, -2.0});
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.tau, b.tau);
  EXPECT_THROW(runGriddyGibbs(sse, 5, o, {0.0, 1.0}), InputError);
  EXPECT_THROW(runGriddyGibbs(sse, 5, o, {0.0, 1.0, std::nan(""), 0.0}), InputError);
}

// A banana: SSE = SSE0 + A (z2 − 0.5 − 2 (z1 − 0.5)²)² + B (z1 − 0.5)² on the unit square. A
// straight sweep along the weak axis leaves the bent ridge; the region's ridge trace follows it
// and the kernel rounds fill it. The importance-weighted design must recover the posterior
// moments and 95 % intervals of a brute-force grid.
TEST(AdaptiveDesign, RidgeTraceAndKernelRoundsFollowACurvedRidge) {
  const double A = 4e5, B = 2e3, sse0 = 100.0;
  const int n = 50;
  auto f = [&](double z1, double z2) {
    const double r = z2 - 0.5 - 2.0 * (z1 - 0.5) * (z1 - 0.5);
    return sse0 + A * r * r + B * (z1 - 0.5) * (z1 - 0.5);
  };
  // Reference: a fine grid, τ integrated out: w ∝ (b + SSE/2)^−(a + n/2).
  const int g = 1500;
  double sw = 0, m[2] = {0, 0}, v[2] = {0, 0};
  std::vector<double> w1(g, 0.0), w2(g, 0.0);  // marginals on the grid
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) {
      const double z1 = (i + 0.5) / g, z2 = (j + 0.5) / g;
      const double w = std::exp(-(1e-3 + 0.5 * n) *
                                (std::log(1e-3 + 0.5 * f(z1, z2)) - std::log(1e-3 + 0.5 * sse0)));
      sw += w;
      m[0] += w * z1;
      m[1] += w * z2;
      v[0] += w * z1 * z1;
      v[1] += w * z2 * z2;
      w1[static_cast<std::size_t>(i)] += w;
      w2[static_cast<std::size_t>(j)] += w;
    }
  double sd[2];
  for (int c = 0; c < 2; ++c) {
    m[c] /= sw;
    sd[c] = std::sqrt(v[c] / sw - m[c] * m[c]);
  }
  auto gridQuantile = [&](const std::vector<double>& w, double p) {
    double c = 0;
    for (int i = 0; i < g; ++i) {
      c += w[static_cast<std::size_t>(i)] / sw;
      if (c >= p) return (i + 0.5) / g;
    }
    return 1.0;
  };
  const SseFunction sse = [&](const std::vector<double>& t) { return f(t[0], t[1]); };
  const ResidualFunction residuals = [&](const std::vector<double>& t) {
    return std::vector<double>{std::sqrt(A) * (t[1] - 0.5 - 2.0 * (t[0] - 0.5) * (t[0] - 0.5)),
                               std::sqrt(B) * (t[0] - 0.5), std::sqrt(sse0)};
  };
  BoxProblem bp;
  bp.theta_hat = {0.5, 0.5};
  bp.sse_min = sse0;
  bp.n_data = n;
  bp.lower = {0.0, 0.0};
  bp.upper = {1.0, 1.0};
  const Region r = calcJointRegion(sse, residuals, bp);
  ASSERT_GT(r.ridge.rows(), 4) << "the weak axis should have been traced";
  // The trace follows the bend: its far floor points lie off the straight axis by about 2 t².
  double bent = 0;
  for (Eigen::Index k = 0; k < r.ridge.rows(); ++k)
    bent = std::max(bent, std::abs(r.ridge(k, 1) - 0.5 - 2 * std::pow(r.ridge(k, 0) - 0.5, 2)));
  EXPECT_LT(bent, 0.002) << "ridge floor points off the true floor";
  AdaptiveDesignOptions o;
  o.first_points = 200;
  o.round_points = 200;
  o.max_rounds = 10;
  o.target_ess = 600;
  o.seed = 9;
  int calls = 0, next_first = 0;
  const DesignEvaluator eval = [&](const Eigen::MatrixXd& p, int first) {
    EXPECT_EQ(first, next_first);
    next_first += static_cast<int>(p.rows());
    ++calls;
    std::vector<double> s;
    for (Eigen::Index i = 0; i < p.rows(); ++i) s.push_back(f(p(i, 0), p(i, 1)));
    return s;
  };
  const AdaptiveDesign d = runAdaptiveDesign(r, n, o, eval);
  EXPECT_EQ(calls, static_cast<int>(d.rounds.size()));
  EXPECT_GE(d.ess, 300.0) << d.stop_reason;
  // Weighted moments and quantiles (τ integrated out) equal the grid's.
  std::vector<double> w(static_cast<std::size_t>(d.points.rows()));
  double w_sum = 0, a[2] = {0, 0}, b[2] = {0, 0};
  for (Eigen::Index k = 0; k < d.points.rows(); ++k) {
    const auto kk = static_cast<std::size_t>(k);
    w[kk] = std::exp(d.log_weight[kk] - (1e-3 + 0.5 * n) * (std::log(1e-3 + 0.5 * d.sse[kk]) -
                                                            std::log(1e-3 + 0.5 * sse0)));
    w_sum += w[kk];
    for (int c = 0; c < 2; ++c) {
      a[c] += w[kk] * d.points(k, c);
      b[c] += w[kk] * d.points(k, c) * d.points(k, c);
    }
  }
  for (int c = 0; c < 2; ++c) {
    a[c] /= w_sum;
    EXPECT_NEAR(a[c], m[c], 0.1 * sd[c]) << "z" << c + 1;
    EXPECT_NEAR(std::sqrt(b[c] / w_sum - a[c] * a[c]), sd[c], 0.1 * sd[c]) << "z" << c + 1;
    std::vector<std::pair<double, double>> pw;
    for (Eigen::Index k = 0; k < d.points.rows(); ++k)
      pw.push_back({d.points(k, c), w[static_cast<std::size_t>(k)] / w_sum});
    std::sort(pw.begin(), pw.end());
    double cum = 0, lo = 0, hi = 0;
    for (const auto& [x, q] : pw) {
      if (cum < 0.025 && cum + q >= 0.025) lo = x;
      if (cum < 0.975 && cum + q >= 0.975) hi = x;
      cum += q;
    }
    const double glo = gridQuantile(c == 0 ? w1 : w2, 0.025),
                 ghi = gridQuantile(c == 0 ? w1 : w2, 0.975);
    EXPECT_NEAR(lo, glo, 0.1 * (ghi - glo)) << "z" << c + 1 << " 2.5 % quantile";
    EXPECT_NEAR(hi, ghi, 0.1 * (ghi - glo)) << "z" << c + 1 << " 97.5 % quantile";
  }
  // Deterministic: the same inputs give the same design.
  next_first = 0;
  const AdaptiveDesign again = runAdaptiveDesign(r, n, o, eval);
  EXPECT_TRUE(again.points.isApprox(d.points, 0));
  EXPECT_EQ(again.log_weight, d.log_weight);
}

TEST(AdaptiveDesign, OneRoundIsThePapersUniformDesign) {
  const Region r = square();
  AdaptiveDesignOptions o;
  o.adaptive = false;
  o.first_points = 150;
  const AdaptiveDesign d = runAdaptiveDesign(
      r, 10, o, [](const Eigen::MatrixXd& p, int) { return std::vector<double>(p.rows(), 5.0); });
  ASSERT_EQ(d.rounds.size(), 1u);
  EXPECT_EQ(d.rounds[0].kind, "uniform");
  EXPECT_NEAR(static_cast<double>(d.points.rows()), 150.0, 15.0);
  for (double w : d.log_weight) EXPECT_EQ(w, 0.0);
  for (Eigen::Index k = 0; k < d.points.rows(); ++k) {
    const Eigen::Vector2d z(d.points(k, 0) / 2.0, d.points(k, 1) / 4.0);
    EXPECT_TRUE(r.contains(z));
  }
}

TEST(AdaptiveDesign, BadOptionsAreNamed) {
  AdaptiveDesignOptions o;
  o.target_ess = -1;
  try {
    o.validate();
    FAIL() << "target_ess -1 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "design.target_ess");
    EXPECT_EQ(e.rule(), "must be a finite number > 0, got -1");
  }
}

namespace {

/// A 4-parameter posterior shaped like the demonstration drive's (scaled units, n = 5995): SSE =
/// n + |U e|², e = z − μ with its second component bent by `bend` · e₁² / sd₁ (0: a Gaussian).
struct Tube {
  Eigen::Matrix4d C, P, U;
  Eigen::Vector4d mu{0.100, 0.425, 0.126, 0.114};
  double bend = 0.0;
  int n = 5995;
  explicit Tube(double b) : bend(b) {
    C << 1.18e-5, 5.07e-5, 4.6e-6, 5.0e-7, 5.07e-5, 2.56e-4, 2.07e-5, 6.4e-6, 4.6e-6, 2.07e-5,
        2.93e-6, 2.8e-7, 5.0e-7, 6.4e-6, 2.8e-7, 6.1e-7;
    P = C.inverse();
    U = Eigen::LLT<Eigen::Matrix4d>(P).matrixU();
  }
  std::vector<double> residuals(const std::vector<double>& t) const {
    Eigen::Vector4d e = Eigen::Vector4d(t[0], t[1], t[2], t[3]) - mu;
    e(1) -= bend * e(0) * e(0) / std::sqrt(C(0, 0));
    const Eigen::Vector4d r = U * e;
    return {r(0), r(1), r(2), r(3), std::sqrt(static_cast<double>(n))};
  }
  double sse(const std::vector<double>& t) const {
    double s = 0;
    for (double v : residuals(t)) s += v * v;
    return s;
  }
  Region region() const {
    BoxProblem bp;
    bp.theta_hat = {mu(0), mu(1), mu(2), mu(3)};
    bp.sse_min = n;
    bp.n_data = n;
    bp.lower = {0, 0, 0, 0};
    bp.upper = {1, 1, 1, 1};
    return calcJointRegion([&](const std::vector<double>& t) { return sse(t); },
                           [&](const std::vector<double>& t) { return residuals(t); }, bp);
  }
  AdaptiveDesign design(const Region& r, int max_rounds) const {
    AdaptiveDesignOptions o;
    o.max_rounds = max_rounds;
    o.seed = 3;
    return runAdaptiveDesign(r, n, o, [&](const Eigen::MatrixXd& p, int) {
      std::vector<double> s;
      for (Eigen::Index i = 0; i < p.rows(); ++i)
        s.push_back(sse({p(i, 0), p(i, 1), p(i, 2), p(i, 3)}));
      return s;
    });
  }
};

}  // namespace

// Closed form: on a Gaussian posterior the ridge floor is the straight line z(t) = μ + t g with
// g = a + B du/dt, du/dt = −(BᵀPB)⁻¹BᵀPa, and the cross-section at every floor point is
// σ² B (BᵀPB)⁻¹ Bᵀ (σ² = SSE_min / n = 1 here, P the Hessian / 2). Region::ridge_cov must equal
// it in every direction orthogonal to g. The ridge is straight, so the design draws from the
// Gaussian guess (no kernel with its own covariance).
TEST(AdaptiveDesign, RidgeKernelsCarryTheExactCrossSectionOfAGaussianPosterior) {
  const Tube tube(0.0);
  const Region r = tube.region();
  ASSERT_GE(r.ridge.rows(), 4);
  ASSERT_EQ(r.ridge_cov.size(), static_cast<std::size_t>(r.ridge.rows()));
  const Eigen::VectorXd a = r.axes.col(0);
  Eigen::MatrixXd B(4, 3);
  B << r.axes.col(1), r.axes.col(2), r.axes.col(3);
  const Eigen::MatrixXd BPB = B.transpose() * tube.P * B;
  const Eigen::VectorXd g = a - B * BPB.ldlt().solve(B.transpose() * tube.P * a);
  const Eigen::MatrixXd cross = B * BPB.inverse() * B.transpose();
  // An orthonormal basis of the complement of g.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(g.transpose(), Eigen::ComputeFullV);
  const Eigen::MatrixXd W = svd.matrixV().rightCols(3);
  for (std::size_t q = 0; q < r.ridge_cov.size(); ++q) {
    ASSERT_EQ(r.ridge_cov[q].rows(), 4) << "ridge point " << q;
    const Eigen::MatrixXd got = W.transpose() * r.ridge_cov[q] * W,
                          want = W.transpose() * cross * W;
    EXPECT_LT((got - want).norm(), 1e-4 * want.norm()) << "ridge point " << q << "\n"
                                                       << got << "\n"
                                                       << want;
  }
  const AdaptiveDesign d = tube.design(r, 1);
  ASSERT_EQ(d.rounds.size(), 2u);
  EXPECT_TRUE(d.rounds[1].own_cov.empty());
}

// A thin bent tube (the second coordinate bent by 2 sd per sd² of the first): the first adaptive
// round puts kernels with their own local covariance on the ridge, and a quarter of its points is
// effective. (Kernels with one common covariance on the few heavy points of round 0 gave 14-28 of
// 200 here, the Gaussian guess's centres 19-28.)
TEST(AdaptiveDesign, ABentTubeIsFollowedByLocalKernels) {
  const Tube tube(2.0);
  const Region r = tube.region();
  const AdaptiveDesign d = tube.design(r, 1);
  ASSERT_EQ(d.rounds.size(), 2u);
  const auto& own = d.rounds[1].own_cov;
  EXPECT_GT(
      std::count_if(own.begin(), own.end(), [](const Eigen::MatrixXd& m) { return m.size() > 0; }),
      25);
  EXPECT_GT(d.rounds[1].ess, 0.25 * d.rounds[1].count) << "round 0 ESS " << d.rounds[0].ess;
}
