#include "study/generate.hpp"

#include <unistd.h>

#include <filesystem>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>

#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/names.hpp"
#include "common/parallel.hpp"
#include "common/validate.hpp"
#include "io/provenance.hpp"
#include "subsystems/effect.hpp"
#include "subsystems/random.hpp"
#include "twin/simulator.hpp"

namespace dtwin {

namespace fs = std::filesystem;
namespace {

double noiseVariance(const Study& study, const std::optional<double>& override_value) {
  const double v = override_value.value_or(study.noise_variance_N2);
  if (!(std::isfinite(v) && v >= 0))
    throw InputError("noise variance",
                     "must be a finite number >= 0 [N^2], got " + std::to_string(v));
  return v;
}

/// A channel of the study's runs (the twin's and its [sensors]').
Channel channelInfo(const Study& study, const std::string& name, const std::string& where) {
  const std::vector<Channel> known = measurableChannels(study.sensors);
  const std::string rule = checkChannelName(name, known);
  if (!rule.empty()) throw InputError(where, rule);
  for (const auto& c : known)
    if (c.name == name) return c;
  DTWIN_CHECK(false, "channel " + name);
  return known.front();
}

/// The calibrated parameters with the values a model uses (truths where the study gives them).
nlohmann::json truthJson(const Study& study, const Model& model) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& c : study.calibrated) {
    if (!model.table().contains(c.name)) continue;
    const auto& e = model.table().at(c.name);
    j[c.name] = {{"value", e.value},
                 {"unit", e.spec.unit},
                 {"source", e.source},
                 {"truth_given", c.truth.has_value()}};
  }
  return j;
}

/// Validates the hidden effects' names (errors name the options field `where`, e.g.
/// "lab.hidden_effects") and builds the model with them.
std::shared_ptr<const Model> modelWithHidden(const Study& study, const AssemblySpec& assembly,
                                             const std::vector<EffectSetting>& hidden,
                                             const std::string& where) {
  for (std::size_t i = 0; i < hidden.size(); ++i) {
    const auto& e = hidden[i];
    study.effectCatalog().make(e.name, where);
    for (std::size_t j = 0; j < i; ++j)
      if (hidden[j].name == e.name) throw InputError(where, "effect " + e.name + " given twice");
    for (const auto& v : e.values)
      if (v.name.rfind(e.name + ".", 0) != 0)
        throw InputError(where, "parameter '" + v.name + "' does not belong to effect " + e.name);
  }
  return study.makeModel(assembly, hidden);
}

/// Grid indices k in [t0, t1] (inclusive, 1e-6 sample tolerance) that are multiples of `step`.
std::vector<std::size_t> windowRows(double t0, double t1, double rate, std::size_t step) {
  const double k0 = std::ceil(t0 * rate - 1e-6), k1 = std::floor(t1 * rate + 1e-6);
  std::vector<std::size_t> rows;
  if (k1 < k0) return rows;
  auto k = static_cast<std::size_t>(std::max(0.0, k0));
  k = (k + step - 1) / step * step;
  for (; static_cast<double>(k) <= k1; k += step) rows.push_back(k);
  return rows;
}

}  // namespace

nlohmann::json hiddenEffectsJson(const Model& model, const std::vector<EffectSetting>& hidden) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& h : hidden) {
    const auto& names = model.assembly().effects;
    const auto it = std::find(names.begin(), names.end(), h.name);
    DTWIN_CHECK(it != names.end(), "hidden effect " + h.name + " not installed");
    const auto& effect = *model.effects()[static_cast<std::size_t>(it - names.begin())];
    nlohmann::json params = nlohmann::json::object(), given = nlohmann::json::array();
    for (const auto& ps : effect.parameters())
      params[ps.name] = model.table().value(h.name + "." + ps.name);
    for (const auto& v : h.values) given.push_back(v.name.substr(h.name.size() + 1));
    out.push_back({{"name", h.name}, {"parameters", params}, {"given", given}});
  }
  return out;
}

