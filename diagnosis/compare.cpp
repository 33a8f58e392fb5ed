#include "diagnosis/compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/parallel.hpp"
#include "common/validate.hpp"

namespace dtwin::diag {
namespace {

/// The normal deviate of F = (X/d1) against F(d1, d2) (Paulson 1942; d2 = inf: Wilson–Hilferty
/// for χ²_d1/d1). Accurate to ~1e-3 in p for d1, d2 >= 10.
double fDeviate(double f, double d1, double d2) {
  const double a1 = 2.0 / (9.0 * d1), a2 = std::isfinite(d2) ? 2.0 / (9.0 * d2) : 0.0;
  const double c = std::cbrt(f);
  return ((1.0 - a2) * c - (1.0 - a1)) / std::sqrt(a2 * c * c + a1);
}

/// "fl", "fr", "rl", "rr" from a channel name, or "" (chassis channels).
std::string cornerOf(const std::string& channel) {
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    const std::string tag = std::string("_") + c + "_";
    if (channel.find(tag) != std::string::npos) return c;
  }
  return "";
}

std::string unitOf(const std::string& channel) {
  const auto u = channel.rfind('_');
  return u == std::string::npos ? "" : channel.substr(u + 1);
}

}  // namespace

std::string describeScenarioWindow(const ScenarioSpec& sc, const VehicleData& v, double t0,
                                   double t1) {
  std::vector<std::string> parts = sc.road->describeWindow(sc, v, t0, t1);
  if (sc.speed.trace) {  // a measured speed: the mean acceleration over the window, if it is marked
    const double a =
        t1 > t0 ? (sc.speed.speed(t1) - sc.speed.speed(t0)) / (t1 - t0) : sc.speed.accel(t0);
    if (a > 0.5) parts.push_back("accelerating");
    if (a < -0.5) parts.push_back("braking");
    if (sc.speed.speed(t0) < 0.1 && sc.speed.speed(t1) < 0.1) parts.push_back("at rest");
  } else if (sc.speed.ramp_s > 0 && t0 < sc.speed.ramp_s) {
    parts.push_back("accelerating");
  }
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? "; " : "") + parts[i];
  return s;
}

std::vector<std::vector<double>> posteriorRows(const std::vector<std::string>& sample_names,
                                               const std::vector<std::vector<double>>& rows,
                                               const std::vector<std::string>& names, int count,
                                               const std::string& where) {
  std::vector<int> col;
  for (const auto& n : names) {
    const auto it = std::find(sample_names.begin(), sample_names.end(), n);
    if (it == sample_names.end())
      throw InputError(where, "has no column '" + n + "' (the calibrated parameters differ)");
    col.push_back(static_cast<int>(it - sample_names.begin()));
  }
  if (rows.empty()) throw InputError(where, "holds no posterior rows");
  if (count < 1) throw InputError("draws", "must be >= 1");
  const std::size_t m = std::min<std::size_t>(static_cast<std::size_t>(count), rows.size());
  std::vector<std::vector<double>> out;
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t i = m == 1 ? rows.size() / 2 : k * (rows.size() - 1) / (m - 1);
    std::vector<double> th;
    th.reserve(col.size());
    for (int c : col) th.push_back(rows[i][static_cast<std::size_t>(c)]);
    out.push_back(th);
  }
  return out;
}

void CompareOptions::validate() const {
  const OptionCheck check("compare");
  check.atLeast("threads", threads, 0);
  check.nonNegative("window_threshold", window_threshold);
  check.nonNegative("window_merge_s", window_merge_s);
  check.nonNegative("window_min_s", window_min_s);
  check.atLeast("window_max_merged", window_max_merged, 1);
  check.atLeast("window_max_listed", window_max_listed, 1);
  check.require(window_listed_share > 0.0 && window_listed_share <= 1.0, "window_listed_share",
                "must lie in (0, 1], got " + formatNumber(window_listed_share));
  check.atLeast("state_bins", state_bins, 1);
  check.atLeast("fitted_parameters", fitted_parameters, 0);
}

