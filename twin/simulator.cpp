#include "twin/simulator.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include <Simbody.h>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/validate.hpp"
#include "twin/rosenbrock.hpp"
#include "twin/force_elements.hpp"
#include "twin/static_start.hpp"

namespace dtwin {
using namespace SimTK;

// ----------------------------------------------------------------------- run helpers
namespace {

/// Why a run failed, in words a user can act on: Simbody's own exception text (its source file,
/// line and method) is replaced; the integrators' and the laws' messages are ours already.
std::string failureInWords(const std::exception& e) {
  if (dynamic_cast<const SimTK::Exception::Base*>(&e))
    return "the multibody model could not be evaluated (Simbody refused the state: non-finite forces or a configuration it "
           "cannot realise)";
  return e.what();
}

std::size_t contiguous(const std::vector<int>& slots) {
  DTWIN_CHECK(!slots.empty(), "empty slot list");
  for (std::size_t i = 1; i < slots.size(); ++i) DTWIN_CHECK(slots[i] == slots[0] + static_cast<int>(i), "slots not contiguous");
  return static_cast<std::size_t>(slots[0]);
}

/// A replayed step whose error norm exceeds this is split (Impl::integrate).
/// A replayed step whose error norm (RosenbrockOptions::accuracy) exceeds this is split into
/// equal parts (Impl::integrate): a safety net for parameters far from those the steps were
/// chosen at. Near them the error norms stay below it (the controller aims at about 0.7), so a
/// replay there is a smooth function of the parameters; a lower value (1) split steps at
/// neighbouring parameters and made the SSE as jagged as an adaptive one.
constexpr double kReplayRefine = 8.0;

// Knot layout (one recorded integrator state).
enum : std::size_t { HX = 0, HXD = 4, HZ = 8, HZD = 12, HZDD = 16, Q = 20, QD = 24, QDD = 28,
                     BODY = 32 /* heave, pitch, roll: value, rate, accel (3 each) */, KNOT = 41 };

double hermite(double h, double u, double y0, double m0, double y1, double m1) {
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * h * m0 + (-2 * u3 + 3 * u2) * y1 + (u3 - u2) * h * m1;
}
double hermiteD(double h, double u, double y0, double m0, double y1, double m1) {
  const double u2 = u * u;
  return ((6 * u2 - 6 * u) * y0 + (-6 * u2 + 6 * u) * y1) / h + (3 * u2 - 4 * u + 1) * m0 + (3 * u2 - 2 * u) * m1;
}

}  // namespace

// ----------------------------------------------------------------------- Impl
struct Simulator::Impl {
  std::shared_ptr<const Model> model;
  SimulationOptions opt;
  RunContext ctx;
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody::Slider heave;
  MobilizedBody::Universal chassis;
  std::array<MobilizedBody, 4> wheels;
  std::array<MobilizedBody, 2> axle_slider, axle;  // solid axle only
  std::array<StrutGeometry, 4> struts;               // main suspension strut per corner
  std::array<const StrutElement*, 4> strut_elems{};
  std::array<TireCorner, 4> tires;
  std::array<double, 4> strut_preload{};
  State default_state;
  QIndex heave_q, chassis_q;
  UIndex heave_u, chassis_u;

  /// With StrutFilter effects installed, `filter_states` selects the system that integrates their
  /// auxiliary states (used for runs where such an effect is active); without, they are inert.
  bool filter_states = false;

  Impl(std::shared_ptr<const Model> m, SimulationOptions o, bool with_filter_states = false)
      : model(std::move(m)), opt(std::move(o)), filter_states(with_filter_states) {
    opt.validate();
    build();
  }

