// Bayesian classification: an analytic Bayes factor between two Gaussians, posteriors with
// non-uniform priors, ties, extreme log-likelihoods, the probability spread, input errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "classification/classify.hpp"
#include "classification/mvn.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::classify;

namespace {

// ln N(y; μ, diag(v)) written out for a diagonal covariance.
double diagLogPdf(const Eigen::VectorXd& y, const Eigen::VectorXd& mu, const Eigen::VectorXd& v) {
  double s = 0.0;
  for (Eigen::Index i = 0; i < y.size(); ++i)
    s += -0.5 * std::log(2 * M_PI * v[i]) - (y[i] - mu[i]) * (y[i] - mu[i]) / (2 * v[i]);
  return s;
}

}  // namespace

TEST(Classify, AnalyticBayesFactorBetweenTwoGaussians) {
  // Model a: N((0, 0), diag(1, 1)); model b: N((1, −1), diag(4, 0.25)).
  const Eigen::Vector2d mu_a(0, 0), mu_b(1, -1), v_a(1, 1), v_b(4, 0.25);
  const GaussianModel a(mu_a, Eigen::MatrixXd(v_a.asDiagonal()));
  const GaussianModel b(mu_b, Eigen::MatrixXd(v_b.asDiagonal()));
  Eigen::MatrixXd Y(2, 4);
  Y << 0.1, 1.2, -0.7, 2.0,  //
      -0.2, -0.9, 0.4, -1.1;
  Eigen::MatrixXd ll(4, 2);
  ll.col(0) = a.logPdfBatch(Y);
  ll.col(1) = b.logPdfBatch(Y);
  const ClassificationResult res = classifyRecords(ll);
  double total = 0.0;
  for (int r = 0; r < 4; ++r) {
    // Closed form: ln B_ab(y) = Σ_i [½ ln(v_b,i / v_a,i) − (y_i − μ_a,i)²/(2 v_a,i)
    //                                + (y_i − μ_b,i)²/(2 v_b,i)].
    double lb = 0.0;
    for (int i = 0; i < 2; ++i)
      lb += 0.5 * std::log(v_b[i] / v_a[i]) - std::pow(Y(i, r) - mu_a[i], 2) / (2 * v_a[i]) +
            std::pow(Y(i, r) - mu_b[i], 2) / (2 * v_b[i]);
    EXPECT_NEAR(ll(r, 0) - ll(r, 1), lb, 1e-12) << r;
    EXPECT_NEAR(ll(r, 0), diagLogPdf(Y.col(r), mu_a, v_a), 1e-12) << r;
    // Uniform prior: P(a | y) = 1 / (1 + exp(−ln B_ab)).
    EXPECT_NEAR(res.probability(r, 0), 1.0 / (1.0 + std::exp(-lb)), 1e-14) << r;
    EXPECT_EQ(res.winner[r], lb > 0 ? 0 : 1) << r;
    total += lb;
  }
  EXPECT_NEAR(res.log_bayes_factor(0, 1), total, 1e-12);
  EXPECT_EQ(res.log_bayes_factor(1, 0), -res.log_bayes_factor(0, 1));
  ASSERT_EQ(res.pairs.size(), 1u);
  EXPECT_NEAR(res.pairs[0].two_ln_b, 2 * total, 2e-12);
  EXPECT_EQ(res.pairs[0].favoured, total > 0 ? 0 : 1);
  EXPECT_EQ(res.pairs[0].category, kassRafteryCategory(2 * total));
  EXPECT_NEAR(res.total_log_likelihood[0] - res.total_log_likelihood[1], total, 1e-12);
  EXPECT_NEAR(res.joint_probability[0], 1.0 / (1.0 + std::exp(-total)), 1e-14);
}

