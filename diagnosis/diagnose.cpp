#include "diagnosis/diagnose.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>

#include <Eigen/Dense>

#include "common/format.hpp"
#include "common/errors.hpp"
#include "common/validate.hpp"
#include "diagnosis/candidates.hpp"
#include "subsystems/effect.hpp"
#include "common/parallel.hpp"
#include "io/provenance.hpp"

namespace fs = std::filesystem;

namespace dtwin::diag {
namespace {

/// P(χ²_k > x) for k = 1, 2 exactly, else Wilson–Hilferty.
double chi2Upper(double x, int k) {
  if (x <= 0) return 1.0;
  if (k == 1) return std::erfc(std::sqrt(x / 2.0));
  if (k == 2) return std::exp(-x / 2.0);
  const double a = 2.0 / (9.0 * k);
  return 1.0 - normalCdf((std::cbrt(x / k) - (1.0 - a)) / std::sqrt(a));
}

std::string fmt(const char* f, double v) { return formatPrintf(f, v); }

std::string joinEffects(const std::vector<std::string>& e) {
  if (e.empty()) return "base";
  std::string s;
  for (std::size_t i = 0; i < e.size(); ++i) s += (i ? "+" : "") + e[i];
  return s;
}

/// The value a probe sets: off + f (far − off), far the prior end farther from the off value.
double towardFar(const ParameterSpec& p, double f) {
  const double off = p.default_value;
  const double far = (p.prior_upper - off >= off - p.prior_lower) ? p.prior_upper : p.prior_lower;
  return off + f * (far - off);
}

/// A parameter whose off value is at a prior bound adds strength (a bar rate); one whose off
/// value lies inside the prior only shapes the effect of the others (a gap) and is scanned.
bool isStrength(const ParameterSpec& p) { return p.default_value <= p.prior_lower || p.default_value >= p.prior_upper; }


/// The fraction of Σ z² in [t0, t1] of a series.
double chi2In(const SeriesComparison& s, double t0, double t1) {
  double a = 0.0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= t0 && s.t[i] <= t1 && std::isfinite(s.z[i])) a += s.z[i] * s.z[i];
  return a;
}

/// An effect's name in words with its article: "bump_stop" -> "a bump stop".
std::string inWords(const std::string& effect) {
  std::string w = effect;
  std::replace(w.begin(), w.end(), '_', ' ');
  return (std::string("aeiou").find(w.empty() ? 'x' : w[0]) == std::string::npos ? "a " : "an ") + w;
}

/// A length parameter's name without its unit suffix: "gap_m" -> "gap".
std::string withoutUnit(const std::string& parameter) {
  const std::string suffix = "_m";
  const bool has =
      parameter.size() > suffix.size() && parameter.compare(parameter.size() - suffix.size(), suffix.size(), suffix) == 0;
  std::string w = has ? parameter.substr(0, parameter.size() - suffix.size()) : parameter;
  std::replace(w.begin(), w.end(), '_', ' ');
  return w;
}

/// Where the residual of a comparison lies: the largest windows, the bands above the noise floor,
/// the strongest force-state signature.
std::string locate(const Comparison& c) {
  struct W {
    double share;
    std::string text;
  };
  std::vector<W> ws;
  for (const auto& s : c.series)
    for (const auto& w : s.windows)
      ws.push_back({w.window.share, s.channel + " in " + s.scenario + " " + fmt("%.3f", w.window.t_begin) + "-" +
                                        fmt("%.3f", w.window.t_end) + " s (" + w.label + ", " +
                                        fmt("%.0f", 100 * w.window.share) + " % of its residual)"});
  std::sort(ws.begin(), ws.end(), [](const W& a, const W& b) { return a.share > b.share; });
  std::string out;
  for (std::size_t i = 0; i < std::min<std::size_t>(2, ws.size()); ++i) out += (i ? "; " : "") + ws[i].text;
  std::set<std::string> bands;
  for (const auto& s : c.series)
    for (const auto& b : s.bands)
      if (b.significant) bands.insert(b.band);
  if (!bands.empty()) {
    out += std::string(out.empty() ? "" : "; ") + "residual above the noise floor in the ";
    std::size_t i = 0;
    for (const auto& b : bands) out += (i++ ? ", " : "") + b;
    out += " band" + std::string(bands.size() > 1 ? "s" : "");
  }
  double best = 0.0;
  std::string map;
  for (const auto& cm : c.maps)
    for (const auto& m : cm.maps)
      if (!m.fits.empty() && m.fits[0].explained_fraction > best) {
        best = m.fits[0].explained_fraction;
        map = cm.channel + " vs " + m.state + " looks " + m.fits[0].feature +
              (m.fits[0].feature == "knee" ? " (beyond " + fmt("%.3g", m.fits[0].knee_at) + ")" : "") + " (" +
              fmt("%.0f", 100 * best) + " % of the map)";
      }
  if (!map.empty() && best > 0.3) out += std::string(out.empty() ? "" : "; ") + "force-state map: " + map;
  return out.empty() ? "no localised structure" : out;
}

nlohmann::json paramsJson(const std::vector<EffectParameter>& ps) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& p : ps)
    j[p.name] = {{"unit", p.unit},        {"mean", p.mean}, {"sd", p.sd}, {"ci95", {p.q025, p.q975}}, {"interval", p.interval},
                 {"credible95", {p.post_q025, p.post_q975}}, {"optimum", p.optimum}};
  return j;
}

}  // namespace

calib::CalibrationSetup candidatesSetup(const std::vector<CandidateSpec>& candidates, const std::map<std::string, double>& weights) {
  calib::CalibrationSetup s;
  s.channel_weights = weights;
  for (const auto& c : candidates) c.install(s);
  return s;
}

nlohmann::json Figures::toJson() const {
  nlohmann::json j{{"label", label},          {"effects", effects}, {"sse_min_weighted", sse_min}, {"bic", bic},
                   {"log_evidence", log_evidence}, {"parameters", parameters}, {"folder", folder}};
  j["effect_parameters"] = paramsJson(effect_parameters);
  j["values"] = paramsJson(values);
  j["bound_findings"] = nlohmann::json::array();
  for (const auto& b : bounds) j["bound_findings"].push_back(b.toJson());
  if (!left_out.empty()) j["left_out"] = left_out;
  j["calibration"] = full ? "full" : "optimum only";
  if (full) j["integrator_check"] = integrator.toJson();
  j["importance_ess"] = importance_ess;
  j["lack_of_fit_z"] = comparison.lack_of_fit_z;
  j["lack_of_fit_p"] = comparison.lack_of_fit_p;
  j["systematic_rms_noise_sd"] = comparison.systematic_rms_sd;
  j["series"] = nlohmann::json::array();
  for (const auto& s : comparison.series) {
    nlohmann::json e{{"data_set", s.data_set}, {"scenario", s.scenario}, {"channel", s.channel}, {"rms", s.rms},
                     {"nrmse", s.nrmse}, {"max_abs_error", s.max_abs}, {"coverage95", s.coverage},
                     {"systematic_rms", s.systematic_rms}};
    for (const auto& b : s.bands) e["band_power_ratio"][b.band] = b.ratio;
    j["series"].push_back(e);
  }
  if (holdout) j["holdout"] = {{"systematic_rms_noise_sd", holdout->systematic_rms_sd}, {"lack_of_fit_z", holdout->lack_of_fit_z}};
  return j;
}

void DiagnoseOptions::validate() const {
  const OptionCheck check("diagnose");
  calibration.validate();
  check.atLeast("candidates", candidates, 0);
  check.require(confirm_within >= 1.0, "confirm_within", "must be >= 1 (a factor of the best screening score)");
  check.atLeast("causes", causes, 1);
  check.open01("screen_alpha", screen_alpha);
  check.nonNegative("bic_strong", bic_strong);
  check.nonNegative("ambiguity_log_evidence", ambiguity_log_evidence);
  check.require(full_within >= 0, "full_within", "must be >= 0 (infinity: every confirmed candidate calibrated in full)");
  check.inRange("explained_min", explained_min, 0.0, 1.0);
  check.open01("lack_of_fit_alpha", lack_of_fit_alpha);
  check.atLeast("compare_draws", compare_draws, 1);
  check.atLeast("threads", threads, 0);
  check.inRange("propose_terms", propose_terms, 0, 3);
  for (const char* field : {"effects", "apply"}) {
    const auto& names = std::string(field) == "effects" ? effects : apply;
    std::set<std::string> seen;
    for (const auto& e : names) {
      // The form only: an effect's name is checked against the study's catalogue (diagnose(), naming
      // the nearest and every known effect), a freed value or a sensor model against the study and
      // the data (catalogueOf).
      check.require(hasCandidateForm(e), field,
                    "'" + e + "' is not a candidate: an effect, free:<vehicle value>, widen:<calibrated value>, <subsystem>=<option> or "
                    "<lowpass|lowpass2|gain|delay>:<channel group>");
      check.require(seen.insert(e).second, field, "names '" + e + "' twice");
    }
  }
}

namespace {

/// What the stages of one diagnosis share (docs/diagnosis.md, "twin diagnose"): the inputs, the
/// fitted data and their weights, the catalogue, every calibration's optimum and the result
/// being built. Each stage below reads and extends it.
struct Diagnosis {
  Diagnosis(const Study& s, const AssemblySpec& a, const DiagnoseOptions& o, std::string out, const DiagnoseProgress& p)
      : study(s), assembly(a), options(o), out_dir(std::move(out)), progress(p) {}
  const Study& study;
  const AssemblySpec& assembly;
  const DiagnoseOptions& options;
  const std::string out_dir;
  const DiagnoseProgress& progress;
  std::map<std::string, ChannelNoise> noise;          ///< per fitted channel
  std::map<std::string, double> weights;              ///< 1/σ_c² per fitted channel
  std::vector<calib::DataSet> fit_sets, hold_sets;    ///< the fitted channels of the fit and held-out data
  std::string data_hash;                              ///< of fit_sets: a calibration folder's identity
  std::vector<std::string> catalogue;                 ///< the candidates ranked (no installed effect)
  std::map<std::string, CandidateSpec> specs;         ///< every candidate of the catalogue and of options.apply
  std::map<std::string, std::vector<double>> optima;  ///< every calibration's optimum, by joinEffects(effects)
  std::map<std::string, std::vector<std::string>> optima_names;  ///< ... and the names of its values
  /// The optimiser's extra starts of each calibration folder, fixed by its first call: a folder
  /// calibrated again (in full after its optimum, or from another stage) resumes the same
  /// calibration instead of meeting a different one.
  std::map<std::string, std::vector<std::vector<double>>> starts_of;
  std::unique_ptr<calib::LabObjective> base_obj;      ///< the current stage's reference model on fit_sets (screening, refinement)
  DiagnosisResult res;
  /// Forward stagewise (docs/diagnosis.md, "More than one cause"): the causes installed so far.
  /// Empty in the first stage, whose reference is the base; later stages screen and confirm on
  /// top of them, and their candidates are res.further.back().candidates.
  std::vector<std::string> installed;
  /// The current stage's reference model (res.base in the first stage).
  const Figures* reference = nullptr;

  /// The parameters of candidate `name` in the calibration `f` (which may hold other causes too).
  std::vector<EffectParameter> parametersOf(const std::string& name, const Figures& f) const {
    std::vector<EffectParameter> out;
    for (const auto& n : spec(name).calibrated_names)
      for (const auto& p : f.effect_parameters)
        if (p.name == n) out.push_back(p);
    return out;
  }
  /// What `f` says of candidate `name`, in words (CandidateSpec::finding at its mean values).
  std::string findingOf(const std::string& name, const Figures& f) const {
    std::vector<double> values;
    for (const auto& p : parametersOf(name, f)) values.push_back(p.mean);
    return spec(name).finding(values);
  }
  /// The candidates of the current stage.
  std::vector<Candidate>& stage() { return installed.empty() ? res.candidates : res.further.back().candidates; }
  /// `name` installed on top of the causes of the current stage.
  std::vector<std::string> withInstalled(const std::string& name) const {
    auto e = installed;
    e.push_back(name);
    return e;
  }

