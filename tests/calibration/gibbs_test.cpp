// Griddy Gibbs against closed forms: the normal–gamma posterior of a linear model, the exact
// discrete marginal on the design grid, and the Gamma sampler's moments.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "calibration/gibbs.hpp"
#include "calibration/summary.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::calib;

namespace {

struct Moments {
  double mean = 0, var = 0, m4 = 0;  // mean, variance, 4th central moment
};

Moments moments(const std::vector<double>& w, const std::vector<double>& x) {
  Moments m;
  for (std::size_t k = 0; k < w.size(); ++k) m.mean += w[k] * x[k];
  for (std::size_t k = 0; k < w.size(); ++k) {
    const double d = x[k] - m.mean;
    m.var += w[k] * d * d;
    m.m4 += w[k] * d * d * d * d;
  }
  return m;
}

/// Normalised weights from log weights (log-sum-exp).
std::vector<double> softmax(const std::vector<double>& lw) {
  double mx = -std::numeric_limits<double>::infinity();
  for (double v : lw) mx = std::max(mx, v);
  std::vector<double> w(lw.size());
  double s = 0;
  for (std::size_t k = 0; k < lw.size(); ++k) s += (w[k] = std::exp(lw[k] - mx));
  for (double& v : w) v /= s;
  return w;
}

}  // namespace

