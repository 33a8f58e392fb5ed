#include "twin/stepped_run.hpp"

#include <cmath>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "twin/input_road.hpp"
#include "twin/recorder.hpp"
#include "twin/rosenbrock.hpp"
#include "twin/scenario.hpp"
#include "twin/static_start.hpp"
#include "twin/stepper.hpp"
#include "twin/vehicle_system.hpp"

namespace dtwin {
using namespace SimTK;

namespace {

/// The speed over one step: linear from v0 at t0 to v1 at t1 (a two-sample trace: its PCHIP is the
/// line), the distance s0 at t0.
SpeedProfile stepSpeed(double t0, double v0, double t1, double v1, double s0) {
  SpeedProfile p;
  p.trace = std::make_shared<const SpeedTrace>(std::vector<double>{t0, t1},
                                               std::vector<double>{v0, v1}, "co-simulation input");
  p.start_m = s0 - p.trace->distance(t0);
  return p;
}

void checkInputs(const StepInputs& in) {
  if (!std::isfinite(in.speed_mps) || in.speed_mps < 0)
    throw InputError("input speed_mps",
                     "must be finite and >= 0, got " + formatNumber(in.speed_mps));
  for (int c = 0; c < 4; ++c) {
    const auto i = static_cast<std::size_t>(c);
    if (!std::isfinite(in.road_m[i]))
      throw InputError(std::string("input road_") + kCornerNames[i] + "_m", "must be finite");
    if (!std::isfinite(in.actuator_N[i]))
      throw InputError(std::string("input actuator_") + kCornerNames[i] + "_N", "must be finite");
  }
}

}  // namespace

struct SteppedRun::Impl {
  std::shared_ptr<const Model> model;
  SimulationOptions opt;
  std::unique_ptr<sim::VehicleSystem> sys;
  std::unique_ptr<sim::Stepper> stepper;
  std::unique_ptr<sim::Recorder> recorder;
  std::unique_ptr<RosenbrockIntegrator> ros;
  std::vector<double> values;
  InputRoad road;
  ScenarioSpec sc;  ///< its speed: the current step's
  State state;      ///< at time t (the non-rosenbrock integrators restart from it)
  double t = 0.0, v_prev = 0.0, t_prev = -1.0, v_now = 0.0;
  sim::Knots knots;  ///< the start's knot, then the present's
  std::vector<double> times;
  std::vector<double> out;
  std::vector<LowPassStream> filters;  ///< per sensor (order 0: none)
  std::size_t first_sensor = 0;
  long steps = 0;
  bool started = false, failed = false;

  void build() {
    bool filter_states = false;
    const Model& M = *model;
    for (std::size_t i = 0; i < M.effects().size(); ++i)
      if (M.effects()[i]->kind() == EffectKind::StrutFilter)
        filter_states = filter_states || M.effects()[i]->filterActive(
                                             ParamValues(values.data() + M.effectSlots()[i][0],
                                                         M.effects()[i]->parameters().size()));
    sys = std::make_unique<sim::VehicleSystem>(M, filter_states, opt.hub_motion == "link");
    stepper = std::make_unique<sim::Stepper>(*sys, opt);
    recorder = std::make_unique<sim::Recorder>(*sys, opt);
    sim::RunContext& ctx = sys->ctx;
    ctx.p = values.data();
    ctx.road = &road;
    ctx.gain_slot = static_cast<std::size_t>(M.roadGainSlot());
    ctx.delay_slot = static_cast<std::size_t>(M.roadDelaySlot());
    ctx.form_slot = static_cast<std::size_t>(M.roadFormSlot());
    ctx.wheelbase = M.vehicle().wheelbase();
  }

  void setSpeed(const SpeedProfile& p) {
    sc.speed = p;
    sys->ctx.speed = p;
  }

  void pushRoad(double s, const StepInputs& in) {
    const double wb = model->vehicle().wheelbase();
    for (int c = 0; c < 4; ++c)
      road.push(c, s - (c < 2 ? 0.0 : wb), in.road_m[static_cast<std::size_t>(c)]);
  }

  /// The outputs at the present knot (knots.back()).
  void readOutputs() {
    Trace tr;
    recorder->writeRows(knots, times, sc, {t}, tr);
    out.clear();
    for (std::size_t i = 1; i < tr.channels().size(); ++i) out.push_back(tr.column(i)[0]);
    for (std::size_t s = 0; s < filters.size(); ++s) {
      double& y = out[first_sensor + s];
      y = t == 0.0 ? filters[s].start(y) : filters[s].step(y, t - t_prev);
    }
    const State& st = ros ? ros->getState() : state;
    for (int c = 0; c < 4; ++c) {
      const sim::StrutGeometry& g = sys->struts[static_cast<std::size_t>(c)];
      out.push_back(g.upper.findStationVelocityInGround(st, g.st_upper)[2]);
    }
  }

