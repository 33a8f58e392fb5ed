#include "classification/synthesis.hpp"
#include "classification/synthesis_internal.hpp"

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
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/json.hpp"
#include "common/parallel.hpp"
#include "common/statistics.hpp"
#include "common/validate.hpp"
#include "io/provenance.hpp"
#include "subsystems/random.hpp"
#include "twin/simulator.hpp"

namespace fs = std::filesystem;

namespace dtwin::classify {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return quantileSorted(v, 0.5);
}

}  // namespace

nlohmann::json failureJson(const SynthesisFailure& f) {
  return {{"draw", f.draw},
          {"road", f.road},
          {"library_index", f.library_index},
          {"road_seed", f.road_seed},
          {"message", f.message}};
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

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// "F" + the bytes of `path` as the root reads them, "" when it does not exist: resume decisions
/// are taken on what the root reads (the same bytes on every MPI rank).
std::string rootRead(const Distributed* processes, const fs::path& path) {
  return onRoot(processes, [&]() -> std::string {
    return fs::exists(path) ? "F" + readTextFile(path.string()) : std::string();
  });
}

std::string rootReadCheckpoint(const Distributed* processes, const SynthesisFiles& files) {
  return onRoot(processes, [&]() -> std::string {
    const fs::path& path = files.checkpoint;
    if (!fs::exists(path)) return std::string();
    const std::string text = readTextFile(path.string());
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(text);
    } catch (const std::exception&) {
      setAsideCorrupt(path.string(), "is not valid JSON");
      return std::string();
    }
    if (checkSeal(j) == Seal::broken) {
      setAsideCorrupt(path.string(), "fails its checksum");
      return std::string();
    }
    if (j.is_object() && j.contains("nodes") && j["nodes"].is_array())
      for (const auto& n : j["nodes"]) {
        const std::string sum = n.value("checksum", std::string()),
                          file = n.value("file", std::string());
        if (sum.empty() || file.empty())
          continue;  // a checkpoint written before checksums were recorded
        const fs::path node = files.dir / file;
        if (!fs::exists(node) || contentChecksum(readTextFile(node.string())) != sum) {
          setAsideCorrupt(
              path.string(),
              "its node file " + file + (fs::exists(node) ? " fails its checksum" : " is missing"));
          return std::string();
        }
      }
    return "F" + text;
  });
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
  throw InputError(
      path.string(),
      "was made by a different synthesis (study, posterior, assembly, sizes, seed, window or "
      "options changed); use a new output folder or delete it to start over");
}

