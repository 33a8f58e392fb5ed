// Private to twin/: the simulator's stepper. It integrates a run on the built system
// (twin/vehicle_system.hpp) from a start state through the run's integration segments, with the
// project's Rosenbrock-W (twin/rosenbrock.hpp, which may replay or record a step sequence) or a
// Simbody integrator, and records a knot per step: the values, rates and accelerations the
// recorder (twin/recorder.hpp) interpolates into the output.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "twin/vehicle_system.hpp"

namespace dtwin::sim {

/// Knot layout (one recorded integrator state): per corner (4 each) the hub's x, x rate, z, z rate
/// and z acceleration and the main strut's q, rate and acceleration; then the chassis.
namespace knot {
enum : std::size_t {
  HX = 0,
  HXD = 4,
  HZ = 8,
  HZD = 12,
  HZDD = 16,
  Q = 20,
  QD = 24,
  QDD = 28,
  BODY = 32 /* heave, pitch, roll: value, rate, accel (3 each) */,
  ZS = 41 /* prescribed hubs: the system's auxiliary states (at most kMaxZ); else unused */,
  KNOT = 49
};
constexpr std::size_t kMaxZ = KNOT - ZS;
}  // namespace knot
using Knots = std::vector<std::array<double, knot::KNOT>>;
using Segments = std::vector<std::pair<double, double>>;  // (end time, max step)

class Stepper {
 public:
  Stepper(VehicleSystem& sys, const SimulationOptions& opt) : sys_(sys), opt_(opt) {}

  /// Integrates from `s0` through segments [i0, i1) of `segs`, appending a knot per step (and one
  /// for `s0` itself when `record_start`). Never throws for a diverging run: ok = false and the
  /// message say why. On success `end` (if given) receives the final State.
  RunStats integrate(const State& s0, const Segments& segs, std::size_t i0, std::size_t i1,
                     bool record_start, Knots& knots, std::vector<double>& times, State* end,
                     StepControl steps = {});

  /// Appends the knot of `s` (realized to accelerations here if it is not yet) and its time.
  void record(const State& s, Knots& knots, std::vector<double>& times);
  std::unique_ptr<Integrator> makeIntegrator(const std::string& method);

  VehicleSystem& sys_;
  const SimulationOptions& opt_;
};

}  // namespace dtwin::sim
