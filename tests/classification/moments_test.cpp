// Streaming moments: single adds, batched adds and merges against a two-pass computation; the
// optional third/fourth moments; bitwise properties (commutative merge, tracking does not change
// the mean/covariance); exact serialisation round trips; input errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "classification/moments.hpp"
#include "common/errors.hpp"
#include "subsystems/random.hpp"

using namespace dtwin;
using namespace dtwin::classify;

namespace {

// n correlated vectors of length p (columns), with a non-zero mean, from a fixed stream.
Eigen::MatrixXd makeData(int p, int n, std::uint64_t seed, double offset = 10.0) {
  RandomStream rng(seed, 11);
  Eigen::MatrixXd mix(p, p);
  for (int i = 0; i < p; ++i)
    for (int j = 0; j < p; ++j) mix(i, j) = (i == j ? 1.0 : 0.0) + 0.3 * rng.normal();
  Eigen::MatrixXd z(p, n);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < p; ++i) z(i, k) = rng.normal();
  Eigen::MatrixXd x = mix * z;
  for (int i = 0; i < p; ++i) x.row(i).array() += offset + i;
  return x;
}

struct TwoPass {
  Eigen::VectorXd mean;
  Eigen::MatrixXd cov;  // unbiased
  Eigen::VectorXd t;    // Σ ‖x − μ‖² (x − μ)
  double q = 0.0;       // Σ ‖x − μ‖⁴
};

TwoPass twoPass(const Eigen::MatrixXd& x) {
  TwoPass r;
  const double n = static_cast<double>(x.cols());
  r.mean = x.rowwise().sum() / n;
  const Eigen::MatrixXd c = x.colwise() - r.mean;
  r.cov = c * c.transpose() / (n - 1.0);
  r.t = Eigen::VectorXd::Zero(x.rows());
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    const double s = c.col(k).squaredNorm();
    r.t += s * c.col(k);
    r.q += s * s;
  }
  return r;
}

void expectMatches(const MomentAccumulator& acc, const TwoPass& ref, const std::string& what) {
  const double mscale = ref.mean.cwiseAbs().maxCoeff();
  EXPECT_LT((acc.mean() - ref.mean).cwiseAbs().maxCoeff(), 1e-13 * mscale) << what;
  const double cscale = ref.cov.cwiseAbs().maxCoeff();
  EXPECT_LT((acc.covariance() - ref.cov).cwiseAbs().maxCoeff(), 1e-12 * cscale) << what;
  if (acc.tracksFourthMoment()) {
    EXPECT_LT((acc.getThirdMoment() - ref.t).cwiseAbs().maxCoeff(),
              1e-10 * ref.t.cwiseAbs().maxCoeff())
        << what;
    EXPECT_NEAR(acc.getFourthMoment(), ref.q, 1e-11 * ref.q) << what;
  }
}

MomentOptions tracked(bool on) {
  MomentOptions o;
  o.track_fourth_moment = on;
  return o;
}

void expectBitwiseEqual(const MomentAccumulator& a, const MomentAccumulator& b,
                        const std::string& what) {
  EXPECT_EQ(a.toVector(), b.toVector()) << what;
}

}  // namespace

TEST(MomentAccumulator, SingleAddsMatchTwoPass) {
  const Eigen::MatrixXd x = makeData(7, 300, 1);
  const TwoPass ref = twoPass(x);
  for (bool track : {false, true}) {
    MomentAccumulator acc(7, tracked(track));
    for (Eigen::Index k = 0; k < x.cols(); ++k) acc.add(x.col(k));
    EXPECT_EQ(acc.count(), 300);
    expectMatches(acc, ref, track ? "tracked" : "untracked");
  }
}

TEST(MomentAccumulator, BatchedAddsMatchTwoPassForEveryBlockSize) {
  const Eigen::MatrixXd x = makeData(9, 257, 2);
  const TwoPass ref = twoPass(x);
  for (int block : {1, 2, 7, 64, 256, 257}) {
    MomentAccumulator acc(9, tracked(true));
    for (Eigen::Index k = 0; k < x.cols(); k += block) {
      const Eigen::Index len = std::min<Eigen::Index>(block, x.cols() - k);
      acc.addBlock(x.middleCols(k, len));
    }
    EXPECT_EQ(acc.count(), 257);
    expectMatches(acc, ref, "block " + std::to_string(block));
  }
}