// y_i = θ1 + θ2 x_i + ε_i, ε ~ N(0, 1/τ), n = 20, τ ~ Gamma(a, b), θ uniform on a wide box.
// Two references:
//  (1) the EXACT target of the sampler on the design grid, by summing out τ analytically:
//      P(k | y) ∝ ∫ τ^{a+n/2−1} e^{−τ (b + SSE_k/2)} dτ ∝ (b + SSE_k/2)^{−(a + n/2)};
//      E[τ | y] = Σ_k P(k) (a + n/2)/(b + SSE_k/2). The chain must match these within Monte-Carlo
//      error (4 standard errors, with the ESS of the chain).
//  (2) the continuous normal–gamma answer (box wide enough that truncation is negligible):
//      θ | y ~ Student-t_ν(θ̂, s² (XᵀX)⁻¹), ν = 2a + n − p, s² = (2b + SSE_min)/ν, so
//      Var θ = (2b + SSE_min)/(ν − 2) (XᵀX)⁻¹, and τ | y ~ Gamma(a + (n−p)/2, b + SSE_min/2).
//      The grid reference (1) must agree with (2) to 1 % (discretisation and truncation only).
TEST(GriddyGibbs, MatchesNormalGammaPosteriorOfLinearModel) {
  const int n = 20, p = 2;
  const double sigma = 0.5;
  Eigen::MatrixXd X(n, p);
  Eigen::VectorXd y(n);
  RandomStream noise(2024, 7);
  for (int i = 0; i < n; ++i) {
    const double x = 2.0 * i / (n - 1) + 0.5;
    X(i, 0) = 1.0;
    X(i, 1) = x;
    y(i) = 1.5 - 0.8 * x + sigma * noise.normal();
  }
  const Eigen::MatrixXd XtX = X.transpose() * X;
  const Eigen::VectorXd hat = XtX.ldlt().solve(X.transpose() * y);
  const double sse_min = (y - X * hat).squaredNorm();
  GibbsOptions opt;
  opt.iterations = 50000;
  opt.burn_in = 5000;
  opt.seed = 31;
  const double a = opt.a, b = opt.b;
  const double nu = 2 * a + n - p;
  const Eigen::MatrixXd cov = (2 * b + sse_min) / (nu - 2) * XtX.inverse();

  // Design: a 41 x 41 grid over θ̂ ± 5 marginal sd.
  const int g = 41;
  std::vector<double> t1, t2, sse;
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) {
      Eigen::Vector2d th(hat(0) + std::sqrt(cov(0, 0)) * (-5.0 + 10.0 * i / (g - 1)),
                         hat(1) + std::sqrt(cov(1, 1)) * (-5.0 + 10.0 * j / (g - 1)));
      t1.push_back(th(0));
      t2.push_back(th(1));
      sse.push_back((y - X * th).squaredNorm());
    }
  const std::size_t N = sse.size();
  Eigen::MatrixXd design(N, 2);
  for (std::size_t k = 0; k < N; ++k) design(k, 0) = t1[k], design(k, 1) = t2[k];

  // (1) exact grid marginal.
  std::vector<double> lw(N), tau_k(N);
  for (std::size_t k = 0; k < N; ++k) {
    lw[k] = -(a + 0.5 * n) * std::log(b + 0.5 * sse[k]);
    tau_k[k] = (a + 0.5 * n) / (b + 0.5 * sse[k]);
  }
  const std::vector<double> w = softmax(lw);
  const Moments g1 = moments(w, t1), g2 = moments(w, t2);
  double grid_tau = 0;
  for (std::size_t k = 0; k < N; ++k) grid_tau += w[k] * tau_k[k];

  // (2) vs continuum: discretisation/truncation only.
  const double tau_analytic = (a + 0.5 * (n - p)) / (b + 0.5 * sse_min);
  EXPECT_NEAR(g1.mean, hat(0), 0.01 * std::sqrt(cov(0, 0)));
  EXPECT_NEAR(g2.mean, hat(1), 0.01 * std::sqrt(cov(1, 1)));
  EXPECT_NEAR(g1.var / cov(0, 0), 1.0, 0.01);
  EXPECT_NEAR(g2.var / cov(1, 1), 1.0, 0.01);
  EXPECT_NEAR(grid_tau / tau_analytic, 1.0, 0.01);

  // The sampler vs (1), within Monte-Carlo error.
  const GibbsChains ch = runGriddyGibbs(sse, n, opt);
  ASSERT_EQ(ch.index.size(), 45000u);
  ASSERT_EQ(ch.tau.size(), 45000u);
  const PosteriorSummary s = summarisePosterior(design, ch, {"theta_1", "theta_2"});
  const Moments* gm[2] = {&g1, &g2};
  for (int j = 0; j < 2; ++j) {
    const DrawSummary& d = s.parameters[j];
    const Moments& m = *gm[j];
    ASSERT_GT(d.ess, 1000.0) << d.name;
    EXPECT_NEAR(d.mean, m.mean, 4.0 * std::sqrt(m.var / d.ess)) << d.name;
    EXPECT_NEAR(d.sd * d.sd, m.var, 4.0 * std::sqrt((m.m4 - m.var * m.var) / d.ess)) << d.name;
    std::cout << d.name << ": mean " << d.mean << " (exact " << m.mean << "), var " << d.sd * d.sd
              << " (exact " << m.var << ", analytic " << cov(j, j) << "), ESS " << d.ess << "\n";
  }
  double tau_var = 0;  // E[Var(τ|k)] + Var(E[τ|k]) under the grid marginal
  for (std::size_t k = 0; k < N; ++k)
    tau_var +=
        w[k] * (tau_k[k] / (b + 0.5 * sse[k]) + (tau_k[k] - grid_tau) * (tau_k[k] - grid_tau));
  EXPECT_NEAR(s.tau.mean, grid_tau, 4.0 * std::sqrt(tau_var / s.tau.ess));
  EXPECT_NEAR(s.tau.sd * s.tau.sd / tau_var, 1.0, 0.05);
  std::cout << "tau: mean " << s.tau.mean << " (exact grid " << grid_tau << ", analytic "
            << tau_analytic << "), ESS " << s.tau.ess << "\n";
  // Visit statistics: the most visited point's share matches the largest grid probability.
  const double w_max = *std::max_element(w.begin(), w.end());
  EXPECT_NEAR(s.top_share, w_max, 5.0 * std::sqrt(w_max * (1 - w_max) / s.tau.ess));
  EXPECT_FALSE(s.design_too_coarse);
  EXPECT_GT(s.distinct_points, 100);
}