  void report(const std::string& stage, std::size_t done, std::size_t total) const {
    if (progress) progress(stage, done, total);
  }
  const CandidateSpec& spec(const std::string& name) const { return specs.at(name); }
  /// The calibration setup with `names` installed, weighted by `weights`.
  calib::CalibrationSetup setupOf(const std::vector<std::string>& names) const {
    std::vector<CandidateSpec> cs;
    for (const auto& n : names) cs.push_back(spec(n));
    return candidatesSetup(cs, weights);
  }
  /// One calibration with `effects` installed (persisted under out_dir/calibrations, resumable),
  /// compared on the fit and held-out data. effect_start, theta_start: the screening's estimate of
  /// the effects' and the base parameters (extra optimiser starts); a base given theta_start is
  /// the refined base and has its own folder. full = false: the optimum alone
  /// (calib::calibrateOptimum), compared at the optimum; a later full call resumes from it.
  Figures calibrateWith(const std::vector<std::string>& effects, const std::string& stage,
                        const std::vector<double>& effect_start = {}, const std::vector<double>& theta_start = {},
                        bool full = true);

 private:
  /// The optimiser's extra starts of a calibration with `effects` (see calibrateWith).
  std::vector<std::vector<double>> extraStarts(const std::vector<std::string>& effects, const std::vector<double>& effect_start,
                                               const std::vector<double>& theta_start) const;
  /// The model calibrated with `setup` compared with the data at evenly spaced posterior rows of `r`.
  void compareFigures(Figures& f, const calib::CalibrationResult& r, const calib::CalibrationSetup& setup,
                      const std::string& stage) const;
};

/// The off values of the diagnosed parameters of a candidate, in order.
std::vector<double> offValues(const CandidateSpec& c) {
  std::vector<double> v;
  for (const auto& p : c.parameters) v.push_back(p.default_value);
  return v;
}

std::vector<std::vector<double>> Diagnosis::extraStarts(const std::vector<std::string>& effects,
                                                        const std::vector<double>& effect_start,
                                                        const std::vector<double>& theta_start) const {
  // Every calibration polishes its optimum; a model with effects also starts from the nested
  // model's optimum with the effects' parameters off, so adding an effect never fits worse.
  std::vector<std::vector<double>> starts;
  if (effects.empty() && !theta_start.empty()) starts.push_back(theta_start);
  if (effects.empty()) return starts;
  const std::vector<std::string> nested(effects.begin(), effects.end() - 1);
  const auto it = optima.find(joinEffects(nested));
  if (it == optima.end()) return starts;
  const CandidateSpec& last = spec(effects.back());
  if (!last.addsParameters()) {
    // A widened range or another option: the nested optimum's values by name (an option may lack
    // some, e.g. the hub input the tire's), and the screening's estimate of the widened model.
    const calib::LabObjective target(study, assembly, fit_sets, setupOf(effects));
    const auto& from = optima_names.at(joinEffects(nested));
    std::vector<double> x;
    for (std::size_t k = 0; k < target.names().size(); ++k) {
      const auto at = std::find(from.begin(), from.end(), target.names()[k]);
      x.push_back(at != from.end() ? it->second[static_cast<std::size_t>(at - from.begin())]
                                   : 0.5 * (target.lower()[k] + target.upper()[k]));
    }
    starts.push_back(x);
    if (theta_start.size() == x.size()) starts.push_back(theta_start);
    return starts;
  }
  auto x = it->second;
  for (double v : offValues(last)) x.push_back(v);
  starts.push_back(x);
  if (effect_start.empty()) return starts;
  auto y = it->second;
  for (double v : effect_start) y.push_back(v);
  starts.push_back(y);
  if (theta_start.size() == it->second.size()) {  // the screening's θ̂ + δθ of the nested model
    auto z = theta_start;
    for (double v : effect_start) z.push_back(v);
    starts.push_back(z);
  }
  return starts;
}

Figures Diagnosis::calibrateWith(const std::vector<std::string>& effects, const std::string& stage,
                                 const std::vector<double>& effect_start, const std::vector<double>& theta_start, bool full) {
  Figures f;
  f.effects = effects;
  f.label = effects.empty() ? "base" : "+ " + joinEffects(effects);
  // A base started from a better point than its own optimum (see refine) has its own folder.
  f.folder = (fs::path(out_dir) / "calibrations" / (joinEffects(effects) + (effects.empty() && !theta_start.empty() ? ".refined" : "")))
                 .string();
  const auto setup = setupOf(effects);
  auto copt = options.calibration;
  copt.threads = options.threads;
  copt.command = options.command;
  copt.polish_step = 0.01;
  const auto known = starts_of.find(f.folder);
  const auto& starts = known != starts_of.end() ? known->second
                                                : (starts_of[f.folder] = extraStarts(effects, effect_start, theta_start));
  copt.extra_starts.insert(copt.extra_starts.end(), starts.begin(), starts.end());
  const auto progress_of = [&](const std::string& s, std::size_t d, std::size_t t) { report(stage + ": " + s, d, t); };
  const auto r = full ? calib::calibrateAssembly(study, assembly, fit_sets, setup, copt, f.folder, data_hash, progress_of)
                      : calib::calibrateOptimum(study, assembly, fit_sets, setup, copt, f.folder, data_hash, progress_of);
  optima[joinEffects(effects)] = r.optimum.theta;
  optima_names[joinEffects(effects)] = r.names;
  f.full = full;
  f.parameters = static_cast<int>(r.names.size());
  f.sse_min = r.optimum.sse;
  f.integrator = r.integrator;
  f.importance_ess = r.rounds.ess;
  f.bic = r.optimum.sse + f.parameters * std::log(static_cast<double>(r.n_data));
  f.log_evidence = -0.5 * f.bic;
  f.bounds = r.bounds;
  f.left_out = r.left_out;
  // The candidates' own parameters: those the setup adds (after the study's calibrated values),
  // and a widened value's (a range candidate's, one of the study's).
  const std::size_t n_fit_params = r.names.size() - setup.extra_calibrated.size();
  for (std::size_t k = 0; k < r.names.size(); ++k) {
    const bool own = k >= n_fit_params || setup.bounds.count(r.names[k]);
    EffectParameter ep;
    ep.name = r.names[k];
    ep.unit = k < r.units.size() ? r.units[k] : "";
    ep.optimum = r.optimum.theta[k];
    if (!full) {  // the optimum alone: no posterior, no interval
      ep.mean = ep.optimum;
      ep.sd = ep.q025 = ep.q975 = ep.post_q025 = ep.post_q975 = std::numeric_limits<double>::quiet_NaN();
      ep.interval = "none";
    } else {
      const auto& p = r.posterior.parameters[k];
      ep.mean = p.mean;
      ep.sd = p.sd;
      ep.post_q025 = p.q025;
      ep.post_q975 = p.q975;
      const bool prof = r.interval == "profile" && k < r.profile.lower.size();
      ep.interval = prof ? "profile" : "posterior";
      ep.q025 = prof ? r.profile.lower[k] : p.q025;
      ep.q975 = prof ? r.profile.upper[k] : p.q975;
    }
    f.values.push_back(ep);
    if (own) f.effect_parameters.push_back(ep);
  }
  compareFigures(f, r, setup, stage);
  return f;
}

void Diagnosis::compareFigures(Figures& f, const calib::CalibrationResult& r, const calib::CalibrationSetup& setup,
                               const std::string& stage) const {
  std::vector<std::vector<double>> rows;
  if (!f.full) rows.push_back(r.optimum.theta);  // the optimum alone: no posterior rows
  const std::size_t m = f.full ? r.chains.index.size() : 0;
  const std::size_t want = std::min<std::size_t>(static_cast<std::size_t>(std::max(1, options.compare_draws)), m);
  for (std::size_t k = 0; k < want; ++k) {
    const std::size_t i = want == 1 ? m / 2 : k * (m - 1) / (want - 1);
    std::vector<double> th(r.names.size());
    for (std::size_t c = 0; c < th.size(); ++c) th[c] = r.design(r.chains.index[i], static_cast<long>(c));
    rows.push_back(th);
  }
  report(stage + ": compare", 0, 1);
  CompareOptions co;
  co.threads = options.threads;
  co.fitted_parameters = f.parameters;
  calib::LabObjective obj(study, assembly, fit_sets, setup);
  f.comparison = compareModel(obj, fit_sets, rows, noise, co);
  if (!hold_sets.empty()) {
    calib::LabObjective hobj(study, assembly, hold_sets, setup);
    CompareOptions ho = co;
    ho.fitted_parameters = 0;
    f.holdout = compareModel(hobj, hold_sets, rows, noise, ho);
  }
  report(stage + ": compare", 1, 1);
}

// ------------------------------------------------------------------ inputs

/// The candidates to rank: options.effects, or the default catalogue (candidates.hpp) without the
/// effects installed in the assembly or the study, on data with the fitted `channels`. Their specs
/// and those of options.apply go into `specs`. Throws InputError when options.effects or
/// options.apply names an installed effect or a candidate these study and data do not have.
/// The effects installed in `assembly` or the study; InputError when options.effects or
/// options.apply names one (checked before any data are read).
std::set<std::string> refuseInstalled(const Study& study, const AssemblySpec& assembly, const DiagnoseOptions& options) {
  const OptionCheck check("diagnose");
  std::set<std::string> installed(assembly.effects.begin(), assembly.effects.end());
  for (const auto& e : study.effects) installed.insert(e.name);
  const std::string rule = " is already installed in assembly " + assembly.id + " or the study's [effects]";
  for (const auto& e : options.effects) check.require(!installed.count(e), "effects", "'" + e + "'" + rule);
  for (const auto& e : options.apply) check.require(!installed.count(e), "apply", "'" + e + "'" + rule);
  return installed;
}

/// Whether a data set's road is a measured signal (RoadSetting::measured): the input-side and
/// input-form candidates join the default catalogue.
bool measuredRoad(const Study& study, const std::vector<calib::DataSet>& sets) {
  for (const auto& s : sets)
    if (study.scenario(s.scenario).road->measured()) return true;
  return false;
}

std::vector<std::string> catalogueOf(const Study& study, const AssemblySpec& assembly, const DiagnoseOptions& options,
                                     const std::vector<std::string>& channels, std::map<std::string, CandidateSpec>& specs,
                                     bool measured_road) {
  const OptionCheck check("diagnose");
  const auto installed = refuseInstalled(study, assembly, options);
  std::vector<std::string> catalogue =
      options.effects.empty() ? defaultCandidates(study.effectCatalog(), assembly, channels, measured_road) : options.effects;
  // The default catalogue leaves out what the model has already: an installed effect, a value the
  // study calibrates (a named one is refused by candidateSpec).
  const auto calibrated = [&](const std::string& e) {
    return options.effects.empty() && std::any_of(study.calibrated.begin(), study.calibrated.end(),
                                                   [&](const CalibratedParameter& c) { return e == "free:" + c.name; });
  };
  catalogue.erase(std::remove_if(catalogue.begin(), catalogue.end(), [&](const std::string& e) { return installed.count(e) > 0 || calibrated(e); }),
                  catalogue.end());
  for (const char* field : {"effects", "apply"})
    for (const auto& e : std::string(field) == "effects" ? catalogue : options.apply)
      if (!specs.count(e)) specs.emplace(e, candidateSpec(e, study, assembly, channels, check.where(field)));
  return catalogue;
}

/// The noise of every channel, the weights 1/σ_c², and the data sets reduced to the channels with
/// a noise estimate (the others are compared, not weighed).
void prepareData(Diagnosis& d, const std::vector<calib::DataSet>& fit, const std::vector<calib::DataSet>& holdout) {
  std::vector<std::string> left;
  d.noise = estimateChannelNoise(d.study, fit, &left);
  d.res.left_out_channels = left;
  if (d.noise.empty())
    throw InputError(fit.front().name, "no channel has a noise estimate: give at least two repetitions, or force channels (unit N) "
                                       "with the study's [noise] variance");
  for (const auto& [c, n] : d.noise) {
    d.weights[c] = 1.0 / n.variance;
    d.res.fitted_channels.push_back(c);
  }
  auto fittedOnly = [&](const std::vector<calib::DataSet>& sets) {
    std::vector<calib::DataSet> out;
    for (const auto& s : sets) {
      calib::DataSet ds{s.name, s.scenario, {}, s.road_seed};
      for (const auto& r : s.data.records)
        if (d.noise.count(r.channel)) ds.data.records.push_back(r);
      if (!ds.data.records.empty()) out.push_back(std::move(ds));
    }
    return out;
  };
  d.fit_sets = fittedOnly(fit);
  d.hold_sets = fittedOnly(holdout);
  for (const auto& s : d.fit_sets)
    d.data_hash += s.scenario + ":" + hexId(fnv1a64(labCsvText(s.data, measurableChannels(d.study.sensors)))) + ";";
}

/// The base's values on a bound of their range with a physical limit beyond it: each a candidate
/// "widen:<value>" of the default catalogue (docs/diagnosis.md, "Values on their bounds").
void addRangeCandidates(Diagnosis& d) {
  if (!d.options.effects.empty()) return;  // a named catalogue is the user's
  for (const auto& f : d.res.base.bounds) {
    if (f.side == "none" || f.at_limit() || !std::isfinite(f.limit)) continue;
    const std::string name = "widen:" + f.name;
    if (std::find(d.catalogue.begin(), d.catalogue.end(), name) != d.catalogue.end()) continue;
    try {
      d.specs.emplace(name, candidateSpec(name, d.study, d.assembly, d.res.fitted_channels, "diagnose.effects"));
      d.catalogue.push_back(name);
    } catch (const InputError&) {
      // no physical limit beyond the study's range: nothing to widen
    }
  }
}

// ------------------------------------------------------------------ screen

/// The base model linearised at its optimum θ̂: the standardised residual r, the sensitivities
/// J = ∂η/∂θ (weighted, central differences) and J's QR (the span re-calibrating θ could absorb).
struct Linearisation {
  std::vector<double> theta_hat, eta_hat;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;  ///< ∂η/∂θ, weighted
  Eigen::HouseholderQR<Eigen::MatrixXd> qr;
  Eigen::MatrixXd Q;  ///< orthonormal basis of span(J)
  /// G with span(J) projected out.
  Eigen::MatrixXd project(const Eigen::MatrixXd& G) const { return G - Q * (Q.transpose() * G); }
  /// G with the span of J's other columns than `k` projected out: what re-calibrating every value
  /// but θ_k could absorb (the score of θ_k beyond its bound).
  Eigen::MatrixXd projectWithout(std::size_t k, const Eigen::MatrixXd& G) const {
    if (J.cols() <= 1) return G;
    Eigen::MatrixXd Jk(J.rows(), J.cols() - 1);
    for (long c = 0, o = 0; c < J.cols(); ++c)
      if (c != static_cast<long>(k)) Jk.col(o++) = J.col(c);
    Eigen::HouseholderQR<Eigen::MatrixXd> q(Jk);
    const Eigen::MatrixXd Qk = q.householderQ() * Eigen::MatrixXd::Identity(Jk.rows(), Jk.cols());
    return G - Qk * (Qk.transpose() * G);
  }
};

Linearisation linearise(const Diagnosis& d) {
  const auto& obj = *d.base_obj;
  Linearisation lin;
  lin.theta_hat = d.optima.at(joinEffects(d.installed));
  lin.eta_hat = obj.predict(lin.theta_hat);
  if (lin.eta_hat.empty()) throw std::runtime_error("diagnose: the run at the base optimum failed");
  const auto& y = obj.measured();
  const auto& w = obj.weights();
  const std::size_t n = y.size(), dim = lin.theta_hat.size();
  lin.r.resize(static_cast<long>(n));
  for (std::size_t i = 0; i < n; ++i) lin.r[static_cast<long>(i)] = std::sqrt(w[i]) * (y[i] - lin.eta_hat[i]);
  Eigen::MatrixXd J(static_cast<long>(n), static_cast<long>(dim));
  std::vector<std::vector<double>> plus(dim), minus(dim);
  std::vector<double> h(dim);
  for (std::size_t k = 0; k < dim; ++k)
    h[k] = 1e-2 * std::max(std::abs(lin.theta_hat[k]), 1e-3 * (obj.upper()[k] - obj.lower()[k]));
  d.report("screening: sensitivities", 0, 2 * dim);
  // Central differences, one-sided where a value sits on a bound of its range (an effect at its
  // off value 0, a value the data pushed to its bound): a step across the bound may leave the
  // value's valid set, and its run would fail.
  std::vector<double> up(dim), down(dim);
  for (std::size_t k = 0; k < dim; ++k) {
    up[k] = std::min(h[k], obj.upper()[k] - lin.theta_hat[k]);
    down[k] = std::min(h[k], lin.theta_hat[k] - obj.lower()[k]);
    if (up[k] < 0.5 * h[k] && down[k] < 0.5 * h[k]) up[k] = down[k] = h[k];  // a range narrower than the step: both sides
    else if (up[k] < 0.5 * h[k]) up[k] = 0.0, down[k] = h[k];
    else if (down[k] < 0.5 * h[k]) down[k] = 0.0, up[k] = h[k];
    else up[k] = down[k] = h[k];
  }
  parallelFor(2 * dim, d.options.threads, [&](std::size_t t, int) {
    const std::size_t k = t / 2;
    auto th = lin.theta_hat;
    th[k] += t % 2 == 0 ? up[k] : -down[k];
    (t % 2 == 0 ? plus[k] : minus[k]) = (t % 2 == 0 ? up[k] : down[k]) == 0.0 ? lin.eta_hat : obj.predict(th);
  });
  for (std::size_t k = 0; k < dim; ++k) {
    if (plus[k].empty() || minus[k].empty())
      throw std::runtime_error("diagnose: a sensitivity run at the base optimum failed (" + obj.names()[k] + " = " +
                               fmt("%.6g", lin.theta_hat[k]) + ")");
    for (std::size_t i = 0; i < n; ++i)
      J(static_cast<long>(i), static_cast<long>(k)) = std::sqrt(w[i]) * (plus[k][i] - minus[k][i]) / (up[k] + down[k]);
  }
  lin.qr.compute(J);
  lin.Q = lin.qr.householderQ() * Eigen::MatrixXd::Identity(static_cast<long>(n), static_cast<long>(dim));
  lin.J = std::move(J);
  return lin;
}

/// One probe of one effect: columns of its parameter vectors (one strength parameter moved per
/// column, at one level, the scanned shape-like parameters at one point), tested together.
struct ProbeGroup {
  std::size_t effect;                     ///< index into the catalogue
  std::vector<std::vector<double>> cols;  ///< parameter vectors, one per column
  /// A range candidate: the index in θ of the widened value, which each column's one value
  /// replaces (instead of parameters appended to θ); -1 otherwise.
  long theta_index = -1;
};

/// The probes of effect `e` (docs/diagnosis.md, screening): every strength parameter at 5, 20 and
/// 60 % of the way to its far prior end, for every point of the scan (10, 30, 60 % of the prior)
/// of the parameters whose off value lies inside their prior.
std::vector<ProbeGroup> probesOf(std::size_t e, const CandidateSpec& candidate, double at = std::numeric_limits<double>::quiet_NaN(),
                                 long theta_index = -1) {
  if (candidate.kind == "option") return {};  // not nested: no score test (always confirmed)
  if (candidate.kind == "range") {
    // Beyond the study's bound the value sits at (the upper one when unknown), 5, 20 and 60 % of the
    // way to its physical limit.
    const bool lower = std::isfinite(at) && at - candidate.study_lower < candidate.study_upper - at;
    const double b = lower ? candidate.study_lower : candidate.study_upper;
    const double lim = lower ? candidate.parameters[0].prior_lower : candidate.parameters[0].prior_upper;
    std::vector<ProbeGroup> groups;
    if (lim == b) return groups;
    for (double level : {0.05, 0.2, 0.6}) groups.push_back({e, {{b + level * (lim - b)}}, theta_index});
    return groups;
  }
  const auto& ps = candidate.parameters;
  const std::vector<double> off = offValues(candidate);
  std::vector<std::size_t> strength, scan;
  for (std::size_t k = 0; k < ps.size(); ++k) (k == 0 || isStrength(ps[k]) ? strength : scan).push_back(k);
  std::vector<std::vector<double>> scans{off};
  for (std::size_t k : scan) {
    std::vector<std::vector<double>> next;
    for (const auto& base_v : scans)
      for (double f : {0.1, 0.3, 0.6}) {
        auto v = base_v;
        v[k] = ps[k].prior_lower + f * (ps[k].prior_upper - ps[k].prior_lower);
        next.push_back(v);
      }
    scans = next;
  }
  std::vector<ProbeGroup> groups;
  for (double level : {0.05, 0.2, 0.6})
    for (const auto& sv : scans) {
      ProbeGroup g{e, {}};
      for (std::size_t k : strength) {
        auto v = sv;
        v[k] = towardFar(ps[k], level);
        g.cols.push_back(v);
      }
      groups.push_back(g);
    }
  return groups;
}

/// The predictions at every probe column, in group then column order (empty: a failed run).
std::vector<std::vector<double>> simulateProbes(const Diagnosis& d, const std::vector<ProbeGroup>& groups,
                                                const std::vector<double>& theta_hat) {
  std::vector<std::unique_ptr<calib::LabObjective>> eff_obj;
  for (const auto& e : d.catalogue)
    eff_obj.push_back(d.spec(e).addsParameters()
                          ? std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets, d.setupOf(d.withInstalled(e)))
                          : nullptr);
  std::vector<std::pair<std::size_t, std::size_t>> jobs;  // (group, column)
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t c = 0; c < groups[g].cols.size(); ++c) jobs.push_back({g, c});
  std::vector<std::vector<double>> probe_eta(jobs.size());
  d.report("screening: probes", 0, jobs.size());
  parallelFor(jobs.size(), d.options.threads, [&](std::size_t j, int) {
    const auto& g = groups[jobs[j].first];
    auto th = theta_hat;
    if (g.theta_index >= 0) {
      th[static_cast<std::size_t>(g.theta_index)] = g.cols[jobs[j].second][0];
      probe_eta[j] = d.base_obj->predict(th);
      return;
    }
    for (double v : g.cols[jobs[j].second]) th.push_back(v);
    probe_eta[j] = eff_obj[g.effect]->predict(th);
  });
  d.report("screening: probes", jobs.size(), jobs.size());
  return probe_eta;
}

