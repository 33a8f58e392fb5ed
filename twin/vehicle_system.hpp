// Private to twin/: the simulator's system builder. It builds the Simbody system of one Model
// once: the chassis on a heave slider and a pitch/roll universal joint, the wheels (on sliders at
// MacPherson struts, or on a solid axle's slider and pin) and the force elements
// (twin/force_elements.hpp), which read the per-run context `ctx`. The static start
// (twin/static_start.hpp), the stepper (twin/stepper.hpp) and the recorder (twin/recorder.hpp)
// work on the built system; Simulator (twin/simulator.cpp) sets `ctx` before each run.
#pragma once

#include <array>

#include "twin/force_elements.hpp"

namespace dtwin::sim {

/// The Simbody system of one Model, built by the constructor. Neither copied nor moved: the force
/// elements point into it (ctx, struts, tires).
struct VehicleSystem {
  /// `filter_states` selects the system that also integrates the auxiliary states of StrutFilter
  /// effects (used for runs where such an effect is active); without, they are inert.
  VehicleSystem(const Model& model, bool filter_states);
  VehicleSystem(const VehicleSystem&) = delete;
  VehicleSystem& operator=(const VehicleSystem&) = delete;

  const Model& model;
  RunContext ctx;
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody::Slider heave;
  MobilizedBody::Universal chassis;
  std::array<MobilizedBody, 4> wheels;
  std::array<MobilizedBody, 2> axle_slider, axle;  // solid axle only
  std::array<StrutGeometry, 4> struts;               // main suspension strut per corner
  std::array<TireCorner, 4> tires;
  std::array<double, 4> strut_preload{};
  State default_state;
  QIndex heave_q, chassis_q;
  UIndex heave_u, chassis_u;

 private:
  void build(bool filter_states);
};

}  // namespace dtwin::sim
