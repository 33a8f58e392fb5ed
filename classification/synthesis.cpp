#include "classification/synthesis.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

#include "calibration/calibrate.hpp"
#include "common/errors.hpp"
#include "subsystems/random.hpp"
#include "twin/distributed.hpp"
#include "twin/parallel.hpp"
#include "twin/provenance.hpp"
#include "twin/simulator.hpp"

namespace fs = std::filesystem;

namespace dtwin::classify {
namespace {

/// Grid index of time t at `rate`; InputError if t is not on the grid or outside [0, duration].
std::size_t gridIndex(double t, double rate, double duration, const std::string& where) {
  const double k = t * rate;
  if (!std::isfinite(t) || std::abs(k - std::round(k)) > 1e-6)
    throw InputError(where, formatExact(t) + " s is not on the output grid (multiples of " + formatExact(1.0 / rate) + " s)");
  if (t < 0 || t > duration + 1e-9)
    throw InputError(where, formatExact(t) + " s lies outside the scenario (0 .. " + formatExact(duration) + " s)");
  return static_cast<std::size_t>(std::llround(k));
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const std::size_t m = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(m), v.end());
  const double hi = v[m];
  if (v.size() % 2) return hi;
  return 0.5 * (hi + *std::max_element(v.begin(), v.begin() + static_cast<long>(m)));
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

}  // namespace

std::uint64_t librarySeed(std::uint64_t seed, std::uint64_t index) {
  return RandomStream(seed, kRoadLibraryStream, index).bits() >> 11;
}

// ------------------------------------------------------------------ synthesis
SynthesisResult synthesizeAssembly(const Study& study, const AssemblySpec& assembly, const PosteriorSample& post,
                                   const SynthesisOptions& opt, const std::string& out_dir, const ProgressFn& progress) {
  using Clock = std::chrono::steady_clock;
  const auto t_all = Clock::now();
  const long M = opt.draws > 0 ? opt.draws : study.sizes.at("posterior_draws");
  const long R = opt.roads_per_draw > 0 ? opt.roads_per_draw : study.sizes.at("roads_per_draw");
  const long L = opt.road_library > 0 ? opt.road_library : study.sizes.at("road_library");
  const long B = opt.block;
  const std::uint64_t seed = opt.seed.value_or(study.seed);
  if (M < 1) throw InputError("posterior draws", "must be >= 1, got " + std::to_string(M));
  if (R < 1) throw InputError("roads per draw", "must be >= 1, got " + std::to_string(R));
  if (L < R)
    throw InputError("road library", "must hold at least the roads per draw (" + std::to_string(R) + "), got " + std::to_string(L));
  if (B < 1) throw InputError("block", "must be >= 1 draws, got " + std::to_string(B));
  if (!(opt.checkpoint_interval_s >= 0)) throw InputError("checkpoint interval", "must be >= 0 s");
  if (post.size() == 0) throw InputError(post.path, "the posterior sample is empty");

  // The posterior's parameters must be the study's calibrated ones, in order.
  std::vector<std::string> names;
  for (const auto& c : study.calibrated) names.push_back(c.name);
  if (post.names != names) {
    std::string a, b;
    for (const auto& n : post.names) a += (a.empty() ? "" : ",") + n;
    for (const auto& n : names) b += (b.empty() ? "" : ",") + n;
    throw InputError(post.path + ":1", "parameter columns " + a + " are not the study's calibrated parameters " + b +
                                           " (" + study.path + ")");
  }
  auto model = study.makeModel(assembly);
  std::vector<int> slots;
  for (const auto& n : names) {
    const int s = model->slot(n);
    if (s < 0) throw InputError(study.path + ": calibrated", "'" + n + "' is not a parameter of assembly " + assembly.id);
    slots.push_back(s);
  }
  const std::vector<double> base = model->defaultRunValues();
  const ScenarioSpec& sc = study.scenario(opt.scenario);
  if (sc.road.type != RoadSpec::Type::Iso)
    throw InputError("scenario " + sc.name, "synthetic field data need a random (iso8608) road to draw a road library from");
  const auto channels = measurableChannels();
  const std::string rule = checkChannelName(opt.channel, channels);
  if (!rule.empty()) throw InputError("channel", rule);
  std::string unit;
  for (const auto& c : channels)
    if (c.name == opt.channel) unit = c.unit;
  const bool noisy = unit == "N";
  const double rate = study.simulation.output_rate_hz;
  if (!(opt.t_begin_s <= opt.t_end_s))
    throw InputError("window", "needs begin <= end, got " + formatExact(opt.t_begin_s) + " .. " + formatExact(opt.t_end_s) + " s");
  const std::size_t kb = gridIndex(opt.t_begin_s, rate, sc.duration_s, "window begin");
  const std::size_t ke = gridIndex(opt.t_end_s, rate, sc.duration_s, "window end");
  const std::size_t p = ke - kb + 1;
  if (p > 46000) throw InputError("window", std::to_string(p) + " samples: the covariance would not fit in memory");
  std::vector<double> times;
  for (std::size_t k = kb; k <= ke; ++k) times.push_back(static_cast<double>(k) / rate);
  Simulator probe(model, study.simulation);
  const bool branched = opt.branch && probe.branchTime(sc) > 0 && probe.branchTime(sc) < sc.duration_s;
  const double t_branch = branched ? probe.branchTime(sc) : -1.0;

  // Fingerprint: everything that changes the numbers (not threads, not the checkpoint interval).
  const bool root = Distributed::instance().isRoot();  // only the root writes files
  const std::string post_text = root && fs::exists(post.path) ? readFileBytes(post.path) : std::string();
  std::string post_rows;
  for (std::size_t i = 0; i < post.size(); ++i) {
    for (double v : post.theta[i]) post_rows += formatExact(v) + ",";
    post_rows += formatExact(post.tau[i]) + "\n";
  }
  const std::string post_hash = hexId(calib::fnv1a64(post_rows));
  nlohmann::json fp{{"format", 1},
                    {"assembly", assembly.id},
                    {"label", assembly.label()},
                    {"names", names},
                    {"posterior_values_fnv1a64", post_hash},
                    {"draws", M},
                    {"roads_per_draw", R},
                    {"road_library", L},
                    {"block", B},
                    {"seed", seed},
                    {"streams", {hexId(kSynthDrawStream), hexId(kSynthRoadStream), hexId(kSynthNoiseStream), hexId(kRoadLibraryStream)}},
                    {"scenario", sc.toJson()},
                    {"simulation", study.simulation.toJson()},
                    {"channel", opt.channel},
                    {"window", {kb, ke}},
                    {"noise", noisy},
                    {"track_fourth_moment", opt.track_fourth_moment},
                    {"branched", branched},
                    {"run_values", base}};
  const std::string fingerprint = hexId(calib::fnv1a64(fp.dump()));

  if (root) fs::create_directories(out_dir);
  const fs::path dir(out_dir);
  const fs::path moments_path = dir / "moments.bin", info_path = dir / "synthesis.json", ckpt_path = dir / "checkpoint.json";

  SynthesisResult res;
  res.assembly = assembly.id;
  res.fingerprint = fingerprint;
  res.times_s = times;
  res.draws = M;
  res.roads_per_draw = R;
  res.road_library = L;
  res.block = B;
  res.simulations = M * R;

  // Resume decisions are taken on what the root reads (the same bytes on every MPI rank).
  auto rootRead = [&](const fs::path& path) {
    return onRoot([&]() -> std::string { return fs::exists(path) ? "F" + readFileBytes(path.string()) : std::string(); });
  };
  auto parseJson = [](const std::string& text) {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(text.begin() + 1, text.end());
    } catch (const std::exception&) {
      return nlohmann::json();  // written atomically: a foreign file
    }
    return j;
  };
  auto refuse = [&](const fs::path& path) {
    throw InputError(path.string(), "was made by a different synthesis (study, posterior, assembly, sizes, seed, window or "
                                    "options changed); use a new --out folder or delete it to start over");
  };