namespace {

/// Grid index of a window end, or InputError naming the option field (synthesis.<field>).
std::size_t windowIndex(double t, double rate, double duration, const char* field) {
  return gridIndex(t, rate, duration, OptionCheck("synthesis").where(field));
}

/// The sizes (options, else the study's sizes), the posterior checked against the study's
/// calibrated parameters, the model's slots, the scenario, channel and window, and whether the
/// roads of a draw branch from one smooth start.
SynthesisPlan planSynthesis(const Study& study, const AssemblySpec& assembly,
                            const PosteriorSample& post, const SynthesisOptions& opt) {
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
                "must hold at least the roads per draw (" + std::to_string(plan.R) + "), got " +
                    std::to_string(plan.L));
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
    throw InputError(post.path + ":1", "parameter columns " + a +
                                           " are not the study's calibrated parameters " + b +
                                           " (" + study.path + ")");
  }
  for (const auto& n : plan.names) {
    const int s = plan.model->slot(n);
    if (s < 0)
      throw InputError(study.path + ": calibrated",
                       "'" + n + "' is not a parameter of assembly " + assembly.id);
    plan.slots.push_back(s);
  }
  plan.base = plan.model->defaultRunValues();
  const ScenarioSpec& sc = study.scenario(opt.scenario);
  plan.sc = &sc;
  if (!sc.road->random())
    throw InputError(
        "scenario " + sc.name,
        "synthetic field data need a random (iso8608) road to draw a road library from");
  for (const auto& c : measurableChannels(study.sensors))
    if (c.name == opt.channel) plan.unit = c.unit;
  plan.noisy = plan.unit == "N";
  plan.rate = study.simulation.output_rate_hz;
  plan.kb = windowIndex(opt.t_begin_s, plan.rate, sc.duration_s, "t_begin_s");
  plan.ke = windowIndex(opt.t_end_s, plan.rate, sc.duration_s, "t_end_s");
  plan.p = plan.ke - plan.kb + 1;
  check.require(plan.p <= 46000, "t_end_s",
                "the window holds " + std::to_string(plan.p) +
                    " samples: the covariance would not fit in memory");
  for (std::size_t k = plan.kb; k <= plan.ke; ++k)
    plan.times.push_back(static_cast<double>(k) / plan.rate);
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
SynthesisIdentity identifySynthesis(const Study& study, const AssemblySpec& assembly,
                                    const PosteriorSample& post, const SynthesisOptions& opt,
                                    const SynthesisPlan& plan, bool root) {
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
                    {"streams",
                     {hexId(kSynthDrawStream), hexId(kSynthRoadStream), hexId(kSynthNoiseStream),
                      hexId(kRoadLibraryStream)}},
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

/// A finished synthesis of this fingerprint in the folder: `res` filled from its files, true.
/// False when there is none; InputError when the folder holds a different synthesis.
bool reuseFinished(const Distributed* processes, const SynthesisFiles& files,
                   const std::string& fingerprint, SynthesisResult& res) {
  const std::string info_text = rootRead(processes, files.info);
  if (info_text.empty()) return false;
  const nlohmann::json j = parseRootJson(info_text);
  if (!j.is_object() || j.value("fingerprint", "") != fingerprint) refuseForeign(files.info);
  if (onRoot(processes, [&] { return std::string(fs::exists(files.moments) ? "1" : "0"); }) != "1")
    return false;
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
DrawOutput simulateDraw(const SynthesisPlan& plan, const PosteriorSample& post,
                        const std::string& channel, Simulator& sim, long j) {
  const long R = plan.R, L = plan.L;
  DrawOutput out;
  out.vectors.resize(static_cast<std::size_t>(R));
  // θ_j, τ_j: a row of the posterior sample.
  RandomStream draw_rs(plan.seed, kSynthDrawStream, static_cast<std::uint64_t>(j));
  const std::size_t row =
      std::min(post.size() - 1,
               static_cast<std::size_t>(draw_rs.uniform() * static_cast<double>(post.size())));
  std::vector<double> values = plan.base;
  for (std::size_t k = 0; k < plan.slots.size(); ++k)
    values[static_cast<std::size_t>(plan.slots[k])] = post.theta[row][k];
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
      out.failures.push_back(
          {j, r, idx[static_cast<std::size_t>(r)], road_seeds[static_cast<std::size_t>(r)], msg});
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

/// synthesis.json (SynthesisResult::info): provenance, sizes, streams, noise, window, moments,
/// cost and wall time.
nlohmann::json synthesisInfo(const Study& study, const AssemblySpec& assembly,
                             const PosteriorSample& post, const SynthesisOptions& opt,
                             const SynthesisPlan& plan, const SynthesisIdentity& id,
                             const Reduction& red, const MomentAccumulator& acc,
                             const SynthesisResult& res, double wall_total, int workers,
                             int ranks) {
  const long M = plan.M, R = plan.R;
  nlohmann::json j;
  stampProvenance(j, opt.command);
  j["study"] = study.path;
  j["assembly"] = assembly.id;
  j["label"] = assembly.label();
  j["posterior"] = {
      {"path", post.path},
      {"rows", post.size()},
      {"parameters", plan.names},
      {"values_fnv1a64", id.post_hash},
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
  for (std::size_t i = 0; i < red.sink.failures.size() && i < 1000; ++i)
    j["failure_list"].push_back(failureJson(red.sink.failures[i]));
  if (red.sink.failures.size() > 1000) j["failure_list_truncated"] = true;
  j["seed"] = plan.seed;
  j["streams"] = {{"draw",
                   {{"constant", hexId(kSynthDrawStream)},
                    {"rule",
                     "draw j uses posterior row floor(u * rows), u the first uniform of "
                     "RandomStream(seed, draw, j)"}}},
                  {"road",
                   {{"constant", hexId(kSynthRoadStream)},
                    {"rule",
                     "draw j's library indices: floor(u * library) from RandomStream(seed, road, "
                     "j), redrawn while one repeats"}}},
                  {"road_library",
                   {{"constant", hexId(kRoadLibraryStream)},
                    {"rule",
                     "library road i has seed RandomStream(seed, road_library, i).bits() >> 11 "
                     "(not the field data's stream)"}}},
                  {"noise",
                   {{"constant", hexId(kSynthNoiseStream)},
                    {"rule",
                     "vector (j, r) adds sigma_j * N(0, 1) from RandomStream(seed, noise, j * "
                     "roads_per_draw + r) in time order"}}}};
  j["noise"] = {
      {"applied", plan.noisy},
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
  j["moments"] = {
      {"file", "moments.bin"},
      {"format",
       "MomentAccumulator::save: 8-byte tag DTWMOM01, then doubles (little-endian): magic, "
       "version, p, n, "
       "track flag, mean (p), packed upper triangle of M2 column by column (p(p+1)/2), [T (p), Q]"},
      {"dimension", plan.p},
      {"count", acc.count()},
      {"track_fourth_moment", opt.track_fourth_moment},
      {"accumulation",
       "fixed blocks of `block` draws, addBlock in (draw, road) order; leaves of `leaf_blocks` "
       "blocks "
       "in block order; leaves merged in a fixed binary tree (node (l+1, k) = node (l, 2k) merged "
       "with "
       "node (l, 2k+1))"}};
  j["cost"] = {
      {"wall_s_per_simulated_s_median", res.cost_s_per_s},
      {"run_wall_s_median", res.median_run_wall_s},
      {"runs_measured", red.sink.costs.size()},
      {"rule", std::string("median over the successful runs of wall time / simulated time") +
                   (plan.branched
                        ? "; a branched run carries an even share of its draw's common smooth part"
                        : "")}};
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
  check.require(
      t_begin_s <= t_end_s, "t_begin_s",
      "must be <= t_end_s (" + formatExact(t_end_s) + " s), got " + formatExact(t_begin_s) + " s");
  check.require(
      checkpoint_interval_s >= 0, "checkpoint_interval_s",  // +inf: no checkpoint
      "must be >= 0 s (0: after every block), got " + formatNumber(checkpoint_interval_s));
  const std::string channel_rule = checkChannelName(channel, measurableChannels());
  check.require(channel_rule.empty(), "channel", channel_rule);
}

// ------------------------------------------------------------------ synthesis
// The stages: plan (sizes, model, window) → identity (fingerprint) → reuse a finished synthesis,
// or resume from its checkpoint → simulate the remaining draws, reduced in block order (threads
// or MPI ranks) → synthesis.json and moments.bin.
SynthesisResult synthesizeAssembly(const Study& study, const AssemblySpec& assembly,
                                   const PosteriorSample& post, const SynthesisOptions& opt,
                                   const std::string& out_dir, const ProgressFn& progress) {
  const auto t_all = Clock::now();
  opt.validate();
  const SynthesisPlan plan = planSynthesis(study, assembly, post, opt);
  const bool root = isRootProcess(opt.processes);  // only the root writes files
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
  if (reuseFinished(opt.processes, files, id.fingerprint, res)) {
    res.wall_s = secondsSince(t_all);
    if (progress) progress(static_cast<std::size_t>(plan.M), static_cast<std::size_t>(plan.M));
    return res;
  }

  Reduction red(plan, opt, files, assembly.id, id.fingerprint, root);
  red.resume();
  res.resumed_blocks = red.sink.next_block;
  const long first_draw = std::min(plan.M, red.sink.next_block * plan.B);
  const long todo = plan.M - first_draw;
  const int ranks = processCount(opt.processes);
  const int workers = distributedWorkers(
      opt.processes, static_cast<std::size_t>(std::max<long>(todo, 1)), opt.threads);
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
    reduceOnThreads(
        plan, opt.threads, first_draw, plan.M, draw, red.sink, [&] { red.checkpointIfDue(t_run); },
        [&] {
          if (progress) progress(++done, static_cast<std::size_t>(plan.M));
        });
  } else {
    reduceOnRanks(*opt.processes, plan, opt.threads, ranks, draw, red, t_run, progress);
  }
  DTWIN_CHECK(red.sink.next_block == plan.blocks(), "blocks left unreduced");

  // The root's tree is complete; under MPI every rank gets its root.
  MomentAccumulator acc{1};
  if (ranks == 1) {
    acc = red.tree.takeRoot();
  } else {
    const std::string bytes = onRoot(opt.processes, [&]() -> std::string {
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
  nlohmann::json info = synthesisInfo(study, assembly, post, opt, plan, id, red, acc, res,
                                      wall_total, workers, ranks);
  red.writeResults(acc, info);
  res.info = std::move(info);
  res.moments = std::move(acc);
  res.wall_s = secondsSince(t_all);
  return res;
}

}  // namespace dtwin::classify