TEST(Classify, NonUniformPriorGivesHandComputedPosterior) {
  Eigen::MatrixXd ll(1, 3);
  ll << -1.0, -2.0, -0.5;
  ClassifyOptions o;
  o.prior = {0.5, 0.3, 0.2};
  const ClassificationResult res = classifyRecords(ll, o);
  double z = 0.0;
  for (int m = 0; m < 3; ++m) z += o.prior[m] * std::exp(ll(0, m));
  for (int m = 0; m < 3; ++m) {
    EXPECT_NEAR(res.probability(0, m), o.prior[m] * std::exp(ll(0, m)) / z, 1e-15) << m;
    EXPECT_DOUBLE_EQ(res.log_posterior(0, m), ll(0, m) + std::log(o.prior[m]));
  }
  EXPECT_NEAR(res.log_marginal[0], std::log(z), 1e-15);
  // 0.5 e^-1 = 0.1839 > 0.2 e^-0.5 = 0.1213 > 0.3 e^-2 = 0.0406
  EXPECT_EQ(res.winner[0], 0);
  EXPECT_FALSE(res.tie[0]);
  // With a uniform prior the winner is the largest ℓ instead.
  EXPECT_EQ(classifyRecords(ll).winner[0], 2);
  // Bayes factors ignore the prior.
  EXPECT_DOUBLE_EQ(res.log_bayes_factor(0, 2), -0.5);
}

TEST(Classify, TiesPickTheLowestIndexAndSetTheFlag) {
  Eigen::MatrixXd ll(5, 3);
  ll << -3.0, -1.0, -1.0,        // exact tie between 1 and 2
      -1.0 - 5e-13, -1.0, -7.0,  // within 1e-12 relative: tie, lowest index wins
      -1.0 - 1e-9, -1.0, -7.0,   // a real difference: no tie
      -2.0, -2.0, -2.0,          // three-way tie
      1e-13, 0.0, -5.0;          // near zero: the absolute floor applies
  const ClassificationResult res = classifyRecords(ll);
  EXPECT_EQ(res.winner, (std::vector<int>{1, 0, 1, 0, 0}));
  EXPECT_EQ(res.tie, (std::vector<bool>{true, true, false, true, true}));
  EXPECT_EQ(res.tied_records, 4);
  EXPECT_EQ(res.wins, (std::vector<int>{3, 2, 0}));
  EXPECT_NEAR(res.probability(3, 0), 1.0 / 3.0, 1e-15);
}

TEST(Classify, ExtremeLogLikelihoodsDoNotUnderflow) {
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd ll(3, 2);
  ll << -1e6, -1e6 - 3.0,  //
      -1e6, -inf,          //
      -2e6, -1e6;
  const ClassificationResult res = classifyRecords(ll);
  ASSERT_TRUE(res.probability.allFinite());
  EXPECT_NEAR(res.probability(0, 0), 1.0 / (1.0 + std::exp(-3.0)), 1e-15);
  EXPECT_NEAR(res.probability(0, 1), std::exp(-3.0) / (1.0 + std::exp(-3.0)), 1e-15);
  EXPECT_EQ(res.probability(1, 0), 1.0);
  EXPECT_EQ(res.probability(1, 1), 0.0);
  EXPECT_EQ(res.probability(2, 1), 1.0);
  EXPECT_NEAR(res.log_marginal[0], -1e6 - std::log(2.0) + std::log1p(std::exp(-3.0)), 1e-9);
  EXPECT_EQ(res.winner, (std::vector<int>{0, 0, 1}));
  EXPECT_EQ(res.log_bayes_factor(0, 1), inf);  // record 1 excludes model 1
  EXPECT_EQ(res.pairs[0].category, "very strong");
  EXPECT_TRUE(std::isfinite(logSumExp(Eigen::Vector2d(-1e308, -1e308))));
}

