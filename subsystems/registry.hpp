#pragma once
// The law registries' entries (tire laws, strut laws): common/registry.hpp's Registry of
// factories, each entry named by the law it makes.
#include <memory>
#include <string>

#include "common/registry.hpp"

namespace dtwin {

template <class T>
using Factory = std::unique_ptr<T> (*)();

/// The registry entry of law class L (a subclass of Base): its name from L itself, the
/// description given, and a factory.
template <class L, class Base>
RegistryEntry<Factory<Base>> lawEntry(std::string description) {
  return {L().name(), std::move(description),
          [] { return std::unique_ptr<Base>(std::make_unique<L>()); }};
}

}  // namespace dtwin
