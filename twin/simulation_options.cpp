// The simulation's options (SimulationOptions) and the integrators a study may name: kept apart
// from the simulator's run (simulator.cpp, stepper.cpp), which they configure.
#include <memory>
#include <string>
#include <vector>

#include <Simbody.h>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/validate.hpp"
#include "twin/simulator.hpp"

namespace dtwin {

const Registry<IntegratorMaker>& integrators() {
  using P = std::unique_ptr<SimTK::Integrator>;
  static const Registry<IntegratorMaker> r(
      "integrator",
      {
          {"rosenbrock",
           "ROS34PW2, an L-stable Rosenbrock-W method of order 3 (the project's own; the default)",
           nullptr},
          {"rk-merson", "Simbody's Runge-Kutta-Merson, explicit, order 4",
           [](SimTK::System& s) {
             return P(std::make_unique<SimTK::RungeKuttaMersonIntegrator>(s));
           }},
          {"rk3", "Simbody's Runge-Kutta 3, explicit, order 3",
           [](SimTK::System& s) { return P(std::make_unique<SimTK::RungeKutta3Integrator>(s)); }},
          {"rk-feldberg", "Simbody's Runge-Kutta-Feldberg, explicit, order 5",
           [](SimTK::System& s) {
             return P(std::make_unique<SimTK::RungeKuttaFeldbergIntegrator>(s));
           }},
          {"cpodes", "Simbody's CPodes (SUNDIALS CVODE): BDF with Newton iterations, implicit",
           [](SimTK::System& s) {
             return P(std::make_unique<SimTK::CPodesIntegrator>(s, SimTK::CPodes::BDF,
                                                                SimTK::CPodes::Newton));
           }},
          {"semi-explicit-euler2", "Simbody's semi-explicit Euler with error control, order 2",
           [](SimTK::System& s) {
             return P(std::make_unique<SimTK::SemiExplicitEuler2Integrator>(s));
           }},
      });
  return r;
}

std::vector<std::string> SimulationOptions::integratorNames() { return integrators().names(); }

void SimulationOptions::validate() const {
  const OptionCheck check("simulation");
  check.require(integrators().contains(integrator), "integrator",
                unknownNameRule(integrators().what(), integrator, integratorNames()));
  // Lower limits keep the work bounded: below them a run would take millions of steps (or, at a
  // step of 1e-320 s, divide by a denormal) before it failed (docs/study-file.md).
  check.require(accuracy >= 1e-10 && accuracy < 1, "accuracy",
                "must lie in [1e-10, 1), got " + formatNumber(accuracy));
  check.require(max_step_s >= 1e-6 && max_step_s <= 10, "max_step_s",
                "must lie in [1e-6, 10] s, got " + formatNumber(max_step_s));
  check.require(obstacle_max_step_s >= 1e-6 && obstacle_max_step_s <= 10, "obstacle_max_step_s",
                "must lie in [1e-6, 10] s, got " + formatNumber(obstacle_max_step_s));
  check.nonNegative("obstacle_margin_before_s", obstacle_margin_before_s);
  check.nonNegative("obstacle_margin_after_s", obstacle_margin_after_s);
  check.require(output_rate_hz > 0 && output_rate_hz <= 1e6, "output_rate_hz",
                "must lie in (0, 1e6], got " + formatNumber(output_rate_hz));
  check.atLeast("max_internal_steps", max_internal_steps, 1);
  check.require(max_wall_s > 0 && max_wall_s <= 1e6, "max_wall_s",
                "must lie in (0, 1e6] s, got " + formatNumber(max_wall_s));
  check.require(hub_motion == "prescribed" || hub_motion == "link", "hub_motion",
                "must be 'prescribed' or 'link', got '" + hub_motion + "'");
}

nlohmann::json SimulationOptions::toJson() const {
  return {
      {"integrator", integrator},
      {"integrator_note", integrator == "rosenbrock"
                              ? "ROS34PW2 Rosenbrock-W (Rang & Angermann 2005), twin/rosenbrock.hpp"
                              : "Simbody's " + integrator + " integrator"},
      {"accuracy", accuracy},
      {"max_step_s", max_step_s},
      {"obstacle_max_step_s", obstacle_max_step_s},
      {"obstacle_margin_before_s", obstacle_margin_before_s},
      {"obstacle_margin_after_s", obstacle_margin_after_s},
      {"output_rate_hz", output_rate_hz},
      {"hub_motion", hub_motion},
      {"output_method",
       "cubic Hermite interpolation of states recorded at every integrator step; forces from the "
       "laws"}};
}

}  // namespace dtwin
