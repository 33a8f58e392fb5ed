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
            {"travel_limit_m", "m", "travel from design height at which the hardstop engages", 0, 0, inf, false},
            {"hardstop_stiffness", "N/m", "hardstop penalty stiffness", 0, 0, inf, true}};
}

double LinearStrut::hardstop(double q, double limit, double k_hs) {
  if (q > limit) return k_hs * (q - limit);
  if (q < -limit) return k_hs * (q + limit);
  return 0.0;
}

double LinearStrut::calcForce(const StrutState& s, ParamValues p) const {
  return s.preload_N + p[0] * s.deflection_m + p[1] * s.rate_mps + hardstop(s.deflection_m, p[2], p[3]);
}

// ---------------------------------------------------------------- registry
// The one list of strut laws: each entry makes a law, which names itself. Adding a law is its
// class and one line here (docs/extending.md).
namespace {
const std::vector<Factory<StrutLaw>>& strutRegistry() {
  static const std::vector<Factory<StrutLaw>> r = {
      [] { return std::unique_ptr<StrutLaw>(std::make_unique<LinearStrut>()); },
  };
  return r;
}
}  // namespace

std::vector<std::string> strutLawNames() { return registeredNames(strutRegistry()); }

std::unique_ptr<StrutLaw> makeStrutLaw(const std::string& name, const std::string& where) {
  return makeRegistered(strutRegistry(), name, "strut option", where);
}

}  // namespace dtwin
