#include "subsystems/sensor.hpp"

#include <limits>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/names.hpp"

namespace dtwin {

namespace {
const char* kWheelMounts[4] = {"wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr"};
}  // namespace

nlohmann::json SensorFilter::toJson() const {
  nlohmann::json j = {{"order", order}};
  if (order > 0) j["cutoff_hz"] = cutoff_hz;
  if (order == 2) j["damping"] = damping;
  return j;
}

std::string SensorSpec::channel() const {
  switch (quantity) {
    case SensorQuantity::DisplacementZ:
      return name + "_m";
    case SensorQuantity::VelocityZ:
      return name + "_mps";
    case SensorQuantity::AccelerationZ:
      return name + "_mps2";
    case SensorQuantity::Travel:
      return name + "_m";
    case SensorQuantity::TravelRate:
      return name + "_mps";
  }
  return name;
}

std::string SensorSpec::unit() const {
  switch (quantity) {
    case SensorQuantity::DisplacementZ:
      return "m";
    case SensorQuantity::VelocityZ:
      return "m/s";
    case SensorQuantity::AccelerationZ:
      return "m/s^2";
    case SensorQuantity::Travel:
      return "m";
    case SensorQuantity::TravelRate:
      return "m/s";
  }
  return "";
}

int SensorSpec::corner() const {
  for (int c = 0; c < 4; ++c)
    if (mount == kWheelMounts[c]) return c;
  return -1;
}

void SensorSpec::validate(const std::string& where) const {
  bool name_ok = !name.empty() && name.size() <= 40 && name[0] >= 'a' && name[0] <= 'z';
  for (char c : name)
    name_ok = name_ok && ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_');
  if (!name_ok)
    throw InputError(where,
                     "sensor name '" + name +
                         "' must be 1-40 characters of a-z, 0-9 and _, starting with a letter");
  if (mount != "chassis" && corner() < 0)
    throw InputError(
        where + ".body",
        "must be \"chassis\", \"wheel_fl\", \"wheel_fr\", \"wheel_rl\" or \"wheel_rr\", got \"" +
            mount + "\"");
  for (double x : position_m)
    if (!(std::isfinite(x) && std::abs(x) <= 10.0))
      throw InputError(
          where + ".position_m",
          "each coordinate must be a finite number of at most 10 m, got " + formatNumber(x));
  if (corner() >= 0 && (position_m[0] != 0 || position_m[1] != 0 || position_m[2] != 0))
    throw InputError(
        where + ".position_m",
        "a wheel sensor measures at the wheel centre: leave position_m out (or [0, 0, 0])");
  if (relative() && corner() < 0)
    throw InputError(
        where + ".body",
        "a " + sensorQuantityName(quantity) +
            " sensor measures a wheel's travel relative to the chassis: body must be \"wheel_fl\", "
            "\"wheel_fr\", \"wheel_rl\" or \"wheel_rr\", got \"" +
            mount + "\"");
  if (filter.order < 0 || filter.order > 2)
    throw InputError(where + ".filter.order",
                     "must be 0 (none), 1 or 2, got " + std::to_string(filter.order));
  if (filter.order > 0 &&
      !(std::isfinite(filter.cutoff_hz) && filter.cutoff_hz > 0 && filter.cutoff_hz <= 1e4))
    throw InputError(where + ".filter.cutoff_hz",
                     "must lie in (0, 1e4] Hz, got " + formatNumber(filter.cutoff_hz));
  if (filter.order == 2 &&
      !(std::isfinite(filter.damping) && filter.damping > 0 && filter.damping <= 10))
    throw InputError(where + ".filter.damping",
                     "must lie in (0, 10], got " + formatNumber(filter.damping));
  if (!(std::isfinite(noise_sd) && noise_sd >= 0))
    throw InputError(where + ".noise_sd",
                     "must be a finite number >= 0, got " + formatNumber(noise_sd));
  if (positionMeasured() && !(std::isfinite(position_sd_m) && position_sd_m <= 10.0))
    throw InputError(
        where + ".position_sd_m",
        "must be a finite number of metres in [0, 10], got " + formatNumber(position_sd_m));
  if (positionMeasured() && corner() >= 0)
    throw InputError(where + ".position_sd_m",
                     "a wheel sensor sits at the wheel centre: only a chassis sensor's position is "
                     "declared measured");
}

nlohmann::json SensorSpec::toJson() const {
  nlohmann::json j = {{"name", name},
                      {"channel", channel()},
                      {"body", mount},
                      {"quantity", sensorQuantityName(quantity)},
                      {"filter", filter.toJson()}};
  if (corner() < 0) j["position_m"] = position_m;
  if (noise_sd > 0) j["noise_sd"] = noise_sd;
  if (positionMeasured()) j["position_sd_m"] = position_sd_m;
  return j;
}

const Registry<SensorQuantity>& sensorQuantities() {
  static const Registry<SensorQuantity> r(
      "sensor quantity",
      {
          {"displacement_z",
           "the point's world-vertical displacement from its start (channel NAME_m); the point: on "
           "the chassis, or a wheel centre",
           SensorQuantity::DisplacementZ},
          {"velocity_z", "the point's world-vertical velocity (channel NAME_mps)",
           SensorQuantity::VelocityZ},
          {"acceleration_z",
           "the point's world-vertical acceleration d²z/dt², 0 at rest (channel NAME_mps2)",
           SensorQuantity::AccelerationZ},
          {"travel",
           "a wheel's travel relative to the chassis along the chassis z axis, compression "
           "positive, from its start (a string potentiometer between body and wheel carrier; body "
           "= the wheel; channel NAME_m)",
           SensorQuantity::Travel},
          {"travel_rate", "the rate of that travel, compression positive (channel NAME_mps)",
           SensorQuantity::TravelRate},
      });
  return r;
}

SensorQuantity parseSensorQuantity(const std::string& text, const std::string& where) {
  return sensorQuantities().at(text, where).value;
}

std::string sensorQuantityName(SensorQuantity q) {
  for (const auto& e : sensorQuantities())
    if (e.value == q) return e.name;
  return "";
}

Motion chassisPointMotion(const Motion& heave, const Motion& pitch, const Motion& roll,
                          const std::array<double, 3>& p) {
  const double x = p[0], y = p[1], z = p[2];
  const double st = std::sin(pitch.q), ct = std::cos(pitch.q), sf = std::sin(roll.q),
               cf = std::cos(roll.q);
  const double w = z * ct - x * st;  // the pitched point's height before the roll
  const double g = y * sf + w * cf;
  const double g_t = (-x * ct - z * st) * cf;
  const double g_f = y * cf - w * sf;
  const double g_tt = -w * cf;
  const double g_ff = -y * sf - w * cf;
  const double g_tf = (x * ct + z * st) * sf;
  Motion m;
  m.q = heave.q + g;
  m.qd = heave.qd + g_t * pitch.qd + g_f * roll.qd;
  m.qdd = heave.qdd + g_t * pitch.qdd + g_f * roll.qdd + g_tt * pitch.qd * pitch.qd +
          2.0 * g_tf * pitch.qd * roll.qd + g_ff * roll.qd * roll.qd;
  return m;
}

Motion chassisAxisHeight(const Motion& world_z, const Motion& heave, const Motion& pitch,
                         const Motion& roll, double x, double y) {
  const double st = std::sin(pitch.q), ct = std::cos(pitch.q), sf = std::sin(roll.q),
               cf = std::cos(roll.q);
  const double num = world_z.q - heave.q - y * sf;  // the height before the roll is undone
  const double A = num / cf;
  const double A_d =
      (world_z.qd - heave.qd - y * cf * roll.qd) / cf + num * sf * roll.qd / (cf * cf);
  Motion m;
  m.q = (A + x * st) / ct;
  m.qd = (A_d + x * ct * pitch.qd) / ct + (A + x * st) * st * pitch.qd / (ct * ct);
  return m;
}

namespace {
/// One step h of the filter x' = A x + B u, y = x_0, augmented with the input u and its slope s
/// (constant over a step): [x; u; s]' = M [x; u; s], the step exp(M h).
Eigen::MatrixXd lowPassStep(const SensorFilter& f, double h) {
  const double wc = 2.0 * kPi * f.cutoff_hz;
  const int n = f.order;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + 2, n + 2);
  if (n == 1) {
    M(0, 0) = -wc;
    M(0, 1) = wc;
  } else {
    M(0, 1) = 1.0;
    M(1, 0) = -wc * wc;
    M(1, 1) = -2.0 * f.damping * wc;
    M(1, 2) = wc * wc;
  }
  M(n, n + 1) = 1.0;
  return (M * h).exp();
}
}  // namespace

