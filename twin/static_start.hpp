#pragma once
// The static start of a run whose corners differ: the warped equilibrium of four corners on a
// rigid body (docs/model.md, "Per-corner and per-axle values"). Pure arithmetic on the model's
// laws; the simulator sets its start state from it.
#include <array>

#include "twin/model.hpp"

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

}  // namespace dtwin