std::string hiddenEffectsSummary(const nlohmann::json& hidden, const EffectCatalog& catalog) {
  std::string s;
  for (const auto& h : hidden) {
    const std::string name = h["name"].get<std::string>();
    const auto effect = catalog.make(name, "hidden effect");
    std::string p;
    for (const auto& [k, v] : h["parameters"].items()) {
      p += (p.empty() ? "" : ", ") + k + "=" + formatExact(v.get<double>());
      for (const auto& ps : effect->parameters())
        if (ps.name == k && ps.unit != "1") p += " " + ps.unit;
    }
    s += (s.empty() ? "" : "; ") + name + " (" + p + ")";
  }
  return s;
}

std::uint64_t fieldRoadSeed(std::uint64_t seed, std::size_t run) {
  DTWIN_CHECK(run >= 1, "runs are numbered from 1");
  // 53 bits: exact as a double (MATLAB's readmatrix, pandas with NaNs) and as a signed 64-bit
  // integer (`twin simulate --seed`).
  return RandomStream(seed, kFieldRoadStream, run - 1).bits() >> 11;
}

double obstacleTime(const ScenarioSpec& s) { return s.road->featureTime_s(); }

std::vector<double> automaticLabTimes(const Trace& tr, const std::string& channel,
                                      double obstacle_time_s, std::size_t count,
                                      double min_separation_s) {
  const auto& t = tr.column("time_s");
  const auto& x = tr.column(channel);
  if (x.empty() || count == 0) return {};
  const double static_value = x.front();
  // Runs of equal values (a flat run is one extremum at most, placed at its middle sample).
  struct Run {
    std::size_t lo, hi;
  };
  std::vector<Run> runs;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!runs.empty() && x[k] == x[runs.back().hi])
      runs.back().hi = k;
    else
      runs.push_back({k, k});
  }
  struct Candidate {
    std::size_t k;
    double score;
  };
  std::vector<Candidate> cand;
  for (std::size_t j = 1; j + 1 < runs.size(); ++j) {
    const double v = x[runs[j].lo], before = x[runs[j - 1].lo], after = x[runs[j + 1].lo];
    const bool extremum = (v > before && v > after) || (v < before && v < after);
    const std::size_t mid = (runs[j].lo + runs[j].hi) / 2;
    if (extremum && t[mid] >= obstacle_time_s - 1e-12)
      cand.push_back({mid, std::abs(v - static_value)});
  }
  std::stable_sort(cand.begin(), cand.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  std::vector<double> kept;
  for (const auto& c : cand) {
    if (kept.size() >= count) break;
    bool far = true;
    for (double tk : kept) far = far && std::abs(t[c.k] - tk) >= min_separation_s - 1e-9;
    if (far) kept.push_back(t[c.k]);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

std::uint64_t labNoiseStream(const std::string& scenario) {
  return kLabNoiseStream ^ fnv1a64(scenario);
}

// About 150 lines, kept whole on purpose: the checks of the options (each naming its field), the
// one run, the noise draws in record order and the sidecar form one straight sequence whose
// order fixes the random streams; split into pieces it would pass a dozen locals between them.
namespace {

/// Which samples of the lab run are kept when every sample is (times mode all): the window and
/// the kept rate, checked; empty rows otherwise.
struct LabSampling {
  bool all_times = false;
  double w0 = 0.0, w1 = 0.0, rate = 0.0, keep_rate = 0.0;
  std::size_t step = 1;
  std::vector<std::size_t> rows;
};

LabSampling labSampling(const Study& study, const ScenarioSpec& sc, const LabOptions& opt,
                        const OptionCheck& check) {
  LabSampling s;
  s.rate = s.keep_rate = study.simulation.output_rate_hz;
  s.w1 = sc.duration_s;
  s.all_times = opt.times_mode == LabTimesMode::All;
  check.require(s.all_times || !opt.window, "window", "needs every sample kept (times mode all)");
  check.require(s.all_times || !opt.rate_hz, "rate_hz", "needs every sample kept (times mode all)");
  if (!s.all_times) return s;
  if (opt.window) {
    s.w0 = opt.window->first;
    s.w1 = opt.window->second;
    if (!(std::isfinite(s.w0) && std::isfinite(s.w1) && s.w0 < s.w1))
      throw InputError(check.where("window"), "expects T0,T1 with T0 < T1, got " +
                                                  formatExact(s.w0) + "," + formatExact(s.w1));
    if (s.w0 < 0 || s.w1 > sc.duration_s + 1e-9)
      throw InputError(check.where("window"), formatExact(s.w0) + " .. " + formatExact(s.w1) +
                                                  " s lies outside the scenario '" + sc.name +
                                                  "' (0 .. " + formatExact(sc.duration_s) + " s)");
  }
  if (opt.rate_hz) {
    s.keep_rate = *opt.rate_hz;
    const double q = s.rate / s.keep_rate;
    if (!(std::isfinite(s.keep_rate) && s.keep_rate > 0) || !(q >= 1 - 1e-9) ||
        std::abs(q - std::round(q)) > 1e-9 * q)
      throw InputError(check.where("rate_hz"),
                       "must divide the output rate " + formatExact(s.rate) +
                           " Hz into an integer step (e.g. " + formatExact(s.rate / 2) + ", " +
                           formatExact(s.rate / 5) + ", " + formatExact(s.rate / 10) +
                           " Hz), got " + formatExact(s.keep_rate) + " Hz");
    s.step = static_cast<std::size_t>(std::llround(q));
  }
  s.rows = windowRows(s.w0, s.w1, s.rate, s.step);
  if (s.rows.empty())
    throw InputError(check.where("window"), "no output sample at " + formatExact(s.keep_rate) +
                                                " Hz in " + formatExact(s.w0) + " .. " +
                                                formatExact(s.w1) + " s");
  return s;
}

/// The lab channels, each once.
std::vector<Channel> labChannels(const Study& study, const LabOptions& opt,
                                 const std::vector<std::string>& names, const OptionCheck& check) {
  std::vector<Channel> channels;
  for (const auto& n : names) {
    channels.push_back(channelInfo(
        study, n, opt.channels.empty() ? study.path + ": lab.channels" : check.where("channels")));
    for (std::size_t i = 0; i + 1 < channels.size(); ++i)
      if (channels[i].name == n)
        throw InputError(check.where("channels"), "channel '" + n + "' listed twice");
  }
  return channels;
}

/// The model that makes the data: the hidden effects installed, the hidden vehicle values set.
std::shared_ptr<const Model> labModel(const Study& study, const AssemblySpec& assembly,
                                      const LabOptions& opt, const OptionCheck& check) {
  auto model = modelWithHidden(study, assembly, opt.hidden_effects, check.where("hidden_effects"));
  if (opt.hidden_values.empty()) return model;
  const auto& freeable = freeableVehicleParameters();
  for (const auto& v : opt.hidden_values)
    if (std::find(freeable.begin(), freeable.end(), v.name) == freeable.end() &&
        !parseCornerFactor(v.name)) {
      if (const std::string rule = cornerFactorRule(v.name); !rule.empty())
        throw InputError(check.where("hidden_values"), rule);
      throw InputError(
          check.where("hidden_values"),
          unknownNameRule("vehicle value that can be changed (or a per-corner factor VALUE@PLACE)",
                          v.name, freeable));
    }
  return study.makeModel(assembly, opt.hidden_effects, opt.hidden_values);
}

/// The hidden sensor models, checked.
SensorDistortion hiddenDistortion(const LabOptions& opt, const OptionCheck& check) {
  SensorDistortion distortion;
  for (const auto& [kind, value] : opt.hidden_sensor) {
    const ParameterSpec p = sensorModelParameter(kind, check.where("hidden_sensor"));
    const std::string rule = checkParameterValue(p, value);
    if (!rule.empty())
      throw InputError(check.where("hidden_sensor"), kind + "." + p.name + " " + rule);
    distortion.set(kind, value);
  }
  return distortion;
}

/// The lab times (res.times_s, res.times_rule) with their provenance, and the trace rows they are.
nlohmann::json chooseLabTimes(const Study& study, const ScenarioSpec& sc, const Trace& trace,
                              const std::string& first_channel, const LabSampling& s,
                              LabResult& res, std::vector<std::size_t>& rows) {
  nlohmann::json times_json;
  rows = s.rows;
  if (s.all_times) {
    for (std::size_t r : rows) res.times_s.push_back(trace.column("time_s").at(r));
    res.times_rule = "all samples in [" + formatExact(s.w0) + "," + formatExact(s.w1) + "] at " +
                     formatExact(s.keep_rate) + " Hz";
    return {{"source", "all"},
            {"rule", res.times_rule + ": the noise-free " + formatExact(s.rate) +
                         " Hz output samples k (time k / " + formatExact(s.rate) +
                         " s) in the window with k a multiple of " + std::to_string(s.step)},
            {"window_s", {s.w0, s.w1}},
            {"rate_hz", s.keep_rate},
            {"output_rate_hz", s.rate},
            {"step", s.step},
            {"count", rows.size()}};
  }
  const double t_obstacle = obstacleTime(sc);
  if (!study.lab.times_s.empty()) {
    res.times_s = study.lab.times_s;
    res.times_rule = "explicit: [lab] times_s of " + study.path;
    times_json = {{"source", "explicit"}, {"rule", res.times_rule}};
  } else {
    res.times_s = automaticLabTimes(trace, first_channel, t_obstacle,
                                    static_cast<std::size_t>(study.lab.auto_times),
                                    study.lab.min_separation_s);
    if (res.times_s.empty())
      throw InputError(study.path + ": lab", "no local extremum of " + first_channel +
                                                 " at or after t = " + formatExact(t_obstacle) +
                                                 " s in scenario '" + sc.name +
                                                 "'; give the times with [lab] times_s");
    res.times_rule = formatPrintf(
        "automatic: local extrema (sign changes of the discrete derivative; a flat run counts "
        "once, at its middle "
        "sample) of the noise-free %s at or after the obstacle time %g s, ranked by |value - "
        "static value at t = 0|, "
        "the %ld largest at least %g s apart, in time order, on the %g Hz output grid",
        first_channel.c_str(), t_obstacle, study.lab.auto_times, study.lab.min_separation_s,
        s.rate);
    times_json = {{"source", "automatic"},
                  {"rule", res.times_rule},
                  {"channel", first_channel},
                  {"obstacle_time_s", t_obstacle},
                  {"requested", study.lab.auto_times},
                  {"found", res.times_s.size()},
                  {"min_separation_s", study.lab.min_separation_s},
                  {"static_value", trace.column(first_channel).front()}};
  }
  for (std::size_t i = 0; i < res.times_s.size(); ++i)
    rows.push_back(gridIndex(res.times_s[i], s.rate, sc.duration_s,
                             study.path + ": lab.times_s[" + std::to_string(i) + "]"));
  return times_json;
}

/// The noise record of the lab file's provenance.
nlohmann::json labNoiseJson(const std::vector<Channel>& channels, double variance,
                            std::uint64_t seed, const std::string& scenario) {
  std::vector<std::string> noisy, clean;
  for (const auto& c : channels) (c.unit == "N" ? noisy : clean).push_back(c.name);
  return {
      {"distribution", "independent normal N(0, variance) added to every value of a channel in N"},
      {"variance_N2", variance},
      {"sigma_N", std::sqrt(variance)},
      {"applied_to", noisy},
      {"not_applied_to", clean},
      {"seed", seed},
      {"stream", hexId(labNoiseStream(scenario))},
      {"rule",
       "repetition r draws from RandomStream(seed, stream, r - 1) (mt19937_64 seeded by "
       "SplitMix64, "
       "Box-Muller), in the order of the channels, then of the times; stream = " +
           hexId(kLabNoiseStream) +
           " xor FNV-1a 64 of the scenario name (files of two scenarios made with one seed have "
           "independent noise)"}};
}

}  // namespace

LabResult generateLab(const Study& study, const AssemblySpec& assembly, const LabOptions& opt,
                      const ProgressFn& progress) {
  const OptionCheck check("lab");
  const ScenarioSpec& sc = study.scenario(opt.scenario);
  const long reps = opt.repetitions > 0 ? opt.repetitions : study.sizes.at("lab_repetitions");
  const std::uint64_t seed = opt.seed.value_or(study.seed);
  const double variance = noiseVariance(study, opt.noise_variance_N2);
  const double sigma = std::sqrt(variance);
  const std::vector<std::string> names =
      opt.channels.empty() ? study.lab.channelsOrDefault() : opt.channels;
  const std::vector<Channel> channels = labChannels(study, opt, names, check);
  const LabSampling sampling = labSampling(study, sc, opt, check);
  const auto model = labModel(study, assembly, opt, check);
  const SensorDistortion distortion = hiddenDistortion(opt, check);

  auto road = makeRoad(sc, model->vehicle(), seed);
  Simulator sim(model, study.simulation);
  const auto values = model->defaultRunValues();
  if (progress) progress(0, 1);
  RunResult run = sim.run(values, *road, sc);
  if (!run.stats.ok)
    throw RunFailedError("lab run of " + assembly.id + " over scenario '" + sc.name + "' (seed " +
                             std::to_string(seed) + ") failed: " + run.stats.message,
                         0, seed);
  if (progress) progress(1, 1);
  if (!distortion.identity()) {
    const auto& t = run.trace.column("time_s");
    for (const auto& c : channels) {
      const auto i = static_cast<std::size_t>(run.trace.index(c.name));
      run.trace.column(i) = distortChannel(run.trace.column(i), sampling.rate, t, distortion);
    }
  }

  LabResult res;
  std::vector<std::size_t> rows;
  const nlohmann::json times_json =
      chooseLabTimes(study, sc, run.trace, names.front(), sampling, res, rows);
  for (std::size_t r : rows) DTWIN_CHECK(r < run.trace.rows(), "lab time beyond the trace");
  nlohmann::json noise_free = nlohmann::json::object();
  for (const auto& c : channels) {
    std::vector<double> v;
    v.reserve(rows.size());
    for (std::size_t r : rows) v.push_back(run.trace.column(c.name)[r]);
    noise_free[c.name] = v;
  }
  const auto& time_col = run.trace.column("time_s");
  for (long rep = 1; rep <= reps; ++rep) {
    RandomStream rs(seed, labNoiseStream(sc.name), static_cast<std::uint64_t>(rep - 1));
    for (const auto& c : channels) {
      const auto& col = run.trace.column(c.name);
      const bool noisy = c.unit == "N";
      for (std::size_t r : rows)
        res.data.records.push_back(
            {rep, time_col[r], c.name, col[r] + (noisy ? sigma * rs.normal() : 0.0)});
    }
  }
  validateLabData(res.data, "generated lab data", measurableChannels(study.sensors));

  nlohmann::json j = runRecord(study, *model, sc, road->describe(), seed, values, study.simulation,
                               run.stats, channels, opt.command);
  j["kind"] = "lab";
  j["format"] = "tidy CSV: repetition,time_s,channel,value (docs/data-files.md)";
  j["truth"] = truthJson(study, *model);
  if (!opt.hidden_effects.empty())
    j["hidden_effects"] = hiddenEffectsJson(*model, opt.hidden_effects);
  for (const auto& v : opt.hidden_values) j["hidden_values"][v.name] = v.value;
  for (const auto& [kind, value] : opt.hidden_sensor)
    j["hidden_sensor"][kind] = {{sensorModelParameter(kind, "").name, value},
                                {"applied_to", names}};
  j["noise"] = labNoiseJson(channels, variance, seed, sc.name);
  j["lab"] = {{"repetitions", reps},
              {"times_s", res.times_s},
              {"times", times_json},
              {"channels", nlohmann::json::array()},
              {"noise_free_values", noise_free}};
  for (const auto& c : channels)
    j["lab"]["channels"].push_back(
        {{"name", c.name}, {"unit", c.unit}, {"description", c.description}});
  res.provenance = std::move(j);
  res.noise_free = std::move(run.trace);
  return res;
}

FieldResult generateField(const Study& study, const AssemblySpec& assembly, const FieldOptions& opt,
                          const ProgressFn& progress) {
  const ScenarioSpec& sc = study.scenario(opt.scenario);
  const long n_runs = opt.runs > 0 ? opt.runs : study.sizes.at("field_runs");
  const std::uint64_t seed = opt.seed.value_or(study.seed);
  const double variance = noiseVariance(study, opt.noise_variance_N2);
  const double sigma = std::sqrt(variance);
  const Channel channel = channelInfo(study, opt.channel, "field channel");
  const bool noisy = channel.unit == "N";
  const double rate = study.simulation.output_rate_hz;
  if (!(opt.t_begin_s <= opt.t_end_s))
    throw InputError("field window", "needs begin <= end, got " + formatExact(opt.t_begin_s) +
                                         " .. " + formatExact(opt.t_end_s) + " s");
  const std::size_t kb = gridIndex(opt.t_begin_s, rate, sc.duration_s, "field window begin");
  const std::size_t ke = gridIndex(opt.t_end_s, rate, sc.duration_s, "field window end");

  auto model = modelWithHidden(study, assembly, opt.hidden_effects,
                               OptionCheck("field").where("hidden_effects"));
  const auto values = model->defaultRunValues();
  const std::size_t N = static_cast<std::size_t>(n_runs), T = ke - kb + 1;
  FieldData d;
  for (std::size_t k = kb; k <= ke; ++k)
    d.times_s.push_back(static_cast<double>(k) / rate);  // as the simulator's grid
  d.runs.resize(N);
  d.road_seeds.resize(N);
  d.values.assign(N * T, 0.0);
  struct Stats {
    long steps = 0;
    double wall_s = 0;
  };
  std::vector<Stats> stats(N);
  // Runs are spread over the MPI ranks (run i on rank i % size) and the threads of each rank;
  // every rank receives every run's window (common/distributed.hpp).
  const int workers = distributedWorkers(opt.processes, N, opt.threads);
  std::vector<std::unique_ptr<Simulator>> sims(static_cast<std::size_t>(workers));
  if (progress) progress(0, N);
  const auto t0 = std::chrono::steady_clock::now();

  const auto results = distributedMap(
      opt.processes, N, opt.threads,
      [&](std::size_t i, int w) {
        const std::size_t run_no = i + 1;
        const std::uint64_t road_seed = fieldRoadSeed(seed, run_no);
        auto road = makeRoad(sc, model->vehicle(), road_seed);
        auto& sim = sims[static_cast<std::size_t>(w)];
        if (!sim) sim = std::make_unique<Simulator>(model, study.simulation);
        RunResult r = sim->run(values, *road, sc);
        if (!r.stats.ok)
          throw RunFailedError(
              "field run " + std::to_string(run_no) + " of " + std::to_string(N) + " (road seed " +
                  std::to_string(road_seed) + ") failed: " + r.stats.message +
                  "; reproduce it with `twin simulate --assembly " + assembly.id + " --scenario " +
                  sc.name + " --seed " + std::to_string(road_seed) + "`",
              run_no, road_seed);
        const auto& col = r.trace.column(channel.name);
        DTWIN_CHECK(col.size() > ke, "field window beyond the trace");
        RandomStream rs(seed, kFieldNoiseStream, i);
        std::vector<double> v(T + 2);
        for (std::size_t k = 0; k < T; ++k)
          v[k] = col[kb + k] + (noisy ? sigma * rs.normal() : 0.0);
        v[T] = static_cast<double>(r.stats.steps);
        v[T + 1] = r.stats.wall_s;
        return v;
      },
      progress);
  for (std::size_t i = 0; i < N; ++i) {
    const auto& v = results[i];
    DTWIN_CHECK(v.size() == T + 2, "field run result has the wrong size");
    std::copy(v.begin(), v.begin() + static_cast<long>(T),
              d.values.begin() + static_cast<long>(i * T));
    d.runs[i] = static_cast<long>(i + 1);
    d.road_seeds[i] = fieldRoadSeed(seed, i + 1);
    stats[i] = {static_cast<long>(v[T]), v[T + 1]};
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  RunStats total;
  total.sim_s = sc.duration_s * static_cast<double>(N);
  total.wall_s = wall;
  for (const auto& s : stats) total.steps += s.steps;
  const nlohmann::json road_family{
      {"family", sc.toJson()["road"]},
      {"seed_rule",
       "road seed of run k = RandomStream(seed, " + hexId(kFieldRoadStream) +
           ", k - 1).bits() >> 11 (53 bits: exact as a double); `twin simulate --scenario " +
           sc.name + " --seed <road seed>` reproduces run k without noise"}};
  nlohmann::json j = runRecord(study, *model, sc, road_family, seed, values, study.simulation,
                               total, {channel}, opt.command);
  j["kind"] = "field";
  j["format"] = "CSV matrix: run,road_seed,t_<seconds>,... one row per run (docs/data-files.md)";
  j["truth"] = truthJson(study, *model);
  if (!opt.hidden_effects.empty())
    j["hidden_effects"] = hiddenEffectsJson(*model, opt.hidden_effects);
  j["noise"] = {{"distribution",
                 "independent normal N(0, variance) added to every value (channels in N only)"},
                {"variance_N2", variance},
                {"sigma_N", sigma},
                {"applied", noisy},
                {"seed", seed},
                {"stream", hexId(kFieldNoiseStream)},
                {"rule",
                 "run k draws from RandomStream(seed, stream, k - 1) (mt19937_64 seeded by "
                 "SplitMix64, Box-Muller), "
                 "one value per time in time order"}};
  j["field"] = {{"channel", channel.name},
                {"unit", channel.unit},
                {"window_s", {d.times_s.front(), d.times_s.back()}},
                {"samples_per_run", T},
                {"output_rate_hz", rate},
                {"runs", N},
                {"threads", workers},
                {"ranks", processCount(opt.processes)},
                {"per_run", nlohmann::json::array()}};
  for (std::size_t i = 0; i < N; ++i)
    j["field"]["per_run"].push_back({{"run", d.runs[i]},
                                     {"road_seed", d.road_seeds[i]},
                                     {"integrator_steps", stats[i].steps},
                                     {"wall_s", stats[i].wall_s}});
  j["stats"]["message"] =
      "totals over all runs; wall_s is the elapsed time of the whole parallel loop";
  return {std::move(d), std::move(j)};
}

namespace {

/// Rejects an output that is not a .csv file or whose folder cannot be made or written, before any
/// run.
void checkDataOut(const std::string& out) {
  const fs::path p(out);
  if (p.extension() != ".csv")
    throw InputError("generate.out", "must name a .csv file, got '" + out + "'");
  // The folder is made only when the data are written (writeFileAtomic); here its nearest existing
  // ancestor must be a folder we may write into, so that no run is wasted and nothing is created.
  fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  while (!fs::exists(dir) && dir.has_parent_path() && dir.parent_path() != dir)
    dir = dir.parent_path();
  if (!fs::exists(dir)) dir = ".";
  if (!fs::is_directory(dir) || ::access(dir.c_str(), W_OK) != 0)
    throw InputError("generate.out", "cannot write into folder '" + dir.string() + "'");
}

}  // namespace

LabResult generateLabFile(const Study& study, const AssemblySpec& assembly,
                          const LabOptions& options, const std::string& out,
                          const ProgressFn& progress) {
  rootWrites(options.processes, [&] { checkDataOut(out); });
  LabResult r = generateLab(study, assembly, options, progress);
  rootWrites(options.processes, [&] {
    writeLabCsv(out, r.data, measurableChannels(study.sensors));
    writeFileAtomic(sidecarPath(out), r.provenance.dump(2) + "\n");
  });
  return r;
}

FieldResult generateFieldFile(const Study& study, const AssemblySpec& assembly,
                              const FieldOptions& options, const std::string& out,
                              const ProgressFn& progress) {
  rootWrites(options.processes, [&] { checkDataOut(out); });
  FieldResult r = generateField(study, assembly, options, progress);
  rootWrites(options.processes, [&] {
    writeFieldCsv(out, r.data);
    writeFileAtomic(sidecarPath(out), r.provenance.dump(2) + "\n");
  });
  return r;
}

}  // namespace dtwin
