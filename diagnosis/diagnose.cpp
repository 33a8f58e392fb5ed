// diagnose(): its options, inputs (the catalogue, the fitted data), the calibrations a diagnosis
// makes (Diagnosis::calibrateWith), its work estimate and the stages in order; the helpers they
// share.
#include "diagnosis/diagnose.hpp"
#include "diagnosis/diagnose_internal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>

#include <Eigen/Dense>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/parallel.hpp"
#include "common/validate.hpp"
#include "diagnosis/candidates.hpp"
#include "io/provenance.hpp"
#include "subsystems/effect.hpp"

namespace fs = std::filesystem;

namespace dtwin::diag {

std::string fmt(const char* f, double v) { return formatPrintf(f, v); }

std::string joinEffects(const std::vector<std::string>& e) {
  if (e.empty()) return "base";
  std::string s;
  for (std::size_t i = 0; i < e.size(); ++i) s += (i ? "+" : "") + e[i];
  return s;
}

/// An effect's name in words with its article: "bump_stop" -> "a bump stop"; at one corner,
/// "bump_stop@rr" -> "a bump stop at the rear-right corner".
std::string inWords(const std::string& effect) {
  static const char* const corners[] = {"front-left", "front-right", "rear-left", "rear-right"};
  const auto at = effect.find('@');
  std::string w = effect.substr(0, at);
  std::replace(w.begin(), w.end(), '_', ' ');
  std::string out =
      (std::string("aeiou").find(w.empty() ? 'x' : w[0]) == std::string::npos ? "a " : "an ") + w;
  if (at != std::string::npos)
    for (int c = 0; c < 4; ++c)
      if (effect.substr(at + 1) == kEffectCorners[c])
        out += std::string(" at the ") + corners[c] + " corner";
  return out;
}

nlohmann::json paramsJson(const std::vector<EffectParameter>& ps) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& p : ps)
    j[p.name] = {{"unit", p.unit},
                 {"mean", p.mean},
                 {"sd", p.sd},
                 {"ci95", {p.q025, p.q975}},
                 {"interval", p.interval},
                 {"credible95", {p.post_q025, p.post_q975}},
                 {"optimum", p.optimum}};
  return j;
}

calib::CalibrationSetup candidatesSetup(const std::vector<CandidateSpec>& candidates,
                                        const std::map<std::string, double>& weights) {
  calib::CalibrationSetup s;
  s.channel_weights = weights;
  for (const auto& c : candidates) c.install(s);
  return s;
}

nlohmann::json Figures::toJson() const {
  nlohmann::json j{{"label", label},  {"effects", effects},           {"sse_min_weighted", sse_min},
                   {"bic", bic},      {"log_evidence", log_evidence}, {"parameters", parameters},
                   {"folder", folder}};
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
    nlohmann::json e{{"data_set", s.data_set},   {"scenario", s.scenario},
                     {"channel", s.channel},     {"rms", s.rms},
                     {"nrmse", s.nrmse},         {"max_abs_error", s.max_abs},
                     {"coverage95", s.coverage}, {"systematic_rms", s.systematic_rms}};
    for (const auto& b : s.bands) e["band_power_ratio"][b.band] = b.ratio;
    j["series"].push_back(e);
  }
  if (holdout)
    j["holdout"] = {{"systematic_rms_noise_sd", holdout->systematic_rms_sd},
                    {"lack_of_fit_z", holdout->lack_of_fit_z}};
  return j;
}

