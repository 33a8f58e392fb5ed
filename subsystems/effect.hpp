#pragma once
// Optional physical effects: force elements that can be added to any assembly. Each has named
// parameters with units, an "off" value (its ParameterSpec::default_value) at which it exerts no
// force, and a signature: the trace it leaves in a residual. This catalogue is what the
// diagnosis ranks. Every effect is one entry of effectRegistry() (effect.cpp); how to add one:
// docs/extending.md.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "subsystems/parameter.hpp"
#include "subsystems/road.hpp"
#include "subsystems/strut_law.hpp"
#include "subsystems/tire_law.hpp"

namespace dtwin {

enum class EffectKind {
  Strut,         ///< adds a force along every suspension strut (chassis side), from q and dq/dt
  TireInput,     ///< modifies the road the tire sees (effective road)
  TireForce,     ///< multiplies the tire law's normal force by a factor (1 when off)
  AxleCoupling,  ///< a force pair between the left and right struts of an axle, from both deflections
  StrutFilter,   ///< a series element with one auxiliary state z [N] per strut (see calcFilterRate)
};

/// The name of a kind as docs/model.md writes it ("Strut", "TireInput", ...).
const char* kindName(EffectKind kind);

/// Where the diagnosis expects an effect's trace in the force-state maps of a residual
/// (docs/diagnosis.md, "The catalogue's signatures").
struct ResidualSignature {
  /// Prefix of the state the residual is binned against: "susp_defl_", "susp_rate_",
  /// "tire_defl_", "roll_defl_" (left − right deflection of an axle) or "speed_mps". Empty: no
  /// specific map (the diagnosis then cites none).
  std::string state_map;
  /// The signature fit expected on that map: on deflection-like states "knee", "cubic" or
  /// "linear"; on rate states "step", "rebound_slope", "compression_slope" or "linear".
  std::string feature;
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  /// What the effect leaves in a residual, in words (used by reports and the diagnosis).
  virtual std::string signature() const = 0;
  virtual EffectKind kind() const = 0;
  /// Each parameter's default_value is its off value; prior_lower/prior_upper its prior range.
  virtual const std::vector<ParameterSpec>& parameters() const = 0;
  /// Where the diagnosis looks for this effect's trace (default: no specific force-state map).
  virtual ResidualSignature residualSignature() const { return {}; }
  /// The parameter (a name in parameters(), unit m) that is an engagement threshold on suspension
  /// compression: the effect exerts no force until the deflection exceeds it (the bump stop's
  /// gap_m). When no plausible value of the effect changes these data, the diagnosis then says why
  /// ("the suspension never compresses beyond the smallest plausible gap (0.008 m < 0.01 m): a bump
  /// stop cannot act here", the parameter's name without "_m" and the effect's in words). Empty: none.
  virtual std::string engagementThreshold() const { return ""; }
  /// Strut effects: extra strut force [N] (same sign convention as StrutState).
  virtual double calcStrutForce(const StrutState& s, ParamValues p) const { return 0.0; }
  /// TireInput effects: the effective road under the contact point.
  virtual RoadSample filterRoad(const Road& road, Track t, double x, ParamValues p) const {
    return road.sample(t, x);
  }
  /// TireForce effects: the factor [1] the tire law's normal force is multiplied by (exactly 1
  /// when off). Must be >= 0 so the force stays >= 0.
  virtual double tireForceFactor(const TireState& s, ParamValues p) const { return 1.0; }
  /// AxleCoupling effects: the force [N] on the left strut of an axle (strut sign convention:
  /// positive pushes the wheel down and the chassis up); the right strut gets its negative.
  /// q_left, q_right: suspension deflections (compression positive); front: front axle.
  virtual double calcAxleCouplingForce(double q_left, double q_right, bool front, ParamValues p) const { return 0.0; }
  /// StrutFilter effects. Whether the auxiliary state is needed at all for parameters p (false
  /// at the off values: the simulator then integrates no extra state, so "off" is exactly the
  /// base model).
  virtual bool filterActive(ParamValues p) const { return false; }
  /// StrutFilter effects: dz/dt [N/s] of the strut's auxiliary state z [N] (z = 0 at rest).
  virtual double calcFilterRate(const StrutState& s, double z, ParamValues p) const { return 0.0; }
  /// StrutFilter effects: extra strut force [N] given the auxiliary state z.
  virtual double calcFilteredStrutForce(const StrutState& s, double z, ParamValues p) const { return 0.0; }
};

/// Suspension bump stop: F = k (q - gap)^n for q > gap (compression beyond the gap), else 0.
/// Off: k = 0. Signature: a knee in force vs deflection beyond the gap; peaks clipped on bumps.
class BumpStopEffect final : public Effect {
 public:
  BumpStopEffect();
  std::string name() const override { return "bump_stop"; }
  std::string description() const override { return "progressive rubber bump stop in compression"; }
  std::string signature() const override {
    return "residual grows like a knee in force vs suspension deflection beyond the gap; only at large compression (bump peaks)";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"susp_defl_", "knee"}; }
  std::string engagementThreshold() const override { return "gap_m"; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Damper asymmetry: rebound (extension, dq/dt < 0) damping is ratio times the compression
/// damping c: extra force (ratio - 1) c dq/dt for dq/dt < 0. Off: ratio = 1.
/// Signature: different slopes of force vs deflection rate either side of zero rate.
class DamperAsymmetryEffect final : public Effect {
 public:
  DamperAsymmetryEffect();
  std::string name() const override { return "damper_asymmetry"; }
  std::string description() const override { return "rebound/compression damping ratio"; }
  std::string signature() const override {
    return "residual linear in deflection rate on the rebound side only (slope change at zero rate)";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"susp_rate_", "rebound_slope"}; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Strut Coulomb friction, smoothed: F = F_c tanh(dq/dt / v_s). Off: F_c = 0.
/// Signature: a step in force vs deflection rate at zero rate; damps small motions most.
class StrutFrictionEffect final : public Effect {
 public:
  StrutFrictionEffect();
  std::string name() const override { return "strut_friction"; }
  std::string description() const override { return "Coulomb friction in the strut, tanh-smoothed"; }
  std::string signature() const override {
    return "residual is a step in force vs deflection rate at zero rate; strongest on small, slow motions";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"susp_rate_", "step"}; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Tire enveloping of short obstacles: the tire sees the moving average of the road over a
/// base length L centred on the contact point (a first-order stand-in for the tandem-cam
/// effective road; Zegelaar 1998). Off: L = 0 (single-point contact).
/// Signature: on short obstacles the measured force is lower and longer than the point-contact
/// model's spike; concentrated at high frequency (> 20 Hz) around obstacles.
class TireEnvelopingEffect final : public Effect {
 public:
  TireEnvelopingEffect();
  std::string name() const override { return "tire_enveloping"; }
  std::string description() const override { return "effective road: moving average over the contact length"; }
  std::string signature() const override {
    return "at short obstacles the measured peak is lower and wider than the model's; residual > 20 Hz near obstacles";
  }
  EffectKind kind() const override { return EffectKind::TireInput; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  RoadSample filterRoad(const Road& road, Track t, double x, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Progressive (cubic) spring in parallel with the main spring: F = k3 q^3 (odd: it stiffens
/// compression and rebound alike; tangent stiffness 3 k3 q^2). Off: k3 = 0.
class ProgressiveSpringEffect final : public Effect {
 public:
  ProgressiveSpringEffect();
  std::string name() const override { return "progressive_spring"; }
  std::string description() const override {
    return "progressive strut spring: extra force k3 q^3 (tangent stiffness 3 k3 q^2), both directions";
  }
  std::string signature() const override {
    return "residual grows cubically with |suspension deflection|, odd in deflection (compression and rebound); "
           "large-travel events (bump peaks, wheel drops), not small motions; independent of rate";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"susp_defl_", "cubic"}; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Speed-dependent tire vertical stiffness: the tire law's normal force is multiplied by
/// (1 + c_v v), v the vehicle's forward speed (TireState::forward_speed_mps). The whole law's
/// output is scaled (its damping term too, small against the elastic term). Off: c_v = 0.
class SpeedDependentTireStiffnessEffect final : public Effect {
 public:
  SpeedDependentTireStiffnessEffect();
  std::string name() const override { return "speed_dependent_tire_stiffness"; }
  std::string description() const override {
    return "tire normal force scaled by (1 + c_v v), v the forward speed: the tire stiffens with speed";
  }
  std::string signature() const override {
    return "residual proportional to the tire force (about the tire deflection) times the speed: none at rest, "
           "growing with speed; largest at tire-force peaks (obstacles) and in the wheel-hop band";
  }
  EffectKind kind() const override { return EffectKind::TireForce; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"tire_defl_", "linear"}; }
  double tireForceFactor(const TireState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Anti-roll (torsion) bar per axle: force k (q_left - q_right) on the left strut and the opposite
/// on the right, k = stiffness_front or stiffness_rear (linear rate at the wheel, or at the solid
/// axle's spring seats). Off: both stiffnesses 0.
class AntiRollBarEffect final : public Effect {
 public:
  AntiRollBarEffect();
  std::string name() const override { return "anti_roll_bar"; }
  std::string description() const override {
    return "torsion bar per axle: force k (q_left - q_right) on the left strut, the opposite on the right";
  }
  std::string signature() const override {
    return "residual only where left and right deflections differ (roll, one-sided obstacles, independent rough "
           "tracks), proportional to q_left - q_right and antisymmetric left/right; none on identical tracks";
  }
  EffectKind kind() const override { return EffectKind::AxleCoupling; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  ResidualSignature residualSignature() const override { return {"roll_defl_", "linear"}; }
  double calcAxleCouplingForce(double q_left, double q_right, bool front, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Top-mount compliance: a rubber mount of compliance C = 1/k_mount in series with the main
/// damper (the damper is a Maxwell element: damper c and mount spring k_mount in series). The
/// damper force F_d obeys  tau dF_d/dt + F_d = c dq/dt,  tau = c C, i.e. c dq/dt through a
/// first-order low-pass with corner 1/(2 pi tau). Modelled with a true auxiliary state per strut
/// (z = F_d, a Simbody Z variable; no quasi-static approximation): the effect replaces the main
/// damper's c dq/dt by z (extra force z - c dq/dt). The main spring is not in series (dual-path
/// mount). Off: C = 0 (rigid mount; the simulator then adds no state, exactly the base model).
class TopMountComplianceEffect final : public Effect {
 public:
  TopMountComplianceEffect();
  std::string name() const override { return "top_mount_compliance"; }
  std::string description() const override {
    return "rubber top mount of compliance C in series with the damper: damper force low-pass filtered with "
           "tau = c C (auxiliary state per strut)";
  }
  std::string signature() const override {
    return "damping force attenuated and lagged above the corner frequency 1/(2 pi c C) (above 12 Hz over the prior at c = 2500 N s/m): "
           "residual concentrated in the wheel-hop band (10-20 Hz), little in body modes (1-2 Hz)";
  }
  EffectKind kind() const override { return EffectKind::StrutFilter; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  bool filterActive(ParamValues p) const override { return p[0] > 0.0; }
  double calcFilterRate(const StrutState& s, double z, ParamValues p) const override;
  double calcFilteredStrutForce(const StrutState& s, double z, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// One effect parameter for an effect's parameters(): off value (default_value), valid range
/// [lo, hi] (lo excluded when !lo_inclusive) and prior range [prior_lo, prior_hi] (inside the valid
/// range, containing the off value: what the diagnosis searches).
ParameterSpec effectParameter(std::string name, std::string unit, std::string description, double off, double lo, double hi,
                              double prior_lo, double prior_hi, bool lo_inclusive = true);

/// One entry of the effect registry: the effect's name (its own name()) and its factory.
struct EffectEntry {
  std::string name;
  std::function<std::unique_ptr<Effect>()> make;
};

/// Every effect, in the order `twin list`, the study file and the diagnosis know them: the one
/// table in effect.cpp (names unique). A new effect is one line there (docs/extending.md).
const std::vector<EffectEntry>& effectRegistry();

/// The registered effect `name`. Throws InputError(where, "unknown effect 'x' (known: ...; did you
/// mean 'y'?)") (common/names.hpp unknownNameRule).
std::unique_ptr<Effect> makeEffect(const std::string& name, const std::string& where);
/// The registered names, in registry order.
std::vector<std::string> effectNames();

}  // namespace dtwin
