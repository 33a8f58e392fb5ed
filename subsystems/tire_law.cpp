#include "subsystems/tire_law.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/names.hpp"
#include "subsystems/registry.hpp"

namespace dtwin {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

ParameterSpec spec(std::string name, std::string unit, std::string desc, double lo, double hi,
                   bool shared = false, bool lo_inclusive = true) {
  ParameterSpec s;
  s.name = std::move(name);
  s.unit = std::move(unit);
  s.description = std::move(desc);
  s.min_value = lo;
  s.max_value = hi;
  s.shared = shared;
  s.min_inclusive = lo_inclusive;
  return s;
}
}  // namespace

double TireLaw::calcStaticDeflection(double load_N, ParamValues p) const {
  DTWIN_CHECK(load_N >= 0.0, "negative static load");
  if (load_N == 0.0) return 0.0;
  TireState s;
  double lo = 0.0, hi = 0.01;
  s.deflection_m = hi;
  while (calcNormalForce(s, p) < load_N) {
    hi *= 2.0;
    s.deflection_m = hi;
    DTWIN_CHECK(hi < 100.0, "tire law cannot carry the static load");
  }
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    s.deflection_m = mid;
    (calcNormalForce(s, p) < load_N ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// ---------------------------------------------------------------- Fiala
FialaTire::FialaTire() {
  specs_ = {spec("stiffness", "N/m", "vertical stiffness k", 0.0, kInf, true, false),
            spec("damping", "N*s/m", "vertical damping b on the deflection rate", 0.0, kInf, true),
            spec("unloaded_radius_m", "m", "unloaded radius R0", 0.0, kInf, true, false)};
}

double FialaTire::calcNormalForce(const TireState& s, ParamValues p) const {
  if (s.deflection_m <= 0.0) return 0.0;
  return std::max(0.0, p[0] * s.deflection_m + contactDampingForce(p[1], s));
}

// ---------------------------------------------------------------- PAC2002
namespace pac {
enum : std::size_t { Cz, C, R0, QFZ2, QFZ3, QV2, QFCX, QFCY, PPFZ1, FZ0, V0, P, P0, N };
}

Pac2002Tire::Pac2002Tire() {
  specs_.resize(pac::N);
  specs_[pac::Cz] =
      spec("stiffness", "N/m", "vertical stiffness Cz at the nominal load", 0, kInf, true, false);
  specs_[pac::C] =
      spec("damping", "N*s/m", "VERTICAL_DAMPING on the deflection rate", 0, kInf, true);
  specs_[pac::R0] = spec("unloaded_radius_m", "m", "UNLOADED_RADIUS R0", 0, kInf, true, false);
  specs_[pac::QFZ2] = spec("qfz2", "1", "QFZ2 quadratic stiffness coefficient", 0, kInf);
  specs_[pac::QFZ3] = spec("qfz3", "1", "QFZ3 camber dependency of stiffness", -kInf, kInf);
  specs_[pac::QV2] = spec("qv2", "1", "QV2 stiffness variation with speed", 0, kInf);
  specs_[pac::QFCX] = spec("qfcx", "1", "QFCX load response to Fx", -kInf, kInf);
  specs_[pac::QFCY] = spec("qfcy", "1", "QFCY load response to Fy", -kInf, kInf);
  specs_[pac::PPFZ1] = spec("ppfz1", "1", "PPFZ1 pressure effect on stiffness", -kInf, kInf);
  specs_[pac::FZ0] = spec("fnomin_N", "N", "FNOMIN nominal load Fz0", 0, kInf, false, false);
  specs_[pac::V0] = spec("longvl_mps", "m/s", "LONGVL measurement speed V0", 0, kInf, false, false);
  specs_[pac::P] =
      spec("inflation_pressure_Pa", "Pa", "INFLPRES inflation pressure p", 0, kInf, false, false);
  specs_[pac::P0] = spec("nompres_Pa", "Pa", "NOMPRES nominal pressure p0", 0, kInf, false, false);
}

namespace {
double qfz1(ParamValues p) {
  const double a = p[pac::Cz] * p[pac::R0] / p[pac::FZ0];
  return std::sqrt(std::max(0.0, a * a - 4.0 * p[pac::QFZ2]));
}
}  // namespace

std::string Pac2002Tire::checkCombination(ParamValues p) const {
  const double a = p[pac::Cz] * p[pac::R0] / p[pac::FZ0];
  if (a * a <= 4.0 * p[pac::QFZ2])
    return "PAC2002 needs (stiffness*R0/Fz0)^2 > 4*qfz2 so that qFz1 is real (stiffness " +
           std::to_string(p[pac::Cz]) + " N/m is too low for qfz2 " + std::to_string(p[pac::QFZ2]) +
           ")";
  return {};
}

double Pac2002Tire::calcNormalForce(const TireState& s, ParamValues p) const {
  if (s.deflection_m <= 0.0) return 0.0;
  const double R0 = p[pac::R0], Fz0 = p[pac::FZ0];
  const double speed = 1.0 + p[pac::QV2] * std::abs(s.wheel_speed_radps) * R0 / p[pac::V0];
  const double fx = p[pac::QFCX] * s.fx_N / Fz0, fy = p[pac::QFCY] * s.fy_N / Fz0;
  const double x = s.deflection_m / R0;
  const double g2 = s.camber_rad * s.camber_rad;
  const double dpi = (p[pac::P] - p[pac::P0]) / p[pac::P0];
  const double stiff = ((qfz1(p) + p[pac::QFZ3] * g2) * x + p[pac::QFZ2] * x * x);
  const double fz = (speed - fx * fx - fy * fy) * stiff * (1.0 + p[pac::PPFZ1] * dpi) * Fz0 +
                    contactDampingForce(p[pac::C], s);
  return std::max(0.0, fz);
}

double Pac2002Tire::statedStiffness(ParamValues p) const {
  const double dpi = (p[pac::P] - p[pac::P0]) / p[pac::P0];
  return p[pac::Cz] * (1.0 + p[pac::PPFZ1] * dpi);
}

double Pac2002Tire::operatingDeflection(ParamValues p) const {
  // Deflection at which the static part equals Fz0 with dpi = 0: b x^2 + a x - 1 = 0.
  const double a = qfz1(p), b = p[pac::QFZ2], R0 = p[pac::R0];
  const double x = b > 0 ? (-a + std::sqrt(a * a + 4 * b)) / (2 * b) : 1.0 / a;
  return x * R0;
}

// ---------------------------------------------------------------- the hub's own motion
HubInput::HubInput() {
  specs_ = {
      spec("link_stiffness", "N/m",
           "stiffness k_l of the link that holds the wheel centre to the signal", 0.0, kInf, false,
           false),
      spec("link_damping", "N*s/m",
           "damping c_l of that link, on the signal's rate minus the hub's", 0.0, kInf),
      spec("unloaded_radius_m", "m", "the wheel centre's height above the signal at zero load", 0.0,
           kInf, true, false)};
  specs_[0].default_value = 1e8;
  specs_[1].default_value = 1e5;
}

double HubInput::calcNormalForce(const TireState& s, ParamValues p) const {
  return p[0] * s.deflection_m + p[1] * (s.road_rate_mps + s.deflection_rate_mps);
}

// ---------------------------------------------------------------- registry
// The one list of tire laws: each entry makes a law, which names itself. Adding a law is its
// class and one line here (docs/extending.md).
const Registry<Factory<TireLaw>>& tireLawRegistry() {
  static const Registry<Factory<TireLaw>> r(
      "tire option",
      {
          lawEntry<FialaTire, TireLaw>("Fiala's vertical law: linear stiffness on the deflection, "
                                       "contact damping (paper eq. 2)"),
          lawEntry<Pac2002Tire, TireLaw>(
              "PAC2002's vertical law (MFeval): quadratic in the deflection, speed, pressure and "
              "camber terms (paper eq. 3)"),
          lawEntry<HubInput, TireLaw>(
              "the road signal is the wheel centre's own motion (a hub-motion estimate): the wheel "
              "follows it through a stiff two-sided link, with no tire compliance and no lift-off"),
      });
  return r;
}

std::vector<std::string> tireLawNames() { return tireLawRegistry().names(); }

std::unique_ptr<TireLaw> makeTireLaw(const std::string& name, const std::string& where) {
  return tireLawRegistry().at(name, where).value();
}

}  // namespace dtwin