std::vector<double> lowPass(const std::vector<double>& u, double rate_hz, const SensorFilter& f) {
  if (f.order == 0 || u.empty()) return u;
  DTWIN_CHECK(f.order <= 2 && rate_hz > 0 && f.cutoff_hz > 0, "lowPass: bad filter or rate");
  const int n = f.order;
  const Eigen::MatrixXd E = lowPassStep(f, 1.0 / rate_hz);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  x(0) = u[0];
  std::vector<double> y(u.size());
  y[0] = u[0];
  for (std::size_t k = 0; k + 1 < u.size(); ++k) {
    const double slope = (u[k + 1] - u[k]) * rate_hz;
    Eigen::VectorXd next =
        E.topLeftCorner(n, n) * x + E.block(0, n, n, 1) * u[k] + E.block(0, n + 1, n, 1) * slope;
    x = next;
    y[k + 1] = x(0);
  }
  return y;
}

double LowPassStream::start(double u) {
  x_[0] = u;
  x_[1] = 0.0;
  u_ = u;
  return u;
}

double LowPassStream::step(double u, double h) {
  if (f_.order == 0) return u_ = u;
  DTWIN_CHECK(f_.order <= 2 && h > 0 && f_.cutoff_hz > 0, "LowPassStream: bad filter or step");
  const int n = f_.order;
  if (h != h_) {  // lowPass's augmented matrix, exponentiated for this spacing
    const Eigen::MatrixXd E = lowPassStep(f_, h);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n + 2; ++j) E_[i][j] = E(i, j);
    h_ = h;
  }
  const double slope = (u - u_) / h;
  double next[2] = {0.0, 0.0};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) next[i] += E_[i][j] * x_[j];
    next[i] += E_[i][n] * u_ + E_[i][n + 1] * slope;
  }
  x_[0] = next[0];
  x_[1] = next[1];
  u_ = u;
  return x_[0];
}

