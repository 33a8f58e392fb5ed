#include "subsystems/effect.hpp"

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/names.hpp"
// Effects in their own files, subsystems/effects/<name>.hpp (docs/extending.md): one #include
// each here, and one line in effectRegistry() below.
#include "subsystems/effects/anti_roll_bar.hpp"
#include "subsystems/effects/bump_stop.hpp"
#include "subsystems/effects/damper_asymmetry.hpp"
#include "subsystems/effects/groundhook.hpp"
#include "subsystems/effects/progressive_spring.hpp"
#include "subsystems/effects/road_feedforward.hpp"
#include "subsystems/effects/skyhook.hpp"
#include "subsystems/effects/speed_dependent_tire_stiffness.hpp"
#include "subsystems/effects/strut_friction.hpp"
#include "subsystems/effects/tire_enveloping.hpp"
#include "subsystems/effects/top_mount_compliance.hpp"
#include "subsystems/user_effect.hpp"

namespace dtwin {

ParameterSpec effectParameter(std::string name, std::string unit, std::string description,
                              double off, double lo, double hi, double prior_lo, double prior_hi,
                              bool lo_inclusive) {
  ParameterSpec s;
  s.name = std::move(name);
  s.unit = std::move(unit);
  s.description = std::move(description);
  s.default_value = off;
  s.min_value = lo;
  s.max_value = hi;
  s.min_inclusive = lo_inclusive;
  s.prior_lower = prior_lo;
  s.prior_upper = prior_hi;
  return s;
}

const char* kindName(EffectKind kind) {
  switch (kind) {
    case EffectKind::Strut:
      return "Strut";
    case EffectKind::TireInput:
      return "TireInput";
    case EffectKind::TireForce:
      return "TireForce";
    case EffectKind::AxleCoupling:
      return "AxleCoupling";
    case EffectKind::StrutFilter:
      return "StrutFilter";
    case EffectKind::TireLoad:
      return "TireLoad";
    case EffectKind::ChassisForce:
      return "ChassisForce";
  }
  return "?";
}

// ------------------------------------------------------------------ the registry
namespace {

/// The registry entry of effect class E: its name from E itself, and a factory.
template <class E>
EffectEntry entry() {
  return {E().name(), E().description(),
          [] { return std::unique_ptr<Effect>(std::make_unique<E>()); }};
}

}  // namespace

const Registry<EffectFactory>& effectRegistry() {
  // The one list of effects. A new effect: its class (subsystems/effects/<name>.hpp, #included
  // above) and one line here (docs/extending.md). The order is the order of `twin list`.
  static const Registry<EffectFactory> registry("effect",
                                                {
                                                    entry<BumpStopEffect>(),
                                                    entry<DamperAsymmetryEffect>(),
                                                    entry<StrutFrictionEffect>(),
                                                    entry<TireEnvelopingEffect>(),
                                                    entry<ProgressiveSpringEffect>(),
                                                    entry<SpeedDependentTireStiffnessEffect>(),
                                                    entry<AntiRollBarEffect>(),
                                                    entry<TopMountComplianceEffect>(),
                                                    entry<SkyhookEffect>(),
                                                    entry<GroundhookEffect>(),
                                                    entry<RoadFeedforwardEffect>(),
                                                });
  return registry;
}

std::vector<std::string> effectNames() { return effectRegistry().names(); }

std::unique_ptr<Effect> makeEffect(const std::string& name, const std::string& where) {
  if (const auto* e = effectRegistry().find(name)) return e->value();
  if (name.rfind(kTermPrefix, 0) == 0) {
    // A library term of twin diagnose's proposal: strut force a * (TERM), a unregistered user
    // effect.
    UserEffectSpec u;
    u.name = name;
    u.element = "strut";
    u.force = "a * (" + name.substr(std::string(kTermPrefix).size()) + ")";
    u.parameters = {{"a", "1", 0.0, -1e12, 1e12, false}};
    u.check_units = false;  // the coefficient's unit follows from the term (diagnosis/proposal.hpp)
    u.where = where + ": " + name;
    return makeUserEffect(u);
  }
  throw InputError(where, unknownNameRule("effect", name, effectNames()));
}

bool actsAtOneCorner(EffectKind kind) {
  return kind == EffectKind::Strut || kind == EffectKind::StrutFilter ||
         kind == EffectKind::TireInput || kind == EffectKind::TireForce ||
         kind == EffectKind::TireLoad;
}

EffectPlace splitEffectPlace(const std::string& name, const std::string& where) {
  const auto at = name.find('@');
  if (at == std::string::npos || name.rfind(kTermPrefix, 0) == 0) return {name, -1};
  const std::string place = name.substr(at + 1);
  for (int c = 0; c < 4; ++c)
    if (place == kEffectCorners[c]) return {name.substr(0, at), c};
  throw InputError(where, "'" + name +
                              "': an effect is installed at one corner (fl, fr, rl, rr) or at all "
                              "four (no @), not at '" +
                              place + "'");
}

}  // namespace dtwin
