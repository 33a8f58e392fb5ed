#pragma once
// Strut laws: the force along a suspension strut (or any compliant interface) between an upper
// body (chassis, or axle) and a lower body (wheel carrier, axle, or wheel).
// Sign convention: deflection q > 0 is compression (lower body moves up relative to the upper);
// a positive force pushes the upper body up and the lower body down.
#include <memory>
#include <string>
#include <vector>

#include "subsystems/parameter.hpp"
#include "subsystems/registry.hpp"

namespace dtwin {

struct StrutState {
  double deflection_m = 0.0;    ///< q, compression positive, 0 at design ride height
  double rate_mps = 0.0;        ///< dq/dt
  double preload_N = 0.0;       ///< static force at q = 0 (set by the assembly from equilibrium)
  double base_stiffness = 0.0;  ///< k of the main spring [N/m] (effects such as asymmetry read it)
  double base_damping = 0.0;    ///< c of the main damper [N*s/m]
  // The run's context on a main strut, for effects (the laws ignore it; 0 elsewhere):
  double time_s = 0.0;              ///< simulation time
  double speed_mps = 0.0;           ///< vehicle forward speed
  double other_deflection_m = 0.0;  ///< q of the other main strut on the same axle
  double other_rate_mps = 0.0;      ///< its dq/dt
  bool front = true;                ///< on the front axle
  // The absolute motion at the corner, for effects that read it (Effect::needsMotion; 0 otherwise):
  double body_velocity_mps =
      0.0;  ///< world-vertical velocity of the strut's upper end on the body (up positive)
  double wheel_velocity_mps =
      0.0;  ///< world-vertical velocity of its lower end (the wheel centre; a solid axle's seat)
  double road_velocity_mps =
      0.0;  ///< vertical velocity of the road signal under the corner's wheel, dh/dt
};

/// The law of a suspension's main strut. The contract every registered law keeps (checked over
/// the registry by tests/subsystems/strut_law_test.cpp):
///   - its first two parameters are "stiffness" [N/m] and "damping" [N*s/m], shared by every
///     suspension option (the calibrated pair, and what effects read as base_stiffness and
///     base_damping);
///   - calcForce(q = 0, dq/dt = 0) equals preload_N, so design ride height is the static
///     equilibrium the simulator starts from;
///   - the force is finite for finite inputs.
class StrutLaw {
 public:
  virtual ~StrutLaw() = default;
  /// Option name as used in the study file's [subsystems] `strut` list ("linear").
  virtual std::string name() const = 0;
  /// One sentence for `twin list`.
  virtual std::string description() const = 0;
  virtual const std::vector<ParameterSpec>& parameters() const = 0;
  /// Strut force [N] (sign convention above).
  virtual double calcForce(const StrutState& s, ParamValues p) const = 0;
};

/// Linear spring-damper with preload and a travel-limit hardstop; MacPherson, paper eq. 4:
///   F = F0 + k q + c dq/dt + F_hardstop(q),
///   F_hardstop = k_hs (q - H) for q > H,  k_hs (q + H) for q < -H,  else 0,
/// with H the travel limit (Hmax = 0.25 m, Table 9) and k_hs a stiff penalty. The steering and
/// anti-sway terms of eq. 4 are zero in straight-line driving. The same law with an infinite
/// travel limit is the solid axle's wheel/axle interface, paper eq. 5 (F0 = 2907 N).
class LinearStrut final : public StrutLaw {
 public:
  LinearStrut();
  std::string name() const override { return "linear"; }
  std::string description() const override {
    return "preload + k q + c dq/dt, with a hardstop beyond the travel limit (paper eq. 4)";
  }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  /// Parameter order: stiffness, damping, travel_limit_m, hardstop_stiffness.
  double calcForce(const StrutState& s, ParamValues p) const override;
  static double hardstop(double q, double limit, double k_hs);

 private:
  std::vector<ParameterSpec> specs_;
};

/// Every strut law, in the order `twin list` shows them (docs: the "strut law" table of
/// docs/model.md).
const Registry<Factory<StrutLaw>>& strutLawRegistry();
/// Factory keyed by study-file option name. Throws InputError listing the known names.
std::unique_ptr<StrutLaw> makeStrutLaw(const std::string& name, const std::string& where);
/// The registered strut laws, in registry order; the first is the default when a study does
/// not name a `strut` subsystem.
std::vector<std::string> strutLawNames();

}  // namespace dtwin
