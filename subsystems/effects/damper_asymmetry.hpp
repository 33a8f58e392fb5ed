#pragma once
// The `damper_asymmetry` effect (docs/model.md, "Effects"; registered in subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// Damper asymmetry: rebound (extension, dq/dt < 0) damping is ratio times the compression
/// damping c: extra force (ratio - 1) c dq/dt for dq/dt < 0. Off: ratio = 1.
/// Signature: different slopes of force vs deflection rate either side of zero rate.
class DamperAsymmetryEffect final : public Effect {
 public:
  DamperAsymmetryEffect();
  std::string name() const override { return "damper_asymmetry"; }
  std::string description() const override { return "rebound/compression damping ratio"; }
  std::string signature() const override {
    return "residual linear in deflection rate on the rebound side only (slope change at zero "
           "rate)";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  bool screenedAtEachCorner() const override { return true; }  // a part that wears at one strut
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"susp_rate_", "rebound_slope"}; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
