// Ledoit–Wolf shrinkage from a streaming accumulator against a brute-force, two-pass
// computation of the LW (2004) estimator that forms every x_k x_kᵀ − S_n explicitly.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "classification/shrinkage.hpp"
#include "common/errors.hpp"
#include "subsystems/random.hpp"

using namespace dtwin;
using namespace dtwin::classify;

namespace {

Eigen::MatrixXd makeData(int p, int n, std::uint64_t seed, double corr) {
  RandomStream rng(seed, 21);
  Eigen::MatrixXd x(p, n);
  for (int k = 0; k < n; ++k) {
    const double common = rng.normal();
    for (int i = 0; i < p; ++i)
      x(i, k) = 3.0 + 0.5 * i + (1.0 + 0.2 * i) * rng.normal() + corr * common;
  }
  return x;
}

struct BruteLw {
  double m, d2, b2_bar, rho;
  Eigen::MatrixXd shrunk;
};

// Ledoit & Wolf (2004), Lemma 3.2 / Theorem 3.2, written out literally.
BruteLw bruteForce(const Eigen::MatrixXd& x) {
  const int p = static_cast<int>(x.rows());
  const double n = static_cast<double>(x.cols());
  const Eigen::MatrixXd c = x.colwise() - x.rowwise().mean();
  const Eigen::MatrixXd s = c * c.transpose() / n;
  const Eigen::MatrixXd id = Eigen::MatrixXd::Identity(p, p);
  auto norm2 = [p](const Eigen::MatrixXd& a) { return (a * a.transpose()).trace() / p; };
  BruteLw r;
  r.m = s.trace() / p;
  r.d2 = norm2(s - r.m * id);
  double sum = 0.0;
  for (Eigen::Index k = 0; k < x.cols(); ++k) sum += norm2(c.col(k) * c.col(k).transpose() - s);
  r.b2_bar = sum / (n * n);
  const double b2 = std::min(r.b2_bar, r.d2);
  r.rho = b2 / r.d2;
  r.shrunk = (b2 / r.d2) * r.m * id + ((r.d2 - b2) / r.d2) * s;
  return r;
}

MomentAccumulator accumulate(const Eigen::MatrixXd& x, int mode) {
  MomentOptions o;
  o.track_fourth_moment = true;
  MomentAccumulator acc(static_cast<int>(x.rows()), o);
  const Eigen::Index n = x.cols();
  if (mode == 0) {
    for (Eigen::Index k = 0; k < n; ++k) acc.add(x.col(k));
  } else if (mode == 1) {
    for (Eigen::Index k = 0; k < n; k += 8)
      acc.addBlock(x.middleCols(k, std::min<Eigen::Index>(8, n - k)));
  } else {  // three partial accumulators merged in order
    const Eigen::Index a = n / 3, b = 2 * n / 3;
    MomentAccumulator p1(static_cast<int>(x.rows()), o), p2 = p1, p3 = p1;
    p1.addBlock(x.leftCols(a));
    for (Eigen::Index k = a; k < b; ++k) p2.add(x.col(k));
    p3.addBlock(x.rightCols(n - b));
    acc.merge(p1);
    acc.merge(p2);
    acc.merge(p3);
  }
  return acc;
}

}  // namespace

TEST(LedoitWolf, MatchesBruteForceEstimator) {
  // (p, n, correlation): many samples (little shrinkage), few samples (strong shrinkage),
  // more dimensions than samples.
  struct Case {
    int p, n;
    double corr;
  };
  for (const Case& cs : {Case{6, 200, 1.5}, Case{10, 15, 0.3}, Case{25, 12, 0.0}}) {
    const Eigen::MatrixXd x = makeData(cs.p, cs.n, 100 + cs.p, cs.corr);
    const BruteLw ref = bruteForce(x);
    for (int mode : {0, 1, 2}) {
      const std::string what = "p " + std::to_string(cs.p) + " n " + std::to_string(cs.n) +
                               " mode " + std::to_string(mode);
      const LedoitWolfEstimate lw = calcLedoitWolf(accumulate(x, mode));
      EXPECT_EQ(lw.count, cs.n) << what;
      EXPECT_EQ(lw.dimension, cs.p) << what;
      EXPECT_NEAR(lw.target_scale, ref.m, 1e-12 * ref.m) << what;
      EXPECT_NEAR(lw.d2, ref.d2, 1e-10 * ref.d2) << what;
      EXPECT_NEAR(lw.b2_bar, ref.b2_bar, 1e-9 * ref.b2_bar) << what;
      EXPECT_NEAR(lw.intensity, ref.rho, 1e-9) << what;
      EXPECT_GT(lw.intensity, 0.0) << what;
      EXPECT_LE(lw.intensity, 1.0) << what;
      EXPECT_LT((lw.covariance - ref.shrunk).cwiseAbs().maxCoeff(),
                1e-10 * ref.shrunk.cwiseAbs().maxCoeff())
          << what;
      const LedoitWolfEstimate scalars = calcLedoitWolf(accumulate(x, mode), false);
      EXPECT_EQ(scalars.covariance.size(), 0) << what;
      EXPECT_EQ(scalars.intensity, lw.intensity) << what;
    }
  }
}

