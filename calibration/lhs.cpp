#include "calibration/lhs.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "calibration/common.hpp"
#include "common/errors.hpp"

namespace dtwin::calib {

std::uint64_t uniformIndex(RandomStream& rng, std::uint64_t m) {
  DTWIN_CHECK(m >= 1, "uniformIndex needs m >= 1");
  // Accept r only in the largest multiple of m below 2^64; (2^64 − m) mod m == (−m) mod m is the
  // number of rejected values at the bottom of the range.
  const std::uint64_t reject_below = (0 - m) % m;
  for (;;) {
    const std::uint64_t r = rng.bits();
    if (r >= reject_below) return r % m;
  }
}

std::vector<int> randomPermutation(RandomStream& rng, int n) {
  DTWIN_CHECK(n >= 0, "randomPermutation needs n >= 0");
  std::vector<int> p(static_cast<std::size_t>(n));
  std::iota(p.begin(), p.end(), 0);
  for (int i = n - 1; i >= 1; --i) {
    const auto k = static_cast<int>(uniformIndex(rng, static_cast<std::uint64_t>(i) + 1));
    std::swap(p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(k)]);
  }
  return p;
}

Eigen::MatrixXd latinHypercube(int n, const std::vector<double>& lower,
                               const std::vector<double>& upper, std::uint64_t seed) {
  if (n < 1)
    throw InputError("latin hypercube", "number of points must be >= 1, got " + std::to_string(n));
  checkBounds(lower, upper, "latin hypercube", /*allow_degenerate=*/true);
  const int d = static_cast<int>(lower.size());
  Eigen::MatrixXd x(n, d);
  for (int j = 0; j < d; ++j) {
    RandomStream rng(seed, kStreamLhs, static_cast<std::uint64_t>(j));
    const std::vector<int> perm = randomPermutation(rng, n);
    const double lo = lower[static_cast<std::size_t>(j)];
    const double hi = upper[static_cast<std::size_t>(j)];
    const double h = (hi - lo) / n;
    for (int i = 0; i < n; ++i) {
      const double u = rng.uniform();
      // Clamp guards against rounding past the upper bound when perm = n−1 and u -> 1.
      x(i, j) = std::min(hi, lo + (perm[static_cast<std::size_t>(i)] + u) * h);
    }
  }
  return x;
}

double normalQuantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw InputError("normal quantile", "p must lie in (0, 1), got " + std::to_string(p));
  const double q = p - 0.5;
  if (std::abs(q) <= 0.425) {
    const double r = 0.180625 - q * q;
    return q *
           (((((((2509.0809287301226727 * r + 33430.575583588128105) * r + 67265.770927008700853) * r +
                45921.953931549871457) * r + 13731.693765509461125) * r + 1971.5909503065514427) * r +
             133.14166789178437745) * r + 3.387132872796366608) /
           (((((((5226.495278852545925 * r + 28729.085735721942674) * r + 39307.89580009271061) * r +
                21213.794301586595867) * r + 5394.1960214247511077) * r + 687.1870074920579083) * r +
             42.313330701600911252) * r + 1.0);
  }
  double r = q < 0.0 ? p : 1.0 - p;
  r = std::sqrt(-std::log(r));
  double x;
  if (r <= 5.0) {
    r -= 1.6;
    x = (((((((7.7454501427834140764e-4 * r + 0.0227238449892691845833) * r + 0.24178072517745061177) * r +
             1.27045825245236838258) * r + 3.64784832476320460504) * r + 5.7694972214606914055) * r +
          4.6303378461565452959) * r + 1.42343711074968357734) /
        (((((((1.05075007164441684324e-9 * r + 5.475938084995344946e-4) * r + 0.0151986665636164571966) * r +
             0.14810397642748007459) * r + 0.68976733498510000455) * r + 1.6763848301838038494) * r +
          2.05319162663775882187) * r + 1.0);
  } else {
    r -= 5.0;
    x = (((((((2.01033439929228813265e-7 * r + 2.71155556874348757815e-5) * r + 0.0012426609473880784386) * r +
             0.026532189526576123093) * r + 0.29656057182850489123) * r + 1.7848265399172913358) * r +
          5.4637849111641143699) * r + 6.6579046435011037772) /
        (((((((2.04426310338993978564e-15 * r + 1.4215117583164458887e-7) * r + 1.8463183175100546818e-5) * r +
             7.868691311456132591e-4) * r + 0.0148753612908506148525) * r + 0.13692988092273580531) * r +
          0.59983220655588793769) * r + 1.0);
  }
  return q < 0.0 ? -x : x;
}

}  // namespace dtwin::calib
