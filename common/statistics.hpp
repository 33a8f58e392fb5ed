#pragma once
// The small statistics every layer uses, once: π, the standard normal's CDF and quantile, and the
// type-7 sample quantile (R's default; numpy's "linear").
#include <vector>

namespace dtwin {

/// π (C++17 has no std::numbers).
inline constexpr double kPi = 3.14159265358979323846;

/// Φ(x), the standard normal CDF.
double normalCdf(double x);
/// Φ⁻¹(p) for p in (0, 1) (Wichura's AS 241, relative error about 1e-16); InputError otherwise.
double normalQuantile(double p);
/// The type-7 quantile of `sorted` (ascending, non-empty; p in [0, 1]): linear between the order
/// statistics at (n − 1) p.
double quantileSorted(const std::vector<double>& sorted, double p);

}  // namespace dtwin
