#pragma once
// User-defined effects (issue 16, first part): a force element whose force is an expression in the
// study file, parsed once with muparser and evaluated from bytecode. No rebuild is needed.
//
// This part builds the strut element: an extra force along every suspension strut, with the same
// sign as the built-in strut effects (positive pushes the wheel down and the chassis up). Its
// expression may use the strut's state and the effect's own parameters:
//   q  deflection [m], compression positive, 0 at design ride height
//   v  deflection rate dq/dt [m/s]
//   k  the main spring's stiffness [N/m], c  the main damper's damping [N*s/m]
// and muparser's operators and functions (+ - * / ^, comparisons, ?:, sin, exp, sqrt, abs, sign,
// min, max, ...). Each parameter has a unit, a value and a prior range [lower, upper]. The value
// is the effect's "off" setting: with every parameter at its value the force must be 0, so adding
// the effect never changes a model until a parameter moves (what the diagnosis relies on).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "subsystems/effect.hpp"

namespace dtwin {

struct UserEffectParameter {
  std::string name, unit;
  double value = 0.0;                 ///< the off value
  double lower = 0.0, upper = 0.0;    ///< the prior range (and the valid range), lower < upper
  bool shape = false;                 ///< held at its value while a diagnosis calibrates the others
};

struct UserEffectSpec {
  std::string name;      ///< the effect's name (a study's [user_effects.NAME])
  std::string element;   ///< where the force acts: "strut"
  std::string force;     ///< the expression
  std::vector<UserEffectParameter> parameters;
  std::string where;     ///< names the definition in errors, e.g. "study.toml:12: user_effects.soft_stop"
};

/// The state variables an element's expression may use, in the order the evaluator binds them.
std::vector<std::string> userEffectVariables(const std::string& element);

/// Builds the effect; InputError(spec.where + "...", rule) for an element it does not know, a
/// parameter whose name is taken or not an identifier, a missing or empty prior range, a value
/// outside it, an expression that does not parse or names an unknown symbol, a force that is not
/// finite, or one that is not 0 with every parameter at its value.
std::unique_ptr<Effect> makeUserEffect(const UserEffectSpec& spec);

/// Makes `spec` known by name to makeEffect and effectNames (subsystems/effect.hpp), after the
/// built-in effects, for the rest of the process: a study file's [user_effects.NAME] tables are
/// registered when the study is read. Registering the same definition again does nothing.
/// InputError(spec.where, ...) when the name is a built-in effect's, or another definition of it
/// is registered already (two studies in one process that disagree).
void registerUserEffect(const UserEffectSpec& spec);
/// The effect of the registered definition `name` (no checks: they were made when it was
/// registered), or nullptr.
std::unique_ptr<Effect> makeRegisteredUserEffect(const std::string& name);
/// The registered names, in the order they were registered.
std::vector<std::string> userEffectNames();

}  // namespace dtwin
