#include "classification/moment_tree.hpp"

#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace dtwin::classify {

namespace {
constexpr const char* kTreeWhere = "moment tree";

/// True when node (right_level, right_index) is the right sibling of (left_level, left_index).
bool siblings(int left_level, long left_index, int right_level, long right_index) {
  return left_level == right_level && left_index % 2 == 0 && right_index == left_index + 1;
}
bool siblings(const TreeNode& left, const TreeNode& right) {
  return siblings(left.level, left.index, right.level, right.index);
}

/// True when node (level, index) of an n-leaf tree is its own parent: a left child whose right
/// sibling would start at or after leaf n (and not the root).
bool promotable(int level, long index, long n) {
  const bool is_root = index == 0 && (1L << level) >= n;
  return !is_root && index % 2 == 0 && ((index + 1) << level) >= n;
}

/// Leaves [first, end) of node (level, index) in a tree of n leaves.
long nodeEnd(const TreeNode& node, long n) { return std::min(n, (node.index + 1) << node.level); }
}  // namespace

MomentTree::MomentTree(long leaves, long first) : n_(leaves), first_(first), end_(first) {
  if (leaves < 1)
    throw InputError(kTreeWhere, "needs at least 1 leaf, got " + std::to_string(leaves));
  if (first < 0 || first > leaves)
    throw InputError(kTreeWhere, "a range must start within [0, " + std::to_string(leaves) +
                                     "], got " + std::to_string(first));
}

// Appends a node that starts at end_ and merges while the tail allows: two siblings become their
// parent; a left child whose right sibling covers no leaf (starts at or after n) becomes its parent
// as it is. Every node produced is the tree's node of that (level, index), whoever produced it.
void MomentTree::push(TreeNode node) {
  DTWIN_CHECK(node.firstLeaf() == end_, "moment tree: a node pushed out of order");
  end_ = nodeEnd(node, n_);
  nodes_.push_back(std::move(node));
  for (;;) {
    TreeNode& last = nodes_.back();
    if (nodes_.size() >= 2 && siblings(nodes_[nodes_.size() - 2], last)) {
      TreeNode right = std::move(last);
      nodes_.pop_back();
      TreeNode& left = nodes_.back();
      left.acc.merge(right.acc);
      left.level += 1;
      left.index /= 2;
      continue;
    }
    if (promotable(last.level, last.index, n_)) {
      last.level += 1;  // the right sibling is empty: the parent is this node
      last.index /= 2;
      continue;
    }
    break;
  }
}

void MomentTree::pushLeaf(MomentAccumulator leaf) {
  if (end_ >= n_)
    throw InputError(kTreeWhere, "all " + std::to_string(n_) + " leaves are present already");
  TreeNode node;
  node.level = 0;
  node.index = end_;
  node.acc = std::move(leaf);
  push(std::move(node));
}

void MomentTree::append(MomentTree&& right) {
  if (right.n_ != n_ || right.first_ != end_)
    throw InputError(kTreeWhere, "cannot append leaves [" + std::to_string(right.first_) + ", " +
                                     std::to_string(right.end_) + ") of a " +
                                     std::to_string(right.n_) + "-leaf tree after leaves [" +
                                     std::to_string(first_) + ", " + std::to_string(end_) +
                                     ") of a " + std::to_string(n_) + "-leaf tree");
  for (auto& node : right.nodes_) push(std::move(node));
  right.nodes_.clear();
  right.first_ = right.end_;
}

const MomentAccumulator& MomentTree::root() const {
  DTWIN_CHECK(complete() && nodes_.size() == 1,
              "moment tree: the root is asked for before every leaf is in");
  return nodes_.front().acc;
}

MomentAccumulator MomentTree::takeRoot() {
  DTWIN_CHECK(complete() && nodes_.size() == 1,
              "moment tree: the root is asked for before every leaf is in");
  return std::move(nodes_.front().acc);
}

