#pragma once
// The `road_feedforward` effect (docs/model.md, "Controlled suspensions"; registered in
// subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// A feed-forward actuator at every corner driven by the road signal's vertical velocity under
/// its wheel (a preview or road-estimate controller): the strut force z follows G * vr through a
/// first-order low-pass of time constant tau,
///   tau dz/dt + z = G vr,   F = z,
/// (strut sign: positive pushes the body up and the wheel down). One auxiliary state per strut, as
/// top_mount_compliance has. G may have either sign (a controller that cancels the road's push on
/// the body has G < 0). tau is a shape parameter (held while a diagnosis calibrates G). Off: G = 0
/// (no state, exactly the base model).
class RoadFeedforwardEffect final : public Effect {
 public:
  RoadFeedforwardEffect();
  std::string name() const override { return "road_feedforward"; }
  std::string description() const override {
    return "feed-forward actuator: a strut force G vr through a first-order low-pass (time "
           "constant tau), vr the road signal's vertical "
           "velocity under the wheel (auxiliary state per strut)";
  }
  std::string signature() const override {
    return "a force in phase with the road's vertical velocity, lagged by tau: residual coherent "
           "with the road input at every "
           "frequency below 1/(2 pi tau)";
  }
  EffectKind kind() const override { return EffectKind::StrutFilter; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  bool needsMotion() const override { return true; }
  bool filterActive(ParamValues p) const override { return p[0] != 0.0; }
  double calcFilterRate(const StrutState& s, double z, ParamValues p) const override {
    return p[0] != 0.0 ? (p[0] * s.road_velocity_mps - z) / p[1] : 0.0;
  }
  double calcFilteredStrutForce(const StrutState&, double z, ParamValues p) const override {
    return p[0] != 0.0 ? z : 0.0;
  }

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
