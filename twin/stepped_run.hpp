#pragma once
// One run of an assembly advanced step by step from outside, as a co-simulation drives it (the FMU
// of `twin export-fmu`, docs/fmu.md): it starts at the static equilibrium at t = 0, and each
// advance() integrates to a given time with the inputs given at the step's start (the speed, the
// road signal under each wheel, an actuator force in each strut), then reads every output channel
// there. The same system, start, integrator and outputs as Simulator::run (twin/simulator.hpp); the
// road and the speed are known only up to the present, so each step continues them along their
// last slope (a first-order hold, twin/input_road.hpp) and the actuator forces are held.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "twin/model.hpp"
#include "twin/run_types.hpp"

namespace dtwin {

/// What a co-simulation gives the twin at a communication point.
struct StepInputs {
  double speed_mps = 0.0;  ///< forward speed, >= 0
  /// The road signal under each wheel (Corner order): the road's height for a tire law on the
  /// road, the hub's motion for the hub input (tire = "hub"), as the study's road would give it.
  std::array<double, 4> road_m{};
  /// A force in each main strut (Corner order), strut sign: positive pushes the body up and the
  /// wheel down (the skyhook effect's sign).
  std::array<double, 4> actuator_N{};
};

class SteppedRun {
 public:
  /// InputError (common/errors.hpp) for invalid options.
  SteppedRun(std::shared_ptr<const Model> model, SimulationOptions options);
  ~SteppedRun();
  SteppedRun(const SteppedRun&) = delete;
  SteppedRun& operator=(const SteppedRun&) = delete;

  /// The output channels, in outputs() order: every run channel (runChannels(sensors)) but
  /// time_s, then the body's world-vertical velocity at the top of each main strut,
  /// body_vz_{fl,fr,rl,rr}_mps (what a skyhook controller reads).
  static std::vector<Channel> channels(const std::vector<SensorSpec>& sensors);

  /// Starts at t = 0 at the static equilibrium with run vector `values` (Model::runParameterNames
  /// layout) on the road `in` gives. InputError for invalid values or inputs; std::runtime_error
  /// (one line) when the start cannot be evaluated.
  void start(const std::vector<double>& values, const StepInputs& in);
  /// Integrates from time() to `t_end` (> time()) with `in` given at time(). std::runtime_error
  /// (one line) when the integration fails; the run cannot go on after that.
  void advance(double t_end, const StepInputs& in);

  double time() const;
  /// Every channel at time() (channels() order).
  const std::vector<double>& outputs() const;
  /// Integrator steps taken so far.
  long steps() const;
  const Model& model() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dtwin
