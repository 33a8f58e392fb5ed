// The reduction of a synthesis's draws, in block order, on the threads of one process
// (reduceOnThreads) or over MPI ranks (reduceOnRanks), with the packing of what they send.
#include "classification/synthesis_internal.hpp"

#include <algorithm>
#include <map>
#include <mutex>

#include "common/distributed.hpp"
#include "common/parallel.hpp"

namespace dtwin::classify {
namespace {

/// A draw's output as doubles (what distributedMap carries between MPI ranks).
std::vector<double> packDraw(const DrawOutput& d) {
  Packer pk;
  pk.put(static_cast<double>(d.vectors.size()));
  for (const auto& v : d.vectors) pk.put(v);
  pk.put(static_cast<double>(d.failures.size()));
  for (const auto& f : d.failures)
    pk.put(static_cast<double>(f.draw))
        .put(static_cast<double>(f.road))
        .put(static_cast<double>(f.library_index))
        .put(static_cast<double>(f.road_seed))
        .put(f.message);
  pk.put(d.cost).put(d.run_wall);
  return pk.take();
}
DrawOutput unpackDraw(const std::vector<double>& v) {
  Unpacker u(v);
  DrawOutput d;
  d.vectors.resize(static_cast<std::size_t>(u.integer()));
  for (auto& x : d.vectors) x = u.vec();
  d.failures.resize(static_cast<std::size_t>(u.integer()));
  for (auto& f : d.failures) {
    f.draw = static_cast<long>(u.integer());
    f.road = static_cast<long>(u.integer());
    f.library_index = static_cast<long>(u.integer());
    f.road_seed = static_cast<std::uint64_t>(u.num());  // < 2^53: exact
    f.message = u.str();
  }
  d.cost = u.vec();
  d.run_wall = u.vec();
  return d;
}

}  // namespace

/// Draws [first_draw, end_draw) on this process's threads, each finished block added to `sink`
/// as soon as its predecessors are (one reducer at a time; a finished block whose predecessor is
/// still running waits in `pending`). `after_block` runs after each block is added (under the
/// reducer's lock); `tick` after each draw.
void reduceOnThreads(const SynthesisPlan& plan, int threads, long first_draw, long end_draw,
                     const DrawFn& draw, LeafSink& sink, const std::function<void()>& after_block,
                     const std::function<void()>& tick) {
  std::mutex state_m, reduce_m, progress_m;
  std::map<long, PendingBlock> pending;  // guarded by state_m
  auto reduce = [&]() {
    while (true) {
      std::unique_lock<std::mutex> rl(reduce_m, std::try_to_lock);
      if (!rl.owns_lock()) return;
      while (true) {
        PendingBlock blk;
        {
          std::lock_guard<std::mutex> sl(state_m);
          auto it = pending.find(sink.next_block);
          if (it == pending.end() || it->second.remaining > 0) break;
          blk = std::move(it->second);
          pending.erase(it);
        }
        sink.add(blk);
        if (after_block) after_block();
      }
      rl.unlock();
      std::lock_guard<std::mutex> sl(state_m);  // a block finished while we were releasing?
      auto it = pending.find(sink.next_block);
      if (it == pending.end() || it->second.remaining > 0) return;
    }
  };
  parallelFor(static_cast<std::size_t>(end_draw - first_draw), threads,
              [&](std::size_t task, int w) {
                const long j = first_draw + static_cast<long>(task);
                DrawOutput out = draw(j, w);
                {
                  std::lock_guard<std::mutex> sl(state_m);
                  const long b = j / plan.B;
                  auto& blk = pending[b];
                  if (blk.draws.empty()) {
                    blk.draws.resize(static_cast<std::size_t>(plan.blockSize(b)));
                    blk.remaining = plan.blockSize(b);
                  }
                  blk.draws[static_cast<std::size_t>(j - b * plan.B)] = std::move(out);
                  --blk.remaining;
                }
                reduce();
                if (tick) {
                  std::lock_guard<std::mutex> pl(progress_m);
                  tick();
                }
              });
  reduce();
}

namespace {

/// Failures and run costs of a rank's draws, as doubles (what distributedMap carries).
std::vector<double> packSink(const LeafSink& s) {
  DrawOutput d;
  d.failures = s.failures;
  d.cost = s.costs;
  d.run_wall = s.run_walls;
  return packDraw(d);
}

}  // namespace

/// Several MPI ranks: rounds of whole leaves. Rank r of K takes the round's leaves
/// [L0 + r·q, L0 + (r + 1)·q), simulates their draws on its threads and builds its part of the
/// tree; the parts are combined along a binomial tree of ranks (rank r + 2^s sends its nodes to
/// rank r, s = 0, 1, ...: log2 K steps, each a transfer and the sibling merges it completes) and
/// the root appends the round's nodes to its tree. Every node is the tree's own, so the moments
/// are those of one process bit for bit. Rounds (at most kRoundLeaves leaves per rank, so that a
/// checkpoint comes every few minutes) are balanced: q = ⌈leaves left / (K · rounds left)⌉.
void reduceOnRanks(const Distributed& processes, const SynthesisPlan& plan, int threads, int ranks,
                   const DrawFn& draw, Reduction& red, Clock::time_point t_run,
                   const ProgressFn& progress) {
  constexpr long kRoundLeaves = 8;
  const Distributed& D = processes;
  const long leaf_draws = plan.LB * plan.B;
  const long n_leaves = plan.leaves();
  while (red.sink.next_block < plan.blocks()) {
    const long L0 = red.sink.next_block / plan.LB, left = n_leaves - L0;
    const long rounds = (left + kRoundLeaves * ranks - 1) / (kRoundLeaves * ranks);
    const long q = (left + ranks * rounds - 1) / (ranks * rounds);
    const long L1 = std::min(n_leaves, L0 + q * ranks);
    const long lo = std::min(L1, L0 + q * D.rank()), hi = std::min(L1, lo + q);
    MomentTree part(n_leaves, lo);
    std::size_t done = static_cast<std::size_t>(std::min(plan.M, L0 * leaf_draws));
    const auto packed = distributedMap(
        &D, static_cast<std::size_t>(ranks), threads,
        [&](std::size_t r, int) -> std::vector<double> {
          DTWIN_CHECK(static_cast<int>(r) == D.rank(), "a rank's leaves computed on another rank");
          LeafSink sink(plan, red.sink.moments(), part);
          const long j0 = std::min(plan.M, lo * leaf_draws), j1 = std::min(plan.M, hi * leaf_draws);
          reduceOnThreads(plan, threads, j0, j1, draw, sink, nullptr, [&] {
            if (progress)
              progress(std::min<std::size_t>(static_cast<std::size_t>(plan.M),
                                             done += static_cast<std::size_t>(ranks)),
                       static_cast<std::size_t>(plan.M));
          });
          DTWIN_CHECK(sink.atLeafBoundary(), "a rank's draws end inside a leaf");
          return packSink(sink);
        });
    // The parts, combined along the binomial tree of ranks: after step s, rank r (r divisible by
    // 2^(s+1)) holds the leaves of ranks r .. r + 2^(s+1) − 1.
    const auto t_combine = Clock::now();
    for (int s = 1; s < ranks; s *= 2) {
      if (D.rank() % (2 * s) == s) {
        D.sendDoubles(D.rank() - s, part.toVector());
        break;
      }
      if (D.rank() % (2 * s) == 0 && D.rank() + s < ranks)
        part.append(MomentTree::fromVector(D.receiveDoubles(D.rank() + s)));
    }
    if (D.isRoot()) {
      DTWIN_CHECK(part.first() == L0 && part.end() == L1,
                  "the ranks' parts do not cover the round");
      red.tree.append(std::move(part));
    }
    red.combine_s += secondsSince(t_combine);
    for (const auto& p : packed) red.sink.addRecords(unpackDraw(p));
    red.sink.next_block = std::min(plan.blocks(), L1 * plan.LB);
    if (!D.isRoot()) red.tree = MomentTree(n_leaves, L1);  // the root holds [0, L1)
    onRoot(&D, [&]() -> std::string {
      red.checkpointIfDue(t_run);
      return std::string();
    });
  }
}

}  // namespace dtwin::classify