  // A finished synthesis: reuse it.
  if (const std::string info_text = rootRead(info_path); !info_text.empty()) {
    const nlohmann::json j = parseJson(info_text);
    if (!j.is_object() || j.value("fingerprint", "") != fingerprint) refuse(info_path);
    if (onRoot([&] { return std::string(fs::exists(moments_path) ? "1" : "0"); }) == "1") {
      res.moments = MomentAccumulator::load(moments_path.string());
      res.info = j;
      res.reused = true;
      res.failures = j.at("failures").get<long>();
      for (const auto& f : j.at("failure_list")) res.failure_list.push_back(failureFrom(f));
      res.cost_s_per_s = j.at("cost").at("wall_s_per_simulated_s_median").get<double>();
      res.median_run_wall_s = j.at("cost").at("run_wall_s_median").get<double>();
      res.wall_s = std::chrono::duration<double>(Clock::now() - t_all).count();
      if (progress) progress(static_cast<std::size_t>(M), static_cast<std::size_t>(M));
      return res;
    }
  }

  // State of the ordered reduction (guarded by reduce_m once the workers run).
  MomentOptions mo;
  mo.track_fourth_moment = opt.track_fourth_moment;
  MomentAccumulator acc(static_cast<int>(p), mo);
  long next_block = 0;
  std::vector<SynthesisFailure> failures;
  std::vector<double> costs, run_walls;
  double previous_wall = 0.0;  // wall time of earlier (interrupted) invocations
  std::string ckpt_file;       // current checkpoint_<block>.bin
  if (const std::string ckpt_text = rootRead(ckpt_path); !ckpt_text.empty()) {
    const nlohmann::json j = parseJson(ckpt_text);
    if (!j.is_object() || j.value("fingerprint", "") != fingerprint) refuse(ckpt_path);
    ckpt_file = j.at("moments").get<std::string>();
    acc = MomentAccumulator::load((dir / ckpt_file).string());
    if (acc.count() != j.at("vectors").get<std::int64_t>() || acc.dimension() != static_cast<int>(p))
      throw InputError(ckpt_path.string(), "does not match " + ckpt_file + "; delete the folder to start over");
    next_block = j.at("next_block").get<long>();
    for (const auto& f : j.at("failure_list")) failures.push_back(failureFrom(f));
    costs = j.at("cost_samples").get<std::vector<double>>();
    run_walls = j.at("run_wall_samples").get<std::vector<double>>();
    previous_wall = j.at("wall_s").get<double>();
  }
  const long n_blocks = (M + B - 1) / B;
  res.resumed_blocks = next_block;
  const long first_draw = std::min(M, next_block * B);

