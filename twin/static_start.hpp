#pragma once
// The static start of a run: the vehicle at rest at its static equilibrium at t = 0. When the
// corners differ, the warped equilibrium of four corners on a rigid body (docs/model.md,
// "Per-corner and per-axle values"; pure arithmetic on the model's laws), and the simulator's
// start state on the built Simbody system (StaticStart, private to twin/).
#include <array>

#include "twin/model.hpp"

namespace SimTK {
class State;
}  // namespace SimTK

namespace dtwin {

/// True when a tire factor of the run vector `p` is not 1 (the corners' tires differ).
bool tireFactorsActive(const Model& model, const double* p);

/// The warped static equilibrium: per corner (Corner order) the tire load and the main strut's
/// compression (a MacPherson strut; a solid axle's spring seat).
struct WarpedStart {
  std::array<double, 4> tire_load_N{}, strut_compression_m{};
};

/// Four corners on a rigid body are statically indeterminate by one warp mode
/// w = (+1, -1, -1, +1) (fl, fr, rl, rr): tire loads W_c + w_c d and main-strut forces
/// preload_c + w_c d e, which leave the body's force and moments as they are (e = 1 at MacPherson
/// struts; a solid axle's seats, spring_track apart, carry the wheels' roll moment:
/// e = track / spring_track). d keeps the chassis points of the four main struts coplanar.
/// Solved with the tire, strut and interface laws of `model` at the run vector `p`; the strut
/// effects are left out (the run settles from there).
WarpedStart warpedStart(const Model& model, const double* p);

namespace sim {
struct VehicleSystem;

/// The simulator's static start on its built system (twin/vehicle_system.hpp), for the run set up
/// in the system's context (run vector, road, speed): the tire loads (warped when the tires
/// differ), the hubs' targets on the road under the wheels, and a Newton solve of the chassis's
/// heave, pitch and roll that puts the hubs there.
class StaticStart {
 public:
  explicit StaticStart(VehicleSystem& sys) : sys_(sys) {}
  /// The system's default State at t = 0 set to the static equilibrium (zero velocities); it also
  /// stores the chassis's start coordinates in the context (ctx.heave0, pitch0, roll0).
  SimTK::State state();

 private:
  /// Static equilibrium at t = 0 for the run parameters in ctx (vehicle at rest, flat start).
  void setEquilibrium(SimTK::State& s);
  VehicleSystem& sys_;
};
}  // namespace sim

}  // namespace dtwin