namespace {
ParameterSpec sensorParameter(std::string name, std::string unit, std::string description,
                              double off, double lo, bool lo_inclusive, double prior_lo,
                              double prior_hi) {
  ParameterSpec p{std::move(name), std::move(unit), std::move(description), off, lo};
  p.min_inclusive = lo_inclusive;
  p.prior_lower = prior_lo;
  p.prior_upper = prior_hi;
  return p;
}
}  // namespace

const Registry<ParameterSpec>& sensorModels() {
  static const Registry<ParameterSpec> r(
      "sensor model",
      {
          {"lowpass", "a first-order low-pass filter on the channel",
           sensorParameter(
               "time_constant_s", "s",
               "first-order low-pass time constant 1/(2 pi f_c) (off: 0; 0.05 s is 3.2 Hz)", 0.0,
               0.0, true, 0.0, 0.05)},
          {"lowpass2", "a second-order Butterworth low-pass filter on the channel",
           sensorParameter("time_constant_s", "s",
                           "second-order Butterworth low-pass time constant 1/(2 pi f_c) (off: 0; "
                           "0.05 s is 3.2 Hz)",
                           0.0, 0.0, true, 0.0, 0.05)},
          {"gain", "a gain error of the channel",
           sensorParameter("gain", "1", "gain of the channel (off: 1)", 1.0, 0.0, false, 0.5, 1.5)},
          {"delay", "a time offset of the channel",
           sensorParameter("delay_s", "s",
                           "time offset: the record at t is the signal at t - delay_s (off: 0)",
                           0.0, -std::numeric_limits<double>::infinity(), true, -0.05, 0.05)},
      });
  return r;
}

std::vector<std::string> sensorModelKinds() { return sensorModels().names(); }

ParameterSpec sensorModelParameter(const std::string& kind, const std::string& where) {
  return sensorModels().at(kind, where).value;
}

void SensorDistortion::set(const std::string& kind, double value) {
  if (kind == "gain") {
    gain = value;
  } else if (kind == "delay") {
    delay_s = value;
  } else {
    DTWIN_CHECK(kind == "lowpass" || kind == "lowpass2", "SensorDistortion: unknown kind " + kind);
    filter.order = value > 0 ? (kind == "lowpass" ? 1 : 2) : 0;
    filter.cutoff_hz = value > 0 ? 1.0 / (2.0 * kPi * value) : 0.0;
  }
}

std::vector<double> distortChannel(const std::vector<double>& grid, double rate_hz,
                                   const std::vector<double>& times, const SensorDistortion& d) {
  DTWIN_CHECK(!grid.empty() && rate_hz > 0, "distortChannel: empty grid");
  const std::vector<double> y = lowPass(grid, rate_hz, d.filter);
  const long n = static_cast<long>(y.size());
  auto at = [&](long k) { return y[static_cast<std::size_t>(std::clamp(k, 0L, n - 1))]; };
  std::vector<double> out;
  out.reserve(times.size());
  for (double t : times) {
    double s = std::clamp((t - d.delay_s) * rate_hz, 0.0, static_cast<double>(n - 1));
    if (std::abs(s - std::round(s)) < 1e-9 * std::max(1.0, s))
      s = std::round(s);  // a grid time, up to rounding
    const long k = static_cast<long>(std::floor(s));
    const double u = s - static_cast<double>(k);
    double v;
    if (u == 0.0) {
      v = at(k);
    } else {
      // Lagrange through k−1, k, k+1, k+2 at offset u in [0, 1).
      const double wm = -u * (u - 1) * (u - 2) / 6, w0 = (u + 1) * (u - 1) * (u - 2) / 2,
                   w1 = -(u + 1) * u * (u - 2) / 2, w2 = (u + 1) * u * (u - 1) / 6;
      v = wm * at(k - 1) + w0 * at(k) + w1 * at(k + 1) + w2 * at(k + 2);
    }
    out.push_back(d.gain * v);
  }
  return out;
}

}  // namespace dtwin
