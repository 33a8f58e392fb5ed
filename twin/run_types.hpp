#pragma once
// What a run takes and gives, without the simulator: the integrator settings a study names
// (SimulationOptions), a run's statistics, its frozen step plan, its result, and the channels every
// run writes. The file readers and writers (io/) include this header, never twin/simulator.hpp.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/stop.hpp"
#include "subsystems/sensor.hpp"
#include "twin/trace.hpp"

namespace dtwin {

struct SimulationOptions {
  /// rosenbrock (ROS34PW2, L-stable: the solid axle's wheel/axle interface is stiff) | rk-merson |
  /// rk3 | rk-feldberg | cpodes | semi-explicit-euler2 (Simbody's). docs/performance.md compares
  /// them.
  std::string integrator = "rosenbrock";
  double accuracy = 3e-4;   ///< integrator relative accuracy (docs/performance.md: error << noise)
  double max_step_s = 0.2;  ///< largest step anywhere
  double obstacle_max_step_s = 2e-3;  ///< largest step while a wheel crosses an obstacle
  double obstacle_margin_before_s = 0.02;
  double obstacle_margin_after_s = 0.05;
  double output_rate_hz = 1000.0;
  long max_internal_steps = 2000000;  ///< a run taking more steps is reported as failed
  double max_wall_s = 600.0;          ///< a run taking longer (wall clock) is reported as failed
  /// How the hub input (a tire law that follows the road signal) moves the wheels on MacPherson
  /// struts: "prescribed" (the hubs move as the signal; no wheel states, the body sets the steps)
  /// or "link" (wheel bodies held to the signal by the law's stiff link). docs/model.md, "Where the
  /// road enters". A solid axle always uses the link.
  std::string hub_motion = "prescribed";
  /// Checked at every integrator step: a requested stop throws Stopped (common/stop.hpp), not a
  /// failed run. Not a setting: no file names it and toJson leaves it out.
  StopToken stop;
  /// InputError "simulation.<field>: <rule>" (common/validate.hpp) when a field is out of range.
  void validate() const;
  nlohmann::json toJson() const;
  /// integrators()'s names.
  static std::vector<std::string> integratorNames();
};

struct RunStats {
  bool ok = true;
  std::string message;  ///< why a run failed
  long steps = 0;       ///< integrator steps taken
  long steps_attempted = 0;
  long knots = 0;       ///< recorded states
  double wall_s = 0.0;  ///< wall time of the run (integration + output)
  double sim_s = 0.0;   ///< simulated time
};

/// A frozen step sequence (docs/calibration.md, "A smooth objective"): the end time of every step
/// of one run of the rosenbrock integrator and whether the step began with a new Jacobian. An
/// adaptive integrator chooses its steps from the error of the run at hand, so its error changes
/// in jumps as the parameters move and the SSE of dense, quiet data is jagged. Replayed for other
/// parameters, one sequence makes every output a smooth function of them: the same arithmetic on
/// other numbers.
struct StepPlan {
  std::vector<double> times;  ///< end time of every step, ascending
  std::vector<unsigned char>
      new_jacobian;  ///< per step: 1 when a Jacobian was computed at its start
  std::size_t size() const { return times.size(); }
};

/// How a run chooses its integrator steps. Default: adaptively (SimulationOptions::accuracy).
/// `replay`: exactly the steps of that plan, with no error control (rosenbrock only; the plan must
/// come from a run of the same scenario and road, as its segment ends are steps of it).
/// `record`: receives the steps the run took (rosenbrock only; cleared first).
struct StepControl {
  const StepPlan* replay = nullptr;
  StepPlan* record = nullptr;
};

struct RunResult {
  Trace trace;  ///< every channel on the output grid (rows at k / output_rate_hz)
  /// Every channel at the scenario's sample_times_s (rows in that order), from the same dense
  /// output as the grid; empty when there are none or the run failed.
  Trace samples;
  RunStats stats;
};

/// Channel names and units every run produces.
std::vector<Channel> runChannels();
/// runChannels(), then one channel per sensor (SensorSpec::channel()): what a run of a model with
/// these sensors produces.
std::vector<Channel> runChannels(const std::vector<SensorSpec>& sensors);

}  // namespace dtwin
