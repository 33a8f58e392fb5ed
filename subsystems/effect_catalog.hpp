#pragma once
// The effects one study knows: the built-in ones (effectRegistry, subsystems/effect.hpp) and the
// study's own [user_effects] definitions (subsystems/user_effect.hpp). A Study owns one and
// passes it to what makes effects (the model, the parameter table, the diagnosis's candidates,
// `twin list`); there is no process-wide list, so two studies in one process never see each
// other's definitions. A catalogue is a value: adding to a copy leaves the original unchanged.
#include <memory>
#include <string>
#include <vector>

#include "subsystems/effect.hpp"
#include "subsystems/user_effect.hpp"

namespace dtwin {

class EffectCatalog {
 public:
  /// The built-in effects only.
  EffectCatalog() = default;

  /// Adds a user-defined effect after every check of makeUserEffect. The same definition again
  /// does nothing. InputError(spec.where, ...) when the name is a built-in effect's, or another
  /// definition of it is in the catalogue already.
  void add(const UserEffectSpec& spec);

  /// The effect `name`: a built-in one, a user-defined one of this catalogue, or a library term
  /// ("term:EXPR", subsystems/effect.hpp kTermPrefix). Throws InputError(where, "unknown effect
  /// 'x' (known: ...; did you mean 'y'?)").
  std::unique_ptr<Effect> make(const std::string& name, const std::string& where) const;
  /// Whether `name` is a built-in or user-defined effect of this catalogue (terms are not listed).
  bool contains(const std::string& name) const;
  /// The built-in effects in registry order, then the user-defined ones in the order added.
  std::vector<std::string> names() const;
  /// The user-defined definitions, in the order added.
  const std::vector<UserEffectSpec>& userEffects() const { return user_; }

 private:
  std::vector<UserEffectSpec> user_;
};

}  // namespace dtwin