void DiagnoseOptions::validate() const {
  const OptionCheck check("diagnose");
  calibration.validate();
  check.atLeast("candidates", candidates, 0);
  check.require(confirm_within >= 1.0, "confirm_within",
                "must be >= 1 (a factor of the best screening score)");
  check.atLeast("confirm_rounds", confirm_rounds, 1);
  check.atLeast("causes", causes, 1);
  check.open01("screen_alpha", screen_alpha);
  check.nonNegative("bic_strong", bic_strong);
  check.nonNegative("ambiguity_log_evidence", ambiguity_log_evidence);
  check.require(full_within >= 0, "full_within",
                "must be >= 0 (infinity: every confirmed candidate calibrated in full)");
  check.inRange("explained_min", explained_min, 0.0, 1.0);
  check.open01("lack_of_fit_alpha", lack_of_fit_alpha);
  check.atLeast("compare_draws", compare_draws, 1);
  check.atLeast("threads", threads, 0);
  check.inRange("propose_terms", propose_terms, 0, 3);
  for (const char* field : {"effects", "apply"}) {
    const auto& names = std::string(field) == "effects" ? effects : apply;
    std::set<std::string> seen;
    for (const auto& e : names) {
      // The form only: an effect's name is checked against the study's catalogue (diagnose(),
      // naming the nearest and every known effect), a freed value or a sensor model against the
      // study and the data (catalogueOf).
      check.require(hasCandidateForm(e), field,
                    "'" + e +
                        "' is not a candidate: an effect, free:<vehicle value>, widen:<calibrated "
                        "value>, <subsystem>=<option> or "
                        "<lowpass|lowpass2|gain|delay>:<channel group>");
      check.require(seen.insert(e).second, field, "names '" + e + "' twice");
    }
  }
}

/// The off values of the diagnosed parameters of a candidate, in order.
std::vector<double> offValues(const CandidateSpec& c) {
  std::vector<double> v;
  for (const auto& p : c.parameters) v.push_back(p.default_value);
  return v;
}

std::vector<std::vector<double>> Diagnosis::extraStarts(
    const std::vector<std::string>& effects, const std::vector<double>& effect_start,
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
  // Every start by name: the nested model's values, then the last candidate's own, the others
  // (none, unless a value the nested model lacks) at the middle of their range. The model with
  // `effects` may lack values of either (an option such as tire=hub leaves out the tire's, and a
  // tire's factor on top of it), so no start is the nested optimum with values appended.
  const calib::LabObjective target(study, assembly, fit_sets, setupOf(effects));
  const auto& from = optima_names.at(joinEffects(nested));
  auto byName = [&](const std::vector<double>& nested_values, const std::vector<double>& own) {
    std::vector<double> x;
    for (std::size_t k = 0; k < target.names().size(); ++k) {
      const std::string& n = target.names()[k];
      const auto at = std::find(from.begin(), from.end(), n);
      const auto mine = std::find(last.calibrated_names.begin(), last.calibrated_names.end(), n);
      const auto i = static_cast<std::size_t>(mine - last.calibrated_names.begin());
      x.push_back(at != from.end() ? nested_values[static_cast<std::size_t>(at - from.begin())]
                  : mine != last.calibrated_names.end() && i < own.size()
                      ? own[i]
                      : 0.5 * (target.lower()[k] + target.upper()[k]));
    }
    return x;
  };
  if (!last.addsParameters()) {
    // A widened range or another option: the nested optimum's values, and the screening's
    // estimate of the widened model.
    const auto x = byName(it->second, {});
    starts.push_back(x);
    if (theta_start.size() == x.size()) starts.push_back(theta_start);
    return starts;
  }
  starts.push_back(byName(it->second, offValues(last)));
  if (effect_start.empty()) return starts;
  starts.push_back(byName(it->second, effect_start));
  if (theta_start.size() == it->second.size())  // the screening's θ̂ + δθ of the nested model
    starts.push_back(byName(theta_start, effect_start));
  return starts;
}

