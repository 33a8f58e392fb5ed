#include "diagnosis/diagnose.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <set>

#include <Eigen/Dense>

#include "subsystems/effect.hpp"
#include "common/errors.hpp"
#include "twin/parallel.hpp"
#include "twin/provenance.hpp"

namespace fs = std::filesystem;

namespace dtwin::diag {
namespace {

double normalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }
/// P(χ²_k > x) for k = 1, 2 exactly, else Wilson–Hilferty.
double chi2Upper(double x, int k) {
  if (x <= 0) return 1.0;
  if (k == 1) return std::erfc(std::sqrt(x / 2.0));
  if (k == 2) return std::exp(-x / 2.0);
  const double a = 2.0 / (9.0 * k);
  return 1.0 - normalCdf((std::cbrt(x / k) - (1.0 - a)) / std::sqrt(a));
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

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

std::vector<const ParameterSpec*> diagnosedParameters(const Effect& e) {
  std::vector<const ParameterSpec*> v;
  for (const auto& p : e.parameters())
    if (!p.shape) v.push_back(&p);
  return v;
}

/// The fraction of Σ z² in [t0, t1] of a series.
double chi2In(const SeriesComparison& s, double t0, double t1) {
  double a = 0.0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= t0 && s.t[i] <= t1 && std::isfinite(s.z[i])) a += s.z[i] * s.z[i];
  return a;
}

/// The state map and feature where an effect's signature shows (empty: none specific).
std::pair<std::string, std::string> expectedSignature(const std::string& effect) {
  if (effect == "bump_stop") return {"susp_defl_", "knee"};
  if (effect == "progressive_spring") return {"susp_defl_", "cubic"};
  if (effect == "strut_friction") return {"susp_rate_", "step"};
  if (effect == "damper_asymmetry") return {"susp_rate_", "rebound_slope"};
  if (effect == "anti_roll_bar") return {"roll_defl_", "linear"};
  if (effect == "speed_dependent_tire_stiffness") return {"tire_defl_", "linear"};
  return {"", ""};
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

calib::CalibrationSetup effectSetup(const std::vector<std::string>& effects, const std::map<std::string, double>& weights) {
  calib::CalibrationSetup s;
  s.channel_weights = weights;
  for (const auto& name : effects) {
    const auto e = makeEffect(name, "effect");
    EffectSetting es;
    es.name = name;
    s.extra_effects.push_back(es);
    for (const auto* p : diagnosedParameters(*e)) {
      CalibratedParameter c;
      c.name = name + "." + p->name;
      c.unit = p->unit;
      c.lower = p->prior_lower;
      c.upper = p->prior_upper;
      s.extra_calibrated.push_back(c);
    }
  }
  return s;
}

nlohmann::json Figures::toJson() const {
  nlohmann::json j{{"label", label},          {"effects", effects}, {"sse_min_weighted", sse_min}, {"bic", bic},
                   {"log_evidence", log_evidence}, {"parameters", parameters}, {"folder", folder}};
  j["effect_parameters"] = paramsJson(effect_parameters);
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

DiagnosisResult diagnose(const Study& study, const AssemblySpec& assembly, const std::vector<calib::DataSet>& fit,
                         const std::vector<calib::DataSet>& holdout, const DiagnoseOptions& options,
                         const std::string& out_dir, const DiagnoseProgress& progress) {
  if (fit.empty()) throw InputError("diagnose", "needs at least one measurement file (--data)");
  auto report = [&](const std::string& s, std::size_t d, std::size_t t) {
    if (progress) progress(s, d, t);
  };
  DiagnosisResult res;
  res.assembly = assembly.id;
  std::vector<std::string> left;
  const auto noise = estimateChannelNoise(study, fit, &left);
  res.left_out_channels = left;
  if (noise.empty())
    throw InputError(fit.front().name, "no channel has a noise estimate: give at least two repetitions, or force channels (unit N) "
                                       "with the study's [noise] variance");
  std::map<std::string, double> weights;
  for (const auto& [c, n] : noise) {
    weights[c] = 1.0 / n.variance;
    res.fitted_channels.push_back(c);
  }
  // Only fitted channels enter the calibrations (others are compared, not weighed).
  auto fittedOnly = [&](const std::vector<calib::DataSet>& sets) {
    std::vector<calib::DataSet> out;
    for (const auto& s : sets) {
      calib::DataSet d{s.name, s.scenario, {}, s.road_seed};
      for (const auto& r : s.data.records)
        if (noise.count(r.channel)) d.data.records.push_back(r);
      if (!d.data.records.empty()) out.push_back(std::move(d));
    }
    return out;
  };
  const auto fit_sets = fittedOnly(fit);
  const auto hold_sets = fittedOnly(holdout);
  std::string data_hash;
  for (const auto& s : fit_sets) data_hash += s.scenario + ":" + hexId(fnv1a64(labCsvText(s.data))) + ";";

  // The catalogue.
  std::set<std::string> installed(assembly.effects.begin(), assembly.effects.end());
  for (const auto& e : study.effects) installed.insert(e.name);
  std::vector<std::string> catalogue = options.effects.empty() ? effectNames() : options.effects;
  for (const auto& e : catalogue) {
    makeEffect(e, "--effects");  // InputError listing the known names
    if (installed.count(e)) {
      if (!options.effects.empty())
        throw InputError("--effects " + e, "is already installed in assembly " + assembly.id + " or the study's [effects]");
    }
  }
  catalogue.erase(std::remove_if(catalogue.begin(), catalogue.end(), [&](const std::string& e) { return installed.count(e) > 0; }),
                  catalogue.end());
  for (const auto& e : options.apply) {
    makeEffect(e, "--apply");
    if (installed.count(e)) throw InputError("--apply " + e, "is already installed in assembly " + assembly.id);
  }

  // One calibration (persisted, resumable), compared on the fit and held-out data.
  const int n_fit_params = static_cast<int>(study.calibrated.size());
  // Every calibration polishes its optimum; a model with effects also starts from the nested
  // model's optimum with the effects' parameters off, so adding an effect never fits worse.
  auto offValues = [&](const std::vector<std::string>& effects) {
    std::vector<double> v;
    for (const auto& e : effects)
      for (const auto* p : diagnosedParameters(*makeEffect(e, "effect"))) v.push_back(p->default_value);
    return v;
  };
  std::map<std::string, std::vector<double>> optima;  // by joinEffects(effects)
  auto calibrateWith = [&](const std::vector<std::string>& effects, const std::string& stage,
                           const std::vector<double>& effect_start = {}, const std::vector<double>& theta_start = {}) {
    Figures f;
    f.effects = effects;
    f.label = effects.empty() ? "base" : "+ " + joinEffects(effects);
    // A base started from a better point than its own optimum (see "refined" below) has its own folder.
    f.folder = (fs::path(out_dir) / "calibrations" / (joinEffects(effects) + (effects.empty() && !theta_start.empty() ? ".refined" : "")))
                   .string();
    const auto setup = effectSetup(effects, weights);
    auto copt = options.calibration;
    copt.threads = options.threads;
    copt.command = options.command;
    copt.polish_step = 0.01;
    if (effects.empty() && !theta_start.empty()) copt.extra_starts.push_back(theta_start);
    if (!effects.empty()) {
      const std::vector<std::string> nested(effects.begin(), effects.end() - 1);
      const auto it = optima.find(joinEffects(nested));
      if (it != optima.end()) {
        auto x = it->second;
        for (double v : offValues({effects.back()})) x.push_back(v);
        copt.extra_starts.push_back(x);
        if (!effect_start.empty()) {
          auto y = it->second;
          for (double v : effect_start) y.push_back(v);
          copt.extra_starts.push_back(y);
          if (effects.size() == 1 && theta_start.size() == static_cast<std::size_t>(n_fit_params)) {
            auto z = theta_start;
            for (double v : effect_start) z.push_back(v);
            copt.extra_starts.push_back(z);
          }
        }
      }
    }
    const auto r = calib::calibrateAssembly(study, assembly, fit_sets, setup, copt, f.folder, data_hash,
                                            [&](const std::string& s, std::size_t d, std::size_t t) {
                                              report(stage + ": " + s, d, t);
                                            });
    optima[joinEffects(effects)] = r.optimum.theta;
    f.parameters = static_cast<int>(r.names.size());
    f.sse_min = r.optimum.sse;
    f.bic = r.optimum.sse + f.parameters * std::log(static_cast<double>(r.n_data));
    f.log_evidence = -0.5 * f.bic;
    for (std::size_t k = static_cast<std::size_t>(n_fit_params); k < r.names.size(); ++k) {
      const auto& p = r.posterior.parameters[k];
      EffectParameter ep;
      ep.name = r.names[k];
      ep.unit = setup.extra_calibrated[k - static_cast<std::size_t>(n_fit_params)].unit;
      ep.mean = p.mean;
      ep.sd = p.sd;
      ep.post_q025 = p.q025;
      ep.post_q975 = p.q975;
      const bool prof = r.interval == "profile" && k < r.profile.lower.size();
      ep.interval = prof ? "profile" : "posterior";
      ep.q025 = prof ? r.profile.lower[k] : p.q025;
      ep.q975 = prof ? r.profile.upper[k] : p.q975;
      ep.optimum = r.optimum.theta[k];
      f.effect_parameters.push_back(ep);
    }
    // Posterior rows for the comparison.
    std::vector<std::vector<double>> rows;
    const std::size_t m = r.chains.index.size();
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
    return f;
  };

  // 1. Base.
  res.base = calibrateWith({}, "base");
  const Comparison& base = res.base.comparison;

  // 2. Screening at the base optimum.
  calib::LabObjective base_obj(study, assembly, fit_sets, effectSetup({}, weights));
  const std::vector<double> theta_hat = optima.at("base");
  const auto eta_hat = base_obj.predict(theta_hat);
  if (eta_hat.empty()) throw std::runtime_error("diagnose: the run at the base optimum failed");
  const auto& y = base_obj.measured();
  const auto& w = base_obj.weights();
  const std::size_t n = y.size();
  Eigen::VectorXd r(static_cast<long>(n));
  for (std::size_t i = 0; i < n; ++i) r[static_cast<long>(i)] = std::sqrt(w[i]) * (y[i] - eta_hat[i]);
  const std::size_t d = theta_hat.size();
  Eigen::MatrixXd J(static_cast<long>(n), static_cast<long>(d));
  {
    std::vector<std::vector<double>> plus(d), minus(d);
    std::vector<double> h(d);
    for (std::size_t k = 0; k < d; ++k)
      h[k] = 1e-2 * std::max(std::abs(theta_hat[k]), 1e-3 * (base_obj.upper()[k] - base_obj.lower()[k]));
    report("screening: sensitivities", 0, 2 * d);
    parallelFor(2 * d, options.threads, [&](std::size_t t, int) {
      const std::size_t k = t / 2;
      auto th = theta_hat;
      th[k] += (t % 2 == 0 ? 1.0 : -1.0) * h[k];
      (t % 2 == 0 ? plus[k] : minus[k]) = base_obj.predict(th);
    });
    for (std::size_t k = 0; k < d; ++k) {
      if (plus[k].empty() || minus[k].empty()) throw std::runtime_error("diagnose: a sensitivity run at the base optimum failed");
      for (std::size_t i = 0; i < n; ++i)
        J(static_cast<long>(i), static_cast<long>(k)) = std::sqrt(w[i]) * (plus[k][i] - minus[k][i]) / (2 * h[k]);
    }
  }
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(J);
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(static_cast<long>(n), static_cast<long>(d));
  auto project = [&](const Eigen::MatrixXd& G) -> Eigen::MatrixXd { return G - Q * (Q.transpose() * G); };

  // The model's largest compression over the fit data (for the bump stop's gate sentence).
  double max_compression = -std::numeric_limits<double>::infinity();
  {
    const auto tr = base_obj.traces(theta_hat);
    for (const auto& t : tr)
      for (const char* c : {"fl", "fr", "rl", "rr"})
        for (double q : t.column(std::string("susp_defl_") + c + "_m")) max_compression = std::max(max_compression, q);
  }

  std::vector<std::unique_ptr<calib::LabObjective>> eff_obj;
  struct Group {
    std::size_t effect;
    std::vector<std::vector<double>> cols;  // parameter vectors, one per column
  };
  std::vector<Group> groups;
  for (std::size_t e = 0; e < catalogue.size(); ++e) {
    const auto eff = makeEffect(catalogue[e], "effect");
    const auto ps = diagnosedParameters(*eff);
    eff_obj.push_back(std::make_unique<calib::LabObjective>(study, assembly, fit_sets, effectSetup({catalogue[e]}, weights)));
    std::vector<double> off;
    for (const auto* p : ps) off.push_back(p->default_value);
    std::vector<std::size_t> strength, scan;
    for (std::size_t k = 0; k < ps.size(); ++k) (k == 0 || isStrength(*ps[k]) ? strength : scan).push_back(k);
    std::vector<std::vector<double>> scans{off};
    for (std::size_t k : scan) {
      std::vector<std::vector<double>> next;
      for (const auto& base_v : scans)
        for (double f : {0.1, 0.3, 0.6}) {
          auto v = base_v;
          v[k] = ps[k]->prior_lower + f * (ps[k]->prior_upper - ps[k]->prior_lower);
          next.push_back(v);
        }
      scans = next;
    }
    for (double level : {0.05, 0.2, 0.6})
      for (const auto& sv : scans) {
        Group g{e, {}};
        for (std::size_t k : strength) {
          auto v = sv;
          v[k] = towardFar(*ps[k], level);
          g.cols.push_back(v);
        }
        groups.push_back(g);
      }
  }
  // Simulate every probe column.
  std::vector<std::pair<std::size_t, std::size_t>> jobs;  // (group, column)
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t c = 0; c < groups[g].cols.size(); ++c) jobs.push_back({g, c});
  std::vector<std::vector<double>> probe_eta(jobs.size());
  report("screening: probes", 0, jobs.size());
  parallelFor(jobs.size(), options.threads, [&](std::size_t j, int) {
    const auto& g = groups[jobs[j].first];
    auto th = theta_hat;
    for (double v : g.cols[jobs[j].second]) th.push_back(v);
    probe_eta[j] = eff_obj[g.effect]->predict(th);
  });
  report("screening: probes", jobs.size(), jobs.size());
  const double bonferroni = static_cast<double>(groups.size());
  res.candidates.resize(catalogue.size());
  for (std::size_t e = 0; e < catalogue.size(); ++e) {
    const auto eff = makeEffect(catalogue[e], "effect");
    res.candidates[e].effect = catalogue[e];
    res.candidates[e].signature = eff->signature();
  }
  std::vector<bool> any_failed(catalogue.size(), false);
  for (std::size_t g = 0, j = 0; g < groups.size(); ++g) {
    const std::size_t e = groups[g].effect;
    Eigen::MatrixXd G(static_cast<long>(n), static_cast<long>(groups[g].cols.size()));
    bool failed = false;
    for (std::size_t c = 0; c < groups[g].cols.size(); ++c, ++j) {
      if (probe_eta[j].empty()) {
        failed = true;
        continue;
      }
      for (std::size_t i = 0; i < n; ++i) G(static_cast<long>(i), static_cast<long>(c)) = std::sqrt(w[i]) * (probe_eta[j][i] - eta_hat[i]);
    }
    if (failed) {
      any_failed[e] = true;
      continue;
    }
    const Eigen::MatrixXd Gp = project(G);
    auto& cand = res.candidates[e];
    cand.max_signal = std::max(cand.max_signal, Gp.squaredNorm());
    // S = rᵀ Gp (Gpᵀ Gp)⁺ Gpᵀ r (rank-revealing: a column the base absorbs entirely drops out).
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(Gp);
    const long rank = cod.rank();
    if (rank == 0) continue;
    const Eigen::VectorXd coef = cod.solve(r);
    const double S = (Gp * coef).squaredNorm();
    if (S > cand.score) {
      cand.score = S;
      cand.score_dof = static_cast<int>(rank);
      // Column c probes one strength parameter at value v_c (the others off): the linearised
      // fit says the parameter is off + coef_c (v_c − off), clipped to the prior.
      const auto eff = makeEffect(catalogue[e], "effect");
      const auto ps = diagnosedParameters(*eff);
      std::vector<double> est = groups[g].cols[0];
      for (std::size_t col = 0; col < groups[g].cols.size(); ++col)
        for (std::size_t k = 0; k < ps.size(); ++k)
          if (groups[g].cols[col][k] != ps[k]->default_value && (k == 0 || isStrength(*ps[k]))) {
            const double v = ps[k]->default_value + coef[static_cast<long>(col)] * (groups[g].cols[col][k] - ps[k]->default_value);
            est[k] = std::clamp(v, ps[k]->prior_lower, ps[k]->prior_upper);
          }
      cand.screening_estimate = est;
      // The base parameters of the joint linearised fit r ≈ J δθ + G c: δθ = J⁺ (r − G c).
      const Eigen::VectorXd dtheta = qr.solve(r - G * coef);
      cand.screening_theta = theta_hat;
      for (std::size_t k = 0; k < d; ++k)
        cand.screening_theta[k] = std::clamp(theta_hat[k] + dtheta[static_cast<long>(k)], base_obj.lower()[k], base_obj.upper()[k]);
    }
  }
  for (std::size_t e = 0; e < catalogue.size(); ++e) {
    auto& c = res.candidates[e];
    c.p_value = std::min(1.0, bonferroni * chi2Upper(c.score, c.score_dof));
    if (c.max_signal == 0.0) {
      if (c.effect == "bump_stop")
        c.gate = "the suspension never compresses beyond the smallest plausible gap (" + fmt("%.3g", max_compression) + " m < " +
                 fmt("%.3g", makeEffect("bump_stop", "")->parameters()[1].prior_lower) + " m): a bump stop cannot act here";
      else
        c.gate = "exerts no force in these runs at any plausible value";
    } else if (c.max_signal < 1.0) {
      c.gate = "its largest plausible contribution, after re-calibrating the base parameters, is below the noise (" +
               fmt("%.2g", c.max_signal) + " noise variances in total): these data cannot show it";
    } else if (any_failed[e]) {
      c.gate = "a probe simulation failed";
    }
  }

  // 3. Confirm the best candidates.
  std::vector<std::size_t> order(catalogue.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return res.candidates[a].score > res.candidates[b].score; });
  std::vector<std::size_t> to_confirm;
  for (std::size_t i : order)
    if (res.candidates[i].gate.empty() && res.candidates[i].p_value < options.screen_alpha &&
        static_cast<int>(to_confirm.size()) < options.candidates)
      to_confirm.push_back(i);
  for (std::size_t k = 0; k < to_confirm.size(); ++k) {
    auto& c = res.candidates[to_confirm[k]];
    c.confirmed = true;
    c.fit = calibrateWith({c.effect}, "confirm " + c.effect + " (" + std::to_string(k + 1) + "/" + std::to_string(to_confirm.size()) + ")",
                          c.screening_estimate, c.screening_theta);
  }
  // The evidence for an effect must not come from a base optimum the optimiser missed. The base is
  // polished again from every strongly favoured candidate's base parameters (its effect switched
  // off); when that fits better, the base is re-calibrated from there and becomes the reference
  // of every ΔBIC and of the lack-of-fit figures.
  {
    std::vector<double> better;
    double better_sse = res.base.sse_min - 1.0;  // below the integrator's noise in the SSE: no change
    for (std::size_t i : to_confirm) {
      const auto& c = res.candidates[i];
      if (c.fit->bic - res.base.bic >= -options.bic_strong) continue;
      auto th = optima.at(joinEffects({c.effect}));
      th.resize(d);
      report("refine base from " + c.effect, 0, 1);
      const auto p = calib::polishLeastSquares(base_obj, th, options.threads);
      report("refine base from " + c.effect, 1, 1);
      if (p.sse < better_sse) {
        better_sse = p.sse;
        better = p.theta;
        res.base_refined_from = c.effect;
      }
    }
    if (!better.empty()) {
      res.base_unrefined_sse = res.base.sse_min;
      res.base = calibrateWith({}, "base (refined)", {}, better);
    }
  }
  const double base_excess = base.lack_of_fit - static_cast<double>(base.lack_of_fit_dof);
  for (std::size_t k = 0; k < to_confirm.size(); ++k) {
    auto& c = res.candidates[to_confirm[k]];
    c.delta_bic = c.fit->bic - res.base.bic;
    c.explained = base_excess > 0 ? std::clamp((base.lack_of_fit - c.fit->comparison.lack_of_fit) / base_excess, 0.0, 1.0) : 0.0;
    if (c.fit->holdout && res.base.holdout && res.base.holdout->systematic_rms_sd > 0)
      c.holdout_change = c.fit->holdout->systematic_rms_sd / res.base.holdout->systematic_rms_sd;
  }
  // Rank: confirmed by log evidence, then by score, gated last.
  std::stable_sort(res.candidates.begin(), res.candidates.end(), [](const Candidate& a, const Candidate& b) {
    auto cls = [](const Candidate& c) { return c.confirmed ? 0 : (c.gate.empty() ? 1 : 2); };
    if (cls(a) != cls(b)) return cls(a) < cls(b);
    if (a.confirmed) return a.fit->log_evidence > b.fit->log_evidence;
    return a.score > b.score;
  });

  // Why, per candidate.
  for (auto& c : res.candidates) {
    if (!c.gate.empty()) {
      c.why = c.effect + ": not a candidate: " + c.gate + ".";
      continue;
    }
    if (!c.confirmed) {
      c.why = c.effect + ": screening score " + fmt("%.3g", c.score) + " (p = " + fmt("%.2g", c.p_value) + ")" +
              (c.p_value < options.screen_alpha ? ", not among the best candidates confirmed" : ": explains nothing beyond noise") + ".";
      continue;
    }
    std::string s = c.effect + ": " + (c.delta_bic < 0 ? "ΔBIC " : "ΔBIC +") + fmt("%.1f", c.delta_bic) + ", explains " +
                    fmt("%.0f", 100 * c.explained) + " % of the excess residual";
    // The window it fixes most.
    double best_drop = 0.0;
    std::string where;
    for (std::size_t i = 0; i < base.series.size() && i < c.fit->comparison.series.size(); ++i)
      for (const auto& win : base.series[i].windows) {
        const double before = chi2In(base.series[i], win.window.t_begin, win.window.t_end);
        const double after = chi2In(c.fit->comparison.series[i], win.window.t_begin, win.window.t_end);
        if (before - after > best_drop) {
          best_drop = before - after;
          where = "removes " + fmt("%.0f", before > 0 ? 100 * (before - after) / before : 0.0) + " % of the residual of " +
                  base.series[i].channel + " in " + base.series[i].scenario + " " + fmt("%.3f", win.window.t_begin) + "-" +
                  fmt("%.3f", win.window.t_end) + " s (" + win.label + ")";
        }
      }
    if (!where.empty()) s += "; " + where;
    // The band it fixes most.
    double band_drop = 0.0;
    std::string band;
    for (std::size_t i = 0; i < base.series.size() && i < c.fit->comparison.series.size(); ++i)
      for (std::size_t b = 0; b < base.series[i].bands.size() && b < c.fit->comparison.series[i].bands.size(); ++b) {
        const double before = base.series[i].bands[b].ratio, after = c.fit->comparison.series[i].bands[b].ratio;
        if (before - after > band_drop && before > 2.0) {
          band_drop = before - after;
          band = base.series[i].bands[b].band + " band of " + base.series[i].channel + " from " + fmt("%.3g", before) + "x to " +
                 fmt("%.3g", after) + "x the noise floor";
        }
      }
    if (!band.empty()) s += "; lowers the " + band;
    // The force-state signature it predicts, as seen in the base residual.
    const auto sig = expectedSignature(c.effect);
    if (!sig.first.empty()) {
      double ef = 0.0;
      std::string txt;
      for (const auto& cm : base.maps)
        for (const auto& m : cm.maps)
          if (m.state.rfind(sig.first, 0) == 0)
            for (const auto& f : m.fits)
              if (f.feature == sig.second && f.explained_fraction > ef) {
                ef = f.explained_fraction;
                txt = cm.channel + " vs " + m.state + " shows a " + f.feature +
                      (f.feature == "knee" ? " beyond " + fmt("%.3g", f.knee_at) : "") + " (" + fmt("%.0f", 100 * ef) +
                      " % of that map)";
              }
      if (!txt.empty() && ef > 0.1) s += "; its signature is in the data: " + txt;
    }
    if (c.holdout_change) s += "; held-out systematic error x" + fmt("%.2f", *c.holdout_change);
    c.why = s + ".";
  }

  // 4. Verdict.
  const double alpha = options.lack_of_fit_alpha;
  const bool base_bad = base.lack_of_fit_p < alpha;
  std::vector<const Candidate*> named;
  for (const auto& c : res.candidates)
    if (c.confirmed && c.delta_bic < -options.bic_strong) named.push_back(&c);
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
  } else {
    const Candidate& best = *named.front();
    const bool after_bad = best.fit->comparison.lack_of_fit_p < alpha;
    if (after_bad && best.explained < options.explained_min) {
      res.verdict = "unexplained";
      res.unexplained_location = locate(best.fit->comparison);
      res.summary = "Unexplained residual: the best catalogue effect, " + best.effect + ", explains only " +
                    fmt("%.0f", 100 * best.explained) + " % of the excess residual and a significant lack of fit remains (z = " +
                    fmt("%.1f", best.fit->comparison.lack_of_fit_z) + "); it is not named. Where: " + res.unexplained_location + ".";
    } else {
      res.verdict = "effect";
      res.named_effect = best.effect;
      res.summary = "Missing effect: " + best.effect + " (ΔBIC " + fmt("%.1f", best.delta_bic) + ", explains " +
                    fmt("%.0f", 100 * best.explained) + " % of the excess residual).";
      for (std::size_t i = 1; i < named.size(); ++i)
        if (best.fit->log_evidence - named[i]->fit->log_evidence < options.ambiguity_log_evidence)
          res.ambiguous_with.push_back(named[i]->effect);
      if (!res.ambiguous_with.empty()) {
        res.summary += " Ambiguous: ";
        for (std::size_t i = 0; i < res.ambiguous_with.size(); ++i) res.summary += (i ? ", " : "") + res.ambiguous_with[i];
        res.summary += " explain" + std::string(res.ambiguous_with.size() == 1 ? "s" : "") +
                       " the data almost as well (log evidence within " + fmt("%.0f", options.ambiguity_log_evidence) +
                       "); more data (another scenario) would separate them.";
      }
      if (after_bad)
        res.summary += " A smaller significant residual remains (z = " + fmt("%.1f", best.fit->comparison.lack_of_fit_z) +
                       "): " + locate(best.fit->comparison) + ".";
    }
  }

