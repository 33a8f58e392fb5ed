#include "calibration/summary.hpp"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <sstream>

#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::calib {

void SummaryOptions::validate() const {
  const OptionCheck check("summary");
  check.require(dominance_threshold > 0.0 && dominance_threshold <= 1.0, "dominance_threshold",
                "must lie in (0, 1], got " + formatNumber(dominance_threshold));
}

double effectiveSampleSize(const std::vector<double>& x) {
  DTWIN_CHECK(!x.empty(), "ESS of an empty chain");
  const std::size_t S = x.size();
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(S);
  double var0 = 0.0;
  for (double v : x) var0 += (v - mean) * (v - mean);
  if (!(var0 > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (S < 4) return static_cast<double>(S);

  // Autocovariance by FFT with zero padding to >= 2S (no circular wrap-around).
  std::size_t nfft = 1;
  while (nfft < 2 * S) nfft <<= 1;
  std::vector<std::complex<double>> buf(nfft, {0.0, 0.0}), spec(nfft);
  for (std::size_t t = 0; t < S; ++t) buf[t] = {x[t] - mean, 0.0};
  Eigen::FFT<double> fft;
  fft.fwd(spec, buf);
  for (auto& c : spec) c = {std::norm(c), 0.0};
  fft.inv(buf, spec);
  const double c0 = buf[0].real();
  DTWIN_CHECK(c0 > 0.0, "lag-0 autocovariance must be positive");
  auto rho = [&](std::size_t t) { return t < S ? buf[t].real() / c0 : 0.0; };

  // Geyer's initial positive + monotone sequence.
  double sum = 0.0;
  double prev = std::numeric_limits<double>::infinity();
  for (std::size_t m = 0; 2 * m + 1 < S; ++m) {
    double p = rho(2 * m) + rho(2 * m + 1);
    if (!(p > 0.0)) break;
    p = std::min(p, prev);
    sum += p;
    prev = p;
  }
  const double tau_int = std::max(-1.0 + 2.0 * sum, 1.0 / static_cast<double>(S));
  return static_cast<double>(S) / tau_int;
}

DrawSummary summariseDraws(const std::vector<double>& x, const std::string& name) {
  DTWIN_CHECK(!x.empty(), "summary of an empty chain");
  DrawSummary s;
  s.name = name;
  const double S = static_cast<double>(x.size());
  for (double v : x) s.mean += v;
  s.mean /= S;
  double ss = 0.0;
  for (double v : x) ss += (v - s.mean) * (v - s.mean);
  s.sd = x.size() > 1 ? std::sqrt(ss / (S - 1.0)) : 0.0;
  std::vector<double> sorted = x;
  std::sort(sorted.begin(), sorted.end());
  s.q025 = quantileSorted(sorted, 0.025);
  s.q975 = quantileSorted(sorted, 0.975);
  s.ess = effectiveSampleSize(x);
  return s;
}

PosteriorSummary summarisePosterior(const Eigen::MatrixXd& design, const GibbsChains& chains,
                                    const std::vector<std::string>& names,
                                    const SummaryOptions& options) {
  const std::string where = "posterior summary";
  options.validate();
  if (chains.index.empty()) throw InputError(where, "the chain is empty (no draws after burn-in)");
  if (chains.index.size() != chains.tau.size())
    throw InputError(
        where, "index and tau chains differ in length: " + std::to_string(chains.index.size()) +
                   " vs " + std::to_string(chains.tau.size()));
  if (design.rows() != chains.design_points)
    throw InputError(where, "the design has " + std::to_string(design.rows()) +
                                " rows but the chains were run on " +
                                std::to_string(chains.design_points) + " design points");
  const auto d = static_cast<std::size_t>(design.cols());
  if (!names.empty() && names.size() != d)
    throw InputError(where, std::to_string(names.size()) + " parameter names for " +
                                std::to_string(d) + " design columns");

  PosteriorSummary out;
  const std::size_t S = chains.index.size();
  out.draws = static_cast<int>(S);
  std::vector<double> x(S);
  for (std::size_t j = 0; j < d; ++j) {
    for (std::size_t t = 0; t < S; ++t) {
      const int k = chains.index[t];
      DTWIN_CHECK(k >= 0 && k < design.rows(), "chain index outside the design");
      x[t] = design(k, static_cast<Eigen::Index>(j));
    }
    out.parameters.push_back(
        summariseDraws(x, names.empty() ? "theta_" + std::to_string(j + 1) : names[j]));
  }
  out.tau = summariseDraws(chains.tau, "tau");

  std::vector<int> visits(static_cast<std::size_t>(design.rows()), 0);
  for (int k : chains.index) ++visits[static_cast<std::size_t>(k)];
  int top_count = 0;
  for (std::size_t k = 0; k < visits.size(); ++k) {
    if (visits[k] > 0) ++out.distinct_points;
    if (visits[k] > top_count) {
      top_count = visits[k];
      out.top_point = static_cast<int>(k);
    }
  }
  out.top_share = static_cast<double>(top_count) / static_cast<double>(S);
  if (out.top_share > options.dominance_threshold) {
    out.design_too_coarse = true;
    std::ostringstream os;
    os.precision(3);
    os << "design too coarse for the data: design point " << out.top_point << " carries "
       << 100.0 * out.top_share << " % of the " << S << " draws (" << out.distinct_points
       << " distinct points visited); the posterior is essentially a single point, so its "
          "spread is not resolved. Use more design points (lhs_points, [calibration] round_points, "
          "max_rounds) or the adaptive design.";
    out.message = os.str();
  }
  return out;
}

namespace {
void line(std::ostringstream& os, const DrawSummary& s) {
  os << "  " << s.name << ": mean " << s.mean << ", sd " << s.sd << ", 95 % [" << s.q025 << ", "
     << s.q975 << "], ESS " << s.ess << "\n";
}
}  // namespace

std::string PosteriorSummary::briefReport() const {
  std::ostringstream os;
  os.precision(4);
  os << draws << " draws, " << distinct_points << " distinct design points, top share "
     << 100.0 * top_share << " %";
  if (design_too_coarse) os << " -- " << message;
  return os.str();
}

std::string PosteriorSummary::fullReport() const {
  std::ostringstream os;
  os.precision(6);
  for (const auto& p : parameters) line(os, p);
  line(os, tau);
  os << briefReport() << "\n";
  return os.str();
}

}  // namespace dtwin::calib
