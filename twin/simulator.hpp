#pragma once
// Runs one assembly in Simbody. A Simulator owns one Simbody System, built once from a Model;
// it then runs any number of per-run parameter vectors, roads and scenarios without rebuilding.
// A Simulator is used by one thread at a time (Simbody keeps mutable bookkeeping inside its
// System); parallel runs use one Simulator per worker, all sharing the same const Model.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subsystems/road.hpp"
#include "twin/model.hpp"
#include "twin/scenario.hpp"
#include "twin/trace.hpp"

namespace dtwin {

struct SimulationOptions {
  /// rosenbrock (ROS34PW2, L-stable: the solid axle's wheel/axle interface is stiff) | rk-merson |
  /// rk3 | rk-feldberg | cpodes | semi-explicit-euler2 (Simbody's). docs/performance.md compares them.
  std::string integrator = "rosenbrock";
  double accuracy = 3e-4;                ///< integrator relative accuracy (docs/performance.md: error << noise)
  double max_step_s = 0.2;               ///< largest step anywhere
  double obstacle_max_step_s = 2e-3;     ///< largest step while a wheel crosses an obstacle
  double obstacle_margin_before_s = 0.02;
  double obstacle_margin_after_s = 0.05;
  double output_rate_hz = 1000.0;
  long max_internal_steps = 2000000;     ///< a run taking more steps is reported as failed
  /// "" if valid, else "<field> <rule>".
  std::string check() const;
  nlohmann::json toJson() const;
  static std::vector<std::string> integratorNames();
};

struct RunStats {
  bool ok = true;
  std::string message;     ///< why a run failed
  long steps = 0;          ///< integrator steps taken
  long steps_attempted = 0;
  long knots = 0;          ///< recorded states
  double wall_s = 0.0;     ///< wall time of the run (integration + output)
  double sim_s = 0.0;      ///< simulated time
};

struct RunResult {
  Trace trace;
  RunStats stats;
};

class Simulator {
 public:
  Simulator(std::shared_ptr<const Model> model, SimulationOptions options);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  const Model& model() const;
  const SimulationOptions& options() const;

  /// Simulates `scenario` on `road` with run parameters `values` (layout: model().runParameterNames()).
  /// Never throws for a diverging simulation: stats.ok = false and stats.message say why.
  /// Throws InputError for invalid `values`.
  RunResult run(const std::vector<double>& values, const Road& road, const ScenarioSpec& scenario);

  /// Channel names and units every run produces.
  static std::vector<Channel> channels();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dtwin
