#pragma once
// The `top_mount_compliance` effect (docs/model.md, "Effects"; registered in
// subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// Top-mount compliance: a rubber mount of compliance C = 1/k_mount in series with the main
/// damper (the damper is a Maxwell element: damper c and mount spring k_mount in series). The
/// damper force F_d obeys  tau dF_d/dt + F_d = c dq/dt,  tau = c C, i.e. c dq/dt through a
/// first-order low-pass with corner 1/(2 pi tau). Modelled with a true auxiliary state per strut
/// (z = F_d, a Simbody Z variable; no quasi-static approximation): the effect replaces the main
/// damper's c dq/dt by z (extra force z - c dq/dt). The main spring is not in series (dual-path
/// mount). Off: C = 0 (rigid mount; the simulator then adds no state, exactly the base model).
class TopMountComplianceEffect final : public Effect {
 public:
  TopMountComplianceEffect();
  std::string name() const override { return "top_mount_compliance"; }
  std::string description() const override {
    return "rubber top mount of compliance C in series with the damper: damper force low-pass "
           "filtered with "
           "tau = c C (auxiliary state per strut)";
  }
  std::string signature() const override {
    return "damping force attenuated and lagged above the corner frequency 1/(2 pi c C) (above 12 "
           "Hz over the prior at c = 2500 N s/m): "
           "residual concentrated in the wheel-hop band (10-20 Hz), little in body modes (1-2 Hz)";
  }
  EffectKind kind() const override { return EffectKind::StrutFilter; }
  bool screenedAtEachCorner() const override { return true; }  // a part that wears at one strut
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  bool filterActive(ParamValues p) const override { return p[0] > 0.0; }
  double calcFilterRate(const StrutState& s, double z, ParamValues p) const override;
  double calcFilteredStrutForce(const StrutState& s, double z, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
