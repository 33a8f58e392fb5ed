#pragma once
// The `progressive_spring` effect (docs/model.md, "Effects"; registered in subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// Progressive (cubic) spring in parallel with the main spring: F = k3 q^3 (odd: it stiffens
/// compression and rebound alike; tangent stiffness 3 k3 q^2). Off: k3 = 0.
class ProgressiveSpringEffect final : public Effect {
 public:
  ProgressiveSpringEffect();
  std::string name() const override { return "progressive_spring"; }
  std::string description() const override {
    return "progressive strut spring: extra force k3 q^3 (tangent stiffness 3 k3 q^2), both "
           "directions";
  }
  std::string signature() const override {
    return "residual grows cubically with |suspension deflection|, odd in deflection (compression "
           "and rebound); "
           "large-travel events (bump peaks, wheel drops), not small motions; independent of rate";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"susp_defl_", "cubic"}; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