namespace {

/// The residual of one channel pooled over every data set, with the model's states at the same
/// times (the force-state maps).
struct Pooled {
  std::map<std::string, std::vector<double>> state;
  std::vector<double> residual;
};

/// What every series of one comparison shares.
struct SeriesContext {
  const calib::LabObjective& objective;
  const std::vector<const std::vector<double>*>&
      ok;  ///< the predictions of the draws that simulated
  const std::map<std::string, ChannelNoise>& noise;
  const CompareOptions& options;
  const VehicleData& vehicle;
};

/// Where a record reads a run: the run of its data set and the record's index in the objective.
struct At {
  const calib::LabObjective& objective;
  const RunResult& run;
  std::size_t record;
  /// The column `name` at the record's time (on the grid or at the run's extra output time).
  double column(const std::string& name) const {
    const int c = run.trace.index(name);
    DTWIN_CHECK(c >= 0, "no channel " + name);
    return objective.read(run, record, static_cast<std::size_t>(c));
  }
};

/// Adds the residual of channel `ch` at a record's time (`at`: where it reads the run) and the
/// model's states there (the channel's corner, "fl" for chassis channels) to `pl`.
void poolStates(Pooled& pl, const std::string& ch, const At& at, double residual) {
  pl.residual.push_back(residual);
  std::string c = cornerOf(ch);
  if (c.empty()) c = "fl";
  const bool front = c[0] == 'f';
  pl.state["susp_defl_" + c + "_m"].push_back(at.column("susp_defl_" + c + "_m"));
  pl.state["susp_rate_" + c + "_mps"].push_back(at.column("susp_rate_" + c + "_mps"));
  pl.state["tire_defl_" + c + "_m"].push_back(at.column("tire_defl_" + c + "_m"));
  pl.state["speed_mps"].push_back(at.column("speed_mps"));
  const std::string l = front ? "fl" : "rl", r = front ? "fr" : "rr";
  pl.state[std::string("roll_defl_") + (front ? "front" : "rear") + "_m"].push_back(
      at.column("susp_defl_" + l + "_m") - at.column("susp_defl_" + r + "_m"));
}

/// One (data set, channel): the predictive mean and band at every measured time, the error
/// figures, the windows of large residual (fitted series) and the bands; the residual is pooled
/// into `pl` for the force-state maps. `offset`: the data set's first record in the objective.
SeriesComparison compareSeries(const SeriesContext& cx, const calib::DataSet& ds,
                               const std::string& ch, std::size_t offset, const RunResult& run,
                               const ScenarioSpec& scenario, Pooled& pl) {
  const auto& measured = cx.objective.measured();
  SeriesComparison sc;
  sc.data_set = ds.name;
  sc.scenario = ds.scenario;
  sc.channel = ch;
  sc.unit = unitOf(ch);
  const auto nit = cx.noise.find(ch);
  if (nit != cx.noise.end()) {
    sc.fitted = true;
    sc.noise_variance = nit->second.variance;
    sc.noise_source = nit->second.source;
    sc.noise_dof = nit->second.dof;
  } else {
    sc.noise_source = "none (not fitted)";
  }
  std::map<double, std::vector<std::size_t>> by_time;
  for (std::size_t k = 0; k < ds.data.records.size(); ++k)
    if (ds.data.records[k].channel == ch) by_time[ds.data.records[k].time_s].push_back(offset + k);
  double ss = 0, ss_sys = 0, ss_noise = 0, ymin = std::numeric_limits<double>::infinity(),
         ymax = -ymin;
  double y_sum = 0, y_sq = 0;  // the measured values' sum and sum of squares (the fit percentage)
  long n_rec = 0, covered = 0;
  std::vector<At> samples;  // where each measured time reads the run
  for (const auto& [t, idx] : by_time) {
    double ym = 0.0;
    for (auto i : idx) ym += measured[i];
    ym /= static_cast<double>(idx.size());
    double pm = 0.0, pv = 0.0;
    for (const auto* p : cx.ok) pm += (*p)[idx[0]];
    pm /= static_cast<double>(cx.ok.size());
    for (const auto* p : cx.ok) pv += ((*p)[idx[0]] - pm) * ((*p)[idx[0]] - pm);
    pv = cx.ok.size() > 1 ? pv / static_cast<double>(cx.ok.size() - 1) : 0.0;
    const double half = 1.959964 * std::sqrt(pv + sc.noise_variance);
    sc.t.push_back(t);
    sc.repetitions.push_back(static_cast<int>(idx.size()));
    sc.measured_mean.push_back(ym);
    sc.predicted_mean.push_back(pm);
    sc.band_lo.push_back(pm - half);
    sc.band_hi.push_back(pm + half);
    const double zden = std::sqrt(sc.noise_variance / static_cast<double>(idx.size()) + pv);
    sc.z.push_back(zden > 0 ? (ym - pm) / zden : std::numeric_limits<double>::quiet_NaN());
    for (auto i : idx) {
      const double e = measured[i] - pm;
      ss += e * e;
      y_sum += measured[i];
      y_sq += measured[i] * measured[i];
      ++n_rec;
      if (std::abs(e) > sc.max_abs) {
        sc.max_abs = std::abs(e);
        sc.max_at_s = t;
      }
      if (std::abs(e) <= half) ++covered;
    }
    ss_sys += (ym - pm) * (ym - pm);
    ss_noise += sc.noise_variance / static_cast<double>(idx.size());
    ymin = std::min(ymin, ym);
    ymax = std::max(ymax, ym);
    if (sc.fitted)
      sc.lack_of_fit += static_cast<double>(idx.size()) * (ym - pm) * (ym - pm) / sc.noise_variance;
    samples.push_back(At{cx.objective, run, idx[0]});
    poolStates(pl, ch, samples.back(), ym - pm);
  }
  const double nt = static_cast<double>(sc.t.size());
  sc.rms = std::sqrt(ss / static_cast<double>(n_rec));
  sc.nrmse = ymax > ymin ? sc.rms / (ymax - ymin) : 0.0;
  sc.fit_percent = fitPercent(ss, static_cast<double>(n_rec), y_sum, y_sq);
  sc.coverage = static_cast<double>(covered) / static_cast<double>(n_rec);
  sc.systematic_rms = std::sqrt(std::max(0.0, (ss_sys - ss_noise) / nt));
  // In time: windows of large standardised residual, ranked, the listed ones labelled.
  if (sc.fitted)
    addWindows(sc, cx.options, [&](const Window& w) {
      return LabelledWindow{w, describeScenarioWindow(scenario, cx.vehicle, w.t_begin, w.t_end),
                            scenario.speed.speed(0.5 * (w.t_begin + w.t_end))};
    });
  // In frequency, with the road under the channel's wheel as the coherence input.
  std::vector<double> road;
  std::string c = cornerOf(ch);
  if (c.empty()) c = "fl";
  if (samples.size() >= 64) {
    road.reserve(samples.size());
    for (const auto& at : samples) road.push_back(at.column("road_" + c + "_m"));
  }
  addResidualBands(sc, road);
  sc.frequency_response =
      seriesResponse(sc.t, road, "road_" + c + "_m", sc.measured_mean, sc.predicted_mean);
  return sc;
}

/// The force-state maps of one channel: its pooled residual binned against each state, with the
/// signature fits (rate-like states: fitRateSignatures, else fitDeflectionSignatures), best first.
ChannelMaps stateMaps(const std::string& ch, const Pooled& pl, int state_bins) {
  ChannelMaps cm;
  cm.channel = ch;
  for (const auto& [name, values] : pl.state) {
    StateMap m;
    m.state = name;
    m.bins = binByState(values, pl.residual,
                        std::min<int>(state_bins, static_cast<int>(values.size() / 2)));
    const bool rate_like = name.find("_rate_") != std::string::npos;
    m.fits = rate_like ? fitRateSignatures(values, pl.residual)
                       : fitDeflectionSignatures(values, pl.residual);
    std::sort(m.fits.begin(), m.fits.end(), [](const SignatureFit& a, const SignatureFit& b) {
      return a.explained_fraction > b.explained_fraction;
    });
    cm.maps.push_back(std::move(m));
  }
  return cm;
}

/// The lack-of-fit test over the fitted series of `out` (see Comparison) and the systematic RMS.
void lackOfFit(Comparison& out, int fitted_parameters) {
  long fitted_points = 0;
  for (const auto& x : out.series)
    if (x.fitted) {
      out.lack_of_fit += x.lack_of_fit;
      fitted_points += static_cast<long>(x.t.size());
    }
  out.lack_of_fit_dof = std::max<long>(1, fitted_points - fitted_parameters);
  const double k = static_cast<double>(out.lack_of_fit_dof);
  // σ_c² estimated from the repetitions with dof_c: X/k is F-like. Its denominator's effective
  // dof: 1/d2 = Σ_c (k_c/K)² / dof_c (study [noise] variances are known: no contribution).
  double inv_d2 = 0.0;
  for (const auto& x : out.series)
    if (x.fitted && x.noise_dof > 0) {
      const double share =
          static_cast<double>(x.t.size()) / static_cast<double>(std::max<long>(1, fitted_points));
      inv_d2 += share * share / static_cast<double>(x.noise_dof);
    }
  out.noise_dof_effective = inv_d2 > 0 ? 1.0 / inv_d2 : std::numeric_limits<double>::infinity();
  out.lack_of_fit_z = fDeviate(out.lack_of_fit / k, k, out.noise_dof_effective);
  out.lack_of_fit_p = 1.0 - normalCdf(out.lack_of_fit_z);
  out.systematic_rms_sd =
      fitted_points > 0
          ? std::sqrt(std::max(0.0, out.lack_of_fit - k) / static_cast<double>(fitted_points))
          : 0.0;
}

}  // namespace

