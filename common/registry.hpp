#pragma once
// The one shape of every extension point's registry: tire laws, strut laws, effects, road types,
// suspension options, sensor quantities, sensor models, integrators and the CLI's commands. A
// registry is an ordered list of entries, each a name, a one-line description and what the
// extension point needs of it (a factory, a parser, a value), with one error text for a name it
// does not hold ("unknown tire option 'fial' (known: fiala, pac2002; did you mean 'fiala'?)").
// `twin list --registries` prints every registry as a Markdown table, and a test checks each
// against its table in the docs (tests/docs/registry_docs_test.cpp).
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "common/names.hpp"

namespace dtwin {

template <class Value>
struct RegistryEntry {
  std::string name;
  std::string description;  ///< one line, as `twin list` and the docs show it
  Value value;
};

template <class Value>
class Registry {
 public:
  using Entry = RegistryEntry<Value>;

  /// `what` names an entry in errors ("tire option"). Throws std::logic_error for a repeated or
  /// empty name, or an entry without a description (a programming error, found at first use).
  Registry(std::string what, std::vector<Entry> entries)
      : what_(std::move(what)), entries_(std::move(entries)) {
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (entries_[i].name.empty() || entries_[i].description.empty())
        throw std::logic_error("registry of " + what_ + "s: entry " + std::to_string(i) +
                               " needs a name and a description");
      for (std::size_t j = 0; j < i; ++j)
        if (entries_[j].name == entries_[i].name)
          throw std::logic_error("registry of " + what_ + "s: '" + entries_[i].name +
                                 "' registered twice");
    }
  }

  const std::string& what() const { return what_; }
  const std::vector<Entry>& entries() const { return entries_; }
  typename std::vector<Entry>::const_iterator begin() const { return entries_.begin(); }
  typename std::vector<Entry>::const_iterator end() const { return entries_.end(); }
  std::size_t size() const { return entries_.size(); }

  /// The names, in registry order.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : entries_) out.push_back(e.name);
    return out;
  }
  /// The entry called `name`, or nullptr.
  const Entry* find(const std::string& name) const {
    for (const auto& e : entries_)
      if (e.name == name) return &e;
    return nullptr;
  }
  bool contains(const std::string& name) const { return find(name) != nullptr; }
  /// The entry called `name`; InputError(where, unknownNameRule(what, name, names())).
  const Entry& at(const std::string& name, const std::string& where) const {
    if (const Entry* e = find(name)) return *e;
    throw InputError(where, unknownNameRule(what_, name, names()));
  }

 private:
  std::string what_;
  std::vector<Entry> entries_;
};

}  // namespace dtwin
