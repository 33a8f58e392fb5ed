#include "subsystems/effect_catalog.hpp"

#include <algorithm>

#include "common/errors.hpp"
#include "common/names.hpp"

namespace dtwin {

void EffectCatalog::add(const UserEffectSpec& spec) {
  for (const auto& e : effectRegistry())
    if (e.name == spec.name) throw InputError(spec.where, "'" + spec.name + "' is a built-in effect's name; give the user-defined one another");
  for (const auto& u : user_)
    if (u.name == spec.name) {
      if (sameDefinition(u, spec)) return;
      throw InputError(spec.where, "another definition of '" + spec.name + "' is in use (" + u.where + "): one study holds one definition per name");
    }
  (void)makeUserEffect(spec);  // every check, before it becomes known
  user_.push_back(spec);
}

std::unique_ptr<Effect> EffectCatalog::make(const std::string& name, const std::string& where) const {
  for (const auto& u : user_)
    if (u.name == name) return remakeUserEffect(u);  // checked when added
  for (const auto& e : effectRegistry())
    if (e.name == name) return e.value();
  if (name.rfind(kTermPrefix, 0) == 0) return makeEffect(name, where);
  throw InputError(where, unknownNameRule("effect", name, names()));
}

bool EffectCatalog::contains(const std::string& name) const {
  const auto n = names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

std::vector<std::string> EffectCatalog::names() const {
  std::vector<std::string> out = effectNames();
  for (const auto& u : user_) out.push_back(u.name);
  return out;
}

}  // namespace dtwin
