#pragma once
// `twin bench --accumulation`: what a synthesis costs per draw and per accumulation step, and
// the wall time it would take on K single-core MPI ranks (the scheme of classification/
// synthesis.hpp, "Accumulation": leaves built by each rank, combined along a binomial tree of
// ranks), modelled from those measured costs.
#include <string>
#include <vector>

#include "io/study.hpp"

namespace dtwin {

/// The measured costs the model is made of (seconds, one core).
struct AccumulationCosts {
  long draws = 0, roads = 0, block = 0, leaf_blocks = 0, leaves = 0;
  int p = 0;          ///< samples per vector
  double draw_s = 0;  ///< one draw: its R runs (branched as the synthesis runs them)
  double add_per_vector_s =
      0;               ///< MomentAccumulator::addBlock of a block's B·R vectors, per vector
  double merge_s = 0;  ///< one merge of two nodes
  double pack_s = 0, unpack_s = 0;  ///< MomentTree toVector / fromVector of a one-node range
  double save_s = 0;                ///< MomentAccumulator::save of a node (a checkpoint's file)
  double node_bytes = 0;
  double link_bytes_per_s = 0;  ///< assumed bandwidth between ranks (not measured here)
};

struct ScalingRow {
  int ranks = 1;
  long rounds = 0;
  double wall_s = 0, speedup = 1, efficiency = 1;
  double combine_s = 0;  ///< of wall_s: the binomial combination of the parts and the root's share
  double ordered_wall_s = 0;  ///< the earlier scheme: every rank adds every vector between rounds
};

/// The wall time of the synthesis of one assembly on `ranks` single-core ranks (1: one process
/// with one thread), round by round as classification/synthesis_reduction.cpp schedules it.
ScalingRow modelSynthesisWall(const AccumulationCosts& c, int ranks);

struct AccumulationBench {
  std::string assembly, label;
  AccumulationCosts costs;
  std::vector<ScalingRow> rows;
};

/// Measures the costs for `assembly` at its default run values on the study's field scenario
/// (`draws_timed` draws, median; the study's sizes and the synthesis defaults block 16, two blocks
/// per leaf) and models ranks 1, 2, 8, 64, 256 with `link_gb_per_s` between ranks.
AccumulationBench benchAccumulation(const Study& study, const AssemblySpec& assembly,
                                    int draws_timed, double link_gb_per_s);

}  // namespace dtwin
