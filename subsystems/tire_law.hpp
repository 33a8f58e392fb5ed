#pragma once
// Vertical tire laws: the normal force between road and wheel hub.
//
// Contact model (the same for every law, stated plainly): single-point contact under the wheel
// centre. Deflection rho_z = R0 - (z_hub - h_road(x_contact)); the law is evaluated only for
// rho_z > 0 and the force is clamped at >= 0, so the wheel may leave the ground. A short-obstacle
// enveloping filter can be added as an effect (see effect.hpp, "tire_enveloping").
//
// Touch-down: the damping term b d(rho_z)/dt ramps in over the first kContactDampingRamp_m of
// deflection (b d(rho_z)/dt min(1, rho_z / ramp), the penetration depth of full damping of
// ADAMS's IMPACT function), so that the normal force is a continuous function of the state. With
// the damping at full strength from rho_z = 0+, the force jumped from 0 to b d(rho_z)/dt at
// touch-down, and a hub force sampled just after a wheel's touch-down jumped by up to its static
// load when a parameter moved that touch-down across the sample time: the calibration's SSE was
// discontinuous in θ (docs/model.md, "Tire contact").
#include <memory>
#include <string>
#include <vector>

#include "subsystems/parameter.hpp"
#include "subsystems/registry.hpp"

namespace dtwin {

/// Inputs of a vertical tire law at one instant.
struct TireState {
  double deflection_m = 0.0;  ///< rho_z, positive in contact
  /// Rate the damping term acts on. The twin passes -dz_hub/dt (paper eq. 2): see
  /// docs/model.md, "tire damping".
  double deflection_rate_mps = 0.0;
  double wheel_speed_radps = 0.0;  ///< |Omega|
  double forward_speed_mps =
      0.0;            ///< vehicle forward speed v (read by tire-force effects, not by the laws)
  double fx_N = 0.0;  ///< longitudinal force (PAC2002 load-response term)
  double fy_N = 0.0;  ///< lateral force
  double camber_rad = 0.0;  ///< inclination angle gamma
  // Read by effects only (the laws ignore them):
  double road_height_m = 0.0;   ///< road height under the wheel (before tire-input effects)
  double time_s = 0.0;          ///< simulation time
  bool front = true;            ///< on the front axle
  double normal_force_N = 0.0;  ///< the law's normal force (set before TireLoad effects run)
  /// The vertical velocity of the road under the wheel, dh/dt = slope x (forward speed of the
  /// contact point) [m/s]: the full deflection rate is road_rate_mps + deflection_rate_mps. Read by
  /// laws that follow the road signal (HubInput); the tire laws ignore it (see
  /// deflection_rate_mps).
  double road_rate_mps = 0.0;
};

/// Deflection [m] over which the tire damping ramps in at touch-down (see the header comment).
inline constexpr double kContactDampingRamp_m = 1e-3;

/// The damping force b d(rho_z)/dt with its touch-down ramp: b rate min(1, rho_z / ramp).
inline double contactDampingForce(double b, const TireState& s) {
  const double ramp =
      s.deflection_m < kContactDampingRamp_m ? s.deflection_m / kContactDampingRamp_m : 1.0;
  return b * s.deflection_rate_mps * ramp;
}

class TireLaw {
 public:
  virtual ~TireLaw() = default;
  /// Option name as used in study files ("fiala", "pac2002").
  virtual std::string name() const = 0;
  virtual const std::vector<ParameterSpec>& parameters() const = 0;
  /// Normal force [N], >= 0, and exactly 0 when deflection_m <= 0.
  virtual double calcNormalForce(const TireState& s, ParamValues p) const = 0;
  /// The stiffness [N/m] this law states for parameters p at its operating point
  /// (operatingDeflection), with zero rate, speed, Fx, Fy and camber.
  virtual double statedStiffness(ParamValues p) const = 0;
  /// Deflection [m] at the operating point where statedStiffness holds.
  virtual double operatingDeflection(ParamValues p) const = 0;
  /// Checks combinations of values that single-parameter ranges cannot express. Returns an
  /// empty string if valid, else the broken rule.
  virtual std::string checkCombination(ParamValues p) const { return {}; }
  /// False for a tire (the default): the force is >= 0 and 0 out of contact, the wheel may leave
  /// the road. True for a law that holds the wheel to the road signal (HubInput): the force may
  /// pull, so the wheel never leaves the signal. Such a law has no tire compliance, so it has
  /// no shared `stiffness` and `damping` (a study's calibrated tire.stiffness and tire.damping are
  /// left out of its assemblies).
  virtual bool followsSignal() const { return false; }
  /// Unloaded radius R0 [m] (every law has one).
  double unloadedRadius(ParamValues p) const {
    return p[parameterIndex(parameters(), "unloaded_radius_m")];
  }

