#include "subsystems/effects/strut_friction.hpp"

#include <cmath>

namespace dtwin {

StrutFrictionEffect::StrutFrictionEffect() {
  specs_ = {effectParameter("force_N", "N", "Coulomb friction force level (off: 0)", 0.0, 0.0,
                            kUnbounded, 0.0, 500.0),
            effectParameter("smoothing_velocity_mps", "m/s", "tanh smoothing velocity", 0.01, 0.0,
                            kUnbounded, 0.001, 0.05, false)};
  specs_[1].shape = true;
}
double StrutFrictionEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  return v[0] == 0.0 ? 0.0 : v[0] * std::tanh(s.rate_mps / v[1]);
}

}  // namespace dtwin
