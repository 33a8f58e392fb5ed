#pragma once
// The `bump_stop` effect (docs/model.md, "Effects"; registered in subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// Suspension bump stop: F = k (q - gap)^n for q > gap (compression beyond the gap), else 0.
/// Off: k = 0. Signature: a knee in force vs deflection beyond the gap; peaks clipped on bumps.
class BumpStopEffect final : public Effect {
 public:
  BumpStopEffect();
  std::string name() const override { return "bump_stop"; }
  std::string description() const override { return "progressive rubber bump stop in compression"; }
  std::string signature() const override {
    return "residual grows like a knee in force vs suspension deflection beyond the gap; only at "
           "large compression (bump peaks)";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  bool screenedAtEachCorner() const override { return true; }  // a part that wears at one strut
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"susp_defl_", "knee"}; }
  std::string engagementThreshold() const override { return "gap_m"; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