/// Scores every probe group: S = rᵀ P r, P the projection on span(g⊥) (g⊥ the group's
/// contributions with span(J) projected out), rank(g⊥) degrees of freedom. Each candidate keeps its
/// largest S, its largest ‖g⊥‖², and the linearised estimate of the effect's and the base
/// parameters at its best probe. Returns, per catalogue effect, whether every probe group failed.
std::vector<bool> scoreProbes(Diagnosis& d, const Linearisation& lin, const std::vector<ProbeGroup>& groups,
                              const std::vector<std::vector<double>>& probe_eta) {
  const auto& w = d.base_obj->weights();
  const std::size_t n = lin.eta_hat.size(), dim = lin.theta_hat.size();
  // Per effect: every probe group failed (a failed group, e.g. the strongest probe of a force
  // that destabilises the vehicle, is left out of the score; the others still count).
  std::vector<bool> all_failed(d.catalogue.size(), true);
  for (std::size_t g = 0, j = 0; g < groups.size(); ++g) {
    const std::size_t e = groups[g].effect;
    Eigen::MatrixXd G(static_cast<long>(n), static_cast<long>(groups[g].cols.size()));
    bool failed = false;
    for (std::size_t c = 0; c < groups[g].cols.size(); ++c, ++j) {
      if (probe_eta[j].empty()) {
        failed = true;
        continue;
      }
      for (std::size_t i = 0; i < n; ++i)
        G(static_cast<long>(i), static_cast<long>(c)) = std::sqrt(w[i]) * (probe_eta[j][i] - lin.eta_hat[i]);
    }
    if (failed) continue;
    all_failed[e] = false;
    const long k_range = groups[g].theta_index;
    const Eigen::MatrixXd Gp = k_range >= 0 ? lin.projectWithout(static_cast<std::size_t>(k_range), G) : lin.project(G);
    auto& cand = d.stage()[e];
    cand.max_signal = std::max(cand.max_signal, Gp.squaredNorm());
    // S = rᵀ Gp (Gpᵀ Gp)⁺ Gpᵀ r (rank-revealing: a column the base absorbs entirely drops out).
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(Gp);
    const long rank = cod.rank();
    if (rank == 0) continue;
    const Eigen::VectorXd coef = cod.solve(lin.r);
    const double S = (Gp * coef).squaredNorm();
    if (S <= cand.score) continue;
    cand.score = S;
    cand.score_dof = static_cast<int>(rank);
    if (k_range >= 0) {
      // The widened value beyond its bound b at v: the linearised fit says b + coef (v − b); the
      // other values follow it along their own columns (θ̂ + J₋ₖ⁺ (r − G coef)), as the nested
      // model's would.
      const auto kk = static_cast<std::size_t>(k_range);
      const auto& p0 = d.spec(d.catalogue[e]).parameters[0];
      const double b = lin.theta_hat[kk], v = groups[g].cols[0][0];
      cand.screening_estimate.clear();
      cand.screening_theta = lin.theta_hat;
      cand.screening_theta[kk] = std::clamp(b + coef[0] * (v - b), p0.prior_lower, p0.prior_upper);
      continue;
    }
    // Column c probes one strength parameter at value v_c (the others off): the linearised
    // fit says the parameter is off + coef_c (v_c − off), clipped to the prior.
    const auto& ps = d.spec(d.catalogue[e]).parameters;
    std::vector<double> est = groups[g].cols[0];
    for (std::size_t col = 0; col < groups[g].cols.size(); ++col)
      for (std::size_t k = 0; k < ps.size(); ++k)
        if (groups[g].cols[col][k] != ps[k].default_value && (k == 0 || isStrength(ps[k]))) {
          const double v = ps[k].default_value + coef[static_cast<long>(col)] * (groups[g].cols[col][k] - ps[k].default_value);
          est[k] = std::clamp(v, ps[k].prior_lower, ps[k].prior_upper);
        }
    cand.screening_estimate = est;
    // The base parameters of the joint linearised fit r ≈ J δθ + G c: δθ = J⁺ (r − G c).
    const Eigen::VectorXd dtheta = lin.qr.solve(lin.r - G * coef);
    cand.screening_theta = lin.theta_hat;
    for (std::size_t k = 0; k < dim; ++k)
      cand.screening_theta[k] =
          std::clamp(lin.theta_hat[k] + dtheta[static_cast<long>(k)], d.base_obj->lower()[k], d.base_obj->upper()[k]);
  }
  return all_failed;
}

