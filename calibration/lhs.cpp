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

}  // namespace dtwin::calib
