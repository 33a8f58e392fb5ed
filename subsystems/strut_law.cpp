#include "subsystems/strut_law.hpp"

#include <limits>

#include "common/errors.hpp"
#include "common/names.hpp"
#include "subsystems/registry.hpp"

namespace dtwin {

LinearStrut::LinearStrut() {
  const double inf = std::numeric_limits<double>::infinity();
  specs_ = {{"stiffness", "N/m", "spring stiffness k", 0, 0, inf, false, true},
            {"damping", "N*s/m", "damping c", 0, 0, inf, true, true},
            {"travel_limit_m", "m", "travel from design height at which the hardstop engages", 0, 0,
             inf, false},
            {"hardstop_stiffness", "N/m", "hardstop penalty stiffness", 0, 0, inf, true}};
}

double LinearStrut::hardstop(double q, double limit, double k_hs) {
  if (q > limit) return k_hs * (q - limit);
  if (q < -limit) return k_hs * (q + limit);
  return 0.0;
}

double LinearStrut::calcForce(const StrutState& s, ParamValues p) const {
  return s.preload_N + p[0] * s.deflection_m + p[1] * s.rate_mps +
         hardstop(s.deflection_m, p[2], p[3]);
}

// ---------------------------------------------------------------- registry
// The one list of strut laws: each entry makes a law, which names itself. Adding a law is its
// class and one line here (docs/extending.md).
const Registry<Factory<StrutLaw>>& strutLawRegistry() {
  static const Registry<Factory<StrutLaw>> r(
      "strut option",
      {
          lawEntry<LinearStrut, StrutLaw>("a linear spring and damper about the static preload, "
                                          "with hardstops beyond the travel limit (paper eq. 4)"),
      });
  return r;
}

std::vector<std::string> strutLawNames() { return strutLawRegistry().names(); }

std::unique_ptr<StrutLaw> makeStrutLaw(const std::string& name, const std::string& where) {
  return strutLawRegistry().at(name, where).value();
}

}  // namespace dtwin
