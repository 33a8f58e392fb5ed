// The calibration's entry points (calibrateAssembly, calibrateOptimum; their stages are
// CalibrationRun's, calibration_run*.cpp), its options, the least-squares polish and the integrator
// check's figures.
#include "calibration/calibrate.hpp"
#include "calibration/calibrate_internal.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "calibration/subspace_lm.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/parallel.hpp"
#include "common/validate.hpp"

namespace dtwin::calib {

// ------------------------------------------------------------------ options
CalibrationOptions CalibrationOptions::fromStudy(const Study& study) {
  CalibrationOptions o;
  o.optimizer_starts = static_cast<int>(study.sizes.at("optimizer_starts"));
  o.lhs_points = static_cast<int>(study.sizes.at("lhs_points"));
  o.gibbs_iterations = static_cast<int>(study.sizes.at("gibbs_iterations"));
  o.gibbs_burn_in = static_cast<int>(study.sizes.at("gibbs_burn_in"));
  o.seed = study.seed;
  o.region = study.calibration.region;
  o.design.adaptive = study.calibration.designOrDefault() == "adaptive";
  o.design.round_points = static_cast<int>(study.calibration.round_points);  // 0: lhs_points
  o.design.max_rounds = static_cast<int>(study.calibration.max_rounds);
  o.design.target_ess = study.calibration.target_ess;
  o.joint.margin = study.calibration.margin;
  o.joint.ridge_steps = static_cast<int>(study.calibration.ridge_steps);
  o.interval = study.calibration.interval;
  o.steps = study.calibration.steps;
  return o;
}

AdaptiveDesignOptions CalibrationOptions::designOptions() const {
  AdaptiveDesignOptions d = design;
  d.first_points = lhs_points;
  if (d.round_points <= 0) d.round_points = lhs_points;
  d.tau_a = tau_prior_a;
  d.tau_b = tau_prior_b;
  d.seed = seed;
  return d;
}

GibbsOptions CalibrationOptions::gibbsOptions() const {
  GibbsOptions g;
  g.iterations = gibbs_iterations;
  g.burn_in = gibbs_burn_in;
  g.a = tau_prior_a;
  g.b = tau_prior_b;
  g.seed = seed;
  return g;
}

void CalibrationOptions::validate() const {
  const OptionCheck check("calibration");
  check.atLeast("threads", threads, 0);
  check.atLeast("optimizer_starts", optimizer_starts, 1);
  check.atLeast("lhs_points", lhs_points, 2);
  check.atLeast("gibbs_iterations", gibbs_iterations, 1);
  check.atLeast("gibbs_burn_in", gibbs_burn_in, 0);
  check.require(gibbs_burn_in < gibbs_iterations, "gibbs_burn_in",
                "must be below the number of Gibbs iterations (" +
                    std::to_string(gibbs_iterations) + "), got " + std::to_string(gibbs_burn_in));
  check.nonNegative("tau_prior_a", tau_prior_a);
  check.nonNegative("tau_prior_b", tau_prior_b);
  check.require(region == "joint" || region == "paper", "region",
                "must be \"joint\" or \"paper\", got \"" + region + "\"");
  check.require(interval == "profile" || interval == "posterior", "interval",
                "must be \"profile\" or \"posterior\", got \"" + interval + "\"");
  check.inRange("polish_step", polish_step, 0.0, 0.5);
  check.require(steps == "frozen" || steps == "adaptive", "steps",
                "must be \"frozen\" or \"adaptive\", got \"" + steps + "\"");
  profile.validate();
  optimizer.validate();
  box.validate();
  joint.validate();
  designOptions().validate();
  gibbsOptions().validate();
}

nlohmann::json CalibrationOptions::toJson() const {
  nlohmann::json j{
      {"optimizer_starts", optimizer_starts},
      {"lhs_points", lhs_points},
      {"gibbs_iterations", gibbs_iterations},
      {"gibbs_burn_in", gibbs_burn_in},
      {"tau_prior",
       {{"distribution", "Gamma(shape a, rate b)"}, {"a", tau_prior_a}, {"b", tau_prior_b}}},
      {"theta_prior", "uniform on the feasible box"},
      {"seed", seed},
      {"optimizer",
       {{"algorithm", optimizer.algorithm},
        {"xtol_rel", optimizer.xtol_rel},
        {"ftol_rel", optimizer.ftol_rel},
        {"maxeval", optimizer.maxeval},
        {"initial_step_scaled", optimizer.initial_step},
        {"screen_per_start", optimizer.screen_per_start}}},
      {"feasible_box",
       {{"rule", "SSE <= SSE_min (1 + 2 ln(100) / n): likelihood ratio 1 %"},
        {"initial_step_scaled", box.initial_step},
        {"growth", box.growth},
        {"tolerance_scaled", box.tolerance},
        {"max_evaluations_per_sweep", box.max_evaluations}}}};
  j["region"] = region;
  if (region == "joint") {
    j.erase("feasible_box");
    j["joint_region"] = joint.toJson();
  }
  j["design"] = designOptions().toJson();
  j["profile"] = profile.toJson();
  j["interval"] = interval;
  if (!extra_starts.empty()) j["extra_starts"] = extra_starts;
  if (polish_step > 0) j["polish_step"] = polish_step;
  j["steps"] = steps;
  return j;
}

/// Levenberg–Marquardt on the weighted residuals e = sqrt(w) (η(θ) − y) in the scaled
/// coordinates z ∈ [0,1]^d, from θ0 (minimiseOnSubspace on the whole box): a central-difference
/// Jacobian (step `h` scaled units, 2d simulations, in parallel), then Broyden updates after
/// every trial point until the carried Jacobian finds no better point or only a small gain
/// (fresh differences then); damping λ·diag(JᵀJ), a parameter on a bound held there. A
/// least-squares polish for sharp minima of dense data, where a derivative-free quadratic model
/// stalls. Returns the best point seen. The step must stay well above the integrator's noise: at
/// 2e-3 scaled units the residual differences of a damping rate were comparable with it and the
/// polish stalled 280 SSE units above the truth (dense diag_bump + diag_rough data); 1e-2 reaches
/// it.
StartResult polishLeastSquares(const LabObjective& obj, const std::vector<double>& theta0,
                               const PolishOptions& options) {
  const std::size_t d = theta0.size();
  const long dl = static_cast<long>(d);
  const auto& lo = obj.lower();
  const auto& up = obj.upper();
  const auto& y = obj.measured();
  const auto& w = obj.weights();
  auto toTheta = [&](const Eigen::VectorXd& z) {
    std::vector<double> th(d);
    for (std::size_t k = 0; k < d; ++k)
      th[k] = lo[k] + std::clamp(z[static_cast<long>(k)], 0.0, 1.0) * (up[k] - lo[k]);
    return th;
  };
  std::atomic<int> runs{0};
  const ScaledResiduals residual = [&](const Eigen::VectorXd& z, Eigen::VectorXd& e) {
    ++runs;
    const auto eta = obj.predict(toTheta(z));
    if (eta.empty()) return false;
    e.resize(static_cast<long>(y.size()));
    for (std::size_t i = 0; i < y.size(); ++i)
      e[static_cast<long>(i)] = std::sqrt(w[i]) * (eta[i] - y[i]);
    return e.allFinite();
  };
  StartResult res;
  res.start = theta0;
  res.theta = theta0;
  res.status = "LM_POLISH";
  Eigen::VectorXd z(dl), e;
  for (std::size_t k = 0; k < d; ++k)
    z[static_cast<long>(k)] = std::clamp((theta0[k] - lo[k]) / (up[k] - lo[k]), 0.0, 1.0);
  SubspaceLmSettings set;
  set.tries = 8;
  set.min_rel_gain = options.rel_gain;
  set.forward = options.forward;
  set.converge_on_fresh = true;
  set.lower = Eigen::VectorXd::Zero(dl);
  set.upper = Eigen::VectorXd::Ones(dl);
  set.threads = options.threads;
  double sse = 0.0;
  const bool ok = minimiseOnSubspace(
      residual, Eigen::VectorXd::Zero(dl), Eigen::MatrixXd::Identity(dl, dl),
      Eigen::VectorXd::Constant(dl, options.h), 30, 0.0, z, e, sse, options.carried, set);
  res.evaluations = runs.load();
  res.sse = ok ? sse : std::numeric_limits<double>::infinity();
  if (ok) res.theta = toTheta(z);
  return res;
}

// ------------------------------------------------------------------ integrator check
IntegratorCheck assessIntegrator(const std::vector<double>& eta,
                                 const std::vector<double>& eta_fine, const std::vector<double>& y,
                                 const std::vector<double>& w, double accuracy, double threshold) {
  DTWIN_CHECK(eta.size() == y.size() && eta_fine.size() == y.size() && w.size() == y.size(),
              "assessIntegrator: sizes differ");
  IntegratorCheck c;
  c.accuracy = accuracy;
  c.accuracy_check = accuracy / 10;
  c.threshold = threshold;
  double ee = 0.0, dd = 0.0, ff = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    ee += w[i] * (eta[i] - y[i]) * (eta[i] - y[i]);
    ff += w[i] * (eta_fine[i] - y[i]) * (eta_fine[i] - y[i]);
    dd += w[i] * (eta[i] - eta_fine[i]) * (eta[i] - eta_fine[i]);
  }
  c.sse = ee;
  c.sse_check = ff;
  c.prediction_change = std::sqrt(dd);
  c.jitter = y.empty() ? 0.0
                       : std::max(std::abs(ee - ff), 2.0 * std::sqrt(ee) * std::sqrt(dd) /
                                                         std::sqrt(static_cast<double>(y.size())));
  c.ok = !(c.threshold > 0) || c.jitter < 0.5 * c.threshold;
  if (!c.ok)
    c.message = "the integrator's error moves the SSE by about " + formatNumber(c.jitter, 3) +
                " at the optimum (accuracy " + formatNumber(c.accuracy, 3) + " against " +
                formatNumber(c.accuracy_check, 3) + "), against the 95 % intervals' threshold of " +
                formatNumber(c.threshold, 3) +
                ": the optimum and the intervals follow the integrator, not the data; tighten "
                "[simulation] accuracy "
                "(to " +
                formatNumber(c.accuracy_check, 3) + " or less) and rerun";
  return c;
}

