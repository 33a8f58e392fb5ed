#include "subsystems/speed_trace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"

namespace dtwin {
namespace {

/// The Hermite basis on s ∈ [0, 1]: values, derivatives in s, and integrals from 0 to s.
struct Hermite {
  double h00, h10, h01, h11;
};
Hermite basis(double s) {
  const double s2 = s * s, s3 = s2 * s;
  return {2 * s3 - 3 * s2 + 1, s3 - 2 * s2 + s, -2 * s3 + 3 * s2, s3 - s2};
}
Hermite basisDerivative(double s) {
  const double s2 = s * s;
  return {6 * s2 - 6 * s, 3 * s2 - 4 * s + 1, -6 * s2 + 6 * s, 3 * s2 - 2 * s};
}
Hermite basisIntegral(double s) {
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s;
  return {s4 / 2 - s3 + s, s4 / 4 - 2 * s3 / 3 + s2 / 2, -s4 / 2 + s3, s4 / 4 - s3 / 3};
}

/// Fritsch–Butland slopes: zero at a local extremum or a flat side, else the weighted harmonic
/// mean of the neighbouring secants; the ends by the one-sided three-point formula, limited so
/// the end intervals stay monotone (as in Moler, "Numerical Computing with MATLAB", pchip).
std::vector<double> pchipSlopes(const std::vector<double>& t, const std::vector<double>& v) {
  const std::size_t n = t.size();
  std::vector<double> h(n - 1), delta(n - 1), d(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = t[k + 1] - t[k];
    delta[k] = (v[k + 1] - v[k]) / h[k];
  }
  if (n == 2) {
    d[0] = d[1] = delta[0];
    return d;
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (delta[k - 1] * delta[k] <= 0) continue;
    const double w1 = 2 * h[k] + h[k - 1], w2 = h[k] + 2 * h[k - 1];
    d[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k]);
  }
  auto end = [](double h0, double h1, double del0, double del1) {
    double e = ((2 * h0 + h1) * del0 - h0 * del1) / (h0 + h1);
    if (e * del0 <= 0) return 0.0;
    if (del0 * del1 <= 0 && std::abs(e) > std::abs(3 * del0)) e = 3 * del0;
    return e;
  };
  d[0] = end(h[0], h[1], delta[0], delta[1]);
  d[n - 1] = end(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
  return d;
}

}  // namespace

SpeedTrace::SpeedTrace(std::vector<double> t_s, std::vector<double> v_mps, std::string name)
    : t_(std::move(t_s)), v_(std::move(v_mps)), name_(std::move(name)) {
  if (t_.size() != v_.size())
    throw InputError(name_, "has " + std::to_string(t_.size()) + " times but " +
                                std::to_string(v_.size()) + " speeds");
  if (t_.size() < 2)
    throw InputError(name_,
                     "a speed trace needs at least 2 samples, got " + std::to_string(t_.size()));
  for (std::size_t k = 0; k < t_.size(); ++k) {
    const std::string at = "sample " + std::to_string(k) + ": ";
    if (!std::isfinite(t_[k]))
      throw InputError(name_, at + "time must be finite, got " + formatNumber(t_[k]));
    if (!std::isfinite(v_[k]))
      throw InputError(name_, at + "speed must be finite, got " + formatNumber(v_[k]));
    if (v_[k] < 0)
      throw InputError(name_, at + "speed must be >= 0, got " + formatNumber(v_[k], 17));
    if (k > 0 && !(t_[k] > t_[k - 1]))
      throw InputError(name_, at + "time must increase, got " + formatNumber(t_[k], 17) +
                                  " after " + formatNumber(t_[k - 1], 17));
  }
  d_ = pchipSlopes(t_, v_);
  cum_.assign(t_.size(), 0.0);
  for (std::size_t k = 0; k + 1 < t_.size(); ++k) {
    const double h = t_[k + 1] - t_[k];  // the Hermite trapezoid rule: exact for the cubic
    cum_[k + 1] = cum_[k] + h * (v_[k] + v_[k + 1]) / 2 + h * h * (d_[k] - d_[k + 1]) / 12;
  }
  // The interval index at the start of each of t_.size() equal buckets of the span: interval()
  // starts there and walks a step or two instead of a binary search over the whole trace.
  const std::size_t nb = t_.size();
  bucket_scale_ = static_cast<double>(nb) / (t_.back() - t_.front());
  bucket_.resize(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    const double tb = t_.front() + static_cast<double>(b) / bucket_scale_;
    const auto it = std::upper_bound(t_.begin(), t_.end(), tb);
    bucket_[b] = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(it - t_.begin() - 1, 0, static_cast<std::ptrdiff_t>(nb) - 2));
  }
  offset_ = integral(0.0);
}

