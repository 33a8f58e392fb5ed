#include "classification/synthesis.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

#include "calibration/calibrate.hpp"
#include "classification/moment_tree.hpp"
#include "common/json.hpp"
#include "common/errors.hpp"
#include "common/statistics.hpp"
#include "common/validate.hpp"
#include "subsystems/random.hpp"
#include "common/distributed.hpp"
#include "common/parallel.hpp"
#include "io/provenance.hpp"
#include "twin/simulator.hpp"

namespace fs = std::filesystem;

namespace dtwin::classify {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return quantileSorted(v, 0.5);
}

nlohmann::json failureJson(const SynthesisFailure& f) {
  return {{"draw", f.draw}, {"road", f.road}, {"library_index", f.library_index}, {"road_seed", f.road_seed}, {"message", f.message}};
}
SynthesisFailure failureFrom(const nlohmann::json& j) {
  SynthesisFailure f;
  f.draw = j.at("draw").get<long>();
  f.road = j.at("road").get<long>();
  f.library_index = j.at("library_index").get<long>();
  f.road_seed = j.at("road_seed").get<std::uint64_t>();
  f.message = j.at("message").get<std::string>();
  return f;
}

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

/// A draw's output as doubles (what distributedMap carries between MPI ranks).
std::vector<double> packDraw(const DrawOutput& d) {
  Packer pk;
  pk.put(static_cast<double>(d.vectors.size()));
  for (const auto& v : d.vectors) pk.put(v);
  pk.put(static_cast<double>(d.failures.size()));
  for (const auto& f : d.failures)
    pk.put(static_cast<double>(f.draw)).put(static_cast<double>(f.road)).put(static_cast<double>(f.library_index))
        .put(static_cast<double>(f.road_seed)).put(f.message);
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

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Grid index of a window end, or InputError naming the option field (synthesis.<field>).
std::size_t windowIndex(double t, double rate, double duration, const char* field) {
  return gridIndex(t, rate, duration, OptionCheck("synthesis").where(field));
}

/// Everything a synthesis fixes before it simulates (synthesis.hpp, "What is simulated").
struct SynthesisPlan {
  long M = 0, R = 0, L = 0, B = 0;      ///< draws, roads per draw, library roads, draws per block
  std::uint64_t seed = 0;
  std::vector<std::string> names;       ///< the study's calibrated parameters (= the posterior's columns)
  std::shared_ptr<const Model> model;
  std::vector<int> slots;               ///< run-value slot of each calibrated parameter
  std::vector<double> base;             ///< the model's default run values
  const ScenarioSpec* sc = nullptr;     ///< the field scenario (random road)
  std::string unit;                     ///< of the channel
  bool noisy = false;                   ///< noise N(0, 1/τ) is added (channels in N)
  double rate = 0.0;                    ///< output grid [Hz]
  std::size_t kb = 0, ke = 0, p = 0;    ///< the window: first and last grid index, samples
  std::vector<double> times;            ///< the window's times
  bool branched = false;                ///< the roads of a draw share the smooth start
  double t_branch = -1.0;
  long LB = 1;                          ///< blocks per leaf of the accumulation tree
  long blocks() const { return (M + B - 1) / B; }
  long leaves() const { return (blocks() + LB - 1) / LB; }
  long blockSize(long b) const { return std::min(B, M - b * B); }
};

/// The sizes (options, else the study's sizes), the posterior checked against the study's
/// calibrated parameters, the model's slots, the scenario, channel and window, and whether the
/// roads of a draw branch from one smooth start.
SynthesisPlan planSynthesis(const Study& study, const AssemblySpec& assembly, const PosteriorSample& post,
                            const SynthesisOptions& opt) {
  const OptionCheck check("synthesis");
  SynthesisPlan plan;
  plan.M = opt.draws > 0 ? opt.draws : study.sizes.at("posterior_draws");
  plan.R = opt.roads_per_draw > 0 ? opt.roads_per_draw : study.sizes.at("roads_per_draw");
  plan.L = opt.road_library > 0 ? opt.road_library : study.sizes.at("road_library");
  plan.B = opt.block;
  plan.LB = opt.leaf_blocks;
  plan.seed = opt.seed.value_or(study.seed);
  check.atLeast("draws", plan.M, 1);
  check.atLeast("roads_per_draw", plan.R, 1);
  check.require(plan.L >= plan.R, "road_library",
                "must hold at least the roads per draw (" + std::to_string(plan.R) + "), got " + std::to_string(plan.L));
  if (post.size() == 0) throw InputError(post.path, "the posterior sample is empty");

  // The posterior's parameters must be the study's calibrated ones the assembly has, in order
  // (the hub input has no tire stiffness or damping: LabObjective::leftOut).
  plan.model = study.makeModel(assembly);
  for (const auto& c : study.calibrated)
    if (!plan.model->lacksOptionParameter(c.name)) plan.names.push_back(c.name);
  if (post.names != plan.names) {
    std::string a, b;
    for (const auto& n : post.names) a += (a.empty() ? "" : ",") + n;
    for (const auto& n : plan.names) b += (b.empty() ? "" : ",") + n;
    throw InputError(post.path + ":1", "parameter columns " + a + " are not the study's calibrated parameters " + b +
                                           " (" + study.path + ")");
  }
  for (const auto& n : plan.names) {
    const int s = plan.model->slot(n);
    if (s < 0) throw InputError(study.path + ": calibrated", "'" + n + "' is not a parameter of assembly " + assembly.id);
    plan.slots.push_back(s);
  }
  plan.base = plan.model->defaultRunValues();
  const ScenarioSpec& sc = study.scenario(opt.scenario);
  plan.sc = &sc;
  if (!sc.road->random())
    throw InputError("scenario " + sc.name, "synthetic field data need a random (iso8608) road to draw a road library from");
  for (const auto& c : measurableChannels(study.sensors))
    if (c.name == opt.channel) plan.unit = c.unit;
  plan.noisy = plan.unit == "N";
  plan.rate = study.simulation.output_rate_hz;
  plan.kb = windowIndex(opt.t_begin_s, plan.rate, sc.duration_s, "t_begin_s");
  plan.ke = windowIndex(opt.t_end_s, plan.rate, sc.duration_s, "t_end_s");
  plan.p = plan.ke - plan.kb + 1;
  check.require(plan.p <= 46000, "t_end_s", "the window holds " + std::to_string(plan.p) +
                                                " samples: the covariance would not fit in memory");
  for (std::size_t k = plan.kb; k <= plan.ke; ++k) plan.times.push_back(static_cast<double>(k) / plan.rate);
  Simulator probe(plan.model, study.simulation);
  plan.branched = opt.branch && probe.branchTime(sc) > 0 && probe.branchTime(sc) < sc.duration_s;
  plan.t_branch = plan.branched ? probe.branchTime(sc) : -1.0;
  return plan;
}

/// Who a synthesis is: the fingerprint of everything that changes the numbers (not threads, not
/// the checkpoint interval), and the hashes of the posterior recorded in synthesis.json.
struct SynthesisIdentity {
  std::string fingerprint;
  std::string post_text;  ///< the posterior file's bytes (root only; "" elsewhere)
  std::string post_hash;  ///< FNV-1a of the posterior's values as read
};

/// The fingerprint of `plan` and the posterior (synthesis.hpp, "Resume").
SynthesisIdentity identifySynthesis(const Study& study, const AssemblySpec& assembly, const PosteriorSample& post,
                                    const SynthesisOptions& opt, const SynthesisPlan& plan, bool root) {
  SynthesisIdentity id;
  id.post_text = root && fs::exists(post.path) ? readTextFile(post.path) : std::string();
  std::string post_rows;
  for (std::size_t i = 0; i < post.size(); ++i) {
    for (double v : post.theta[i]) post_rows += formatExact(v) + ",";
    post_rows += formatExact(post.tau[i]) + "\n";
  }
  id.post_hash = hexId(calib::fnv1a64(post_rows));
  nlohmann::json fp{{"format", 2},
                    {"assembly", assembly.id},
                    {"label", assembly.label()},
                    {"names", plan.names},
                    {"posterior_values_fnv1a64", id.post_hash},
                    {"draws", plan.M},
                    {"roads_per_draw", plan.R},
                    {"road_library", plan.L},
                    {"block", plan.B},
                    {"leaf_blocks", plan.LB},
                    {"seed", plan.seed},
                    {"streams", {hexId(kSynthDrawStream), hexId(kSynthRoadStream), hexId(kSynthNoiseStream), hexId(kRoadLibraryStream)}},
                    {"scenario", plan.sc->toJson()},
                    {"simulation", study.simulation.toJson()},
                    {"channel", opt.channel},
                    {"window", {plan.kb, plan.ke}},
                    {"noise", plan.noisy},
                    {"track_fourth_moment", opt.track_fourth_moment},
                    {"branched", plan.branched},
                    {"run_values", plan.base}};
  id.fingerprint = hexId(calib::fnv1a64(fp.dump()));
  return id;
}

/// The files of a synthesis folder (synthesis.hpp, "Files in out_dir").
struct SynthesisFiles {
  fs::path dir, moments, info, checkpoint;
  explicit SynthesisFiles(const std::string& out_dir)
      : dir(out_dir), moments(dir / "moments.bin"), info(dir / "synthesis.json"), checkpoint(dir / "checkpoint.json") {}
};

/// "F" + the bytes of `path` as the root reads them, "" when it does not exist: resume decisions
/// are taken on what the root reads (the same bytes on every MPI rank).
std::string rootRead(const fs::path& path) {
  return onRoot([&]() -> std::string { return fs::exists(path) ? "F" + readTextFile(path.string()) : std::string(); });
}

/// The JSON of a rootRead() text; null when it is not JSON (written atomically: a foreign file).
nlohmann::json parseRootJson(const std::string& text) {
  try {
    return nlohmann::json::parse(text.begin() + 1, text.end());
  } catch (const std::exception&) {
    return nlohmann::json();
  }
}

/// InputError: `path` belongs to a different synthesis.
[[noreturn]] void refuseForeign(const fs::path& path) {
  throw InputError(path.string(), "was made by a different synthesis (study, posterior, assembly, sizes, seed, window or "
                                  "options changed); use a new output folder or delete it to start over");
}

/// A finished synthesis of this fingerprint in the folder: `res` filled from its files, true.
/// False when there is none; InputError when the folder holds a different synthesis.
bool reuseFinished(const SynthesisFiles& files, const std::string& fingerprint, SynthesisResult& res) {
  const std::string info_text = rootRead(files.info);
  if (info_text.empty()) return false;
  const nlohmann::json j = parseRootJson(info_text);
  if (!j.is_object() || j.value("fingerprint", "") != fingerprint) refuseForeign(files.info);
  if (onRoot([&] { return std::string(fs::exists(files.moments) ? "1" : "0"); }) != "1") return false;
  res.moments = MomentAccumulator::load(files.moments.string());
  res.info = j;
  res.reused = true;
  res.failures = j.at("failures").get<long>();
  for (const auto& f : j.at("failure_list")) res.failure_list.push_back(failureFrom(f));
  res.cost_s_per_s = j.at("cost").at("wall_s_per_simulated_s_median").get<double>();
  res.median_run_wall_s = j.at("cost").at("run_wall_s_median").get<double>();
  return true;
}

/// Draw j on `sim`: its posterior row, R distinct library roads, the runs (branched or not), each
/// run's window plus noise, and what failed (synthesis.hpp, "What is simulated").
DrawOutput simulateDraw(const SynthesisPlan& plan, const PosteriorSample& post, const std::string& channel, Simulator& sim,
                        long j) {
  const long R = plan.R, L = plan.L;
  DrawOutput out;
  out.vectors.resize(static_cast<std::size_t>(R));
  // θ_j, τ_j: a row of the posterior sample.
  RandomStream draw_rs(plan.seed, kSynthDrawStream, static_cast<std::uint64_t>(j));
  const std::size_t row = std::min(post.size() - 1, static_cast<std::size_t>(draw_rs.uniform() * static_cast<double>(post.size())));
  std::vector<double> values = plan.base;
  for (std::size_t k = 0; k < plan.slots.size(); ++k) values[static_cast<std::size_t>(plan.slots[k])] = post.theta[row][k];
  const double sigma = 1.0 / std::sqrt(post.tau[row]);
  // R distinct library roads.
  RandomStream road_rs(plan.seed, kSynthRoadStream, static_cast<std::uint64_t>(j));
  std::vector<long> idx;
  while (static_cast<long>(idx.size()) < R) {
    const long i = std::min(L - 1, static_cast<long>(road_rs.uniform() * static_cast<double>(L)));
    if (std::find(idx.begin(), idx.end(), i) == idx.end()) idx.push_back(i);
  }
  std::vector<std::shared_ptr<const Road>> roads;
  std::vector<const Road*> ptrs;
  std::vector<std::uint64_t> road_seeds;
  for (long i : idx) {
    road_seeds.push_back(librarySeed(plan.seed, static_cast<std::uint64_t>(i)));
    roads.push_back(makeRoad(*plan.sc, plan.model->vehicle(), road_seeds.back()));
    ptrs.push_back(roads.back().get());
  }
  std::vector<RunResult> runs;
  std::string input_error;
  try {
    if (plan.branched) {
      runs = sim.runBranched(values, ptrs, *plan.sc);
    } else {
      for (const Road* r : ptrs) runs.push_back(sim.run(values, *r, *plan.sc));
    }
  } catch (const InputError& e) {
    input_error = e.what();  // a θ the laws reject: every run of the draw fails
  }
  for (long r = 0; r < R; ++r) {
    const auto fail = [&](const std::string& msg) {
      out.failures.push_back({j, r, idx[static_cast<std::size_t>(r)], road_seeds[static_cast<std::size_t>(r)], msg});
    };
    if (!input_error.empty()) {
      fail(input_error);
      continue;
    }
    const RunResult& run = runs[static_cast<std::size_t>(r)];
    if (!run.stats.ok) {
      fail(run.stats.message);
      continue;
    }
    const auto& col = run.trace.column(channel);
    if (col.size() <= plan.ke) {
      fail("the run ended before the window");
      continue;
    }
    std::vector<double> v(plan.p);
    RandomStream noise(plan.seed, kSynthNoiseStream, static_cast<std::uint64_t>(j * R + r));
    bool finite = true;
    for (std::size_t k = 0; k < plan.p; ++k) {
      v[k] = col[plan.kb + k] + (plan.noisy ? sigma * noise.normal() : 0.0);
      finite = finite && std::isfinite(v[k]);
    }
    if (!finite) {
      fail("non-finite output in the window");
      continue;
    }
    out.vectors[static_cast<std::size_t>(r)] = std::move(v);
    if (run.stats.sim_s > 0) out.cost.push_back(run.stats.wall_s / run.stats.sim_s);
    out.run_wall.push_back(run.stats.wall_s);
  }
  return out;
}

/// Adds a synthesis's blocks, in block order, to the leaves of a MomentTree: a leaf is
/// `leaf_blocks` blocks added with addBlock to an empty accumulator, then pushed into the tree
/// (synthesis.hpp, "Accumulation"). Also keeps the failures and run costs in draw order. Not
/// thread-safe: the caller adds one block at a time.
class LeafSink {
 public:
  LeafSink(const SynthesisPlan& plan, const MomentOptions& mo, MomentTree& tree)
      : next_block(tree.end() * plan.LB), plan_(plan), mo_(mo), tree_(tree), leaf_(static_cast<int>(plan.p), mo) {}

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
          if (!v.empty()) X.col(c++) = Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(plan_.p));
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
  Reduction(const SynthesisPlan& plan, const SynthesisOptions& opt, const SynthesisFiles& files, std::string assembly,
            std::string fingerprint, bool root)
      : tree(plan.leaves()), sink(plan, momentOptions(opt), tree), plan_(plan), opt_(opt), files_(files),
        assembly_(std::move(assembly)), fingerprint_(std::move(fingerprint)), root_(root) {}

  /// Continues from checkpoint.json when the folder has one (InputError when it is another
  /// synthesis's or does not match its node files).
  void resume() {
    const std::string ckpt_text = rootRead(files_.checkpoint);
    if (ckpt_text.empty()) return;
    const nlohmann::json j = parseRootJson(ckpt_text);
    if (!j.is_object() || j.value("fingerprint", "") != fingerprint_ || !j.contains("nodes")) refuseForeign(files_.checkpoint);
    const long next_leaf = j.at("next_leaf").get<long>();
    if (root_) {
      std::vector<TreeNode> nodes;
      for (const auto& n : j.at("nodes")) {
        TreeNode node;
        node.level = n.at("level").get<int>();
        node.index = n.at("index").get<long>();
        node.acc = MomentAccumulator::load((files_.dir / n.at("file").get<std::string>()).string());
        if (node.acc.dimension() != static_cast<int>(plan_.p))
          throw InputError(files_.checkpoint.string(), "does not match " + n.at("file").get<std::string>() + "; delete the folder to start over");
        nodes.push_back(std::move(node));
      }
      tree = MomentTree::fromNodes(plan_.leaves(), 0, std::move(nodes), files_.checkpoint.string());
      if (tree.end() != next_leaf)
        throw InputError(files_.checkpoint.string(), "its nodes end at leaf " + std::to_string(tree.end()) + ", not at next_leaf " +
                                                         std::to_string(next_leaf) + "; delete the folder to start over");
      for (const auto& n : j.at("nodes")) node_files_.push_back(n.at("file").get<std::string>());
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
    onRoot([&]() -> std::string {
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
    std::vector<std::string> files;
    nlohmann::json nodes = nlohmann::json::array();
    for (const auto& node : tree.nodes()) {
      const std::string file = "node_" + std::to_string(node.level) + "_" + std::to_string(node.index) + ".bin";
      if (std::find(node_files_.begin(), node_files_.end(), file) == node_files_.end()) node.acc.save((files_.dir / file).string());
      nodes.push_back({{"level", node.level}, {"index", node.index}, {"file", file}, {"vectors", node.acc.count()}});
      files.push_back(file);
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
    writeFileAtomic(files_.checkpoint.string(), j.dump() + "\n");
    for (const auto& f : node_files_)
      if (std::find(files.begin(), files.end(), f) == files.end()) fs::remove(files_.dir / f);
    node_files_ = std::move(files);
  }

  const SynthesisPlan& plan_;
  const SynthesisOptions& opt_;
  const SynthesisFiles& files_;
  std::string assembly_, fingerprint_;
  bool root_;
  std::vector<std::string> node_files_;  ///< the nodes of the current checkpoint
  Clock::time_point last_ckpt_ = Clock::now();
};

/// Simulates draw j on worker w (each worker has its own Simulator, made on first use).
using DrawFn = std::function<DrawOutput(long j, int w)>;

/// Draws [first_draw, end_draw) on this process's threads, each finished block added to `sink`
/// as soon as its predecessors are (one reducer at a time; a finished block whose predecessor is
/// still running waits in `pending`). `after_block` runs after each block is added (under the
/// reducer's lock); `tick` after each draw.
void reduceOnThreads(const SynthesisPlan& plan, int threads, long first_draw, long end_draw, const DrawFn& draw, LeafSink& sink,
                     const std::function<void()>& after_block, const std::function<void()>& tick) {
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
  parallelFor(static_cast<std::size_t>(end_draw - first_draw), threads, [&](std::size_t task, int w) {
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

/// Failures and run costs of a rank's draws, as doubles (what distributedMap carries).
std::vector<double> packSink(const LeafSink& s) {
  DrawOutput d;
  d.failures = s.failures;
  d.cost = s.costs;
  d.run_wall = s.run_walls;
  return packDraw(d);
}

/// Several MPI ranks: rounds of whole leaves. Rank r of K takes the round's leaves
/// [L0 + r·q, L0 + (r + 1)·q), simulates their draws on its threads and builds its part of the
/// tree; the parts are combined along a binomial tree of ranks (rank r + 2^s sends its nodes to
/// rank r, s = 0, 1, ...: log2 K steps, each a transfer and the sibling merges it completes) and
/// the root appends the round's nodes to its tree. Every node is the tree's own, so the moments
/// are those of one process bit for bit. Rounds (at most kRoundLeaves leaves per rank, so that a
/// checkpoint comes every few minutes) are balanced: q = ⌈leaves left / (K · rounds left)⌉.
void reduceOnRanks(const SynthesisPlan& plan, int threads, int ranks, const DrawFn& draw, Reduction& red,
                   Clock::time_point t_run, const ProgressFn& progress) {
  constexpr long kRoundLeaves = 8;
  const Distributed& D = Distributed::instance();
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
    const auto packed = distributedMap(static_cast<std::size_t>(ranks), threads, [&](std::size_t r, int) -> std::vector<double> {
      DTWIN_CHECK(static_cast<int>(r) == D.rank(), "a rank's leaves computed on another rank");
      LeafSink sink(plan, red.sink.moments(), part);
      const long j0 = std::min(plan.M, lo * leaf_draws), j1 = std::min(plan.M, hi * leaf_draws);
      reduceOnThreads(plan, threads, j0, j1, draw, sink, nullptr, [&] {
        if (progress) progress(std::min<std::size_t>(static_cast<std::size_t>(plan.M), done += static_cast<std::size_t>(ranks)),
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
      if (D.rank() % (2 * s) == 0 && D.rank() + s < ranks) part.append(MomentTree::fromVector(D.receiveDoubles(D.rank() + s)));
    }
    if (D.isRoot()) {
      DTWIN_CHECK(part.first() == L0 && part.end() == L1, "the ranks' parts do not cover the round");
      red.tree.append(std::move(part));
    }
    red.combine_s += secondsSince(t_combine);
    for (const auto& p : packed) red.sink.addRecords(unpackDraw(p));
    red.sink.next_block = std::min(plan.blocks(), L1 * plan.LB);
    if (!D.isRoot()) red.tree = MomentTree(n_leaves, L1);  // the root holds [0, L1)
    onRoot([&]() -> std::string {
      red.checkpointIfDue(t_run);
      return std::string();
    });
  }
}

/// synthesis.json (SynthesisResult::info): provenance, sizes, streams, noise, window, moments,
/// cost and wall time.
nlohmann::json synthesisInfo(const Study& study, const AssemblySpec& assembly, const PosteriorSample& post,
                             const SynthesisOptions& opt, const SynthesisPlan& plan, const SynthesisIdentity& id,
                             const Reduction& red, const MomentAccumulator& acc, const SynthesisResult& res, double wall_total,
                             int workers, int ranks) {
  const long M = plan.M, R = plan.R;
  nlohmann::json j;
  j["program"] = programInfo();
  j["command"] = opt.command;
  j["created_utc"] = utcNow();
  j["study"] = study.path;
  j["assembly"] = assembly.id;
  j["label"] = assembly.label();
  j["posterior"] = {{"path", post.path}, {"rows", post.size()}, {"parameters", plan.names}, {"values_fnv1a64", id.post_hash},
                    {"file_fnv1a64", id.post_text.empty() ? std::string() : hexId(calib::fnv1a64(id.post_text))}};
  j["draws"] = M;
  j["roads_per_draw"] = R;
  j["road_library"] = plan.L;
  j["block"] = plan.B;
  j["leaf_blocks"] = plan.LB;
  j["simulations"] = M * R;
  j["vectors"] = acc.count();
  j["failures"] = res.failures;
  j["failure_list"] = nlohmann::json::array();
  for (std::size_t i = 0; i < red.sink.failures.size() && i < 1000; ++i) j["failure_list"].push_back(failureJson(red.sink.failures[i]));
  if (red.sink.failures.size() > 1000) j["failure_list_truncated"] = true;
  j["seed"] = plan.seed;
  j["streams"] = {
      {"draw", {{"constant", hexId(kSynthDrawStream)},
                {"rule", "draw j uses posterior row floor(u * rows), u the first uniform of RandomStream(seed, draw, j)"}}},
      {"road", {{"constant", hexId(kSynthRoadStream)},
                {"rule", "draw j's library indices: floor(u * library) from RandomStream(seed, road, j), redrawn while one repeats"}}},
      {"road_library", {{"constant", hexId(kRoadLibraryStream)},
                        {"rule", "library road i has seed RandomStream(seed, road_library, i).bits() >> 11 (not the field data's stream)"}}},
      {"noise", {{"constant", hexId(kSynthNoiseStream)},
                 {"rule", "vector (j, r) adds sigma_j * N(0, 1) from RandomStream(seed, noise, j * roads_per_draw + r) in time order"}}}};
  j["noise"] = {{"applied", plan.noisy},
                {"rule", plan.noisy ? "N(0, 1/tau_j) per value, tau_j from the posterior row of draw j"
                                    : "none: the channel is not in N (as twin generate field)"}};
  j["scenario"] = plan.sc->toJson();
  j["simulation"] = study.simulation.toJson();
  j["branched"] = plan.branched;
  if (plan.branched) j["branch_time_s"] = plan.t_branch;
  j["channel"] = opt.channel;
  j["unit"] = plan.unit;
  j["window_s"] = {plan.times.front(), plan.times.back()};
  j["samples"] = plan.p;
  j["output_rate_hz"] = plan.rate;
  j["moments"] = {{"file", "moments.bin"},
                  {"format", "MomentAccumulator::save: 8-byte tag DTWMOM01, then doubles (little-endian): magic, version, p, n, "
                             "track flag, mean (p), packed upper triangle of M2 column by column (p(p+1)/2), [T (p), Q]"},
                  {"dimension", plan.p},
                  {"count", acc.count()},
                  {"track_fourth_moment", opt.track_fourth_moment},
                  {"accumulation", "fixed blocks of `block` draws, addBlock in (draw, road) order; leaves of `leaf_blocks` blocks "
                                   "in block order; leaves merged in a fixed binary tree (node (l+1, k) = node (l, 2k) merged with "
                                   "node (l, 2k+1))"}};
  j["cost"] = {{"wall_s_per_simulated_s_median", res.cost_s_per_s},
               {"run_wall_s_median", res.median_run_wall_s},
               {"runs_measured", red.sink.costs.size()},
               {"rule", std::string("median over the successful runs of wall time / simulated time") +
                            (plan.branched ? "; a branched run carries an even share of its draw's common smooth part" : "")}};
  j["wall_s"] = wall_total;
  j["resumed_blocks"] = res.resumed_blocks;
  j["threads"] = workers;
  j["ranks"] = ranks;
  if (ranks > 1) j["rank_tree_combine_s"] = red.combine_s;
  j["fingerprint"] = id.fingerprint;
  return j;
}

}  // namespace

std::uint64_t librarySeed(std::uint64_t seed, std::uint64_t index) {
  return RandomStream(seed, kRoadLibraryStream, index).bits() >> 11;
}

void SynthesisOptions::validate() const {
  const OptionCheck check("synthesis");
  check.atLeast("block", block, 1);
  check.atLeast("leaf_blocks", leaf_blocks, 1);
  check.finite("t_begin_s", t_begin_s);
  check.finite("t_end_s", t_end_s);
  check.require(t_begin_s <= t_end_s, "t_begin_s",
                "must be <= t_end_s (" + formatExact(t_end_s) + " s), got " + formatExact(t_begin_s) + " s");
  check.require(checkpoint_interval_s >= 0, "checkpoint_interval_s",  // +inf: no checkpoint
                "must be >= 0 s (0: after every block), got " + formatNumber(checkpoint_interval_s));
  const std::string channel_rule = checkChannelName(channel, measurableChannels());
  check.require(channel_rule.empty(), "channel", channel_rule);
}

// ------------------------------------------------------------------ synthesis
// The stages: plan (sizes, model, window) → identity (fingerprint) → reuse a finished synthesis,
// or resume from its checkpoint → simulate the remaining draws, reduced in block order (threads
// or MPI ranks) → synthesis.json and moments.bin.
SynthesisResult synthesizeAssembly(const Study& study, const AssemblySpec& assembly, const PosteriorSample& post,
                                   const SynthesisOptions& opt, const std::string& out_dir, const ProgressFn& progress) {
  const auto t_all = Clock::now();
  opt.validate();
  const SynthesisPlan plan = planSynthesis(study, assembly, post, opt);
  const bool root = Distributed::instance().isRoot();  // only the root writes files
  const SynthesisIdentity id = identifySynthesis(study, assembly, post, opt, plan, root);
  if (root) fs::create_directories(out_dir);
  const SynthesisFiles files(out_dir);

  SynthesisResult res;
  res.assembly = assembly.id;
  res.fingerprint = id.fingerprint;
  res.times_s = plan.times;
  res.draws = plan.M;
  res.roads_per_draw = plan.R;
  res.road_library = plan.L;
  res.block = plan.B;
  res.simulations = plan.M * plan.R;
  if (reuseFinished(files, id.fingerprint, res)) {
    res.wall_s = secondsSince(t_all);
    if (progress) progress(static_cast<std::size_t>(plan.M), static_cast<std::size_t>(plan.M));
    return res;
  }

  Reduction red(plan, opt, files, assembly.id, id.fingerprint, root);
  red.resume();
  res.resumed_blocks = red.sink.next_block;
  const long first_draw = std::min(plan.M, red.sink.next_block * plan.B);
  const long todo = plan.M - first_draw;
  const int ranks = Distributed::instance().size();
  const int workers = distributedWorkers(static_cast<std::size_t>(std::max<long>(todo, 1)), opt.threads);
  std::vector<std::unique_ptr<Simulator>> sims(static_cast<std::size_t>(workers));
  const DrawFn draw = [&](long j, int w) {
    auto& sim = sims[static_cast<std::size_t>(w)];
    if (!sim) sim = std::make_unique<Simulator>(plan.model, study.simulation);
    return simulateDraw(plan, post, opt.channel, *sim, j);
  };
  red.startClock();
  const auto t_run = Clock::now();
  if (progress) progress(static_cast<std::size_t>(first_draw), static_cast<std::size_t>(plan.M));
  if (ranks == 1) {
    std::size_t done = static_cast<std::size_t>(first_draw);
    reduceOnThreads(plan, opt.threads, first_draw, plan.M, draw, red.sink, [&] { red.checkpointIfDue(t_run); },
                    [&] {
                      if (progress) progress(++done, static_cast<std::size_t>(plan.M));
                    });
  } else {
    reduceOnRanks(plan, opt.threads, ranks, draw, red, t_run, progress);
  }
  DTWIN_CHECK(red.sink.next_block == plan.blocks(), "blocks left unreduced");

  // The root's tree is complete; under MPI every rank gets its root.
  MomentAccumulator acc{1};
  if (ranks == 1) {
    acc = red.tree.takeRoot();
  } else {
    const std::string bytes = onRoot([&]() -> std::string {
      const std::vector<std::uint8_t> b = red.tree.root().toBytes();
      return std::string(b.begin(), b.end());
    });
    acc = MomentAccumulator::fromBytes(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
  }
  const double wall_total = red.previous_wall + secondsSince(t_run);
  res.failures = static_cast<long>(red.sink.failures.size());
  res.failure_list = red.sink.failures;
  res.cost_s_per_s = median(red.sink.costs);
  res.median_run_wall_s = median(red.sink.run_walls);
  nlohmann::json info = synthesisInfo(study, assembly, post, opt, plan, id, red, acc, res, wall_total, workers, ranks);
  red.writeResults(acc, info);
  res.info = std::move(info);
  res.moments = std::move(acc);
  res.wall_s = secondsSince(t_all);
  return res;
}

}  // namespace dtwin::classify
