#include "subsystems/parameter.hpp"

#include <sstream>
#include <stdexcept>

namespace dtwin {

std::string checkParameterValue(const ParameterSpec& spec, double v) {
  std::ostringstream os;
  os.precision(10);
  if (!std::isfinite(v)) {
    os << "must be a finite number, got " << v;
    return os.str();
  }
  const bool below = spec.min_inclusive ? v < spec.min_value : v <= spec.min_value;
  if (below) {
    os << "must be " << (spec.min_inclusive ? ">= " : "> ") << spec.min_value
       << (spec.unit == "1" ? "" : " " + spec.unit) << ", got " << v;
    return os.str();
  }
  if (v > spec.max_value) {
    os << "must be <= " << spec.max_value << (spec.unit == "1" ? "" : " " + spec.unit) << ", got "
       << v;
    return os.str();
  }
  return {};
}

std::size_t parameterIndex(const std::vector<ParameterSpec>& specs, const std::string& name) {
  for (std::size_t i = 0; i < specs.size(); ++i)
    if (specs[i].name == name) return i;
  throw std::logic_error("internal error: no parameter named '" + name + "'");
}

}  // namespace dtwin
