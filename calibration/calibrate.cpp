#include "calibration/calibrate.hpp"
#include "calibration/folder.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <tuple>

#include "calibration/correlated.hpp"
#include "calibration/design_journal.hpp"
#include "calibration/lhs.hpp"
#include "calibration/subspace_lm.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/errors.hpp"
#include "common/validate.hpp"
#include "common/distributed.hpp"
#include "common/parallel.hpp"
#include "io/provenance.hpp"

namespace fs = std::filesystem;

namespace dtwin::calib {

// ------------------------------------------------------------------ LabObjective
struct LabObjective::Pool {
  std::shared_ptr<const Model> model;
  SimulationOptions options;
  std::mutex m;
  std::vector<std::unique_ptr<Simulator>> free;
  std::atomic<long> failures{0}, evaluations{0};
  std::vector<double> walls;
  std::string first_failure;

  std::unique_ptr<Simulator> acquire() {
    {
      std::lock_guard<std::mutex> lock(m);
      if (!free.empty()) {
        auto s = std::move(free.back());
        free.pop_back();
        return s;
      }
    }
    return std::make_unique<Simulator>(model, options);
  }
  /// Gives a simulator back; `wall` (one evaluation's wall time) is recorded when given.
  void release(std::unique_ptr<Simulator> s, std::optional<double> wall) {
    std::lock_guard<std::mutex> lock(m);
    free.push_back(std::move(s));
    if (wall) walls.push_back(*wall);
  }
};

// ------------------------------------------------------------------ CalibrationSetup
nlohmann::json CalibrationSetup::toJson() const {
  nlohmann::json j = nlohmann::json::object();
  j["extra_effects"] = nlohmann::json::array();
  for (const auto& e : extra_effects) {
    nlohmann::json v = nlohmann::json::object();
    for (const auto& p : e.values) v[p.name] = p.value;
    j["extra_effects"].push_back({{"name", e.name}, {"values", v}});
  }
  j["extra_calibrated"] = nlohmann::json::array();
  for (const auto& c : extra_calibrated) {
    nlohmann::json e{{"name", c.name}, {"unit", c.unit}, {"lower", c.lower}, {"upper", c.upper}};
    if (c.truth) e["truth"] = *c.truth;
    j["extra_calibrated"].push_back(e);
  }
  j["channel_weights"] = nlohmann::json::object();
  for (const auto& [c, w] : channel_weights) j["channel_weights"][c] = w;
  // Written only when used: the fingerprint of every setup without them is as before.
  if (!freed.empty()) j["freed"] = freed;
  for (const auto& m : sensor_models)
    j["sensor_models"].push_back({{"name", m.name}, {"kind", m.kind}, {"channels", m.channels}});
  for (const auto& [sub, opt] : options) j["options"].push_back({{"subsystem", sub}, {"option", opt}});
  for (const auto& [name, b] : bounds) j["bounds"][name] = {b.first, b.second};
  return j;
}

CalibrationSetup CalibrationSetup::fromJson(const nlohmann::json& j) {
  CalibrationSetup s;
  if (j.is_null()) return s;
  for (const auto& e : j.at("extra_effects")) {
    EffectSetting es;
    es.name = e.at("name").get<std::string>();
    for (const auto& [k, v] : e.at("values").items()) {
      ParameterSetting ps;
      ps.name = k;
      ps.value = v.get<double>();
      ps.where = "setup";
      es.values.push_back(ps);
    }
    s.extra_effects.push_back(es);
  }
  for (const auto& e : j.at("extra_calibrated")) {
    CalibratedParameter c;
    c.name = e.at("name").get<std::string>();
    c.unit = e.value("unit", "");
    c.lower = e.at("lower").get<double>();
    c.upper = e.at("upper").get<double>();
    if (e.contains("truth")) c.truth = e.at("truth").get<double>();
    s.extra_calibrated.push_back(c);
  }
  for (const auto& [k, v] : j.at("channel_weights").items()) s.channel_weights[k] = v.get<double>();
  if (j.contains("freed")) s.freed = j.at("freed").get<std::vector<std::string>>();
  if (j.contains("sensor_models"))
    for (const auto& m : j.at("sensor_models"))
      s.sensor_models.push_back(
          {m.at("name").get<std::string>(), m.at("kind").get<std::string>(), m.at("channels").get<std::vector<std::string>>()});
  if (j.contains("options"))
    for (const auto& o : j.at("options")) s.options.push_back({o.at("subsystem").get<std::string>(), o.at("option").get<std::string>()});
  if (j.contains("bounds"))
    for (const auto& [k, v] : j.at("bounds").items()) s.bounds[k] = {v.at(0).get<double>(), v.at(1).get<double>()};
  return s;
}

// ------------------------------------------------------------------ LabObjective
LabObjective::LabObjective(const Study& study, const AssemblySpec& assembly, const LabData& data,
                           const std::string& scenario, const std::vector<EffectSetting>& extra_effects)
    : LabObjective(study, assembly, std::vector<DataSet>{DataSet{"lab data", scenario, data}}, [&] {
        CalibrationSetup s;
        s.extra_effects = extra_effects;
        return s;
      }()) {}

LabObjective::LabObjective(const Study& study, const AssemblySpec& assembly, const std::vector<DataSet>& data,
                           const CalibrationSetup& setup)
    : pool_(std::make_unique<Pool>()) {
  AssemblySpec spec = assembly;
  spec.freed.insert(spec.freed.end(), setup.freed.begin(), setup.freed.end());
  for (const auto& swap : setup.options) {  // (subsystem, option); no structured binding: a lambda captures it
    const std::string& sub = swap.first;
    const auto it = std::find_if(spec.options.begin(), spec.options.end(), [&](const auto& o) { return o.first == sub; });
    if (it == spec.options.end()) throw InputError("calibration setup", "assembly " + assembly.id + " has no subsystem '" + sub + "'");
    it->second = swap.second;
  }
  model_ = study.makeModel(spec, setup.extra_effects);
  if (study.calibrated.empty()) throw InputError(study.path + ": calibrated", "the study names no calibrated parameters");
  if (data.empty()) throw InputError("calibration", "no data sets given");
  const auto channels = Simulator::channels(model_->sensors());
  // A sensor model's parameter distorts the predictions (distort); it is no run parameter.
  auto sensorModelOf = [&](const std::string& name, const std::string& where) -> std::optional<SensorModelUse> {
    for (const auto& m : setup.sensor_models) {
      if (name != m.name + "." + sensorModelParameter(m.kind, where).name) continue;
      SensorModelUse use{m.kind, {}, names_.size()};
      for (const auto& ch : m.channels) {
        const auto it = std::find_if(channels.begin(), channels.end(), [&](const Channel& k) { return k.name == ch; });
        if (it == channels.end()) throw InputError(where, "sensor model " + m.name + ": unknown channel '" + ch + "'");
        use.columns.push_back(static_cast<int>(it - channels.begin()));
      }
      return use;
    }
    return std::nullopt;
  };
  auto add = [&](const CalibratedParameter& c, const std::string& where) {
    const auto sensor_model = sensorModelOf(c.name, where);
    if (!sensor_model && model_->lacksOptionParameter(c.name)) {  // e.g. tire.stiffness of an assembly whose road enters at the hub
      left_out_.push_back(c.name);
      return;
    }
    const int slot = sensor_model ? -1 : model_->slot(c.name);
    if (!sensor_model && slot < 0)
      throw InputError(where, "'" + c.name + "' is not a parameter of assembly " + assembly.id + " (" +
                                  model_->assembly().label() + ")");
    if (std::find(names_.begin(), names_.end(), c.name) != names_.end())
      throw InputError(where, "'" + c.name + "' is calibrated twice");
    double lower = c.lower, upper = c.upper;
    if (const auto b = setup.bounds.find(c.name); b != setup.bounds.end()) std::tie(lower, upper) = b->second;
    if (!(lower < upper)) throw InputError(where, "'" + c.name + "' needs lower < upper");
    if (sensor_model) sensor_models_.push_back(*sensor_model);
    names_.push_back(c.name);
    lower_.push_back(lower);
    upper_.push_back(upper);
    truths_.push_back(c.truth);
    slots_.push_back(slot);
  };
  for (const auto& c : study.calibrated) add(c, study.path + ": calibrated");
  for (const auto& c : setup.extra_calibrated) add(c, "calibrated effect parameter");
  for (const auto& m : setup.sensor_models)
    if (std::none_of(sensor_models_.begin(), sensor_models_.end(), [&](const SensorModelUse& u) { return names_[u.theta_index].rfind(m.name + ".", 0) == 0; }))
      throw InputError("sensor model " + m.name, "its parameter is not calibrated (add it to extra_calibrated)");
  rate_hz_ = study.simulation.output_rate_hz;
  base_values_ = model_->defaultRunValues();
  for (const auto& [c, w] : setup.channel_weights)
    if (!(std::isfinite(w) && w > 0)) throw InputError("channel weight of " + c, "must be finite and > 0");
  for (const auto& ds : data) {
    const std::size_t first = y_.size();
    addDataSet(study, ds, data.size() == 1);
    for (std::size_t i = first; i < y_.size(); ++i) {
      const auto& ch = ds.data.records[i - first].channel;
      const auto it = setup.channel_weights.find(ch);
      w_.push_back(it == setup.channel_weights.end() ? 1.0 : it->second);
      set_of_.push_back(static_cast<int>(sets_.size() - 1));
    }
  }
  pool_->model = model_;
  pool_->options = study.simulation;
}

void LabObjective::addDataSet(const Study& study, const DataSet& ds, bool single) {
  Set set;
  set.scenario = study.scenario(ds.scenario);
  set.road = makeRoad(set.scenario, model_->vehicle(), ds.road_seed.value_or(study.seed));
  set.first = y_.size();
  const auto channels = Simulator::channels(model_->sensors());
  const double rate = study.simulation.output_rate_hz;
  double t_max = 0.0;
  const std::string prefix = single ? ds.name + " record " : ds.name + ": record ";
  for (std::size_t i = 0; i < ds.data.records.size(); ++i) {
    const LabRecord& r = ds.data.records[i];
    int col = -1;
    for (std::size_t c = 0; c < channels.size(); ++c)
      if (channels[c].name == r.channel) col = static_cast<int>(c);
    if (col < 0) throw InputError(prefix + std::to_string(i + 1), "unknown channel '" + r.channel + "'");
    if (!(r.time_s >= 0.0 && r.time_s <= set.scenario.duration_s))
      throw InputError(prefix + std::to_string(i + 1),
                       "time_s " + formatExact(r.time_s) + " lies outside scenario '" + set.scenario.name + "' (0.." +
                           formatExact(set.scenario.duration_s) + " s)");
    y_.push_back(r.value);
    t_.push_back(r.time_s);
    rep_.push_back(r.repetition);
    where_.push_back({col, false, 0});
    t_max = std::max(t_max, r.time_s);
  }
  if (ds.data.records.empty()) throw InputError(ds.name, "holds no records");
  set.count = y_.size() - set.first;
  // Nothing after the last measured time matters: stop the simulation shortly after it (the
  // step sequence before that point does not depend on where the run ends).
  set.scenario.duration_s = std::min(set.scenario.duration_s, t_max + 0.05);
  // A time on the output grid reads its row; any other time is an extra output time of the run,
  // from the same dense output (twin/simulator.hpp RunResult::samples).
  std::vector<double>& extra = set.scenario.sample_times_s;
  for (std::size_t i = 0; i < set.count; ++i)
    if (!onGrid(ds.data.records[i].time_s, rate)) extra.push_back(ds.data.records[i].time_s);
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  for (std::size_t i = 0; i < set.count; ++i) {
    RecordRead& w = where_[set.first + i];
    const double t = ds.data.records[i].time_s;
    if (onGrid(t, rate)) {
      w.index = static_cast<std::size_t>(std::llround(t * rate));
    } else {
      w.at_sample = true;
      w.index = static_cast<std::size_t>(std::lower_bound(extra.begin(), extra.end(), t) - extra.begin());
    }
  }
  sets_.push_back(std::move(set));
}

LabObjective::~LabObjective() = default;

std::vector<ScenarioSpec> LabObjective::scenarios() const {
  std::vector<ScenarioSpec> v;
  for (const auto& s : sets_) v.push_back(s.scenario);
  return v;
}

std::vector<double> LabObjective::runValues(const std::vector<double>& theta) const {
  DTWIN_CHECK(theta.size() == slots_.size(), "theta has the wrong size");
  std::vector<double> values = base_values_;
  for (std::size_t j = 0; j < slots_.size(); ++j)
    if (slots_[j] >= 0) values[static_cast<std::size_t>(slots_[j])] = theta[j];
  return values;
}

std::vector<RunResult> LabObjective::runAll(const std::vector<double>& theta) const {
  const std::vector<double> values = runValues(theta);
  pool_->evaluations++;
  auto sim = pool_->acquire();
  std::vector<RunResult> out;
  double wall = 0.0;
  for (const auto& set : sets_) {
    RunResult r;
    try {
      StepControl steps;
      if (!plans_.empty()) steps.replay = plans_[static_cast<std::size_t>(&set - sets_.data())].get();
      r = sim->run(values, *set.road, set.scenario, steps);
    } catch (const InputError& e) {
      // A combination of in-bound values the laws reject (e.g. PAC2002 with an impossible shape):
      // a failed point, not a failed calibration.
      r.stats.ok = false;
      r.stats.message = e.what();
    }
    wall += r.stats.wall_s;
    const bool ok = r.stats.ok;
    if (!ok) {
      pool_->failures++;
      std::lock_guard<std::mutex> lock(pool_->m);
      if (pool_->first_failure.empty()) pool_->first_failure = r.stats.message;
    }
    out.push_back(std::move(r));
    if (!ok) break;
  }
  pool_->release(std::move(sim), wall / static_cast<double>(sets_.size()));
  return out;
}

bool LabObjective::freezeSteps(const std::vector<double>& theta, double accuracy) {
  plans_.clear();
  frozen_at_.clear();
  frozen_accuracy_ = 0.0;
  if (pool_->options.integrator != "rosenbrock") return false;
  const std::vector<double> values = runValues(theta);
  const bool own = accuracy > 0 && accuracy != pool_->options.accuracy;
  std::unique_ptr<Simulator> sim;
  if (own) {
    SimulationOptions o = pool_->options;
    o.accuracy = accuracy;
    sim = std::make_unique<Simulator>(model_, o);
  } else {
    sim = pool_->acquire();
  }
  std::vector<std::shared_ptr<const StepPlan>> plans;
  bool ok = true;
  for (const auto& set : sets_) {
    auto plan = std::make_shared<StepPlan>();
    StepControl steps;
    steps.record = plan.get();
    try {
      ok = sim->run(values, *set.road, set.scenario, steps).stats.ok;
    } catch (const InputError&) {
      ok = false;
    }
    if (!ok) break;
    plans.push_back(std::move(plan));
  }
  if (!own) pool_->release(std::move(sim), std::nullopt);  // not an evaluation: no wall time recorded
  if (!ok) return false;
  plans_ = std::move(plans);
  frozen_at_ = theta;
  frozen_accuracy_ = own ? accuracy : pool_->options.accuracy;
  return true;
}

std::vector<std::size_t> LabObjective::frozenStepCounts() const {
  std::vector<std::size_t> n;
  for (const auto& p : plans_) n.push_back(p->size());
  return n;
}

std::vector<RunResult> LabObjective::runs(const std::vector<double>& theta) const {
  auto r = runAll(theta);
  if (r.size() != sets_.size() || !r.back().stats.ok) return {};
  return r;
}

std::vector<Trace> LabObjective::traces(const std::vector<double>& theta) const {
  std::vector<Trace> t;
  for (auto& r : runs(theta)) t.push_back(std::move(r.trace));
  return t;
}

double LabObjective::read(const RunResult& run, std::size_t record, std::size_t column) const {
  const RecordRead& w = where_[record];
  const Trace& tr = w.at_sample ? run.samples : run.trace;
  DTWIN_CHECK(column < tr.channels().size() && w.index < tr.rows(), "read: record outside its run's output");
  return tr.column(column)[w.index];
}

std::vector<double> LabObjective::predict(const std::vector<double>& theta) const {
  const auto rs = runAll(theta);
  if (rs.size() != sets_.size() || !rs.back().stats.ok) return {};
  std::vector<double> eta(y_.size());
  for (std::size_t k = 0; k < sets_.size(); ++k)
    for (std::size_t i = sets_[k].first; i < sets_[k].first + sets_[k].count; ++i) {
      const RecordRead& w = where_[i];
      const Trace& tr = w.at_sample ? rs[k].samples : rs[k].trace;
      if (w.index >= tr.rows()) return {};
      eta[i] = tr.column(static_cast<std::size_t>(w.column))[w.index];
    }
  if (!sensor_models_.empty()) distort(theta, rs, eta);
  return eta;
}

void LabObjective::distort(const std::vector<double>& theta, const std::vector<RunResult>& runs, std::vector<double>& eta) const {
  std::map<int, SensorDistortion> by_column;
  for (const auto& m : sensor_models_)
    for (int c : m.columns) by_column[c].set(m.kind, theta[m.theta_index]);
  for (const auto& [column, d] : by_column) {
    if (d.identity()) continue;
    for (std::size_t k = 0; k < sets_.size(); ++k) {
      std::vector<std::size_t> records;
      std::vector<double> times;
      for (std::size_t i = sets_[k].first; i < sets_[k].first + sets_[k].count; ++i)
        if (where_[i].column == column) {
          records.push_back(i);
          times.push_back(t_[i]);
        }
      if (records.empty()) continue;
      const auto v = distortChannel(runs[k].trace.column(static_cast<std::size_t>(column)), rate_hz_, times, d);
      for (std::size_t j = 0; j < records.size(); ++j) eta[records[j]] = v[j];
    }
  }
}

std::vector<double> LabObjective::residuals(const std::vector<double>& theta) const {
  auto r = predict(theta);
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = std::sqrt(w_[i]) * (r[i] - y_[i]);
  return r;
}

double LabObjective::sse(const std::vector<double>& theta) const {
  const auto eta = predict(theta);
  if (eta.empty()) return std::numeric_limits<double>::infinity();
  double s = 0.0;
  for (std::size_t i = 0; i < y_.size(); ++i) s += w_[i] * (y_[i] - eta[i]) * (y_[i] - eta[i]);
  return std::isfinite(s) ? s : std::numeric_limits<double>::infinity();
}

long LabObjective::failures() const { return pool_->failures.load(); }
long LabObjective::evaluations() const { return pool_->evaluations.load(); }
double LabObjective::medianWallSeconds() const {
  std::lock_guard<std::mutex> lock(pool_->m);
  if (pool_->walls.empty()) return 0.0;
  std::vector<double> w = pool_->walls;
  std::nth_element(w.begin(), w.begin() + static_cast<long>(w.size() / 2), w.end());
  return w[w.size() / 2];
}

// ------------------------------------------------------------------ options
CalibrationOptions CalibrationOptions::fromStudy(const Study& study) {
  CalibrationOptions o;
  o.optimizer_starts = static_cast<int>(study.sizes.at("optimizer_starts"));
  o.lhs_points = static_cast<int>(study.sizes.at("lhs_points"));
  o.gibbs_iterations = static_cast<int>(study.sizes.at("gibbs_iterations"));
  o.gibbs_burn_in = static_cast<int>(study.sizes.at("gibbs_burn_in"));
  o.seed = study.seed;
  o.region = study.calibration.region;
  o.design.adaptive = study.calibration.designOrDefault() == "adaptive";
  o.design.round_points = static_cast<int>(study.calibration.round_points);  // 0: lhs_points
  o.design.max_rounds = static_cast<int>(study.calibration.max_rounds);
  o.design.target_ess = study.calibration.target_ess;
  o.joint.margin = study.calibration.margin;
  o.joint.ridge_steps = static_cast<int>(study.calibration.ridge_steps);
  o.interval = study.calibration.interval;
  o.steps = study.calibration.steps;
  return o;
}

AdaptiveDesignOptions CalibrationOptions::designOptions() const {
  AdaptiveDesignOptions d = design;
  d.first_points = lhs_points;
  if (d.round_points <= 0) d.round_points = lhs_points;
  d.tau_a = tau_prior_a;
  d.tau_b = tau_prior_b;
  d.seed = seed;
  return d;
}

GibbsOptions CalibrationOptions::gibbsOptions() const {
  GibbsOptions g;
  g.iterations = gibbs_iterations;
  g.burn_in = gibbs_burn_in;
  g.a = tau_prior_a;
  g.b = tau_prior_b;
  g.seed = seed;
  return g;
}

void CalibrationOptions::validate() const {
  const OptionCheck check("calibration");
  check.atLeast("threads", threads, 0);
  check.atLeast("optimizer_starts", optimizer_starts, 1);
  check.atLeast("lhs_points", lhs_points, 2);
  check.atLeast("gibbs_iterations", gibbs_iterations, 1);
  check.atLeast("gibbs_burn_in", gibbs_burn_in, 0);
  check.require(gibbs_burn_in < gibbs_iterations, "gibbs_burn_in",
                "must be below the number of Gibbs iterations (" + std::to_string(gibbs_iterations) + "), got " +
                    std::to_string(gibbs_burn_in));
  check.nonNegative("tau_prior_a", tau_prior_a);
  check.nonNegative("tau_prior_b", tau_prior_b);
  check.require(region == "joint" || region == "paper", "region", "must be \"joint\" or \"paper\", got \"" + region + "\"");
  check.require(interval == "profile" || interval == "posterior", "interval",
                "must be \"profile\" or \"posterior\", got \"" + interval + "\"");
  check.inRange("polish_step", polish_step, 0.0, 0.5);
  check.require(steps == "frozen" || steps == "adaptive", "steps", "must be \"frozen\" or \"adaptive\", got \"" + steps + "\"");
  profile.validate();
  optimizer.validate();
  box.validate();
  joint.validate();
  designOptions().validate();
  gibbsOptions().validate();
}

nlohmann::json CalibrationOptions::toJson() const {
  nlohmann::json j{{"optimizer_starts", optimizer_starts},
          {"lhs_points", lhs_points},
          {"gibbs_iterations", gibbs_iterations},
          {"gibbs_burn_in", gibbs_burn_in},
          {"tau_prior", {{"distribution", "Gamma(shape a, rate b)"}, {"a", tau_prior_a}, {"b", tau_prior_b}}},
          {"theta_prior", "uniform on the feasible box"},
          {"seed", seed},
          {"optimizer",
           {{"algorithm", optimizer.algorithm},
            {"xtol_rel", optimizer.xtol_rel},
            {"ftol_rel", optimizer.ftol_rel},
            {"maxeval", optimizer.maxeval},
            {"initial_step_scaled", optimizer.initial_step},
            {"screen_per_start", optimizer.screen_per_start}}},
          {"feasible_box",
           {{"rule", "SSE <= SSE_min (1 + 2 ln(100) / n): likelihood ratio 1 %"},
            {"initial_step_scaled", box.initial_step},
            {"growth", box.growth},
            {"tolerance_scaled", box.tolerance},
            {"max_evaluations_per_sweep", box.max_evaluations}}}};
  j["region"] = region;
  if (region == "joint") {
    j.erase("feasible_box");
    j["joint_region"] = joint.toJson();
  }
  j["design"] = designOptions().toJson();
  j["profile"] = profile.toJson();
  j["interval"] = interval;
  if (!extra_starts.empty()) j["extra_starts"] = extra_starts;
  if (polish_step > 0) j["polish_step"] = polish_step;
  j["steps"] = steps;
  return j;
}

// ------------------------------------------------------------------ persistence helpers
namespace {

nlohmann::json optimumJson(const Optimum& o) {
  nlohmann::json j{{"theta", jsonNumbers(o.theta)}, {"sse", jsonNumber(o.sse)}, {"best_start", o.best_start}, {"evaluations", o.evaluations}};
  for (const auto& s : o.starts)
    j["starts"].push_back({{"start", jsonNumbers(s.start)},
                           {"theta", jsonNumbers(s.theta)},
                           {"sse", jsonNumber(s.sse)},
                           {"evaluations", s.evaluations},
                           {"nonfinite_evaluations", s.nonfinite_evaluations},
                           {"status", s.status}});
  return j;
}
Optimum optimumFrom(const nlohmann::json& j) {
  Optimum o;
  o.theta = numbersFromJson(j.at("theta"));
  o.sse = numberFromJson(j.at("sse"));
  o.best_start = j.at("best_start").get<int>();
  o.evaluations = j.at("evaluations").get<int>();
  for (auto& s : j.at("starts")) {
    StartResult r;
    r.start = numbersFromJson(s.at("start"));
    r.theta = numbersFromJson(s.at("theta"));
    r.sse = numberFromJson(s.at("sse"));
    r.evaluations = s.at("evaluations").get<int>();
    r.nonfinite_evaluations = s.at("nonfinite_evaluations").get<int>();
    r.status = s.at("status").get<std::string>();
    o.starts.push_back(r);
  }
  return o;
}

nlohmann::json boxJson(const FeasibleBox& b) {
  nlohmann::json j{{"lower", jsonNumbers(b.lower)}, {"upper", jsonNumbers(b.upper)}, {"threshold", jsonNumber(b.threshold)}, {"evaluations", b.evaluations}};
  j["lower_clipped"] = b.lower_clipped;
  j["upper_clipped"] = b.upper_clipped;
  for (const auto& s : b.sweeps)
    j["sweeps"].push_back({{"parameter", s.parameter},
                           {"direction", s.direction},
                           {"edge", jsonNumber(s.edge)},
                           {"edge_sse", jsonNumber(s.edge_sse)},
                           {"clipped", s.clipped},
                           {"bracketed", s.bracketed},
                           {"evaluations", s.evaluations},
                           {"message", s.message}});
  return j;
}
FeasibleBox boxFrom(const nlohmann::json& j) {
  FeasibleBox b;
  b.lower = numbersFromJson(j.at("lower"));
  b.upper = numbersFromJson(j.at("upper"));
  b.threshold = numberFromJson(j.at("threshold"));
  b.evaluations = j.at("evaluations").get<int>();
  b.lower_clipped = j.at("lower_clipped").get<std::vector<bool>>();
  b.upper_clipped = j.at("upper_clipped").get<std::vector<bool>>();
  for (auto& s : j.at("sweeps")) {
    SweepResult r;
    r.parameter = s.at("parameter").get<int>();
    r.direction = s.at("direction").get<int>();
    r.edge = numberFromJson(s.at("edge"));
    r.edge_sse = numberFromJson(s.at("edge_sse"));
    r.clipped = s.at("clipped").get<bool>();
    r.bracketed = s.at("bracketed").get<bool>();
    r.evaluations = s.at("evaluations").get<int>();
    r.message = s.at("message").get<std::string>();
    b.sweeps.push_back(r);
  }
  return b;
}

/// Reads a stage file when it exists and carries `fingerprint`; null otherwise. Under MPI the
/// root reads it and every rank decides on the same bytes.
nlohmann::json readStage(const fs::path& p, const std::string& fingerprint) {
  const std::string text = onRoot([&]() -> std::string {
    if (!fs::exists(p)) return std::string();
    std::ifstream in(p, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return "F" + os.str();
  });
  if (text.empty()) return nullptr;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.begin() + 1, text.end());
  } catch (const std::exception&) {
    return nullptr;  // written atomically, so this is a foreign file: redo the stage
  }
  if (!j.contains("fingerprint") || j["fingerprint"] != fingerprint)
    throw InputError(p.string(), "was made by a different calibration (study, data, assembly or sizes changed); "
                                 "use a new output folder or delete it to start over");
  return j;
}

std::string hex(std::uint64_t v) { return formatPrintf("%016llx", static_cast<unsigned long long>(v)); }

std::vector<double> packStart(const StartResult& r) {
  return Packer().put(r.start).put(r.theta).put(r.sse).put(r.evaluations).put(r.nonfinite_evaluations).put(r.status).take();
}
StartResult unpackStart(const std::vector<double>& v) {
  Unpacker u(v);
  StartResult r;
  r.start = u.vec();
  r.theta = u.vec();
  r.sse = u.num();
  r.evaluations = static_cast<int>(u.integer());
  r.nonfinite_evaluations = static_cast<int>(u.integer());
  r.status = u.str();
  return r;
}
std::vector<double> packSweep(const SweepResult& r) {
  return Packer()
      .put(r.parameter)
      .put(r.direction)
      .put(r.edge)
      .put(r.edge_sse)
      .put(r.clipped ? 1.0 : 0.0)
      .put(r.bracketed ? 1.0 : 0.0)
      .put(r.evaluations)
      .put(r.message)
      .take();
}
SweepResult unpackSweep(const std::vector<double>& v) {
  Unpacker u(v);
  SweepResult r;
  r.parameter = static_cast<int>(u.integer());
  r.direction = static_cast<int>(u.integer());
  r.edge = u.num();
  r.edge_sse = u.num();
  r.clipped = u.num() != 0.0;
  r.bracketed = u.num() != 0.0;
  r.evaluations = static_cast<int>(u.integer());
  r.message = u.str();
  return r;
}

std::vector<double> packRay(const RaySweep& r) {
  return Packer()
      .put(r.t_edge)
      .put(r.edge_sse)
      .put(r.clipped ? 1.0 : 0.0)
      .put(r.bracketed ? 1.0 : 0.0)
      .put(r.budget_out ? 1.0 : 0.0)
      .put(r.loose ? 1.0 : 0.0)
      .put(r.bracket)
      .put(r.evaluations)
      .take();
}
RaySweep unpackRay(const std::vector<double>& v) {
  Unpacker u(v);
  RaySweep r;
  r.t_edge = u.num();
  r.edge_sse = u.num();
  r.clipped = u.num() != 0.0;
  r.bracketed = u.num() != 0.0;
  r.budget_out = u.num() != 0.0;
  r.loose = u.num() != 0.0;
  r.bracket = u.num();
  r.evaluations = static_cast<int>(u.integer());
  return r;
}

std::vector<double> packTrace(const RidgeTrace& r) {
  std::vector<double> z, cross;
  for (const auto& p : r.z) z.insert(z.end(), p.data(), p.data() + p.size());
  for (const auto& c : r.cross) {  // d·d values, or one NaN for an unknown cross-section
    if (c.size() == 0) cross.push_back(std::numeric_limits<double>::quiet_NaN());
    else cross.insert(cross.end(), c.data(), c.data() + c.size());
  }
  return Packer()
      .put(r.axis)
      .put(r.direction)
      .put(r.t)
      .put(z)
      .put(r.sse)
      .put(cross)
      .put(r.closed ? 1.0 : 0.0)
      .put(r.crossing)
      .put(r.clipped ? 1.0 : 0.0)
      .put(r.evaluations)
      .put(r.message)
      .take();
}
RidgeTrace unpackTrace(const std::vector<double>& v, int d) {
  Unpacker u(v);
  RidgeTrace r;
  r.axis = static_cast<int>(u.integer());
  r.direction = static_cast<int>(u.integer());
  r.t = u.vec();
  const std::vector<double> z = u.vec();
  for (std::size_t k = 0; k + static_cast<std::size_t>(d) <= z.size(); k += static_cast<std::size_t>(d))
    r.z.push_back(Eigen::Map<const Eigen::VectorXd>(z.data() + k, d));
  r.sse = u.vec();
  const std::vector<double> cross = u.vec();
  for (std::size_t k = 0; k < cross.size();) {
    if (std::isnan(cross[k])) {
      r.cross.emplace_back();
      ++k;
      continue;
    }
    r.cross.push_back(Eigen::Map<const Eigen::MatrixXd>(cross.data() + k, d, d));
    k += static_cast<std::size_t>(d * d);
  }
  r.closed = u.num() != 0.0;
  r.crossing = u.num();
  r.clipped = u.num() != 0.0;
  r.evaluations = static_cast<int>(u.integer());
  r.message = u.str();
  return r;
}

std::vector<double> packProfileEnd(const ProfileEnd& e) {
  return Packer().put(e.theta).put(e.sse).put(e.at_bound ? 1.0 : 0.0).put(e.evaluations).put(e.steps_taken).put(e.jacobians).put(e.outside_points).take();
}
ProfileEnd unpackProfileEnd(const std::vector<double>& v) {
  Unpacker u(v);
  ProfileEnd e;
  e.theta = u.vec();
  e.sse = u.num();
  e.at_bound = u.num() != 0.0;
  e.evaluations = static_cast<int>(u.integer());
  e.steps_taken = static_cast<int>(u.integer());
  e.jacobians = static_cast<int>(u.integer());
  e.outside_points = static_cast<int>(u.integer());
  return e;
}

/// box.json's "gauss_newton" of a joint region: the Gauss–Newton model, the sweeps along its
/// axes and the ridge traces.
nlohmann::json gaussNewtonJson(const JointRegionPlan& plan, const std::vector<RaySweep>& sweeps,
                               const std::vector<RidgeTrace>& traces) {
  nlohmann::json gn{{"hessian", "J^T J of the weighted residuals, scaled coordinates"},
                    {"eigenvalues", jsonNumbers(std::vector<double>(plan.eigenvalues.data(), plan.eigenvalues.data() + plan.eigenvalues.size()))},
                    {"quadratic_half_width", jsonNumbers(std::vector<double>(plan.half_width.data(), plan.half_width.data() + plan.half_width.size()))}};
  for (std::size_t k = 0; k < sweeps.size(); ++k)
    gn["sweeps"].push_back({{"axis", k / 2},
                            {"direction", k % 2 == 0 ? -1 : 1},
                            {"crossing", sweeps[k].t_edge},
                            {"edge_sse", jsonNumber(sweeps[k].edge_sse)},
                            {"clipped", sweeps[k].clipped},
                            {"bracketed", sweeps[k].bracketed},
                            {"evaluations", sweeps[k].evaluations},
                            {"quadratic_guess", plan.half_width(static_cast<long>(k / 2))}});
  for (const auto& tr : traces) {
    nlohmann::json t{{"axis", tr.axis}, {"direction", tr.direction}, {"t", tr.t}, {"sse", jsonNumbers(tr.sse)}, {"closed", tr.closed},
                     {"crossing", tr.crossing},
                     {"clipped", tr.clipped}, {"evaluations", tr.evaluations}, {"message", tr.message}};
    gn["ridges"].push_back(t);
  }
  return gn;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

/// Levenberg–Marquardt on the weighted residuals e = sqrt(w) (η(θ) − y) in the scaled
/// coordinates z ∈ [0,1]^d, from θ0 (minimiseOnSubspace on the whole box): a central-difference
/// Jacobian (step `h` scaled units, 2d simulations, in parallel), then Broyden updates after
/// every trial point until the carried Jacobian finds no better point or only a small gain
/// (fresh differences then); damping λ·diag(JᵀJ), a parameter on a bound held there. A least-squares
/// polish for sharp minima of dense data, where a derivative-free quadratic model stalls. Returns
/// the best point seen. The step must stay well above the integrator's noise: at 2e-3 scaled
/// units the residual differences of a damping rate were comparable with it and the polish
/// stalled 280 SSE units above the truth (dense diag_bump + diag_rough data); 1e-2 reaches it.
StartResult polishLeastSquares(const LabObjective& obj, const std::vector<double>& theta0, const PolishOptions& options) {
  const std::size_t d = theta0.size();
  const long dl = static_cast<long>(d);
  const auto& lo = obj.lower();
  const auto& up = obj.upper();
  const auto& y = obj.measured();
  const auto& w = obj.weights();
  auto toTheta = [&](const Eigen::VectorXd& z) {
    std::vector<double> th(d);
    for (std::size_t k = 0; k < d; ++k) th[k] = lo[k] + std::clamp(z[static_cast<long>(k)], 0.0, 1.0) * (up[k] - lo[k]);
    return th;
  };
  std::atomic<int> runs{0};
  const ScaledResiduals residual = [&](const Eigen::VectorXd& z, Eigen::VectorXd& e) {
    ++runs;
    const auto eta = obj.predict(toTheta(z));
    if (eta.empty()) return false;
    e.resize(static_cast<long>(y.size()));
    for (std::size_t i = 0; i < y.size(); ++i) e[static_cast<long>(i)] = std::sqrt(w[i]) * (eta[i] - y[i]);
    return e.allFinite();
  };
  StartResult res;
  res.start = theta0;
  res.theta = theta0;
  res.status = "LM_POLISH";
  Eigen::VectorXd z(dl), e;
  for (std::size_t k = 0; k < d; ++k) z[static_cast<long>(k)] = std::clamp((theta0[k] - lo[k]) / (up[k] - lo[k]), 0.0, 1.0);
  SubspaceLmSettings set;
  set.tries = 8;
  set.min_rel_gain = options.rel_gain;
  set.forward = options.forward;
  set.converge_on_fresh = true;
  set.lower = Eigen::VectorXd::Zero(dl);
  set.upper = Eigen::VectorXd::Ones(dl);
  set.threads = options.threads;
  double sse = 0.0;
  const bool ok = minimiseOnSubspace(residual, Eigen::VectorXd::Zero(dl), Eigen::MatrixXd::Identity(dl, dl),
                                     Eigen::VectorXd::Constant(dl, options.h), 30, 0.0, z, e, sse, options.carried, set);
  res.evaluations = runs.load();
  res.sse = ok ? sse : std::numeric_limits<double>::infinity();
  if (ok) res.theta = toTheta(z);
  return res;
}

// ------------------------------------------------------------------ result JSON
IntegratorCheck assessIntegrator(const std::vector<double>& eta, const std::vector<double>& eta_fine, const std::vector<double>& y,
                                 const std::vector<double>& w, double accuracy, double threshold) {
  DTWIN_CHECK(eta.size() == y.size() && eta_fine.size() == y.size() && w.size() == y.size(), "assessIntegrator: sizes differ");
  IntegratorCheck c;
  c.accuracy = accuracy;
  c.accuracy_check = accuracy / 10;
  c.threshold = threshold;
  double ee = 0.0, dd = 0.0, ff = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    ee += w[i] * (eta[i] - y[i]) * (eta[i] - y[i]);
    ff += w[i] * (eta_fine[i] - y[i]) * (eta_fine[i] - y[i]);
    dd += w[i] * (eta[i] - eta_fine[i]) * (eta[i] - eta_fine[i]);
  }
  c.sse = ee;
  c.sse_check = ff;
  c.prediction_change = std::sqrt(dd);
  c.jitter = y.empty() ? 0.0 : std::max(std::abs(ee - ff), 2.0 * std::sqrt(ee) * std::sqrt(dd) / std::sqrt(static_cast<double>(y.size())));
  c.ok = !(c.threshold > 0) || c.jitter < 0.5 * c.threshold;
  if (!c.ok)
    c.message = "the integrator's error moves the SSE by about " + formatNumber(c.jitter, 3) + " at the optimum (accuracy " +
                formatNumber(c.accuracy, 3) + " against " + formatNumber(c.accuracy_check, 3) + "), against the 95 % intervals' threshold of " +
                formatNumber(c.threshold, 3) + ": the optimum and the intervals follow the integrator, not the data; tighten [simulation] accuracy "
                "(to " + formatNumber(c.accuracy_check, 3) + " or less) and rerun";
  return c;
}

double quadraticRoughness(const std::vector<double>& x, const std::vector<double>& f) {
  DTWIN_CHECK(x.size() == f.size() && x.size() >= 4, "quadraticRoughness: needs at least 4 points");
  const long m = static_cast<long>(x.size());
  Eigen::MatrixXd A(m, 3);
  Eigen::VectorXd b(m);
  const double x0 = x[x.size() / 2];
  double scale = 0.0;
  for (double v : x) scale = std::max(scale, std::abs(v - x0));
  if (!(scale > 0)) scale = 1.0;
  for (long i = 0; i < m; ++i) {
    const double u = (x[static_cast<std::size_t>(i)] - x0) / scale;
    A(i, 0) = 1.0;
    A(i, 1) = u;
    A(i, 2) = u * u;
    b[i] = f[static_cast<std::size_t>(i)];
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  return (A * c - b).cwiseAbs().maxCoeff();
}

double integratorOptimumShift(const Eigen::MatrixXd& J, const Eigen::VectorXd& g) {
  DTWIN_CHECK(J.cols() == g.size(), "integratorOptimumShift: J and g disagree");
  const Eigen::MatrixXd H = 2.0 * J.transpose() * J;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(H);
  const Eigen::VectorXd ev = es.eigenvalues();
  const double tol = std::max(ev.cwiseAbs().maxCoeff(), 1e-300) * 1e-12;
  const Eigen::VectorXd p = es.eigenvectors().transpose() * g;
  double s = 0.0;
  for (long i = 0; i < ev.size(); ++i)
    if (ev[i] > tol) s += p[i] * p[i] / ev[i];
  return 0.5 * s;
}

std::vector<double> probeStepsFromJacobian(const Eigen::MatrixXd& J, double threshold) {
  const long d = J.cols();
  std::vector<double> h(static_cast<std::size_t>(d), 1e-2);
  if (d == 0 || !(threshold > 0) || !J.allFinite()) return h;
  const Eigen::MatrixXd H = J.transpose() * J;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(H);
  const Eigen::VectorXd ev = es.eigenvalues();
  const double tol = std::max(ev.cwiseAbs().maxCoeff(), 1e-300) * 1e-12;
  for (long k = 0; k < d; ++k) {
    double c = 0.0;  // (JᵀJ)⁺_kk
    for (long i = 0; i < d; ++i)
      if (ev[i] > tol) c += es.eigenvectors()(k, i) * es.eigenvectors()(k, i) / ev[i];
    const double half = c > 0 ? std::sqrt(threshold * c) : 1.0;
    h[static_cast<std::size_t>(k)] = std::clamp(half / 10, 1e-4, 1e-2);
  }
  return h;
}

void applyProbes(IntegratorCheck& c, double roughness, double optimum_shift, double shift_floor) {
  c.steps = "frozen";
  c.roughness = roughness;
  c.optimum_shift = optimum_shift;
  c.shift_floor = shift_floor;
  c.jitter = optimum_shift > 4 * shift_floor ? std::max(roughness, optimum_shift) : roughness;
  c.ok = !(c.threshold > 0) || c.jitter < 0.5 * c.threshold;
  c.message.clear();
  if (!c.ok)
    c.message = "with its steps frozen the integrator's error still moves the optimum by about " + formatNumber(optimum_shift, 3) +
                " (SSE units; the SSE departs from a quadratic by " + formatNumber(roughness, 3) + "), against the 95 % intervals' "
                "threshold of " + formatNumber(c.threshold, 3) + ": the optimum and the intervals follow the integrator, not the data; "
                "tighten [simulation] accuracy (to " + formatNumber(c.accuracy_check, 3) + " or less) and rerun";
}

nlohmann::json IntegratorCheck::toJson() const {
  return {{"steps", steps}, {"roughness", jsonNumber(roughness)}, {"optimum_shift", jsonNumber(optimum_shift)},
          {"shift_floor", jsonNumber(shift_floor)},
          {"accuracy", accuracy},           {"accuracy_check", accuracy_check}, {"sse", jsonNumber(sse)},
          {"sse_check", jsonNumber(sse_check)}, {"prediction_change", jsonNumber(prediction_change)},
          {"jitter", jsonNumber(jitter)},     {"threshold", jsonNumber(threshold)}, {"ok", ok}, {"message", message}};
}

nlohmann::json CalibrationResult::toJson() const {
  nlohmann::json j;
  j["assembly"] = assembly;
  j["label"] = label;
  j["n_data"] = n_data;
  j["sse_min"] = jsonNumber(optimum.sse);
  j["tau_hat"] = optimum.sse > 0 ? jsonNumber(n_data / optimum.sse) : jsonNumber(std::numeric_limits<double>::infinity());
  std::vector<double> box_lo, box_hi;
  region.boundingBox(box_lo, box_hi);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& p = posterior.parameters[k];
    const bool has_profile = k < profile.lower.size();
    const double plo = has_profile ? profile.lower[k] : p.q025, phi = has_profile ? profile.upper[k] : p.q975;
    const bool use_profile = interval == "profile" && has_profile;
    nlohmann::json e{{"mean", p.mean},
                     {"sd", p.sd},
                     {"ci95", {use_profile ? plo : p.q025, use_profile ? phi : p.q975}},
                     {"interval", use_profile ? "profile" : "posterior"},
                     {"credible95", {p.q025, p.q975}},
                     {"ess", jsonNumber(p.ess)},
                     {"optimum", optimum.theta[k]},
                     {"box", {box_lo[k], box_hi[k]}},
                     {"box_clipped", {box_lo[k] <= region.lower[k], box_hi[k] >= region.upper[k]}}};
    if (has_profile) e["profile95"] = {plo, phi};
    if (truth[k]) {
      e["truth"] = *truth[k];
      e["truth_in_credible95"] = *truth[k] >= p.q025 && *truth[k] <= p.q975;
      if (has_profile) e["truth_in_profile95"] = *truth[k] >= plo && *truth[k] <= phi;
      e["truth_in_ci95"] = use_profile ? (*truth[k] >= plo && *truth[k] <= phi) : (*truth[k] >= p.q025 && *truth[k] <= p.q975);
    }
    j["parameters"][names[k]] = e;
  }
  j["parameter_order"] = names;
  j["bounds"] = nlohmann::json::array();
  for (std::size_t k = 0; k < names.size() && k < lower.size(); ++k) j["bounds"].push_back({lower[k], upper[k]});
  j["units"] = units;
  j["bound_findings"] = nlohmann::json::array();
  for (const auto& f : bounds) j["bound_findings"].push_back(f.toJson());
  if (!left_out.empty()) {
    j["left_out"] = left_out;
    j["left_out_note"] = "calibrated values of the study that this assembly's options do not have (the hub input has no tire "
                         "stiffness or damping): not calibrated";
  }
  j["tau"] = {{"mean", posterior.tau.mean},
              {"sd", posterior.tau.sd},
              {"ci95", {posterior.tau.q025, posterior.tau.q975}},
              {"ess", jsonNumber(posterior.tau.ess)},
              {"noise_variance_mean_N2", posterior.tau.mean > 0 ? 1.0 / posterior.tau.mean : 0.0}};
  j["optimum"] = optimumJson(optimum);
  j["integrator_check"] = integrator.toJson();
  j["region"] = region.toJson();
  j["interval"] = interval;
  if (!profile.lower.empty()) j["profile"] = profile.toJson();
  if (region.kind == "paper") j["box"] = boxJson(box);
  j["design"] = rounds.toJson(names);
  j["design"]["failures"] = design_failures;
  j["design"]["resumed_points"] = resumed_points;
  j["design"]["method"] = rounds.rounds.size() > 1
                              ? "Latin hypercube in the region, then stratified Gaussian rounds around the posterior; "
                                "Griddy Gibbs with deterministic-mixture design weights"
                              : "Latin hypercube in the region, one point per stratum per dimension";
  for (const auto& w : rounds.warnings) j["warnings"].push_back(w);
  for (const auto& w : warnings) j["warnings"].push_back(w);
  double best = std::numeric_limits<double>::infinity();
  for (double s : sse) best = std::min(best, s);
  j["design"]["sse_min"] = jsonNumber(best);
  j["design"]["better_than_optimum"] = best < optimum.sse;
  if (best < optimum.sse)
    j["warnings"].push_back("a design point has a lower SSE (" + std::to_string(best) + ") than the optimiser's optimum (" +
                            std::to_string(optimum.sse) + "): the optimiser stopped in a local minimum; more starts may help");
  j["gibbs"] = {{"iterations", chains.options.iterations},
                {"burn_in", chains.options.burn_in},
                {"draws", posterior.draws},
                {"seed", chains.options.seed},
                {"distinct_points", posterior.distinct_points},
                {"top_point", posterior.top_point},
                {"top_share", posterior.top_share},
                {"design_too_coarse", posterior.design_too_coarse},
                {"message", posterior.message}};
  double ess_min = std::numeric_limits<double>::infinity();
  for (const auto& p : posterior.parameters)
    if (std::isfinite(p.ess)) ess_min = std::min(ess_min, p.ess);
  j["effective_sample_size_min"] = jsonNumber(ess_min);
  for (const auto& [s, w] : stage_wall_s) j["stages_wall_s"][s] = w;
  j["median_run_wall_s"] = median_run_wall_s;
  return j;
}

// ------------------------------------------------------------------ calibrateAssembly
namespace {

/// One calibration of one assembly (docs/method.md §4; docs/calibration.md lists its files): the
/// inputs, the state its stages share and the result they fill in, one method per stage, run in
/// order by calibrateAssembly. A stage that takes long persists what it found in the output folder
/// under the resume fingerprint as it finishes (readStage, the design journal) and reads it back
/// on a rerun with the same inputs. Starts, sweeps and design points are spread over the MPI ranks
/// and the threads of each rank (distributedMap: task i on rank i % size, results by index on
/// every rank); only the root writes files (rootWrites).
class CalibrationRun {
 public:
  CalibrationRun(const Study& study, const AssemblySpec& assembly, const std::vector<DataSet>& data,
                 const CalibrationSetup& setup, const CalibrationOptions& options, const std::string& out_dir,
                 const std::string& fingerprint_extra, const StageProgress& progress)
      : study_(study), assembly_(assembly), data_(data), setup_(setup), options_(options), out_dir_(out_dir),
        fingerprint_extra_(fingerprint_extra), progress_(progress), t_all_(Clock::now()) {}

