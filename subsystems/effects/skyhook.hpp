#pragma once
// The `skyhook` effect (docs/model.md, "Controlled suspensions"; registered in
// subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// A skyhook controller at every corner: an actuator in the strut that pushes on the body against
/// the body's own absolute vertical velocity at the corner, as if a damper c_sky hung the body
/// from the sky:  F = -c_sky * vb  (strut sign: positive pushes the body up and the wheel down; vb
/// the world-vertical velocity of the strut's top). Ideal (active): it may also push when a
/// semi-active damper could not. On a body held to rigid hubs (sprung mass m, spring k, damper c)
/// it raises the damping ratio from c / (2 sqrt(k m)) to (c + c_sky) / (2 sqrt(k m)) without
/// stiffening the road's path to the body. Off: c_sky = 0.
class SkyhookEffect final : public Effect {
 public:
  SkyhookEffect();
  std::string name() const override { return "skyhook"; }
  std::string description() const override {
    return "skyhook controller: an actuator force -c_sky vb on the body at each corner, vb the "
           "body's absolute vertical velocity there";
  }
  std::string signature() const override {
    return "the body's motion damped against the sky: body-mode (1-2 Hz) residual that a passive "
           "damper cannot remove without "
           "passing more of the road to the body; the wheel-hop band little changed";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  bool needsMotion() const override { return true; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override {
    return -p[0] * s.body_velocity_mps;
  }

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
