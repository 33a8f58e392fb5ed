#pragma once
// Synthetic field data of one calibrated assembly (docs/method.md §5, first bullet), accumulated as
// streaming moments: the input of the classifier (classify_field.hpp).
//
// \par What is simulated
// M posterior draws (default: the study's sizes.posterior_draws), each on R roads
// (sizes.roads_per_draw) from a road library of L class-D roads (sizes.road_library):
//  * draw j (0 .. M−1) uses row ⌊u·S⌋ of the posterior sample (S rows; u the first uniform of
//    RandomStream(seed, kSynthDrawStream, j)): θ_j and τ_j;
//  * its R library indices come from RandomStream(seed, kSynthRoadStream, j): uniform integers
//    ⌊u·L⌋, redrawn while one repeats (distinct within a draw), in the order drawn;
//  * library road i is the field scenario's road with seed librarySeed(seed, i) =
//    RandomStream(seed, kRoadLibraryStream, i).bits() >> 11 — a different stream from `twin
//    generate field` (kFieldRoadStream), so the field records are not in the library;
//  * the R runs of a draw share the smooth start (Simulator::runBranched; unbranched runs when
//    the scenario has no smooth start or SynthesisOptions::branch is false);
//  * vector (j, r) is the window [t_begin, t_end] of `channel` on the output grid (default the
//    10–15 s window of hub_force_fl_N at 1 kHz: p = 5001 values) plus noise N(0, 1/τ_j) per
//    value, drawn from RandomStream(seed, kSynthNoiseStream, j·R + r) in time order (channels in
//    N only, as `twin generate field` does; other channels stay noise-free and the JSON says so).
//
// \par Accumulation (bitwise reproducible for any thread or process count)
// Draws are grouped in FIXED blocks of B draws (block b = draws bB .. bB+B−1) and blocks in FIXED
// leaves of `leaf_blocks` blocks. The vectors of a block are added with one
// MomentAccumulator::addBlock, columns in (j, r) order, blocks in block order into their leaf's
// accumulator (an ordered reduction: a finished block waits for its predecessors; draws are
// simulated in parallel, one Simulator per worker), and the leaves are merged in a fixed binary
// tree (classification/moment_tree.hpp): the same nodes whoever computes them. Under MPI each rank
// builds the leaves of its share of a round and the parts meet along a binomial tree of ranks, so
// no rank adds every vector. A failed simulation (diverged, parameters a law rejects, non-finite
// output) is counted and listed; its vector is left out of its block (never averaged in), which
// depends only on (j, r), never on timing.
//
// \par Files in out_dir
//   moments.bin        the accumulator (MomentAccumulator::save: tag DTWMOM01, then
//                      MomentAccumulator::toVector as little-endian doubles: header, mean, packed
//                      upper triangle of the scatter matrix M2, optionally T and Q)
//   synthesis.json     sizes, seeds, streams, failures, cost, wall time, window, channel,
//                      fingerprint, program information (SynthesisResult::info)
//   checkpoint.json + node_<level>_<index>.bin   while running (removed at the end)
// Resume: every ~checkpoint_interval_s (default 30 s), at a leaf boundary, the tree's current
// nodes are saved (atomic; at most about 2 log2(leaves) of them, each written once: a node never
// changes until it is merged into its parent, at p = 5001 each is 100 MB) with the next leaf and
// the fingerprint of everything that changes the numbers. A rerun of the same synthesis continues
// from the checkpoint and ends with a bit-identical moments.bin; a rerun after completion reuses
// the finished files; a rerun with different inputs into the same folder is refused (InputError).
// Memory: one accumulator per node held (8 p² bytes each: 200 MB at p = 5001).
//
// \par Cost
// Each run's wall time per simulated second (runBranched splits the shared part's time evenly
// among the roads); SynthesisResult::cost_s_per_s is the median over the successful runs (over
// all invocations when resumed). Wall times depend on the machine and its load; they are
// recorded, never part of the fingerprint.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/folder.hpp"
#include "classification/moments.hpp"
#include "common/progress.hpp"
#include "io/study.hpp"