  void objective();
  void optimum();
  void region();
  void design();
  void profile();
  void sampler();
  void integratorCheck();
  /// What probeBias measured: ok false when a run failed.
  struct BiasProbe {
    bool ok = false;
    double roughness = 0.0, shift = 0.0;
    /// The shift central differences would show from the roughness alone (gradient errors of
    /// roughness_k / h_k per axis): below it a shift is not resolved. 0 with three points.
    double shift_floor = 0.0;
  };
  LabObjective fineObjective(double accuracy) const;
  BiasProbe probeBias(const LabObjective& fine, const std::vector<double>& theta, const std::vector<double>& h, bool five,
                      const std::string& stage) const;
  void chooseStepAccuracy();
  void summary();
  CalibrationResult take() { return std::move(res_); }
  /// After optimum() alone: the result with the optimum, the stages' wall times and the run cost.
  CalibrationResult takeOptimum() {
    res_.stage_wall_s.push_back({"total", secondsSince(t_all_)});
    res_.median_run_wall_s = objective_->medianWallSeconds();
    findBoundFindings();
    return take();
  }
  /// res_.bounds from what the stages so far found (the optimum; the intervals and the posterior
  /// when they exist).
  void findBoundFindings() {
    BoundInputs in;
    in.names = res_.names;
    in.units = res_.units;
    in.lower = res_.lower;
    in.upper = res_.upper;
    in.optimum = res_.optimum.theta;
    if (res_.posterior.parameters.size() == d_) {
      for (std::size_t k = 0; k < d_; ++k) {
        const bool prof = res_.interval == "profile" && k < res_.profile.lower.size();
        in.interval_lo.push_back(prof ? res_.profile.lower[k] : res_.posterior.parameters[k].q025);
        in.interval_hi.push_back(prof ? res_.profile.upper[k] : res_.posterior.parameters[k].q975);
      }
      in.design = &res_.design;
      in.draws = res_.chains.index;
    }
    in.limit_lower = limit_lower_;
    in.limit_upper = limit_upper_;
    in.limit_basis = limit_basis_;
    res_.bounds = findBounds(in);
  }

