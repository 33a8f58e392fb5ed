// Multivariate normal: log-density against the brute-force formula with an explicit inverse and
// determinant; batch equals single; the LDLT and jitter fallbacks; input errors.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "classification/moments.hpp"
#include "classification/mvn.hpp"
#include "common/errors.hpp"
#include "subsystems/random.hpp"

using namespace dtwin;
using namespace dtwin::classify;

namespace {

const double kLn2Pi = std::log(2.0 * M_PI);

double bruteLogPdf(const Eigen::VectorXd& y, const Eigen::VectorXd& mu, const Eigen::MatrixXd& s) {
  const Eigen::VectorXd r = y - mu;
  const double q = r.dot(s.inverse() * r);
  return -0.5 * (static_cast<double>(y.size()) * kLn2Pi + std::log(s.determinant()) + q);
}

Eigen::MatrixXd randomSpd(int p, RandomStream& rng) {
  Eigen::MatrixXd a(p, p);
  for (int i = 0; i < p; ++i)
    for (int j = 0; j < p; ++j) a(i, j) = rng.normal();
  return a * a.transpose() + 0.5 * Eigen::MatrixXd::Identity(p, p);
}

Eigen::VectorXd randomVector(int p, RandomStream& rng, double scale = 1.0) {
  Eigen::VectorXd v(p);
  for (int i = 0; i < p; ++i) v[i] = scale * rng.normal();
  return v;
}

}  // namespace

TEST(GaussianModel, OneDimensionalClosedForm) {
  const double mu = 1.5, sigma = 0.7;
  GaussianModel g(Eigen::VectorXd::Constant(1, mu), Eigen::MatrixXd::Constant(1, 1, sigma * sigma));
  EXPECT_EQ(g.factorization(), "cholesky");
  EXPECT_EQ(g.jitter(), 0.0);
  for (double y : {-2.0, 1.5, 3.1}) {
    const double expected =
        -0.5 * std::log(2 * M_PI * sigma * sigma) - (y - mu) * (y - mu) / (2 * sigma * sigma);
    EXPECT_NEAR(g.logPdf(Eigen::VectorXd::Constant(1, y)), expected, 1e-14);
  }
  EXPECT_NEAR(g.logDeterminant(), std::log(sigma * sigma), 1e-15);
}

TEST(GaussianModel, MatchesBruteForceForSmallDimensions) {
  RandomStream rng(31, 1);
  for (int p = 1; p <= 6; ++p) {
    const Eigen::MatrixXd s = randomSpd(p, rng);
    const Eigen::VectorXd mu = randomVector(p, rng, 3.0);
    GaussianModel g(mu, s);
    EXPECT_EQ(g.factorization(), "cholesky") << p;
    EXPECT_NEAR(g.logDeterminant(), std::log(s.determinant()),
                1e-12 * (1 + std::abs(g.logDeterminant())));
    for (int t = 0; t < 5; ++t) {
      const Eigen::VectorXd y = mu + randomVector(p, rng, 2.0);
      const double ref = bruteLogPdf(y, mu, s);
      EXPECT_NEAR(g.logPdf(y), ref, 1e-11 * (1 + std::abs(ref))) << "p " << p;
    }
  }
}

TEST(GaussianModel, BatchEqualsSingle) {
  RandomStream rng(32, 1);
  const int p = 9, R = 17;
  const Eigen::MatrixXd s = randomSpd(p, rng);
  const Eigen::VectorXd mu = randomVector(p, rng);
  Eigen::MatrixXd Y(p, R);
  for (int r = 0; r < R; ++r) Y.col(r) = mu + randomVector(p, rng, 1.5);
  for (bool ldlt : {false, true}) {
    FactorOptions o;
    o.try_cholesky = !ldlt;
    GaussianModel g(mu, s, o);
    const Eigen::VectorXd batch = g.logPdfBatch(Y);
    ASSERT_EQ(batch.size(), R);
    for (int r = 0; r < R; ++r)
      EXPECT_NEAR(batch[r], g.logPdf(Y.col(r)), 1e-12 * std::abs(batch[r])) << r;
  }
}

TEST(GaussianModel, LdltPathMatchesBruteForce) {
  // Skipping plain Cholesky forces the pivoted LDLT path (P Σ Pᵀ = L D Lᵀ).
  RandomStream rng(33, 1);
  FactorOptions o;
  o.try_cholesky = false;
  for (int p : {1, 3, 8}) {
    Eigen::MatrixXd s = randomSpd(p, rng);
    s(p - 1, p - 1) += 40.0;  // a large last variance makes the pivoting permute
    const Eigen::VectorXd mu = randomVector(p, rng);
    GaussianModel g(mu, s, o);
    EXPECT_EQ(g.factorization(), "ldlt");
    EXPECT_EQ(g.jitter(), 0.0);
    EXPECT_NEAR(g.logDeterminant(), std::log(s.determinant()),
                1e-12 * (1 + std::abs(g.logDeterminant())));
    for (int t = 0; t < 4; ++t) {
      const Eigen::VectorXd y = mu + randomVector(p, rng, 2.0);
      const double ref = bruteLogPdf(y, mu, s);
      EXPECT_NEAR(g.logPdf(y), ref, 1e-11 * (1 + std::abs(ref))) << "p " << p;
    }
  }
}