namespace dtwin::classify {

using calib::PosteriorSample;  // calibration/folder.hpp

/// Stream constants of RandomStream(seed, stream, index) (ASCII tags; recorded in synthesis.json).
inline constexpr std::uint64_t kSynthDrawStream =
    0x53594E5444524157ULL;  // "SYNTDRAW"; index: draw j
inline constexpr std::uint64_t kSynthRoadStream =
    0x53594E54524F4144ULL;  // "SYNTROAD"; index: draw j
inline constexpr std::uint64_t kSynthNoiseStream =
    0x53594E544E4F4953ULL;  // "SYNTNOIS"; index: j * R + r
inline constexpr std::uint64_t kRoadLibraryStream =
    0x524F41444C494252ULL;  // "ROADLIBR"; index: library road i

/// Seed of library road i: RandomStream(seed, kRoadLibraryStream, i).bits() >> 11 (53 bits, as
/// fieldRoadSeed). `twin simulate --scenario field --seed <it>` reproduces the road.
std::uint64_t librarySeed(std::uint64_t seed, std::uint64_t index);

struct SynthesisOptions {
  long draws = 0;           ///< M; <= 0: the study's sizes.posterior_draws
  long roads_per_draw = 0;  ///< R; <= 0: sizes.roads_per_draw
  long road_library = 0;    ///< L (>= R); <= 0: sizes.road_library
  long block = 16;          ///< B draws per block (changes the numbers at the rounding level)
  long leaf_blocks =
      2;  ///< blocks per leaf of the accumulation tree (changes the numbers at the rounding level)
  int threads = 0;  ///< <= 0: all cores (never changes the numbers)
  const Distributed* processes =
      nullptr;  ///< the process context (common/distributed.hpp); nullptr: this process alone
  std::optional<std::uint64_t> seed;  ///< default: the study's seed
  std::string scenario = "field";
  std::string channel = "hub_force_fl_N";
  double t_begin_s = 10.0, t_end_s = 15.0;  ///< window kept (inclusive), on the output grid
  /// Accumulate the third/fourth moments needed by Ledoit–Wolf (classify's default when
  /// M·R < 2p); costs ~10 % of the accumulation time and 8 (p + 1) bytes.
  bool track_fourth_moment = true;
  bool branch = true;                   ///< share the smooth start among the roads of a draw
  double checkpoint_interval_s = 30.0;  ///< at most this long between checkpoints (0: every block)
  std::string command;                  ///< recorded in synthesis.json
  /// InputError whose where() is "synthesis.<field>" (common/validate.hpp): block >= 1, a finite
  /// window with t_begin_s <= t_end_s, checkpoint_interval_s >= 0, a known channel. The sizes
  /// (draws, roads_per_draw, road_library: <= 0 for the study's) are checked once resolved.
  void validate() const;
};

struct SynthesisFailure {
  long draw = 0;                ///< j
  long road = 0;                ///< r
  long library_index = 0;       ///< i
  std::uint64_t road_seed = 0;  ///< librarySeed(seed, i)
  std::string message;
};

struct SynthesisResult {
  std::string assembly;
  std::string fingerprint;
  MomentAccumulator moments{1};
  std::vector<double> times_s;  ///< the window's times (p of them)
  long draws = 0, roads_per_draw = 0, road_library = 0, block = 0;
  long simulations = 0;  ///< M·R
  long failures = 0;
  std::vector<SynthesisFailure> failure_list;  ///< in (j, r) order
  double cost_s_per_s = 0.0;  ///< median wall seconds per simulated second of the runs
  double median_run_wall_s = 0.0;
  double wall_s = 0.0;      ///< this invocation
  long resumed_blocks = 0;  ///< blocks taken from a checkpoint
  bool reused = false;      ///< the synthesis had finished before: files reused
  nlohmann::json info;      ///< the content of synthesis.json
};

/// Synthesizes `assembly` from `posterior` (whose θ names must be the study's calibrated
/// parameters, in order) and writes out_dir/moments.bin and out_dir/synthesis.json (see the file
/// header). `progress(done, total)` counts draws (resumed ones included); it is called one call
/// at a time, possibly from worker threads; an exception it throws stops the synthesis (the last
/// checkpoint stays valid). InputError for bad options or inputs.
SynthesisResult synthesizeAssembly(const Study& study, const AssemblySpec& assembly,
                                   const PosteriorSample& posterior,
                                   const SynthesisOptions& options, const std::string& out_dir,
                                   const ProgressFn& progress = {});

}  // namespace dtwin::classify