 private:
  using Clock = std::chrono::steady_clock;
  using ResumedPoints = std::map<long, std::pair<std::vector<double>, double>>;  ///< design index -> (θ, SSE)

  void report(const std::string& stage, std::size_t done, std::size_t total) const {
    if (progress_) progress_(stage, done, total);
  }
  fs::path file(const char* name) const { return fs::path(out_dir_) / name; }
  std::string resumeFingerprint() const;
  std::vector<std::vector<double>> optimiserStarts(nlohmann::json& screening) const;
  void polish(std::vector<StartResult>& starts) const;
  void polishOnOwnSteps();
  void polishFrozen();
  nlohmann::json stepsJson() const;
  BoxProblem boxProblem() const;
  void paperBox(const BoxProblem& bp, nlohmann::json& stage);
  void jointRegion(const BoxProblem& bp, nlohmann::json& stage);
  ResumedPoints openJournal(const std::string& journal_path, std::unique_ptr<DesignJournal>& journal) const;
  std::vector<double> evaluateRound(const Eigen::MatrixXd& pts, int first, const std::string& stage, DesignJournal* journal,
                                    const std::string& journal_path, ResumedPoints& resumed);
  void writeDesignTable() const;
  void evaluatedPoints(Eigen::MatrixXd& pts, std::vector<double>& f) const;
  void appendStartEnds(Eigen::MatrixXd& pts, std::vector<double>& f) const;
  void warnOtherBasins(const nlohmann::json& basins);
  /// The residuals' correlation in time at the optimum (correlated.hpp): blocks 0 unless every
  /// data set is a drive (one repetition, enough sample times).
  CorrelationAdjustment timeCorrelation();
  void writePosterior() const;