std::string windowsNote(const WindowSummary& s) {
  if (s.found == 0) return "";
  const auto pct = [](double x) {
    return 100.0 * x >= 9.5 ? formatPrintf("%.0f", 100.0 * x) : formatNumber(100.0 * x, 2);
  };
  std::string out = std::to_string(s.found) + (s.found == 1 ? " window" : " windows") + " over " +
                    pct(s.time_share) + " % of the record";
  if (100.0 * s.time_share >= 49.5)
    out += ": the model misses throughout, not in a few places";  // "over 50 %" and more
  if (s.merged < s.found)
    out += "; merged to " + std::to_string(s.merged) + " (neighbours closer than " +
           formatNumber(s.merge_gap_s, 3) + " s),";
  else
    out += ";";
  if (s.listed < s.merged)
    out += " the " + std::to_string(s.listed) + " largest, listed, hold " + pct(s.listed_share) +
           " % of the residual";
  else
    out += std::string(s.listed == 1 ? " it holds " : " together they hold ") +
           pct(s.listed_share) + " % of the residual";
  return out;
}

void addWindows(SeriesComparison& sc, const CompareOptions& o,
                const std::function<LabelledWindow(const Window&)>& describe) {
  o.validate();
  WindowRankOptions ro;
  ro.max_merged = static_cast<std::size_t>(o.window_max_merged);
  ro.max_listed = static_cast<std::size_t>(o.window_max_listed);
  ro.listed_share = o.window_listed_share;
  WindowRanking r =
      rankWindows(sc.t, sc.z, o.window_threshold, o.window_merge_s, o.window_min_s, ro);
  sc.windows.clear();
  for (std::size_t k = 0; k < r.summary.listed; ++k) sc.windows.push_back(describe(r.ranked[k]));
  sc.all_windows = std::move(r.found);
  sc.window_summary = r.summary;
  sc.windows_note = windowsNote(r.summary);
}

