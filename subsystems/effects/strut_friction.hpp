#pragma once
// The `strut_friction` effect (docs/model.md, "Effects"; registered in subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// Strut Coulomb friction, smoothed: F = F_c tanh(dq/dt / v_s). Off: F_c = 0.
/// Signature: a step in force vs deflection rate at zero rate; damps small motions most.
class StrutFrictionEffect final : public Effect {
 public:
  StrutFrictionEffect();
  std::string name() const override { return "strut_friction"; }
  std::string description() const override {
    return "Coulomb friction in the strut, tanh-smoothed";
  }
  std::string signature() const override {
    return "residual is a step in force vs deflection rate at zero rate; strongest on small, slow "
           "motions";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  bool screenedAtEachCorner() const override { return true; }  // a part that wears at one strut
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"susp_rate_", "step"}; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