  // 5. Apply: effects added in turn.
  if (!options.apply.empty()) {
    res.steps.push_back(res.base);
    std::vector<std::string> acc;
    for (std::size_t k = 0; k < options.apply.size(); ++k) {
      acc.push_back(options.apply[k]);
      std::vector<double> start, theta;
      const Figures* confirmed = nullptr;
      for (const auto& c : res.candidates)
        if (c.effect == options.apply[k]) {
          start = c.screening_estimate;
          theta = c.screening_theta;
          if (acc.size() == 1 && c.fit) confirmed = &*c.fit;  // already calibrated with this effect alone
        }
      res.steps.push_back(confirmed ? *confirmed : calibrateWith(acc, "apply " + joinEffects(acc), start, theta));
    }
  }
  return res;
}

nlohmann::json DiagnosisResult::toJson() const {
  nlohmann::json j;
  j["assembly"] = assembly;
  j["verdict"] = verdict;
  j["summary"] = summary;
  if (!named_effect.empty()) j["effect"] = named_effect;
  j["ambiguous_with"] = ambiguous_with;
  if (verdict != "none") j["unexplained_location"] = unexplained_location;
  j["fitted_channels"] = fitted_channels;
  j["left_out_channels"] = left_out_channels;
  j["base"] = base.toJson();
  if (!base_refined_from.empty())
    j["base_refined"] = {{"from", base_refined_from}, {"sse_min_weighted_before", base_unrefined_sse}};
  j["ranked"] = nlohmann::json::array();
  j["screening"] = nlohmann::json::array();
  for (const auto& c : candidates) {
    nlohmann::json s{{"effect", c.effect},     {"score", c.score},         {"score_dof", c.score_dof}, {"p_value", c.p_value},
                     {"max_signal", c.max_signal}, {"gate", c.gate},       {"confirmed", c.confirmed}, {"why", c.why},
                     {"signature", c.signature}};
    j["screening"].push_back(s);
    if (!c.confirmed) continue;
    nlohmann::json r{{"effect", c.effect},
                     {"log_evidence", c.fit->log_evidence},
                     {"log_evidence_vs_base", c.fit->log_evidence - base.log_evidence},
                     {"delta_bic", c.delta_bic},
                     {"explained_fraction", c.explained},
                     {"parameters", paramsJson(c.fit->effect_parameters)},
                     {"why", c.why},
                     {"fit", c.fit->toJson()}};
    if (c.holdout_change) r["holdout_systematic_rms_ratio"] = *c.holdout_change;
    j["ranked"].push_back(r);
  }
  j["evidence_estimator"] =
      "BIC = SSE_w,min + k ln n with SSE_w = sum of (y - eta)^2 / sigma_c^2 (sigma_c^2 from the repetitions); log evidence ~ -BIC/2";
  if (!steps.empty()) {
    j["before"] = steps.front().toJson();
    j["after"] = steps.back().toJson();
    j["steps"] = nlohmann::json::array();
    for (const auto& s : steps) j["steps"].push_back(s.toJson());
  }
  return j;
}

