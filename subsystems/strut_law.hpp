#pragma once
// Strut laws: the force along a suspension strut (or any compliant interface) between an upper
// body (chassis, or axle) and a lower body (wheel carrier, axle, or wheel).
// Sign convention: deflection q > 0 is compression (lower body moves up relative to the upper);
// a positive force pushes the upper body up and the lower body down.
#include <string>
#include <vector>

#include "subsystems/parameter.hpp"

namespace dtwin {

struct StrutState {
  double deflection_m = 0.0;  ///< q, compression positive, 0 at design ride height
  double rate_mps = 0.0;      ///< dq/dt
  double preload_N = 0.0;     ///< static force at q = 0 (set by the assembly from equilibrium)
  double base_stiffness = 0.0;  ///< k of the main spring [N/m] (effects such as asymmetry read it)
  double base_damping = 0.0;    ///< c of the main damper [N*s/m]
};

/// Linear spring-damper with preload and a travel-limit hardstop; MacPherson, paper eq. 4:
///   F = F0 + k q + c dq/dt + F_hardstop(q),
///   F_hardstop = k_hs (q - H) for q > H,  k_hs (q + H) for q < -H,  else 0,
/// with H the travel limit (Hmax = 0.25 m, Table 9) and k_hs a stiff penalty. The steering and
/// anti-sway terms of eq. 4 are zero in straight-line driving. The same law with an infinite
/// travel limit is the solid axle's wheel/axle interface, paper eq. 5 (F0 = 2907 N).
class LinearStrut {
 public:
  LinearStrut();
  const std::vector<ParameterSpec>& parameters() const { return specs_; }
  /// Parameter order: stiffness, damping, travel_limit_m, hardstop_stiffness.
  double calcForce(const StrutState& s, ParamValues p) const;
  static double hardstop(double q, double limit, double k_hs);

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
