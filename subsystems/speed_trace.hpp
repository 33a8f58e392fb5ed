#pragma once
// A measured speed trace: the vehicle's speed against time as a logger recorded it, at any sample
// times. Between samples the speed is the monotone piecewise-cubic Hermite interpolant (PCHIP,
// Fritsch & Carlson 1980, with the slopes of Fritsch & Butland 1984): on every interval it lies
// between the two samples, so it never overshoots and never turns negative, and it is C¹ (speed
// and acceleration are continuous). The distance is its exact integral
// (a quartic per interval), so the road under the wheels follows the same speed the forces see.
// Outside the samples the end speeds are held.
#include <string>
#include <vector>

namespace dtwin {

class SpeedTrace {
 public:
  /// `t_s`: sample times in s, finite and strictly increasing; `v_mps`: speeds in m/s, finite and
  /// >= 0, one per time; at least two samples. Throws InputError(`name`, rule) naming the first
  /// offending sample (its index from 0) otherwise.
  SpeedTrace(std::vector<double> t_s, std::vector<double> v_mps, std::string name);

  /// Speed [m/s] at time t [s].
  double speed(double t) const;
  /// Acceleration [m/s²] at time t: the interpolant's derivative (0 outside the samples).
  double accel(double t) const;
  /// Distance [m] travelled from time 0 to time t (negative for t < 0 when moving there).
  double distance(double t) const;
  /// The first time >= 0 at which distance() reaches x (0 for x <= 0); +inf when it never does
  /// (the trace ends at rest short of x).
  double timeAtDistance(double x) const;

  double startTime() const { return t_.front(); }
  double endTime() const { return t_.back(); }
  const std::string& name() const { return name_; }
  const std::vector<double>& times() const { return t_; }
  const std::vector<double>& speeds() const { return v_; }

 private:
  /// The interval k with t_[k] <= t < t_[k+1], for t inside [t_.front(), t_.back()).
  std::size_t interval(double t) const;
  /// ∫ from t_[0] to t of the speed.
  double integral(double t) const;

  std::vector<double> t_, v_, d_;    ///< sample times, speeds, PCHIP slopes dv/dt at the samples
  std::vector<double> cum_;          ///< ∫ from t_[0] to t_[k] of the speed
  double offset_ = 0;                ///< integral(0)
  std::vector<std::size_t> bucket_;  ///< interval() at the start of each equal bucket of the span
  double bucket_scale_ = 0;          ///< buckets per second
  std::string name_;
};

}  // namespace dtwin