long MomentTree::nodeCount(long leaves, long first, long end) {
  std::vector<std::pair<int, long>> nodes;  // (level, index): push() without the accumulators
  for (long leaf = first; leaf < end; ++leaf) {
    nodes.emplace_back(0, leaf);
    for (;;) {
      auto& last = nodes.back();
      if (nodes.size() >= 2 && siblings(nodes[nodes.size() - 2].first,
                                        nodes[nodes.size() - 2].second, last.first, last.second)) {
        nodes.pop_back();
      } else if (!promotable(last.first, last.second, leaves)) {
        break;
      }
      nodes.back().first += 1;
      nodes.back().second /= 2;
    }
  }
  return static_cast<long>(nodes.size());
}

MomentTree MomentTree::fromNodes(long leaves, long first, std::vector<TreeNode> nodes,
                                 const std::string& where) {
  MomentTree t(leaves, first);
  for (auto& node : nodes) {
    if (node.level < 0 || node.level > 62 || node.index < 0 || node.firstLeaf() != t.end_ ||
        node.firstLeaf() >= leaves)
      throw InputError(where, "node (" + std::to_string(node.level) + ", " +
                                  std::to_string(node.index) + ") does not continue the leaves [" +
                                  std::to_string(first) + ", " + std::to_string(t.end_) + ")");
    t.end_ = nodeEnd(node, leaves);
    t.nodes_.push_back(std::move(node));
  }
  // Canonical: no two neighbours are siblings and no node could be promoted.
  for (std::size_t i = 0; i < t.nodes_.size(); ++i) {
    const TreeNode& node = t.nodes_[i];
    if ((i + 1 < t.nodes_.size() && siblings(node, t.nodes_[i + 1])) ||
        promotable(node.level, node.index, leaves))
      throw InputError(where, "node (" + std::to_string(node.level) + ", " +
                                  std::to_string(node.index) +
                                  ") should have been merged with its sibling");
  }
  return t;
}

std::vector<double> MomentTree::toVector() const {
  std::vector<double> v{static_cast<double>(n_), static_cast<double>(first_),
                        static_cast<double>(end_), static_cast<double>(nodes_.size())};
  for (const auto& node : nodes_) {
    const std::vector<double> a = node.acc.toVector();
    v.push_back(node.level);
    v.push_back(static_cast<double>(node.index));
    v.push_back(static_cast<double>(a.size()));
    v.insert(v.end(), a.begin(), a.end());
  }
  return v;
}

MomentTree MomentTree::fromVector(const std::vector<double>& v) {
  const std::string where = "moment tree data";
  auto whole = [&](std::size_t at, const char* what) {
    if (at >= v.size()) throw InputError(where, std::string("ends before its ") + what);
    const double x = v[at];
    if (!(x >= 0) || x != std::floor(x) || x > 9.0e15)
      throw InputError(where, std::string(what) + " is not a count");
    return static_cast<long>(x);
  };
  const long leaves = whole(0, "leaf count"), first = whole(1, "first leaf"),
             end = whole(2, "end leaf"), count = whole(3, "node count");
  std::size_t at = 4;
  std::vector<TreeNode> nodes;
  for (long k = 0; k < count; ++k) {
    TreeNode node;
    node.level = static_cast<int>(whole(at, "node level"));
    node.index = whole(at + 1, "node index");
    const std::size_t len = static_cast<std::size_t>(whole(at + 2, "node length"));
    at += 3;
    if (at + len > v.size()) throw InputError(where, "ends inside node " + std::to_string(k));
    node.acc = MomentAccumulator::fromVector(std::vector<double>(
        v.begin() + static_cast<long>(at), v.begin() + static_cast<long>(at + len)));
    at += len;
    nodes.push_back(std::move(node));
  }
  if (at != v.size())
    throw InputError(where, "has " + std::to_string(v.size() - at) + " values after its last node");
  MomentTree t = fromNodes(leaves, first, std::move(nodes), where);
  if (t.end_ != end)
    throw InputError(
        where, "its nodes end at leaf " + std::to_string(t.end_) + ", not " + std::to_string(end));
  return t;
}

}  // namespace dtwin::classify
