#include "diagnosis/discrepancy.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/validate.hpp"
#include "diagnosis/signal.hpp"

namespace dtwin::diag {
namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

/// A band's figures within which the car reads "as the model".
constexpr double kSameGain = 0.05, kSamePhaseDeg = 3.0;
/// The least share of the model's power in a band for its ratio to be read.
constexpr double kReadShare = 0.01;

/// "0.5–2 Hz"
std::string hz(double lo, double hi) {
  return formatNumber(lo, 3) + "–" + formatNumber(hi, 3) + " Hz";
}

/// The distinct times of `channel`'s records in `data`, ascending, with the mean of `values`
/// (one per record) at each.
void distinctTimes(const LabData& data, const std::string& channel,
                   const std::vector<double>& values, std::vector<double>& t,
                   std::vector<double>& mean) {
  std::map<double, std::pair<double, int>> at;
  for (std::size_t i = 0; i < data.records.size(); ++i)
    if (data.records[i].channel == channel) {
      auto& a = at[data.records[i].time_s];
      a.first += values[i];
      a.second += 1;
    }
  t.clear();
  mean.clear();
  for (const auto& [time, a] : at) {
    t.push_back(time);
    mean.push_back(a.first / a.second);
  }
}

/// The values v at the distinct times t (ascending) as a signal against time: u[0] on a 1 ms grid
/// from 0 to the last time, linear between the times (before the first: its value).
RoadInput modelSignal(const std::vector<double>& t, const std::vector<double>& v) {
  RoadInput m;
  m.dt_s = 0.001;
  if (t.empty()) return m;
  const auto n = static_cast<std::size_t>(std::ceil(t.back() / m.dt_s)) + 1;
  m.u[0].resize(n);
  std::size_t i = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double time = static_cast<double>(k) * m.dt_s;
    while (i + 1 < t.size() && t[i + 1] <= time) ++i;
    if (time <= t[i] || i + 1 == t.size())
      m.u[0][k] = v[i];
    else
      m.u[0][k] = v[i] + (v[i + 1] - v[i]) * (time - t[i]) / (t[i + 1] - t[i]);
  }
  return m;
}

/// The words of one band (b.read set).
std::string bandWords(const DiscrepancyBand& b) {
  const std::string where = b.band + " band, " + hz(b.lo_hz, b.hi_hz);
  if (!b.read)
    return where + ": the model has little there (" + formatFixed(100 * b.model_share, 1) +
           " % of its power); not read";
  if (std::abs(b.gain - 1) < kSameGain && std::abs(b.phase_deg) < kSamePhaseDeg)
    return where + ": the car responds as the model (gain within " +
           formatFixed(100 * kSameGain, 0) + " %, phase within " + formatFixed(kSamePhaseDeg, 0) +
           "°)";
  std::string s = "at " + hz(b.lo_hz, b.hi_hz) + " (" + b.band + ") the car responds ";
  if (std::abs(b.phase_deg) >= kSamePhaseDeg)
    s += formatFixed(std::abs(b.phase_deg), 0) + "° " + (b.phase_deg > 0 ? "earlier" : "later") +
         " than the model (" + formatNumber(std::abs(b.lead_ms), 2) + " ms), with ";
  else
    s += "in phase with the model, with ";
  return s + formatNumber(b.gain, 2) + " times its gain";
}

/// What would respond so, from the band that holds most of the filter's power (the model's share
/// there times the filter's ratio squared).
std::string reading(const std::vector<DiscrepancyBand>& bands) {
  const DiscrepancyBand* most = nullptr;
  double largest = 0;
  for (const auto& b : bands) {
    if (!b.read) continue;
    const std::complex<double> r = std::polar(b.gain, b.phase_deg * kRadPerDeg) - 1.0;
    if (std::abs(r) < kSameGain && std::abs(b.phase_deg) < kSamePhaseDeg) continue;
    if (b.model_share * b.filter_ratio * b.filter_ratio > largest)
      largest = b.model_share * b.filter_ratio * b.filter_ratio, most = &b;
  }
  if (!most) return "the car responds as the model in every band it excites";
  const std::complex<double> r = std::polar(most->gain, most->phase_deg * kRadPerDeg) - 1.0;
  const std::string where = "most of the filter is in the " + most->band + " band: ";
  if (std::abs(r.real()) >= std::abs(r.imag()))
    return where + (r.real() < 0
                        ? "less of the road reaches the channel than the model lets through: "
                          "damping the model lacks, or an "
                          "actuator against the body's motion (a skyhook would)"
                        : "more of the road reaches the channel than the model lets through: a "
                          "stiffer path, or a force that "
                          "adds to the road's push (a feed-forward in phase with the road would)");
  return where + (r.imag() > 0 ? "earlier than the model: a force ahead of the model's, in phase "
                                 "with the road's velocity (a "
                                 "feed-forward or a skyhook would)"
                               : "later than the model: a lag the model lacks (a compliance, a "
                                 "controller's or a sensor's delay would)");
}