TEST(MomentAccumulator, MergesOfPartialAccumulatorsMatchTwoPass) {
  const Eigen::MatrixXd x = makeData(6, 200, 3);
  const TwoPass ref = twoPass(x);
  // Different splits, each part built by single adds (even parts) or one block (odd parts),
  // then merged in part order; includes empty and one-vector parts.
  const std::vector<std::vector<int>> splits = {
      {0, 100, 200}, {0, 1, 200}, {0, 0, 50, 51, 120, 200}, {0, 199, 200}, {0, 17, 33, 90, 200}};
  for (bool track : {false, true})
    for (const auto& cut : splits) {
      MomentAccumulator total(6, tracked(track));
      for (std::size_t s = 0; s + 1 < cut.size(); ++s) {
        MomentAccumulator part(6, tracked(track));
        if (cut[s + 1] > cut[s]) {
          if (s % 2 == 0)
            for (int k = cut[s]; k < cut[s + 1]; ++k) part.add(x.col(k));
          else
            part.addBlock(x.middleCols(cut[s], cut[s + 1] - cut[s]));
        }
        total.merge(part);
      }
      EXPECT_EQ(total.count(), 200);
      expectMatches(total, ref, "split of " + std::to_string(cut.size() - 1) + " parts");
    }
}

TEST(MomentAccumulator, BlockEqualsSingleAddsWithinRounding) {
  const Eigen::MatrixXd x = makeData(12, 64, 4);
  MomentAccumulator single(12, tracked(true)), block(12, tracked(true));
  for (Eigen::Index k = 0; k < x.cols(); ++k) single.add(x.col(k));
  block.addBlock(x);
  EXPECT_LT((single.mean() - block.mean()).cwiseAbs().maxCoeff(), 1e-13 * 25);
  const Eigen::MatrixXd cs = single.covariance(), cb = block.covariance();
  EXPECT_LT((cs - cb).cwiseAbs().maxCoeff(), 1e-13 * cs.cwiseAbs().maxCoeff());
  EXPECT_NEAR(single.getFourthMoment(), block.getFourthMoment(), 1e-12 * block.getFourthMoment());
}

TEST(MomentAccumulator, MergeIsBitwiseCommutativeAndBlockingIsReproducible) {
  const Eigen::MatrixXd x = makeData(5, 90, 5);
  MomentAccumulator a(5, tracked(true)), b(5, tracked(true));
  a.addBlock(x.leftCols(37));
  for (int k = 37; k < 90; ++k) b.add(x.col(k));
  MomentAccumulator ab = a, ba = b;
  ab.merge(b);
  ba.merge(a);
  expectBitwiseEqual(ab, ba, "merge(a, b) vs merge(b, a)");
  // The same fixed blocking twice gives the identical bits.
  MomentAccumulator r1(5, tracked(true)), r2(5, tracked(true));
  for (MomentAccumulator* r : {&r1, &r2})
    for (int k = 0; k < 90; k += 16) r->addBlock(x.middleCols(k, std::min(16, 90 - k)));
  expectBitwiseEqual(r1, r2, "repeat of a fixed blocking");
}

TEST(MomentAccumulator, TrackingDoesNotChangeMeanOrScatter) {
  const Eigen::MatrixXd x = makeData(8, 50, 6);
  MomentAccumulator plain(8, tracked(false)), withq(8, tracked(true));
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    plain.add(x.col(k));
    withq.add(x.col(k));
  }
  EXPECT_EQ(plain.count(), withq.count());
  EXPECT_TRUE(plain.mean() == withq.mean());
  EXPECT_TRUE(plain.getScatterUpper().triangularView<Eigen::Upper>().toDenseMatrix() ==
              withq.getScatterUpper().triangularView<Eigen::Upper>().toDenseMatrix());
}

TEST(MomentAccumulator, MergeWithEmptyAndSelf) {
  const Eigen::MatrixXd x = makeData(4, 30, 7);
  MomentAccumulator a(4, tracked(true));
  a.addBlock(x);
  MomentAccumulator empty(4, tracked(true));
  MomentAccumulator a1 = a;
  a1.merge(empty);
  expectBitwiseEqual(a1, a, "a + empty");
  MomentAccumulator e1 = empty;
  e1.merge(a);
  expectBitwiseEqual(e1, a, "empty + a");
  // a merged with itself = every vector twice.
  MomentAccumulator twice = a;
  twice.merge(twice);
  Eigen::MatrixXd xx(4, 60);
  xx << x, x;
  EXPECT_EQ(twice.count(), 60);
  expectMatches(twice, twoPass(xx), "self merge");
}