void addResidualBands(SeriesComparison& sc, const std::vector<double>& road) {
  sc.bands.clear();
  sc.bands_note.clear();
  const std::size_t n = sc.t.size();
  if (n < 64) {
    sc.bands_note = "no spectrum: fewer than 64 times";
    return;
  }
  DTWIN_CHECK(
      sc.measured_mean.size() == n && sc.predicted_mean.size() == n && sc.repetitions.size() == n,
      "a series' values and times differ in number");
  DTWIN_CHECK(road.empty() || road.size() == n, "the road input and the times differ in number");
  const UniformGrid g = uniformGrid(sc.t);
  const std::string gaps = std::to_string(g.gaps) + (g.gaps == 1 ? " gap" : " gaps") +
                           " in the times (steps longer than " + formatNumber(g.gap_step_s, 3) +
                           " s)";
  if (g.size() < 64) {
    sc.bands_note = "no spectrum: " + gaps + ", and no stretch between gaps holds 64 times";
    return;
  }
  const std::string stretch = "the longest stretch between gaps, " +
                              formatNumber(sc.t[g.begin], 6) + "–" +
                              formatNumber(sc.t[g.end - 1], 6) + " s (" + std::to_string(g.size()) +
                              " of " + std::to_string(n) + " times)";
  if (!g.steady) {
    sc.bands_note = "no spectrum: the sampling rate changes within " +
                    (g.gaps ? stretch : std::string("the record")) + ", from " +
                    formatNumber(g.rate_lo_hz, 4) + " to " + formatNumber(g.rate_hi_hz, 4) + " Hz";
    return;
  }
  std::vector<std::string> parts;
  if (g.gaps) parts.push_back("the spectrum of " + stretch);
  if (g.resampled)
    parts.push_back("resampled to a uniform " + formatFixed(1.0 / g.dt, 1) +
                    " Hz grid by linear interpolation: the clock jitters by up to " +
                    formatNumber(100.0 * g.jitter, 3) +
                    " % of a step (the noise floor follows the interpolation)");
  for (std::size_t k = 0; k < parts.size(); ++k) sc.bands_note += (k ? "; " : "") + parts[k];
  if (!sc.fitted) {
    sc.bands_note = "no spectrum: no noise estimate for this channel";
    return;
  }
  std::vector<double> res(n);
  for (std::size_t i = 0; i < n; ++i) res[i] = sc.measured_mean[i] - sc.predicted_mean[i];
  double rbar = 0.0;
  for (std::size_t i = g.begin; i < g.end; ++i) rbar += sc.repetitions[i];
  rbar /= static_cast<double>(g.size());
  const std::vector<double> r = onGrid(g, res);
  std::vector<double> u;
  if (!road.empty()) u = onGrid(g, road);
  sc.bands = bandAnalysis(r, 1.0 / g.dt, sc.noise_variance / rbar, road.empty() ? nullptr : &u,
                          welchSegmentFor(r.size()), 0.01, gridNoiseAutocorrelation(g));
}