  auto writeCheckpoint = [&](double wall_so_far) {
    if (!root) return;
    const std::string file = "checkpoint_" + std::to_string(next_block) + ".bin";
    acc.save((dir / file).string());
    nlohmann::json j{{"fingerprint", fingerprint},
                     {"assembly", assembly.id},
                     {"next_block", next_block},
                     {"blocks", n_blocks},
                     {"moments", file},
                     {"vectors", acc.count()},
                     {"failure_list", nlohmann::json::array()},
                     {"cost_samples", costs},
                     {"run_wall_samples", run_walls},
                     {"wall_s", wall_so_far}};
    for (const auto& f : failures) j["failure_list"].push_back(failureJson(f));
    writeFileAtomic(ckpt_path.string(), j.dump() + "\n");
    if (!ckpt_file.empty() && ckpt_file != file) fs::remove(dir / ckpt_file);
    ckpt_file = file;
  };

  // ---- the parallel loop over the remaining draws, reduced in block order
  const long todo = M - first_draw;
  const int ranks = Distributed::instance().size();
  const int workers = distributedWorkers(static_cast<std::size_t>(std::max<long>(todo, 1)), opt.threads);
  std::vector<std::unique_ptr<Simulator>> sims(static_cast<std::size_t>(workers));
  std::mutex state_m, reduce_m, progress_m;
  std::map<long, PendingBlock> pending;  // guarded by state_m
  std::size_t done = static_cast<std::size_t>(first_draw);
  auto last_ckpt = Clock::now();
  const auto t_run = Clock::now();
  if (progress) progress(done, static_cast<std::size_t>(M));

