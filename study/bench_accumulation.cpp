#include "study/bench_accumulation.hpp"

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <random>

#include "classification/moment_tree.hpp"
#include "classification/synthesis.hpp"
#include "common/errors.hpp"
#include "twin/simulator.hpp"

namespace dtwin {

using classify::MomentAccumulator;
using classify::MomentTree;

namespace {
using AccClock = std::chrono::steady_clock;
double accSince(AccClock::time_point t0) {
  return std::chrono::duration<double>(AccClock::now() - t0).count();
}
double accMedian(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}
long accCeilDiv(long a, long b) { return (a + b - 1) / b; }
}  // namespace

ScalingRow modelSynthesisWall(const AccumulationCosts& c, int ranks) {
  DTWIN_CHECK(ranks >= 1 && c.leaves >= 1, "modelSynthesisWall: ranks and leaves >= 1");
  const long leaf_draws = c.leaf_blocks * c.block, n = c.leaves;
  auto leafTime = [&](long leaf) {
    const double d =
        static_cast<double>(std::max(0L, std::min(leaf_draws, c.draws - leaf * leaf_draws)));
    return d * c.draw_s + d * static_cast<double>(c.roads) * c.add_per_vector_s;
  };
  const double node_s = c.pack_s + c.node_bytes / c.link_bytes_per_s + c.unpack_s;
  ScalingRow row;
  row.ranks = ranks;
  if (ranks == 1) {
    for (long l = 0; l < n; ++l) row.wall_s += leafTime(l);
    row.wall_s += static_cast<double>(n - 1) * c.merge_s;
    row.rounds = 1;
  } else {
    constexpr long kRoundLeaves = 8;  // as reduceOnRanks
    long L0 = 0;
    double since_ckpt = 0;
    while (L0 < n) {
      const long left = n - L0, rounds = accCeilDiv(left, kRoundLeaves * ranks),
                 q = accCeilDiv(left, ranks * rounds);
      const long L1 = std::min(n, L0 + q * ranks);
      auto lo = [&](long r) { return std::min(L1, L0 + q * r); };
      auto hi = [&](long r) { return std::min(L1, lo(r) + q); };
      double compute = 0;
      for (long r = 0; r < ranks; ++r) {
        double t = 0;
        for (long l = lo(r); l < hi(r); ++l) t += leafTime(l);
        t += static_cast<double>((hi(r) - lo(r)) - MomentTree::nodeCount(n, lo(r), hi(r))) *
             c.merge_s;
        compute = std::max(compute, t);
      }
      // The binomial combination: at step s rank r receives the part of ranks r+s .. r+2s−1.
      double combine = 0;
      for (long s = 1; s < ranks; s *= 2) {
        double step = 0;
        for (long r = 0; r + s < ranks; r += 2 * s) {
          const long from = lo(r + s), to = hi(std::min<long>(ranks - 1, r + 2 * s - 1));
          const long m = MomentTree::nodeCount(n, from, to);
          const long before = MomentTree::nodeCount(n, lo(r), from),
                     after = MomentTree::nodeCount(n, lo(r), to);
          step = std::max(step, static_cast<double>(m) * node_s +
                                    static_cast<double>(before + m - after) * c.merge_s);
        }
        combine += step;
      }
      // The root appends the round to its list, and saves the new nodes when a checkpoint is due
      // (30 s).
      const long before = MomentTree::nodeCount(n, 0, L0), part = MomentTree::nodeCount(n, L0, L1),
                 after = MomentTree::nodeCount(n, 0, L1);
      combine += static_cast<double>(before + part - after) * c.merge_s;
      since_ckpt += compute + combine;
      if (since_ckpt >= 30.0 && L1 < n) {
        combine += c.save_s;  // about one new node per checkpoint
        since_ckpt = 0;
      }
      row.wall_s += compute + combine;
      row.combine_s += combine;
      ++row.rounds;
      L0 = L1;
    }
    const double bcast = std::ceil(std::log2(static_cast<double>(ranks))) *
                         node_s;  // the root's moments to every rank
    row.wall_s += bcast;
    row.combine_s += bcast;
  }
  // The earlier scheme: rounds of about 8 draws per rank, whole blocks, spread round-robin;
  // between rounds every rank adds every vector of the round in block order.
  {
    const long blocks = accCeilDiv(c.draws, c.block);
    const long per_round = std::max(1L, (8L * ranks) / c.block);
    double t = 0;
    for (long b0 = 0; b0 < blocks; b0 += per_round) {
      const long d = std::min(c.draws, (b0 + per_round) * c.block) - b0 * c.block;
      t += static_cast<double>(accCeilDiv(d, ranks)) * c.draw_s +
           static_cast<double>(d * c.roads) * c.add_per_vector_s;
    }
    row.ordered_wall_s = t;
  }
  return row;
}

AccumulationBench benchAccumulation(const Study& study, const AssemblySpec& assembly,
                                    int draws_timed, double link_gb_per_s) {
  if (draws_timed < 1) throw InputError("twin bench --accumulation", "--runs must be >= 1");
  if (!(link_gb_per_s > 0))
    throw InputError("twin bench --accumulation", "--link-gb-per-s must be > 0");
  const ScenarioSpec& sc = study.scenario("field");
  AccumulationBench b;
  b.assembly = assembly.id;
  b.label = assembly.label();
  AccumulationCosts& c = b.costs;
  c.draws = study.sizes.at("posterior_draws");
  c.roads = study.sizes.at("roads_per_draw");
  c.block = classify::SynthesisOptions{}.block;
  c.leaf_blocks = classify::SynthesisOptions{}.leaf_blocks;
  c.leaves = accCeilDiv(accCeilDiv(c.draws, c.block), c.leaf_blocks);
  c.p = static_cast<int>(std::lround(5.0 * study.simulation.output_rate_hz)) +
        1;  // the default 10–15 s window
  c.link_bytes_per_s = link_gb_per_s * 1e9;

  // One draw: R library roads from one smooth start, at the assembly's default values.
  const auto model = study.makeModel(assembly);
  Simulator sim(model, study.simulation);
  const auto values = model->defaultRunValues();
  const bool branched = sim.branchTime(sc) > 0 && sim.branchTime(sc) < sc.duration_s;
  std::vector<double> draw_walls;
  for (int j = 0; j <= draws_timed; ++j) {  // draw 0: warm-up
    std::vector<std::shared_ptr<const Road>> roads;
    std::vector<const Road*> ptrs;
    for (long r = 0; r < c.roads; ++r) {
      roads.push_back(
          makeRoad(sc, model->vehicle(),
                   classify::librarySeed(study.seed, static_cast<std::uint64_t>(j * c.roads + r))));
      ptrs.push_back(roads.back().get());
    }
    const auto t0 = AccClock::now();
    if (branched) {
      for (const auto& run : sim.runBranched(values, ptrs, sc))
        if (!run.stats.ok)
          throw std::runtime_error("twin bench --accumulation: a run failed: " + run.stats.message);
    } else {
      for (const Road* road : ptrs)
        if (!sim.run(values, *road, sc).stats.ok)
          throw std::runtime_error("twin bench --accumulation: a run failed");
    }
    if (j > 0) draw_walls.push_back(accSince(t0));
  }
  c.draw_s = accMedian(draw_walls);

  // The accumulation's steps at p samples, on random vectors.
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0.0, 1.0);
  classify::MomentOptions mo;
  mo.track_fourth_moment = true;
  const long cols = c.block * c.roads;
  Eigen::MatrixXd X(c.p, cols);
  for (Eigen::Index k = 0; k < X.size(); ++k) X.data()[k] = 1000.0 + 50.0 * g(rng);
  std::vector<double> add_s, merge_s, pack_s, unpack_s, save_s;
  MomentAccumulator a(c.p, mo), other(c.p, mo);
  other.addBlock(X);
  const std::string tmp = (std::filesystem::temp_directory_path() /
                           ("dtwin_bench_node_" + std::to_string(::getpid()) + ".bin"))
                              .string();
  for (int k = 0; k < 3; ++k) {
    auto t0 = AccClock::now();
    a.addBlock(X);
    add_s.push_back(accSince(t0) / static_cast<double>(cols));
    MomentAccumulator m = a;
    t0 = AccClock::now();
    m.merge(other);
    merge_s.push_back(accSince(t0));
    MomentTree t(1);
    t.pushLeaf(std::move(m));
    t0 = AccClock::now();
    const std::vector<double> v = t.toVector();
    pack_s.push_back(accSince(t0));
    c.node_bytes = 8.0 * static_cast<double>(v.size());
    t0 = AccClock::now();
    const MomentTree back = MomentTree::fromVector(v);
    unpack_s.push_back(accSince(t0));
    t0 = AccClock::now();
    back.root().save(tmp);
    save_s.push_back(accSince(t0));
  }
  std::error_code ec;
  std::filesystem::remove(tmp, ec);
  c.add_per_vector_s = accMedian(add_s);
  c.merge_s = accMedian(merge_s);
  c.pack_s = accMedian(pack_s);
  c.unpack_s = accMedian(unpack_s);
  c.save_s = accMedian(save_s);
  for (int k : {1, 2, 8, 64, 256}) {
    ScalingRow r = modelSynthesisWall(c, k);
    b.rows.push_back(r);
  }
  const double t1 = b.rows.front().wall_s;
  for (auto& r : b.rows) {
    r.speedup = t1 / r.wall_s;
    r.efficiency = r.speedup / r.ranks;
  }
  return b;
}

}  // namespace dtwin