TEST(MomentAccumulator, SerialisationRoundTripIsExact) {
  const Eigen::MatrixXd x = makeData(11, 40, 8);
  for (bool track : {false, true}) {
    MomentAccumulator acc(11, tracked(track));
    acc.addBlock(x.leftCols(25));
    const std::vector<double> v = acc.toVector();
    const std::size_t expected = 5 + 11 + 11 * 12 / 2 + (track ? 12 : 0);
    EXPECT_EQ(v.size(), expected);
    const MomentAccumulator back = MomentAccumulator::fromVector(v);
    EXPECT_EQ(back.toVector(), v);
    EXPECT_EQ(back.count(), 25);
    EXPECT_EQ(back.tracksFourthMoment(), track);
    EXPECT_TRUE(back.covariance() == acc.covariance());
    const MomentAccumulator fromb = MomentAccumulator::fromBytes(acc.toBytes());
    EXPECT_EQ(fromb.toVector(), v);
    const std::string path = ::testing::TempDir() + "dtwin_moments_test.bin";
    acc.save(path);
    MomentAccumulator loaded = MomentAccumulator::load(path);
    EXPECT_EQ(loaded.toVector(), v);
    // Resuming from the file continues bit for bit like the original.
    MomentAccumulator cont = acc;
    cont.addBlock(x.rightCols(15));
    loaded.addBlock(x.rightCols(15));
    expectBitwiseEqual(loaded, cont, "resumed");
    std::remove(path.c_str());
  }
}

TEST(MomentAccumulator, RejectsMalformedSerialisations) {
  MomentAccumulator acc(3);
  acc.add(Eigen::Vector3d(1, 2, 3));
  std::vector<double> v = acc.toVector();
  std::vector<double> bad = v;
  bad.pop_back();
  EXPECT_THROW(
      {
        try {
          MomentAccumulator::fromVector(bad);
        } catch (const InputError& e) {
          EXPECT_EQ(std::string(e.what()),
                    "moment accumulator data: has 13 values, expected 14 for dimension 3");
          throw;
        }
      },
      InputError);
  bad = v;
  bad[0] = 1.0;
  try {
    MomentAccumulator::fromVector(bad);
    ADD_FAILURE() << "bad magic accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("header[0] (magic)"), std::string::npos) << e.what();
  }
  bad = v;
  bad[3] = 2.5;
  try {
    MomentAccumulator::fromVector(bad);
    ADD_FAILURE() << "fractional count accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("header[3] (count) is 2.5"), std::string::npos)
        << e.what();
  }
  const std::string path = ::testing::TempDir() + "dtwin_moments_not_a_file.bin";
  { std::ofstream(path) << "hello"; }
  try {
    MomentAccumulator::load(path);
    ADD_FAILURE() << "garbage file accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing tag DTWMOM01"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

TEST(MomentAccumulator, InputErrorsNameTheProblem) {
  MomentAccumulator acc(3);
  try {
    acc.add(Eigen::Vector2d(1, 2));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "moment accumulator: vector has length 2, expected 3");
  }
  try {
    Eigen::MatrixXd x = Eigen::MatrixXd::Ones(3, 4);
    x(1, 2) = std::numeric_limits<double>::quiet_NaN();
    acc.addBlock(x);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "moment accumulator: block column 2 entry 1 is nan (must be finite)");
  }
  EXPECT_EQ(acc.count(), 0);  // nothing was added
  acc.add(Eigen::Vector3d(1, 2, 3));
  try {
    acc.covariance();
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "moment accumulator: covariance needs at least 2 vectors, got 1");
  }
  MomentAccumulator other(4);
  EXPECT_THROW(acc.merge(other), InputError);
  MomentAccumulator tracked3(3, tracked(true));
  EXPECT_THROW(acc.merge(tracked3), InputError);
  EXPECT_THROW(acc.getFourthMoment(), InputError);
  EXPECT_THROW(MomentAccumulator(0), InputError);
}