  void integrate(double t_end) {
    if (ros) {
      ros->refreshDerivative();
      ros->setMaximumStepSize(opt.max_step_s);
      const long before = ros->steps();
      while (ros->getTime() < t_end - 1e-12) {
        opt.stop.throwIfRequested();
        ros->step(t_end);
      }
      steps += ros->steps() - before;
    } else {
      state.invalidateAllCacheAtOrAbove(Stage::Time);
      sim::Knots k;
      std::vector<double> ts;
      State end;
      const RunStats st =
          stepper->integrate(state, {{t_end, opt.max_step_s}}, 0, 1, false, k, ts, &end);
      if (!st.ok) throw std::runtime_error(st.message);
      steps += st.steps;
      state = end;
    }
  }
};

SteppedRun::SteppedRun(std::shared_ptr<const Model> model, SimulationOptions options)
    : impl_(std::make_unique<Impl>()) {
  options.validate();
  impl_->model = std::move(model);
  impl_->opt = std::move(options);
  impl_->sc.name = "co-simulation";
}
SteppedRun::~SteppedRun() = default;

std::vector<Channel> SteppedRun::channels(const std::vector<SensorSpec>& sensors) {
  std::vector<Channel> ch = runChannels(sensors);
  ch.erase(ch.begin());  // time_s: the importer's own
  for (const char* c : kCornerNames)
    ch.push_back({std::string("body_vz_") + c + "_mps", "m/s",
                  std::string("world-vertical velocity of the body at the top of the ") + c +
                      " strut, up positive (what a skyhook reads)"});
  return ch;
}

void SteppedRun::start(const std::vector<double>& values, const StepInputs& in) {
  Impl& I = *impl_;
  const Model& M0 = *I.model;
  if (values.size() != M0.runParameterNames().size())
    throw InputError("run parameters",
                     "expected " + std::to_string(M0.runParameterNames().size()) + " values");
  if (const std::string rule = M0.checkRunValues(values); !rule.empty())
    throw InputError("run parameters", rule);
  checkInputs(in);
  if (!M0.builtFor(values)) I.model = M0.withFreedValues(values);
  I.values = values;
  I.road = InputRoad();
  I.build();
  I.setSpeed(stepSpeed(0.0, in.speed_mps, 1.0, in.speed_mps, 0.0));
  I.pushRoad(0.0, in);
  I.sys->ctx.actuator_N = in.actuator_N;
  I.t = 0.0;
  I.t_prev = -1.0;
  I.v_now = in.speed_mps;
  I.steps = 0;
  I.failed = true;  // until the start is made
  try {
    sim::StaticStart start(*I.sys);
    I.state = start.state();
    I.sys->system.realize(I.state, Stage::Acceleration);
    if (I.opt.integrator == "rosenbrock") {
      RosenbrockOptions ro;
      ro.accuracy = I.opt.accuracy;
      ro.max_step_s = I.opt.max_step_s;
      ro.max_steps = I.opt.max_internal_steps;
      I.ros = std::make_unique<RosenbrockIntegrator>(I.sys->system, ro);
      I.ros->initialize(I.state);
    } else {
      I.ros.reset();
    }
    I.knots.clear();
    I.times.clear();
    I.stepper->record(I.state, I.knots, I.times);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(oneLine(std::string("the static start failed: ") + e.what()));
  }
  I.filters.clear();
  I.first_sensor = runChannels().size() - 1;
  for (const auto& s : I.model->sensors()) I.filters.emplace_back(s.filter);
  I.readOutputs();
  I.started = true;
  I.failed = false;
}

void SteppedRun::advance(double t_end, const StepInputs& in) {
  Impl& I = *impl_;
  if (!I.started) throw std::logic_error("SteppedRun::advance before start");
  if (I.failed) throw std::runtime_error("the run failed before; it cannot go on");
  if (!(t_end > I.t))
    throw InputError("step", "the end time " + formatNumber(t_end) +
                                 " s is not after the present " + formatNumber(I.t) + " s");
  checkInputs(in);
  const double v = in.speed_mps;
  const double a = I.t_prev >= 0.0 ? (v - I.v_prev) / (I.t - I.t_prev) : 0.0;
  const double v_end = std::max(0.0, v + a * (t_end - I.t));
  const double s = I.sc.speed.distance(I.t);
  I.setSpeed(stepSpeed(I.t, v, t_end, v_end, s));
  I.pushRoad(s, in);
  I.sys->ctx.actuator_N = in.actuator_N;
  I.failed = true;
  try {
    I.integrate(t_end);
    I.knots.resize(1);
    I.times.resize(1);
    I.stepper->record(I.ros ? I.ros->getState() : I.state, I.knots, I.times);
  } catch (const std::exception& e) {
    throw std::runtime_error(
        oneLine(std::string("simulation failed at t = ") + formatNumber(I.t) + " s: " + e.what()));
  }
  I.v_prev = v;
  I.t_prev = I.t;
  I.t = t_end;
  I.readOutputs();
  I.failed = false;
}

double SteppedRun::time() const { return impl_->t; }
const std::vector<double>& SteppedRun::outputs() const { return impl_->out; }
long SteppedRun::steps() const { return impl_->steps; }
const Model& SteppedRun::model() const { return *impl_->model; }

}  // namespace dtwin
