// Private to twin/: the simulator's system builder. It builds the Simbody system of one Model
// once: the chassis on a heave slider and a pitch/roll universal joint, the wheels (on sliders at
// MacPherson struts, or on a solid axle's slider and pin) and the force elements
// (twin/force_elements.hpp), which read the per-run context `ctx`. The static start
// (twin/static_start.hpp), the stepper (twin/stepper.hpp) and the recorder (twin/recorder.hpp)
// work on the built system; Simulator (twin/simulator.cpp) sets `ctx` before each run.
#pragma once

#include <array>
#include <functional>

#include "twin/force_elements.hpp"

namespace dtwin::sim {

/// The Simbody system of one Model, built by the constructor. Neither copied nor moved: the force
/// elements point into it (ctx, struts, tires).
struct VehicleSystem {
  /// `filter_states` selects the system that also integrates the auxiliary states of StrutFilter
  /// effects (used for runs where such an effect is active); without, they are inert.
  /// `link_hubs`: a tire law that follows the signal (the hub input) holds the wheels to it by its
  /// stiff link even on MacPherson struts (SimulationOptions::hub_motion "link"); otherwise their
  /// motion is prescribed there (prescribed_hubs).
  VehicleSystem(const Model& model, bool filter_states, bool link_hubs = false);
  VehicleSystem(const VehicleSystem&) = delete;
  VehicleSystem& operator=(const VehicleSystem&) = delete;

  const Model& model;
  RunContext ctx;
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody::Slider heave;
  MobilizedBody::Universal chassis;
  /// The hub input on MacPherson struts: no wheel bodies (`wheels` empty handles); each hub moves
  /// as the road signal under it (TireCorner::hubPath) and its strut acts on the body alone
  /// (StrutGeometry::is_prescribed), with the wheel's reactions across the slide
  /// (HubReactionElement). The body alone sets the integrator's steps.
  bool prescribed_hubs = false;
  std::array<MobilizedBody, 4> wheels;
  std::array<MobilizedBody, 2> axle_slider, axle;  // solid axle only
  std::array<StrutGeometry, 4> struts;             // main suspension strut per corner
  std::array<TireCorner, 4> tires;
  std::array<double, 4> strut_preload{};
  State default_state;
  QIndex heave_q, chassis_q;
  UIndex heave_u, chassis_u;

  /// With prescribed hubs: the vertical force the road passes to the hub at corner c to hold the
  /// wheel on its path, m_w (z_hub'' + g) plus the strut's and any axle coupling's push (and the
  /// fore-aft reaction's part along the strut axis), for the hub's acceleration z_hub''. Velocity
  /// stage. (With wheel bodies the tire law gives it: Recorder.)
  double prescribedHubForce(const State& s, int c, double hub_zdd) const;

 private:
  void build(bool filter_states, bool link_hubs);
  /// The AxleCoupling effects' elements on each axle (with prescribed hubs, their share of each
  /// corner's strut_force_ too). After the struts.
  void installAxleCouplings();
  std::array<std::function<double(const State&)>, 4>
      strut_force_;  // prescribed hubs: strut + coupling, compression positive
};

}  // namespace dtwin::sim