double quadraticRoughness(const std::vector<double>& x, const std::vector<double>& f) {
  DTWIN_CHECK(x.size() == f.size() && x.size() >= 4, "quadraticRoughness: needs at least 4 points");
  const long m = static_cast<long>(x.size());
  Eigen::MatrixXd A(m, 3);
  Eigen::VectorXd b(m);
  const double x0 = x[x.size() / 2];
  double scale = 0.0;
  for (double v : x) scale = std::max(scale, std::abs(v - x0));
  if (!(scale > 0)) scale = 1.0;
  for (long i = 0; i < m; ++i) {
    const double u = (x[static_cast<std::size_t>(i)] - x0) / scale;
    A(i, 0) = 1.0;
    A(i, 1) = u;
    A(i, 2) = u * u;
    b[i] = f[static_cast<std::size_t>(i)];
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  return (A * c - b).cwiseAbs().maxCoeff();
}

double integratorOptimumShift(const Eigen::MatrixXd& J, const Eigen::VectorXd& g) {
  DTWIN_CHECK(J.cols() == g.size(), "integratorOptimumShift: J and g disagree");
  const Eigen::MatrixXd H = 2.0 * J.transpose() * J;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(H);
  const Eigen::VectorXd& ev = es.eigenvalues();
  const double tol = std::max(ev.cwiseAbs().maxCoeff(), 1e-300) * 1e-12;
  const Eigen::VectorXd p = es.eigenvectors().transpose() * g;
  double s = 0.0;
  for (long i = 0; i < ev.size(); ++i)
    if (ev[i] > tol) s += p[i] * p[i] / ev[i];
  return 0.5 * s;
}

std::vector<double> probeStepsFromJacobian(const Eigen::MatrixXd& J, double threshold) {
  const long d = J.cols();
  std::vector<double> h(static_cast<std::size_t>(d), 1e-2);
  if (d == 0 || !(threshold > 0) || !J.allFinite()) return h;
  const Eigen::MatrixXd H = J.transpose() * J;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(H);
  const Eigen::VectorXd& ev = es.eigenvalues();
  const double tol = std::max(ev.cwiseAbs().maxCoeff(), 1e-300) * 1e-12;
  for (long k = 0; k < d; ++k) {
    double c = 0.0;  // (JᵀJ)⁺_kk
    for (long i = 0; i < d; ++i)
      if (ev[i] > tol) c += es.eigenvectors()(k, i) * es.eigenvectors()(k, i) / ev[i];
    const double half = c > 0 ? std::sqrt(threshold * c) : 1.0;
    h[static_cast<std::size_t>(k)] = std::clamp(half / 10, 1e-4, 1e-2);
  }
  return h;
}

std::optional<ProbeFigures> takeOverProbe(const nlohmann::json& last,
                                          const std::vector<double>& theta,
                                          const std::vector<double>& h, double accuracy,
                                          const std::vector<double>& lower,
                                          const std::vector<double>& upper) {
  const std::size_t d = theta.size();
  if (!last.is_object() || !last.contains("at") || !last.contains("probe_step") ||
      !last.contains("accuracy"))
    return std::nullopt;
  if (last.value("kept", true) == false || !last.at("accuracy").is_number() ||
      last.at("accuracy").get<double>() != accuracy)
    return std::nullopt;
  const std::vector<double> at = numbersFromJson(last.at("at")),
                            step = numbersFromJson(last.at("probe_step"));
  if (at.size() != d || step.size() != d || h.size() != d || lower.size() != d || upper.size() != d)
    return std::nullopt;
  for (std::size_t k = 0; k < d; ++k) {
    if (!(std::abs(theta[k] - at[k]) <= 0.01 * h[k] * (upper[k] - lower[k]))) return std::nullopt;
    if (!(step[k] * 1.5 >= h[k] && step[k] <= 1.5 * h[k])) return std::nullopt;
  }
  return ProbeFigures{numberFromJson(last.at("roughness")),
                      numberFromJson(last.at("optimum_shift")),
                      numberFromJson(last.at("shift_floor"))};
}

void applyProbes(IntegratorCheck& c, double roughness, double optimum_shift, double shift_floor) {
  c.steps = "frozen";
  c.roughness = roughness;
  c.optimum_shift = optimum_shift;
  c.shift_floor = shift_floor;
  c.jitter = optimum_shift > 4 * shift_floor ? std::max(roughness, optimum_shift) : roughness;
  c.ok = !(c.threshold > 0) || c.jitter < 0.5 * c.threshold;
  c.message.clear();
  if (!c.ok)
    c.message = "with its steps frozen the integrator's error still moves the optimum by about " +
                formatNumber(optimum_shift, 3) +
                " (SSE units; the SSE departs from a quadratic by " + formatNumber(roughness, 3) +
                "), against the 95 % intervals' "
                "threshold of " +
                formatNumber(c.threshold, 3) +
                ": the optimum and the intervals follow the integrator, not the data; "
                "tighten [simulation] accuracy (to " +
                formatNumber(c.accuracy_check, 3) + " or less) and rerun";
}

// ------------------------------------------------------------------ calibrateAssembly
CalibrationResult calibrateAssembly(const Study& study, const AssemblySpec& assembly,
                                    const LabData& data, const std::string& scenario,
                                    const CalibrationOptions& options, const std::string& out_dir,
                                    const std::string& fingerprint_extra,
                                    const StageProgress& progress) {
  return calibrateAssembly(study, assembly,
                           std::vector<DataSet>{DataSet{"lab data", scenario, data}},
                           CalibrationSetup{}, options, out_dir, fingerprint_extra, progress);
}

CalibrationResult calibrateAssembly(const Study& study, const AssemblySpec& assembly,
                                    const std::vector<DataSet>& data, const CalibrationSetup& setup,
                                    const CalibrationOptions& options, const std::string& out_dir,
                                    const std::string& fingerprint_extra,
                                    const StageProgress& progress) {
  options.validate();
  CalibrationRun run(study, assembly, data, setup, options, out_dir, fingerprint_extra, progress);
  run.objective();  // the SSE against the data, the output folder, the resume fingerprint
  run.optimum();    // optimum.json
  run.region();     // box.json
  run.design();     // design_journal.csv, design.csv
  run.profile();    // profile.json
  run.sampler();    // posterior.csv
  run.integratorCheck();
  run.summary();  // summary.json
  return run.take();
}

CalibrationResult calibrateOptimum(const Study& study, const AssemblySpec& assembly,
                                   const std::vector<DataSet>& data, const CalibrationSetup& setup,
                                   const CalibrationOptions& options, const std::string& out_dir,
                                   const std::string& fingerprint_extra,
                                   const StageProgress& progress) {
  options.validate();
  CalibrationRun run(study, assembly, data, setup, options, out_dir, fingerprint_extra, progress);
  run.objective();
  run.optimum();  // optimum.json: a later calibrateAssembly of the same folder resumes from it
  return run.takeOptimum();
}

}  // namespace dtwin::calib
