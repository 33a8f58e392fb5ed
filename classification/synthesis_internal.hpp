// Private to classification/ (not installed): what synthesis.cpp and synthesis_reduction.cpp share,
// the plan of a synthesis, a draw's output, the folder's files, and the reduction of the draws into
// the moment tree with its checkpoint (LeafSink, Reduction; reduceOnThreads, reduceOnRanks).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "classification/moment_tree.hpp"
#include "classification/moments.hpp"
#include "classification/synthesis.hpp"
#include "common/checksum.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/json.hpp"
#include "twin/simulator.hpp"

namespace fs = std::filesystem;

namespace dtwin::classify {

// ------------------------------------------------------------------ shared helpers (synthesis.cpp)
nlohmann::json failureJson(const SynthesisFailure& f);
SynthesisFailure failureFrom(const nlohmann::json& j);

/// What one draw produced: R vectors (empty where the run failed), failures, run costs.
struct DrawOutput {
  std::vector<std::vector<double>> vectors;
  std::vector<SynthesisFailure> failures;
  std::vector<double> cost;      ///< wall s per simulated s, successful runs
  std::vector<double> run_wall;  ///< wall s, successful runs
};

struct PendingBlock {
  std::vector<DrawOutput> draws;
  long remaining = 0;
};

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0);

/// Everything a synthesis fixes before it simulates (synthesis.hpp, "What is simulated").
struct SynthesisPlan {
  long M = 0, R = 0, L = 0, B = 0;  ///< draws, roads per draw, library roads, draws per block
  std::uint64_t seed = 0;
  std::vector<std::string>
      names;  ///< the study's calibrated parameters (= the posterior's columns)
  std::shared_ptr<const Model> model;
  std::vector<int> slots;             ///< run-value slot of each calibrated parameter
  std::vector<double> base;           ///< the model's default run values
  const ScenarioSpec* sc = nullptr;   ///< the field scenario (random road)
  std::string unit;                   ///< of the channel
  bool noisy = false;                 ///< noise N(0, 1/τ) is added (channels in N)
  double rate = 0.0;                  ///< output grid [Hz]
  std::size_t kb = 0, ke = 0, p = 0;  ///< the window: first and last grid index, samples
  std::vector<double> times;          ///< the window's times
  bool branched = false;              ///< the roads of a draw share the smooth start
  double t_branch = -1.0;
  long LB = 1;  ///< blocks per leaf of the accumulation tree
  long blocks() const { return (M + B - 1) / B; }
  long leaves() const { return (blocks() + LB - 1) / LB; }
  long blockSize(long b) const { return std::min(B, M - b * B); }
};

/// The files of a synthesis folder (synthesis.hpp, "Files in out_dir").
struct SynthesisFiles {
  fs::path dir, moments, info, checkpoint;
  explicit SynthesisFiles(const std::string& out_dir)
      : dir(out_dir),
        moments(dir / "moments.bin"),
        info(dir / "synthesis.json"),
        checkpoint(dir / "checkpoint.json") {}
};

std::string rootRead(const Distributed* processes, const fs::path& path);
/// rootRead of checkpoint.json, checked on the root first: one that is not JSON, fails its
/// checksum or names a node file whose bytes differ from the checksum it recorded was damaged on
/// disk; it is set aside (checkpoint.json.corrupt, one note on stderr) and "" returned, so the
/// synthesis starts again instead of trusting it.
std::string rootReadCheckpoint(const Distributed* processes, const SynthesisFiles& files);
nlohmann::json parseRootJson(const std::string& text);
[[noreturn]] void refuseForeign(const fs::path& path);

// ------------------------------------------------------------------ the reduction
// (synthesis_reduction.cpp)
/// Adds a synthesis's blocks, in block order, to the leaves of a MomentTree: a leaf is
/// `leaf_blocks` blocks added with addBlock to an empty accumulator, then pushed into the tree
/// (synthesis.hpp, "Accumulation"). Also keeps the failures and run costs in draw order. Not
/// thread-safe: the caller adds one block at a time.
class LeafSink {
 public:
  LeafSink(const SynthesisPlan& plan, const MomentOptions& mo, MomentTree& tree)
      : next_block(tree.end() * plan.LB),
        plan_(plan),
        mo_(mo),
        tree_(tree),
        leaf_(static_cast<int>(plan.p), mo) {}