  const Study& study_;
  const AssemblySpec& assembly_;
  const std::vector<DataSet>& data_;
  const CalibrationSetup& setup_;
  const CalibrationOptions& options_;
  const std::string& out_dir_;
  const std::string& fingerprint_extra_;
  const StageProgress& progress_;
  const Clock::time_point t_all_;
  std::unique_ptr<LabObjective> objective_;
  SseFunction sse_;          ///< objective_->sse
  std::size_t d_ = 0;        ///< calibrated parameters
  int n_ = 0;                ///< scalar residuals
  std::string fingerprint_;  ///< of everything that changes the numbers; every stage file carries it
  CalibrationResult res_;
  nlohmann::json steps_log_ = nlohmann::json::array();  ///< chooseStepAccuracy's tries
  /// The Jacobian of the last polish on frozen steps (scaled units): the next polish's first, and
  /// the source of the integrator probes' steps (probeStepsFromJacobian).
  SubspaceJacobian polish_jacobian_;
  std::vector<double> reference_;  ///< the θ the screening's and the starts' steps were frozen at
  /// Per calibrated value: its physical limits (NaN: none known) and their basis (physicalLimit).
  std::vector<double> limit_lower_, limit_upper_;
  std::vector<std::string> limit_basis_;
};

/// The resume fingerprint: everything that changes the numbers.
std::string CalibrationRun::resumeFingerprint() const {
  const LabObjective& objective = *objective_;
  nlohmann::json fp{{"assembly", assembly_.id},
                    {"label", assembly_.label()},
                    {"names", objective.names()},
                    {"lower", objective.lower()},
                    {"upper", objective.upper()},
                    {"scenario", objective.scenario().toJson()},
                    {"simulation", study_.simulation.toJson()},
                    {"options", options_.toJson()},
                    {"data", fingerprint_extra_}};
  // Only the general form adds keys, so a plain calibration keeps its fingerprint.
  if (data_.size() > 1) {
    fp["scenarios"] = nlohmann::json::array();
    for (const auto& sc : objective.scenarios()) fp["scenarios"].push_back(sc.toJson());
  }
  if (!setup_.empty()) fp["setup"] = setup_.toJson();
  for (const auto& ds : data_)
    if (ds.road_seed) fp["road_seeds"].push_back(*ds.road_seed);
  return hex(fnv1a64(fp.dump()));
}

/// Stage 0, objective: the SSE of the assembly against the data sets (LabObjective), the output
/// folder, the result's header and the resume fingerprint. Nothing is persisted.
void CalibrationRun::objective() {
  objective_ = std::make_unique<LabObjective>(study_, assembly_, data_, setup_);
  d_ = objective_->names().size();
  n_ = objective_->dataCount();
  rootWrites([&] { fs::create_directories(out_dir_); });
  res_.assembly = assembly_.id;
  res_.label = assembly_.label();
  res_.names = objective_->names();
  res_.truth = objective_->truths();
  res_.n_data = n_;
  res_.lower = objective_->lower();
  res_.upper = objective_->upper();
  res_.left_out = objective_->leftOut();
  const ParameterTable table = study_.parameterTable();
  for (const auto& name : res_.names) {
    std::string unit;
    for (const auto& c : study_.calibrated)
      if (c.name == name) unit = c.unit;
    for (const auto& c : setup_.extra_calibrated)
      if (c.name == name) unit = c.unit;
    res_.units.push_back(unit);
    const auto lim = physicalLimit(name, table);
    limit_lower_.push_back(lim ? lim->lower : std::numeric_limits<double>::quiet_NaN());
    limit_upper_.push_back(lim ? lim->upper : std::numeric_limits<double>::quiet_NaN());
    limit_basis_.push_back(lim ? lim->basis : "");
  }
  fingerprint_ = resumeFingerprint();
  sse_ = [this](const std::vector<double>& th) { return objective_->sse(th); };
  if (options_.steps == "frozen") {
    // The screening and the optimiser's starts replay the steps of one reference point: the extra
    // start (e.g. a nested model's optimum) that fits best, or the box centre.
    std::vector<double> ref(d_);
    for (std::size_t k = 0; k < d_; ++k) ref[k] = 0.5 * (objective_->lower()[k] + objective_->upper()[k]);
    std::vector<std::vector<double>> extra;
    for (const auto& x : options_.extra_starts)
      if (x.size() == d_) {
        extra.push_back(x);
        for (std::size_t k = 0; k < d_; ++k) extra.back()[k] = std::clamp(x[k], objective_->lower()[k], objective_->upper()[k]);
      }
    if (extra.size() == 1) ref = extra[0];
    if (extra.size() > 1) {
      const auto f = distributedMap(
          extra.size(), options_.threads, [&](std::size_t i, int) { return std::vector<double>{objective_->sse(extra[i])}; },
          [&](std::size_t done, std::size_t total) { report("optimum: reference", done, total); });
      std::size_t best = 0;
      for (std::size_t i = 1; i < f.size(); ++i)
        if (std::isfinite(f[i][0]) && !(f[i][0] >= f[best][0])) best = i;  // a failed run never wins
      ref = extra[best];
    }
    reference_ = ref;
    if (!objective_->freezeSteps(ref))
      res_.warnings.push_back("the integrator's steps could not be frozen at the reference point (its run failed); the optimiser's "
                              "starts chose their steps adaptively");
  }
}

/// The optimiser's starting points: the best screening points (or a plain spread of starts when
/// screening is off), after the options' extra starts. `screening` receives what the screening did.
std::vector<std::vector<double>> CalibrationRun::optimiserStarts(nlohmann::json& screening) const {
  const LabObjective& objective = *objective_;
  std::vector<std::vector<double>> x0;
  if (options_.optimizer.screen_per_start > 0) {
    const auto cand = screeningPoints(objective.lower(), objective.upper(), options_.optimizer_starts,
                                      options_.optimizer.screen_per_start, options_.seed);
    const auto f = distributedMap(
        cand.size(), options_.threads, [&](std::size_t i, int) { return std::vector<double>{objective.sse(cand[i])}; },
        [&](std::size_t done, std::size_t total) { report("optimum: screening", done, total); });
    std::vector<double> fs;
    for (const auto& v : f) fs.push_back(v[0]);
    x0 = bestStarts(cand, fs, objective.lower(), objective.upper(), options_.optimizer_starts);
    screening = {{"points", cand.size()},
                 {"rule", "the box centre and a Latin hypercube of the bounds; starts = the best, 0.05 apart (scaled)"},
                 {"best_sse", jsonNumber(*std::min_element(fs.begin(), fs.end()))}};
  } else {
    x0 = optimizerStarts(objective.lower(), objective.upper(), options_.optimizer_starts, options_.seed);
  }
  report("optimum", 0, static_cast<std::size_t>(options_.optimizer_starts));
  for (std::size_t k = options_.extra_starts.size(); k-- > 0;) {
    auto x = options_.extra_starts[k];
    if (x.size() != d_) throw InputError("extra optimiser start", "has " + std::to_string(x.size()) + " values, expected " + std::to_string(d_));
    for (std::size_t i = 0; i < d_; ++i) x[i] = std::clamp(x[i], objective.lower()[i], objective.upper()[i]);
    x0.insert(x0.begin(), x);
  }
  return x0;
}

/// options.polish_step > 0: one more local run from the best start with that initial step, then
/// Levenberg–Marquardt from the best point so far (polishLeastSquares); both appended to `starts`.
void CalibrationRun::polish(std::vector<StartResult>& starts) const {
  const LabObjective& objective = *objective_;
  const Optimum first = collectOptimum(starts);
  if (!std::isfinite(first.sse)) return;
  OptimizerOptions po = options_.optimizer;
  po.initial_step = options_.polish_step;
  report("optimum: polish", 0, 1);
  starts.push_back(minimiseFrom(sse_, objective.lower(), objective.upper(), first.theta, po));
  const Optimum second = collectOptimum(starts);
  report("optimum: polish", 0, 1);
  starts.push_back(polishLeastSquares(objective, second.theta, {options_.threads, kPolishStep}));
}

/// Steps frozen: the starts ran on the steps of the reference point (objective()). Freezes the
/// steps again at the best start's θ and polishes it by Levenberg–Marquardt on them (appended to
/// the starts); that is the optimum, and the later stages replay the same steps. If the run at
/// the best start fails adaptively, the steps go back to adaptive and the optimum stays.
void CalibrationRun::polishOnOwnSteps() {
  if (!std::isfinite(res_.optimum.sse)) return;
  if (!objective_->freezeSteps(res_.optimum.theta)) {
    objective_->thawSteps();
    res_.warnings.push_back("the integrator's steps could not be frozen at the optimiser's best point (its run failed); the later "
                            "stages chose their steps adaptively");
    return;
  }
  polishFrozen();
  chooseStepAccuracy();
}

/// One Levenberg–Marquardt polish from the optimum on the steps frozen now; it becomes the optimum
/// (only its SSE is on those steps).
void CalibrationRun::polishFrozen() {
  report("optimum: polish on its own steps", 0, 1);
  PolishOptions po;
  po.threads = options_.threads;
  po.h = kPolishStepFrozen;
  po.carried = &polish_jacobian_;
  StartResult lm = polishLeastSquares(*objective_, res_.optimum.theta, po);
  lm.status = "LM_POLISH_FROZEN_STEPS";
  res_.optimum.evaluations += lm.evaluations;
  res_.optimum.starts.push_back(std::move(lm));
  res_.optimum.best_start = static_cast<int>(res_.optimum.starts.size()) - 1;
  res_.optimum.theta = res_.optimum.starts.back().theta;
  res_.optimum.sse = res_.optimum.starts.back().sse;
  report("optimum: polish on its own steps", 1, 1);
}

/// Steps frozen: is the accuracy they were chosen at enough for these data? The integrator's bias
/// moves the optimum by the shift of probeBias (steps h a tenth of the Gauss–Newton half-widths
/// of the polish's Jacobian, as the final check's are of the profile's); the intervals'
/// threshold is c s² (profile.hpp, from the optimum's SSE). While the shift exceeds an eighth of
/// the threshold (so that the final check, with its own probe, stays below a quarter), the steps
/// are chosen again at a tighter accuracy, accuracy × (threshold / 8 / shift)^(2/3), between a
/// tenth and 0.7 of the last, and the optimum polished on them; at most twice. (The shift would go
/// with the tolerance squared if the error were proportional to it; on the demonstration drive it
/// went as the tolerance^1.6, hence the exponent 1/1.5.) When a tighter accuracy does not halve
/// the shift, the shift is not the integrator's: the last accuracy and its optimum are kept. Each try is recorded (steps_log_, optimum.json "steps").
void CalibrationRun::chooseStepAccuracy() {
  const double dof = n_ > static_cast<int>(d_) ? n_ - static_cast<int>(d_) : n_;
  const double t = studentQuantile(0.5 + 0.5 * options_.profile.level, dof);
  // The final check (integratorCheck) probes at a tenth of each interval's half-width; so do these
  // probes, the half-widths from the polish's Jacobian (Gauss–Newton), since the roughness and
  // the shift depend on the probe's step.
  const bool have_j = polish_jacobian_.J.rows() == n_ && polish_jacobian_.J.cols() == static_cast<long>(d_);
  const std::vector<double> h =
      have_j ? probeStepsFromJacobian(polish_jacobian_.J, t * t * res_.optimum.sse / dof) : std::vector<double>(d_, kPolishStepFrozen);
  double last_shift = 0.0, last_accuracy = 0.0;
  std::vector<double> last_theta;
  Optimum last_optimum;
  for (int round = 0; round < 3; ++round) {
    const double accuracy = objective_->stepsFrozenAccuracy();
    const double threshold = t * t * res_.optimum.sse / dof;
    LabObjective fine = fineObjective(accuracy);
    if (!fine.freezeSteps(res_.optimum.theta)) return;
    const BiasProbe p = probeBias(fine, res_.optimum.theta, h, true, "optimum: integrator bias");
    if (!p.ok) return;
    steps_log_.push_back({{"accuracy", accuracy}, {"optimum_shift", jsonNumber(p.shift)}, {"threshold", jsonNumber(threshold)},
                          {"roughness", jsonNumber(p.roughness)}, {"shift_floor", jsonNumber(p.shift_floor)},
                          {"probe_step", jsonNumbers(h)}});
    if (!(p.shift > 4 * p.shift_floor)) {
      // The shift is within what the SSE's roughness lets central differences see (jumps of the
      // model itself, e.g. a tire force that jumps at touch-down between two stage times): no
      // tighter accuracy can be shown to help, so this one stays.
      steps_log_.back()["note"] = "the shift is within the roughness floor: accuracy kept";
      return;
    }
    if (round > 0 && !(p.shift < 0.5 * last_shift)) {
      // Tighter steps did not halve the shift: it is not the integrator's bias but a jump of the
      // model itself (a tire law whose force jumps when a wheel touches down between two samples).
      // Back to the last accuracy and its optimum.
      objective_->freezeSteps(last_theta, last_accuracy);
      res_.optimum = last_optimum;
      steps_log_.back()["kept"] = false;
      return;
    }
    if (!(p.shift > threshold / 8) || round == 2) return;
    last_shift = p.shift;
    last_accuracy = accuracy;
    last_theta = objective_->stepsFrozenAt();
    last_optimum = res_.optimum;
    const double tighter = accuracy * std::clamp(std::pow(threshold / 8 / p.shift, 2.0 / 3.0), 0.1, 0.7);
    if (!objective_->freezeSteps(res_.optimum.theta, tighter)) {
      objective_->freezeSteps(res_.optimum.theta, accuracy);
      return;
    }
    polishFrozen();
  }
}

/// How the objective chose its steps, for optimum.json (the θ they are frozen at, to resume).
nlohmann::json CalibrationRun::stepsJson() const {
  nlohmann::json j{{"mode", options_.steps}, {"frozen", objective_->stepsFrozen()}};
  if (objective_->stepsFrozen()) {
    j["frozen_at"] = jsonNumbers(objective_->stepsFrozenAt());
    j["accuracy"] = objective_->stepsFrozenAccuracy();
    j["steps_per_data_set"] = objective_->frozenStepCounts();
    j["accuracy_choice"] = steps_log_;
  }
  if (!reference_.empty()) j["starts_frozen_at"] = jsonNumbers(reference_);
  return j;
}

/// Stage 1, optimum (optimum.json): as minimiseSse, with the screening and the starts spread over
/// ranks and threads, then the optional polish. Throws when every simulation of it failed.
void CalibrationRun::optimum() {
  const auto t0 = Clock::now();
  const fs::path opt_path = file("optimum.json");
  if (auto j = readStage(opt_path, fingerprint_); !j.is_null()) {
    res_.optimum = optimumFrom(j.at("optimum"));
    // The later stages replay the steps the optimum's polish was made on: frozen again at the same θ.
    if (options_.steps == "frozen") {
      if (j.contains("steps") && j.at("steps").value("frozen", false))
        objective_->freezeSteps(numbersFromJson(j.at("steps").at("frozen_at")), j.at("steps").value("accuracy", 0.0));
      else objective_->thawSteps();
    }
  } else {
    nlohmann::json screening;
    const std::vector<std::vector<double>> x0 = optimiserStarts(screening);
    const LabObjective& objective = *objective_;
    // Frozen steps: the SSE is a smooth sum of squares, so each start is a Levenberg–Marquardt run
    // (one thread each; the starts share the workers) on forward differences (the polish on the
    // best start's own steps settles it with central ones), stopped when a step gains less than a
    // thousandth of the intervals' threshold c s² ≈ 4 SSE / (n − d).
    const bool lm = objective.stepsFrozen();
    const double dof = n_ > static_cast<int>(d_) ? n_ - static_cast<int>(d_) : std::max(n_, 1);
    const auto packed = distributedMap(
        x0.size(), options_.threads,
        [&](std::size_t i, int) {
          if (!lm) return packStart(minimiseFrom(sse_, objective.lower(), objective.upper(), x0[i], options_.optimizer));
          PolishOptions po;
          po.h = kPolishStepFrozen;
          po.rel_gain = 4e-3 / dof;
          po.forward = true;
          StartResult r = polishLeastSquares(objective, x0[i], po);
          r.status = "LM";
          return packStart(r);
        },
        [&](std::size_t done, std::size_t total) { report("optimum", done, total); });
    std::vector<StartResult> starts;
    for (const auto& v : packed) starts.push_back(unpackStart(v));
    // With frozen steps the starts are least-squares runs already and polishOnOwnSteps polishes
    // the best on its own steps: the derivative-free polish would add nothing.
    if (options_.polish_step > 0 && !lm) polish(starts);
    res_.optimum = collectOptimum(std::move(starts));
    if (options_.steps == "frozen") polishOnOwnSteps();
    rootWrites([&] {
      nlohmann::json stage{{"fingerprint", fingerprint_}, {"optimum", optimumJson(res_.optimum)}, {"steps", stepsJson()}};
      if (!screening.is_null()) stage["screening"] = screening;
      writeFileAtomic(opt_path.string(), stage.dump(2) + "\n");
    });
  }
  if (!std::isfinite(res_.optimum.sse))
    throw std::runtime_error("assembly " + assembly_.id + ": every simulation of the optimiser failed; no calibration possible");
  res_.stage_wall_s.push_back({"optimum", secondsSince(t0)});
}

/// The problem the region's sweeps share: the optimum, n and the bounds.
BoxProblem CalibrationRun::boxProblem() const {
  BoxProblem bp;
  bp.theta_hat = res_.optimum.theta;
  bp.sse_min = res_.optimum.sse;
  bp.n_data = n_;
  bp.lower = objective_->lower();
  bp.upper = objective_->upper();
  bp.validate();
  return bp;
}

/// The paper's box (region = "paper"): as calcFeasibleBox, with the 2d sweeps spread over ranks
/// and threads. Sets res_.box and res_.region; `stage` receives the box.
void CalibrationRun::paperBox(const BoxProblem& bp, nlohmann::json& stage) {
  const auto packed = distributedMap(
      2 * d_, options_.threads,
      [&](std::size_t i, int) { return packSweep(calcBoxSweep(sse_, bp, static_cast<int>(i), options_.box)); },
      [&](std::size_t done, std::size_t total) { report("box", done, total); });
  std::vector<SweepResult> sweeps;
  for (const auto& v : packed) sweeps.push_back(unpackSweep(v));
  res_.box = collectFeasibleBox(bp, std::move(sweeps));
  res_.region = regionFromBox(res_.box, bp);
  stage["box"] = boxJson(res_.box);
}

/// The joint region (region = "joint"): as calcJointRegion, the Jacobian stencil, then the sweeps
/// along the principal axes, then the ridge traces, each spread over ranks and threads. Sets
/// res_.region; `stage` receives the Gauss–Newton model, the sweeps and the traces.
void CalibrationRun::jointRegion(const BoxProblem& bp, nlohmann::json& stage) {
  const LabObjective& objective = *objective_;
  const auto stencil = jacobianStencil(bp, options_.joint);
  const auto residuals = distributedMap(
      stencil.size(), options_.threads, [&](std::size_t i, int) { return objective.residuals(stencil[i]); },
      [&](std::size_t done, std::size_t total) { report("region: Jacobian", done, total); });
  const JointRegionPlan plan = planJointRegion(bp, residuals, options_.joint);
  const auto packed = distributedMap(
      2 * d_, options_.threads,
      [&](std::size_t i, int) { return packRay(calcRegionSweep(sse_, plan, static_cast<int>(i), options_.joint)); },
      [&](std::size_t done, std::size_t total) { report("region: sweeps", done, total); });
  std::vector<RaySweep> sweeps;
  for (const auto& v : packed) sweeps.push_back(unpackRay(v));
  // A smooth SSE (frozen steps): forward differences are enough for the traces' Jacobians.
  JointRegionOptions traceOptions = options_.joint;
  traceOptions.forward_differences = objective.stepsFrozen();
  stage["ridge_differences"] = traceOptions.forward_differences ? "forward" : "central";
  const auto packed_traces = distributedMap(
      2 * ridgeAxes(plan, options_.joint).size(), options_.threads,
      [&](std::size_t i, int) {
        return packTrace(calcRidgeTrace([&](const std::vector<double>& th) { return objective.residuals(th); }, plan, sweeps,
                                        static_cast<int>(i), traceOptions));
      },
      [&](std::size_t done, std::size_t total) { report("region: ridges", done, total); });
  std::vector<RidgeTrace> traces;
  for (const auto& v : packed_traces) traces.push_back(unpackTrace(v, static_cast<int>(d_)));
  res_.region = collectJointRegion(plan, sweeps, traces, options_.joint);
  stage["gauss_newton"] = gaussNewtonJson(plan, sweeps, traces);
}

/// Stage 2, region (box.json): the region the design covers, the joint 1 % contour or the
/// paper's box.
void CalibrationRun::region() {
  const auto t0 = Clock::now();
  const fs::path box_path = file("box.json");
  if (auto j = readStage(box_path, fingerprint_); !j.is_null()) {
    res_.region = Region::fromJson(j.at("region"));
    if (j.contains("box")) res_.box = boxFrom(j.at("box"));
  } else {
    const BoxProblem bp = boxProblem();
    nlohmann::json stage{{"fingerprint", fingerprint_}};
    if (options_.region == "paper") paperBox(bp, stage);
    else jointRegion(bp, stage);
    stage["region"] = res_.region.toJson();
    rootWrites([&] { writeFileAtomic(box_path.string(), stage.dump(2) + "\n"); });
  }
  res_.stage_wall_s.push_back({"region", secondsSince(t0)});
}

/// Opens the design journal on the root (`journal`, null on the other ranks) and returns the
/// points it holds, which every rank learns from the root.
CalibrationRun::ResumedPoints CalibrationRun::openJournal(const std::string& journal_path,
                                                          std::unique_ptr<DesignJournal>& journal) const {
  const std::size_t d = d_;
  const std::vector<double> resumed_flat = bytesToDoubles(onRoot([&]() -> std::string {
    journal = std::make_unique<DesignJournal>(journal_path, static_cast<int>(d), fingerprint_);
    std::vector<double> v;
    for (const auto& e : journal->resumed()) {
      if (e.index < 0) throw InputError(journal->path(), "design index " + std::to_string(e.index) + " is negative");
      v.push_back(static_cast<double>(e.index));
      v.insert(v.end(), e.theta.begin(), e.theta.end());
      v.push_back(e.sse);
    }
    return doublesToBytes(v);
  }));
  ResumedPoints resumed;
  for (std::size_t k = 0; k + d + 2 <= resumed_flat.size(); k += d + 2)
    resumed[static_cast<long>(resumed_flat[k])] = {std::vector<double>(resumed_flat.begin() + static_cast<long>(k) + 1,
                                                                       resumed_flat.begin() + static_cast<long>(k + 1 + d)),
                                                   resumed_flat[k + 1 + d]};
  return resumed;
}

/// The SSEs of one round's points `pts` (design rows first ..): those in `resumed` from there
/// (each checked against the point and taken out of `resumed`), the others simulated and
/// journalled. One process: one loop, each point journalled as it finishes. Several ranks: chunks
/// of 8 points per worker; the root journals its own points as they finish and the others' at the
/// end of each chunk (a killed job loses at most one chunk of them).
std::vector<double> CalibrationRun::evaluateRound(const Eigen::MatrixXd& pts, int first, const std::string& stage,
                                                  DesignJournal* journal, const std::string& journal_path,
                                                  ResumedPoints& resumed) {
  const std::size_t d = d_;
  const std::size_t ranks = static_cast<std::size_t>(Distributed::instance().size());
  const std::size_t m_all = static_cast<std::size_t>(pts.rows());
  std::vector<double> out(m_all, std::numeric_limits<double>::quiet_NaN());
  auto point = [&](std::size_t t) {
    std::vector<double> th(d);
    for (std::size_t k = 0; k < d; ++k) th[k] = pts(static_cast<long>(t), static_cast<long>(k));
    return th;
  };
  std::vector<std::size_t> todo;
  for (std::size_t t = 0; t < m_all; ++t) {
    const long idx = first + static_cast<long>(t);
    const auto it = resumed.find(idx);
    if (it == resumed.end()) {
      todo.push_back(t);
      continue;
    }
    if (it->second.first != point(t))
      throw InputError(journal_path, "design point " + std::to_string(idx) + " differs from this calibration's design");
    out[t] = it->second.second;
    ++res_.resumed_points;
    resumed.erase(it);
  }
  report(stage, m_all - todo.size(), m_all);
  const std::size_t chunk = ranks == 1 ? std::max<std::size_t>(todo.size(), 1)
                                       : 8 * ranks * static_cast<std::size_t>(distributedWorkers(todo.size(), options_.threads));
  for (std::size_t c0 = 0; c0 < todo.size(); c0 += chunk) {
    const std::size_t m = std::min(chunk, todo.size() - c0);
    const auto sse_of = distributedMap(
        m, options_.threads,
        [&](std::size_t t, int) {
          const std::size_t row = todo[c0 + t];
          const auto th = point(row);
          const double s = objective_->sse(th);
          if (journal) journal->append(first + static_cast<long>(row), th, s);  // the root's own points, at once
          return std::vector<double>{s};
        },
        [&](std::size_t done, std::size_t) { report(stage, m_all - todo.size() + c0 + done, m_all); });
    for (std::size_t t = 0; t < m; ++t) out[todo[c0 + t]] = sse_of[t][0];
    if (ranks > 1)
      rootWrites([&] {
        for (std::size_t t = 0; t < m; ++t)
          if (t % ranks != 0) journal->append(first + static_cast<long>(todo[c0 + t]), point(todo[c0 + t]), sse_of[t][0]);
      });
  }
  return out;
}

/// design.csv: every design point with its SSE, round and log design weight.
void CalibrationRun::writeDesignTable() const {
  std::vector<double> round_of(res_.sse.size());
  for (const auto& r : res_.rounds.rounds)
    for (int i = r.first; i < r.first + r.count; ++i) round_of[static_cast<std::size_t>(i)] = r.index;
  rootWrites([&] {
    writeDesignTableCsv(file("design.csv").string(), res_.names, res_.design, res_.sse, "sse",
                        {{"round", round_of}, {"log_design_weight", res_.rounds.log_weight}});
  });
}

/// Stage 3, design (design_journal.csv, design.csv): runAdaptiveDesign, round by round, each
/// point journalled as it finishes; a rerun takes the journalled points from the journal.
void CalibrationRun::design() {
  const auto t0 = Clock::now();
  {
    // The journal lives on the root; every rank learns the journalled points from it.
    const std::string journal_path = file("design_journal.csv").string();
    std::unique_ptr<DesignJournal> journal;
    ResumedPoints resumed = openJournal(journal_path, journal);
    int round_no = 0;
    const DesignEvaluator evaluate = [&](const Eigen::MatrixXd& pts, int first) {
      return evaluateRound(pts, first, "design round " + std::to_string(round_no++), journal.get(), journal_path, resumed);
    };
    res_.rounds = runAdaptiveDesign(res_.region, n_, options_.designOptions(), evaluate);
    if (!resumed.empty())
      throw InputError(journal_path, "holds design point " + std::to_string(resumed.begin()->first) +
                                         ", which this calibration's design does not have (made by another version?); delete it to start over");
  }
  res_.design = res_.rounds.points;
  res_.sse = res_.rounds.sse;
  for (double s : res_.sse) res_.design_failures += std::isfinite(s) ? 0 : 1;
  writeDesignTable();
  res_.stage_wall_s.push_back({"design", secondsSince(t0)});
}

/// Every evaluated point the profile starts from: the design, the optimum, the ridge floor
/// (rows of `pts`, physical units) and their SSEs `f`.
void CalibrationRun::evaluatedPoints(Eigen::MatrixXd& pts, std::vector<double>& f) const {
  const std::size_t d = d_;
  const long extra = 1 + res_.region.ridge.rows();
  pts.resize(res_.design.rows() + extra, static_cast<long>(d));
  f = res_.sse;
  pts.topRows(res_.design.rows()) = res_.design;
  for (std::size_t k = 0; k < d; ++k) pts(res_.design.rows(), static_cast<long>(k)) = res_.optimum.theta[k];
  f.push_back(res_.optimum.sse);
  for (Eigen::Index q = 0; q < res_.region.ridge.rows(); ++q) {
    const auto th = res_.region.toPhysical(res_.region.ridge.row(q).transpose());
    for (std::size_t k = 0; k < d; ++k) pts(res_.design.rows() + 1 + q, static_cast<long>(k)) = th[k];
    f.push_back(res_.region.ridge_sse[static_cast<std::size_t>(q)]);
  }
}

/// The optimiser's start ends other than the optimum, with their SSEs on the steps the later stages
/// replay, appended to the evaluated points: a second basin that the data cannot tell from the
/// optimum's lies inside the threshold, and the profile's intervals must span it (the design,
/// drawn around the optimum, never sees it).
void CalibrationRun::appendStartEnds(Eigen::MatrixXd& pts, std::vector<double>& f) const {
  std::vector<std::vector<double>> ends;
  for (const auto& st : res_.optimum.starts)
    if (st.theta.size() == d_ && std::isfinite(st.sse) && st.theta != res_.optimum.theta) ends.push_back(st.theta);
  if (ends.empty()) return;
  const auto out = distributedMap(
      ends.size(), options_.threads, [&](std::size_t i, int) { return std::vector<double>{objective_->sse(ends[i])}; },
      [&](std::size_t done, std::size_t total) { report("profile: optimiser ends", done, total); });
  const Eigen::Index r0 = pts.rows();
  pts.conservativeResize(r0 + static_cast<Eigen::Index>(ends.size()), Eigen::NoChange);
  for (std::size_t i = 0; i < ends.size(); ++i) {
    for (std::size_t k = 0; k < d_; ++k) pts(r0 + static_cast<Eigen::Index>(i), static_cast<long>(k)) = ends[i][k];
    f.push_back(out[i][0]);
  }
}

/// The warning for the other basins profile() found (profile.json "other_basins").
void CalibrationRun::warnOtherBasins(const nlohmann::json& basins) {
  if (!basins.is_array() || basins.empty()) return;
  std::string where;
  for (std::size_t k = 0; k < d_ && k < basins[0].at("theta").size(); ++k)
    where += (k ? ", " : "") + res_.names[k] + " = " + formatNumber(basins[0].at("theta")[k].get<double>(), 4);
  res_.warnings.push_back(std::to_string(basins.size()) + " optimiser start(s) ended in another basin that the data cannot reject (e.g. " +
                          where + "): the 95 % profile intervals span it and the optimum's basin; the posterior and the design see only the optimum's");
}

CorrelationAdjustment CalibrationRun::timeCorrelation() {
  const LabObjective& objective = *objective_;
  const std::vector<int> blocks = timeBlocks(objective.times(), objective.dataSetOf(), objective.repetitions());
  if (blocks.empty() || blocks.front() < 0) return {};
  // The weighted residuals' Jacobian at the optimum: forward differences in scaled units, each
  // step towards the inside of the bounds (κ does not depend on the parameters' scales).
  const std::vector<double>& theta = res_.optimum.theta;
  const double h = objective.stepsFrozen() ? kPolishStepFrozen : kPolishStep;
  const auto scaled_step = [&](std::size_t j) {  // h, or −h where +h would leave the bounds
    return theta[j] + h * (objective.upper()[j] - objective.lower()[j]) <= objective.upper()[j] ? h : -h;
  };
  const auto runs = distributedMap(
      d_ + 1, options_.threads,
      [&](std::size_t k, int) {
        std::vector<double> th = theta;
        if (k > 0) th[k - 1] += scaled_step(k - 1) * (objective.upper()[k - 1] - objective.lower()[k - 1]);
        return objective.residuals(th);
      },
      [&](std::size_t done, std::size_t total) { report("profile: residual correlation", done, total); });
  const auto n = static_cast<Eigen::Index>(runs[0].size());
  if (n != n_) return {};
  const Eigen::Map<const Eigen::VectorXd> r0(runs[0].data(), n);
  Eigen::MatrixXd J(n, static_cast<Eigen::Index>(d_));
  for (std::size_t j = 0; j < d_; ++j) {
    if (static_cast<Eigen::Index>(runs[j + 1].size()) != n) return {};
    J.col(static_cast<Eigen::Index>(j)) = (Eigen::Map<const Eigen::VectorXd>(runs[j + 1].data(), n) - r0) / scaled_step(j);
  }
  const double s2 = res_.optimum.sse / static_cast<double>(n_ > static_cast<int>(d_) ? n_ - static_cast<int>(d_) : n_);
  return blockAdjustment(J, r0, blocks, s2, options_.profile.level);
}

/// Stage 4, profile (profile.json): the profile-likelihood intervals, from every evaluated point
/// (the design, the ridge floor, the optimum), each end pushed out by profile steps.
void CalibrationRun::profile() {
  const auto t0 = Clock::now();
  res_.interval = options_.interval;
  const fs::path profile_path = file("profile.json");
  nlohmann::json basins;
  if (auto j = readStage(profile_path, fingerprint_); !j.is_null()) {
    res_.profile = ProfileIntervals::fromJson(j.at("profile"));
    basins = j.value("other_basins", nlohmann::json::array());
  } else {
    Eigen::MatrixXd pts;
    std::vector<double> f;
    evaluatedPoints(pts, f);
    const Eigen::Index first_end = pts.rows();
    appendStartEnds(pts, f);
    const LabObjective& objective = *objective_;
    const ProfilePlan plan = planProfile(pts, f, n_, objective.lower(), objective.upper(), options_.profile, timeCorrelation());
    // An optimiser start that ended in another basin the data cannot reject (inside the threshold,
    // a parameter more than a tenth of its range from the optimum): the intervals span both.
    basins = nlohmann::json::array();
    for (Eigen::Index q = first_end; q < pts.rows(); ++q) {
      if (!(f[static_cast<std::size_t>(q)] <= *std::max_element(plan.thresholds.begin(), plan.thresholds.end()))) continue;
      bool far = false;
      for (std::size_t k = 0; k < d_; ++k)
        far = far || std::abs(pts(q, static_cast<long>(k)) - res_.optimum.theta[k]) > 0.1 * (objective.upper()[k] - objective.lower()[k]);
      if (far) {
        std::vector<double> th(d_);
        for (std::size_t k = 0; k < d_; ++k) th[k] = pts(q, static_cast<long>(k));
        basins.push_back({{"theta", jsonNumbers(th)}, {"sse", jsonNumber(f[static_cast<std::size_t>(q)])}});
      }
    }
    // A smooth SSE (frozen steps): forward differences are enough for the profile points' Jacobians.
    ProfileOptions po = options_.profile;
    po.forward_differences = objective.stepsFrozen();
    const auto packed = distributedMap(
        2 * d_, options_.threads,
        [&](std::size_t i, int) {
          return packProfileEnd(refineProfileEnd([&](const std::vector<double>& th) { return objective.residuals(th); }, plan,
                                                 static_cast<int>(i), po));
        },
        [&](std::size_t done, std::size_t total) { report("profile", done, total); });
    std::vector<ProfileEnd> ends;
    for (const auto& v : packed) ends.push_back(unpackProfileEnd(v));
    res_.profile = collectProfile(plan, ends, options_.profile);
    rootWrites([&] {
      writeFileAtomic(profile_path.string(),
                      nlohmann::json{{"fingerprint", fingerprint_},
                                     {"profile", res_.profile.toJson()},
                                     {"differences", po.forward_differences ? "forward" : "central"},
                                     {"other_basins", basins}}
                              .dump(2) + "\n");
    });
  }
  warnOtherBasins(basins);
  res_.stage_wall_s.push_back({"profile", secondsSince(t0)});
}

/// posterior.csv: θ, τ and the design index of every kept Gibbs iteration.
void CalibrationRun::writePosterior() const {
  rootWrites([&] {
    std::vector<std::vector<double>> rows;
    std::vector<long> index;
    for (std::size_t t = 0; t < res_.chains.index.size(); ++t) {
      const int k = res_.chains.index[t];
      std::vector<double> row(d_);
      for (std::size_t c = 0; c < d_; ++c) row[c] = res_.design(k, static_cast<long>(c));
      rows.push_back(std::move(row));
      index.push_back(k);
    }
    writeFileAtomic(file("posterior.csv").string(), posteriorCsv(res_.names, rows, res_.chains.tau, index));
  });
}

/// Stage 5, sampler (posterior.csv): the two-block Griddy Gibbs with the design weights and the
/// posterior summaries. Cheap and deterministic from the seed: never persisted half-way, always
/// rerun.
void CalibrationRun::sampler() {
  const auto t0 = Clock::now();
  report("gibbs", 0, 1);
  res_.chains = runGriddyGibbs(res_.sse, n_, options_.gibbsOptions(), res_.rounds.log_weight);
  res_.posterior = summarisePosterior(res_.design, res_.chains, res_.names);
  report("gibbs", 1, 1);
  writePosterior();
  res_.stage_wall_s.push_back({"gibbs", secondsSince(t0)});
}

/// Stage 6, the integrator check (IntegratorCheck): two simulations at the optimum, one at a tenth
/// of the accuracy the steps were chosen at; with frozen steps, the probes of probeBias along
/// every axis as well. Deterministic: never persisted, always rerun.
void CalibrationRun::integratorCheck() {
  const auto t0 = Clock::now();
  const double threshold = res_.profile.threshold - res_.profile.sse_best;
  const std::vector<double>& theta = res_.optimum.theta;
  if (!std::isfinite(res_.optimum.sse) || theta.size() != d_) return;
  const double accuracy = objective_->stepsFrozen() ? objective_->stepsFrozenAccuracy() : study_.simulation.accuracy;
  report("integrator check", 0, 1);
  LabObjective fine = fineObjective(accuracy);
  const std::vector<double> eta = objective_->predict(theta), eta_fine = fine.predict(theta);
  report("integrator check", 1, 1);
  if (eta.empty() || eta_fine.empty()) return;  // a failed run: no check (ok, zero figures)
  res_.integrator = assessIntegrator(eta, eta_fine, objective_->measured(), objective_->weights(), accuracy, threshold);
  if (objective_->stepsFrozen() && fine.freezeSteps(theta)) {
    // Probe steps: a tenth of each profile half-width, in [1e-4, 1e-2] of the bounds' range.
    std::vector<double> h(d_);
    for (std::size_t k = 0; k < d_; ++k) {
      const double range = objective_->upper()[k] - objective_->lower()[k];
      const double half = k < res_.profile.lower.size() && std::isfinite(res_.profile.upper[k] - res_.profile.lower[k])
                              ? 0.5 * (res_.profile.upper[k] - res_.profile.lower[k]) / range
                              : 1e-1;
      h[k] = std::clamp(half / 10, 1e-4, 1e-2);
    }
    const BiasProbe p = probeBias(fine, theta, h, true, "integrator check: probes");
    if (p.ok) applyProbes(res_.integrator, p.roughness, p.shift, p.shift_floor);
  }
  res_.stage_wall_s.push_back({"integrator check", secondsSince(t0)});
}

/// The objective of the study with adaptive steps at `accuracy` / 10: the integrator check's reference.
LabObjective CalibrationRun::fineObjective(double accuracy) const {
  Study tight = study_;
  tight.simulation.accuracy = accuracy / 10;
  return LabObjective(tight, assembly_, data_, setup_);
}

/// The integrator's bias at θ on frozen steps (IntegratorCheck): along each parameter's axis k,
/// frozen-step runs of the objective at offsets −2..2 (`five`) or −1, +1 times h_k (scaled units;
/// the points moved inside the bounds) and runs of `fine` (steps frozen at a tenth of the accuracy)
/// at −1 and +1. The roughness is the largest departure of an axis's five SSEs from their
/// quadratic (NaN with three points); the residuals' Jacobian and the gradient of SSE − SSE_fine
/// come from the runs at ±1 by central differences, and give the shift (integratorOptimumShift).
CalibrationRun::BiasProbe CalibrationRun::probeBias(const LabObjective& fine, const std::vector<double>& theta,
                                                    const std::vector<double>& h, bool five, const std::string& stage) const {
  const std::size_t d = d_;
  const auto& lo = objective_->lower();
  const auto& up = objective_->upper();
  const int reach = five ? 2 : 1;
  std::vector<int> offsets;
  for (int o = -reach; o <= reach; ++o)
    if (o != 0 || five) offsets.push_back(o);
  const std::size_t frozen = offsets.size(), per = frozen + 2;  // then -1 and +1 on `fine`
  std::vector<double> centre(d);
  for (std::size_t k = 0; k < d; ++k) centre[k] = std::clamp((theta[k] - lo[k]) / (up[k] - lo[k]), reach * h[k], 1 - reach * h[k]);
  auto point = [&](std::size_t k, int offset) {
    std::vector<double> th(d);
    for (std::size_t j = 0; j < d; ++j) th[j] = lo[j] + (j == k ? centre[j] + offset * h[j] : centre[j]) * (up[j] - lo[j]);
    return th;
  };
  const auto out = distributedMap(
      per * d, options_.threads,
      [&](std::size_t t, int) -> std::vector<double> {
        const std::size_t k = t / per, which = t % per;
        if (which < frozen) return objective_->residuals(point(k, offsets[which]));
        return {fine.sse(point(k, which == frozen ? -1 : 1))};
      },
      [&](std::size_t done, std::size_t total) { report(stage, done, total); });
  BiasProbe p;
  Eigen::MatrixXd J(n_, static_cast<long>(d));
  Eigen::VectorXd g(static_cast<long>(d)), g_floor = Eigen::VectorXd::Zero(static_cast<long>(d));
  p.roughness = five ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < d; ++k) {
    std::vector<double> x, f;
    const Eigen::VectorXd* rm = nullptr;
    const Eigen::VectorXd* rp = nullptr;
    std::vector<Eigen::VectorXd> r(frozen);
    for (std::size_t o = 0; o < frozen; ++o) {
      const auto& v = out[k * per + o];
      if (v.size() != static_cast<std::size_t>(n_)) return p;  // a failed run: no figures (p.ok false)
      r[o] = Eigen::Map<const Eigen::VectorXd>(v.data(), n_);
      x.push_back(offsets[o]);
      f.push_back(r[o].squaredNorm());
      if (offsets[o] == -1) rm = &r[o];
      if (offsets[o] == 1) rp = &r[o];
    }
    const double fine_minus = out[k * per + frozen][0], fine_plus = out[k * per + frozen + 1][0];
    if (!std::isfinite(fine_minus) || !std::isfinite(fine_plus)) return p;
    if (five) {
      const double r_k = quadraticRoughness(x, f);
      p.roughness = std::max(p.roughness, r_k);
      g_floor[static_cast<long>(k)] = r_k / h[k];
    }
    J.col(static_cast<long>(k)) = (*rp - *rm) / (2 * h[k]);
    g[static_cast<long>(k)] = ((rp->squaredNorm() - rm->squaredNorm()) - (fine_plus - fine_minus)) / (2 * h[k]);
  }
  p.shift = integratorOptimumShift(J, g);
  p.shift_floor = integratorOptimumShift(J, g_floor);
  p.ok = true;
  return p;
}

/// Stage 7, summary (summary.json): the result (CalibrationResult::toJson) with how it was made:
/// program, command, study, data sets, setup and options.
void CalibrationRun::summary() {
  res_.stage_wall_s.push_back({"total", secondsSince(t_all_)});
  res_.median_run_wall_s = objective_->medianWallSeconds();
  findBoundFindings();

  nlohmann::json j = res_.toJson();
  j["program"] = programInfo();
  j["command"] = options_.command;
  j["created_utc"] = utcNow();
  j["study"] = study_.path;
  j["scenario"] = data_.front().scenario;
  std::size_t records = 0;
  for (const auto& ds : data_) records += ds.data.records.size();
  j["data"] = {{"path", options_.data_path}, {"records", records}, {"fnv1a64", fingerprint_extra_}};
  j["data_sets"] = nlohmann::json::array();
  for (const auto& ds : data_)
    j["data_sets"].push_back({{"name", ds.name},
                              {"scenario", ds.scenario},
                              {"records", ds.data.records.size()},
                              {"road_seed", ds.road_seed ? nlohmann::json(*ds.road_seed) : nlohmann::json(study_.seed)}});
  j["setup"] = setup_.toJson();
  j["options"] = options_.toJson();
  j["threads"] = options_.threads;
  rootWrites([&] { writeFileAtomic(file("summary.json").string(), j.dump(2) + "\n"); });
}

}  // namespace