TEST(GaussianModel, ExactlySingularUsesSmallestJitter) {
  // [[1, 1], [1, 1]]: the second Cholesky pivot and the second LDLT pivot are exactly 0, so the
  // first jitter ε = 1e-10 (× mean diag 1) is taken; the density is that of Σ + 1e-10 I.
  Eigen::MatrixXd s(2, 2);
  s << 1, 1, 1, 1;
  const Eigen::VectorXd mu = Eigen::Vector2d(0.5, -0.5);
  GaussianModel g(mu, s);
  EXPECT_EQ(g.factorization(), "cholesky+jitter(1e-10)");
  EXPECT_DOUBLE_EQ(g.jitter(), 1e-10);
  EXPECT_DOUBLE_EQ(g.jitterAbsolute(), 1e-10);
  const Eigen::VectorXd y = Eigen::Vector2d(1.0, 0.0);  // y − μ lies along (1, 1): in range
  // Closed form for Σ + εI: eigenvalues 2 + ε (along (1,1)/√2) and ε; y − μ = (0.5, 0.5).
  const double eps = 1e-10;
  const double expected = -0.5 * (2 * kLn2Pi + std::log((2 + eps) * eps) + 0.5 / (2 + eps));
  EXPECT_NEAR(g.logPdf(y), expected, 1e-6 * std::abs(expected));
}

TEST(GaussianModel, PivotBelowRoundingLevelIsNotAccepted) {
  // diag(1, 1e-17): Cholesky "succeeds" in floating point, but the pivot 1e-17 is below the
  // default tolerance p · 2.2e-16 · max diag = 4.4e-16, so jitter 1e-10 × mean diag is added.
  const Eigen::MatrixXd s = Eigen::Vector2d(1.0, 1e-17).asDiagonal();
  GaussianModel g(Eigen::Vector2d::Zero(), s);
  EXPECT_EQ(g.factorization(), "cholesky+jitter(1e-10)");
  EXPECT_DOUBLE_EQ(g.jitterAbsolute(), 1e-10 * 0.5 * (1.0 + 1e-17));
  EXPECT_NEAR(g.logDeterminant(), std::log((1.0 + 5e-11) * (1e-17 + 5e-11)), 1e-9);
  // With pivot_tolerance = 0 any positive pivot is accepted.
  FactorOptions o;
  o.pivot_tolerance = 0.0;
  GaussianModel plain(Eigen::Vector2d::Zero(), s, o);
  EXPECT_EQ(plain.factorization(), "cholesky");
  EXPECT_NEAR(plain.relativeMinPivot(), 1e-17, 1e-30);
}

TEST(GaussianModel, RankDeficientSampleCovarianceFallsBackAndStaysFinite) {
  // 5 samples in 20 dimensions: the sample covariance has rank 4.
  RandomStream rng(34, 1);
  const int p = 20, n = 5;
  MomentAccumulator acc(p);
  for (int k = 0; k < n; ++k) acc.add(randomVector(p, rng, 2.0));
  const Eigen::MatrixXd s = acc.covariance();
  GaussianModel g(acc.mean(), s);
  EXPECT_EQ(g.factorization().rfind("cholesky+jitter(", 0), 0u) << g.factorization();
  EXPECT_GT(g.jitter(), 0.0);
  EXPECT_LE(g.jitter(), 1e-3);
  EXPECT_NEAR(g.jitterAbsolute(), g.jitter() * s.diagonal().mean(), 1e-15 * s.diagonal().mean());
  const Eigen::VectorXd y = acc.mean() + randomVector(p, rng);
  const double lp = g.logPdf(y);
  EXPECT_TRUE(std::isfinite(lp)) << lp;
  // The reported jitter is what was used: brute force on Σ + jitter I agrees.
  const Eigen::MatrixXd sj = s + g.jitterAbsolute() * Eigen::MatrixXd::Identity(p, p);
  const Eigen::LLT<Eigen::MatrixXd> llt(sj);
  const Eigen::VectorXd z = llt.matrixL().solve(y - acc.mean());
  const double ref =
      -0.5 * (p * kLn2Pi + 2 * llt.matrixLLT().diagonal().array().log().sum() + z.squaredNorm());
  EXPECT_NEAR(lp, ref, 1e-6 * std::abs(ref));
  EXPECT_TRUE(std::isfinite(g.logPdfBatch(y.replicate(1, 3)).sum()));
}

TEST(GaussianModel, IndefiniteMatrixIsRejectedWithExplanation) {
  Eigen::MatrixXd s(2, 2);
  s << 1, 2, 2, 1;  // eigenvalues 3 and −1: no jitter up to 1e-3 helps
  try {
    GaussianModel g(Eigen::Vector2d::Zero(), s);
    ADD_FAILURE() << g.factorization();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("Gaussian model: covariance is not positive definite: Cholesky failed; "
                        "LDLT has a non-positive pivot",
                        0),
              0u)
        << msg;
    EXPECT_NE(msg.find("jitter up to 0.001 x mean(diag) = 0.001 also failed"), std::string::npos)
        << msg;
  }
}

TEST(GaussianModel, InputErrorsNameTheField) {
  Eigen::MatrixXd s = Eigen::MatrixXd::Identity(2, 2);
  s(0, 1) = 0.5;
  try {
    GaussianModel g(Eigen::Vector2d::Zero(), s);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "Gaussian model: covariance is not symmetric: entry (0, 1) = 0.5 but (1, 0) = 0");
  }
  FactorOptions o;
  o.jitter_growth = 1.0;
  try {
    o.validate();
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "factor.jitter_growth: must be a finite number > 1, got 1");
  }
  GaussianModel g(Eigen::Vector2d::Zero(), Eigen::MatrixXd::Identity(2, 2));
  try {
    g.logPdf(Eigen::Vector3d::Zero());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "Gaussian model: record has length 3, expected 2");
  }
  EXPECT_THROW(GaussianModel(Eigen::Vector3d::Zero(), Eigen::MatrixXd::Identity(2, 2)), InputError);
}