  /// Adds block next_block (vectors in (draw, road) order; failed runs left out) and moves on.
  void add(PendingBlock& blk) {
    long cols = 0;
    for (const auto& d : blk.draws)
      for (const auto& v : d.vectors) cols += v.empty() ? 0 : 1;
    if (cols > 0) {
      Eigen::MatrixXd X(static_cast<Eigen::Index>(plan_.p), cols);
      Eigen::Index c = 0;
      for (const auto& d : blk.draws)
        for (const auto& v : d.vectors)
          if (!v.empty())
            X.col(c++) =
                Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(plan_.p));
      leaf_.addBlock(X);
    }
    for (const auto& d : blk.draws) addRecords(d);
    ++next_block;
    if (atLeafBoundary()) {
      tree_.pushLeaf(std::move(leaf_));
      leaf_ = MomentAccumulator(static_cast<int>(plan_.p), mo_);
    }
  }
  /// Appends a draw's (or a rank's) failures and run costs, in draw order.
  void addRecords(const DrawOutput& d) {
    failures.insert(failures.end(), d.failures.begin(), d.failures.end());
    costs.insert(costs.end(), d.cost.begin(), d.cost.end());
    run_walls.insert(run_walls.end(), d.run_wall.begin(), d.run_wall.end());
  }
  const MomentOptions& moments() const { return mo_; }
  /// True when every block added so far is in a leaf of the tree.
  bool atLeafBoundary() const { return next_block % plan_.LB == 0 || next_block == plan_.blocks(); }

  long next_block;
  std::vector<SynthesisFailure> failures;
  std::vector<double> costs, run_walls;

 private:
  const SynthesisPlan& plan_;
  MomentOptions mo_;
  MomentTree& tree_;
  MomentAccumulator leaf_;
};

/// The reduction of a whole synthesis: the tree of its leaves, what is added next, the failures
/// and run costs so far, and the checkpoint that lets a rerun continue (synthesis.hpp,
/// "Accumulation" and "Resume"). Under MPI only the root holds the tree's nodes; every rank
/// keeps next_block, the failures and the costs.
class Reduction {
 public:
  Reduction(const SynthesisPlan& plan, const SynthesisOptions& opt, const SynthesisFiles& files,
            std::string assembly, std::string fingerprint, bool root)
      : tree(plan.leaves()),
        sink(plan, momentOptions(opt), tree),
        plan_(plan),
        opt_(opt),
        files_(files),
        assembly_(std::move(assembly)),
        fingerprint_(std::move(fingerprint)),
        root_(root) {}

  /// Continues from checkpoint.json when the folder has one (InputError when it is another
  /// synthesis's or does not match its node files).
  void resume() {
    const std::string ckpt_text = rootReadCheckpoint(opt_.processes, files_);
    if (ckpt_text.empty()) return;
    const nlohmann::json j = parseRootJson(ckpt_text);
    if (!j.is_object() || j.value("fingerprint", "") != fingerprint_ || !j.contains("nodes"))
      refuseForeign(files_.checkpoint);
    const long next_leaf = j.at("next_leaf").get<long>();
    if (root_) {
      std::vector<TreeNode> nodes;
      for (const auto& n : j.at("nodes")) {
        TreeNode node;
        node.level = n.at("level").get<int>();
        node.index = n.at("index").get<long>();
        node.acc = MomentAccumulator::load((files_.dir / n.at("file").get<std::string>()).string());
        if (node.acc.dimension() != static_cast<int>(plan_.p))
          throw InputError(files_.checkpoint.string(), "does not match " +
                                                           n.at("file").get<std::string>() +
                                                           "; delete the folder to start over");
        nodes.push_back(std::move(node));
      }
      tree = MomentTree::fromNodes(plan_.leaves(), 0, std::move(nodes), files_.checkpoint.string());
      if (tree.end() != next_leaf)
        throw InputError(files_.checkpoint.string(),
                         "its nodes end at leaf " + std::to_string(tree.end()) +
                             ", not at next_leaf " + std::to_string(next_leaf) +
                             "; delete the folder to start over");
      for (const auto& n : j.at("nodes")) {
        node_files_.push_back(n.at("file").get<std::string>());
        node_sums_.push_back(n.value("checksum", std::string()));
      }
    } else {
      tree = MomentTree(plan_.leaves(), next_leaf);  // the root holds [0, next_leaf)
    }
    sink.next_block = std::min(plan_.blocks(), next_leaf * plan_.LB);
    for (const auto& f : j.at("failure_list")) sink.failures.push_back(failureFrom(f));
    sink.costs = j.at("cost_samples").get<std::vector<double>>();
    sink.run_walls = j.at("run_wall_samples").get<std::vector<double>>();
    previous_wall = j.at("wall_s").get<double>();
  }

  /// Starts the checkpoint clock (when the simulations start).
  void startClock() { last_ckpt_ = Clock::now(); }