  void build() {
    const Model& M = *model;
    const VehicleData& d = M.vehicle();
    std::vector<StrutElement*> slider_elems;
    const Rotation xToZ(-Pi / 2, YAxis);  // a slider's x axis along the parent's z
    const Rotation zToX(Pi / 2, YAxis);   // a pin's z axis along the parent's x
    heave = MobilizedBody::Slider(matter.Ground(), Transform(xToZ), Body::Massless(), Transform(xToZ));
    chassis = MobilizedBody::Universal(heave, Transform(), Body::Rigid(MassProperties(d.chassis_mass, Vec3(0), Inertia(d.ixx, d.iyy, d.izz))), Transform());
    const double z_wc = -(d.cg_height - M.table().value("tire.unloaded_radius_m"));  // wheel centre below CG
    const Body::Rigid wheelBody(MassProperties(d.wheel_mass, Vec3(0), Inertia(1e-3)));
    std::vector<std::pair<MobilizedBody, double>> massive = {{chassis, d.chassis_mass}};
    for (int c = 0; c < 4; ++c) {
      const double x = isFront(c) ? d.a : -d.b;
      const double y = (cornerTrack(c) == Track::Left ? 0.5 : -0.5) * d.track;
      strut_preload[c] = M.staticStrutForce(c);
      if (M.topology() == SuspensionTopology::MacPherson) {
        wheels[c] = MobilizedBody::Slider(chassis, Transform(xToZ, Vec3(x, y, z_wc)), wheelBody, Transform(xToZ));
        struts[c] = {chassis, wheels[c], Vec3(x, y, z_wc), Vec3(0)};
      }
    }
    if (M.topology() == SuspensionTopology::SolidAxle) {
      const Body::Rigid axleBody(MassProperties(d.axle_mass, Vec3(0), Inertia(d.axle_ixx, d.axle_ixx, d.axle_ixx)));
      for (int ax = 0; ax < 2; ++ax) {
        const double x = ax == 0 ? d.a : -d.b;
        axle_slider[ax] = MobilizedBody::Slider(chassis, Transform(xToZ, Vec3(x, 0, z_wc)), Body::Massless(), Transform(xToZ));
        axle[ax] = MobilizedBody::Pin(axle_slider[ax], Transform(zToX), axleBody, Transform(zToX));
        massive.push_back({axle[ax], d.axle_mass});
        for (int side = 0; side < 2; ++side) {
          const int c = 2 * ax + side;
          const double sgn = side == 0 ? 1.0 : -1.0;
          wheels[c] = MobilizedBody::Slider(axle[ax], Transform(xToZ, Vec3(0, sgn * 0.5 * d.track, 0)), wheelBody, Transform(xToZ));
          struts[c] = {chassis, axle[ax], Vec3(x, sgn * 0.5 * d.spring_track, z_wc), Vec3(0, sgn * 0.5 * d.spring_track, 0)};
          // Wheel/axle compliant interface (paper eq. 5): no effects, preload from the data.
          StrutGeometry iface{axle[ax], wheels[c], Vec3(0, sgn * 0.5 * d.track, 0), Vec3(0)};
          auto* ie = new StrutElement(&ctx, &M, &M.interfaceLaw(), iface, contiguous(M.interfaceSlots()), M.interfacePreloadSlot(), 0.0, false);
          ie->bind_slider_ = true;  // the wheel slides on the axle along the axle's z
          slider_elems.push_back(ie);
          Force::Custom(forces, ie);
        }
      }
    }
    for (int c = 0; c < 4; ++c) {
      massive.push_back({wheels[c], d.wheel_mass});
      auto* se = new StrutElement(&ctx, &M, &M.strut(), struts[c], contiguous(M.suspensionSlots()), -1, strut_preload[c], true,
                                  filter_states, forces.getMySubsystemIndex());
      strut_elems[c] = se;
      se->placeAt(c);
      se->factors_ = M.strutFactors()[static_cast<std::size_t>(c)];
      if (M.topology() == SuspensionTopology::MacPherson) {
        se->bind_slider_ = true;  // the wheel carrier slides along the chassis z at the strut
      } else {
        const int ax = c / 2;
        se->seat_slider_ = axle_slider[ax];
        se->seat_pin_ = axle[ax];
        se->seat_y_ = struts[c].st_lower[1];
      }
      se->partner_ = &struts[c ^ 1];  // corners 2 ax + side: the other side of the axle
      se->front_ = isFront(c);
      se->tire_ = &tires[static_cast<std::size_t>(c)];
      se->wheel_ = wheels[c];
      slider_elems.push_back(se);
      Force::Custom(forces, se);
      TireCorner tc;
      tc.model = &M;
      tc.corner = c;
      tc.p0 = contiguous(M.tireSlots());
      tc.np = M.tireSlots().size();
      tc.r0 = parameterIndex(M.tire().parameters(), "unloaded_radius_m");
      tc.factors = M.tireFactors()[static_cast<std::size_t>(c)];
      for (std::size_t i = 0; i < M.effects().size(); ++i)
        if (!M.effectActsAt(i, c))
          continue;  // installed at another corner
        else if (M.effects()[i]->kind() == EffectKind::TireInput)
          tc.filters.push_back({M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
        else if (M.effects()[i]->kind() == EffectKind::TireForce)
          tc.scalers.push_back({M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
        else if (M.effects()[i]->kind() == EffectKind::TireLoad)
          tc.loads.push_back({M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
      tires[c] = tc;
      Force::Custom(forces, new TireElement(&ctx, tc, wheels[c]));
    }
    for (std::size_t i = 0; i < M.effects().size(); ++i)
      if (M.effects()[i]->kind() == EffectKind::AxleCoupling)
        for (int ax = 0; ax < 2; ++ax)
          Force::Custom(forces, new AxleCouplingElement(&ctx, M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0]),
                                                        &struts[2 * ax], &struts[2 * ax + 1], ax == 0));
    for (std::size_t i = 0; i < M.effects().size(); ++i)
      if (M.effects()[i]->kind() == EffectKind::ChassisForce)
        Force::Custom(forces, new ChassisForceElement(&ctx, M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0]), heave, chassis));
    Force::Custom(forces, new BodyLoadElement(&ctx, massive, d.gravity));
    ctx.traction_per_wheel_per_accel = d.total_mass(M.topology()) / 4.0;
    system.realizeTopology();
    default_state = system.getDefaultState();
    for (auto* e : slider_elems) e->bind(default_state);
    heave_q = heave.getFirstQIndex(default_state);
    heave_u = heave.getFirstUIndex(default_state);
    chassis_q = chassis.getFirstQIndex(default_state);
    chassis_u = chassis.getFirstUIndex(default_state);
    for (int c = 0; c < 4; ++c) {
      if (M.topology() == SuspensionTopology::MacPherson) struts[c].bindSlider(default_state);
      else struts[c].bindAxleSeat(default_state, axle_slider[c / 2], axle[c / 2], struts[c].st_lower[1]);
    }
  }

  /// Static equilibrium at t = 0 for the run parameters in ctx (vehicle at rest, flat start).
  void setEquilibrium(State& s) {
    const Model& M = *model;
    const VehicleData& d = M.vehicle();
    const ParamValues tp(ctx.p + tires[0].p0, tires[0].np);
    const double R0 = M.tire().unloadedRadius(tp);
    std::array<double, 4> target{};
    // The corners' tire loads: the static ones, warped when the tires differ (warpedStart).
    std::array<double, 4> load{}, strut_q{};
    for (int c = 0; c < 4; ++c) load[c] = M.staticTireLoad(c);
    if (tireFactorsActive(M, ctx.p)) {
      const WarpedStart warp = warpedStart(M, ctx.p);
      load = warp.tire_load_N;
      strut_q = warp.strut_compression_m;
      if (M.topology() == SuspensionTopology::MacPherson) {
        for (int c = 0; c < 4; ++c) wheels[c].setOneQ(s, 0, strut_q[c]);
      } else {  // a seat moves by q_h + y sin(phi), y = +-spring_track / 2 (left +)
        for (int ax = 0; ax < 2; ++ax) {
          const double ql = strut_q[2 * ax], qr = strut_q[2 * ax + 1];
          axle_slider[ax].setOneQ(s, 0, 0.5 * (ql + qr));
          axle[ax].setOneQ(s, 0, std::asin(std::clamp((ql - qr) / d.spring_track, -1.0, 1.0)));
        }
      }
    }
    for (int c = 0; c < 4; ++c) {
      // The corner's own tire values (its factors applied; tp itself without).
      LawValueBuffer buf;
      const double rho = M.tire().calcStaticDeflection(load[c], tires[c].values(ctx, buf));
      const double x_road = -(isFront(c) ? 0.0 : d.wheelbase());
      const double delay = ctx.p[ctx.delay_slot], shift = delay != 0.0 ? ctx.speed.distance(delay) - ctx.speed.distance(0.0) : 0.0;
      double weight = 1.0, ahead = 0.0;
      ctx.signalAt(c, weight, ahead);
      target[c] = weight * ctx.road->sample(cornerTrack(c), x_road + ahead + shift).height_m + R0 - rho;
      if (M.topology() == SuspensionTopology::SolidAxle) {
        const double* p = ctx.p;
        const double k = p[M.interfaceSlots()[0]], F0 = p[M.interfacePreloadSlot()];
        const double q = (load[c] - d.wheel_mass * d.gravity - F0) / k;
        wheels[c].setOneQ(s, 0, q);
      }
    }
    // Newton on (heave, pitch, roll) so that the FL, FR, RL hubs sit at their targets.
    auto residual = [&](const Vec3& x) {
      heave.setOneQ(s, 0, x[0]);
      chassis.setOneQ(s, 0, x[2]);  // roll
      chassis.setOneQ(s, 1, x[1]);  // pitch
      system.realize(s, Stage::Position);
      return Vec3(wheels[0].getBodyOriginLocation(s)[2] - target[0], wheels[1].getBodyOriginLocation(s)[2] - target[1],
                  wheels[2].getBodyOriginLocation(s)[2] - target[2]);
    };
    Vec3 x(d.cg_height, 0, 0);
    for (int it = 0; it < 6; ++it) {
      const Vec3 r = residual(x);
      if (r.norm() < 1e-12) break;
      Mat33 J;
      for (int j = 0; j < 3; ++j) {
        Vec3 xp = x;
        xp[j] += 1e-7;
        J(j) = (residual(xp) - r) / 1e-7;
      }
      x -= J.invert() * r;
    }
    residual(x);
    s.updU() = 0;
    system.realize(s, Stage::Velocity);
    ctx.heave0 = x[0];
    ctx.pitch0 = x[1];
    ctx.roll0 = x[2];
  }

  void record(const State& s, std::vector<std::array<double, KNOT>>& knots, std::vector<double>& times) {
    system.realize(s, Stage::Acceleration);  // a no-op after an integrator step (already realized)
    std::array<double, KNOT> k{};
    for (int c = 0; c < 4; ++c) {
      const Vec3 p = wheels[c].getBodyOriginLocation(s), v = wheels[c].getBodyOriginVelocity(s);
      const Vec3 a = wheels[c].getBodyOriginAcceleration(s);
      k[HX + c] = p[0];
      k[HXD + c] = v[0];
      k[HZ + c] = p[2];
      k[HZD + c] = v[2];
      k[HZDD + c] = a[2];
      const auto kin = struts[c].kin(s);
      k[Q + c] = kin.q;
      k[QD + c] = kin.qd;
      k[QDD + c] = struts[c].accel(s);
    }
    // Heave (slider) and pitch/roll (universal) coordinates: their q-dot is u, so read the State.
    const Vector &q = s.getQ(), &u = s.getU(), &ud = s.getUDot();
    const double vals[9] = {q[heave_q], u[heave_u], ud[heave_u],
                            q[chassis_q + 1], u[chassis_u + 1], ud[chassis_u + 1],
                            q[chassis_q], u[chassis_u], ud[chassis_u]};
    for (int i = 0; i < 9; ++i) k[BODY + i] = vals[i];
    knots.push_back(k);
    times.push_back(s.getTime());
  }

  std::unique_ptr<Integrator> makeIntegrator(const std::string& method) { return integrators().at(method, "simulation.integrator").value(system); }

  /// Time windows in which a wheel crosses an obstacle (merged, clipped).
  using Knots = std::vector<std::array<double, KNOT>>;
  using Segments = std::vector<std::pair<double, double>>;  // (end time, max step)

  /// Validates the run vector and the scenario and points the force elements at them.
  void begin(const std::vector<double>& values, const Road& road, const ScenarioSpec& sc) {
    const Model& M = *model;
    if (values.size() != M.runParameterNames().size())
      throw InputError("run parameters", "expected " + std::to_string(M.runParameterNames().size()) + " values");
    const std::string rule = M.checkRunValues(values);
    if (!rule.empty()) throw InputError("run parameters", rule);
    if (!(sc.duration_s > 0)) throw InputError("scenario " + sc.name, "duration_s must be > 0");
    ctx.p = values.data();
    ctx.road = &road;
    ctx.speed = sc.speed;
    ctx.gain_slot = static_cast<std::size_t>(M.roadGainSlot());
    ctx.delay_slot = static_cast<std::size_t>(M.roadDelaySlot());
    ctx.form_slot = static_cast<std::size_t>(M.roadFormSlot());
    ctx.wheelbase = M.vehicle().wheelbase();
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

  /// Integrates from `s0` through segments [i0, i1) of `segs`, appending a knot per step (and one
  /// for `s0` itself when `record_start`). Never throws for a diverging run: ok = false and the
  /// message say why. On success `end` (if given) receives the final State.
  RunStats integrate(const State& s0, const Segments& segs, std::size_t i0, std::size_t i1, bool record_start, Knots& knots,
                     std::vector<double>& times, State* end, StepControl steps = {}) {
    RunStats st;
    const std::string& method = opt.integrator;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(opt.max_wall_s);
    long checks = 0;
    auto checkFinite = [&](double time) {
      opt.stop.throwIfRequested();  // Stopped is no std::exception: it leaves the run (docs/python.md)
      for (double v : knots.back())
        if (!std::isfinite(v)) throw std::runtime_error("state became non-finite at t = " + std::to_string(time) + " s");
      if (++checks % 256 == 0 && std::chrono::steady_clock::now() > deadline)
        throw std::runtime_error("the run took longer than " + formatNumber(opt.max_wall_s) +
                                 " s of wall time (simulation.max_wall_s) at t = " + std::to_string(time) + " s");
    };
    if (method == "rosenbrock") {
      RosenbrockOptions ro;
      ro.accuracy = opt.accuracy;
      ro.max_step_s = opt.max_step_s;
      ro.max_steps = opt.max_internal_steps;
      RosenbrockIntegrator integ(system, ro);
      try {
        integ.initialize(s0);
        if (record_start) record(integ.getState(), knots, times);
        if (steps.record) *steps.record = StepPlan{};
        std::size_t k = 0;  // next step of a replayed plan
        const StepPlan* plan = steps.replay;
        if (plan) {  // skip the plan's steps before s0 (never the case for a whole run)
          while (k < plan->size() && plan->times[k] <= s0.getTime() + 1e-12) ++k;
        }
        for (std::size_t i = i0; i < i1; ++i) {
          const auto [t_end, hmax] = segs[i];
          integ.setMaximumStepSize(hmax);
          while (integ.getTime() < t_end - 1e-12) {
            if (plan) {
              if (k >= plan->size() || plan->times[k] > t_end + 1e-12)
                throw std::runtime_error("the frozen step sequence does not fit this scenario (" +
                                         (k >= plan->size() ? std::string("it ends at t = ") + formatNumber(integ.getTime()) + " s"
                                                            : "no step ends at the segment end t = " + formatNumber(t_end) + " s") +
                                         "); it was recorded on another scenario or road");
              // A planned step far too large for these parameters (its error norm above
              // kReplayRefine) is split into m equal parts, m from the error's third-order growth;
              // the rest are replayed as they are.
              const double t_k = plan->times[k];
              const double e = integ.stepToIfAccurate(t_k, plan->new_jacobian[k] != 0, kReplayRefine);
              ++k;
              if (!(e <= kReplayRefine)) {
                const int m = std::isfinite(e) ? std::clamp(static_cast<int>(std::ceil(1.25 * std::cbrt(e))), 2, 64) : 16;
                const double t0 = integ.getTime();
                for (int j = 1; j < m; ++j) {
                  integ.stepTo(t0 + (t_k - t0) * j / m, false);
                  record(integ.getState(), knots, times);
                  checkFinite(integ.getTime());
                }
                integ.stepTo(t_k, false);
              }
            } else {
              integ.step(t_end);
            }
            if (steps.record) {
              steps.record->times.push_back(integ.getTime());
              steps.record->new_jacobian.push_back(integ.lastStepNewJacobian() ? 1 : 0);
            }
            record(integ.getState(), knots, times);
            checkFinite(integ.getTime());
          }
        }
        if (end) *end = integ.getState();
      } catch (const std::exception& e) {
        st.ok = false;
        st.message = oneLine("simulation failed: " + failureInWords(e));
      }
      st.steps = integ.steps();
      st.steps_attempted = integ.attempts();
    } else {
      auto integ = makeIntegrator(method);
      integ->setAccuracy(opt.accuracy);
      integ->setReturnEveryInternalStep(true);
      integ->setInternalStepLimit(0);
      integ->setMaximumStepSize(opt.max_step_s);
      try {
        integ->initialize(s0);
        if (record_start) record(integ->getState(), knots, times);
        for (std::size_t i = i0; i < i1; ++i) {
          const auto [t_end, hmax] = segs[i];
          integ->setMaximumStepSize(hmax);
          while (integ->getTime() < t_end - 1e-12) {
            const auto status = integ->stepTo(t_end, t_end);
            if (integ->isSimulationOver() && integ->getTerminationReason() == Integrator::AnUnrecoverableErrorOccurred)
              throw std::runtime_error("integrator failed");
            if (status == Integrator::TimeHasAdvanced || status == Integrator::ReachedScheduledEvent ||
                status == Integrator::ReachedReportTime) {
              const State& s = integ->getState();
              if (times.empty() || s.getTime() > times.back()) record(s, knots, times);
            }
            if (integ->getNumStepsTaken() > opt.max_internal_steps)
              throw std::runtime_error("more than " + std::to_string(opt.max_internal_steps) + " integrator steps");
            checkFinite(integ->getTime());
          }
        }
        if (end) *end = integ->getState();
      } catch (const std::exception& e) {
        st.ok = false;
        st.message = oneLine("simulation failed: " + failureInWords(e));
      }
      st.steps = integ->getNumStepsTaken();
      st.steps_attempted = integ->getNumStepsAttempted();
    }
    return st;
  }

  /// The equilibrium start state for the run set up by begin().
  State startState() {
    State s = default_state;
    s.setTime(0);
    setEquilibrium(s);
    return s;
  }

  RunResult run(const std::vector<double>& values, const Road& road, const ScenarioSpec& sc, StepControl steps) {
    const auto t_start = std::chrono::steady_clock::now();
    begin(values, road, sc);
    if ((steps.replay || steps.record) && opt.integrator != "rosenbrock")
      throw InputError("simulation.integrator", "a frozen step sequence needs the rosenbrock integrator, not '" + opt.integrator + "'");
    RunResult res;
    Knots knots;
    std::vector<double> times;
    const State s = startState();
    const Segments segs = segments(road, sc);
    res.stats = integrate(s, segs, 0, segs.size(), true, knots, times, nullptr, steps);
    finish(knots, times, sc, res);
    res.stats.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    return res;
  }

  /// Fills knot count, simulated time and the output trace of `res` from the recorded knots.
  void finish(const Knots& knots, const std::vector<double>& times, const ScenarioSpec& sc, RunResult& res) {
    if (times.empty()) {  // the integrator could not even start: an empty trace with its channels
      for (auto& ch : channels(model->sensors())) res.trace.addChannel(ch);
      return;
    }
    res.stats.knots = static_cast<long>(knots.size());
    res.stats.sim_s = times.back();
    if (!sc.grid_output && !sc.sample_times_s.empty() && !filteredSensors()) {  // the samples alone (ScenarioSpec::grid_output)
      for (auto& ch : channels(model->sensors())) res.trace.addChannel(ch);
      if (res.stats.ok) {
        DTWIN_CHECK(std::is_sorted(sc.sample_times_s.begin(), sc.sample_times_s.end()) && sc.sample_times_s.front() >= 0 &&
                        sc.sample_times_s.back() <= times.back() + 1e-9,
                    "sample_times_s must be ascending and within the run");
        writeRows(knots, times, sc, sc.sample_times_s, res.samples);
      }
      return;
    }
    makeOutput(knots, times, sc, res.trace);
    if (!sc.sample_times_s.empty() && res.stats.ok) {
      DTWIN_CHECK(std::is_sorted(sc.sample_times_s.begin(), sc.sample_times_s.end()) && sc.sample_times_s.front() >= 0 &&
                      sc.sample_times_s.back() <= times.back() + 1e-9,
                  "sample_times_s must be ascending and within the run");
      writeRows(knots, times, sc, sc.sample_times_s, res.samples);
      resampleFilteredSensors(res.trace, sc.sample_times_s, res.samples);
    }
  }

  std::vector<RunResult> runBranched(const std::vector<double>& values, const std::vector<const Road*>& roads,
                                     const ScenarioSpec& sc) {
    using Clock = std::chrono::steady_clock;
    const auto t_start = Clock::now();
    if (roads.empty()) throw InputError("runBranched", "needs at least one road");
    for (std::size_t r = 0; r < roads.size(); ++r)
      if (!roads[r]) throw InputError("runBranched", "road " + std::to_string(r) + " is null");
    const double tb = branchTime(sc);
    if (!(tb > 0))
      throw InputError("scenario " + sc.name,
                       "cannot branch: the road has no smooth start (needs an iso8608 road with smooth_until_s > "
                       "obstacle_margin_before_s = " + std::to_string(opt.obstacle_margin_before_s) + " s)");
    if (!(tb < sc.duration_s))
      throw InputError("scenario " + sc.name, "cannot branch: the smooth part (to " + std::to_string(tb) +
                                                  " s) covers the whole run (duration " + std::to_string(sc.duration_s) + " s)");
    begin(values, *roads[0], sc);
    const Segments segs = segments(*roads[0], sc);
    std::size_t ib = segs.size();
    for (std::size_t i = 0; i < segs.size(); ++i)
      if (segs[i].first == tb) ib = i;
    if (ib == segs.size())
      throw InputError("scenario " + sc.name, "cannot branch: no integration segment ends at the branch time " + std::to_string(tb) +
                                                  " s (an obstacle window overlaps the smooth part's end)");
    // Every road must share the segments and the smooth part (the scenario's road, other seed).
    for (std::size_t r = 1; r < roads.size(); ++r) {
      if (segments(*roads[r], sc) != segs)
        throw InputError("runBranched", "road " + std::to_string(r) + " has other obstacle windows than road 0");
      const double x_hi = sc.speed.distance(tb) + 0.1, x_lo = sc.speed.distance(0) - model->vehicle().wheelbase() - 1.0;
      for (double x = x_lo; x <= x_hi; x += 0.05)
        for (Track t : {Track::Left, Track::Right}) {
          const RoadSample a = roads[0]->sample(t, x), b = roads[r]->sample(t, x);
          if (a.height_m != b.height_m || a.slope != b.slope)
            throw InputError("runBranched", "road " + std::to_string(r) + " differs from road 0 before the branch point (x = " +
                                                std::to_string(x) + " m): the roads must share the smooth start");
        }
    }
    // The common part, once.
    Knots knots0;
    std::vector<double> times0;
    State at_branch;
    const RunStats common = integrate(startState(), segs, 0, ib + 1, true, knots0, times0, &at_branch);
    const double common_wall = std::chrono::duration<double>(Clock::now() - t_start).count();
    const double share = common_wall / static_cast<double>(roads.size());
    std::vector<RunResult> out(roads.size());
    for (std::size_t r = 0; r < roads.size(); ++r) {
      const auto t_branch = Clock::now();
      RunResult& res = out[r];
      ctx.road = roads[r];
      Knots knots = knots0;
      std::vector<double> times = times0;
      if (common.ok) {
        State s = at_branch;
        s.invalidateAllCacheAtOrAbove(Stage::Time);  // forces are re-evaluated on this branch's road
        res.stats = integrate(s, segs, ib + 1, segs.size(), false, knots, times, nullptr);
        res.stats.steps += common.steps;
        res.stats.steps_attempted += common.steps_attempted;
      } else {
        res.stats = common;
      }
      finish(knots, times, sc, res);
      res.stats.wall_s = share + std::chrono::duration<double>(Clock::now() - t_branch).count();
    }
    return out;
  }

  void makeOutput(const std::vector<std::array<double, KNOT>>& knots, const std::vector<double>& times,
                  const ScenarioSpec& sc, Trace& tr) {
    const std::size_t n = static_cast<std::size_t>(std::floor(times.back() * opt.output_rate_hz + 1e-9)) + 1;
    std::vector<double> ts(n);
    for (std::size_t r = 0; r < n; ++r) ts[r] = std::min(static_cast<double>(r) / opt.output_rate_hz, times.back());
    writeRows(knots, times, sc, ts, tr);
    filterSensors(tr);
  }

  /// The output channels at the ascending times `ts` (within the knots' span), from the cubic
  /// Hermite interpolant of the knots: the integrator's dense output, whatever the times.
  void writeRows(const std::vector<std::array<double, KNOT>>& knots, const std::vector<double>& times,
                 const ScenarioSpec& sc, const std::vector<double>& ts, Trace& tr) {
    for (auto& ch : channels(model->sensors())) tr.addChannel(ch);
    const std::size_t n = ts.size();
    for (std::size_t i = 0; i < tr.channels().size(); ++i) tr.column(i).resize(n);
    const auto& k0 = knots.front();
    std::size_t j = 0;
    for (std::size_t r = 0; r < n; ++r) {
      const double t = ts[r];
      while (j + 2 < times.size() && times[j + 1] < t) ++j;
      const std::size_t j1 = std::min(j + 1, times.size() - 1);
      const auto& a = knots[j];
      const auto& b = knots[j1];
      const double h = times[j1] - times[j];
      const double u = h > 0 ? std::clamp((t - times[j]) / h, 0.0, 1.0) : 0.0;
      auto pos = [&](std::size_t iv, std::size_t id) { return h > 0 ? hermite(h, u, a[iv], a[id], b[iv], b[id]) : a[iv]; };
      auto acc = [&](std::size_t iv, std::size_t id) { return h > 0 ? hermiteD(h, u, a[iv], a[id], b[iv], b[id]) : a[id]; };
      std::size_t col = 0;
      tr.column(col++)[r] = t;
      tr.column(col++)[r] = sc.speed.speed(t);
      for (int c = 0; c < 4; ++c) {
        const double hx = pos(HX + c, HXD + c), hxd = a[HXD + c] + u * (b[HXD + c] - a[HXD + c]);
        const TireEval e = tires[c].eval(ctx, t, hx, hxd, pos(HZ + c, HZD + c), pos(HZD + c, HZDD + c));
        tr.column(col + c)[r] = e.fz;
        tr.column(col + 4 + c)[r] = e.rho;
        tr.column(col + 8 + c)[r] = pos(Q + c, QD + c);
        tr.column(col + 12 + c)[r] = pos(QD + c, QDD + c);
        tr.column(col + 16 + c)[r] = e.road_h;
      }
      col += 20;
      tr.column(col++)[r] = pos(BODY + 0, BODY + 1) - k0[BODY + 0];
      tr.column(col++)[r] = pos(BODY + 3, BODY + 4);
      tr.column(col++)[r] = pos(BODY + 6, BODY + 7);
      tr.column(col++)[r] = acc(BODY + 1, BODY + 2);
      tr.column(col++)[r] = acc(BODY + 4, BODY + 5);
      tr.column(col++)[r] = acc(BODY + 7, BODY + 8);
      for (std::size_t si = 0; si < model->sensors().size(); ++si) {  // before any filter (filterSensors)
        const SensorSpec& x = model->sensors()[si];
        const Model::SensorSlots& sl = model->sensorSlots()[si];
        const double offset = ctx.p[sl.offset];  // run parameters: a calibration may move them
        Motion m;
        if (x.relative()) {
          // The wheel centre's height in chassis axes, from its start: the travel (compression
          // positive) of a potentiometer parallel to the chassis z axis, wherever its body end is.
          const auto c = static_cast<std::size_t>(x.corner());
          const double cx = isFront(x.corner()) ? model->vehicle().a : -model->vehicle().b;
          const double cy = (cornerTrack(x.corner()) == Track::Left ? 0.5 : -0.5) * model->vehicle().track;
          const Motion heave{pos(BODY + 0, BODY + 1), pos(BODY + 1, BODY + 2), 0.0};
          const Motion pitch{pos(BODY + 3, BODY + 4), pos(BODY + 4, BODY + 5), 0.0};
          const Motion roll{pos(BODY + 6, BODY + 7), pos(BODY + 7, BODY + 8), 0.0};
          m = chassisAxisHeight({pos(HZ + c, HZD + c), pos(HZD + c, HZDD + c), 0.0}, heave, pitch, roll, cx, cy);
          m.q -= chassisAxisHeight({k0[HZ + c], 0, 0}, {k0[BODY + 0], 0, 0}, {k0[BODY + 3], 0, 0}, {k0[BODY + 6], 0, 0}, cx, cy).q;
          tr.column(col++)[r] = (x.quantity == SensorQuantity::Travel ? m.q : m.qd) + offset;
          continue;
        }
        if (x.corner() >= 0) {
          const std::size_t c = static_cast<std::size_t>(x.corner());
          m = {pos(HZ + c, HZD + c) - k0[HZ + c], pos(HZD + c, HZDD + c), acc(HZD + c, HZDD + c)};
        } else {
          const Motion heave{pos(BODY + 0, BODY + 1), pos(BODY + 1, BODY + 2), acc(BODY + 1, BODY + 2)};
          const Motion pitch{pos(BODY + 3, BODY + 4), pos(BODY + 4, BODY + 5), acc(BODY + 4, BODY + 5)};
          const Motion roll{pos(BODY + 6, BODY + 7), pos(BODY + 7, BODY + 8), acc(BODY + 7, BODY + 8)};
          const Motion at0{k0[BODY + 0], 0.0, 0.0};
          const std::array<double, 3> where{ctx.p[sl.x], ctx.p[sl.y], ctx.p[sl.z]};
          m = chassisPointMotion(heave, pitch, roll, where);
          m.q -= chassisPointMotion(at0, {k0[BODY + 3], 0, 0}, {k0[BODY + 6], 0, 0}, where).q;
        }
        tr.column(col++)[r] = (x.quantity == SensorQuantity::DisplacementZ ? m.q : x.quantity == SensorQuantity::VelocityZ ? m.qd : m.qdd) + offset;
      }
    }
  }

  /// Whether a sensor of the model is filtered (its filter state lives on the output grid).
  bool filteredSensors() const {
    return std::any_of(model->sensors().begin(), model->sensors().end(), [](const SensorSpec& x) { return x.filter.order > 0; });
  }

  /// The filtered sensors' columns of a grid trace (makeOutput), filtered as the logger did.
  void filterSensors(Trace& grid) {
    const auto& sensors = model->sensors();
    const std::size_t first = channels().size();
    for (std::size_t i = 0; i < sensors.size(); ++i)
      if (sensors[i].filter.order > 0) grid.column(first + i) = lowPass(grid.column(first + i), opt.output_rate_hz, sensors[i].filter);
  }

  /// A filtered sensor at extra output times: the filtered grid column read there (its filter
  /// state lives on the grid; twin/trace.hpp GridSample, the four-point cubic).
  void resampleFilteredSensors(const Trace& grid, const std::vector<double>& ts, Trace& samples) {
    const auto& sensors = model->sensors();
    const std::size_t first = channels().size();
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      if (sensors[i].filter.order == 0) continue;
      const auto& g = grid.column(first + i);
      auto& s = samples.column(first + i);
      const double last = static_cast<double>(g.size() - 1) / opt.output_rate_hz;
      for (std::size_t r = 0; r < ts.size(); ++r) s[r] = gridSample(std::min(ts[r], last), opt.output_rate_hz, g.size()).of(g);
    }
  }
};

Simulator::Simulator(std::shared_ptr<const Model> model, SimulationOptions options)
    : impl_(std::make_unique<Impl>(std::move(model), std::move(options))) {}
Simulator::~Simulator() = default;
const Model& Simulator::model() const { return *impl_->model; }
const SimulationOptions& Simulator::options() const { return impl_->opt; }
Simulator::Impl& Simulator::pick(const std::vector<double>& values) {
  if (values.size() != impl_->model->runParameterNames().size()) return *impl_;  // begin() reports it
  if (!impl_->model->builtFor(values)) {
    // A freed vehicle value (a mass, an inertia) is part of the multibody system: rebuild it.
    impl_ = std::make_unique<Impl>(impl_->model->withFreedValues(values), impl_->opt);
    impl_filter_.reset();
  }
  const Model& M = *impl_->model;
  bool active = false;
  for (std::size_t i = 0; i < M.effects().size(); ++i)
    if (M.effects()[i]->kind() == EffectKind::StrutFilter)
      active = active || M.effects()[i]->filterActive(
                             ParamValues(values.data() + M.effectSlots()[i][0], M.effects()[i]->parameters().size()));
  if (!active) return *impl_;
  if (!impl_filter_) impl_filter_ = std::make_unique<Impl>(impl_->model, impl_->opt, true);
  return *impl_filter_;
}
namespace {
/// A run that could not start because the multibody system cannot be built with the run's freed
/// values: a failed run (its SSE is infinite, as any failed run's), in plain words with the values.
RunResult unbuildableRun(const Model& model, const std::vector<double>& values, const std::vector<Channel>& channels) {
  RunResult r;
  r.stats.ok = false;
  std::string at;
  for (int s : model.freedSlots())
    at += (at.empty() ? "" : ", ") + model.runParameterNames()[static_cast<std::size_t>(s)] + " = " +
          formatNumber(values[static_cast<std::size_t>(s)]);
  r.stats.message = "the vehicle cannot be built with " + (at.empty() ? std::string("these values") : at) +
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
RunResult Simulator::run(const std::vector<double>& values, const Road& road, const ScenarioSpec& sc, StepControl steps) {
  if (Impl* impl = pickBuildable(values)) return impl->run(values, road, sc, steps);
  return unbuildableRun(*impl_->model, values, channels(impl_->model->sensors()));
}
std::vector<RunResult> Simulator::runBranched(const std::vector<double>& values, const std::vector<const Road*>& roads,
                                              const ScenarioSpec& sc) {
  if (Impl* impl = pickBuildable(values)) return impl->runBranched(values, roads, sc);
  return std::vector<RunResult>(roads.size(), unbuildableRun(*impl_->model, values, channels(impl_->model->sensors())));
}
double Simulator::branchTime(const ScenarioSpec& sc) const { return impl_->branchTime(sc); }

std::vector<std::pair<double, double>> integrationSegments(const Road& road, const ScenarioSpec& sc, const SimulationOptions& opt,
                                                           double wheelbase) {
  // The windows in time while a wheel (front: offset 0, rear: the wheelbase) is near an obstacle.
  std::vector<Interval> w;
  for (const auto& ob : road.obstacles())
    for (double offset : {0.0, wheelbase}) {
      const double t0 = sc.speed.timeAtDistance(ob.lo + offset) - opt.obstacle_margin_before_s;
      const double t1 = sc.speed.timeAtDistance(ob.hi + offset) + opt.obstacle_margin_after_s;
      if (t1 > 0 && t0 < sc.duration_s) w.push_back({std::max(0.0, t0), std::min(sc.duration_s, t1)});
    }
  std::sort(w.begin(), w.end(), [](auto& a, auto& b) { return a.lo < b.lo; });
  std::vector<Interval> merged;
  for (auto& i : w) {
    if (!merged.empty() && i.lo <= merged.back().hi) merged.back().hi = std::max(merged.back().hi, i.hi);
    else merged.push_back(i);
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