std::size_t SpeedTrace::interval(double t) const {
  // The largest k <= size - 2 with t_[k] <= t (0 when none): the same k as a binary search.
  const double u = (t - t_.front()) * bucket_scale_;
  const std::size_t last = t_.size() - 2;
  const double nb = static_cast<double>(bucket_.size());
  std::size_t k = u > 0 ? bucket_[u < nb ? static_cast<std::size_t>(u) : bucket_.size() - 1] : 0;
  while (k > 0 && t_[k] > t) --k;
  while (k < last && t_[k + 1] <= t) ++k;
  return k;
}

double SpeedTrace::speed(double t) const {
  if (t <= t_.front()) return v_.front();
  if (t >= t_.back()) return v_.back();
  const std::size_t k = interval(t);
  const double h = t_[k + 1] - t_[k];
  const Hermite b = basis((t - t_[k]) / h);
  return b.h00 * v_[k] + b.h10 * h * d_[k] + b.h01 * v_[k + 1] + b.h11 * h * d_[k + 1];
}

double SpeedTrace::accel(double t) const {
  if (t < t_.front() || t > t_.back()) return 0.0;
  const std::size_t k = interval(t);
  const double h = t_[k + 1] - t_[k];
  const Hermite b = basisDerivative((t - t_[k]) / h);
  return (b.h00 * v_[k] + b.h01 * v_[k + 1]) / h + b.h10 * d_[k] + b.h11 * d_[k + 1];
}

double SpeedTrace::integral(double t) const {
  if (t <= t_.front()) return v_.front() * (t - t_.front());
  if (t >= t_.back()) return cum_.back() + v_.back() * (t - t_.back());
  const std::size_t k = interval(t);
  const double h = t_[k + 1] - t_[k];
  const Hermite b = basisIntegral((t - t_[k]) / h);
  return cum_[k] +
         h * (b.h00 * v_[k] + b.h10 * h * d_[k] + b.h01 * v_[k + 1] + b.h11 * h * d_[k + 1]);
}

double SpeedTrace::distance(double t) const { return integral(t) - offset_; }

double SpeedTrace::timeAtDistance(double x) const {
  if (x <= 0) return 0.0;
  const double target = x + offset_;
  if (target >= cum_.back()) {
    if (v_.back() <= 0)
      return target == cum_.back() ? t_.back() : std::numeric_limits<double>::infinity();
    return t_.back() + (target - cum_.back()) / v_.back();
  }
  // The integral is non-decreasing: the first time it reaches `target`, by bisection on the
  // interval that holds it (the first knot at or above it bounds the search).
  const std::size_t hi =
      static_cast<std::size_t>(std::lower_bound(cum_.begin(), cum_.end(), target) - cum_.begin());
  double a = std::max(0.0, t_[hi == 0 ? 0 : hi - 1]), b = t_[hi];
  if (target <= cum_.front()) {  // before the first sample (the trace starts after time 0)
    a = 0.0;
    b = t_.front();
  }
  for (int i = 0; i < 200 && b - a > 1e-12 * std::max(1.0, std::abs(b)); ++i) {
    const double m = 0.5 * (a + b);
    (integral(m) < target ? a : b) = m;
  }
  return b;
}

}  // namespace dtwin