// Enormous SSE values and n (field data: n ~ 1e6): exp(−τ SSE/2) underflows for every point
// unless the maximum log weight is subtracted. The discrete marginal is again
// P(k) ∝ (b + SSE_k/2)^{−(a+n/2)}.
TEST(GriddyGibbs, StableForHugeSseAndN) {
  const int n = 1000000;
  const std::vector<double> delta = {0.0, 1e-6, 2e-6, 5e-6};
  std::vector<double> sse;
  for (double d : delta) sse.push_back(1e12 * (1.0 + d));
  GibbsOptions opt;
  opt.iterations = 40000;
  opt.burn_in = 1000;
  opt.seed = 5;
  const GibbsChains ch = runGriddyGibbs(sse, n, opt);
  std::vector<double> lw;
  for (double s : sse) lw.push_back(-(opt.a + 0.5 * n) * std::log(opt.b + 0.5 * s));
  const std::vector<double> w = softmax(lw);
  std::vector<double> freq(sse.size(), 0.0);
  for (int k : ch.index) freq[static_cast<std::size_t>(k)] += 1.0 / ch.index.size();
  for (std::size_t k = 0; k < sse.size(); ++k) {
    // τ barely moves (shape 5e5), so successive k draws are nearly independent.
    EXPECT_NEAR(freq[k], w[k], 4.0 * std::sqrt(w[k] * (1 - w[k]) / ch.index.size()) + 1e-4)
        << "point " << k;
  }
  EXPECT_GT(w[3], 0.03);  // the check above is not vacuous for the worst point
  for (double t : ch.tau) ASSERT_TRUE(std::isfinite(t) && t > 0);
}

TEST(GriddyGibbs, FailedPointsGetZeroWeightAndChangeNothingElse) {
  std::vector<double> sse;
  for (int k = 0; k < 200; ++k) sse.push_back(100.0 + 0.05 * (k - 80) * (k - 80));
  GibbsOptions opt;
  opt.iterations = 3000;
  opt.burn_in = 100;
  const GibbsChains base = runGriddyGibbs(sse, 30, opt);
  // Interleave failed simulations (inf and NaN): original point k moves to index map[k].
  std::vector<double> with_failed;
  std::vector<int> map;
  for (int k = 0; k < 200; ++k) {
    if (k % 3 == 0) with_failed.push_back(std::numeric_limits<double>::infinity());
    if (k % 7 == 0) with_failed.push_back(std::numeric_limits<double>::quiet_NaN());
    map.push_back(static_cast<int>(with_failed.size()));
    with_failed.push_back(sse[static_cast<std::size_t>(k)]);
  }
  const GibbsChains ch = runGriddyGibbs(with_failed, 30, opt);
  EXPECT_EQ(ch.failed_points, static_cast<int>(with_failed.size()) - 200);
  EXPECT_EQ(ch.design_points, static_cast<int>(with_failed.size()));
  ASSERT_EQ(ch.index.size(), base.index.size());
  for (std::size_t t = 0; t < ch.index.size(); ++t) {
    ASSERT_TRUE(std::isfinite(with_failed[static_cast<std::size_t>(ch.index[t])]));
    ASSERT_EQ(ch.index[t], map[static_cast<std::size_t>(base.index[t])]) << t;
    ASSERT_EQ(ch.tau[t], base.tau[t]);
  }
}

TEST(GriddyGibbs, SeededAndChainsIndependent) {
  std::vector<double> sse;
  for (int k = 0; k < 100; ++k) sse.push_back(50.0 + 0.1 * k);
  GibbsOptions opt;
  opt.iterations = 2000;
  opt.burn_in = 0;
  const GibbsChains a = runGriddyGibbs(sse, 10, opt);
  const GibbsChains b = runGriddyGibbs(sse, 10, opt);
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.tau, b.tau);
  opt.chain = 1;
  const GibbsChains c = runGriddyGibbs(sse, 10, opt);
  EXPECT_NE(a.index, c.index);
  EXPECT_EQ(a.options.seed, opt.seed);         // the seed is recorded
  EXPECT_DOUBLE_EQ(a.initial_tau, 10 / 50.0);  // default n / SSE_min
}

