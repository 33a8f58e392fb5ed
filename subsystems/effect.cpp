#include "subsystems/effect.hpp"

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/names.hpp"
// Effects in their own files, subsystems/effects/<name>.hpp (docs/extending.md): one #include
// each here, and one line in effectRegistry() below.

namespace dtwin {

ParameterSpec effectParameter(std::string name, std::string unit, std::string description, double off, double lo, double hi,
                              double prior_lo, double prior_hi, bool lo_inclusive) {
  ParameterSpec s;
  s.name = std::move(name);
  s.unit = std::move(unit);
  s.description = std::move(description);
  s.default_value = off;
  s.min_value = lo;
  s.max_value = hi;
  s.min_inclusive = lo_inclusive;
  s.prior_lower = prior_lo;
  s.prior_upper = prior_hi;
  return s;
}

const char* kindName(EffectKind kind) {
  switch (kind) {
    case EffectKind::Strut: return "Strut";
    case EffectKind::TireInput: return "TireInput";
    case EffectKind::TireForce: return "TireForce";
    case EffectKind::AxleCoupling: return "AxleCoupling";
    case EffectKind::StrutFilter: return "StrutFilter";
  }
  return "?";
}

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
/// effectParameter, short.
ParameterSpec p(std::string name, std::string unit, std::string desc, double off, double lo, double hi, double prior_lo,
                double prior_hi, bool lo_incl = true) {
  return effectParameter(std::move(name), std::move(unit), std::move(desc), off, lo, hi, prior_lo, prior_hi, lo_incl);
}
}  // namespace

BumpStopEffect::BumpStopEffect() {
  specs_ = {p("stiffness", "N/m^n", "bump-stop stiffness k (off: 0)", 0.0, 0.0, kInf, 0.0, 5.0e7),
            p("gap_m", "m", "compression from design height at which the stop touches", 0.05, 0.0, kInf, 0.01, 0.15),
            p("exponent", "1", "force exponent n (1 linear, 2 progressive)", 2.0, 1.0, 5.0, 1.0, 3.0)};
  specs_[2].shape = true;
}
double BumpStopEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  const double d = s.deflection_m - v[1];
  return d > 0.0 ? v[0] * std::pow(d, v[2]) : 0.0;
}

DamperAsymmetryEffect::DamperAsymmetryEffect() {
  specs_ = {p("ratio", "1", "rebound / compression damping ratio (off: 1)", 1.0, 0.0, kInf, 0.5, 3.0, false)};
}
double DamperAsymmetryEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  return s.rate_mps < 0.0 ? (v[0] - 1.0) * s.base_damping * s.rate_mps : 0.0;
}

StrutFrictionEffect::StrutFrictionEffect() {
  specs_ = {p("force_N", "N", "Coulomb friction force level (off: 0)", 0.0, 0.0, kInf, 0.0, 500.0),
            p("smoothing_velocity_mps", "m/s", "tanh smoothing velocity", 0.01, 0.0, kInf, 0.001, 0.05, false)};
  specs_[1].shape = true;
}
double StrutFrictionEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  return v[0] == 0.0 ? 0.0 : v[0] * std::tanh(s.rate_mps / v[1]);
}

TireEnvelopingEffect::TireEnvelopingEffect() {
  specs_ = {p("length_m", "m", "averaging base length (off: 0 = point contact)", 0.0, 0.0, 2.0, 0.0, 0.4)};
}
RoadSample TireEnvelopingEffect::filterRoad(const Road& road, Track t, double x, ParamValues v) const {
  return v[0] > 0.0 ? road.sampleAveraged(t, x, v[0]) : road.sample(t, x);
}

ProgressiveSpringEffect::ProgressiveSpringEffect() {
  specs_ = {p("stiffness3", "N/m^3", "cubic spring coefficient k3: extra force k3 q^3 (off: 0)", 0.0, 0.0, kInf, 0.0, 5.0e7)};
}
double ProgressiveSpringEffect::calcStrutForce(const StrutState& s, ParamValues v) const {
  if (v[0] == 0.0) return 0.0;
  const double q = s.deflection_m;
  return v[0] * q * q * q;
}

