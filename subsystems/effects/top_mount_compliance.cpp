#include "subsystems/effects/top_mount_compliance.hpp"

namespace dtwin {

TopMountComplianceEffect::TopMountComplianceEffect() {
  specs_ = {effectParameter("compliance_m_per_N", "m/N",
                            "series mount compliance C = 1/k_mount (off: 0, a rigid mount)", 0.0,
                            0.0, kUnbounded, 0.0, 5.0e-6)};
}
double TopMountComplianceEffect::calcFilterRate(const StrutState& s, double z,
                                                ParamValues v) const {
  const double tau = s.base_damping * v[0];
  return tau > 0.0 ? (s.base_damping * s.rate_mps - z) / tau : 0.0;
}
double TopMountComplianceEffect::calcFilteredStrutForce(const StrutState& s, double z,
                                                        ParamValues v) const {
  const double tau = s.base_damping * v[0];
  return tau > 0.0 ? z - s.base_damping * s.rate_mps : 0.0;
}

}  // namespace dtwin
