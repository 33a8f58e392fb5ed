#pragma once
// The table of every named scalar of a model: fixed vehicle data (masses, geometry) and the
// parameters of force laws and effects. Each value carries its unit and where it came from.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/names.hpp"

#include "subsystems/parameter.hpp"

namespace dtwin {

struct ParameterEntry {
  ParameterSpec spec;   ///< full dotted name in spec.name, unit, valid range
  double value = 0.0;
  std::string source;   ///< e.g. "data/vehicle/midsize.toml: chassis.mass_kg (chosen ...)"
  bool has_value = false;
};

class ParameterTable {
 public:
  /// Declares a parameter (no value yet). Re-declaring the same name is a programming error.
  void declare(ParameterSpec spec);
  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  const ParameterEntry& at(const std::string& name) const;
  /// Sets a value; throws InputError(where, rule) for unknown names, wrong units (if `unit` is
  /// given) or values outside the valid range.
  void set(const std::string& name, double value, const std::string& source, const std::string& where,
           const std::optional<std::string>& unit = std::nullopt);
  double value(const std::string& name) const;
  std::vector<std::string> names() const;
  /// Names whose value is missing.
  std::vector<std::string> missing() const;
  nlohmann::json toJson() const;

 private:
  std::map<std::string, ParameterEntry> entries_;
};


}  // namespace dtwin
