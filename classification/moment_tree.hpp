#pragma once
// A fixed-order tree of partial moment accumulators: the reduction that gives the same bits
// whatever the number of threads, processes or machines that computed its parts.
//
// \par The tree
// The vectors of a synthesis are grouped in n LEAVES (a leaf: a fixed number of blocks, each
// added with MomentAccumulator::addBlock in block order, starting from an empty accumulator).
// Node (level l, index i) covers the leaves [i·2^l, (i+1)·2^l) ∩ [0, n):
//     node(0, i)     = leaf i
//     node(l + 1, k) = node(l, 2k).merge(node(l, 2k + 1)), or node(l, 2k) alone when node(l, 2k +
//     1)
//                      covers no leaf (it would start at or after n).
// The result is node(L, 0) with 2^L >= n. Each node is a function of its leaves only, so any set
// of workers that computes disjoint nodes and merges siblings gives the result bit for bit
// (MomentAccumulator::merge is commutative bit for bit; it is not associative, which is why the
// shape is fixed).
//
// \par A contiguous range
// MomentTree holds the leaves [first, end) of such a tree as its canonical list: the nodes in
// leaf order, every pair of siblings merged as soon as both are present (a binary counter:
// at most about 2 log2(n) nodes). pushLeaf() adds the next leaf; append() adds the list of the
// range that follows (another thread's or rank's). When the range is [0, n) the list is the one
// root node. Serialised (toVector/fromVector) for transfer between processes and for checkpoints.
#include <cstdint>
#include <vector>

#include "classification/moments.hpp"

namespace dtwin::classify {

struct TreeNode {
  int level = 0;
  long index = 0;
  MomentAccumulator acc{1};
  long firstLeaf() const { return index << level; }
};

class MomentTree {
 public:
  /// An empty range starting at leaf `first` of a tree with `leaves` leaves (InputError unless
  /// 0 <= first <= leaves and leaves >= 1).
  MomentTree(long leaves, long first = 0);

  long leaves() const { return n_; }
  long first() const { return first_; }
  /// One past the last leaf held.
  long end() const { return end_; }
  bool empty() const { return end_ == first_; }
  /// True when the range is [0, leaves): one node, the tree's root.
  bool complete() const { return first_ == 0 && end_ == n_; }

  /// Adds leaf end() (its accumulator moved in) and merges the siblings this completes.
  void pushLeaf(MomentAccumulator leaf);
  /// Adds the range that starts at end() (InputError otherwise, or for another tree's range).
  void append(MomentTree&& right);
  /// The root's accumulator (logic error unless complete()).
  const MomentAccumulator& root() const;
  MomentAccumulator takeRoot();

  const std::vector<TreeNode>& nodes() const { return nodes_; }
  /// Number of nodes in the canonical list of leaves [first, end) of a `leaves`-leaf tree (the
  /// same rules as pushLeaf, without accumulators: for cost models).
  static long nodeCount(long leaves, long first, long end);
  /// Rebuilds a range from its nodes (for a checkpoint): they must be the canonical list of
  /// [first, end) (InputError naming `where` otherwise).
  static MomentTree fromNodes(long leaves, long first, std::vector<TreeNode> nodes,
                              const std::string& where);

  /// Flat form, all doubles: leaves, first, end, node count, then per node level, index, length
  /// of its MomentAccumulator::toVector() and that vector.
  std::vector<double> toVector() const;
  static MomentTree fromVector(const std::vector<double>& v);

 private:
  void push(TreeNode node);
  long n_, first_, end_;
  std::vector<TreeNode> nodes_;
};

}  // namespace dtwin::classify
