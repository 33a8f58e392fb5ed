// The model behind `twin bench --accumulation` (study/bench_accumulation.hpp): its node counts are
// the accumulation tree's own, and with free communication and leaves that divide evenly it gives
// the ideal speed-up; with the measured kind of costs it stays below it.
#include "study/bench_accumulation.hpp"

#include <gtest/gtest.h>

#include "classification/moment_tree.hpp"

using namespace dtwin;

TEST(AccumulationModel, NodeCountsAreTheTreesOwn) {
  for (long n : {1L, 2L, 7L, 13L, 64L})
    for (long a = 0; a <= n; ++a)
      for (long b = a; b <= n; ++b) {
        classify::MomentTree t(n, a);
        for (long i = a; i < b; ++i) {
          classify::MomentAccumulator leaf(1);
          leaf.add(Eigen::VectorXd::Constant(1, static_cast<double>(i)));
          t.pushLeaf(std::move(leaf));
        }
        ASSERT_EQ(classify::MomentTree::nodeCount(n, a, b), static_cast<long>(t.nodes().size()))
            << n << " leaves, [" << a << ", " << b << ")";
      }
}

TEST(AccumulationModel, FreeCommunicationAndEvenLeavesGiveTheIdealSpeedUp) {
  AccumulationCosts c;
  c.draws = 64 * 32;  // 64 leaves of 2 blocks of 16 draws
  c.roads = 5;
  c.block = 16;
  c.leaf_blocks = 2;
  c.leaves = 64;
  c.draw_s = 0.2;
  c.add_per_vector_s = 0.001;
  c.link_bytes_per_s = 1e30;  // merge, pack, unpack, save and node bytes stay 0
  const ScalingRow one = modelSynthesisWall(c, 1);
  EXPECT_NEAR(one.wall_s, static_cast<double>(c.draws) * (c.draw_s + 5 * c.add_per_vector_s), 1e-9);
  for (int k : {2, 8, 64}) {
    const ScalingRow r = modelSynthesisWall(c, k);
    EXPECT_NEAR(r.wall_s, one.wall_s / k, 1e-9) << k << " ranks";
    EXPECT_EQ(r.combine_s, 0.0);
  }
  // The earlier scheme adds every vector on every rank: its wall never falls below that.
  EXPECT_GE(modelSynthesisWall(c, 64).ordered_wall_s,
            static_cast<double>(c.draws * c.roads) * c.add_per_vector_s);
}

TEST(AccumulationModel, MergesAndTransfersCostTheCombination) {
  AccumulationCosts c;
  c.draws = 10000;
  c.roads = 5;
  c.block = 16;
  c.leaf_blocks = 2;
  c.leaves = 313;
  c.draw_s = 0.16;
  c.add_per_vector_s = 0.0012;
  c.merge_s = 0.03;
  c.pack_s = 0.05;
  c.unpack_s = 0.07;
  c.save_s = 0.15;
  c.node_bytes = 1e8;
  c.link_bytes_per_s = 1e10;
  const ScalingRow one = modelSynthesisWall(c, 1), many = modelSynthesisWall(c, 64);
  EXPECT_NEAR(one.wall_s, 10000 * (0.16 + 5 * 0.0012) + 312 * 0.03, 1e-6);
  EXPECT_GT(many.combine_s, 6 * (0.05 + 0.01 + 0.07));  // at least one node per step of log2 64
  EXPECT_LT(one.wall_s / many.wall_s, 64.0);
  EXPECT_GT(one.wall_s / many.wall_s, 0.5 * 64);
}
