#include "twin/parameters.hpp"

#include <algorithm>
#include <iterator>

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
  if (it == entries_.end()) throw InputError(where, unknownRule(name));
  auto& e = it->second;
  if (unit && *unit != e.spec.unit)
    throw InputError(
        where, "unit of '" + name + "' must be \"" + e.spec.unit + "\", got \"" + *unit + "\"");
  const std::string rule = checkParameterValue(e.spec, value);
  if (!rule.empty()) throw InputError(where, name + " " + rule);
  e.value = value;
  e.source = source;
  e.has_value = true;
}

std::string ParameterTable::unknownRule(const std::string& name) const {
  if (const std::string rule = cornerFactorRule(name); !rule.empty()) return rule;
  const std::string hint = closestName(name, names());
  return "unknown parameter '" + name + "'" +
         (hint.empty() ? "" : " (did you mean '" + hint + "'?)");
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
  for (auto& [k, e] : entries_)
    j[k] = {{"value", e.value}, {"unit", e.spec.unit}, {"source", e.source}};
  return j;
}

namespace {
std::string joinedNames(const char* const* first, const char* const* last) {
  std::string out;
  for (auto it = first; it != last; ++it) out += (out.empty() ? "" : ", ") + std::string(*it);
  return out;
}
}  // namespace

std::optional<CornerFactor> parseCornerFactor(const std::string& name) {
  const auto at = name.find('@');
  if (at == std::string::npos) return std::nullopt;
  const std::string value = name.substr(0, at), place = name.substr(at + 1);
  if (std::find(std::begin(kCornerFactorValues), std::end(kCornerFactorValues), value) ==
      std::end(kCornerFactorValues))
    return std::nullopt;
  const auto p = std::find(std::begin(kFactorPlaces), std::end(kFactorPlaces), place);
  if (p == std::end(kFactorPlaces)) return std::nullopt;
  return CornerFactor{value, static_cast<int>(p - std::begin(kFactorPlaces))};
}

std::string cornerFactorName(const std::string& value, int place) {
  return value + "@" + kFactorPlaces[static_cast<std::size_t>(place)];
}

std::vector<std::string> cornerFactorNames() {
  std::vector<std::string> out;
  for (const char* v : kCornerFactorValues)
    for (int p = 0; p < static_cast<int>(std::size(kFactorPlaces)); ++p)
      out.push_back(cornerFactorName(v, p));
  return out;
}

void declareCornerFactors(ParameterTable& table) {
  static const char* const words[] = {"the front left corner", "the front right corner",
                                      "the rear left corner",  "the rear right corner",
                                      "both front corners",    "both rear corners"};
  for (const char* v : kCornerFactorValues)
    for (int p = 0; p < static_cast<int>(std::size(kFactorPlaces)); ++p) {
      ParameterSpec s;
      s.name = cornerFactorName(v, p);
      s.unit = "1";
      s.description = std::string("factor on ") + v + " at " + words[p];
      s.default_value = 1.0;
      s.min_value = 0.0;
      s.min_inclusive = false;
      s.prior_lower = kFactorPriorLower;
      s.prior_upper = kFactorPriorUpper;
      table.declare(s);
      table.set(s.name, 1.0, "default (1): " + s.description, "");
    }
}

std::string cornerFactorRule(const std::string& name) {
  const auto at = name.find('@');
  if (at == std::string::npos || parseCornerFactor(name)) return {};
  const std::string value = name.substr(0, at), place = name.substr(at + 1);
  if (place.find('.') != std::string::npos)
    return {};  // an effect's value at one corner ("bump_stop@rr.gap_m"), no factor
  if (std::find(std::begin(kCornerFactorValues), std::end(kCornerFactorValues), value) ==
      std::end(kCornerFactorValues))
    return "'" + name + "': " + value + " has no per-corner or per-axle factor (values with one: " +
           joinedNames(std::begin(kCornerFactorValues), std::end(kCornerFactorValues)) + ")";
  return "'" + name + "': unknown place '" + place +
         "' (places: " + joinedNames(std::begin(kFactorPlaces), std::end(kFactorPlaces)) + ")";
}

}  // namespace dtwin
