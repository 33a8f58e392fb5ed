#pragma once
// Sensors where they are mounted (docs/measurements.md, "Sensors"): the vertical motion of a point
// on the chassis or of a wheel centre, as displacement, velocity or acceleration, or a wheel's
// travel relative to the chassis (a string potentiometer), optionally low-pass filtered as the
// logger did. Pure signal physics: the kinematics of a point on a body
// that heaves, pitches and rolls, and the filters, exact for the sampled input.
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/registry.hpp"
#include "common/statistics.hpp"
#include "subsystems/parameter.hpp"

namespace dtwin {

/// What a sensor measures: the vertical (world z, up positive) motion of its point, or a wheel's
/// travel relative to the chassis along the chassis z axis (compression positive) and its rate.
enum class SensorQuantity { DisplacementZ, VelocityZ, AccelerationZ, Travel, TravelRate };

/// The logger's low-pass filter. order 0: none; 1: H(s) = 1 / (1 + s/ωc); 2: H(s) = ωc² / (s² +
/// 2ζωc s + ωc²) (ζ = 1/√2: Butterworth). ωc = 2π cutoff_hz.
struct SensorFilter {
  int order = 0;
  double cutoff_hz = 0.0;
  double damping = 0.70710678118654752;  ///< ζ of the second-order filter
  nlohmann::json toJson() const;
};

struct SensorSpec {
  std::string name;  ///< the study's [sensors.NAME]
  std::string mount =
      "chassis";  ///< "chassis" or a wheel centre: "wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr"
  std::array<double, 3> position_m{
      0, 0, 0};  ///< chassis: from the centre of mass in chassis axes (x forward, y left, z up)
  SensorQuantity quantity = SensorQuantity::AccelerationZ;
  SensorFilter filter;
  /// Standard deviation of the sensor's noise in its unit (0: unknown). Weighs the channel when
  /// the data have a single repetition (docs/diagnosis.md, "Noise").
  double noise_sd = 0.0;
  /// A chassis sensor's position measured, with this standard deviation [m] per coordinate
  /// (`position_sd_m` in the study); negative: not declared measured, so `twin diagnose` weighs
  /// where the sensor acts as candidates (docs/diagnosis.md, "Where a sensor sits").
  double position_sd_m = -1.0;
  bool positionMeasured() const { return position_sd_m >= 0.0; }

