#include "subsystems/effects/anti_roll_bar.hpp"

namespace dtwin {

AntiRollBarEffect::AntiRollBarEffect() {
  specs_ = {effectParameter("stiffness_front_N_per_m", "N/m",
                            "front bar rate at the wheels: force k (q_left - q_right) (off: 0)",
                            0.0, 0.0, kUnbounded, 0.0, 40000.0),
            effectParameter("stiffness_rear_N_per_m", "N/m",
                            "rear bar rate at the wheels (or spring seats) (off: 0)", 0.0, 0.0,
                            kUnbounded, 0.0, 40000.0)};
}
double AntiRollBarEffect::calcAxleCouplingForce(double q_left, double q_right, bool front,
                                                ParamValues v) const {
  const double k = front ? v[0] : v[1];
  return k == 0.0 ? 0.0 : k * (q_left - q_right);
}

}  // namespace dtwin