/// The model's largest suspension compression [m] over the fit data at θ̂ (every corner).
double maxCompression(const Diagnosis& d, const std::vector<double>& theta_hat) {
  double max_compression = -std::numeric_limits<double>::infinity();
  for (const auto& t : d.base_obj->traces(theta_hat))
    for (const char* c : {"fl", "fr", "rl", "rr"})
      for (double q : t.column(std::string("susp_defl_") + c + "_m")) max_compression = std::max(max_compression, q);
  return max_compression;
}

/// The p-value of every candidate (Bonferroni over `probes`) and its gate: why an effect cannot
/// matter in these data (no plausible value changes them; an engagement threshold the travel
/// never reaches; a contribution below the noise; a failed probe).
void gateCandidates(Diagnosis& d, const std::vector<double>& theta_hat, std::size_t probes, const std::vector<bool>& all_failed) {
  const double bonferroni = static_cast<double>(probes);
  std::optional<double> max_compression;  // one more run, only when a threshold gate needs it
  for (std::size_t e = 0; e < d.catalogue.size(); ++e) {
    auto& c = d.stage()[e];
    c.p_value = std::min(1.0, bonferroni * chi2Upper(c.score, c.score_dof));
    const auto& spec = d.spec(c.effect);
    if (spec.kind == "option") continue;  // not screened: always confirmed
    const auto& names = d.base_obj->names();
    if (spec.kind == "range" && std::find(names.begin(), names.end(), spec.calibrated_names[0]) == names.end()) {
      c.gate = "this model has no " + spec.calibrated_names[0] + " to widen (" + joinEffects(d.installed) + " leaves it out)";
      continue;
    }
    if (all_failed[e]) {
      c.gate = "every probe simulation failed";
    } else if (c.max_signal == 0.0) {
      const std::string& threshold = spec.engagement_threshold;
      if (!threshold.empty()) {
        if (!max_compression) max_compression = maxCompression(d, theta_hat);
        const double smallest = spec.parameters[parameterIndex(spec.parameters, threshold)].prior_lower;
        c.gate = "the suspension never compresses beyond the smallest plausible " + withoutUnit(threshold) + " (" +
                 fmt("%.3g", *max_compression) + " m < " + fmt("%.3g", smallest) + " m): " + inWords(c.effect) + " cannot act here";
      } else {
        c.gate = spec.kind == "effect" ? "exerts no force in these runs at any plausible value"
                                       : "changes nothing in these data at any plausible value";
      }
    } else if (c.max_signal < 1.0) {
      c.gate = "its largest plausible contribution, after re-calibrating the base parameters, is below the noise (" +
               fmt("%.2g", c.max_signal) + " noise variances in total): these data cannot show it";
    }
  }
}

/// Screen (docs/diagnosis.md, `twin diagnose` step 2): at the base optimum θ̂, every catalogue effect's
/// contribution at a few probe values, with what re-calibrating θ could absorb projected out,
/// scored against the residual; fills res.candidates (score, p-value, gate, screening estimates).
void screen(Diagnosis& d) {
  d.base_obj = std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets, d.setupOf(d.installed));
  const Linearisation lin = linearise(d);
  std::vector<ProbeGroup> groups;
  auto& cands = d.stage();
  cands.resize(d.catalogue.size());
  const auto& names = d.base_obj->names();
  for (std::size_t e = 0; e < d.catalogue.size(); ++e) {
    const auto& spec = d.spec(d.catalogue[e]);
    cands[e].effect = d.catalogue[e];
    cands[e].kind = spec.kind;
    cands[e].signature = spec.signature;
    double at = std::numeric_limits<double>::quiet_NaN();
    long index = -1;
    if (spec.kind == "range") {
      const auto it = std::find(names.begin(), names.end(), spec.calibrated_names[0]);
      if (it == names.end()) continue;  // the model lacks the value (another option left it out): gated below
      index = static_cast<long>(it - names.begin());
      at = lin.theta_hat[static_cast<std::size_t>(index)];
    }
    for (auto& g : probesOf(e, spec, at, index)) groups.push_back(std::move(g));
  }
  const auto probe_eta = simulateProbes(d, groups, lin.theta_hat);
  const auto all_failed = scoreProbes(d, lin, groups, probe_eta);
  gateCandidates(d, lin.theta_hat, groups.size(), all_failed);
}

// ------------------------------------------------------------------ confirm, refine

/// The candidates to confirm (docs/diagnosis.md, "Confirmation"), in order: among the ungated ones
/// with p < screen_alpha, every one whose screening score is within a factor
/// options.confirm_within of the best, by score; then the best of each kind (effect, parameter,
/// sensor) not already in, by score; at most options.candidates in all (the work budget).
std::vector<std::size_t> chooseConfirmations(const std::vector<Candidate>& cands, const DiagnoseOptions& options) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (cands[i].gate.empty() && cands[i].p_value < options.screen_alpha) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cands[a].score > cands[b].score; });
  std::vector<std::size_t> chosen;
  if (order.empty()) return chosen;
  const double best = cands[order.front()].score;
  for (std::size_t i : order)
    if (cands[i].score * options.confirm_within >= best) chosen.push_back(i);
  std::set<std::string> kinds;
  for (std::size_t i : chosen) kinds.insert(cands[i].kind);
  for (std::size_t i : order)
    if (kinds.insert(cands[i].kind).second) chosen.push_back(i);
  if (chosen.size() > static_cast<std::size_t>(options.candidates)) chosen.resize(static_cast<std::size_t>(options.candidates));
  // Another option of a subsystem is not nested in the model: no score can screen it, so it is
  // always confirmed, beyond the budget.
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (cands[i].kind == "option" && cands[i].gate.empty()) chosen.push_back(i);
  return chosen;
}

/// Confirm (step 3): the candidates chooseConfirmations picks, re-calibrated with their effect.
/// Returns their indices in res.candidates.
std::vector<std::size_t> confirm(Diagnosis& d) {
  auto& cands = d.stage();
  const std::vector<std::size_t> to_confirm = chooseConfirmations(cands, d.options);
  const std::string on_top = d.installed.empty() ? "" : " on " + joinEffects(d.installed);
  // One candidate's calibration failing (e.g. its region found no point inside the bounds) is
  // reported with the candidate; the diagnosis goes on with the others.
  auto calibrate = [&](Candidate& c, const std::string& stage, bool full) {
    try {
      c.fit = d.calibrateWith(d.withInstalled(c.effect), stage, c.screening_estimate, c.screening_theta, full);
      return true;
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      c.fit.reset();
      c.gate = std::string("its confirming calibration failed: ") + e.what();
      return false;
    }
  };
  // First every candidate's optimum (its evidence), then the full calibration (intervals, the
  // posterior's comparison) of those that could be the verdict or ambiguous with it.
  std::vector<std::size_t> optimised;
  for (std::size_t k = 0; k < to_confirm.size(); ++k) {
    auto& c = cands[to_confirm[k]];
    const std::string stage =
        "confirm " + c.effect + on_top + " (" + std::to_string(k + 1) + "/" + std::to_string(to_confirm.size()) + ")";
    if (calibrate(c, stage, false)) optimised.push_back(to_confirm[k]);
  }
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i : optimised) best = std::max(best, cands[i].fit->log_evidence);
  const double margin = std::max(d.options.full_within, d.options.ambiguity_log_evidence);
  std::vector<std::size_t> confirmed;
  for (std::size_t i : optimised) {
    auto& c = cands[i];
    c.evidence_gap = best - c.fit->log_evidence;
    // On top of causes already named (a later stage of the stagewise selection) the evidence
    // decides alone; only the final model's intervals are reported, so it alone is calibrated in
    // full, once the selection ends (furtherCauses).
    if (d.installed.empty() && c.evidence_gap <= margin && !calibrate(c, "confirm " + c.effect + " in full", true)) continue;
    c.confirmed = true;
    c.finding = d.findingOf(c.effect, *c.fit);
    // Its own parameters all at their off values: the candidate adds nothing; an SSE below the
    // reference's then comes from polishing the reference's values further, not from it.
    const auto& spec = d.spec(c.effect);
    if (spec.addsParameters()) {
      const auto own = d.parametersOf(c.effect, *c.fit);
      c.inert = !own.empty() && std::all_of(own.begin(), own.end(), [&](const EffectParameter& p) {
        for (const auto& ps : spec.parameters)
          if (c.effect + "." + ps.name == p.name || ps.name == p.name || (spec.calibrated_names.size() == 1 && spec.calibrated_names[0] == p.name))
            return std::abs(p.optimum - ps.default_value) <= 1e-6 * (ps.prior_upper - ps.prior_lower);
        return false;
      });
    }
    confirmed.push_back(i);
  }
  return confirmed;
}