TEST(GriddyGibbs, InvalidInputsNameTheRule) {
  const double inf = std::numeric_limits<double>::infinity();
  try {
    runGriddyGibbs({inf, inf, inf}, 10);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("none of the 3 design points has a finite SSE"),
              std::string::npos)
        << e.what();
  }
  GibbsOptions opt;
  opt.iterations = 100;
  opt.burn_in = 100;
  try {
    runGriddyGibbs({1.0}, 10, opt);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "gibbs.burn_in");
    EXPECT_EQ(e.rule(), "must be below iterations (100), got 100");
  }
  try {
    runGriddyGibbs({1.0, -2.0}, 10, {});
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("SSE of design point 1 is negative"), std::string::npos)
        << e.what();
  }
  opt = {};
  opt.b = 0.0;
  EXPECT_THROW(runGriddyGibbs({0.0, 1.0}, 10, opt), InputError);
  // An exact fit is fine with b > 0: τ | k=0 ~ Gamma(a + n/2, b) stays finite.
  opt = {};
  opt.iterations = 200;
  opt.burn_in = 0;
  const GibbsChains ch = runGriddyGibbs({0.0, 1.0}, 10, opt);
  for (double t : ch.tau) EXPECT_TRUE(std::isfinite(t));
}

// Marsaglia–Tsang (shape >= 1) and the u^{1/a} boost (shape < 1): Gamma(α, 1) has mean α and
// variance α; the sample mean and variance must be within 5 standard errors
// (SE of the variance from the 4th central moment 3α² + 6α).
TEST(GammaSampler, MeanAndVarianceMatch) {
  for (double shape : {0.05, 0.3, 1.0, 2.5, 11.0, 5e4}) {
    RandomStream rng(77, 3, static_cast<std::uint64_t>(shape * 1000));
    const int m = 200000;
    double s1 = 0, s2 = 0;
    std::vector<double> x(m);
    for (int i = 0; i < m; ++i) {
      x[i] = sampleGamma(rng, shape);
      ASSERT_GE(x[i], 0.0);
      s1 += x[i];
    }
    const double mean = s1 / m;
    for (double v : x) s2 += (v - mean) * (v - mean);
    const double var = s2 / (m - 1);
    const double m4 = 3 * shape * shape + 6 * shape;
    EXPECT_NEAR(mean, shape, 5 * std::sqrt(shape / m)) << "shape " << shape;
    EXPECT_NEAR(var, shape, 5 * std::sqrt((m4 - shape * shape) / m)) << "shape " << shape;
  }
}

// The whole distribution, not just two moments: Kolmogorov–Smirnov against the closed-form CDF
// of integer shapes, F(x) = 1 − e^{−x} Σ_{i<k} x^i / i!. 200000 draws; 1.95/√m is the 0.001
// critical value of the KS statistic.
TEST(GammaSampler, KolmogorovSmirnovAgainstErlangCdf) {
  for (int k : {1, 3}) {
    RandomStream rng(78, 3, static_cast<std::uint64_t>(k));
    const int m = 200000;
    std::vector<double> x(m);
    for (double& v : x) v = sampleGamma(rng, k);
    std::sort(x.begin(), x.end());
    double dmax = 0.0;
    for (int i = 0; i < m; ++i) {
      double term = 1.0, sum = 0.0;
      for (int j = 0; j < k; ++j) {
        sum += term;
        term *= x[i] / (j + 1);
      }
      const double F = 1.0 - std::exp(-x[i]) * sum;
      dmax = std::max({dmax, std::abs(F - static_cast<double>(i) / m),
                       std::abs(F - static_cast<double>(i + 1) / m)});
    }
    EXPECT_LT(dmax, 1.95 / std::sqrt(static_cast<double>(m))) << "shape " << k;
  }
}
