#include "subsystems/effect.hpp"

#include <cmath>
#include <limits>

#include "subsystems/errors.hpp"

namespace dtwin {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
ParameterSpec p(std::string name, std::string unit, std::string desc, double off, double lo,
                double hi, bool lo_incl = true) {
  ParameterSpec s;
  s.name = std::move(name);
  s.unit = std::move(unit);
  s.description = std::move(desc);
  s.default_value = off;
  s.min_value = lo;
  s.max_value = hi;
  s.min_inclusive = lo_incl;
  return s;
}
}  // namespace

BumpStopEffect::BumpStopEffect() {
  specs_ = {p("stiffness", "N/m^n", "bump-stop stiffness k (off: 0)", 0.0, 0.0, kInf),
            p("gap_m", "m", "compression from design height at which the stop touches", 0.05, 0.0, kInf),
            p("exponent", "1", "force exponent n (1 linear, 2 progressive)", 2.0, 1.0, 5.0)};
}
double BumpStopEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  const double d = s.deflection_m - v[1];
  return d > 0.0 ? v[0] * std::pow(d, v[2]) : 0.0;
}

DamperAsymmetryEffect::DamperAsymmetryEffect() {
  specs_ = {p("ratio", "1", "rebound / compression damping ratio (off: 1)", 1.0, 0.0, kInf, false)};
}
double DamperAsymmetryEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  return s.rate_mps < 0.0 ? (v[0] - 1.0) * s.base_damping * s.rate_mps : 0.0;
}

StrutFrictionEffect::StrutFrictionEffect() {
  specs_ = {p("force_N", "N", "Coulomb friction force level (off: 0)", 0.0, 0.0, kInf),
            p("smoothing_velocity_mps", "m/s", "tanh smoothing velocity", 0.01, 0.0, kInf, false)};
}
double StrutFrictionEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  return v[0] == 0.0 ? 0.0 : v[0] * std::tanh(s.rate_mps / v[1]);
}

TireEnvelopingEffect::TireEnvelopingEffect() {
  specs_ = {p("length_m", "m", "averaging base length (off: 0 = point contact)", 0.0, 0.0, 2.0)};
}
RoadSample TireEnvelopingEffect::filterRoad(const Road& road, Track t, double x, ParamValues v) const {
  return v[0] > 0.0 ? road.sampleAveraged(t, x, v[0]) : road.sample(t, x);
}

std::vector<std::string> effectNames() {
  return {"bump_stop", "damper_asymmetry", "strut_friction", "tire_enveloping"};
}

std::unique_ptr<Effect> makeEffect(const std::string& name, const std::string& where) {
  if (name == "bump_stop") return std::make_unique<BumpStopEffect>();
  if (name == "damper_asymmetry") return std::make_unique<DamperAsymmetryEffect>();
  if (name == "strut_friction") return std::make_unique<StrutFrictionEffect>();
  if (name == "tire_enveloping") return std::make_unique<TireEnvelopingEffect>();
  std::string known;
  for (auto& n : effectNames()) known += (known.empty() ? "" : ", ") + n;
  throw InputError(where, "unknown effect '" + name + "' (known: " + known + ")");
}

}  // namespace dtwin
