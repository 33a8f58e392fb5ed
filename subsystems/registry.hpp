#pragma once
// The shape every subsystem registry shares (tire laws, strut laws): an ordered list of factories,
// each making one law that knows its own name.
#include <memory>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/names.hpp"

namespace dtwin {

template <class T>
using Factory = std::unique_ptr<T> (*)();

/// The names of the registered entries, in registry order.
template <class T>
std::vector<std::string> registeredNames(const std::vector<Factory<T>>& registry) {
  std::vector<std::string> out;
  for (const auto& make : registry) out.push_back(make()->name());
  return out;
}

/// The entry called `name`; InputError(where, "unknown <what> 'x' (known: ...; did you mean ...)").
template <class T>
std::unique_ptr<T> makeRegistered(const std::vector<Factory<T>>& registry, const std::string& name, const std::string& what,
                                  const std::string& where) {
  for (const auto& make : registry)
    if (auto entry = make(); entry->name() == name) return entry;
  throw InputError(where, unknownNameRule(what, name, registeredNames(registry)));
}

}  // namespace dtwin
