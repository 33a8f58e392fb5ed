// The fixed-order tree of partial accumulators (classification/moment_tree.hpp): the same bits
// whichever way the leaves are split among workers, and the same moments as one accumulator.
#include "classification/moment_tree.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::classify;

namespace {

constexpr int kDim = 7;

/// Leaf i: a fixed number of random vectors with its own seed and an offset of its own.
MomentAccumulator leaf(long i) {
  std::mt19937_64 rng(1000 + static_cast<unsigned long>(i));
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd X(kDim, 3 + i % 4);
  for (Eigen::Index c = 0; c < X.cols(); ++c)
    for (Eigen::Index r = 0; r < kDim; ++r)
      X(r, c) = 50.0 * static_cast<double>(i) + (1.0 + r) * g(rng);
  MomentOptions mo;
  mo.track_fourth_moment = true;
  MomentAccumulator a(kDim, mo);
  a.addBlock(X);
  return a;
}

/// The tree's definition, recursively: node (l, k) of n leaves.
MomentAccumulator byDefinition(int level, long index, long n) {
  if (level == 0) return leaf(index);
  MomentAccumulator left = byDefinition(level - 1, 2 * index, n);
  if (((2 * index + 1) << (level - 1)) < n) left.merge(byDefinition(level - 1, 2 * index + 1, n));
  return left;
}

std::vector<double> bits(const MomentAccumulator& a) { return a.toVector(); }

MomentTree range(long n, long first, long end) {
  MomentTree t(n, first);
  for (long i = first; i < end; ++i) t.pushLeaf(leaf(i));
  return t;
}

}  // namespace

TEST(MomentTree, EverySplitOfTheLeavesGivesTheTreesBits) {
  for (long n : {1L, 2L, 3L, 5L, 8L, 11L, 13L}) {
    int levels = 0;
    while ((1L << levels) < n) ++levels;
    const std::vector<double> want = bits(byDefinition(levels, 0, n));
    // One worker, leaf by leaf.
    MomentTree one = range(n, 0, n);
    ASSERT_TRUE(one.complete());
    EXPECT_EQ(bits(one.root()), want) << n << " leaves, one worker";
    // Every split into three contiguous ranges, appended left to right or right first.
    for (long a = 0; a <= n; ++a)
      for (long b = a; b <= n; ++b) {
        MomentTree x = range(n, 0, a), y = range(n, a, b), z = range(n, b, n);
        MomentTree yz = std::move(y);
        yz.append(std::move(z));
        MomentTree right_first = std::move(x);
        right_first.append(std::move(yz));
        ASSERT_TRUE(right_first.complete());
        EXPECT_EQ(bits(right_first.root()), want) << n << " leaves split at " << a << ", " << b;
        MomentTree left_first = range(n, 0, a);
        left_first.append(range(n, a, b));
        left_first.append(range(n, b, n));
        EXPECT_EQ(bits(left_first.root()), want)
            << n << " leaves split at " << a << ", " << b << " (left first)";
      }
  }
}

TEST(MomentTree, TheRootHoldsTheMomentsOfEveryVector) {
  const long n = 11;
  MomentTree t = range(n, 0, n);
  MomentOptions mo;
  mo.track_fourth_moment = true;
  MomentAccumulator all(kDim, mo);
  for (long i = 0; i < n; ++i) all.merge(leaf(i));
  const MomentAccumulator& r = t.root();
  EXPECT_EQ(r.count(), all.count());
  EXPECT_LT((r.mean() - all.mean()).cwiseAbs().maxCoeff(),
            1e-12 * all.mean().cwiseAbs().maxCoeff());
  EXPECT_LT((r.covariance() - all.covariance()).cwiseAbs().maxCoeff(),
            1e-11 * all.covariance().cwiseAbs().maxCoeff());
  EXPECT_NEAR(r.getFourthMoment(), all.getFourthMoment(), 1e-11 * all.getFourthMoment());
}

TEST(MomentTree, ARangeKeepsAboutTwoNodesPerLevel) {
  const long n = 1000;
  MomentTree t(n, 0);
  std::size_t most = 0;
  MomentOptions mo;
  for (long i = 0; i < n; ++i) {
    MomentAccumulator a(2, mo);
    a.add(Eigen::Vector2d(static_cast<double>(i), 1.0));
    t.pushLeaf(std::move(a));
    most = std::max(most, t.nodes().size());
  }
  EXPECT_LE(most, 10u);  // a binary counter of 1000: at most 10 nodes
  EXPECT_EQ(t.nodes().size(), 1u);
  EXPECT_EQ(t.root().count(), n);
}

TEST(MomentTree, FlatFormRoundTripsAndRejectsWhatIsNotCanonical) {
  const long n = 13;
  MomentTree t = range(n, 3, 9);
  const std::vector<double> v = t.toVector();
  MomentTree back = MomentTree::fromVector(v);
  EXPECT_EQ(back.first(), 3);
  EXPECT_EQ(back.end(), 9);
  ASSERT_EQ(back.nodes().size(), t.nodes().size());
  for (std::size_t k = 0; k < t.nodes().size(); ++k)
    EXPECT_EQ(bits(back.nodes()[k].acc), bits(t.nodes()[k].acc));
  std::vector<double> cut(v.begin(), v.end() - 1);
  EXPECT_THROW(MomentTree::fromVector(cut), InputError);
  // Two sibling leaves left unmerged are not a canonical list.
  std::vector<TreeNode> loose(2);
  loose[0].index = 4;
  loose[0].acc = leaf(4);
  loose[1].index = 5;
  loose[1].acc = leaf(5);
  EXPECT_THROW(MomentTree::fromNodes(n, 4, std::move(loose), "checkpoint.json"), InputError);
  MomentTree a = range(n, 0, 4);
  EXPECT_THROW(a.append(range(n, 5, 7)), InputError);      // a gap
  EXPECT_THROW(a.append(range(n + 1, 4, 7)), InputError);  // another tree
}
