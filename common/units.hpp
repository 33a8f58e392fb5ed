#pragma once
// Physical dimensions of unit strings, for checking that an expression's units add up (the
// user-defined effects, subsystems/user_effect.hpp). A unit is a product of SI symbols with
// optional powers: "N*s/m", "m/s^2", "kg*m^2", "N/m^1.5", "(m/s)^0.5", "1". Known symbols:
//   1 (none), kg, m, s, N = kg*m/s^2, Pa = N/m^2, J = N*m, W = J/s, Hz = 1/s, rad (none).
// Prefixed units (mm, kN, ms) are refused: values in a study file are SI.
#include <optional>
#include <string>

namespace dtwin {

/// Exponents of mass, length and time (rational powers are allowed: m^0.5).
struct Dimension {
  double mass = 0.0, length = 0.0, time = 0.0;
  bool operator==(const Dimension& o) const;
  bool operator!=(const Dimension& o) const { return !(*this == o); }
  Dimension operator*(const Dimension& o) const {
    return {mass + o.mass, length + o.length, time + o.time};
  }
  Dimension operator/(const Dimension& o) const {
    return {mass - o.mass, length - o.length, time - o.time};
  }
  Dimension pow(double e) const { return {mass * e, length * e, time * e}; }
  static Dimension force() { return {1, 1, -2}; }
};

/// The dimension of `unit`; std::nullopt and `rule` set to one sentence when it does not parse
/// or names an unknown symbol.
std::optional<Dimension> parseUnit(const std::string& unit, std::string& rule);

/// A readable unit of `d`: based on N when the mass exponent is 1 ("N*s/m^2"), else on kg, m and s
/// ("kg*m^2"); "1" for none. parseUnit(formatUnit(d)) == d.
std::string formatUnit(const Dimension& d);

/// The factor a quantity of dimension `d` is multiplied by when mass, length and time are
/// measured in units `fm`, `fl`, `ft` times smaller: fm^mass * fl^length * ft^time (the scaling
/// test of dimensional homogeneity).
double scaleFactor(const Dimension& d, double fm, double fl, double ft);

}  // namespace dtwin