CalibrationResult calibrateAssembly(const Study& study, const AssemblySpec& assembly, const LabData& data,
                                    const std::string& scenario, const CalibrationOptions& options,
                                    const std::string& out_dir, const std::string& fingerprint_extra,
                                    const StageProgress& progress) {
  return calibrateAssembly(study, assembly, std::vector<DataSet>{DataSet{"lab data", scenario, data}}, CalibrationSetup{},
                           options, out_dir, fingerprint_extra, progress);
}

CalibrationResult calibrateAssembly(const Study& study, const AssemblySpec& assembly, const std::vector<DataSet>& data,
                                    const CalibrationSetup& setup, const CalibrationOptions& options,
                                    const std::string& out_dir, const std::string& fingerprint_extra,
                                    const StageProgress& progress) {
  options.validate();
  CalibrationRun run(study, assembly, data, setup, options, out_dir, fingerprint_extra, progress);
  run.objective();  // the SSE against the data, the output folder, the resume fingerprint
  run.optimum();    // optimum.json
  run.region();     // box.json
  run.design();     // design_journal.csv, design.csv
  run.profile();    // profile.json
  run.sampler();    // posterior.csv
  run.integratorCheck();
  run.summary();    // summary.json
  return run.take();
}

CalibrationResult calibrateOptimum(const Study& study, const AssemblySpec& assembly, const std::vector<DataSet>& data,
                                   const CalibrationSetup& setup, const CalibrationOptions& options,
                                   const std::string& out_dir, const std::string& fingerprint_extra,
                                   const StageProgress& progress) {
  options.validate();
  CalibrationRun run(study, assembly, data, setup, options, out_dir, fingerprint_extra, progress);
  run.objective();
  run.optimum();  // optimum.json: a later calibrateAssembly of the same folder resumes from it
  return run.takeOptimum();
}

}  // namespace dtwin::calib