  /// Static deflection [m] under `load_N` at zero speed (solved numerically, any monotone law).
  double calcStaticDeflection(double load_N, ParamValues p) const;
};

/// Fiala ("Fiala Wheel 2DOF", vertical motion mapped as linear stiffness and damping), paper eq. 2:
///   Fz = k rho_z + b d(rho_z)/dt,  clamped >= 0 (the damping with its touch-down ramp).
/// The paper writes "- b z'" with z the hub height; on a flat road d(rho_z)/dt = -z'. The twin
/// passes -z' as the rate (TireState::deflection_rate_mps). Parameters are in N/m and N s/m and
/// share the calibrated bounds of PAC2002 (docs/method.md §1 explains why the paper's Simulink
/// bounds are not used).
class FialaTire final : public TireLaw {
 public:
  FialaTire();
  std::string name() const override { return "fiala"; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  double calcNormalForce(const TireState& s, ParamValues p) const override;
  double statedStiffness(ParamValues p) const override { return p[0]; }
  double operatingDeflection(ParamValues p) const override { return 0.02; }

 private:
  std::vector<ParameterSpec> specs_;
};

/// PAC2002 vertical law ("Combined Slip Wheel 2DOF"; the same law as MFeval), paper eq. 3:
///   Fz = [1 + qV2 |Omega| R0/V0 - (qFcx Fx/Fz0)^2 - (qFcy Fy/Fz0)^2]
///        * [(qFz1 + qFz3 gamma^2) rho/R0 + qFz2 (rho/R0)^2] * (1 + ppFz1 dpi) * Fz0
///        + c d(rho)/dt,                                     clamped >= 0,
/// with dpi = (p - p0)/p0. The calibrated stiffness Cz sets qFz1 = sqrt((Cz R0/Fz0)^2 - 4 qFz2),
/// which makes the static stiffness equal Cz (1 + ppFz1 dpi) at the nominal load Fz0 (the
/// operating point; MFeval's convention). Unlike Chrono's ChPac02Tire, the qV2 and Fx/Fy terms
/// are kept, as in the paper.
class Pac2002Tire final : public TireLaw {
 public:
  Pac2002Tire();
  std::string name() const override { return "pac2002"; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  double calcNormalForce(const TireState& s, ParamValues p) const override;
  double statedStiffness(ParamValues p) const override;
  double operatingDeflection(ParamValues p) const override;
  std::string checkCombination(ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// The road signal is the motion of the wheel centre itself, not the road under a tire: a
/// logger's "road" that a car's own system estimates from its wheel sensors follows the wheel.
/// The wheel is held to the signal by a stiff, damped, two-sided link,
///   Fz = k_l rho_z + c_l (dh/dt - dz_hub/dt),    rho_z = R0 - (z_hub - h),
/// which may pull (followsSignal): the wheel never leaves the signal, and nothing between the
/// signal and the hub is compliant. With the defaults (k_l = 1e8 N/m, c_l = 1e5 N s/m) and a
/// 29.46 kg wheel the link's own mode is at 295 Hz with damping ratio 0.92: below 20 Hz the hub
/// follows the signal to 0.4 % in amplitude (docs/model.md, "Where the road enters").
class HubInput final : public TireLaw {
 public:
  HubInput();
  std::string name() const override { return "hub"; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  /// Parameter order: link_stiffness, link_damping, unloaded_radius_m.
  double calcNormalForce(const TireState& s, ParamValues p) const override;
  double statedStiffness(ParamValues p) const override { return p[0]; }
  double operatingDeflection(ParamValues p) const override { return 4000.0 / p[0]; }
  bool followsSignal() const override { return true; }

 private:
  std::vector<ParameterSpec> specs_;
};

/// Every tire law, in the order `twin list` shows them (docs: the "tire law" table of
/// docs/model.md).
const Registry<Factory<TireLaw>>& tireLawRegistry();
/// Factory keyed by study-file option name. Throws InputError listing the known names.
std::unique_ptr<TireLaw> makeTireLaw(const std::string& name, const std::string& where);
std::vector<std::string> tireLawNames();

}  // namespace dtwin
