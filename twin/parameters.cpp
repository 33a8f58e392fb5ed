#include "twin/parameters.hpp"

#include <algorithm>

#include "common/errors.hpp"

namespace dtwin {

void ParameterTable::declare(ParameterSpec spec) {
  DTWIN_CHECK(!contains(spec.name), "parameter declared twice: " + spec.name);
  ParameterEntry e;
  e.value = spec.default_value;
  e.spec = std::move(spec);
  entries_.emplace(e.spec.name, std::move(e));
}

const ParameterEntry& ParameterTable::at(const std::string& name) const {
  auto it = entries_.find(name);
  DTWIN_CHECK(it != entries_.end(), "no parameter " + name);
  return it->second;
}

void ParameterTable::set(const std::string& name, double value, const std::string& source,
                         const std::string& where, const std::optional<std::string>& unit) {
  auto it = entries_.find(name);
  if (it == entries_.end()) {
    std::string hint = closestName(name, names());
    throw InputError(where, "unknown parameter '" + name + "'" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  auto& e = it->second;
  if (unit && *unit != e.spec.unit)
    throw InputError(where, "unit of '" + name + "' must be \"" + e.spec.unit + "\", got \"" + *unit + "\"");
  const std::string rule = checkParameterValue(e.spec, value);
  if (!rule.empty()) throw InputError(where, name + " " + rule);
  e.value = value;
  e.source = source;
  e.has_value = true;
}

double ParameterTable::value(const std::string& name) const { return at(name).value; }

std::vector<std::string> ParameterTable::names() const {
  std::vector<std::string> out;
  for (auto& [k, v] : entries_) out.push_back(k);
  return out;
}

std::vector<std::string> ParameterTable::missing() const {
  std::vector<std::string> out;
  for (auto& [k, v] : entries_)
    if (!v.has_value) out.push_back(k);
  return out;
}

nlohmann::json ParameterTable::toJson() const {
  nlohmann::json j = nlohmann::json::object();
  for (auto& [k, e] : entries_) j[k] = {{"value", e.value}, {"unit", e.spec.unit}, {"source", e.source}};
  return j;
}

}  // namespace dtwin
