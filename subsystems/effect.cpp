#include "subsystems/effect.hpp"

#include <cmath>
#include <limits>

#include "common/errors.hpp"

namespace dtwin {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
/// One effect parameter: off value, valid range [lo, hi] and prior range [prior_lo, prior_hi].
ParameterSpec p(std::string name, std::string unit, std::string desc, double off, double lo,
                double hi, double prior_lo, double prior_hi, bool lo_incl = true) {
  ParameterSpec s;
  s.name = std::move(name);
  s.unit = std::move(unit);
  s.description = std::move(desc);
  s.default_value = off;
  s.min_value = lo;
  s.max_value = hi;
  s.min_inclusive = lo_incl;
  s.prior_lower = prior_lo;
  s.prior_upper = prior_hi;
  return s;
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

std::vector<std::string> effectNames() {
  return {"bump_stop",          "damper_asymmetry",
          "strut_friction",     "tire_enveloping",
          "progressive_spring", "speed_dependent_tire_stiffness",
          "anti_roll_bar",      "top_mount_compliance"};
}

std::unique_ptr<Effect> makeEffect(const std::string& name, const std::string& where) {
  if (name == "bump_stop") return std::make_unique<BumpStopEffect>();
  if (name == "damper_asymmetry") return std::make_unique<DamperAsymmetryEffect>();
  if (name == "strut_friction") return std::make_unique<StrutFrictionEffect>();
  if (name == "tire_enveloping") return std::make_unique<TireEnvelopingEffect>();
  if (name == "progressive_spring") return std::make_unique<ProgressiveSpringEffect>();
  if (name == "speed_dependent_tire_stiffness") return std::make_unique<SpeedDependentTireStiffnessEffect>();
  if (name == "anti_roll_bar") return std::make_unique<AntiRollBarEffect>();
  if (name == "top_mount_compliance") return std::make_unique<TopMountComplianceEffect>();
  std::string known;
  for (auto& n : effectNames()) known += (known.empty() ? "" : ", ") + n;
  throw InputError(where, "unknown effect '" + name + "' (known: " + known + ")");
}

}  // namespace dtwin
