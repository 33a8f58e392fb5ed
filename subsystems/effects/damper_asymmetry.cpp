#include "subsystems/effects/damper_asymmetry.hpp"

namespace dtwin {

DamperAsymmetryEffect::DamperAsymmetryEffect() {
  specs_ = {effectParameter("ratio", "1", "rebound / compression damping ratio (off: 1)", 1.0, 0.0,
                            kUnbounded, 0.5, 3.0, false)};
}
double DamperAsymmetryEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  return s.rate_mps < 0.0 ? (v[0] - 1.0) * s.base_damping * s.rate_mps : 0.0;
}

}  // namespace dtwin