Figures Diagnosis::calibrateWith(const std::vector<std::string>& effects, const std::string& stage,
                                 const std::vector<double>& effect_start,
                                 const std::vector<double>& theta_start, bool full) {
  Figures f;
  f.effects = effects;
  f.label = effects.empty() ? "base" : "+ " + joinEffects(effects);
  // A base started from a better point than its own optimum (see refine) has its own folder.
  f.folder = (fs::path(out_dir) / "calibrations" /
              (joinEffects(effects) + (effects.empty() && !theta_start.empty() ? ".refined" : "")))
                 .string();
  const auto setup = setupOf(effects);
  auto copt = options.calibration;
  copt.threads = options.threads;
  copt.processes = options.processes;
  copt.command = options.command;
  copt.polish_step = 0.01;
  const auto known = starts_of.find(f.folder);
  const auto& starts =
      known != starts_of.end()
          ? known->second
          : (starts_of[f.folder] = extraStarts(effects, effect_start, theta_start));
  copt.extra_starts.insert(copt.extra_starts.end(), starts.begin(), starts.end());
  const auto progress_of = [&](const std::string& s, std::size_t d, std::size_t t) {
    report(stage + ": " + s, d, t);
  };
  const auto r = full ? calib::calibrateAssembly(study, assembly, fit_sets, setup, copt, f.folder,
                                                 data_hash, progress_of)
                      : calib::calibrateOptimum(study, assembly, fit_sets, setup, copt, f.folder,
                                                data_hash, progress_of);
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
  // By name: a model may lack some of them (left out, Model::lacksOptionParameter).
  for (std::size_t k = 0; k < r.names.size(); ++k) {
    const bool own =
        setup.bounds.count(r.names[k]) ||
        std::any_of(setup.extra_calibrated.begin(), setup.extra_calibrated.end(),
                    [&](const CalibratedParameter& c) { return c.name == r.names[k]; });
    EffectParameter ep;
    ep.name = r.names[k];
    ep.unit = k < r.units.size() ? r.units[k] : "";
    ep.optimum = r.optimum.theta[k];
    if (!full) {  // the optimum alone: no posterior, no interval
      ep.mean = ep.optimum;
      ep.sd = ep.q025 = ep.q975 = ep.post_q025 = ep.post_q975 =
          std::numeric_limits<double>::quiet_NaN();
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
  if (options.before_candidate_step && !effects.empty())
    options.before_candidate_step(joinEffects(effects), "compare");
  compareFigures(f, r, setup, stage);
  return f;
}

void Diagnosis::compareFigures(Figures& f, const calib::CalibrationResult& r,
                               const calib::CalibrationSetup& setup,
                               const std::string& stage) const {
  std::vector<std::vector<double>> rows;
  if (!f.full) rows.push_back(r.optimum.theta);  // the optimum alone: no posterior rows
  const std::size_t m = f.full ? r.chains.index.size() : 0;
  const std::size_t want =
      std::min<std::size_t>(static_cast<std::size_t>(std::max(1, options.compare_draws)), m);
  for (std::size_t k = 0; k < want; ++k) {
    const std::size_t i = want == 1 ? m / 2 : k * (m - 1) / (want - 1);
    std::vector<double> th(r.names.size());
    for (std::size_t c = 0; c < th.size(); ++c)
      th[c] = r.design(r.chains.index[i], static_cast<long>(c));
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

namespace {

// ------------------------------------------------------------------ inputs

/// The candidates to rank: options.effects, or the default catalogue (candidates.hpp) without the
/// effects installed in the assembly or the study, on data with the fitted `channels`. Their specs
/// and those of options.apply go into `specs`. Throws InputError when options.effects or
/// options.apply names an installed effect or a candidate these study and data do not have.
/// The effects installed in `assembly` or the study; InputError when options.effects or
/// options.apply names one (checked before any data are read).
std::set<std::string> refuseInstalled(const Study& study, const AssemblySpec& assembly,
                                      const DiagnoseOptions& options) {
  const OptionCheck check("diagnose");
  std::set<std::string> installed(assembly.effects.begin(), assembly.effects.end());
  for (const auto& e : study.effects) installed.insert(e.name);
  const std::string rule =
      " is already installed in assembly " + assembly.id + " or the study's [effects]";
  for (const auto& e : options.effects)
    check.require(!installed.count(e), "effects", "'" + e + "'" + rule);
  for (const auto& e : options.apply)
    check.require(!installed.count(e), "apply", "'" + e + "'" + rule);
  return installed;
}

/// Whether a data set's road is a measured signal (RoadSetting::measured): the input-side and
/// input-form candidates join the default catalogue.
bool measuredRoad(const Study& study, const std::vector<calib::DataSet>& sets) {
  for (const auto& s : sets)
    if (study.scenario(s.scenario).road->measured()) return true;
  return false;
}

/// Whether every data set's road is each wheel's own measured motion (a four-corner road).
bool eachWheelRoad(const Study& study, const std::vector<calib::DataSet>& sets) {
  for (const auto& s : sets) {
    const auto j = study.scenario(s.scenario).road->toJson();
    if (!j.is_object() || !j.contains("tracks") || j["tracks"] != "four corners") return false;
  }
  return !sets.empty();
}

std::vector<std::string> catalogueOf(const Study& study, const AssemblySpec& assembly,
                                     const DiagnoseOptions& options,
                                     const std::vector<std::string>& channels,
                                     std::map<std::string, CandidateSpec>& specs,
                                     bool measured_road, bool each_wheel) {
  const OptionCheck check("diagnose");
  const auto installed = refuseInstalled(study, assembly, options);
  std::vector<std::string> catalogue =
      options.effects.empty()
          ? defaultCandidates(study, assembly, channels, measured_road, each_wheel)
          : options.effects;
  // The default catalogue leaves out what the model has already: an installed effect, a value the
  // study calibrates (a named one is refused by candidateSpec).
  const auto calibrated = [&](const std::string& e) {
    return options.effects.empty() &&
           std::any_of(study.calibrated.begin(), study.calibrated.end(),
                       [&](const CalibratedParameter& c) { return e == "free:" + c.name; });
  };
  catalogue.erase(
      std::remove_if(catalogue.begin(), catalogue.end(),
                     [&](const std::string& e) { return installed.count(e) > 0 || calibrated(e); }),
      catalogue.end());
  for (const char* field : {"effects", "apply"})
    for (const auto& e : std::string(field) == "effects" ? catalogue : options.apply)
      if (!specs.count(e))
        specs.emplace(e, candidateSpec(e, study, assembly, channels, check.where(field)));
  return catalogue;
}

/// The noise of every channel, the weights 1/σ_c², and the data sets reduced to the channels with
/// a noise estimate (the others are compared, not weighed).
void prepareData(Diagnosis& d, const std::vector<calib::DataSet>& fit,
                 const std::vector<calib::DataSet>& holdout) {
  std::vector<std::string> left;
  d.noise = estimateChannelNoise(d.study, fit, &left);
  d.res.left_out_channels = left;
  if (d.noise.empty())
    throw InputError(fit.front().name,
                     "no channel has a noise estimate: give at least two repetitions, or force "
                     "channels (unit N) "
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
    d.data_hash += s.scenario + ":" +
                   hexId(fnv1a64(labCsvText(s.data, measurableChannels(d.study.sensors)))) + ";";
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
      d.specs.emplace(name, candidateSpec(name, d.study, d.assembly, d.res.fitted_channels,
                                          "diagnose.effects"));
      d.catalogue.push_back(name);
    } catch (const InputError&) {
      // no physical limit beyond the study's range: nothing to widen
    }
  }
}

}  // namespace

std::vector<StageWork> estimateDiagnoseWork(const Study& study, const AssemblySpec& assembly,
                                            const std::vector<calib::DataSet>& fit,
                                            const std::vector<calib::DataSet>& holdout,
                                            const DiagnoseOptions& options) {
  double fit_span = 0, hold_span = 0, fit_records = 0;
  for (const auto& s : fit) {
    fit_span += dataSpan(s.data);
    fit_records += static_cast<double>(s.data.records.size());
  }
  for (const auto& s : holdout) hold_span += dataSpan(s.data);
  const auto& c = options.calibration;
  const auto design = c.designOptions();
  const double design_points =
      design.first_points +
      (design.adaptive ? static_cast<double>(design.max_rounds) * design.round_points : 0.0);
  const double base_params = static_cast<double>(study.calibrated.size());
  // Screening: a linearisation (two runs per parameter) and every probe column of every effect.
  // ... and, when the verdict is unexplained, a proposal: a linearisation and every library term.
  double catalogue_probes = 0, most_effect_params = 0;
  std::vector<std::string> channels;
  for (const auto& s : fit)
    for (const auto& ch : s.data.channels())
      if (std::find(channels.begin(), channels.end(), ch) == channels.end()) channels.push_back(ch);
  std::map<std::string, CandidateSpec> specs;
  for (const auto& e : catalogueOf(study, assembly, options, channels, specs,
                                   measuredRoad(study, fit), eachWheelRoad(study, fit))) {
    const auto groups = probesOf(0, specs.at(e));
    for (const auto& g : groups) catalogue_probes += static_cast<double>(g.cols.size());
    most_effect_params =
        std::max(most_effect_params, static_cast<double>(specs.at(e).parameters.size()));
  }
  const double probe_runs =
      2 * base_params + catalogue_probes +
      (options.propose_terms > 0 ? 2 * base_params + static_cast<double>(termLibrary(1, 1).size())
                                 : 0.0);
  double applied_params = 0;
  for (const auto& e : options.apply)
    applied_params += static_cast<double>(specs.at(e).parameters.size());
  const double starts = static_cast<double>(c.optimizer_starts) +
                        2;  // the screening's and the nested optimum's starts
  auto calibration = [&](const std::string& stage, double count, double params) {
    const double sims = count * calibrationSimulations(design_points, starts, params);
    return StageWork{stage, sims, sims * fit_span,
                     8.0 * static_cast<double>(c.gibbs_iterations) * (params + 2) +
                         8.0 * design_points * fit_records};
  };
  std::vector<StageWork> out;
  out.push_back(calibration("diagnose base", 2, base_params));  // the base and its refinement
  out.push_back(
      {"diagnose screening", probe_runs, probe_runs * fit_span, 8.0 * probe_runs * fit_records});
  // One round of the budget per stage: a later round runs only where the screening misjudged
  // (docs/diagnosis.md, "Confirmation") and adds at most options.candidates to its stage.
  const double per_stage = static_cast<double>(options.candidates);
  out.push_back(calibration("diagnose confirm", per_stage, base_params + most_effect_params));
  out.push_back(calibration("diagnose apply", static_cast<double>(options.apply.size()),
                            base_params + applied_params));
  // Forward stagewise: at most causes − 1 further stages, each a screening (a linearisation with
  // the causes before it, and every probe) and a confirmation on top of them.
  const double further = static_cast<double>(options.causes - 1);
  auto more = calibration("diagnose further causes", further * per_stage,
                          base_params + static_cast<double>(options.causes) * most_effect_params);
  const double further_probes =
      further * (2 * (base_params + further * most_effect_params) + catalogue_probes);
  more.simulations += further_probes;
  more.simulated_s += further_probes * fit_span;
  out.push_back(more);
  const double models = 2 + per_stage * static_cast<double>(options.causes) +
                        static_cast<double>(options.apply.size());
  const double runs = models * (options.compare_draws + 1);
  out.push_back({"diagnose compare", runs, runs * (fit_span + hold_span),
                 8.0 * (options.compare_draws + 1) * fit_records});
  return out;
}

DiagnosisResult diagnose(const Study& study, const AssemblySpec& assembly,
                         const std::vector<calib::DataSet>& fit,
                         const std::vector<calib::DataSet>& holdout, const DiagnoseOptions& options,
                         const std::string& out_dir, const DiagnoseProgress& progress) {
  options.validate();
  for (const char* field : {"effects", "apply"})  // an effect's name, before the data are read
    for (const auto& e : std::string(field) == "effects" ? options.effects : options.apply)
      if (e.find(':') == std::string::npos && e.find('=') == std::string::npos)
        (void)study.effectCatalog().make(e, OptionCheck("diagnose").where(field));
  if (fit.empty())
    throw InputError(OptionCheck("diagnose").where("fit"),
                     "needs at least one measurement data set");
  Diagnosis d(study, assembly, options, out_dir, progress);
  d.res.assembly = assembly.id;
  refuseInstalled(study, assembly, options);  // before the data are read
  prepareData(d, fit, holdout);
  d.catalogue = catalogueOf(study, assembly, options, d.res.fitted_channels, d.specs,
                            measuredRoad(study, fit), eachWheelRoad(study, fit));
  d.res.base = d.calibrateWith({}, "base");
  addRangeCandidates(d);
  screen(d);
  const auto confirmed = confirm(d);
  refine(d, confirmed);
  verdict(d);
  if (d.res.verdict == "unexplained" && options.propose_terms > 0 &&
      !d.isolated("the proposal", [&] { propose(d); }))
    d.res.proposal.clear();
  apply(d);
  return std::move(d.res);
}

}  // namespace dtwin::diag