Comparison compareModel(const calib::LabObjective& objective,
                        const std::vector<calib::DataSet>& sets,
                        const std::vector<std::vector<double>>& draws,
                        const std::map<std::string, ChannelNoise>& noise,
                        const CompareOptions& options) {
  options.validate();
  if (draws.empty()) throw InputError("compare", "needs at least one posterior draw");
  Comparison out;
  out.draws = static_cast<long>(draws.size());
  std::vector<std::vector<double>> preds(draws.size());
  parallelFor(draws.size(), options.threads,
              [&](std::size_t i, int) { preds[i] = objective.predict(draws[i]); });
  std::vector<const std::vector<double>*> ok;
  for (const auto& p : preds)
    if (p.empty())
      ++out.failures;
    else
      ok.push_back(&p);
  if (ok.empty())
    throw std::runtime_error("compare: every simulation of the posterior draws failed");
  if (out.failures > 0)
    out.notes.push_back(std::to_string(out.failures) + " of " + std::to_string(draws.size()) +
                        " posterior draws failed to simulate and were left out");
  // The central run (states for the maps, road input for coherence): the draws' mean.
  std::vector<double> centre(draws[0].size(), 0.0);
  for (const auto& d : draws)
    for (std::size_t k = 0; k < d.size(); ++k)
      centre[k] += d[k] / static_cast<double>(draws.size());
  std::vector<RunResult> runs = objective.runs(centre);
  if (runs.empty()) runs = objective.runs(draws[0]);
  if (runs.empty()) throw std::runtime_error("compare: the run at the posterior mean failed");
  const auto scenarios = objective.scenarios();
  const SeriesContext cx{objective, ok, noise, options, objective.model().vehicle()};

  std::map<std::string, Pooled> pooled;
  std::vector<std::string> channel_order;
  std::size_t offset = 0;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    for (const auto& ch : sets[s].data.channels()) {
      out.series.push_back(
          compareSeries(cx, sets[s], ch, offset, runs[s], scenarios[s], pooled[ch]));
      if (std::find(channel_order.begin(), channel_order.end(), ch) == channel_order.end())
        channel_order.push_back(ch);
    }
    offset += sets[s].data.records.size();
  }
  // In state: pooled force-state maps per channel.
  for (const auto& ch : channel_order)
    if (pooled[ch].residual.size() >= 8)
      out.maps.push_back(stateMaps(ch, pooled[ch], options.state_bins));
  lackOfFit(out, options.fitted_parameters);
  return out;
}