/// The car over the model per bin and per band on one drive: ŷ the physics and d the filter's
/// output at the distinct times t.
void addResponse(DiscrepancyFilter& f, const std::vector<double>& t,
                 const std::vector<double>& physics, const std::vector<double>& d) {
  if (t.size() < 64) {
    f.response_note =
        "no response: fewer than 64 times of " + f.channel + " on the calibration drive";
    return;
  }
  const UniformGrid g = uniformGrid(t);
  if (g.size() < 64 || !g.steady) {
    f.response_note =
        "no response: the calibration drive's times hold no steady stretch of 64 times";
    return;
  }
  const double fs = 1.0 / g.dt;
  const std::vector<double> y = onGrid(g, physics), dd = onGrid(g, d);
  int segment = 32;  // the largest power of two within half the grid and 5 s
  while (2 * static_cast<std::size_t>(segment) <= g.size() / 2 && 2 * segment <= 5.0 * fs)
    segment *= 2;
  const CrossSpectra cs = welchCrossSpectra(y, dd, fs, segment);
  f.response_note = "on the calibration drive, " + formatNumber(t[g.begin], 6) + "–" +
                    formatNumber(t[g.end - 1], 6) + " s (" + std::to_string(g.size()) +
                    " times at " + formatNumber(fs, 4) + " Hz" +
                    (g.resampled ? ", resampled" : "") + "), Welch segments of " +
                    formatNumber(segment / fs, 3) + " s";
  double total = 0, peak = 0;
  for (std::size_t k = 1; k < cs.freq_hz.size(); ++k)
    total += cs.pxx[k], peak = std::max(peak, cs.pxx[k]);
  for (std::size_t k = 1; k < cs.freq_hz.size(); ++k) {
    if (!(cs.pxx[k] > 1e-3 * peak))
      continue;  // where the model has little power the ratio is noise
    const std::complex<double> r = 1.0 + cs.pxy[k] / cs.pxx[k];
    f.freq_hz.push_back(cs.freq_hz[k]);
    f.gain.push_back(std::abs(r));
    f.phase_deg.push_back(std::arg(r) / kRadPerDeg);
  }
  for (const Band& band : vehicleBands(fs)) {
    DiscrepancyBand b;
    b.band = band.name;
    b.lo_hz = band.lo_hz;
    b.hi_hz = band.hi_hz;
    double pyy = 0, pdd = 0;
    std::complex<double> pyd = 0;
    for (std::size_t k = 1; k < cs.freq_hz.size(); ++k)
      if (cs.freq_hz[k] >= band.lo_hz && (cs.freq_hz[k] < band.hi_hz || k + 1 == cs.freq_hz.size()))
        pyy += cs.pxx[k], pdd += cs.pyy[k], pyd += cs.pxy[k];
    if (!(pyy > 0)) continue;
    const std::complex<double> r = 1.0 + pyd / pyy;
    b.gain = std::abs(r);
    b.phase_deg = std::arg(r) / kRadPerDeg;
    b.lead_ms = 1000.0 * b.phase_deg / (360.0 * std::sqrt(band.lo_hz * band.hi_hz));
    b.model_share = total > 0 ? pyy / total : 0.0;
    b.filter_ratio = std::sqrt(pdd / pyy);
    b.read = b.model_share >= kReadShare;
    b.words = bandWords(b);
    f.bands.push_back(b);
  }
}

std::string inputName(FirInput in) { return in == FirInput::Height ? "height" : "velocity"; }

}  // namespace

void DiscrepancyOptions::validate() const {
  const OptionCheck check("discrepancy");
  check.positive("dt_s", dt_s);
  check.require(!taps.empty(), "taps", "must list at least one order");
  check.require(!model_taps.empty(), "model_taps", "must list at least one order (0: none)");
  for (const int n : model_taps)
    check.require(n >= 0 && n <= 500, "model_taps",
                  "must each lie in [0, 500], got " + std::to_string(n));
  for (const int n : taps)
    check.require(n >= 1 && n <= 500, "taps",
                  "must each lie in [1, 500], got " + std::to_string(n));
}

