#pragma once
// Runs one assembly in Simbody. A Simulator owns one Simbody System, built once from a Model;
// it then runs any number of per-run parameter vectors, roads and scenarios without rebuilding.
// A Simulator is used by one thread at a time (Simbody keeps mutable bookkeeping inside its
// System); parallel runs use one Simulator per worker, all sharing the same const Model.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/registry.hpp"
#include "subsystems/road.hpp"
#include "twin/model.hpp"
#include "twin/run_types.hpp"
#include "twin/scenario.hpp"
#include "twin/trace.hpp"

namespace SimTK {
class Integrator;
class System;
}  // namespace SimTK

namespace dtwin {

/// Makes a Simbody integrator for a system (nullptr for the project's own Rosenbrock-W, which the
/// simulator drives itself, twin/rosenbrock.hpp).
using IntegratorMaker = std::unique_ptr<SimTK::Integrator> (*)(SimTK::System& system);
/// The integrators a study's [simulation] integrator may name (docs/performance.md explains the
/// default).
const Registry<IntegratorMaker>& integrators();

class Simulator {
 public:
  Simulator(std::shared_ptr<const Model> model, SimulationOptions options);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  const Model& model() const;
  const SimulationOptions& options() const;

  /// Simulates `scenario` on `road` with run parameters `values` (layout:
  /// model().runParameterNames()). Never throws for a diverging simulation: stats.ok = false and
  /// stats.message say why. Throws InputError for invalid `values`. `steps` replays or records a
  /// step sequence (StepControl); InputError when one is given and the integrator is not
  /// rosenbrock. A replayed plan that does not fit the scenario (a segment end that is not one of
  /// its steps, too few steps) fails the run (stats.ok = false).
  RunResult run(const std::vector<double>& values, const Road& road, const ScenarioSpec& scenario,
                StepControl steps = {});

  /// Runs `scenario` once per road, sharing the smooth start (docs/method.md §5: "the 0-6 s smooth
  /// part is identical for every road of one θ: simulate it once").
  ///
  /// The common part is integrated once, with roads[0], from the equilibrium up to the branch
  /// time t_b = branchTime(scenario) = road.smooth_until_s - options().obstacle_margin_before_s
  /// (run() lands a knot exactly there for such roads). Then, for each road r, the State saved at
  /// t_b and the knots recorded so far are restored, the road is switched, and a fresh integrator
  /// continues from t_b to the end. Result r is the run on roads[r]: its output rows at t <= t_b
  /// are bit-identical to those of run() on that road; after t_b it equals run() only within the
  /// integrator's accuracy, because the integrator restarts at t_b (initial step, new Jacobian)
  /// where run() carries its step size on. A branched run is itself deterministic: the same
  /// inputs give bit-identical results, whatever the number of roads before or after it.
  /// stats: steps and steps_attempted include the common part; wall_s is the common part's wall
  /// time divided evenly among the roads plus the branch's own (integration and output).
  ///
  /// Preconditions, checked (InputError): at least one road and no null road; an iso8608 road
  /// with smooth_until_s such that 0 < t_b < duration_s; every road has the same obstacle
  /// windows as roads[0] and the same profile before the front wheels reach smooth_until_s
  /// (i.e. they are makeRoad(scenario, ...) with different seeds). Invalid `values`: InputError as
  /// for run(). A failure of the common part fails every result (same message); a failure of a
  /// branch fails that result only. Never throws for a diverging simulation.
  std::vector<RunResult> runBranched(const std::vector<double>& values,
                                     const std::vector<const Road*>& roads,
                                     const ScenarioSpec& scenario);

  /// The branch time runBranched() would use for `scenario` (see there), or a negative value if
  /// the scenario has no smooth start to share.
  double branchTime(const ScenarioSpec& scenario) const;

  /// Channel names and units every run produces (runChannels(), twin/run_types.hpp).
  static std::vector<Channel> channels() { return runChannels(); }
  /// channels(), then one channel per sensor: runChannels(sensors).
  static std::vector<Channel> channels(const std::vector<SensorSpec>& sensors) {
    return runChannels(sensors);
  }

 private:
  struct Impl;
  /// The system the run vector `values` needs: impl_, or (built on first use) impl_filter_, which
  /// also integrates the auxiliary states of StrutFilter effects (top_mount_compliance) for runs
  /// where one is switched on. At their off values no extra state exists: exactly the base model.
  /// A run whose freed vehicle values (AssemblySpec::freed: a mass, an inertia) differ from those
  /// the system was built from first rebuilds it from Model::withFreedValues.
  Impl& pick(const std::vector<double>& values);
  /// pick(), or nullptr when the system cannot be built with the run's freed values (InputError,
  /// a value outside its range, passes through).
  Impl* pickBuildable(const std::vector<double>& values);
  std::unique_ptr<Impl> impl_;
  std::unique_ptr<Impl> impl_filter_;
};

/// The integration segments of a run on `road` (end time, step bound): the step is bounded by
/// obstacle_max_step_s while a front or rear wheel (`wheelbase` behind) is within the margins of
/// an obstacle, and a segment ends at a random road's branch time (its rough start less
/// obstacle_margin_before_s), so that the smooth lead-in is shared bit for bit.
std::vector<std::pair<double, double>> integrationSegments(const Road& road, const ScenarioSpec& sc,
                                                           const SimulationOptions& opt,
                                                           double wheelbase);

}  // namespace dtwin
