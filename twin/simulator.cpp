#include "twin/simulator.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "twin/recorder.hpp"
#include "twin/static_start.hpp"
#include "twin/stepper.hpp"
#include "twin/vehicle_system.hpp"

namespace dtwin {
using namespace SimTK;

// ----------------------------------------------------------------------- Impl
/// One built system and the parts that run on it: the static start, the stepper and the recorder
/// (twin/vehicle_system.hpp, static_start.hpp, stepper.hpp, recorder.hpp). A run validates its
/// inputs and sets the system's context (begin), then starts, steps and records.
struct Simulator::Impl {
  std::shared_ptr<const Model> model;
  SimulationOptions opt;
  sim::VehicleSystem sys;
  sim::StaticStart start{sys};
  sim::Stepper stepper{sys, opt};
  sim::Recorder recorder{sys, opt};

  /// `with_filter_states`: the system that also integrates StrutFilter effects' auxiliary states.
  Impl(std::shared_ptr<const Model> m, SimulationOptions o, bool with_filter_states = false)
      : model(std::move(m)),
        opt(validated(std::move(o))),
        sys(*model, with_filter_states, opt.hub_motion == "link") {}

  static SimulationOptions validated(SimulationOptions o) {
    o.validate();
    return o;
  }

  using Knots = sim::Knots;
  using Segments = sim::Segments;

  /// Validates the run vector and the scenario and points the force elements at them.
  void begin(const std::vector<double>& values, const Road& road, const ScenarioSpec& sc) {
    const Model& M = *model;
    if (values.size() != M.runParameterNames().size())
      throw InputError("run parameters",
                       "expected " + std::to_string(M.runParameterNames().size()) + " values");
    const std::string rule = M.checkRunValues(values);
    if (!rule.empty()) throw InputError("run parameters", rule);
    if (!(sc.duration_s > 0)) throw InputError("scenario " + sc.name, "duration_s must be > 0");
    sys.ctx.p = values.data();
    sys.ctx.road = &road;
    sys.ctx.speed = sc.speed;
    sys.ctx.gain_slot = static_cast<std::size_t>(M.roadGainSlot());
    sys.ctx.delay_slot = static_cast<std::size_t>(M.roadDelaySlot());
    sys.ctx.form_slot = static_cast<std::size_t>(M.roadFormSlot());
    sys.ctx.wheelbase = M.vehicle().wheelbase();
  }

  /// The branch time of a random road with a smooth start (smooth_until_s - margin), or a
  /// negative value when the scenario has none.
  double branchTime(const ScenarioSpec& sc) const {
    if (const double t = sc.road->roughStart_s(); t > 0) return t - opt.obstacle_margin_before_s;
    return -1.0;
  }

  /// Integration segments with their step bound (integrationSegments, simulator.hpp).
  Segments segments(const Road& road, const ScenarioSpec& sc) const {
    return integrationSegments(road, sc, opt, model->vehicle().wheelbase());
  }

  RunResult run(const std::vector<double>& values, const Road& road, const ScenarioSpec& sc,
                StepControl steps) {
    const auto t_start = std::chrono::steady_clock::now();
    begin(values, road, sc);
    if ((steps.replay || steps.record) && opt.integrator != "rosenbrock")
      throw InputError(
          "simulation.integrator",
          "a frozen step sequence needs the rosenbrock integrator, not '" + opt.integrator + "'");
    RunResult res;
    Knots knots;
    std::vector<double> times;
    const State s = start.state();
    const Segments segs = segments(road, sc);
    res.stats = stepper.integrate(s, segs, 0, segs.size(), true, knots, times, nullptr, steps);
    recorder.finish(knots, times, sc, res);
    res.stats.wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    return res;
  }

