#include "subsystems/effects/speed_dependent_tire_stiffness.hpp"

#include <cmath>

namespace dtwin {

SpeedDependentTireStiffnessEffect::SpeedDependentTireStiffnessEffect() {
  specs_ = {effectParameter(
      "c_v", "s/m",
      "relative tire-force increase per unit forward speed: factor 1 + c_v v (off: 0)", 0.0, 0.0,
      kUnbounded, 0.0, 0.01)};
}
double SpeedDependentTireStiffnessEffect::tireForceFactor(const TireState& s, ParamValues v) const {
  return v[0] == 0.0 ? 1.0 : 1.0 + v[0] * std::abs(s.forward_speed_mps);
}

}  // namespace dtwin
