#pragma once
// Named, unit-carrying scalar parameters of force laws and effects.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace dtwin {

/// Description of one scalar parameter of a law. Values are passed to laws as a span of doubles
/// in the order of the law's `parameters()` list.
struct ParameterSpec {
  std::string name;            ///< local name, e.g. "stiffness"
  std::string unit;            ///< SI unit, e.g. "N/m"; "1" for dimensionless
  std::string description;     ///< one line
  double default_value = 0.0;  ///< for effects: the "off" value; for laws: informative only
  double min_value = -std::numeric_limits<double>::infinity();  ///< physically valid range
  double max_value = std::numeric_limits<double>::infinity();
  bool min_inclusive = true;
  /// Shared parameters are named "<subsystem>.<name>" (one value whatever option is chosen, e.g.
  /// the calibrated "tire.stiffness"); the others "<subsystem>.<option>.<name>".
  bool shared = false;
  /// (Last, after `shared`: laws initialise the fields above positionally.)
  /// Effects only: the prior range, i.e. the plausible range a diagnosis may search for this
  /// parameter (inside the valid range, containing the off value). NaN for laws' parameters.
  double prior_lower = std::numeric_limits<double>::quiet_NaN();
  double prior_upper = std::numeric_limits<double>::quiet_NaN();
  /// Effects only: a shape parameter (e.g. a force exponent, a smoothing velocity) that a
  /// diagnosis holds at its default while it calibrates the effect's other parameters.
  bool shape = false;
};

/// A read-only view of parameter values (pointer + count), in a law's `parameters()` order.
class ParamValues {
 public:
  ParamValues() = default;
  ParamValues(const double* data, std::size_t size) : data_(data), size_(size) {}
  ParamValues(const std::vector<double>& v)
      : data_(v.data()), size_(v.size()) {}  // NOLINT: implicit by design
  double operator[](std::size_t i) const { return data_[i]; }
  std::size_t size() const { return size_; }
  const double* data() const { return data_; }

 private:
  const double* data_ = nullptr;
  std::size_t size_ = 0;
};

/// Returns an empty string when `v` is valid for `spec`, else the broken rule
/// (e.g. "must be >= 0, got -3").
std::string checkParameterValue(const ParameterSpec& spec, double v);

/// Index of `name` in `specs`; throws std::logic_error if absent (a programming error).
std::size_t parameterIndex(const std::vector<ParameterSpec>& specs, const std::string& name);

}  // namespace dtwin
