#pragma once
// Optional physical effects: force elements that can be added to any assembly. Each has named
// parameters with units, an "off" value (its ParameterSpec::default_value) at which it exerts no
// force, and a signature: the trace it leaves in a residual. This catalogue is what the
// diagnosis ranks. Every effect is one entry of effectRegistry() (effect.cpp); how to add one:
// docs/extending.md.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "common/registry.hpp"
#include "subsystems/parameter.hpp"
#include "subsystems/road.hpp"
#include "subsystems/strut_law.hpp"
#include "subsystems/tire_law.hpp"

namespace dtwin {

enum class EffectKind {
  Strut,         ///< adds a force along every suspension strut (chassis side), from q and dq/dt
  TireInput,     ///< modifies the road the tire sees (effective road)
  TireForce,     ///< multiplies the tire law's normal force by a factor (1 when off)
  AxleCoupling,  ///< a force pair between the left and right struts of an axle, from both
                 ///< deflections
  StrutFilter,   ///< a series element with one auxiliary state z [N] per strut (see calcFilterRate)
  TireLoad,  ///< adds a vertical force to the tire law's, at every wheel in contact (calcTireLoad)
  ChassisForce,  ///< a vertical force between ground and the chassis at its mass centre
                 ///< (calcChassisForce)
};

/// Both main struts of one axle, for AxleCoupling effects (deflections compression positive).
struct AxleState {
  double q_left = 0.0, q_right = 0.0;  ///< deflections [m]
  double v_left = 0.0, v_right = 0.0;  ///< their rates [m/s]
  bool front = true;
  double time_s = 0.0, speed_mps = 0.0;
};

/// The chassis's motion from its start, for ChassisForce effects.
struct ChassisState {
  double heave_m = 0.0;                    ///< mass-centre height above its height at t = 0 [m]
  double heave_rate_mps = 0.0;             ///< its rate [m/s]
  double pitch_rad = 0.0, roll_rad = 0.0;  ///< from their values at t = 0
  double time_s = 0.0, speed_mps = 0.0;
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
  /// stop cannot act here", the parameter's name without "_m" and the effect's in words). Empty:
  /// none.
  virtual std::string engagementThreshold() const { return ""; }
  /// Strut and StrutFilter effects: whether the effect reads the absolute motion at the corner
  /// (StrutState's body, wheel and road velocities; a controller's sensors). The simulator
  /// computes them only when an installed effect says so.
  virtual bool needsMotion() const { return false; }
  /// Whether the diagnosis's default catalogue also screens this effect at each corner on its own
  /// ("bump_stop@rr": a part that wears or fails at one strut). Any effect that acts at a corner
  /// (actsAtOneCorner) can be installed at one when named; this only adds it to the default list.
  virtual bool screenedAtEachCorner() const { return false; }
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
  virtual double calcAxleCouplingForce(double q_left, double q_right, bool front,
                                       ParamValues p) const {
    return 0.0;
  }
  /// AxleCoupling effects, what the simulator calls: by default calcAxleCouplingForce of the
  /// deflections; an effect that reads rates, time or speed overrides this.
  virtual double calcAxleForce(const AxleState& a, ParamValues p) const {
    return calcAxleCouplingForce(a.q_left, a.q_right, a.front, p);
  }
  /// TireLoad effects: the force [N] added to the tire law's normal force (s.normal_force_N) at a
  /// wheel in contact (s.deflection_m > 0); the sum is clamped at >= 0 (a tire cannot pull).
  virtual double calcTireLoad(const TireState& s, ParamValues p) const { return 0.0; }
  /// ChassisForce effects: the vertical force [N, up positive] on the chassis at its mass centre
  /// (reacted by the ground: an aerodynamic lift, a test rig's actuator).
  virtual double calcChassisForce(const ChassisState& s, ParamValues p) const { return 0.0; }
  /// StrutFilter effects. Whether the auxiliary state is needed at all for parameters p (false
  /// at the off values: the simulator then integrates no extra state, so "off" is exactly the
  /// base model).
  virtual bool filterActive(ParamValues p) const { return false; }
  /// StrutFilter effects: dz/dt [N/s] of the strut's auxiliary state z [N] (z = 0 at rest).
  virtual double calcFilterRate(const StrutState& s, double z, ParamValues p) const { return 0.0; }
  /// StrutFilter effects: extra strut force [N] given the auxiliary state z.
  virtual double calcFilteredStrutForce(const StrutState& s, double z, ParamValues p) const {
    return 0.0;
  }
};

/// The corners an effect can be installed at on its own ("bump_stop@rr"), in the twin's corner
/// order: front-left, front-right, rear-left, rear-right (docs/model.md, "Effects at one corner").
inline constexpr const char* kEffectCorners[] = {"fl", "fr", "rl", "rr"};

/// Whether effects of `kind` act at each corner separately (a strut's or a tire's), so that one
/// can be installed at one corner: Strut, StrutFilter, TireInput, TireForce and TireLoad.
bool actsAtOneCorner(EffectKind kind);

/// An installed effect's name split: "bump_stop@rr" -> ("bump_stop", 3); "bump_stop" ->
/// ("bump_stop", -1: every corner). InputError(where, rule) for a place that is no corner.
struct EffectPlace {
  std::string effect;
  int corner = -1;
};
EffectPlace splitEffectPlace(const std::string& name, const std::string& where);

/// An effectParameter's upper limit when it has none.
inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// One effect parameter for an effect's parameters(): off value (default_value), valid range
/// [lo, hi] (lo excluded when !lo_inclusive) and prior range [prior_lo, prior_hi] (inside the valid
/// range, containing the off value: what the diagnosis searches).
ParameterSpec effectParameter(std::string name, std::string unit, std::string description,
                              double off, double lo, double hi, double prior_lo, double prior_hi,
                              bool lo_inclusive = true);

/// What the effect registry holds of an effect: its factory.
using EffectFactory = std::function<std::unique_ptr<Effect>()>;
/// One entry: the effect's name and description (its own name() and description()), its factory.
using EffectEntry = RegistryEntry<EffectFactory>;

/// Every effect, in the order `twin list`, the study file and the diagnosis know them: the one
/// table in effect.cpp (names unique). A new effect is one line there (docs/extending.md).
const Registry<EffectFactory>& effectRegistry();

/// The prefix of a library term (twin diagnose's proposal, docs/diagnosis.md):
/// makeEffect("term:EXPR") is the strut force a * (EXPR), EXPR in the user-effect variables q and
/// v, with one parameter a (off: 0). Such effects are made on demand and never listed by
/// effectNames().
inline constexpr const char* kTermPrefix = "term:";

/// The built-in effect `name`, or a library term. Throws InputError(where, "unknown effect 'x'
/// (known: ...; did you mean 'y'?)") (common/names.hpp unknownNameRule). A study's user-defined
/// effects are made by its EffectCatalog (subsystems/effect_catalog.hpp), which calls this.
std::unique_ptr<Effect> makeEffect(const std::string& name, const std::string& where);
/// The built-in effects' names, in registry order.
std::vector<std::string> effectNames();

}  // namespace dtwin
