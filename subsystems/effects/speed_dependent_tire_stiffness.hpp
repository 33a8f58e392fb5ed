#pragma once
// The `speed_dependent_tire_stiffness` effect (docs/model.md, "Effects"; registered in
// subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// Speed-dependent tire vertical stiffness: the tire law's normal force is multiplied by
/// (1 + c_v v), v the vehicle's forward speed (TireState::forward_speed_mps). The whole law's
/// output is scaled (its damping term too, small against the elastic term). Off: c_v = 0.
class SpeedDependentTireStiffnessEffect final : public Effect {
 public:
  SpeedDependentTireStiffnessEffect();
  std::string name() const override { return "speed_dependent_tire_stiffness"; }
  std::string description() const override {
    return "tire normal force scaled by (1 + c_v v), v the forward speed: the tire stiffens with "
           "speed";
  }
  std::string signature() const override {
    return "residual proportional to the tire force (about the tire deflection) times the speed: "
           "none at rest, "
           "growing with speed; largest at tire-force peaks (obstacles) and in the wheel-hop band";
  }
  EffectKind kind() const override { return EffectKind::TireForce; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"tire_defl_", "linear"}; }
  double tireForceFactor(const TireState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
