// The JSON of the calibration's result structs (calibrate.hpp): the setup, the optimum, the paper's
// box, the joint region's Gauss–Newton model, the integrator check and the whole result.
#include "calibration/calibrate_internal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/json.hpp"

namespace dtwin::calib {

// ------------------------------------------------------------------ CalibrationSetup
nlohmann::json CalibrationSetup::toJson() const {
  nlohmann::json j = nlohmann::json::object();
  j["extra_effects"] = nlohmann::json::array();
  for (const auto& e : extra_effects) {
    nlohmann::json v = nlohmann::json::object();
    for (const auto& p : e.values) v[p.name] = p.value;
    j["extra_effects"].push_back({{"name", e.name}, {"values", v}});
  }
  j["extra_calibrated"] = nlohmann::json::array();
  for (const auto& c : extra_calibrated) {
    nlohmann::json e{{"name", c.name}, {"unit", c.unit}, {"lower", c.lower}, {"upper", c.upper}};
    if (c.truth) e["truth"] = *c.truth;
    j["extra_calibrated"].push_back(e);
  }
  j["channel_weights"] = nlohmann::json::object();
  for (const auto& [c, w] : channel_weights) j["channel_weights"][c] = w;
  // Written only when used: the fingerprint of every setup without them is as before.
  if (!freed.empty()) j["freed"] = freed;
  for (const auto& m : sensor_models)
    j["sensor_models"].push_back({{"name", m.name}, {"kind", m.kind}, {"channels", m.channels}});
  for (const auto& [sub, opt] : options)
    j["options"].push_back({{"subsystem", sub}, {"option", opt}});
  for (const auto& [name, b] : bounds) j["bounds"][name] = {b.first, b.second};
  return j;
}

CalibrationSetup CalibrationSetup::fromJson(const nlohmann::json& j) {
  CalibrationSetup s;
  if (j.is_null()) return s;
  for (const auto& e : j.at("extra_effects")) {
    EffectSetting es;
    es.name = e.at("name").get<std::string>();
    for (const auto& [k, v] : e.at("values").items()) {
      ParameterSetting ps;
      ps.name = k;
      ps.value = v.get<double>();
      ps.where = "setup";
      es.values.push_back(ps);
    }
    s.extra_effects.push_back(es);
  }
  for (const auto& e : j.at("extra_calibrated")) {
    CalibratedParameter c;
    c.name = e.at("name").get<std::string>();
    c.unit = e.value("unit", "");
    c.lower = e.at("lower").get<double>();
    c.upper = e.at("upper").get<double>();
    if (e.contains("truth")) c.truth = e.at("truth").get<double>();
    s.extra_calibrated.push_back(c);
  }
  for (const auto& [k, v] : j.at("channel_weights").items()) s.channel_weights[k] = v.get<double>();
  if (j.contains("freed")) s.freed = j.at("freed").get<std::vector<std::string>>();
  if (j.contains("sensor_models"))
    for (const auto& m : j.at("sensor_models"))
      s.sensor_models.push_back({m.at("name").get<std::string>(), m.at("kind").get<std::string>(),
                                 m.at("channels").get<std::vector<std::string>>()});
  if (j.contains("options"))
    for (const auto& o : j.at("options"))
      s.options.push_back(
          {o.at("subsystem").get<std::string>(), o.at("option").get<std::string>()});
  if (j.contains("bounds"))
    for (const auto& [k, v] : j.at("bounds").items())
      s.bounds[k] = {v.at(0).get<double>(), v.at(1).get<double>()};
  return s;
}

// ------------------------------------------------------------------ stage files
nlohmann::json optimumJson(const Optimum& o) {
  nlohmann::json j{{"theta", jsonNumbers(o.theta)},
                   {"sse", jsonNumber(o.sse)},
                   {"best_start", o.best_start},
                   {"evaluations", o.evaluations}};
  for (const auto& s : o.starts)
    j["starts"].push_back({{"start", jsonNumbers(s.start)},
                           {"theta", jsonNumbers(s.theta)},
                           {"sse", jsonNumber(s.sse)},
                           {"evaluations", s.evaluations},
                           {"nonfinite_evaluations", s.nonfinite_evaluations},
                           {"status", s.status}});
  return j;
}
Optimum optimumFrom(const nlohmann::json& j) {
  Optimum o;
  o.theta = numbersFromJson(j.at("theta"));
  o.sse = numberFromJson(j.at("sse"));
  o.best_start = j.at("best_start").get<int>();
  o.evaluations = j.at("evaluations").get<int>();
  for (auto& s : j.at("starts")) {
    StartResult r;
    r.start = numbersFromJson(s.at("start"));
    r.theta = numbersFromJson(s.at("theta"));
    r.sse = numberFromJson(s.at("sse"));
    r.evaluations = s.at("evaluations").get<int>();
    r.nonfinite_evaluations = s.at("nonfinite_evaluations").get<int>();
    r.status = s.at("status").get<std::string>();
    o.starts.push_back(r);
  }
  return o;
}

nlohmann::json boxJson(const FeasibleBox& b) {
  nlohmann::json j{{"lower", jsonNumbers(b.lower)},
                   {"upper", jsonNumbers(b.upper)},
                   {"threshold", jsonNumber(b.threshold)},
                   {"evaluations", b.evaluations}};
  j["lower_clipped"] = b.lower_clipped;
  j["upper_clipped"] = b.upper_clipped;
  for (const auto& s : b.sweeps)
    j["sweeps"].push_back({{"parameter", s.parameter},
                           {"direction", s.direction},
                           {"edge", jsonNumber(s.edge)},
                           {"edge_sse", jsonNumber(s.edge_sse)},
                           {"clipped", s.clipped},
                           {"bracketed", s.bracketed},
                           {"evaluations", s.evaluations},
                           {"message", s.message}});
  return j;
}
FeasibleBox boxFrom(const nlohmann::json& j) {
  FeasibleBox b;
  b.lower = numbersFromJson(j.at("lower"));
  b.upper = numbersFromJson(j.at("upper"));
  b.threshold = numberFromJson(j.at("threshold"));
  b.evaluations = j.at("evaluations").get<int>();
  b.lower_clipped = j.at("lower_clipped").get<std::vector<bool>>();
  b.upper_clipped = j.at("upper_clipped").get<std::vector<bool>>();
  for (auto& s : j.at("sweeps")) {
    SweepResult r;
    r.parameter = s.at("parameter").get<int>();
    r.direction = s.at("direction").get<int>();
    r.edge = numberFromJson(s.at("edge"));
    r.edge_sse = numberFromJson(s.at("edge_sse"));
    r.clipped = s.at("clipped").get<bool>();
    r.bracketed = s.at("bracketed").get<bool>();
    r.evaluations = s.at("evaluations").get<int>();
    r.message = s.at("message").get<std::string>();
    b.sweeps.push_back(r);
  }
  return b;
}

nlohmann::json gaussNewtonJson(const JointRegionPlan& plan, const std::vector<RaySweep>& sweeps,
                               const std::vector<RidgeTrace>& traces) {
  nlohmann::json gn{
      {"hessian", "J^T J of the weighted residuals, scaled coordinates"},
      {"eigenvalues",
       jsonNumbers(std::vector<double>(plan.eigenvalues.data(),
                                       plan.eigenvalues.data() + plan.eigenvalues.size()))},
      {"quadratic_half_width",
       jsonNumbers(std::vector<double>(plan.half_width.data(),
                                       plan.half_width.data() + plan.half_width.size()))}};
  for (std::size_t k = 0; k < sweeps.size(); ++k)
    gn["sweeps"].push_back({{"axis", k / 2},
                            {"direction", k % 2 == 0 ? -1 : 1},
                            {"crossing", sweeps[k].t_edge},
                            {"edge_sse", jsonNumber(sweeps[k].edge_sse)},
                            {"clipped", sweeps[k].clipped},
                            {"bracketed", sweeps[k].bracketed},
                            {"evaluations", sweeps[k].evaluations},
                            {"quadratic_guess", plan.half_width(static_cast<long>(k / 2))}});
  for (const auto& tr : traces) {
    nlohmann::json t{{"axis", tr.axis},
                     {"direction", tr.direction},
                     {"t", tr.t},
                     {"sse", jsonNumbers(tr.sse)},
                     {"closed", tr.closed},
                     {"crossing", tr.crossing},
                     {"clipped", tr.clipped},
                     {"evaluations", tr.evaluations},
                     {"message", tr.message}};
    gn["ridges"].push_back(t);
  }
  return gn;
}

// ------------------------------------------------------------------ result JSON
nlohmann::json IntegratorCheck::toJson() const {
  return {{"steps", steps},
          {"probes", probes},
          {"roughness", jsonNumber(roughness)},
          {"optimum_shift", jsonNumber(optimum_shift)},
          {"shift_floor", jsonNumber(shift_floor)},
          {"accuracy", accuracy},
          {"accuracy_check", accuracy_check},
          {"sse", jsonNumber(sse)},
          {"sse_check", jsonNumber(sse_check)},
          {"prediction_change", jsonNumber(prediction_change)},
          {"jitter", jsonNumber(jitter)},
          {"threshold", jsonNumber(threshold)},
          {"ok", ok},
          {"message", message}};
}

nlohmann::json CalibrationResult::toJson() const {
  nlohmann::json j;
  j["assembly"] = assembly;
  j["label"] = label;
  j["n_data"] = n_data;
  j["sse_min"] = jsonNumber(optimum.sse);
  j["tau_hat"] = optimum.sse > 0 ? jsonNumber(n_data / optimum.sse)
                                 : jsonNumber(std::numeric_limits<double>::infinity());
  std::vector<double> box_lo, box_hi;
  region.boundingBox(box_lo, box_hi);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& p = posterior.parameters[k];
    const bool has_profile = k < profile.lower.size();
    const double plo = has_profile ? profile.lower[k] : p.q025,
                 phi = has_profile ? profile.upper[k] : p.q975;
    const bool use_profile = interval == "profile" && has_profile;
    nlohmann::json e{{"mean", p.mean},
                     {"sd", p.sd},
                     {"ci95", {use_profile ? plo : p.q025, use_profile ? phi : p.q975}},
                     {"interval", use_profile ? "profile" : "posterior"},
                     {"credible95", {p.q025, p.q975}},
                     {"ess", jsonNumber(p.ess)},
                     {"optimum", optimum.theta[k]},
                     {"box", {box_lo[k], box_hi[k]}},
                     {"box_clipped", {box_lo[k] <= region.lower[k], box_hi[k] >= region.upper[k]}}};
    if (has_profile) e["profile95"] = {plo, phi};
    if (truth[k]) {
      e["truth"] = *truth[k];
      e["truth_in_credible95"] = *truth[k] >= p.q025 && *truth[k] <= p.q975;
      if (has_profile) e["truth_in_profile95"] = *truth[k] >= plo && *truth[k] <= phi;
      e["truth_in_ci95"] = use_profile ? (*truth[k] >= plo && *truth[k] <= phi)
                                       : (*truth[k] >= p.q025 && *truth[k] <= p.q975);
    }
    j["parameters"][names[k]] = e;
  }
  j["parameter_order"] = names;
  j["bounds"] = nlohmann::json::array();
  for (std::size_t k = 0; k < names.size() && k < lower.size(); ++k)
    j["bounds"].push_back({lower[k], upper[k]});
  j["units"] = units;
  j["bound_findings"] = nlohmann::json::array();
  for (const auto& f : bounds) j["bound_findings"].push_back(f.toJson());
  if (!left_out.empty()) {
    j["left_out"] = left_out;
    j["left_out_note"] =
        "calibrated values of the study that this assembly's options do not have (the hub input "
        "has no tire "
        "stiffness or damping): not calibrated";
  }
  j["tau"] = {{"mean", posterior.tau.mean},
              {"sd", posterior.tau.sd},
              {"ci95", {posterior.tau.q025, posterior.tau.q975}},
              {"ess", jsonNumber(posterior.tau.ess)},
              {"noise_variance_mean_N2", posterior.tau.mean > 0 ? 1.0 / posterior.tau.mean : 0.0}};
  j["optimum"] = optimumJson(optimum);
  j["integrator_check"] = integrator.toJson();
  j["region"] = region.toJson();
  j["interval"] = interval;
  if (!profile.lower.empty()) j["profile"] = profile.toJson();
  if (region.kind == "paper") j["box"] = boxJson(box);
  j["design"] = rounds.toJson(names);
  j["design"]["failures"] = design_failures;
  j["design"]["resumed_points"] = resumed_points;
  j["design"]["method"] =
      rounds.rounds.size() > 1
          ? "Latin hypercube in the region, then stratified Gaussian rounds around the posterior; "
            "Griddy Gibbs with deterministic-mixture design weights"
          : "Latin hypercube in the region, one point per stratum per dimension";
  for (const auto& w : rounds.warnings) j["warnings"].push_back(w);
  for (const auto& w : warnings) j["warnings"].push_back(w);
  double best = std::numeric_limits<double>::infinity();
  for (double s : sse) best = std::min(best, s);
  j["design"]["sse_min"] = jsonNumber(best);
  j["design"]["better_than_optimum"] = best < optimum.sse;
  if (best < optimum.sse)
    j["warnings"].push_back("a design point has a lower SSE (" + std::to_string(best) +
                            ") than the optimiser's optimum (" + std::to_string(optimum.sse) +
                            "): the optimiser stopped in a local minimum; more starts may help");
  j["gibbs"] = {{"iterations", chains.options.iterations},
                {"burn_in", chains.options.burn_in},
                {"draws", posterior.draws},
                {"seed", chains.options.seed},
                {"distinct_points", posterior.distinct_points},
                {"top_point", posterior.top_point},
                {"top_share", posterior.top_share},
                {"design_too_coarse", posterior.design_too_coarse},
                {"message", posterior.message}};
  double ess_min = std::numeric_limits<double>::infinity();
  for (const auto& p : posterior.parameters)
    if (std::isfinite(p.ess)) ess_min = std::min(ess_min, p.ess);
  j["effective_sample_size_min"] = jsonNumber(ess_min);
  for (const auto& [s, w] : stage_wall_s) j["stages_wall_s"][s] = w;
  j["median_run_wall_s"] = median_run_wall_s;
  return j;
}

}  // namespace dtwin::calib
