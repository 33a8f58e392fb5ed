#pragma once
// Helpers of the subsystem tests that evaluate strut laws and effects (effect_test.cpp,
// strut_law_test.cpp and the per-effect tests in tests/subsystems/effects/).
#include <map>
#include <string>
#include <vector>

#include "subsystems/effect.hpp"
#include "subsystems/road.hpp"
#include "subsystems/strut_law.hpp"

namespace dtwin_test {

inline constexpr dtwin::Track kTracks[] = {dtwin::Track::Left, dtwin::Track::Right};

/// Deflection q and rate q' at a mid-size corner: preload 2907 N, k 30 kN/m, c 2500 N s/m.
inline dtwin::StrutState strut(double q, double qdot) {
  dtwin::StrutState s;
  s.deflection_m = q;
  s.rate_mps = qdot;
  s.preload_N = 2907.0;
  s.base_stiffness = 30000.0;
  s.base_damping = 2500.0;
  return s;
}

/// The "off" values of an effect (each ParameterSpec's default_value).
inline std::vector<double> offValues(const dtwin::Effect& e) {
  std::vector<double> v;
  for (const auto& s : e.parameters()) v.push_back(s.default_value);
  return v;
}

/// The off values with some parameters replaced by name.
inline std::vector<double> valuesWith(const dtwin::Effect& e,
                                      const std::map<std::string, double>& on) {
  std::vector<double> v = offValues(e);
  for (const auto& [name, value] : on) v[dtwin::parameterIndex(e.parameters(), name)] = value;
  return v;
}

}  // namespace dtwin_test
