#include "calibration/gibbs.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "calibration/common.hpp"
#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::calib {
namespace {

/// exp(−x) is exactly 0 in double precision for x > 745.14 (below the smallest subnormal).
constexpr double kUnderflow = 746.0;

}  // namespace

double sampleGamma(RandomStream& rng, double shape) {
  DTWIN_CHECK(shape > 0.0 && std::isfinite(shape), "sampleGamma needs a finite shape > 0");
  if (shape < 1.0) {
    const double g = sampleGamma(rng, shape + 1.0);
    double u;
    do u = rng.uniform();
    while (u <= 0.0);
    return g * std::pow(u, 1.0 / shape);
  }
  const double d = shape - 1.0 / 3.0;
  const double c = 1.0 / std::sqrt(9.0 * d);
  for (;;) {
    double x, v;
    do {
      x = rng.normal();
      v = 1.0 + c * x;
    } while (v <= 0.0);
    v = v * v * v;
    const double u = rng.uniform();
    const double x2 = x * x;
    if (u < 1.0 - 0.0331 * x2 * x2) return d * v;
    if (u > 0.0 && std::log(u) < 0.5 * x2 + d * (1.0 - v + std::log(v))) return d * v;
  }
}

void GibbsOptions::validate() const {
  const OptionCheck check("gibbs");
  check.atLeast("iterations", iterations, 1);
  check.atLeast("burn_in", burn_in, 0);
  check.require(burn_in < iterations, "burn_in",
                "must be below iterations (" + std::to_string(iterations) + "), got " +
                    std::to_string(burn_in));
  check.nonNegative("a", a);
  check.nonNegative("b", b);
  if (!std::isnan(initial_tau))
    check.require(initial_tau > 0.0 && std::isfinite(initial_tau), "initial_tau",
                  "must be a finite number > 0 (or NaN for the default n/SSE_min), got " +
                      formatNumber(initial_tau, 17));
}

namespace {

/// The finite design points sorted by SSE (ties by index: deterministic), and what every
/// iteration needs of them.
struct SortedDesign {
  std::vector<int> order;  ///< design index of each finite point, by SSE
  int failed = 0;          ///< points with non-finite SSE (weight 0)
  double sse_min = 0.0;
  std::vector<double> half_delta;  ///< (SSE_m − SSE_min) / 2, sorted order
  std::vector<double> rate;        ///< b + SSE_m / 2: the rate of τ | k
  std::vector<double> omega;       ///< ω_m minus the largest, so <= 0 (empty: no design weights)
  bool weighted = false;           ///< some ω_m differ
};

/// Sorts the finite points; throws InputError (naming `where`) for a negative or −inf SSE, no
/// finite SSE at all, or b = 0 with SSE_min = 0.
SortedDesign sortDesign(const std::vector<double>& sse, const GibbsOptions& options,
                        const std::vector<double>& log_weight, const std::string& where) {
  SortedDesign s;
  s.order.reserve(sse.size());
  for (std::size_t k = 0; k < sse.size(); ++k) {
    if (std::isfinite(sse[k])) {
      if (sse[k] < 0.0)
        throw InputError(where, "SSE of design point " + std::to_string(k) +
                                    " is negative: " + formatNumber(sse[k], 17));
      s.order.push_back(static_cast<int>(k));
    } else if (std::isnan(sse[k]) || sse[k] > 0.0) {
      ++s.failed;
    } else {
      throw InputError(where, "SSE of design point " + std::to_string(k) + " is -inf");
    }
  }
  if (s.order.empty())
    throw InputError(where, "none of the " + std::to_string(sse.size()) +
                                " design points has a finite SSE (all simulations failed?)");
  std::stable_sort(s.order.begin(), s.order.end(), [&](int i, int j) {
    return sse[static_cast<std::size_t>(i)] < sse[static_cast<std::size_t>(j)];
  });
  s.sse_min = sse[static_cast<std::size_t>(s.order.front())];
  if (options.b == 0.0 && s.sse_min == 0.0)
    throw InputError(where,
                     "b = 0 needs SSE_k > 0 at every design point (the conditional rate "
                     "b + SSE_k/2 would be 0), but design point " +
                         std::to_string(s.order.front()) + " has SSE 0");

  const std::size_t m_all = s.order.size();
  s.half_delta.resize(m_all);
  s.rate.resize(m_all);
  for (std::size_t m = 0; m < m_all; ++m) {
    const double v = sse[static_cast<std::size_t>(s.order[m])];
    s.half_delta[m] = 0.5 * (v - s.sse_min);
    s.rate[m] = options.b + 0.5 * v;
  }
  // Design weights relative to the largest, so ω_m <= 0: exp(ω_m − τΔ_m/2) <= exp(−τΔ_m/2).
  if (!log_weight.empty()) {
    double mx = -std::numeric_limits<double>::infinity();
    for (int k : s.order) mx = std::max(mx, log_weight[static_cast<std::size_t>(k)]);
    s.omega.resize(m_all);
    for (std::size_t m = 0; m < m_all; ++m) {
      s.omega[m] = log_weight[static_cast<std::size_t>(s.order[m])] - mx;
      s.weighted = s.weighted || s.omega[m] != 0.0;
    }
  }
  return s;
}

/// One draw of k | τ: the cumulative weights over the sorted points (in `cum`, scratch of one
/// slot per point), cut where exp() underflows to 0, searched for one uniform times their total.
/// Returns the position in s.order.
std::size_t drawPoint(const SortedDesign& s, double tau, RandomStream& rng,
                      std::vector<double>& cum) {
  const std::size_t m_all = s.order.size();
  double total = 0.0;
  std::size_t m = 0;
  if (!s.weighted) {
    for (; m < m_all; ++m) {
      const double x = tau * s.half_delta[m];
      if (x > kUnderflow) break;
      total += std::exp(-x);
      cum[m] = total;
    }
    DTWIN_CHECK(m >= 1 && total >= 1.0, "the best design point must carry weight 1");
  } else {
    // The largest log weight M first (the points are sorted by SSE, so once −τΔ/2 < M − 746 no
    // later point can matter), then the cumulative sums of exp(ω − τΔ/2 − M) over that prefix.
    double top = -std::numeric_limits<double>::infinity();
    std::size_t end = 0;
    for (; end < m_all; ++end) {
      const double x = tau * s.half_delta[end];
      if (-x < top - kUnderflow) break;
      top = std::max(top, s.omega[end] - x);
    }
    for (; m < end; ++m) {
      total += std::exp(s.omega[m] - tau * s.half_delta[m] - top);
      cum[m] = total;
    }
    DTWIN_CHECK(m >= 1 && total >= 1.0, "the heaviest design point must carry weight 1");
  }
  const double target = rng.uniform() * total;
  std::size_t pos = static_cast<std::size_t>(
      std::upper_bound(cum.begin(), cum.begin() + static_cast<std::ptrdiff_t>(m), target) -
      cum.begin());
  if (pos >= m) pos = m - 1;  // rounding guard; target < total in exact arithmetic
  return pos;
}

}  // namespace

