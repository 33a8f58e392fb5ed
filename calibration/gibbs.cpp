#include "calibration/gibbs.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "calibration/common.hpp"
#include "common/errors.hpp"

namespace dtwin::calib {
namespace {

std::string fmt(double v) { return formatNumber(v, 17); }

/// exp(−x) is exactly 0 in double precision for x > 745.14 (below the smallest subnormal).
constexpr double kUnderflow = 746.0;

}  // namespace

double sampleGamma(RandomStream& rng, double shape) {
  DTWIN_CHECK(shape > 0.0 && std::isfinite(shape), "sampleGamma needs a finite shape > 0");
  if (shape < 1.0) {
    const double g = sampleGamma(rng, shape + 1.0);
    double u;
    do u = rng.uniform(); while (u <= 0.0);
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
  const std::string where = "gibbs options";
  if (iterations < 1)
    throw InputError(where, "iterations must be >= 1, got " + std::to_string(iterations));
  if (burn_in < 0 || burn_in >= iterations)
    throw InputError(where, "burn_in must be in [0, iterations = " + std::to_string(iterations) +
                                "), got " + std::to_string(burn_in));
  if (!(a >= 0.0 && std::isfinite(a))) throw InputError(where, "a must be >= 0, got " + fmt(a));
  if (!(b >= 0.0 && std::isfinite(b))) throw InputError(where, "b must be >= 0, got " + fmt(b));
  if (!std::isnan(initial_tau) && !(initial_tau > 0.0 && std::isfinite(initial_tau)))
    throw InputError(where, "initial_tau must be finite and > 0 (or NaN for the default n/SSE_min), "
                            "got " + fmt(initial_tau));
}

GibbsChains runGriddyGibbs(const std::vector<double>& sse, int n_data,
                           const GibbsOptions& options, const std::vector<double>& log_weight) {
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
  // Finite points, sorted by SSE (ties by index: deterministic).
  std::vector<int> order;
  order.reserve(sse.size());
  int failed = 0;
  for (std::size_t k = 0; k < sse.size(); ++k) {
    if (std::isfinite(sse[k])) {
      if (sse[k] < 0.0)
        throw InputError(where, "SSE of design point " + std::to_string(k) +
                                    " is negative: " + fmt(sse[k]));
      order.push_back(static_cast<int>(k));
    } else if (std::isnan(sse[k]) || sse[k] > 0.0) {
      ++failed;
    } else {
      throw InputError(where, "SSE of design point " + std::to_string(k) + " is -inf");
    }
  }
  if (order.empty())
    throw InputError(where, "none of the " + std::to_string(sse.size()) +
                                " design points has a finite SSE (all simulations failed?)");
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
    return sse[static_cast<std::size_t>(i)] < sse[static_cast<std::size_t>(j)];
  });
  const double sse_min = sse[static_cast<std::size_t>(order.front())];
  if (options.b == 0.0 && sse_min == 0.0)
    throw InputError(where, "b = 0 needs SSE_k > 0 at every design point (the conditional rate "
                            "b + SSE_k/2 would be 0), but design point " +
                                std::to_string(order.front()) + " has SSE 0");

  const std::size_t m_all = order.size();
  std::vector<double> half_delta(m_all), rate(m_all), omega;
  for (std::size_t m = 0; m < m_all; ++m) {
    const double s = sse[static_cast<std::size_t>(order[m])];
    half_delta[m] = 0.5 * (s - sse_min);
    rate[m] = options.b + 0.5 * s;
  }
  // Design weights relative to the largest, so ω_m <= 0: exp(ω_m − τΔ_m/2) <= exp(−τΔ_m/2).
  bool weighted = false;
  if (!log_weight.empty()) {
    double mx = -std::numeric_limits<double>::infinity();
    for (int k : order) mx = std::max(mx, log_weight[static_cast<std::size_t>(k)]);
    omega.resize(m_all);
    for (std::size_t m = 0; m < m_all; ++m) {
      omega[m] = log_weight[static_cast<std::size_t>(order[m])] - mx;
      weighted = weighted || omega[m] != 0.0;
    }
  }
  std::vector<double> cum(m_all);

  const double shape = options.a + 0.5 * n_data;
  double tau = options.initial_tau;
  if (std::isnan(tau)) tau = sse_min > 0.0 ? n_data / sse_min : shape / options.b;

  GibbsChains out;
  out.design_points = static_cast<int>(sse.size());
  out.failed_points = failed;
  out.n_data = n_data;
  out.sse_min = sse_min;
  out.initial_tau = tau;
  out.options = options;
  const auto kept = static_cast<std::size_t>(options.iterations - options.burn_in);
  out.index.reserve(kept);
  out.tau.reserve(kept);

  RandomStream rng(options.seed, kStreamGibbs, options.chain);
  for (int it = 0; it < options.iterations; ++it) {
    // k | τ: cumulative weights over the sorted points, cut where exp() underflows to 0.
    double total = 0.0;
    std::size_t m = 0;
    if (!weighted) {
      for (; m < m_all; ++m) {
        const double x = tau * half_delta[m];
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
        const double x = tau * half_delta[end];
        if (-x < top - kUnderflow) break;
        top = std::max(top, omega[end] - x);
      }
      for (; m < end; ++m) {
        total += std::exp(omega[m] - tau * half_delta[m] - top);
        cum[m] = total;
      }
      DTWIN_CHECK(m >= 1 && total >= 1.0, "the heaviest design point must carry weight 1");
    }
    const double target = rng.uniform() * total;
    std::size_t pos = static_cast<std::size_t>(
        std::upper_bound(cum.begin(), cum.begin() + static_cast<std::ptrdiff_t>(m), target) -
        cum.begin());
    if (pos >= m) pos = m - 1;  // rounding guard; target < total in exact arithmetic

    // τ | k.
    tau = sampleGamma(rng, shape) / rate[pos];
    DTWIN_CHECK(tau > 0.0 && std::isfinite(tau), "tau draw must be finite and > 0");

    if (it >= options.burn_in) {
      out.index.push_back(order[pos]);
      out.tau.push_back(tau);
    }
  }
  return out;
}

}  // namespace dtwin::calib
