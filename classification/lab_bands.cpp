#include "classification/lab_bands.hpp"

#include <algorithm>
#include <cmath>

namespace dtwin::classify {

std::size_t ChannelBand::at(double t) const {
  const auto it = std::lower_bound(times.begin(), times.end(), t);
  return it != times.end() && *it == t ? static_cast<std::size_t>(it - times.begin())
                                       : times.size();
}

double normalMixtureQuantile(const std::vector<double>& mean, const std::vector<double>& sd,
                             double p) {
  double lo = mean[0] - 10 * sd[0], hi = mean[0] + 10 * sd[0];
  for (std::size_t k = 0; k < mean.size(); ++k) {
    lo = std::min(lo, mean[k] - 10 * sd[k]);
    hi = std::max(hi, mean[k] + 10 * sd[k]);
  }
  for (int it = 0; it < 200 && hi - lo > 1e-12 * (std::abs(lo) + std::abs(hi) + 1e-300); ++it) {
    const double mid = 0.5 * (lo + hi);
    double f = 0.0;
    for (std::size_t k = 0; k < mean.size(); ++k)
      f += 0.5 * std::erfc(-(mid - mean[k]) / (sd[k] * std::sqrt(2.0)));
    (f / static_cast<double>(mean.size()) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace dtwin::classify