/// The base polished again from every strongly favoured candidate's base parameters (its effect
/// off); when that fits better than the base optimum, the base is re-calibrated from there.
void refineBase(Diagnosis& d, const std::vector<std::size_t>& to_confirm) {
  auto& res = d.res;
  std::vector<double> better;
  double better_sse = res.base.sse_min - 1.0;  // below the integrator's noise in the SSE: no change
  for (std::size_t i : to_confirm) {
    const auto& c = res.candidates[i];
    if (c.fit->bic - res.base.bic >= -d.options.bic_strong) continue;
    if (!d.spec(c.effect).addsParameters()) continue;  // not the base's values plus its own
    auto th = d.optima.at(joinEffects({c.effect}));
    th.resize(d.optima.at("base").size());
    d.report("refine base from " + c.effect, 0, 1);
    const auto p = calib::polishLeastSquares(*d.base_obj, th, {d.options.threads});
    d.report("refine base from " + c.effect, 1, 1);
    if (p.sse < better_sse) {
      better_sse = p.sse;
      better = p.theta;
      res.base_refined_from = c.effect;
    }
  }
  if (!better.empty()) {
    res.base_unrefined_sse = res.base.sse_min;
    res.base = d.calibrateWith({}, "base (refined)", {}, better);
  }
}

/// Refine (the end of step 3): the evidence for an effect must not come from a base optimum the optimiser
/// missed. The base is polished again from every strongly favoured candidate's base parameters
/// (its effect switched off); when that fits better, the base is re-calibrated from there and
/// becomes the reference of every ΔBIC and of the lack-of-fit figures (first stage only: a later
/// stage's reference is the previous stage's confirmed fit). Then each confirmed candidate is
/// weighed against the stage's reference (ΔBIC, share of the base's excess residual it removes,
/// held-out change) and the stage's candidates are ranked: confirmed by log evidence, then by
/// score, gated last.
void refine(Diagnosis& d, const std::vector<std::size_t>& to_confirm) {
  auto& res = d.res;
  auto& cands = d.stage();
  if (d.installed.empty()) refineBase(d, to_confirm);
  const Figures& ref = d.installed.empty() ? res.base : *d.reference;
  const Comparison& base = res.base.comparison;
  const double base_excess = base.lack_of_fit - static_cast<double>(base.lack_of_fit_dof);
  for (std::size_t i : to_confirm) {
    auto& c = cands[i];
    c.delta_bic = c.fit->bic - ref.bic;
    c.explained =
        base_excess > 0 ? std::clamp((ref.comparison.lack_of_fit - c.fit->comparison.lack_of_fit) / base_excess, 0.0, 1.0) : 0.0;
    if (c.fit->holdout && ref.holdout && ref.holdout->systematic_rms_sd > 0)
      c.holdout_change = c.fit->holdout->systematic_rms_sd / ref.holdout->systematic_rms_sd;
  }
  std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) {
    auto cls = [](const Candidate& c) { return c.confirmed ? 0 : (c.gate.empty() ? 1 : 2); };
    if (cls(a) != cls(b)) return cls(a) < cls(b);
    if (a.confirmed) return a.fit->log_evidence > b.fit->log_evidence;
    return a.score > b.score;
  });
}

// ------------------------------------------------------------------ verdict

/// The window of the base residual a confirmed candidate fixes most, in words ("" if none).
std::string windowFixed(const Comparison& base, const Comparison& with) {
  double best_drop = 0.0;
  std::string where;
  for (std::size_t i = 0; i < base.series.size() && i < with.series.size(); ++i)
    for (const auto& win : base.series[i].windows) {
      const double before = chi2In(base.series[i], win.window.t_begin, win.window.t_end);
      const double after = chi2In(with.series[i], win.window.t_begin, win.window.t_end);
      if (before - after > best_drop) {
        best_drop = before - after;
        where = "removes " + fmt("%.0f", before > 0 ? 100 * (before - after) / before : 0.0) + " % of the residual of " +
                base.series[i].channel + " in " + base.series[i].scenario + " " + fmt("%.3f", win.window.t_begin) + "-" +
                fmt("%.3f", win.window.t_end) + " s (" + win.label + ")";
      }
    }
  return where;
}

/// The frequency band a confirmed candidate lowers most (of those > 2x the noise floor), in words.
std::string bandFixed(const Comparison& base, const Comparison& with) {
  double band_drop = 0.0;
  std::string band;
  for (std::size_t i = 0; i < base.series.size() && i < with.series.size(); ++i)
    for (std::size_t b = 0; b < base.series[i].bands.size() && b < with.series[i].bands.size(); ++b) {
      const double before = base.series[i].bands[b].ratio, after = with.series[i].bands[b].ratio;
      if (before - after > band_drop && before > 2.0) {
        band_drop = before - after;
        band = base.series[i].bands[b].band + " band of " + base.series[i].channel + " from " + fmt("%.3g", before) + "x to " +
               fmt("%.3g", after) + "x the noise floor";
      }
    }
  return band;
}

/// The effect's residual signature (Effect::residualSignature) as the base residual shows it, in
/// words ("" if the effect names none or it explains <= 10 % of its map).
std::string signatureSeen(const Comparison& base, const CandidateSpec& candidate) {
  const ResidualSignature& sig = candidate.residual_signature;
  if (sig.state_map.empty()) return "";
  double ef = 0.0;
  std::string txt;
  for (const auto& cm : base.maps)
    for (const auto& m : cm.maps)
      if (m.state.rfind(sig.state_map, 0) == 0)
        for (const auto& f : m.fits)
          if (f.feature == sig.feature && f.explained_fraction > ef) {
            ef = f.explained_fraction;
            txt = cm.channel + " vs " + m.state + " shows a " + f.feature +
                  (f.feature == "knee" ? " beyond " + fmt("%.3g", f.knee_at) : "") + " (" + fmt("%.0f", 100 * ef) + " % of that map)";
          }
  return !txt.empty() && ef > 0.1 ? txt : "";
}

/// One plain sentence per candidate: why it is ranked where it is.
/// `best_score`: the best screening score of the ungated candidates.
std::string whyOf(const Candidate& c, const CandidateSpec& spec, const Comparison& base, const DiagnoseOptions& options,
                  double best_score) {
  if (!c.gate.empty()) return c.effect + ": not a candidate: " + c.gate + ".";
  if (!c.confirmed)
    return c.effect + ": screening score " + fmt("%.3g", c.score) + " (p = " + fmt("%.2g", c.p_value) + ")" +
           (c.p_value < options.screen_alpha
                ? (c.score * options.confirm_within >= best_score
                       ? ", within a factor " + fmt("%.3g", options.confirm_within) + " of the best score but beyond the budget of " +
                             std::to_string(options.candidates) + " confirmations (--candidates)"
                       : ", more than a factor " + fmt("%.3g", options.confirm_within) +
                             " below the best score and not the best of its kind: not confirmed")
                : ": explains nothing beyond noise") +
           ".";
  std::string s = c.effect + ": " + (c.delta_bic < 0 ? "ΔBIC " : "ΔBIC +") + fmt("%.1f", c.delta_bic) + ", explains " +
                  fmt("%.0f", 100 * c.explained) + " % of the excess residual";
  if (c.inert) s += "; its parameters stay at their off values, so it is no cause (the change is the reference's optimum polished further)";
  const std::string where = windowFixed(base, c.fit->comparison);
  if (!where.empty()) s += "; " + where;
  const std::string band = bandFixed(base, c.fit->comparison);
  if (!band.empty()) s += "; lowers the " + band;
  if (!c.finding.empty() && c.delta_bic < 0) s += "; " + c.finding;
  if (!c.fit->full)
    s += c.evidence_gap <= std::max(options.full_within, options.ambiguity_log_evidence)
             ? "; calibrated to its optimum (on top of causes already named the evidence decides; the final model alone is calibrated "
               "in full)"
             : "; calibrated to its optimum only (log evidence " + fmt("%.1f", c.evidence_gap) +
                   " below the best candidate's: it can be neither the verdict nor ambiguous with it, so no intervals)";
  const std::string sig = signatureSeen(base, spec);
  if (!sig.empty()) s += "; its signature is in the data: " + sig;
  if (c.holdout_change) s += "; held-out systematic error x" + fmt("%.2f", *c.holdout_change);
  return s + ".";
}

/// A candidate's finding in words, or its name when it has none (an effect).
std::string inWordsOf(const Candidate& c) { return c.finding.empty() ? inWords(c.effect) + " (" + c.effect + ")" : c.finding + " (" + c.effect + ")"; }

/// What would tell `a` from `b` apart, in words.
std::string separatedBy(const Candidate& a, const Candidate& b) {
  auto timing = [](const Candidate& c) {
    return c.effect.rfind("lowpass", 0) == 0 || c.effect.rfind("delay", 0) == 0;
  };
  if (timing(a) && timing(b))
    return "a step input or the phase above 20 Hz would separate them (a delay shifts the phase in proportion to frequency "
           "and keeps the amplitude; a low-pass lowers the amplitude too)";
  if (a.kind != b.kind)
    return "a scenario that excites one and not the other (another speed, a step, a sweep) would separate them";
  return "more data (another scenario) would separate them";
}

/// The look-alikes of the named candidate `best` (within ambiguity_log_evidence), in words: "The
/// data cannot yet tell it from: the hub_force channels look delayed by 8 ms (delay:hub_force);
/// they differ by ΔBIC 3.1; a step input ... would separate them."
std::string lookAlikes(const Candidate& best, const std::vector<const Candidate*>& alike, const DiagnoseOptions& options) {
  std::string s = "Ambiguous: " + inWordsOf(best);
  for (const Candidate* c : alike) s += " or " + inWordsOf(*c);
  if (alike.size() == 1) {
    s += ": they differ by ΔBIC " + fmt("%.1f", alike.front()->fit->bic - best.fit->bic);
  } else {
    s += ": behind the first by ΔBIC ";
    for (std::size_t i = 0; i < alike.size(); ++i) s += (i ? ", " : "") + fmt("%.1f", alike[i]->fit->bic - best.fit->bic) + " (" + alike[i]->effect + ")";
  }
  s += ", less than " + fmt("%.0f", 2 * options.ambiguity_log_evidence) + "; " + separatedBy(best, *alike.front()) + ".";
  return s;
}

/// Every candidate's why line of the current stage, against its reference comparison `ref`.
void explainStage(Diagnosis& d, const Comparison& ref) {
  auto& cands = d.stage();
  double best_score = 0;
  for (const auto& c : cands)
    if (c.gate.empty()) best_score = std::max(best_score, c.score);
  for (auto& c : cands) {
    const auto& spec = d.spec(c.effect);
    c.why = whyOf(c, spec, ref, d.options, best_score);
    if (!spec.range_note.empty()) c.why.insert(c.why.size() - 1, " (" + spec.range_note + ")");  // before the full stop
  }
}

/// The confirmed candidates with strong evidence (ΔBIC < −bic_strong against the stage's
/// reference), best first.
std::vector<const Candidate*> strongOf(const std::vector<Candidate>& cands, const DiagnoseOptions& options) {
  std::vector<const Candidate*> named;
  for (const auto& c : cands)
    if (c.confirmed && c.delta_bic < -options.bic_strong && !c.inert) named.push_back(&c);
  return named;
}

/// The strong candidates within ambiguity_log_evidence of the first.
std::vector<const Candidate*> alikeOf(const std::vector<const Candidate*>& named, const DiagnoseOptions& options) {
  std::vector<const Candidate*> alike;
  for (std::size_t i = 1; i < named.size(); ++i)
    if (named.front()->fit->log_evidence - named[i]->fit->log_evidence < options.ambiguity_log_evidence) alike.push_back(named[i]);
  return alike;
}

