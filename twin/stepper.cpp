#include "twin/stepper.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "twin/rosenbrock.hpp"

namespace dtwin::sim {
using namespace knot;

namespace {

/// Why a run failed, in words a user can act on: Simbody's own exception text (its source file,
/// line and method) is replaced; the integrators' and the laws' messages are ours already.
std::string failureInWords(const std::exception& e) {
  if (dynamic_cast<const SimTK::Exception::Base*>(&e))
    return "the multibody model could not be evaluated (Simbody refused the state: non-finite "
           "forces or a configuration it "
           "cannot realise)";
  return e.what();
}

/// A replayed step whose error norm (RosenbrockOptions::accuracy) exceeds this is split into
/// equal parts (Stepper::integrate): a safety net for parameters far from those the steps were
/// chosen at. Near them the error norms stay below it (the controller aims at about 0.7), so a
/// replay there is a smooth function of the parameters; a lower value (1) split steps at
/// neighbouring parameters and made the SSE as jagged as an adaptive one.
constexpr double kReplayRefine = 8.0;

}  // namespace

void Stepper::record(const State& s, Knots& knots, std::vector<double>& times) {
  sys_.system.realize(s,
                      Stage::Acceleration);  // a no-op after an integrator step (already realized)
  std::array<double, KNOT> k{};
  if (sys_.prescribed_hubs) {
    // The body's coordinates and the auxiliary states: the recorder rebuilds the State at each
    // output time from them and reads the hubs off the signal there (Recorder::writeRows); the
    // hubs' heights here are the start's reference.
    const Vector& z = s.getZ();
    DTWIN_CHECK(static_cast<std::size_t>(z.size()) <= kMaxZ,
                "too many auxiliary states for prescribed hubs");
    for (int i = 0; i < z.size(); ++i) k[ZS + static_cast<std::size_t>(i)] = z[i];
  }
  for (int c = 0; c < 4; ++c) {
    if (sys_.prescribed_hubs) {
      const StrutGeometry::HubAt h = sys_.struts[c].hubAt(s);
      k[HX + c] = h.p[0];
      k[HZ + c] = h.path.z;
      continue;
    }
    const Vec3 p = sys_.wheels[c].getBodyOriginLocation(s),
               v = sys_.wheels[c].getBodyOriginVelocity(s);
    const Vec3 a = sys_.wheels[c].getBodyOriginAcceleration(s);
    k[HX + c] = p[0];
    k[HXD + c] = v[0];
    k[HZ + c] = p[2];
    k[HZD + c] = v[2];
    k[HZDD + c] = a[2];
    const auto kin = sys_.struts[c].kin(s);
    k[Q + c] = kin.q;
    k[QD + c] = kin.qd;
    k[QDD + c] = sys_.struts[c].accel(s);
  }
  // Heave (slider) and pitch/roll (universal) coordinates: their q-dot is u, so read the State.
  const Vector &q = s.getQ(), &u = s.getU(), &ud = s.getUDot();
  const double vals[9] = {q[sys_.heave_q],       u[sys_.heave_u],       ud[sys_.heave_u],
                          q[sys_.chassis_q + 1], u[sys_.chassis_u + 1], ud[sys_.chassis_u + 1],
                          q[sys_.chassis_q],     u[sys_.chassis_u],     ud[sys_.chassis_u]};
  for (int i = 0; i < 9; ++i) k[BODY + i] = vals[i];
  knots.push_back(k);
  times.push_back(s.getTime());
}

std::unique_ptr<Integrator> Stepper::makeIntegrator(const std::string& method) {
  return integrators().at(method, "simulation.integrator").value(sys_.system);
}

RunStats Stepper::integrate(const State& s0, const Segments& segs, std::size_t i0, std::size_t i1,
                            bool record_start, Knots& knots, std::vector<double>& times, State* end,
                            StepControl steps) {
  RunStats st;
  const std::string& method = opt_.integrator;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(opt_.max_wall_s);
  long checks = 0;
  auto checkFinite = [&](double time) {
    opt_.stop
        .throwIfRequested();  // Stopped is no std::exception: it leaves the run (docs/python.md)
    for (double v : knots.back())
      if (!std::isfinite(v))
        throw std::runtime_error("state became non-finite at t = " + std::to_string(time) + " s");
    if (++checks % 256 == 0 && std::chrono::steady_clock::now() > deadline)
      throw std::runtime_error(
          "the run took longer than " + formatNumber(opt_.max_wall_s) +
          " s of wall time (simulation.max_wall_s) at t = " + std::to_string(time) + " s");
  };
  if (method == "rosenbrock") {
    RosenbrockOptions ro;
    ro.accuracy = opt_.accuracy;
    ro.max_step_s = opt_.max_step_s;
    ro.max_steps = opt_.max_internal_steps;
    RosenbrockIntegrator integ(sys_.system, ro);
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
              throw std::runtime_error(
                  "the frozen step sequence does not fit this scenario (" +
                  (k >= plan->size()
                       ? std::string("it ends at t = ") + formatNumber(integ.getTime()) + " s"
                       : "no step ends at the segment end t = " + formatNumber(t_end) + " s") +
                  "); it was recorded on another scenario or road");
            // A planned step far too large for these parameters (its error norm above
            // kReplayRefine) is split into m equal parts, m from the error's third-order growth;
            // the rest are replayed as they are.
            const double t_k = plan->times[k];
            const double e = integ.stepToIfAccurate(t_k, plan->new_jacobian[k] != 0, kReplayRefine);
            ++k;
            if (!(e <= kReplayRefine)) {
              const int m =
                  std::isfinite(e)
                      ? std::clamp(static_cast<int>(std::ceil(1.25 * std::cbrt(e))), 2, 64)
                      : 16;
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
    integ->setAccuracy(opt_.accuracy);
    integ->setReturnEveryInternalStep(true);
    integ->setInternalStepLimit(0);
    integ->setMaximumStepSize(opt_.max_step_s);
    try {
      integ->initialize(s0);
      if (record_start) record(integ->getState(), knots, times);
      for (std::size_t i = i0; i < i1; ++i) {
        const auto [t_end, hmax] = segs[i];
        integ->setMaximumStepSize(hmax);
        while (integ->getTime() < t_end - 1e-12) {
          const auto status = integ->stepTo(t_end, t_end);
          if (integ->isSimulationOver() &&
              integ->getTerminationReason() == Integrator::AnUnrecoverableErrorOccurred)
            throw std::runtime_error("integrator failed");
          if (status == Integrator::TimeHasAdvanced ||
              status == Integrator::ReachedScheduledEvent ||
              status == Integrator::ReachedReportTime) {
            const State& s = integ->getState();
            if (times.empty() || s.getTime() > times.back()) record(s, knots, times);
          }
          if (integ->getNumStepsTaken() > opt_.max_internal_steps)
            throw std::runtime_error("more than " + std::to_string(opt_.max_internal_steps) +
                                     " integrator steps");
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

}  // namespace dtwin::sim