  std::vector<RunResult> runBranched(const std::vector<double>& values,
                                     const std::vector<const Road*>& roads,
                                     const ScenarioSpec& sc) {
    using Clock = std::chrono::steady_clock;
    const auto t_start = Clock::now();
    if (roads.empty()) throw InputError("runBranched", "needs at least one road");
    for (std::size_t r = 0; r < roads.size(); ++r)
      if (!roads[r]) throw InputError("runBranched", "road " + std::to_string(r) + " is null");
    const double tb = branchTime(sc);
    if (!(tb > 0))
      throw InputError("scenario " + sc.name,
                       "cannot branch: the road has no smooth start (needs an iso8608 road with "
                       "smooth_until_s > "
                       "obstacle_margin_before_s = " +
                           std::to_string(opt.obstacle_margin_before_s) + " s)");
    if (!(tb < sc.duration_s))
      throw InputError("scenario " + sc.name, "cannot branch: the smooth part (to " +
                                                  std::to_string(tb) +
                                                  " s) covers the whole run (duration " +
                                                  std::to_string(sc.duration_s) + " s)");
    begin(values, *roads[0], sc);
    const Segments segs = segments(*roads[0], sc);
    std::size_t ib = segs.size();
    for (std::size_t i = 0; i < segs.size(); ++i)
      if (segs[i].first == tb) ib = i;
    if (ib == segs.size())
      throw InputError("scenario " + sc.name,
                       "cannot branch: no integration segment ends at the branch time " +
                           std::to_string(tb) +
                           " s (an obstacle window overlaps the smooth part's end)");
    // Every road must share the segments and the smooth part (the scenario's road, other seed).
    for (std::size_t r = 1; r < roads.size(); ++r) {
      if (segments(*roads[r], sc) != segs)
        throw InputError("runBranched",
                         "road " + std::to_string(r) + " has other obstacle windows than road 0");
      const double x_hi = sc.speed.distance(tb) + 0.1,
                   x_lo = sc.speed.distance(0) - model->vehicle().wheelbase() - 1.0;
      for (double x = x_lo; x <= x_hi; x += 0.05)
        for (int c = 0; c < 4; ++c) {
          const RoadSample a = roads[0]->sampleAt(c, x), b = roads[r]->sampleAt(c, x);
          if (a.height_m != b.height_m || a.slope != b.slope)
            throw InputError("runBranched",
                             "road " + std::to_string(r) +
                                 " differs from road 0 before the branch point (x = " +
                                 std::to_string(x) + " m): the roads must share the smooth start");
        }
    }
    // The common part, once.
    Knots knots0;
    std::vector<double> times0;
    State at_branch;
    const RunStats common =
        stepper.integrate(start.state(), segs, 0, ib + 1, true, knots0, times0, &at_branch);
    const double common_wall = std::chrono::duration<double>(Clock::now() - t_start).count();
    const double share = common_wall / static_cast<double>(roads.size());
    std::vector<RunResult> out(roads.size());
    for (std::size_t r = 0; r < roads.size(); ++r) {
      const auto t_branch = Clock::now();
      RunResult& res = out[r];
      sys.ctx.road = roads[r];
      Knots knots = knots0;
      std::vector<double> times = times0;
      if (common.ok) {
        State s = at_branch;
        s.invalidateAllCacheAtOrAbove(
            Stage::Time);  // forces are re-evaluated on this branch's road
        res.stats = stepper.integrate(s, segs, ib + 1, segs.size(), false, knots, times, nullptr);
        res.stats.steps += common.steps;
        res.stats.steps_attempted += common.steps_attempted;
      } else {
        res.stats = common;
      }
      recorder.finish(knots, times, sc, res);
      res.stats.wall_s = share + std::chrono::duration<double>(Clock::now() - t_branch).count();
    }
    return out;
  }
};

Simulator::Simulator(std::shared_ptr<const Model> model, SimulationOptions options)
    : impl_(std::make_unique<Impl>(std::move(model), std::move(options))) {}
Simulator::~Simulator() = default;
const Model& Simulator::model() const { return *impl_->model; }
const SimulationOptions& Simulator::options() const { return impl_->opt; }
Simulator::Impl& Simulator::pick(const std::vector<double>& values) {
  if (values.size() != impl_->model->runParameterNames().size())
    return *impl_;  // begin() reports it
  if (!impl_->model->builtFor(values)) {
    // A freed vehicle value (a mass, an inertia) is part of the multibody system: rebuild it.
    impl_ = std::make_unique<Impl>(impl_->model->withFreedValues(values), impl_->opt);
    impl_filter_.reset();
  }
  const Model& M = *impl_->model;
  bool active = false;
  for (std::size_t i = 0; i < M.effects().size(); ++i)
    if (M.effects()[i]->kind() == EffectKind::StrutFilter)
      active =
          active || M.effects()[i]->filterActive(ParamValues(values.data() + M.effectSlots()[i][0],
                                                             M.effects()[i]->parameters().size()));
  if (!active) return *impl_;
  if (!impl_filter_) impl_filter_ = std::make_unique<Impl>(impl_->model, impl_->opt, true);
  return *impl_filter_;
}
namespace {
/// A run that could not start because the multibody system cannot be built with the run's freed
/// values: a failed run (its SSE is infinite, as any failed run's), in plain words with the values.
RunResult unbuildableRun(const Model& model, const std::vector<double>& values,
                         const std::vector<Channel>& channels) {
  RunResult r;
  r.stats.ok = false;
  std::string at;
  for (int s : model.freedSlots())
    at += (at.empty() ? "" : ", ") + model.runParameterNames()[static_cast<std::size_t>(s)] +
          " = " + formatNumber(values[static_cast<std::size_t>(s)]);
  r.stats.message = "the vehicle cannot be built with " +
                    (at.empty() ? std::string("these values") : at) +
                    ": the multibody model refuses these masses or inertias";
  for (const auto& ch : channels) r.trace.addChannel(ch);
  return r;
}
}  // namespace

Simulator::Impl* Simulator::pickBuildable(const std::vector<double>& values) {
  try {
    return &pick(values);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception&) {
    return nullptr;  // the multibody library refused the rebuilt system
  }
}
RunResult Simulator::run(const std::vector<double>& values, const Road& road,
                         const ScenarioSpec& sc, StepControl steps) {
  if (Impl* impl = pickBuildable(values)) return impl->run(values, road, sc, steps);
  return unbuildableRun(*impl_->model, values, channels(impl_->model->sensors()));
}
std::vector<RunResult> Simulator::runBranched(const std::vector<double>& values,
                                              const std::vector<const Road*>& roads,
                                              const ScenarioSpec& sc) {
  if (Impl* impl = pickBuildable(values)) return impl->runBranched(values, roads, sc);
  return std::vector<RunResult>(
      roads.size(), unbuildableRun(*impl_->model, values, channels(impl_->model->sensors())));
}
double Simulator::branchTime(const ScenarioSpec& sc) const { return impl_->branchTime(sc); }

std::vector<std::pair<double, double>> integrationSegments(const Road& road, const ScenarioSpec& sc,
                                                           const SimulationOptions& opt,
                                                           double wheelbase) {
  // The windows in time while a wheel (front: offset 0, rear: the wheelbase) is near an obstacle.
  std::vector<Interval> w;
  for (const auto& ob : road.obstacles())
    for (double offset : {0.0, wheelbase}) {
      const double t0 = sc.speed.timeAtDistance(ob.lo + offset) - opt.obstacle_margin_before_s;
      const double t1 = sc.speed.timeAtDistance(ob.hi + offset) + opt.obstacle_margin_after_s;
      if (t1 > 0 && t0 < sc.duration_s)
        w.push_back({std::max(0.0, t0), std::min(sc.duration_s, t1)});
    }
  std::sort(w.begin(), w.end(), [](auto& a, auto& b) { return a.lo < b.lo; });
  std::vector<Interval> merged;
  for (auto& i : w) {
    if (!merged.empty() && i.lo <= merged.back().hi)
      merged.back().hi = std::max(merged.back().hi, i.hi);
    else
      merged.push_back(i);
  }
  std::vector<std::pair<double, double>> segs;
  double t = 0;
  for (const auto& m : merged) {
    if (m.lo > t) segs.push_back({m.lo, opt.max_step_s});
    segs.push_back({m.hi, std::min(opt.max_step_s, opt.obstacle_max_step_s)});
    t = m.hi;
  }
  if (t < sc.duration_s) segs.push_back({sc.duration_s, opt.max_step_s});
  // A rough section that starts at a known time: the integrator lands on a knot just before it,
  // so nothing before that knot depends on the rough road (every road of one theta shares the
  // smooth part bit for bit; runBranched integrates it once).
  if (const double rough = sc.road->roughStart_s(); rough > 0) {
    const double tb = rough - opt.obstacle_margin_before_s;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      const double lo = i == 0 ? 0.0 : segs[i - 1].first;
      if (tb > lo + 1e-9 && tb < segs[i].first - 1e-9) {
        segs.insert(segs.begin() + static_cast<long>(i), {tb, segs[i].second});
        break;
      }
    }
  }
  return segs;
}

}  // namespace dtwin