TEST(LedoitWolf, FullShrinkageWhenNoiseExceedsDispersion) {
  // The 2p vectors ±c_i e_i: mean 0, S_n = diag(c_i² / p) exactly. With c = (1.1, 1, 1, 1) the
  // dispersion d² = Σ (c_i²/p − m)² / p is tiny while every x xᵀ is far from S_n, so b̄² > d²,
  // b² = min(b̄², d²) = d², ρ = 1 and Σ* = m I with m = Σ c_i² / p².
  const int p = 4;
  const Eigen::Vector4d c(1.1, 1.0, 1.0, 1.0);
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(p, 2 * p);
  for (int i = 0; i < p; ++i) {
    x(i, 2 * i) = c[i];
    x(i, 2 * i + 1) = -c[i];
  }
  const BruteLw ref = bruteForce(x);
  ASSERT_GT(ref.b2_bar, ref.d2);  // the case this test is about
  const double m = c.squaredNorm() / (p * p);
  const double d2 = (c.array().square() / p - m).square().sum() / p;
  for (int mode : {0, 1, 2}) {
    const LedoitWolfEstimate lw = calcLedoitWolf(accumulate(x, mode));
    EXPECT_NEAR(lw.target_scale, m, 1e-15) << mode;
    EXPECT_NEAR(lw.d2, d2, 1e-15) << mode;
    EXPECT_NEAR(lw.b2_bar, ref.b2_bar, 1e-13) << mode;
    EXPECT_EQ(lw.intensity, 1.0) << mode;
    EXPECT_LT((lw.covariance - m * Eigen::MatrixXd::Identity(p, p)).cwiseAbs().maxCoeff(), 1e-15)
        << mode;
  }
  // c all equal: S_n = m I already, d² = 0, so ρ = 0 and Σ* = S_n.
  x = x.cwiseQuotient(Eigen::MatrixXd(c.replicate(1, 2 * p)));
  const LedoitWolfEstimate flat = calcLedoitWolf(accumulate(x, 1));
  EXPECT_EQ(flat.d2, 0.0);
  EXPECT_EQ(flat.intensity, 0.0);
  EXPECT_LT((flat.covariance - 0.25 * Eigen::MatrixXd::Identity(p, p)).cwiseAbs().maxCoeff(),
            1e-16);
}

TEST(LedoitWolf, FewSamplesShrinkMoreThanMany) {
  // Same distribution: the shrinkage intensity falls as n grows (b̄² = O(1/n)).
  const Eigen::MatrixXd x = makeData(8, 4000, 7, 0.5);
  MomentOptions o;
  o.track_fourth_moment = true;
  double last = 2.0;
  for (int n : {10, 100, 4000}) {
    MomentAccumulator acc(8, o);
    acc.addBlock(x.leftCols(n));
    const double rho = calcLedoitWolf(acc, false).intensity;
    EXPECT_LT(rho, last) << "n " << n;
    last = rho;
  }
  EXPECT_LT(last, 0.05);
}

TEST(LedoitWolf, RequiresFourthMomentAndTwoVectors) {
  MomentAccumulator plain(3);
  plain.add(Eigen::Vector3d(1, 2, 3));
  plain.add(Eigen::Vector3d(2, 2, 1));
  try {
    calcLedoitWolf(plain);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("track_fourth_moment"), std::string::npos) << e.what();
  }
  MomentOptions o;
  o.track_fourth_moment = true;
  MomentAccumulator one(3, o);
  one.add(Eigen::Vector3d(1, 2, 3));
  try {
    calcLedoitWolf(one);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "Ledoit-Wolf shrinkage: needs at least 2 vectors, got 1");
  }
}