GibbsChains runGriddyGibbs(const std::vector<double>& sse, int n_data, const GibbsOptions& options,
                           const std::vector<double>& log_weight) {
  const std::string where = "griddy gibbs";
  options.validate();
  if (n_data < 1)
    throw InputError(where, "number of data points n must be >= 1, got " + std::to_string(n_data));

  if (!log_weight.empty() && log_weight.size() != sse.size())
    throw InputError(where, "log_weight has " + std::to_string(log_weight.size()) + " values for " +
                                std::to_string(sse.size()) + " design points");
  for (std::size_t k = 0; k < log_weight.size(); ++k)
    if (!std::isfinite(log_weight[k]))
      throw InputError(where, "log design weight of point " + std::to_string(k) + " is not finite");
  const SortedDesign sorted = sortDesign(sse, options, log_weight, where);
  std::vector<double> cum(sorted.order.size());

  const double shape = options.a + 0.5 * n_data;
  double tau = options.initial_tau;
  if (std::isnan(tau)) tau = sorted.sse_min > 0.0 ? n_data / sorted.sse_min : shape / options.b;

  GibbsChains out;
  out.design_points = static_cast<int>(sse.size());
  out.failed_points = sorted.failed;
  out.n_data = n_data;
  out.sse_min = sorted.sse_min;
  out.initial_tau = tau;
  out.options = options;
  const auto kept = static_cast<std::size_t>(options.iterations - options.burn_in);
  out.index.reserve(kept);
  out.tau.reserve(kept);

  RandomStream rng(options.seed, kStreamGibbs, options.chain);
  for (int it = 0; it < options.iterations; ++it) {
    const std::size_t pos = drawPoint(sorted, tau, rng, cum);  // k | τ
    tau = sampleGamma(rng, shape) / sorted.rate[pos];          // τ | k
    DTWIN_CHECK(tau > 0.0 && std::isfinite(tau), "tau draw must be finite and > 0");
    if (it >= options.burn_in) {
      out.index.push_back(sorted.order[pos]);
      out.tau.push_back(tau);
    }
  }
  return out;
}

}  // namespace dtwin::calib