/// The cause a stage names: its best strong candidate, with its look-alikes.
Cause causeOf(const Candidate& c, const std::vector<const Candidate*>& alike) {
  Cause k;
  k.name = c.effect;
  k.kind = c.kind;
  k.finding = c.finding;
  k.delta_bic = c.delta_bic;
  k.explained = c.explained;
  k.fit = *c.fit;
  for (const Candidate* a : alike) k.ambiguous_with.push_back(a->effect);
  return k;
}

/// More than one cause (docs/diagnosis.md, step 4): forward stagewise selection. While the model
/// with the causes named so far leaves a significant lack of fit and fewer than options.causes
/// are named, they are installed, every other candidate is screened and confirmed on top of them
/// (ΔBIC against the model with them), and the best strong one becomes the next cause.
void furtherCauses(Diagnosis& d) {
  auto& res = d.res;
  while (static_cast<int>(res.causes.size()) < d.options.causes && res.causes.back().fit.comparison.lack_of_fit_p < d.options.lack_of_fit_alpha) {
    d.installed.push_back(res.causes.back().name);
    d.reference = &res.causes.back().fit;
    std::vector<std::string> catalogue;
    for (const auto& e : d.catalogue)
      if (std::find(d.installed.begin(), d.installed.end(), e) == d.installed.end()) catalogue.push_back(e);
    d.catalogue = catalogue;
    res.further.push_back({d.installed, {}});
    screen(d);
    refine(d, confirm(d));
    explainStage(d, d.reference->comparison);
    const auto named = strongOf(d.stage(), d.options);
    if (named.empty()) break;
    res.causes.push_back(causeOf(*named.front(), alikeOf(named, d.options)));
  }
  // Every cause's parameters and finding from the model with all of them (a joint calibration),
  // calibrated in full (its intervals; a later stage stops its candidates at their optimum).
  if (!res.causes.back().fit.full) {
    const std::vector<std::string> effects = res.causes.back().fit.effects;
    res.causes.back().fit = d.calibrateWith(effects, "final " + joinEffects(effects) + " in full", {}, {}, true);
  }
  const Figures& all = res.causes.back().fit;
  for (auto& k : res.causes) {
    k.parameters = d.parametersOf(k.name, all);
    k.finding = d.findingOf(k.name, all);
  }
  // The proposal (an unexplained verdict) linearises the base model again.
  d.installed.clear();
  d.reference = nullptr;
  d.base_obj = std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets, d.setupOf({}));
}

/// A cause in one sentence: "Wrong vehicle value: the wheel mass is about 35 kg, not 29.46 kg
/// (free:wheel.mass_kg, ΔBIC −512.3, explains 64 % of the excess residual)".
std::string causeInWords(const Cause& k) {
  const std::string evidence = "ΔBIC " + fmt("%.1f", k.delta_bic) + ", explains " + fmt("%.0f", 100 * k.explained) + " % of the excess residual";
  if (k.kind == "parameter") return "Wrong vehicle value: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "sensor") return "Sensor distortion: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "input") return "Road signal: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "range") return "Far from the prior: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "option") return "Structure: " + k.finding + " (" + k.name + ", " + evidence + ")";
  return "Missing effect: " + k.name + " (" + evidence + ")";
}

/// The summary of a verdict "effect": the cause, or the causes strongest first, and how far the
/// integrator's jitter limits the evidence.
std::string effectSummary(const Diagnosis& d, const Candidate& best, const std::vector<const Candidate*>& alike) {
  const auto& res = d.res;
  const auto& options = d.options;
  const Cause& first = res.causes.front();
  std::string s;
  if (res.causes.size() == 1) {
    s = causeInWords(first) + ".";
  } else {
    double total = 0;
    for (const auto& k : res.causes) total += k.explained;
    s = std::to_string(res.causes.size()) + " causes, each strong against the model with those before it (together " +
        fmt("%.0f", 100 * std::min(1.0, total)) + " % of the excess residual):";
    std::string apply;
    for (std::size_t i = 0; i < res.causes.size(); ++i) {
      s += " " + std::to_string(i + 1) + ". " + causeInWords(res.causes[i]) + ".";
      apply += (i ? "," : "") + res.causes[i].name;
    }
    s += " Apply them together with --apply " + apply + ".";
  }
  // The evidence is a difference of two minimised SSEs, each as uncertain as the integrator's jitter.
  const double jitter = res.base.integrator.jitter + first.fit.integrator.jitter;
  if (!first.fit.integrator.ok || !res.base.integrator.ok)
    s += -first.delta_bic > options.bic_strong + 2 * jitter
             ? " The integrator's jitter in the SSE (" + fmt("%.3g", jitter) + ") is far below this evidence, so the verdict stands, but the intervals do not (note below)."
             : " Caution: the integrator's jitter in the SSE (" + fmt("%.3g", jitter) +
                   ") is comparable with this evidence: tighten [simulation] accuracy and rerun before trusting the verdict (note below).";
  if (!alike.empty()) s += " " + lookAlikes(best, alike, options);
  return s;
}

/// Verdict (step 4): every candidate's why, then "effect" (the best confirmed candidate with
/// ΔBIC < −bic_strong, and the causes stagewise selection adds on top of it, which together leave
/// no significant lack of fit or explain at least explained_min of the excess; ambiguity
/// stated), "none" (no significant lack of fit in the base: nothing to explain, whatever a
/// candidate's ΔBIC) or "unexplained" (with where).
void verdict(Diagnosis& d) {
  auto& res = d.res;
  const auto& options = d.options;
  const Comparison& base = res.base.comparison;
  explainStage(d, base);
  const double alpha = options.lack_of_fit_alpha;
  const bool base_bad = base.lack_of_fit_p < alpha;
  const auto named = strongOf(res.candidates, options);
  res.unexplained_location = locate(base);
  if (named.empty()) {
    if (base_bad) {
      res.verdict = "unexplained";
      res.summary = "Unexplained residual: the base model leaves a significant lack of fit (z = " + fmt("%.1f", base.lack_of_fit_z) +
                    ") that no catalogue effect explains. Where: " + res.unexplained_location + ".";
    } else {
      res.verdict = "none";
      res.summary = "No missing effect found: the residual is consistent with the measurement noise (lack of fit z = " +
                    fmt("%.1f", base.lack_of_fit_z) + ", p = " + fmt("%.2g", base.lack_of_fit_p) +
                    ") and no catalogue effect passes the screening and the evidence test.";
    }
    return;
  }
  if (!base_bad) {
    // The base fits to the noise: there is no excess residual for a cause to explain. A candidate
    // may still lower the BIC by fitting the noise a little better (or a trace the log's own
    // processing leaves, such as its resampling); it is reported, not named.
    std::string best;
    for (std::size_t i = 0; i < named.size() && i < 3; ++i)
      best += (i ? ", " : "") + named[i]->effect + " ΔBIC " + fmt("%.1f", named[i]->delta_bic);
    res.verdict = "none";
    res.summary = "No missing effect found: the residual is consistent with the measurement noise (lack of fit z = " +
                  fmt("%.1f", base.lack_of_fit_z) + ", p = " + fmt("%.2g", base.lack_of_fit_p) + "). Candidates that fit it slightly better (" +
                  best + ") have no excess residual to explain and are not named; --apply adds one to see what it changes.";
    return;
  }
  const auto alike = alikeOf(named, options);
  res.causes.push_back(causeOf(*named.front(), alike));
  const auto catalogue = d.catalogue;
  furtherCauses(d);
  // Another structure (a subsystem option) is not nested in the forces found on the first cause's
  // model: a car whose road enters at the hub and whose struts carry a controller may fit worse
  // with the hub input alone than with a tire and a delay, and better with both changes. So each
  // strong option that the chain did not take is weighed at its best: the stagewise selection is
  // run again from it, and the chain whose final model has the lower BIC is the verdict.
  const Candidate* lead = named.front();
  for (const Candidate* o : named) {
    if (o->kind != "option" || o == named.front()) continue;
    if (std::any_of(res.causes.begin(), res.causes.end(), [&](const Cause& k) { return k.name == o->effect; })) continue;
    auto chain = std::move(res.causes);
    auto stages = std::move(res.further);
    res.causes = {causeOf(*o, {})};
    res.further.clear();
    d.catalogue = catalogue;
    furtherCauses(d);
    const double bic_chain = chain.back().fit.bic, bic_alt = res.causes.back().fit.bic;
    auto words = [](const std::vector<Cause>& c) {
      std::string w;
      for (const auto& k : c) w += (w.empty() ? "" : " + ") + k.name;
      return w;
    };
    const std::string weighed = "The structure " + o->effect + " was weighed at its best: " + words(res.causes) + " reaches BIC " +
                                fmt("%.1f", bic_alt) + ", " + words(chain) + " BIC " + fmt("%.1f", bic_chain);
    if (bic_alt < bic_chain) {
      res.structure_note = weighed + ": the first is kept.";
      lead = o;
    } else {
      res.structure_note = weighed + ": the second is kept.";
      res.causes = std::move(chain);
      res.further = std::move(stages);
    }
  }
  d.catalogue = catalogue;
  const Cause& last = res.causes.back();
  double total = 0;
  for (const auto& k : res.causes) total += k.explained;
  const bool after_bad = last.fit.comparison.lack_of_fit_p < alpha;
  if (after_bad && total < options.explained_min) {
    res.verdict = "unexplained";
    res.unexplained_location = locate(last.fit.comparison);
    std::string names;
    for (std::size_t i = 0; i < res.causes.size(); ++i)
      names += (i ? (i + 1 == res.causes.size() ? " and " : ", ") : "") + res.causes[i].name;
    res.summary = std::string("Unexplained residual: the best catalogue ") + (res.causes.size() == 1 ? "effect, " : "causes, ") + names +
                  ", explain" + (res.causes.size() == 1 ? "s" : "") + " only " + fmt("%.0f", 100 * total) +
                  " % of the excess residual and a significant lack of fit remains (z = " + fmt("%.1f", last.fit.comparison.lack_of_fit_z) + "); " +
                  (res.causes.size() == 1 ? "it is" : "they are") + " not named. Where: " + res.unexplained_location + ".";
    return;
  }
  res.verdict = "effect";
  const Cause& first = res.causes.front();
  res.named_effect = first.name;
  res.named_kind = first.kind;
  res.finding = first.finding;
  res.ambiguous_with = first.ambiguous_with;
  res.summary = lead == named.front() ? effectSummary(d, *lead, alike) : effectSummary(d, *lead, {});
  if (!res.structure_note.empty()) res.summary += " " + res.structure_note;
  if (after_bad)
    res.summary += " A smaller significant residual remains (z = " + fmt("%.1f", last.fit.comparison.lack_of_fit_z) + "): " + locate(last.fit.comparison) + ".";
}

// ------------------------------------------------------------------ propose