nlohmann::json Comparison::toJson(bool with_series_data) const {
  nlohmann::json j;
  j["draws"] = draws;
  j["failures"] = failures;
  j["lack_of_fit"] = {{"chi2", lack_of_fit},
                      {"dof", lack_of_fit_dof},
                      {"z", lack_of_fit_z},
                      {"p_value", lack_of_fit_p},
                      {"noise_dof_effective", std::isfinite(noise_dof_effective)
                                                  ? nlohmann::json(noise_dof_effective)
                                                  : nlohmann::json("inf")},
                      {"test",
                       "F = X / (points - parameters), X = sum over times of R_t (mean_t - "
                       "prediction_t)^2 / sigma_c^2, against "
                       "F(points - parameters, noise dof) (Paulson's normal approximation; chi2 "
                       "when sigma is known)"}};
  j["systematic_rms_noise_sd"] = systematic_rms_sd;
  j["notes"] = notes;
  j["series"] = nlohmann::json::array();
  for (const auto& s : series) {
    nlohmann::json e{{"data_set", s.data_set},
                     {"scenario", s.scenario},
                     {"channel", s.channel},
                     {"unit", s.unit},
                     {"fitted", s.fitted},
                     {"noise_variance", s.noise_variance},
                     {"noise_source", s.noise_source},
                     {"points", s.t.size()},
                     {"rms", s.rms},
                     {"nrmse", s.nrmse},
                     {"fit_percent", s.fit_percent},
                     {"baseline_fit_percent", jsonNumber(s.baseline_fit_percent)},
                     {"max_abs_error", s.max_abs},
                     {"max_error_at_s", s.max_at_s},
                     {"coverage95", s.coverage},
                     {"systematic_rms", s.systematic_rms},
                     {"lack_of_fit_chi2", s.lack_of_fit}};
    e["windows"] = nlohmann::json::array();  // the listed ones, largest share first
    for (const auto& w : s.windows)
      e["windows"].push_back({{"t_begin_s", w.window.t_begin},
                              {"t_end_s", w.window.t_end},
                              {"peak_z", w.window.peak_z},
                              {"share_of_chi2", w.window.share},
                              {"label", w.label},
                              {"speed_mps", w.speed_mps}});
    const WindowSummary& ws = s.window_summary;
    e["windows_summary"] = {{"found", ws.found},
                            {"merged", ws.merged},
                            {"listed", ws.listed},
                            {"merge_gap_s", ws.merge_gap_s},
                            {"time_share", ws.time_share},
                            {"merged_share_of_chi2", ws.merged_share},
                            {"listed_share_of_chi2", ws.listed_share}};
    if (!s.windows_note.empty()) e["windows_note"] = s.windows_note;
    nlohmann::json rows = nlohmann::json::array();  // every window found, chronological
    for (const auto& w : s.all_windows) rows.push_back({w.t_begin, w.t_end, w.peak_z, w.share});
    e["all_windows"] = {{"columns", {"t_begin_s", "t_end_s", "peak_z", "share_of_chi2"}},
                        {"rows", std::move(rows)}};
    e["bands"] = nlohmann::json::array();
    for (const auto& b : s.bands)
      e["bands"].push_back({{"band", b.band},
                            {"lo_hz", b.lo_hz},
                            {"hi_hz", b.hi_hz},
                            {"residual_power", b.residual_power},
                            {"noise_power", b.noise_power},
                            {"ratio", b.ratio},
                            {"coherence_with_road", b.coherence},
                            {"significant", b.significant}});
    if (!s.bands_note.empty()) e["bands_note"] = s.bands_note;
    if (s.discrepancy)
      e["discrepancy"] = s.discrepancy->toJson(s.baseline_fit_percent, with_series_data);
    e["frequency_response"] = s.frequency_response.toJson(with_series_data);
    if (with_series_data) {
      e["t"] = s.t;
      e["measured_mean"] = s.measured_mean;
      e["predicted_mean"] = s.predicted_mean;
      e["band_lo"] = s.band_lo;
      e["band_hi"] = s.band_hi;
    }
    j["series"].push_back(e);
  }
  j["state_maps"] = nlohmann::json::array();
  for (const auto& cm : maps) {
    nlohmann::json c{{"channel", cm.channel}, {"maps", nlohmann::json::array()}};
    for (const auto& m : cm.maps) {
      nlohmann::json mm{
          {"state", m.state}, {"bins", nlohmann::json::array()}, {"fits", nlohmann::json::array()}};
      for (const auto& b : m.bins)
        mm["bins"].push_back({{"lo", b.lo},
                              {"hi", b.hi},
                              {"centre", b.centre},
                              {"mean_residual", b.mean},
                              {"se", b.se},
                              {"count", b.count}});
      for (const auto& f : m.fits) {
        nlohmann::json fj{{"feature", f.feature},
                          {"coefficient", f.coefficient},
                          {"explained_fraction", f.explained_fraction}};
        if (f.feature == "knee") fj["knee_at"] = f.knee_at;
        mm["fits"].push_back(fj);
      }
      c["maps"].push_back(mm);
    }
    j["state_maps"].push_back(c);
  }
  return j;
}

