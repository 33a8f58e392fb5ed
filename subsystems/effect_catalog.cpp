#include "subsystems/effect_catalog.hpp"

#include <algorithm>

#include "common/errors.hpp"
#include "common/names.hpp"

namespace dtwin {

void EffectCatalog::add(const UserEffectSpec& spec) {
  for (const auto& e : effectRegistry())
    if (e.name == spec.name)
      throw InputError(
          spec.where,
          "'" + spec.name + "' is a built-in effect's name; give the user-defined one another");
  for (const auto& u : user_)
    if (u.name == spec.name) {
      if (sameDefinition(u, spec)) return;
      throw InputError(spec.where, "another definition of '" + spec.name + "' is in use (" +
                                       u.where + "): one study holds one definition per name");
    }
  (void)makeUserEffect(spec);  // every check, before it becomes known
  user_.push_back(spec);
}

std::unique_ptr<Effect> EffectCatalog::make(const std::string& name,
                                            const std::string& where) const {
  if (name.find('@') != std::string::npos && name.rfind(kTermPrefix, 0) != 0) {
    // An effect at one corner: the effect itself, installed there (the model keeps the corner).
    const EffectPlace at = splitEffectPlace(name, where);
    auto e = make(at.effect, where);
    if (!actsAtOneCorner(e->kind()))
      throw InputError(where, "'" + name + "': " + at.effect + " (" + kindName(e->kind()) +
                                  ") does not act at one corner; effects of kinds Strut, "
                                  "StrutFilter, TireInput, TireForce and TireLoad do");
    return e;
  }
  for (const auto& u : user_)
    if (u.name == name) return remakeUserEffect(u);  // checked when added
  for (const auto& e : effectRegistry())
    if (e.name == name) return e.value();
  if (name.rfind(kTermPrefix, 0) == 0) return makeEffect(name, where);
  throw InputError(where, unknownNameRule("effect", name, names()));
}

bool EffectCatalog::contains(const std::string& name) const {
  const auto n = names();
  if (std::find(n.begin(), n.end(), name) != n.end()) return true;
  if (name.find('@') == std::string::npos) return false;
  try {  // an effect of the catalogue at one corner
    const EffectPlace at = splitEffectPlace(name, "");
    return std::find(n.begin(), n.end(), at.effect) != n.end() &&
           actsAtOneCorner(make(at.effect, "")->kind());
  } catch (const InputError&) {
    return false;
  }
}

std::vector<std::string> EffectCatalog::names() const {
  std::vector<std::string> out = effectNames();
  for (const auto& u : user_) out.push_back(u.name);
  return out;
}

}  // namespace dtwin