  /// Writes a checkpoint when leaves remain, the blocks added so far fill whole leaves and
  /// checkpoint_interval_s has passed since the last one; `t_run` is when this invocation
  /// started simulating. Root only (elsewhere a no-op).
  void checkpointIfDue(Clock::time_point t_run) {
    const auto now = Clock::now();
    if (root_ && sink.next_block < plan_.blocks() && sink.atLeafBoundary() &&
        std::chrono::duration<double>(now - last_ckpt_).count() >= opt_.checkpoint_interval_s) {
      writeCheckpoint(previous_wall + std::chrono::duration<double>(now - t_run).count());
      last_ckpt_ = Clock::now();
    }
  }

  /// The finished synthesis replaces the checkpoint: moments.bin and synthesis.json (root only;
  /// its error reaches every rank).
  void writeResults(const MomentAccumulator& acc, const nlohmann::json& info) {
    onRoot(opt_.processes, [&]() -> std::string {
      acc.save(files_.moments.string());
      writeFileAtomic(files_.info.string(), info.dump(2) + "\n");
      // The checkpoint is no longer needed.
      std::error_code ec;
      fs::remove(files_.checkpoint, ec);
      for (const auto& f : node_files_) fs::remove(files_.dir / f, ec);
      return std::string();
    });
  }

  MomentTree tree;
  LeafSink sink;
  double previous_wall = 0.0;  ///< wall time of earlier (interrupted) invocations
  double combine_s = 0.0;      ///< this rank's time in the combination of the ranks' parts (MPI)

 private:
  static MomentOptions momentOptions(const SynthesisOptions& opt) {
    MomentOptions mo;
    mo.track_fourth_moment = opt.track_fourth_moment;
    return mo;
  }

  /// node_<level>_<index>.bin for each node not yet on disk (a node never changes: it is only
  /// merged into its parent), then checkpoint.json naming them, then the files no longer named.
  void writeCheckpoint(double wall_so_far) {
    std::vector<std::string> files, sums;
    nlohmann::json nodes = nlohmann::json::array();
    for (const auto& node : tree.nodes()) {
      const std::string file =
          "node_" + std::to_string(node.level) + "_" + std::to_string(node.index) + ".bin";
      const auto known = std::find(node_files_.begin(), node_files_.end(), file);
      std::string sum = known == node_files_.end()
                            ? std::string()
                            : node_sums_[static_cast<std::size_t>(known - node_files_.begin())];
      if (known == node_files_.end()) {
        node.acc.save((files_.dir / file).string());
        sum = contentChecksum(readTextFile((files_.dir / file).string()));
      }
      nodes.push_back({{"level", node.level},
                       {"index", node.index},
                       {"file", file},
                       {"vectors", node.acc.count()},
                       {"checksum", sum}});
      files.push_back(file);
      sums.push_back(sum);
    }
    nlohmann::json j{{"fingerprint", fingerprint_},
                     {"assembly", assembly_},
                     {"next_block", sink.next_block},
                     {"blocks", plan_.blocks()},
                     {"next_leaf", tree.end()},
                     {"leaves", plan_.leaves()},
                     {"nodes", nodes},
                     {"failure_list", nlohmann::json::array()},
                     {"cost_samples", sink.costs},
                     {"run_wall_samples", sink.run_walls},
                     {"wall_s", wall_so_far}};
    for (const auto& f : sink.failures) j["failure_list"].push_back(failureJson(f));
    writeFileAtomic(files_.checkpoint.string(), sealJson(j).dump() + "\n");
    for (const auto& f : node_files_)
      if (std::find(files.begin(), files.end(), f) == files.end()) fs::remove(files_.dir / f);
    node_files_ = std::move(files);
    node_sums_ = std::move(sums);
  }

  const SynthesisPlan& plan_;
  const SynthesisOptions& opt_;
  const SynthesisFiles& files_;
  std::string assembly_, fingerprint_;
  bool root_;
  std::vector<std::string> node_files_;  ///< the nodes of the current checkpoint
  std::vector<std::string> node_sums_;   ///< their checksums (contentChecksum of the file's bytes)
  Clock::time_point last_ckpt_ = Clock::now();
};

/// Simulates draw j on worker w (each worker has its own Simulator, made on first use).
using DrawFn = std::function<DrawOutput(long j, int w)>;

void reduceOnThreads(const SynthesisPlan& plan, int threads, long first_draw, long end_draw,
                     const DrawFn& draw, LeafSink& sink, const std::function<void()>& after_block,
                     const std::function<void()>& tick);
void reduceOnRanks(const Distributed& processes, const SynthesisPlan& plan, int threads, int ranks,
                   const DrawFn& draw, Reduction& red, Clock::time_point t_run,
                   const ProgressFn& progress);

}  // namespace dtwin::classify