  /// A relative sensor: travel or its rate (between the chassis and the wheel of `mount`).
  bool relative() const {
    return quantity == SensorQuantity::Travel || quantity == SensorQuantity::TravelRate;
  }
  /// The output channel: NAME plus the unit suffix (_m, _mps, _mps2), e.g. "seat_mps2".
  std::string channel() const;
  /// "m", "m/s" or "m/s^2".
  std::string unit() const;
  /// The wheel's corner (0 fl, 1 fr, 2 rl, 3 rr), or -1 on the chassis.
  int corner() const;
  /// InputError(where + ".<field>", rule) for a bad name, mount, position (a wheel sensor sits at
  /// the wheel centre: position must be 0), a travel sensor not on a wheel, filter (order 0-2; 0 <
  /// cutoff_hz <= 1e4; 0 < ζ <= 10) noise_sd (finite, >= 0) or position_sd_m (finite, >= 0 when
  /// declared; a chassis sensor's only).
  void validate(const std::string& where) const;
  nlohmann::json toJson() const;
};

/// The quantities a [sensors] table may measure, by their study-file names.
const Registry<SensorQuantity>& sensorQuantities();
/// "displacement_z" | "velocity_z" | "acceleration_z" | "travel" | "travel_rate"; InputError(where,
/// rule) for any other.
SensorQuantity parseSensorQuantity(const std::string& text, const std::string& where);
std::string sensorQuantityName(SensorQuantity q);

/// One coordinate with its first two time derivatives.
struct Motion {
  double q = 0.0, qd = 0.0, qdd = 0.0;
};

/// The world-vertical motion of the chassis point p (chassis axes, from the centre of mass) when
/// the centre of mass is at height `heave` and the chassis is rolled by `roll` about x, then
/// pitched by `pitch` about the rolled y axis (R = Rx(roll) Ry(pitch): pitch positive nose down,
/// roll positive right side down). Exact, not small-angle: z = heave + y sin φ + (z_p cos θ −
/// x sin θ) cos φ, and its first and second derivatives by the chain rule.
Motion chassisPointMotion(const Motion& heave, const Motion& pitch, const Motion& roll,
                          const std::array<double, 3>& p);

/// The height in chassis axes (z up, from the centre of mass) of a point whose chassis-axis x and y
/// are fixed (a MacPherson wheel centre slides along the chassis z axis; a solid axle's wheel
/// centre stays at its x and, to second order in the axle's roll, its y), from its world height
/// `world_z`: the inverse of chassisPointMotion in z,
///   z = ((z_w − h − y sin φ) / cos φ + x sin θ) / cos θ,
/// with its first derivative by the chain rule (qdd is not computed: 0). A travel sensor reads
/// z − z(0) of the wheel centre: the wheel moving up toward the body is compression, positive.
Motion chassisAxisHeight(const Motion& world_z, const Motion& heave, const Motion& pitch,
                         const Motion& roll, double x, double y);

/// `u` sampled at `rate_hz` filtered by `f`, starting at rest at u[0] (y(0) = u[0], y'(0) = 0).
/// Exact for an input that is linear between samples: each step is the matrix exponential of the
/// filter augmented with the input and its slope. For a sampled sinusoid of angular frequency ω
/// the error is at most max|H| (ω/rate_hz)²/8 (the linear reading's). Order 0 returns u.
std::vector<double> lowPass(const std::vector<double>& u, double rate_hz, const SensorFilter& f);

/// lowPass one sample at a time, at any spacing (a co-simulation's outputs, one per communication
/// point): the same exact discretisation (the input linear between samples), so at the output
/// grid's spacing it gives lowPass's numbers.
class LowPassStream {
 public:
  explicit LowPassStream(const SensorFilter& f) : f_(f) {}
  /// The first sample: the filter at rest at `u`; returns it.
  double start(double u);
  /// The next sample `u`, `h` [s] after the last; returns the filter's output there.
  double step(double u, double h);

 private:
  SensorFilter f_;
  double x_[2] = {0.0, 0.0};  ///< the filter's state
  double u_ = 0.0;            ///< the last input
  double h_ = -1.0;           ///< the spacing E_ was made for
  double E_[2][4] = {};       ///< exp(M h)'s first rows (lowPass's M)
};

/// How a logger may have distorted a channel (twin diagnose's sensor candidates,
/// docs/diagnosis.md):
///   lowpass   a first-order low-pass,           parameter time_constant_s τ = 1/ωc (off: 0)
///   lowpass2  a second-order Butterworth,       parameter time_constant_s τ = 1/ωc (off: 0)
///   gain      a gain error y = g u,             parameter gain g (off: 1)
///   delay     a time offset y(t) = u(t − d),    parameter delay_s d (off: 0; > 0 the record lags)
/// The registry's value is the model's one parameter.
const Registry<ParameterSpec>& sensorModels();
/// sensorModels()'s names.
std::vector<std::string> sensorModelKinds();

/// The parameter of a sensor model `kind` (name, unit, off value, prior range); InputError(where,
/// rule) for an unknown kind.
ParameterSpec sensorModelParameter(const std::string& kind, const std::string& where);

/// What every sensor model of one channel does together: y(t) = gain · (H u)(t − delay_s).
struct SensorDistortion {
  double gain = 1.0, delay_s = 0.0;
  SensorFilter filter;  ///< order 0: none
  /// Sets the parameter of one model `kind` to `value` (time constant, gain or delay).
  void set(const std::string& kind, double value);
  bool identity() const { return gain == 1.0 && delay_s == 0.0 && filter.order == 0; }
};

/// `grid` (a channel sampled at `rate_hz` from t = 0, starting at rest) distorted by `d`, read at
/// `times`: filtered exactly (lowPass), then read at t − delay_s by the four-point Lagrange cubic
/// of the grid (exact at a grid time; clamped to the grid's ends), then scaled.
std::vector<double> distortChannel(const std::vector<double>& grid, double rate_hz,
                                   const std::vector<double>& times, const SensorDistortion& d);

}  // namespace dtwin