DiscrepancyFilter fitDiscrepancy(const std::string& channel,
                                 const std::vector<DiscrepancyDrive>& calibration,
                                 const DiscrepancyOptions& options) {
  options.validate();
  DTWIN_CHECK(!calibration.empty(), "fitDiscrepancy: no calibration drive");
  DiscrepancyFilter f;
  f.channel = channel;
  // The residual of every record of the channel, with its road.
  std::vector<LabData> residual(calibration.size());
  std::vector<const LabData*> data;
  std::vector<const RoadInput*> roads, models;
  std::vector<RoadInput> model(calibration.size());
  std::vector<double> t, physics;
  for (std::size_t s = 0; s < calibration.size(); ++s) {
    const DiscrepancyDrive& d = calibration[s];
    DTWIN_CHECK(d.data && d.physics && d.road && d.physics->size() == d.data->records.size(),
                "fitDiscrepancy: a drive's predictions");
    for (std::size_t i = 0; i < d.data->records.size(); ++i)
      if (d.data->records[i].channel == channel) {
        LabRecord r = d.data->records[i];
        r.value -= (*d.physics)[i];
        residual[s].records.push_back(r);
      }
    data.push_back(&residual[s]);
    roads.push_back(d.road);
    distinctTimes(*d.data, channel, *d.physics, t, physics);
    model[s] = modelSignal(t, physics);
    models.push_back(&model[s]);
  }
  std::size_t records = 0;
  for (const auto& r : residual) records += r.records.size();
  if (records == 0)
    throw InputError("discrepancy " + channel,
                     "the calibration drive holds no records of " + channel);
  FirSearch search;
  search.taps = options.taps;
  search.model_taps = options.model_taps;
  search.allow_none = true;
  f.fir = fitFir(channel, data, roads, options.dt_s, search, models);
  f.candidates = static_cast<int>(f.fir.cv_sse.size());
  if (!f.fir.cv_sse.empty()) {
    f.cv_sse_none = f.fir.cv_sse.front();
    f.cv_sse_chosen = *std::min_element(f.fir.cv_sse.begin(), f.fir.cv_sse.end());
  }
  if (f.fir.none()) {
    f.response_note =
        "no filter: the car responds as the model, as far as the calibration drive tells";
    f.summary =
        "no filter: on the calibration drive no linear filter of the road predicted the residual "
        "better than nothing (two-fold "
        "cross-validation); the physics alone is the prediction";
    return f;
  }
  // The response on the drive with the most times of the channel.
  std::size_t best = 0, most = 0;
  for (std::size_t s = 0; s < calibration.size(); ++s) {
    distinctTimes(*calibration[s].data, channel, *calibration[s].physics, t, physics);
    if (t.size() > most) most = t.size(), best = s;
  }
  distinctTimes(*calibration[best].data, channel, *calibration[best].physics, t, physics);
  std::vector<double> d(t.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    d[i] = f.fir.predict(*calibration[best].road, t[i], &model[best]);
  addResponse(f, t, physics, d);
  std::string words;
  for (const auto& b : f.bands)
    if (b.read && !(std::abs(b.gain - 1) < kSameGain && std::abs(b.phase_deg) < kSamePhaseDeg))
      words += (words.empty() ? "" : "; ") + b.words;
  if (f.bands.empty())
    f.summary =
        "the filter is fitted, but its response against the model's could not be estimated (" +
        f.response_note + ")";
  else
    f.summary =
        (words.empty() ? std::string("the car responds as the model in every band read") : words) +
        ": " + reading(f.bands);
  return f;
}

std::string DiscrepancyFilter::describe() const {
  if (fir.none()) return fir.describe();
  const bool front = fir.corners.size() <= 2 && std::all_of(fir.corners.begin(), fir.corners.end(),
                                                            [](int c) { return c < 2; });
  const std::string wheels =
      front ? (fir.corners.size() == 1 ? "the front wheels (one signal)" : "the 2 front wheels")
            : (fir.corners.size() == 4
                   ? "the 4 wheels"
                   : std::to_string(fir.corners.size()) + " distinct wheel signals");
  std::string s =
      "FIR from the road's " +
      std::string(fir.input == FirInput::Height ? "height" : "vertical velocity") + " under " +
      wheels +
      (fir.model_taps ? " and from the model's own prediction (" + std::to_string(fir.model_taps) +
                            (fir.model_taps == 1 ? " tap)" : " taps)")
                      : std::string()) +
      " to the residual, " + std::to_string(fir.taps) + " taps each at " + formatNumber(fir.dt_s) +
      " s (memory " + formatNumber(fir.taps * fir.dt_s, 3) + " s), ridge " +
      formatNumber(fir.ridge) + ", least squares on " + std::to_string(fir.training_records) +
      " records";
  if (candidates > 1)
    s += " (chosen among " + std::to_string(candidates) +
         " forms and no filter by two-fold cross-validation: residual sum of squares " +
         formatNumber(cv_sse_chosen, 4) + " against " + formatNumber(cv_sse_none, 4) +
         " without a filter)";
  return s;
}

nlohmann::json DiscrepancyFilter::toJson() const {
  nlohmann::json j{{"description", describe()},
                   {"none", fir.none()},
                   {"training_records", fir.training_records},
                   {"forms_scored", candidates},
                   {"cv_sse_none", jsonNumber(cv_sse_none)},
                   {"cv_sse_chosen", jsonNumber(cv_sse_chosen)},
                   {"summary", summary},
                   {"response_note", response_note}};
  if (!fir.none()) {
    j["input"] = inputName(fir.input);
    j["wheels"] = fir.corners;
    j["taps"] = fir.taps;
    j["model_taps"] = fir.model_taps;
    j["dt_s"] = fir.dt_s;
    j["ridge"] = fir.ridge;
    j["coefficients"] = fir.coef;
  }
  j["bands"] = nlohmann::json::array();
  for (const auto& b : bands)
    j["bands"].push_back({{"band", b.band},
                          {"lo_hz", b.lo_hz},
                          {"hi_hz", b.hi_hz},
                          {"gain", b.gain},
                          {"phase_deg", b.phase_deg},
                          {"lead_ms", b.lead_ms},
                          {"model_share", b.model_share},
                          {"filter_ratio", b.filter_ratio},
                          {"read", b.read},
                          {"words", b.words}});
  j["response"] = {{"freq_hz", freq_hz}, {"gain", gain}, {"phase_deg", phase_deg}};
  return j;
}

SeriesDiscrepancy scoreDiscrepancy(const DiscrepancyFilter& filter, const std::vector<double>& t,
                                   const std::vector<double>& physics, const LabData& data,
                                   const RoadInput& road) {
  DTWIN_CHECK(t.size() == physics.size(),
              "scoreDiscrepancy: times and predictions differ in number");
  SeriesDiscrepancy out;
  out.filter = filter;
  const RoadInput model = modelSignal(t, physics);
  std::vector<double> d(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) d[i] = filter.fir.predict(road, t[i], &model);
  out.hybrid.resize(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) out.hybrid[i] = physics[i] + d[i];
  double ss_h = 0, ss_p = 0, sum = 0, sq = 0, n = 0;
  for (const auto& r : data.records) {
    if (r.channel != filter.channel) continue;
    const auto it = std::lower_bound(t.begin(), t.end(), r.time_s);
    if (it == t.end() || *it != r.time_s) continue;  // not a time of the series
    const std::size_t i = static_cast<std::size_t>(it - t.begin());
    ss_h += (r.value - out.hybrid[i]) * (r.value - out.hybrid[i]);
    ss_p += (r.value - physics[i]) * (r.value - physics[i]);
    sum += r.value;
    sq += r.value * r.value;
    n += 1;
  }
  if (n > 0) {
    out.hybrid_fit_percent = fitPercent(ss_h, n, sum, sq);
    out.physics_fit_percent = fitPercent(ss_p, n, sum, sq);
  }
  if (!t.empty()) {
    const auto sdOf = [](const std::vector<double>& v) {
      double m = 0, s = 0;
      for (double x : v) m += x;
      m /= static_cast<double>(v.size());
      for (double x : v) s += (x - m) * (x - m);
      return std::sqrt(s / static_cast<double>(v.size()));
    };
    const double h = sdOf(out.hybrid);
    out.share = h > 0 ? sdOf(d) / h : std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

nlohmann::json SeriesDiscrepancy::toJson(double baseline_fit_percent, bool with_series_data) const {
  nlohmann::json j = filter.toJson();
  j["physics_fit_percent"] = jsonNumber(physics_fit_percent);
  j["hybrid_fit_percent"] = jsonNumber(hybrid_fit_percent);
  j["baseline_fit_percent"] = jsonNumber(baseline_fit_percent);
  j["share"] = jsonNumber(share);
  if (with_series_data) j["hybrid_predicted"] = hybrid;
  return j;
}

}  // namespace dtwin::diag
