#include "subsystems/effects/progressive_spring.hpp"

namespace dtwin {

ProgressiveSpringEffect::ProgressiveSpringEffect() {
  specs_ = {effectParameter("stiffness3", "N/m^3",
                            "cubic spring coefficient k3: extra force k3 q^3 (off: 0)", 0.0, 0.0,
                            kUnbounded, 0.0, 5.0e7)};
}
double ProgressiveSpringEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  if (v[0] == 0.0) return 0.0;
  const double q = s.deflection_m;
  return v[0] * q * q * q;
}

}  // namespace dtwin
