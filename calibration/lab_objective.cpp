// LabObjective: the weighted SSE of an assembly against measured data sets (its simulators, runs,
// predictions, sensor-model distortion and frozen integrator steps).
#include "calibration/calibrate.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <tuple>

#include "common/errors.hpp"
#include "common/format.hpp"

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

LabObjective::LabObjective(const Study& study, const AssemblySpec& assembly, const LabData& data,
                           const std::string& scenario,
                           const std::vector<EffectSetting>& extra_effects)
    : LabObjective(study, assembly, std::vector<DataSet>{DataSet{"lab data", scenario, data}}, [&] {
        CalibrationSetup s;
        s.extra_effects = extra_effects;
        return s;
      }()) {}

LabObjective::LabObjective(const Study& study, const AssemblySpec& assembly,
                           const std::vector<DataSet>& data, const CalibrationSetup& setup)
    : pool_(std::make_unique<Pool>()) {
  AssemblySpec spec = assembly;
  spec.freed.insert(spec.freed.end(), setup.freed.begin(), setup.freed.end());
  for (const auto& swap :
       setup.options) {  // (subsystem, option); no structured binding: a lambda captures it
    const std::string& sub = swap.first;
    const auto it = std::find_if(spec.options.begin(), spec.options.end(),
                                 [&](const auto& o) { return o.first == sub; });
    if (it == spec.options.end())
      throw InputError("calibration setup",
                       "assembly " + assembly.id + " has no subsystem '" + sub + "'");
    it->second = swap.second;
  }
  model_ = study.makeModel(spec, setup.extra_effects);
  if (study.calibrated.empty())
    throw InputError(study.path + ": calibrated", "the study names no calibrated parameters");
  if (data.empty()) throw InputError("calibration", "no data sets given");
  const auto channels = Simulator::channels(model_->sensors());
  // A sensor model's parameter distorts the predictions (distort); it is no run parameter.
  auto sensorModelOf = [&](const std::string& name,
                           const std::string& where) -> std::optional<SensorModelUse> {
    for (const auto& m : setup.sensor_models) {
      if (name != m.name + "." + sensorModelParameter(m.kind, where).name) continue;
      SensorModelUse use{m.kind, {}, names_.size()};
      for (const auto& ch : m.channels) {
        const auto it = std::find_if(channels.begin(), channels.end(),
                                     [&](const Channel& k) { return k.name == ch; });
        if (it == channels.end())
          throw InputError(where, "sensor model " + m.name + ": unknown channel '" + ch + "'");
        use.columns.push_back(static_cast<int>(it - channels.begin()));
      }
      return use;
    }
    return std::nullopt;
  };
  auto add = [&](const CalibratedParameter& c, const std::string& where) {
    const auto sensor_model = sensorModelOf(c.name, where);
    if (!sensor_model &&
        model_->lacksOptionParameter(
            c.name)) {  // e.g. tire.stiffness of an assembly whose road enters at the hub
      left_out_.push_back(c.name);
      return;
    }
    const int slot = sensor_model ? -1 : model_->slot(c.name);
    if (!sensor_model && slot < 0)
      throw InputError(where, "'" + c.name + "' is not a parameter of assembly " + assembly.id +
                                  " (" + model_->assembly().label() + ")");
    if (std::find(names_.begin(), names_.end(), c.name) != names_.end())
      throw InputError(where, "'" + c.name + "' is calibrated twice");
    double lower = c.lower, upper = c.upper;
    if (const auto b = setup.bounds.find(c.name); b != setup.bounds.end())
      std::tie(lower, upper) = b->second;
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
    if (std::none_of(sensor_models_.begin(), sensor_models_.end(), [&](const SensorModelUse& u) {
          return names_[u.theta_index].rfind(m.name + ".", 0) == 0;
        }))
      throw InputError("sensor model " + m.name,
                       "its parameter is not calibrated (add it to extra_calibrated)");
  rate_hz_ = study.simulation.output_rate_hz;
  base_values_ = model_->defaultRunValues();
  for (const auto& [c, w] : setup.channel_weights)
    if (!(std::isfinite(w) && w > 0))
      throw InputError("channel weight of " + c, "must be finite and > 0");
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
    if (col < 0)
      throw InputError(prefix + std::to_string(i + 1), "unknown channel '" + r.channel + "'");
    if (!(r.time_s >= 0.0 && r.time_s <= set.scenario.duration_s))
      throw InputError(prefix + std::to_string(i + 1),
                       "time_s " + formatExact(r.time_s) + " lies outside scenario '" +
                           set.scenario.name + "' (0.." + formatExact(set.scenario.duration_s) +
                           " s)");
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
      w.index =
          static_cast<std::size_t>(std::lower_bound(extra.begin(), extra.end(), t) - extra.begin());
    }
  }
  // The sampled run: every record's time a sample time, a grid time as the grid's own r / rate.
  set.sampled = set.scenario;
  set.sampled.grid_output = false;
  std::vector<double>& all = set.sampled.sample_times_s;
  all.clear();
  auto sampleTime = [&](std::size_t i) {
    const double t = ds.data.records[i].time_s;
    return onGrid(t, rate) ? static_cast<double>(std::llround(t * rate)) / rate : t;
  };
  for (std::size_t i = 0; i < set.count; ++i) all.push_back(sampleTime(i));
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  for (std::size_t i = 0; i < set.count; ++i)
    sampled_row_.push_back(static_cast<std::size_t>(
        std::lower_bound(all.begin(), all.end(), sampleTime(i)) - all.begin()));
  sets_.push_back(std::move(set));
}