/// Propose (verdict "unexplained"; docs/diagnosis.md): every library term (proposal.hpp) simulated
/// as a small strut force at θ̂ (its peak 200 N over the base run's states), its contribution
/// projected off span(J), and the best subset of at most options.propose_terms terms by BIC. A
/// subset is proposed only when it beats the empty model by more than bic_strong.
void propose(Diagnosis& d) {
  auto& res = d.res;
  const Linearisation lin = linearise(d);
  double q_comp = 0, q_reb = 0;
  const auto traces = d.base_obj->traces(lin.theta_hat);
  for (const auto& t : traces)
    for (const char* c : {"fl", "fr", "rl", "rr"})
      for (double q : t.column(std::string("susp_defl_") + c + "_m")) {
        q_comp = std::max(q_comp, q);
        q_reb = std::max(q_reb, -q);
      }
  const auto library = termLibrary(q_comp, q_reb);
  std::vector<double> amplitude(library.size(), 0.0);
  for (std::size_t j = 0; j < library.size(); ++j) {
    double peak = 0;
    const char* corners[] = {"fl", "fr", "rl", "rr"};
    for (const auto& t : traces)
      for (int c = 0; c < 4; ++c) {
        const auto& q = t.column(std::string("susp_defl_") + corners[c] + "_m");
        const auto& v = t.column(std::string("susp_rate_") + corners[c] + "_mps");
        const auto& qo = t.column(std::string("susp_defl_") + corners[c ^ 1] + "_m");  // the other side of the axle
        const auto& vo = t.column(std::string("susp_rate_") + corners[c ^ 1] + "_mps");
        for (std::size_t i = 0; i < q.size(); ++i)
          peak = std::max(peak, std::abs(library[j].f({q[i], v[i], q[i] - qo[i], v[i] - vo[i]})));
      }
    if (peak > 0) amplitude[j] = 200.0 / peak;
  }
  std::vector<std::unique_ptr<calib::LabObjective>> objs(library.size());
  for (std::size_t j = 0; j < library.size(); ++j) {
    if (amplitude[j] == 0) continue;
    calib::CalibrationSetup setup;
    setup.channel_weights = d.weights;
    EffectSetting es;
    es.name = kTermPrefix + library[j].expr;
    setup.extra_effects.push_back(es);
    CalibratedParameter a;
    a.name = es.name + ".a";
    a.unit = library[j].unit;
    a.lower = -1e12;
    a.upper = 1e12;
    setup.extra_calibrated.push_back(a);
    objs[j] = std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets, setup);
  }
  std::vector<std::vector<double>> eta(library.size());
  d.report("propose: library terms", 0, library.size());
  parallelFor(library.size(), d.options.threads, [&](std::size_t j, int) {
    if (!objs[j]) return;
    auto th = lin.theta_hat;
    th.push_back(amplitude[j]);
    eta[j] = objs[j]->predict(th);
  });
  d.report("propose: library terms", library.size(), library.size());
  const auto& w = d.base_obj->weights();
  const long n = lin.r.size();
  std::vector<std::size_t> used;
  for (std::size_t j = 0; j < library.size(); ++j)
    if (!eta[j].empty()) used.push_back(j);
  Eigen::MatrixXd G(n, static_cast<long>(used.size()));
  for (std::size_t k = 0; k < used.size(); ++k)
    for (long i = 0; i < n; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      G(i, static_cast<long>(k)) = std::sqrt(w[ii]) * (eta[used[k]][ii] - lin.eta_hat[ii]) / amplitude[used[k]];
    }
  Eigen::MatrixXd Gp = lin.project(G);
  std::vector<double> norm(used.size(), 0.0);
  for (std::size_t k = 0; k < used.size(); ++k) {
    norm[k] = Gp.col(static_cast<long>(k)).norm();
    if (norm[k] > 0) Gp.col(static_cast<long>(k)) /= norm[k];
  }
  const auto fit = bestSubsetByBic(Gp, lin.r, d.options.propose_terms);
  const double gain = fit.bic_empty - fit.bic;
  const std::string lib_words = std::to_string(used.size()) + " strut-force terms";
  if (fit.chosen.empty() || gain <= d.options.bic_strong) {
    res.proposal_note = "No proposal: no subset of the " + lib_words + " explains the residual (best BIC gain " + fmt("%.1f", gain) + ").";
    return;
  }
  const double excess = std::max(fit.sse_empty - static_cast<double>(n - static_cast<long>(lin.theta_hat.size())), 1e-12);
  const double ln_n = std::log(static_cast<double>(n));
  for (std::size_t i = 0; i < fit.chosen.size(); ++i) {
    const std::size_t k = fit.chosen[i], j = used[k];
    ProposedTerm t;
    t.force = "a * (" + (library[j].gap > 0 ? library[j].g_expr : library[j].expr) + ")";
    t.unit = library[j].unit;
    t.gap = library[j].gap;
    t.coefficient = fit.coef[i] / norm[k];
    t.delta_bic = -(fit.drop_sse[i] - fit.sse - ln_n);
    t.explained = std::clamp((fit.drop_sse[i] - fit.sse) / excess, 0.0, 1.0);
    res.proposal.push_back(t);
  }
  std::sort(res.proposal.begin(), res.proposal.end(), [](const ProposedTerm& a, const ProposedTerm& b) { return a.delta_bic < b.delta_bic; });
  // A term the subset keeps for a small BIC gain (between ln n and bic_strong) is not worth a
  // user's effect: only the strongly supported ones are proposed.
  const auto weak = std::find_if(res.proposal.begin(), res.proposal.end(),
                                 [&](const ProposedTerm& t) { return t.delta_bic >= -d.options.bic_strong; });
  const std::size_t dropped = static_cast<std::size_t>(res.proposal.end() - weak);
  res.proposal.erase(weak, res.proposal.end());
  if (res.proposal.empty()) {
    res.proposal_note = "No proposal: no term of the " + lib_words + " explains the residual strongly (ΔBIC below −" +
                        fmt("%.0f", d.options.bic_strong) + ").";
    return;
  }
  for (std::size_t i = 0; i < res.proposal.size(); ++i) res.proposal[i].name = "proposed_" + std::to_string(i + 1);
  double kept_share = 0;
  for (const auto& t : res.proposal) kept_share += t.explained;
  res.proposal_note = "A sparse regression of the residual on " + lib_words + " (best subset by BIC, linearised at the base optimum) proposes " +
                      std::to_string(res.proposal.size()) + " term" + (res.proposal.size() > 1 ? "s" : "") + " (ΔBIC " +
                      fmt("%.1f", res.proposal.front().delta_bic) + " for the first; together about " +
                      fmt("%.0f", 100 * std::min(1.0, kept_share)) + " % of the excess residual" +
                      (dropped ? "; " + std::to_string(dropped) + " weaker term" + (dropped > 1 ? "s" : "") + " with ΔBIC above −" +
                                     fmt("%.0f", d.options.bic_strong) + " left out"
                               : std::string()) +
                      "): paste it into the study file, or pass proposal.toml to --apply, and apply it.";
  res.summary += " " + res.proposal_note;
}

// ------------------------------------------------------------------ apply

/// Apply (step 5): options.apply's effects added in turn, each model re-calibrated (a lone effect
/// confirmed above is reused); res.steps = base, + e1, + e1 + e2, ...
void apply(Diagnosis& d) {
  const auto& effects = d.options.apply;
  if (effects.empty()) return;
  auto& res = d.res;
  res.steps.push_back(res.base);
  std::vector<std::string> acc;
  for (const auto& effect : effects) {
    acc.push_back(effect);
    std::vector<double> start, theta;
    const Figures* confirmed = nullptr;  // a calibration with exactly these effects, in full, already made
    auto look = [&](const std::vector<Candidate>& cands) {
      for (const auto& c : cands)
        if (c.fit && c.fit->full && c.fit->effects == acc) confirmed = &*c.fit;
    };
    look(res.candidates);
    for (const auto& st : res.further) look(st.candidates);
    for (const auto& c : res.candidates)
      if (c.effect == effect) {
        start = c.screening_estimate;
        theta = c.screening_theta;
      }
    res.steps.push_back(confirmed ? *confirmed : d.calibrateWith(acc, "apply " + joinEffects(acc), start, theta));
  }
}

}  // namespace

std::vector<StageWork> estimateDiagnoseWork(const Study& study, const AssemblySpec& assembly, const std::vector<calib::DataSet>& fit,
                                            const std::vector<calib::DataSet>& holdout, const DiagnoseOptions& options) {
  double fit_span = 0, hold_span = 0, fit_records = 0;
  for (const auto& s : fit) {
    fit_span += dataSpan(s.data);
    fit_records += static_cast<double>(s.data.records.size());
  }
  for (const auto& s : holdout) hold_span += dataSpan(s.data);
  const auto& c = options.calibration;
  const auto design = c.designOptions();
  const double design_points = design.first_points + (design.adaptive ? static_cast<double>(design.max_rounds) * design.round_points : 0.0);
  const double base_params = static_cast<double>(study.calibrated.size());
  // Screening: a linearisation (two runs per parameter) and every probe column of every effect.
  // ... and, when the verdict is unexplained, a proposal: a linearisation and every library term.
  double catalogue_probes = 0, most_effect_params = 0;
  std::vector<std::string> channels;
  for (const auto& s : fit)
    for (const auto& ch : s.data.channels())
      if (std::find(channels.begin(), channels.end(), ch) == channels.end()) channels.push_back(ch);
  std::map<std::string, CandidateSpec> specs;
  for (const auto& e : catalogueOf(study, assembly, options, channels, specs, measuredRoad(study, fit))) {
    const auto groups = probesOf(0, specs.at(e));
    for (const auto& g : groups) catalogue_probes += static_cast<double>(g.cols.size());
    most_effect_params = std::max(most_effect_params, static_cast<double>(specs.at(e).parameters.size()));
  }
  const double probe_runs =
      2 * base_params + catalogue_probes +
      (options.propose_terms > 0 ? 2 * base_params + static_cast<double>(termLibrary(1, 1).size()) : 0.0);
  double applied_params = 0;
  for (const auto& e : options.apply) applied_params += static_cast<double>(specs.at(e).parameters.size());
  const double starts = static_cast<double>(c.optimizer_starts) + 2;  // the screening's and the nested optimum's starts
  auto calibration = [&](const std::string& stage, double count, double params) {
    const double sims = count * calibrationSimulations(design_points, starts, params);
    return StageWork{stage, sims, sims * fit_span,
                     8.0 * static_cast<double>(c.gibbs_iterations) * (params + 2) + 8.0 * design_points * fit_records};
  };
  std::vector<StageWork> out;
  out.push_back(calibration("diagnose base", 2, base_params));  // the base and its refinement
  out.push_back({"diagnose screening", probe_runs, probe_runs * fit_span, 8.0 * probe_runs * fit_records});
  out.push_back(calibration("diagnose confirm", options.candidates, base_params + most_effect_params));
  out.push_back(calibration("diagnose apply", static_cast<double>(options.apply.size()), base_params + applied_params));
  // Forward stagewise: at most causes − 1 further stages, each a screening (a linearisation with
  // the causes before it, and every probe) and a confirmation on top of them.
  const double further = static_cast<double>(options.causes - 1);
  auto more = calibration("diagnose further causes", further * options.candidates, base_params + static_cast<double>(options.causes) * most_effect_params);
  const double further_probes = further * (2 * (base_params + further * most_effect_params) + catalogue_probes);
  more.simulations += further_probes;
  more.simulated_s += further_probes * fit_span;
  out.push_back(more);
  const double models = 2 + options.candidates * static_cast<double>(options.causes) + static_cast<double>(options.apply.size());
  const double runs = models * (options.compare_draws + 1);
  out.push_back({"diagnose compare", runs, runs * (fit_span + hold_span), 8.0 * (options.compare_draws + 1) * fit_records});
  return out;
}

DiagnosisResult diagnose(const Study& study, const AssemblySpec& assembly, const std::vector<calib::DataSet>& fit,
                         const std::vector<calib::DataSet>& holdout, const DiagnoseOptions& options,
                         const std::string& out_dir, const DiagnoseProgress& progress) {
  options.validate();
  for (const char* field : {"effects", "apply"})  // an effect's name, before the data are read
    for (const auto& e : std::string(field) == "effects" ? options.effects : options.apply)
      if (e.find(':') == std::string::npos && e.find('=') == std::string::npos)
        (void)study.effectCatalog().make(e, OptionCheck("diagnose").where(field));
  if (fit.empty()) throw InputError(OptionCheck("diagnose").where("fit"), "needs at least one measurement data set");
  Diagnosis d(study, assembly, options, out_dir, progress);
  d.res.assembly = assembly.id;
  refuseInstalled(study, assembly, options);  // before the data are read
  prepareData(d, fit, holdout);
  d.catalogue = catalogueOf(study, assembly, options, d.res.fitted_channels, d.specs, measuredRoad(study, fit));
  d.res.base = d.calibrateWith({}, "base");
  addRangeCandidates(d);
  screen(d);
  const auto confirmed = confirm(d);
  refine(d, confirmed);
  verdict(d);
  if (d.res.verdict == "unexplained" && options.propose_terms > 0) propose(d);
  apply(d);
  return std::move(d.res);
}