std::string comparisonTable(const Comparison& c) {
  const bool baseline =
      std::any_of(c.series.begin(), c.series.end(),
                  [](const SeriesComparison& x) { return !std::isnan(x.baseline_fit_percent); });
  std::string s = formatPrintf("%-28s %-12s %-20s %10s %8s %7s %10s %9s %10s%s\n", "data set",
                               "scenario", "channel", "RMS", "NRMSE", "fit %", "max |err|",
                               "coverage", "syst. RMS", baseline ? "  FIR fit %" : "");
  for (const auto& x : c.series) {
    std::string name = x.data_set;
    if (name.size() > 28) name = "…" + name.substr(name.size() - 27);
    s += formatPrintf("%-28s %-12s %-20s %10.4g %8.4f %7.1f %10.4g %8.1f%% %10.4g%s\n",
                      name.c_str(), x.scenario.c_str(), x.channel.c_str(), x.rms, x.nrmse,
                      x.fit_percent, x.max_abs, 100.0 * x.coverage, x.systematic_rms,
                      baseline ? formatPrintf(" %10.1f", x.baseline_fit_percent).c_str() : "");
  }
  s += formatPrintf(
      "lack of fit: chi2 = %.1f on %ld dof (z = %.1f, p = %.2g); systematic residual %.3f noise "
      "sd\n",
      c.lack_of_fit, c.lack_of_fit_dof, c.lack_of_fit_z, c.lack_of_fit_p, c.systematic_rms_sd);
  return s;
}

StageWork estimateCompareWork(const std::vector<calib::DataSet>& sets, std::size_t draws) {
  StageWork w{"compare", 0, 0, 0};
  const double runs = static_cast<double>(draws) + 1;  // the draws and the run at their mean
  for (const auto& s : sets) {
    w.simulations += runs;
    w.simulated_s += runs * dataSpan(s.data);
    w.memory_bytes +=
        8.0 * runs *
        static_cast<double>(s.data.records.size());  // one prediction per record and draw
  }
  return w;
}

}  // namespace dtwin::diag