std::string DiagnosisResult::text() const {
  std::string s;
  s += "Diagnosis of " + assembly + ": " + verdict + "\n  " + summary + "\n\n";
  if (!base_refined_from.empty())
    s += "  (The base optimum was improved from " + base_refined_from + "'s fit with the effect off: weighted SSE " +
         fmt("%.1f", base_unrefined_sse) + " -> " + fmt("%.1f", base.sse_min) + "; every ΔBIC is against the improved base.)\n\n";
  s += "Ranked effects (confirmed by re-calibration first):\n";
  int k = 0;
  for (const auto& c : candidates) s += "  " + std::to_string(++k) + ". " + c.why + "\n";
  for (const auto& c : candidates)
    if (c.confirmed && !c.fit->effect_parameters.empty()) {
      s += "\n  " + c.effect + " posterior:\n";
      for (const auto& p : c.fit->effect_parameters)
        s += "    " + p.name + " = " + fmt("%.4g", p.mean) + " ± " + fmt("%.2g", p.sd) + " " + p.unit + "  (95 % " +
             (p.interval == "profile" ? "profile likelihood" : "posterior") + " [" + fmt("%.4g", p.q025) + ", " + fmt("%.4g", p.q975) +
             "])\n";
    }
  if (!left_out_channels.empty()) {
    s += "\n  Compared but not fitted: ";
    for (std::size_t i = 0; i < left_out_channels.size(); ++i) s += (i ? "; " : "") + left_out_channels[i];
    s += "\n";
  }
  if (!steps.empty()) {
    s += "\nBefore/after (effects added in turn):\n";
    char b[256];
    std::snprintf(b, sizeof b, "  %-40s %12s %12s %10s %12s\n", "model", "syst. RMS/σ", "coverage", "log evid.", "Δ log evid.");
    s += b;
    for (const auto& st : steps) {
      double cov = 0.0;
      for (const auto& x : st.comparison.series) cov += x.coverage / static_cast<double>(st.comparison.series.size());
      std::snprintf(b, sizeof b, "  %-40s %12.3f %11.1f%% %10.1f %12.1f\n", st.label.c_str(), st.comparison.systematic_rms_sd,
                    100 * cov, st.log_evidence, st.log_evidence - steps.front().log_evidence);
      s += b;
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
