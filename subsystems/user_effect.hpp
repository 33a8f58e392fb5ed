#pragma once
// User-defined effects: a force element whose force is an expression in the study file, parsed
// once with muparser and evaluated from bytecode. No rebuild is needed.
//
// Four elements, each with the state variables its expression may use (userEffectVariables; the
// table in docs/extending.md, "Effects written as expressions"):
//   strut      a force along every main suspension strut, the built-in strut effects' sign
//              (positive pushes the wheel down and the chassis up): q, v, dq, dv, k, c, t, u,
//              front, and the absolute motion at the corner vb (body), vw (wheel), vr (road signal)
//   tire       a vertical force added to the tire law's at every wheel in contact (the sum is kept
//              >= 0): qt, vt, fz, zr, t, u, front
//   axle_roll  a force pair on each axle's main struts, F on the left and -F on the right:
//              dq, dv, t, u, front
//   chassis    a vertical force (up positive) between ground and the chassis at its mass centre:
//              z, w, pitch, roll, t, u
// and muparser's operators and functions (+ - * / ^, comparisons, ?:, sin, exp, sqrt, abs, sign,
// min, max, ...). Each parameter has a unit, a value and a prior range [lower, upper]. The value
// is the effect's "off" setting: with every parameter at its value the force must be 0, so adding
// the effect never changes a model until a parameter moves (what the diagnosis relies on).
//
// Units are checked: the expression, with every variable and parameter in its unit, must give a
// force in N. The check is the scaling test of dimensional homogeneity (common/units.hpp): measured
// in other units of mass, length and time, a homogeneous expression scales as a force does. A bare
// number in the expression counts as dimensionless.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "subsystems/effect.hpp"

namespace dtwin {

struct UserEffectParameter {
  std::string name, unit;
  double value = 0.0;               ///< the off value
  double lower = 0.0, upper = 0.0;  ///< the prior range (and the valid range), lower < upper
  bool shape = false;               ///< held at its value while a diagnosis calibrates the others
};

struct UserEffectSpec {
  std::string name;     ///< the effect's name (a study's [user_effects.NAME])
  std::string element;  ///< where the force acts: "strut", "tire", "axle_roll" or "chassis"
  std::string force;    ///< the expression
  std::vector<UserEffectParameter> parameters;
  std::string
      where;  ///< names the definition in errors, e.g. "study.toml:12: user_effects.soft_stop"
  /// Whether makeUserEffect checks the units (off only for the diagnosis's own library terms,
  /// whose coefficient's unit follows from the term).
  bool check_units = true;
};

/// One state variable of an element's expression.
struct UserEffectVariable {
  std::string name, unit, meaning;
  double lo = 0.0, hi = 0.0;  ///< a plausible range, where the checks evaluate the expression
};

/// The elements, in the order the documentation lists them.
std::vector<std::string> userEffectElements();
/// The state variables an element's expression may use, in the order the evaluator binds them
/// (empty for an unknown element).
const std::vector<UserEffectVariable>& userEffectVariables(const std::string& element);

/// Builds the effect; InputError(spec.where + "...", rule) for an element it does not know, a
/// parameter whose name is taken or not an identifier, a unit that does not parse, a missing or
/// empty prior range, a value outside it, an expression that does not parse or names an unknown
/// symbol, a force that is not finite, one that is not 0 with every parameter at its value, or
/// one whose units are not N.
std::unique_ptr<Effect> makeUserEffect(const UserEffectSpec& spec);

/// The effect of a definition makeUserEffect accepted, without its checks (what an EffectCatalog
/// makes each time a model installs the effect).
std::unique_ptr<Effect> remakeUserEffect(const UserEffectSpec& spec);
/// Whether two definitions give the same effect (element, force and parameters; names and
/// `where` aside).
bool sameDefinition(const UserEffectSpec& a, const UserEffectSpec& b);

}  // namespace dtwin
