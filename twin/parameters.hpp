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
  ParameterSpec spec;  ///< full dotted name in spec.name, unit, valid range
  double value = 0.0;
  std::string source;  ///< e.g. "data/vehicle/midsize.toml: chassis.mass_kg (chosen ...)"
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
  void set(const std::string& name, double value, const std::string& source,
           const std::string& where, const std::optional<std::string>& unit = std::nullopt);
  double value(const std::string& name) const;
  std::vector<std::string> names() const;
  /// The rule for a name the table does not hold: a malformed per-corner factor named as such
  /// (cornerFactorRule), else "unknown parameter 'x' (did you mean 'y'?)".
  std::string unknownRule(const std::string& name) const;
  /// Names whose value is missing.
  std::vector<std::string> missing() const;
  nlohmann::json toJson() const;

 private:
  std::map<std::string, ParameterEntry> entries_;
};

/// Per-corner and per-axle factors (docs/model.md, "Per-corner and per-axle values"): for each
/// value of kCornerFactorValues and each place of kFactorPlaces a dimensionless factor
/// "<value>@<place>" (default 1, > 0). The value used at corner c is
/// value x factor(axle of c) x factor(c), each factor applied only when it is a run parameter.
inline constexpr const char* kCornerFactorValues[] = {"suspension.stiffness", "suspension.damping",
                                                      "tire.stiffness", "tire.damping"};
/// The places: the four corners (Corner order, twin/model.hpp) and the two axles.
inline constexpr const char* kFactorPlaces[] = {"fl", "fr", "rl", "rr", "front", "rear"};
/// The prior range a calibration or a diagnosis may search a factor over.
inline constexpr double kFactorPriorLower = 0.2, kFactorPriorUpper = 2.0;

/// A factor's name split: the value it scales and its place (index into kFactorPlaces: 0-3 a
/// corner, 4 front, 5 rear).
struct CornerFactor {
  std::string value;
  int place = -1;
};
/// The factor `name` names, or nullopt when it is none (no '@', an unknown place, or a value
/// without per-corner factors).
std::optional<CornerFactor> parseCornerFactor(const std::string& name);
/// "<value>@<place>".
std::string cornerFactorName(const std::string& value, int place);
/// Every factor name, value by value and place by place.
std::vector<std::string> cornerFactorNames();
/// Declares every factor in `table` at 1 (run parameters only when a model calibrates, frees or
/// sets them away from 1: Model).
void declareCornerFactors(ParameterTable& table);
/// For a name with '@' that is no factor, the rule it breaks (an unknown place, a value without
/// per-corner factors); "" otherwise.
std::string cornerFactorRule(const std::string& name);

}  // namespace dtwin