bool LabObjective::sampledPredictions() const {
  return sensor_models_.empty() &&
         std::none_of(model_->sensors().begin(), model_->sensors().end(),
                      [](const SensorSpec& x) { return x.filter.order > 0; });
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

std::vector<RunResult> LabObjective::runAll(const std::vector<double>& theta, bool sampled) const {
  const std::vector<double> values = runValues(theta);
  pool_->evaluations++;
  auto sim = pool_->acquire();
  std::vector<RunResult> out;
  double wall = 0.0;
  for (const auto& set : sets_) {
    RunResult r;
    try {
      StepControl steps;
      if (!plans_.empty())
        steps.replay = plans_[static_cast<std::size_t>(&set - sets_.data())].get();
      r = sim->run(values, *set.road, sampled ? set.sampled : set.scenario, steps);
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
      ok = sim->run(values, *set.road, sampledPredictions() ? set.sampled : set.scenario, steps)
               .stats.ok;
    } catch (const InputError&) {
      ok = false;
    }
    if (!ok) break;
    plans.push_back(std::move(plan));
  }
  if (!own)
    pool_->release(std::move(sim), std::nullopt);  // not an evaluation: no wall time recorded
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
  DTWIN_CHECK(column < tr.channels().size() && w.index < tr.rows(),
              "read: record outside its run's output");
  return tr.column(column)[w.index];
}

std::vector<double> LabObjective::predict(const std::vector<double>& theta) const {
  const bool sampled = sampledPredictions();
  const auto rs = runAll(theta, sampled);
  if (rs.size() != sets_.size() || !rs.back().stats.ok) return {};
  std::vector<double> eta(y_.size());
  if (sampled) {  // every record a row of its run's samples, bit for bit the value of the grid path
    for (std::size_t k = 0; k < sets_.size(); ++k)
      for (std::size_t i = sets_[k].first; i < sets_[k].first + sets_[k].count; ++i) {
        const Trace& tr = rs[k].samples;
        if (sampled_row_[i] >= tr.rows()) return {};
        eta[i] = tr.column(static_cast<std::size_t>(where_[i].column))[sampled_row_[i]];
      }
    return eta;
  }
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

void LabObjective::distort(const std::vector<double>& theta, const std::vector<RunResult>& runs,
                           std::vector<double>& eta) const {
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
      const auto v = distortChannel(runs[k].trace.column(static_cast<std::size_t>(column)),
                                    rate_hz_, times, d);
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

}  // namespace dtwin::calib