namespace {
/// The "screening" (every candidate) and "ranked" (the confirmed ones) arrays of one stage into
/// `j`; `ref_log_evidence`: the stage's reference model's.
void candidatesJson(const std::vector<Candidate>& candidates, double ref_log_evidence, nlohmann::json& j) {
  j["ranked"] = nlohmann::json::array();
  j["screening"] = nlohmann::json::array();
  for (const auto& c : candidates) {
    nlohmann::json s{{"effect", c.effect},     {"kind", c.kind},           {"score", c.score},         {"score_dof", c.score_dof}, {"p_value", c.p_value},
                     {"max_signal", c.max_signal}, {"gate", c.gate},       {"confirmed", c.confirmed}, {"why", c.why},
                     {"signature", c.signature}};
    j["screening"].push_back(s);
    if (!c.confirmed) continue;
    nlohmann::json r{{"effect", c.effect},
                     {"log_evidence", c.fit->log_evidence},
                     {"log_evidence_vs_base", c.fit->log_evidence - ref_log_evidence},
                     {"delta_bic", c.delta_bic},
                     {"explained_fraction", c.explained},
                     {"kind", c.kind},
                     {"finding", c.finding},
                     {"parameters", paramsJson(c.fit->effect_parameters)},
                     {"why", c.why},
                     {"fit", c.fit->toJson()}};
    if (c.holdout_change) r["holdout_systematic_rms_ratio"] = *c.holdout_change;
    j["ranked"].push_back(r);
  }
}
}  // namespace

nlohmann::json DiagnosisResult::toJson() const {
  nlohmann::json j;
  j["assembly"] = assembly;
  j["verdict"] = verdict;
  j["summary"] = summary;
  if (!named_effect.empty()) {
    j["effect"] = named_effect;
    j["kind"] = named_kind;
    j["finding"] = finding;
  }
  j["ambiguous_with"] = ambiguous_with;
  if (!structure_note.empty()) j["structure_note"] = structure_note;
  if (verdict != "none") j["unexplained_location"] = unexplained_location;
  j["fitted_channels"] = fitted_channels;
  j["left_out_channels"] = left_out_channels;
  j["base"] = base.toJson();
  if (!base_refined_from.empty())
    j["base_refined"] = {{"from", base_refined_from}, {"sse_min_weighted_before", base_unrefined_sse}};
  candidatesJson(candidates, base.log_evidence, j);
  j["causes"] = nlohmann::json::array();
  for (const auto& k : causes) {
    nlohmann::json c{{"name", k.name},           {"kind", k.kind},
                     {"finding", k.finding},     {"delta_bic", k.delta_bic},
                     {"explained_fraction", k.explained}, {"lack_of_fit_z_after", k.fit.comparison.lack_of_fit_z},
                     {"parameters", paramsJson(k.parameters)}, {"ambiguous_with", k.ambiguous_with},
                     {"folder", k.fit.folder}};
    j["causes"].push_back(c);
  }
  j["further_stages"] = nlohmann::json::array();
  for (const auto& st : further) {
    nlohmann::json f{{"installed", st.installed}};
    // The stage's reference: the model with its installed causes.
    double ref = base.log_evidence;
    for (const auto& k : causes)
      if (k.fit.effects == st.installed) ref = k.fit.log_evidence;
    candidatesJson(st.candidates, ref, f);
    j["further_stages"].push_back(f);
  }
  j["evidence_estimator"] =
      "BIC = SSE_w,min + k ln n with SSE_w = sum of (y - eta)^2 / sigma_c^2 (sigma_c^2 from the repetitions); log evidence ~ -BIC/2";
  if (!proposal.empty() || !proposal_note.empty()) {
    j["proposal"] = {{"note", proposal_note}, {"terms", nlohmann::json::array()}};
    for (const auto& t : proposal) j["proposal"]["terms"].push_back(t.toJson());
  }
  if (!steps.empty()) {
    j["before"] = steps.front().toJson();
    j["after"] = steps.back().toJson();
    j["steps"] = nlohmann::json::array();
    for (const auto& s : steps) j["steps"].push_back(s.toJson());
  }
  return j;
}

std::string DiagnosisResult::proposalToml() const {
  std::string s;
  for (const auto& t : proposal) s += (s.empty() ? "" : "\n") + t.toml();
  return s;
}

std::string DiagnosisResult::text() const {
  std::string s;
  s += "Diagnosis of " + assembly + ": " + verdict + "\n  " + summary + "\n\n";
  if (!base_refined_from.empty())
    s += "  (The base optimum was improved from " + base_refined_from + "'s fit with the effect off: weighted SSE " +
         fmt("%.1f", base_unrefined_sse) + " -> " + fmt("%.1f", base.sse_min) + "; every ΔBIC is against the improved base.)\n\n";
  if (!base.bounds.empty()) {
    s += "Values on their bounds (the base calibration; docs/calibration.md):\n" + calib::boundFindingsText(base.bounds, "  ") + "\n";
  }
  s += "Ranked candidates (confirmed by re-calibration first):\n";
  int k = 0;
  for (const auto& c : candidates) s += "  " + std::to_string(++k) + ". " + c.why + "\n";
  for (const auto& st : further) {
    s += "\nOn top of " + joinEffects(st.installed) + " (ΔBIC against the model with it):\n";
    k = 0;
    for (const auto& c : st.candidates)
      if (c.confirmed || c.gate.empty()) s += "  " + std::to_string(++k) + ". " + c.why + "\n";
  }
  if (causes.size() > 1) {
    s += "\nCauses (forward stagewise, strongest first; parameters from the joint fit " + causes.back().fit.folder + "):\n";
    for (const auto& c : causes) {
      s += "  " + c.name + ": explains " + fmt("%.0f", 100 * c.explained) + " % of the excess residual (ΔBIC " + fmt("%.1f", c.delta_bic) +
           "; lack of fit z " + fmt("%.1f", c.fit.comparison.lack_of_fit_z) + " after it)\n";
      for (const auto& p : c.parameters)
        s += "    " + p.name + ": optimum " + fmt("%.4g", p.optimum) + " " + p.unit +
             (p.interval == "none" ? std::string() : "  (95 % " + p.interval + " [" + fmt("%.4g", p.q025) + ", " + fmt("%.4g", p.q975) + "])") + "\n";
    }
  }
  if (!causes.empty() && causes.back().fit.full && !causes.back().fit.values.empty()) {
    const Figures& all = causes.back().fit;
    s += "\nThe model with " + (causes.size() > 1 ? std::string("every cause") : "the cause") + " (" + joinEffects(all.effects) +
         "), its calibrated values:\n";
    for (const auto& p : all.values)
      s += "  " + p.name + ": optimum " + fmt("%.5g", p.optimum) + " " + p.unit + "  (95 % " + p.interval + " [" + fmt("%.5g", p.q025) +
           ", " + fmt("%.5g", p.q975) + "])\n";
    if (!all.left_out.empty()) {
      s += "  (left out, this model has no such value:";
      for (const auto& n : all.left_out) s += " " + n;
      s += ")\n";
    }
    if (!all.bounds.empty()) s += calib::boundFindingsText(all.bounds, "  ");
  }
  for (const auto& c : candidates)
    if (c.confirmed && c.fit->full && !c.fit->effect_parameters.empty()) {
      bool named = false;
      for (const auto& k : causes) named = named || k.name == c.effect;
      s += "\n  " + c.effect + " posterior" + (named || causes.empty() ? "" : " (calibrated in full; not among the causes)") + ":\n";
      const bool resolved = c.fit->importance_ess >= Figures::kResolvedEss;
      for (const auto& p : c.fit->effect_parameters) {
        // An unresolved design (a posterior on a handful of points) gives a mean and an sd that
        // mean nothing: the optimum is printed instead, with the profile interval.
        s += "    " + p.name + (resolved ? " = " + fmt("%.4g", p.mean) + " ± " + fmt("%.2g", p.sd) : ": optimum " + fmt("%.4g", p.optimum)) +
             " " + p.unit + "  (95 % " + (p.interval == "profile" ? "profile likelihood" : "posterior") + " [" + fmt("%.4g", p.q025) + ", " +
             fmt("%.4g", p.q975) + "])" + (c.fit->integrator.ok ? "" : "  NOT TO BE TRUSTED: the integrator limits it (note below)") +
             (resolved || p.interval == "profile" ? "" : "  NOT TO BE TRUSTED: the posterior is not resolved") + "\n";
      }
      if (!resolved)
        s += "    (the posterior is not resolved: importance ESS " + fmt("%.1f", c.fit->importance_ess) + " < " +
             fmt("%.0f", Figures::kResolvedEss) + ", so no mean ± sd; raise --lhs-points, or [calibration] round_points or max_rounds in the study; see " + c.fit->folder +
             "/summary.json)\n";
    }
  // Every calibration whose integrator check failed (the base, the confirmed candidates, the steps).
  std::vector<const Figures*> fits{&base};
  for (const auto& c : candidates)
    if (c.fit) fits.push_back(&*c.fit);
  for (const auto& st : steps) fits.push_back(&st);
  std::set<std::string> noted;
  for (const auto* f : fits)
    if (!f->integrator.ok && noted.insert(f->folder).second)
      s += "\n  note (" + f->label + ", " + f->folder + "): " + f->integrator.message + "\n";
  if (!proposal.empty()) {
    s += "\nProposed terms (strut force a * TERM at every strut; ready to paste into the study file):\n";
    for (const auto& t : proposal)
      s += "  " + t.name + ": " + t.force + ", a ≈ " + fmt("%.3g", t.coefficient) + " " + t.unit +
           (t.gap > 0 ? ", g = " + fmt("%.3g", t.gap) + " m" : "") + ", ΔBIC " + fmt("%.1f", t.delta_bic) +
           ", explains " + fmt("%.0f", 100 * t.explained) + " % of the excess residual\n";
    s += "\n" + proposalToml();
  }
  if (!left_out_channels.empty()) {
    s += "\n  Compared but not fitted: ";
    for (std::size_t i = 0; i < left_out_channels.size(); ++i) s += (i ? "; " : "") + left_out_channels[i];
    s += "\n";
  }
  if (!steps.empty()) {
    s += "\nBefore/after (effects added in turn):\n";
    s += formatPrintf("  %-40s %12s %12s %10s %12s\n", "model", "syst. RMS/σ", "coverage", "log evid.", "Δ log evid.");
    for (const auto& st : steps) {
      double cov = 0.0;
      for (const auto& x : st.comparison.series) cov += x.coverage / static_cast<double>(st.comparison.series.size());
      s += formatPrintf("  %-40s %12.3f %11.1f%% %10.1f %12.1f\n", st.label.c_str(), st.comparison.systematic_rms_sd, 100 * cov,
                        st.log_evidence, st.log_evidence - steps.front().log_evidence);
    }
    s += "\n  Per channel (RMS, NRMSE):\n";
    for (std::size_t i = 0; i < steps.front().comparison.series.size(); ++i) {
      const auto& f = steps.front().comparison.series[i];
      std::string line = "    " + f.scenario + " " + f.channel + ":";
      for (const auto& st : steps)
        if (i < st.comparison.series.size())
          line += "  " + fmt("%.4g", st.comparison.series[i].rms) + " (" + fmt("%.3f", st.comparison.series[i].nrmse) + ")";
      s += line + "\n";
    }
  }
  return s;
}

}  // namespace dtwin::diag