TEST(Classify, WinsAndProbabilitySpreadOverRecords) {
  // Two models, five records with ℓ_a − ℓ_b = d_r: P(a | y_r) = 1 / (1 + e^{−d_r}).
  const std::vector<double> d = {2.0, -1.0, 0.5, 3.0, -0.2};
  Eigen::MatrixXd ll(5, 2);
  for (int r = 0; r < 5; ++r) ll.row(r) << -10.0 + d[r], -10.0;
  const ClassificationResult res = classifyRecords(ll);
  EXPECT_EQ(res.wins, (std::vector<int>{3, 2}));
  std::vector<double> pa;
  for (double x : d) pa.push_back(1.0 / (1.0 + std::exp(-x)));
  std::sort(pa.begin(), pa.end());
  // Type 7 with 5 values: q1, median, q3 are exactly the 2nd, 3rd and 4th order statistics.
  const ProbabilitySpread& s = res.spread[0];
  EXPECT_NEAR(s.min, pa[0], 1e-15);
  EXPECT_NEAR(s.q1, pa[1], 1e-15);
  EXPECT_NEAR(s.median, pa[2], 1e-15);
  EXPECT_NEAR(s.q3, pa[3], 1e-15);
  EXPECT_NEAR(s.max, pa[4], 1e-15);
  EXPECT_NEAR(s.mean, (pa[0] + pa[1] + pa[2] + pa[3] + pa[4]) / 5, 1e-15);
  EXPECT_NEAR(res.spread[1].median, 1.0 - pa[2], 1e-15);
  const std::string full = res.fullReport();
  EXPECT_NE(full.find("M1 3 (60.0 %), M2 2 (40.0 %)."), std::string::npos) << full;
  EXPECT_NE(full.find("M1 vs M2: 2 ln B = 8.6, strong (favours M1)"), std::string::npos) << full;
}

TEST(Classify, KassRafteryCategories) {
  EXPECT_EQ(kassRafteryCategory(0.0), "not worth more than a bare mention");
  EXPECT_EQ(kassRafteryCategory(-1.99), "not worth more than a bare mention");
  EXPECT_EQ(kassRafteryCategory(2.0), "positive");
  EXPECT_EQ(kassRafteryCategory(-5.9), "positive");
  EXPECT_EQ(kassRafteryCategory(6.0), "strong");
  EXPECT_EQ(kassRafteryCategory(9.99), "strong");
  EXPECT_EQ(kassRafteryCategory(10.0), "very strong");
  EXPECT_EQ(kassRafteryCategory(-250.0), "very strong");
  EXPECT_EQ(kassRafteryCategory(std::nan("")), "undefined");
}

TEST(Classify, InvalidInputIsRejectedWithMessage) {
  Eigen::MatrixXd ll(2, 2);
  ll << -1, -2, -3, -4;
  auto message = [&](const ClassifyOptions& o, const Eigen::MatrixXd& m) -> std::string {
    try {
      classifyRecords(m, o);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  ClassifyOptions o;
  o.prior = {0.5, 0.6};
  EXPECT_EQ(message(o, ll), "classify.prior: must sum to 1 within 1e-9, got 1.1000000000000001");
  o.prior = {1.5, -0.5};
  EXPECT_EQ(message(o, ll), "classify.prior[1]: must be a finite number > 0, got -0.5");
  o.prior = {1.0};
  EXPECT_EQ(message(o, ll), "classify.prior: has 1 entries, expected 2 (one per model)");
  o.prior = {0.5, 0.5 + 5e-10};  // within 1e-9: accepted
  EXPECT_EQ(message(o, ll), "no error");
  Eigen::MatrixXd bad = ll;
  bad(1, 0) = std::nan("");
  EXPECT_EQ(message({}, bad),
            "log-likelihood matrix: entry (record 1, model 0) is nan (must be finite or -inf)");
  bad = ll;
  bad.row(0).setConstant(-std::numeric_limits<double>::infinity());
  EXPECT_EQ(message({}, bad),
            "log-likelihood matrix: record 0: every model has log-likelihood -inf (posterior "
            "undefined)");
}
