#pragma once
// The `anti_roll_bar` effect (docs/model.md, "Effects"; registered in subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// Anti-roll (torsion) bar per axle: force k (q_left - q_right) on the left strut and the opposite
/// on the right, k = stiffness_front or stiffness_rear (linear rate at the wheel, or at the solid
/// axle's spring seats). Off: both stiffnesses 0.
class AntiRollBarEffect final : public Effect {
 public:
  AntiRollBarEffect();
  std::string name() const override { return "anti_roll_bar"; }
  std::string description() const override {
    return "torsion bar per axle: force k (q_left - q_right) on the left strut, the opposite on "
           "the right";
  }
  std::string signature() const override {
    return "residual only where left and right deflections differ (roll, one-sided obstacles, "
           "independent rough "
           "tracks), proportional to q_left - q_right and antisymmetric left/right; none on "
           "identical tracks";
  }
  EffectKind kind() const override { return EffectKind::AxleCoupling; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"roll_defl_", "linear"}; }
  double calcAxleCouplingForce(double q_left, double q_right, bool front,
                               ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