  auto blockSize = [&](long b) { return std::min(B, M - b * B); };
  // Draw j on worker w: R runs, their windows plus noise, failures and costs.
  auto simulateDraw = [&](long j, int w) {
    auto& sim = sims[static_cast<std::size_t>(w)];
    if (!sim) sim = std::make_unique<Simulator>(model, study.simulation);
    DrawOutput out;
    out.vectors.resize(static_cast<std::size_t>(R));
    // θ_j, τ_j: a row of the posterior sample.
    RandomStream draw_rs(seed, kSynthDrawStream, static_cast<std::uint64_t>(j));
    const std::size_t row = std::min(post.size() - 1, static_cast<std::size_t>(draw_rs.uniform() * static_cast<double>(post.size())));
    std::vector<double> values = base;
    for (std::size_t k = 0; k < slots.size(); ++k) values[static_cast<std::size_t>(slots[k])] = post.theta[row][k];
    const double sigma = 1.0 / std::sqrt(post.tau[row]);
    // R distinct library roads.
    RandomStream road_rs(seed, kSynthRoadStream, static_cast<std::uint64_t>(j));
    std::vector<long> idx;
    while (static_cast<long>(idx.size()) < R) {
      const long i = std::min(L - 1, static_cast<long>(road_rs.uniform() * static_cast<double>(L)));
      if (std::find(idx.begin(), idx.end(), i) == idx.end()) idx.push_back(i);
    }
    std::vector<std::shared_ptr<const Road>> roads;
    std::vector<const Road*> ptrs;
    std::vector<std::uint64_t> road_seeds;
    for (long i : idx) {
      road_seeds.push_back(librarySeed(seed, static_cast<std::uint64_t>(i)));
      roads.push_back(makeRoad(sc, model->vehicle(), road_seeds.back()));
      ptrs.push_back(roads.back().get());
    }
    std::vector<RunResult> runs;
    std::string input_error;
    try {
      if (branched) {
        runs = sim->runBranched(values, ptrs, sc);
      } else {
        for (const Road* r : ptrs) runs.push_back(sim->run(values, *r, sc));
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
      const auto& col = run.trace.column(opt.channel);
      if (col.size() <= ke) {
        fail("the run ended before the window");
        continue;
      }
      std::vector<double> v(p);
      RandomStream noise(seed, kSynthNoiseStream, static_cast<std::uint64_t>(j * R + r));
      bool finite = true;
      for (std::size_t k = 0; k < p; ++k) {
        v[k] = col[kb + k] + (noisy ? sigma * noise.normal() : 0.0);
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
  };

  // Adds one complete block to the accumulator (vectors in (draw, road) order).
  auto addBlockToAcc = [&](PendingBlock& blk) {
    long cols = 0;
    for (const auto& d : blk.draws)
      for (const auto& v : d.vectors) cols += v.empty() ? 0 : 1;
    if (cols > 0) {
      Eigen::MatrixXd X(static_cast<Eigen::Index>(p), cols);
      Eigen::Index c = 0;
      for (const auto& d : blk.draws)
        for (const auto& v : d.vectors)
          if (!v.empty()) X.col(c++) = Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(p));
      acc.addBlock(X);
    }
    for (auto& d : blk.draws) {
      failures.insert(failures.end(), d.failures.begin(), d.failures.end());
      costs.insert(costs.end(), d.cost.begin(), d.cost.end());
      run_walls.insert(run_walls.end(), d.run_wall.begin(), d.run_wall.end());
    }
  };

  // Adds every finished block that is next in order (one reducer at a time; a finished block
  // whose predecessor is still running waits in `pending`).
  auto reduce = [&]() {
    while (true) {
      std::unique_lock<std::mutex> rl(reduce_m, std::try_to_lock);
      if (!rl.owns_lock()) return;
      while (true) {
        PendingBlock blk;
        {
          std::lock_guard<std::mutex> sl(state_m);
          auto it = pending.find(next_block);
          if (it == pending.end() || it->second.remaining > 0) break;
          blk = std::move(it->second);
          pending.erase(it);
        }
        addBlockToAcc(blk);
        ++next_block;
        const auto now = Clock::now();
        if (next_block < n_blocks && std::chrono::duration<double>(now - last_ckpt).count() >= opt.checkpoint_interval_s) {
          writeCheckpoint(previous_wall + std::chrono::duration<double>(now - t_run).count());
          last_ckpt = Clock::now();
        }
      }
      rl.unlock();
      std::lock_guard<std::mutex> sl(state_m);  // a block finished while we were releasing?
      auto it = pending.find(next_block);
      if (it == pending.end() || it->second.remaining > 0) return;
    }
  };

  if (ranks == 1) {
    // One process: draws on the threads, each finished block added as soon as its predecessors are.
    parallelFor(static_cast<std::size_t>(todo), opt.threads, [&](std::size_t task, int w) {
      const long j = first_draw + static_cast<long>(task);
      DrawOutput out = simulateDraw(j, w);
      {
        std::lock_guard<std::mutex> sl(state_m);
        const long b = j / B;
        auto& blk = pending[b];
        if (blk.draws.empty()) {
          blk.draws.resize(static_cast<std::size_t>(blockSize(b)));
          blk.remaining = blockSize(b);
        }
        blk.draws[static_cast<std::size_t>(j - b * B)] = std::move(out);
        --blk.remaining;
      }
      reduce();
      if (progress) {
        std::lock_guard<std::mutex> pl(progress_m);
        progress(++done, static_cast<std::size_t>(M));
      }
    });
    reduce();
  } else {
    // Several MPI ranks: rounds of whole blocks. The draws of a round are spread over the ranks
    // (draw j0 + t on rank t % size); every rank receives every draw's vectors and adds the
    // blocks in block order with the same addBlock calls as one process: the same moments,
    // bit for bit. A round holds about 8 draws per worker, at most ~256 MB of vectors.
    const long per_round_mem = std::max<long>(1, static_cast<long>(256e6 / (8.0 * static_cast<double>(R) * static_cast<double>(p))));
    const long per_round = std::min<long>(8L * ranks * workers, per_round_mem);
    const long blocks_per_round = std::max<long>(1, per_round / B);
    while (next_block < n_blocks) {
      const long b0 = next_block, b1 = std::min(n_blocks, b0 + blocks_per_round);
      const long j0 = b0 * B, j1 = std::min(M, b1 * B);
      const auto packed = distributedMap(
          static_cast<std::size_t>(j1 - j0), opt.threads,
          [&](std::size_t t, int w) { return packDraw(simulateDraw(j0 + static_cast<long>(t), w)); },
          [&](std::size_t d, std::size_t) {
            if (progress) progress(static_cast<std::size_t>(j0) + d, static_cast<std::size_t>(M));
          });
      for (long b = b0; b < b1; ++b) {
        PendingBlock blk;
        for (long j = b * B; j < std::min(M, (b + 1) * B); ++j) blk.draws.push_back(unpackDraw(packed[static_cast<std::size_t>(j - j0)]));
        addBlockToAcc(blk);
        ++next_block;
      }
      onRoot([&]() -> std::string {
        const auto now = Clock::now();
        if (next_block < n_blocks && std::chrono::duration<double>(now - last_ckpt).count() >= opt.checkpoint_interval_s) {
          writeCheckpoint(previous_wall + std::chrono::duration<double>(now - t_run).count());
          last_ckpt = Clock::now();
        }
        return std::string();
      });
    }
  }
  DTWIN_CHECK(next_block == n_blocks, "blocks left unreduced");

  // ---- results
  const double wall_total = previous_wall + std::chrono::duration<double>(Clock::now() - t_run).count();
  res.failures = static_cast<long>(failures.size());
  res.failure_list = failures;
  res.cost_s_per_s = median(costs);
  res.median_run_wall_s = median(run_walls);
  nlohmann::json j;
  j["program"] = programInfo();
  j["command"] = opt.command;
  j["created_utc"] = utcNow();
  j["study"] = study.path;
  j["assembly"] = assembly.id;
  j["label"] = assembly.label();
  j["posterior"] = {{"path", post.path}, {"rows", post.size()}, {"parameters", names}, {"values_fnv1a64", post_hash},
                    {"file_fnv1a64", post_text.empty() ? std::string() : hexId(calib::fnv1a64(post_text))}};
  j["draws"] = M;
  j["roads_per_draw"] = R;
  j["road_library"] = L;
  j["block"] = B;
  j["simulations"] = M * R;
  j["vectors"] = acc.count();
  j["failures"] = res.failures;
  j["failure_list"] = nlohmann::json::array();
  for (std::size_t i = 0; i < failures.size() && i < 1000; ++i) j["failure_list"].push_back(failureJson(failures[i]));
  if (failures.size() > 1000) j["failure_list_truncated"] = true;
  j["seed"] = seed;
  j["streams"] = {
      {"draw", {{"constant", hexId(kSynthDrawStream)},
                {"rule", "draw j uses posterior row floor(u * rows), u the first uniform of RandomStream(seed, draw, j)"}}},
      {"road", {{"constant", hexId(kSynthRoadStream)},
                {"rule", "draw j's library indices: floor(u * library) from RandomStream(seed, road, j), redrawn while one repeats"}}},
      {"road_library", {{"constant", hexId(kRoadLibraryStream)},
                        {"rule", "library road i has seed RandomStream(seed, road_library, i).bits() >> 11 (not the field data's stream)"}}},
      {"noise", {{"constant", hexId(kSynthNoiseStream)},
                 {"rule", "vector (j, r) adds sigma_j * N(0, 1) from RandomStream(seed, noise, j * roads_per_draw + r) in time order"}}}};
  j["noise"] = {{"applied", noisy},
                {"rule", noisy ? "N(0, 1/tau_j) per value, tau_j from the posterior row of draw j"
                               : "none: the channel is not in N (as twin generate field)"}};
  j["scenario"] = sc.toJson();
  j["simulation"] = study.simulation.toJson();
  j["branched"] = branched;
  if (branched) j["branch_time_s"] = t_branch;
  j["channel"] = opt.channel;
  j["unit"] = unit;
  j["window_s"] = {times.front(), times.back()};
  j["samples"] = p;
  j["output_rate_hz"] = rate;
  j["moments"] = {{"file", "moments.bin"},
                  {"format", "MomentAccumulator::save: 8-byte tag DTWMOM01, then doubles (little-endian): magic, version, p, n, "
                             "track flag, mean (p), packed upper triangle of M2 column by column (p(p+1)/2), [T (p), Q]"},
                  {"dimension", p},
                  {"count", acc.count()},
                  {"track_fourth_moment", opt.track_fourth_moment},
                  {"accumulation", "fixed blocks of `block` draws, addBlock in (draw, road) order, blocks added in block order"}};
  j["cost"] = {{"wall_s_per_simulated_s_median", res.cost_s_per_s},
               {"run_wall_s_median", res.median_run_wall_s},
               {"runs_measured", costs.size()},
               {"rule", std::string("median over the successful runs of wall time / simulated time") +
                            (branched ? "; a branched run carries an even share of its draw's common smooth part" : "")}};
  j["wall_s"] = wall_total;
  j["resumed_blocks"] = res.resumed_blocks;
  j["threads"] = workers;
  j["ranks"] = ranks;
  j["fingerprint"] = fingerprint;
  onRoot([&]() -> std::string {  // only the root writes; its error reaches every rank
    acc.save(moments_path.string());
    writeFileAtomic(info_path.string(), j.dump(2) + "\n");
    // The checkpoint is no longer needed.
    std::error_code ec;
    fs::remove(ckpt_path, ec);
    if (!ckpt_file.empty()) fs::remove(dir / ckpt_file, ec);
    return std::string();
  });
  res.info = std::move(j);
  res.moments = std::move(acc);
  res.wall_s = std::chrono::duration<double>(Clock::now() - t_all).count();
  return res;
}

}  // namespace dtwin::classify
