#include "diagnosis/frequency_response.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/format.hpp"
#include "common/json.hpp"

namespace dtwin::diag {
namespace {

constexpr double kHalfTurn =
    3.14159265358979323846;  // π (names distinct from signal.cpp's: unity builds)
constexpr double kDegPerRad = 180.0 / kHalfTurn;

[[noreturn]] void refuse(const std::string& where, const std::string& rule) {
  throw std::invalid_argument(where + ": " + rule);
}

/// arg z in degrees, in (−180°, 180°].
double phaseDegrees(std::complex<double> z) {
  const double p = std::arg(z) * kDegPerRad;
  return p <= -180.0 ? p + 360.0 : p;
}

/// The bins of a band, with signal.hpp's rule: lo <= f < hi, the last bin included when hi reaches
/// it.
bool binInBand(const std::vector<double>& f, std::size_t k, double lo, double hi) {
  return f[k] >= lo && (f[k] < hi || (k + 1 == f.size() && hi >= f[k]));
}

double bandMeanOf(const std::vector<double>& f, const std::vector<double>& v, double lo,
                  double hi) {
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < f.size(); ++k)
    if (binInBand(f, k, lo, hi)) sum += v[k], ++n;
  return n ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

/// v to 6 significant digits (compare.json's arrays: the estimates' own error is far larger).
double rounded6(double v) {
  double r = v;
  return std::isfinite(v) && v != 0 && parseNumber(formatNumber(v, 6), r) ? r : v;
}

nlohmann::json rounded6Array(const std::vector<double>& v) {
  std::vector<double> r(v.size());
  std::transform(v.begin(), v.end(), r.begin(), rounded6);
  return jsonNumbers(r);
}

nlohmann::json responseJson(const FrequencyResponse& r) {
  return {{"magnitude", rounded6Array(r.magnitude)},
          {"phase_deg", rounded6Array(r.phase_deg)},
          {"coherence", rounded6Array(r.coherence)},
          {"magnitude_error", rounded6Array(r.magnitude_error)},
          {"phase_sd_deg", rounded6Array(r.phase_sd_deg)}};
}

}  // namespace

FrequencyResponse frequencyResponse(const std::vector<double>& u, const std::vector<double>& y,
                                    double fs_hz, int segment) {
  const CrossSpectra c = welchCrossSpectra(u, y, fs_hz, segment);
  FrequencyResponse r;
  r.freq_hz = c.freq_hz;
  r.segment = c.segment;
  r.segments = c.segments;
  r.averages = c.averages;
  const std::size_t m = c.freq_hz.size();
  r.h.resize(m);
  r.magnitude.resize(m);
  r.phase_deg.resize(m);
  r.coherence.resize(m);
  r.magnitude_error.resize(m);
  r.phase_sd_deg.resize(m);
  const double two_nd = 2.0 * c.averages, max_phase_sd = kHalfTurn / std::sqrt(3.0);
  for (std::size_t k = 0; k < m; ++k) {
    r.h[k] = c.pxx[k] > 0 ? c.pxy[k] / c.pxx[k] : std::complex<double>(0.0, 0.0);
    const double d = c.pxx[k] * c.pyy[k];
    const double g2 = d > 0 ? std::min(1.0, std::norm(c.pxy[k]) / d) : 0.0;
    r.magnitude[k] = std::abs(r.h[k]);
    r.phase_deg[k] = phaseDegrees(r.h[k]);
    r.coherence[k] = g2;
    const double eps =
        g2 > 0 ? std::sqrt((1.0 - g2) / (g2 * two_nd)) : std::numeric_limits<double>::infinity();
    r.magnitude_error[k] = eps;
    r.phase_sd_deg[k] = std::min(eps, max_phase_sd) * kDegPerRad;
  }
  return r;
}

ResponseComparison compareResponses(const std::vector<double>& u,
                                    const std::vector<double>& measured,
                                    const std::vector<double>& predicted, double fs_hz, int segment,
                                    double level) {
  const char* where = "compareResponses";
  if (measured.size() != u.size() || predicted.size() != u.size())
    refuse(where, "the input, measured and predicted values must have the same length, got " +
                      std::to_string(u.size()) + ", " + std::to_string(measured.size()) + " and " +
                      std::to_string(predicted.size()));
  if (!(level > 0 && level < 1))
    refuse(where, "level must be in (0, 1), got " + formatNumber(level));
  ResponseComparison out;
  out.level = level;
  out.measured = frequencyResponse(u, measured, fs_hz, segment);
  out.predicted = frequencyResponse(u, predicted, fs_hz, segment);
  std::vector<double> residual(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) residual[i] = measured[i] - predicted[i];
  const CrossSpectra r = welchCrossSpectra(u, residual, fs_hz, segment);
  const double nd = r.averages;
  out.coherence_threshold = nd > 1 ? 1.0 - std::pow(1.0 - level, 1.0 / (nd - 1.0)) : 1.0;
  const std::size_t m = r.freq_hz.size();
  out.residual_coherence.assign(m, 0.0);
  out.differs.assign(m, false);
  std::vector<double> s(m,
                        std::numeric_limits<double>::infinity());  // sd of each part of ln(Ĥ_m/Ĥ_p)
  for (std::size_t k = 0; k < m; ++k) {
    const double d = r.pxx[k] * r.pyy[k];
    const double g2 = d > 0 ? std::min(1.0, std::norm(r.pxy[k]) / d) : 0.0;
    out.residual_coherence[k] = g2;
    out.differs[k] = k > 0 && g2 > out.coherence_threshold;
    const double hp = out.predicted.magnitude[k];
    if (r.pxx[k] > 0 && hp > 0 && nd > 1)
      s[k] = std::sqrt(r.pyy[k] * (1.0 - g2) / (2.0 * (nd - 1.0) * r.pxx[k])) / hp;
  }
  const double chi2_level = -2.0 * std::log(1.0 - level);  // χ²₂ quantile
  const auto& f = r.freq_hz;
  for (const Band& b : vehicleBands(fs_hz)) {
    ResponseBand rb;
    rb.band = b.name, rb.lo_hz = b.lo_hz, rb.hi_hz = b.hi_hz;
    double wsum = 0, gain = 0;
    std::complex<double> phasor(0.0, 0.0);
    for (std::size_t k = 1; k < m; ++k) {
      if (!binInBand(f, k, b.lo_hz, b.hi_hz) || !(out.measured.magnitude[k] > 0) ||
          !std::isfinite(s[k]))
        continue;
      const std::complex<double> ratio = out.measured.h[k] / out.predicted.h[k];
      const double w = 1.0 / std::max(s[k] * s[k], 1e-300);
      wsum += w;
      gain += w * std::log(std::abs(ratio));
      phasor += w * ratio / std::abs(ratio);
      ++rb.bins;
    }
    if (rb.bins == 0) continue;  // a band narrower than a bin, or no response in it
    const double lg = gain / wsum, ph = std::arg(phasor),
                 sd = std::sqrt(std::min(rb.bins, 2) / wsum);
    rb.gain_ratio = std::exp(lg);
    rb.gain_ratio_error = sd;
    rb.phase_difference_deg = phaseDegrees(phasor);
    rb.phase_difference_sd_deg = std::min(sd, kHalfTurn / std::sqrt(3.0)) * kDegPerRad;
    rb.coherence_measured = bandMeanOf(f, out.measured.coherence, b.lo_hz, b.hi_hz);
    rb.coherence_predicted = bandMeanOf(f, out.predicted.coherence, b.lo_hz, b.hi_hz);
    rb.chi2 = sd > 0 ? (lg * lg + ph * ph) / (sd * sd)
                     : (lg != 0 || ph != 0 ? std::numeric_limits<double>::infinity() : 0.0);
    rb.differs = rb.chi2 > chi2_level;
    out.bands.push_back(rb);
  }
  return out;
}

SeriesResponse seriesResponse(const std::vector<double>& t, const std::vector<double>& road,
                              const std::string& input, const std::vector<double>& measured,
                              const std::vector<double>& predicted) {
  const char* where = "seriesResponse";
  const std::size_t n = t.size();
  if (measured.size() != n || predicted.size() != n || (!road.empty() && road.size() != n))
    refuse(where, "the times, road, measured and predicted values must have the same length, got " +
                      std::to_string(n) + ", " + std::to_string(road.size()) + ", " +
                      std::to_string(measured.size()) + " and " + std::to_string(predicted.size()));
  SeriesResponse sr;
  sr.input = road.empty() ? "" : input;
  if (road.empty()) {
    sr.note = "no frequency response: no road input";
    return sr;
  }
  if (n < 64) {
    sr.note = "no frequency response: fewer than 64 times";
    return sr;
  }
  const UniformGrid g = uniformGrid(t);
  if (g.size() < 64) {
    sr.note = "no frequency response: " + std::to_string(g.gaps) +
              (g.gaps == 1 ? " gap" : " gaps") +
              " in the times, and no stretch between gaps holds 64 times";
    return sr;
  }
  if (!g.steady) {
    sr.note = "no frequency response: the sampling rate changes from " +
              formatNumber(g.rate_lo_hz, 4) + " to " + formatNumber(g.rate_hi_hz, 4) + " Hz";
    return sr;
  }
  const std::vector<double> u = onGrid(g, road);
  const auto [lo, hi] = std::minmax_element(u.begin(), u.end());
  if (!(*hi > *lo)) {
    sr.note = "no frequency response: the road input does not vary";
    return sr;
  }
  std::vector<std::string> parts;
  if (g.gaps)
    parts.push_back("the response of the longest stretch between gaps, " +
                    formatNumber(t[g.begin], 6) + "–" + formatNumber(t[g.end - 1], 6) + " s (" +
                    std::to_string(g.size()) + " of " + std::to_string(n) + " times)");
  if (g.resampled)
    parts.push_back("resampled to a uniform " + formatFixed(1.0 / g.dt, 1) +
                    " Hz grid by linear interpolation (input and outputs alike: the "
                    "interpolation's loss cancels in the ratio)");
  for (std::size_t k = 0; k < parts.size(); ++k) sr.note += (k ? "; " : "") + parts[k];
  sr.fs_hz = 1.0 / g.dt;
  sr.response = compareResponses(u, onGrid(g, measured), onGrid(g, predicted), sr.fs_hz,
                                 welchSegmentFor(g.size()));
  sr.computed = true;
  return sr;
}

nlohmann::json SeriesResponse::toJson(bool with_bins) const {
  nlohmann::json j{{"input", input}};
  if (!note.empty()) j["note"] = note;
  if (!computed) return j;
  const ResponseComparison& r = response;
  j["fs_hz"] = fs_hz;
  j["segment"] = r.measured.segment;
  j["segments"] = r.measured.segments;
  j["averages"] = r.measured.averages;
  j["level"] = r.level;
  j["coherence_threshold"] = r.coherence_threshold;
  if (with_bins) {
    j["f_hz"] = rounded6Array(r.measured.freq_hz);
    j["measured"] = responseJson(r.measured);
    j["predicted"] = responseJson(r.predicted);
    j["residual_coherence"] = rounded6Array(r.residual_coherence);
    j["differs"] = r.differs;
  }
  j["bands"] = nlohmann::json::array();
  for (const auto& b : r.bands)
    j["bands"].push_back({{"band", b.band},
                          {"lo_hz", b.lo_hz},
                          {"hi_hz", b.hi_hz},
                          {"bins", b.bins},
                          {"gain_ratio", b.gain_ratio},
                          {"gain_ratio_error", b.gain_ratio_error},
                          {"phase_difference_deg", b.phase_difference_deg},
                          {"phase_difference_sd_deg", b.phase_difference_sd_deg},
                          {"coherence_measured", b.coherence_measured},
                          {"coherence_predicted", b.coherence_predicted},
                          {"chi2", jsonNumber(b.chi2)},
                          {"differs", b.differs}});
  return j;
}

}  // namespace dtwin::diag
