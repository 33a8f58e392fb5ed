#pragma once
// The `groundhook` effect (docs/model.md, "Controlled suspensions"; registered in
// subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// A groundhook controller at every corner: an actuator in the strut that pushes on the wheel
/// against the wheel's own absolute vertical velocity, as if a damper c_gh tied the wheel to the
/// ground:  F = c_gh * vw  (strut sign: positive pushes the wheel down and the body up; vw the
/// world-vertical velocity of the strut's lower end, the wheel centre). It damps wheel hop; the
/// body feels the reaction. Off: c_gh = 0.
class GroundhookEffect final : public Effect {
 public:
  GroundhookEffect();
  std::string name() const override { return "groundhook"; }
  std::string description() const override {
    return "groundhook controller: an actuator force -c_gh vw on the wheel at each corner (its "
           "reaction on the body), vw the wheel's absolute vertical velocity";
  }
  std::string signature() const override {
    return "wheel hop (10-15 Hz) damped against the ground: wheel-hop band residual, with the "
           "reaction felt by the body";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  bool needsMotion() const override { return true; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override {
    return p[0] * s.wheel_velocity_mps;
  }

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
