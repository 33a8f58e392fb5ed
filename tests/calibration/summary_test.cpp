// Posterior summaries: quantile definition, ESS against the AR(1) closed form, the single-point
// (design too coarse) check.
#include <gtest/gtest.h>

#include <cmath>

#include "calibration/summary.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::calib;

TEST(PosteriorSummary, QuantileIsType7) {
  // For the sorted sample 0, 1, .., S−1, type 7 gives exactly q(p) = p (S − 1).
  std::vector<double> x;
  for (int i = 0; i < 41; ++i) x.push_back(i);
  for (double p : {0.0, 0.025, 0.3, 0.5, 0.975, 1.0})
    EXPECT_NEAR(quantileSorted(x, p), p * 40.0, 1e-12) << p;
  // Scale invariance and interpolation between unequal neighbours: {1, 2, 10}, p = 0.75:
  // h = 1.5 -> 2 + 0.5 (10 − 2).
  EXPECT_DOUBLE_EQ(quantileSorted({1.0, 2.0, 10.0}, 0.75), 2.0 + 0.5 * 8.0);
  EXPECT_DOUBLE_EQ(quantileSorted({3.0}, 0.025), 3.0);
}

TEST(PosteriorSummary, EssMatchesAr1ClosedForm) {
  // AR(1) x_t = φ x_{t−1} + e_t: integrated autocorrelation time (1 + φ)/(1 − φ).
  const int S = 100000;
  for (double phi : {0.0, 0.5, 0.9, -0.3}) {
    RandomStream rng(4, 4, static_cast<std::uint64_t>((phi + 1) * 100));
    std::vector<double> x(S);
    double v = rng.normal() / std::sqrt(1 - phi * phi);
    for (int t = 0; t < S; ++t) x[t] = v = phi * v + rng.normal();
    const double expected = S * (1 - phi) / (1 + phi);
    const double ess = effectiveSampleSize(x);
    // Geyer's estimator truncates a negative-lag-1 sequence, so allow a looser band there.
    EXPECT_NEAR(ess / expected, 1.0, phi < 0 ? 0.35 : 0.12) << "phi " << phi << " ess " << ess;
  }
  EXPECT_TRUE(std::isnan(effectiveSampleSize(std::vector<double>(100, 2.5))));
}

TEST(PosteriorSummary, SummariseDrawsMomentsAndInterval) {
  std::vector<double> x;
  RandomStream rng(8, 8);
  for (int i = 0; i < 200000; ++i) x.push_back(3.0 + 2.0 * rng.normal());
  const DrawSummary s = summariseDraws(x, "z");
  EXPECT_EQ(s.name, "z");
  EXPECT_NEAR(s.mean, 3.0, 5 * 2.0 / std::sqrt(2e5));
  EXPECT_NEAR(s.sd, 2.0, 0.01);
  EXPECT_NEAR(s.q025, 3.0 - 1.959964 * 2.0, 0.03);
  EXPECT_NEAR(s.q975, 3.0 + 1.959964 * 2.0, 0.03);
  EXPECT_GT(s.ess, 1.5e5);
}

TEST(PosteriorSummary, FlagsSinglePointPosterior) {
  Eigen::MatrixXd design(5, 2);
  design << 1, 10, 2, 20, 3, 30, 4, 40, 5, 50;
  GibbsChains ch;
  ch.design_points = 5;
  for (int t = 0; t < 1000; ++t) {
    ch.index.push_back(t % 100 < 95 ? 2 : (t % 2 ? 1 : 4));  // 95 % on point 2
    ch.tau.push_back(1.0 + 1e-3 * (t % 10));
  }
  const PosteriorSummary s = summarisePosterior(design, ch, {"k_N_per_m", "c_Ns_per_m"});
  EXPECT_EQ(s.draws, 1000);
  EXPECT_EQ(s.distinct_points, 3);
  EXPECT_EQ(s.top_point, 2);
  EXPECT_DOUBLE_EQ(s.top_share, 0.95);
  EXPECT_TRUE(s.design_too_coarse);
  EXPECT_NE(s.message.find("design too coarse for the data"), std::string::npos) << s.message;
  EXPECT_NE(s.briefReport().find("design too coarse"), std::string::npos);
  EXPECT_EQ(s.parameters[1].name, "c_Ns_per_m");
  // θ_2 = 10 θ_1 on this design, so every summary scales by 10.
  EXPECT_NEAR(s.parameters[1].mean, 10 * s.parameters[0].mean, 1e-9);
  EXPECT_NEAR(s.parameters[1].sd, 10 * s.parameters[0].sd, 1e-9);

  SummaryOptions lenient;
  lenient.dominance_threshold = 0.99;
  const PosteriorSummary ok = summarisePosterior(design, ch, {}, lenient);
  EXPECT_FALSE(ok.design_too_coarse);
  EXPECT_TRUE(ok.message.empty());
  EXPECT_EQ(ok.parameters[0].name, "theta_1");
}

TEST(PosteriorSummary, HugeDataMakeOnePointDominateInTheSampler) {
  // n = 1e6 with well-separated SSE: the Gibbs chain sits on the best point. This is the
  // situation the check exists for.
  std::vector<double> sse;
  for (int k = 0; k < 50; ++k) sse.push_back(1e6 * (1.0 + 0.01 * std::abs(k - 17)));
  GibbsOptions opt;
  opt.iterations = 2000;
  opt.burn_in = 100;
  const GibbsChains ch = runGriddyGibbs(sse, 1000000, opt);
  Eigen::MatrixXd design(50, 1);
  for (int k = 0; k < 50; ++k) design(k, 0) = k;
  const PosteriorSummary s = summarisePosterior(design, ch);
  EXPECT_TRUE(s.design_too_coarse);
  EXPECT_EQ(s.top_point, 17);
  EXPECT_EQ(s.distinct_points, 1);
  EXPECT_TRUE(std::isnan(s.parameters[0].ess));  // constant chain: ESS undefined
}

TEST(PosteriorSummary, InconsistentInputsAreRejected) {
  Eigen::MatrixXd design(3, 1);
  design << 1, 2, 3;
  GibbsChains ch;
  ch.design_points = 4;
  ch.index = {0};
  ch.tau = {1.0};
  try {
    summarisePosterior(design, ch);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the design has 3 rows but the chains were run on 4"),
              std::string::npos)
        << e.what();
  }
  ch.design_points = 3;
  ch.index.clear();
  ch.tau.clear();
  EXPECT_THROW(summarisePosterior(design, ch), InputError);
}

TEST(PosteriorSummary, BadOptionsNameTheField) {
  SummaryOptions o;
  EXPECT_NO_THROW(o.validate());
  o.dominance_threshold = 1.0;
  EXPECT_NO_THROW(o.validate());
  o.dominance_threshold = 0.0;
  try {
    o.validate();
    FAIL() << "dominance_threshold 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "summary.dominance_threshold");
  }
}