SpeedDependentTireStiffnessEffect::SpeedDependentTireStiffnessEffect() {
  specs_ = {p("c_v", "s/m", "relative tire-force increase per unit forward speed: factor 1 + c_v v (off: 0)", 0.0, 0.0, kInf,
              0.0, 0.01)};
}
double SpeedDependentTireStiffnessEffect::tireForceFactor(const TireState& s, ParamValues v) const {
  return v[0] == 0.0 ? 1.0 : 1.0 + v[0] * std::abs(s.forward_speed_mps);
}

AntiRollBarEffect::AntiRollBarEffect() {
  specs_ = {p("stiffness_front_N_per_m", "N/m", "front bar rate at the wheels: force k (q_left - q_right) (off: 0)", 0.0, 0.0,
              kInf, 0.0, 40000.0),
            p("stiffness_rear_N_per_m", "N/m", "rear bar rate at the wheels (or spring seats) (off: 0)", 0.0, 0.0, kInf, 0.0,
              40000.0)};
}
double AntiRollBarEffect::calcAxleCouplingForce(double q_left, double q_right, bool front, ParamValues v) const {
  const double k = front ? v[0] : v[1];
  return k == 0.0 ? 0.0 : k * (q_left - q_right);
}

TopMountComplianceEffect::TopMountComplianceEffect() {
  specs_ = {p("compliance_m_per_N", "m/N", "series mount compliance C = 1/k_mount (off: 0, a rigid mount)", 0.0, 0.0, kInf,
              0.0, 5.0e-6)};
}
double TopMountComplianceEffect::calcFilterRate(const StrutState& s, double z, ParamValues v) const {
  const double tau = s.base_damping * v[0];
  return tau > 0.0 ? (s.base_damping * s.rate_mps - z) / tau : 0.0;
}
double TopMountComplianceEffect::calcFilteredStrutForce(const StrutState& s, double z, ParamValues v) const {
  const double tau = s.base_damping * v[0];
  return tau > 0.0 ? z - s.base_damping * s.rate_mps : 0.0;
}

// ------------------------------------------------------------------ the registry
namespace {

/// The registry entry of effect class E: its name from E itself, and a factory.
template <class E>
EffectEntry entry() {
  return {E().name(), [] { return std::unique_ptr<Effect>(std::make_unique<E>()); }};
}

}  // namespace

const std::vector<EffectEntry>& effectRegistry() {
  // The one list of effects. A new effect: its class (subsystems/effects/<name>.hpp, #included
  // above) and one line here (docs/extending.md). The order is the order of `twin list`.
  static const std::vector<EffectEntry> registry = [] {
    std::vector<EffectEntry> r = {
        entry<BumpStopEffect>(),
        entry<DamperAsymmetryEffect>(),
        entry<StrutFrictionEffect>(),
        entry<TireEnvelopingEffect>(),
        entry<ProgressiveSpringEffect>(),
        entry<SpeedDependentTireStiffnessEffect>(),
        entry<AntiRollBarEffect>(),
        entry<TopMountComplianceEffect>(),
    };
    std::set<std::string> seen;
    for (const auto& e : r)
      if (!seen.insert(e.name).second) throw std::logic_error("effectRegistry: effect '" + e.name + "' registered twice");
    return r;
  }();
  return registry;
}

std::vector<std::string> effectNames() {
  std::vector<std::string> names;
  for (const auto& e : effectRegistry()) names.push_back(e.name);
  return names;
}

std::unique_ptr<Effect> makeEffect(const std::string& name, const std::string& where) {
  for (const auto& e : effectRegistry())
    if (e.name == name) return e.make();
  throw InputError(where, unknownNameRule("effect", name, effectNames()));
}

}  // namespace dtwin
