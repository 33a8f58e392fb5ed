#include "subsystems/effects/bump_stop.hpp"

#include <cmath>

namespace dtwin {

BumpStopEffect::BumpStopEffect() {
  specs_ = {
      effectParameter("stiffness", "N/m^n", "bump-stop stiffness k (off: 0)", 0.0, 0.0, kUnbounded,
                      0.0, 5.0e7),
      effectParameter("gap_m", "m", "compression from design height at which the stop touches",
                      0.05, 0.0, kUnbounded, 0.01, 0.15),
      effectParameter("exponent", "1", "force exponent n (1 linear, 2 progressive)", 2.0, 1.0, 5.0,
                      1.0, 3.0)};
  specs_[2].shape = true;
}
double BumpStopEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  const double d = s.deflection_m - v[1];
  return d > 0.0 ? v[0] * std::pow(d, v[2]) : 0.0;
}

}  // namespace dtwin
