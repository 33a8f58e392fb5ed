// The screening stage of diagnose() (docs/diagnosis.md, step 2): the base model linearised at its
// optimum, every candidate's probes simulated and scored against the residual, and their gates.
#include "diagnosis/diagnose_internal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include <Eigen/Dense>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/parallel.hpp"

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

/// The value a probe sets: off + f (far − off), far the prior end farther from the off value.
double towardFar(const ParameterSpec& p, double f) {
  const double off = p.default_value;
  const double far = (p.prior_upper - off >= off - p.prior_lower) ? p.prior_upper : p.prior_lower;
  return off + f * (far - off);
}

/// A parameter whose off value is at a prior bound adds strength (a bar rate); one whose off
/// value lies inside the prior only shapes the effect of the others (a gap) and is scanned.
bool isStrength(const ParameterSpec& p) {
  return p.default_value <= p.prior_lower || p.default_value >= p.prior_upper;
}

/// A length parameter's name without its unit suffix: "gap_m" -> "gap".
std::string withoutUnit(const std::string& parameter) {
  const std::string suffix = "_m";
  const bool has = parameter.size() > suffix.size() &&
                   parameter.compare(parameter.size() - suffix.size(), suffix.size(), suffix) == 0;
  std::string w = has ? parameter.substr(0, parameter.size() - suffix.size()) : parameter;
  std::replace(w.begin(), w.end(), '_', ' ');
  return w;
}

/// An orthonormal basis of the span of J's columns not marked in `skip` (n × 0 when none is left).
Eigen::MatrixXd basisWithout(const Eigen::MatrixXd& J, const std::vector<bool>& skip) {
  long kept = 0;
  for (long c = 0; c < J.cols(); ++c) kept += skip[static_cast<std::size_t>(c)] ? 0 : 1;
  Eigen::MatrixXd Jk(J.rows(), kept);
  for (long c = 0, o = 0; c < J.cols(); ++c)
    if (!skip[static_cast<std::size_t>(c)]) Jk.col(o++) = J.col(c);
  if (kept == 0) return Jk;
  Eigen::HouseholderQR<Eigen::MatrixXd> q(Jk);
  return q.householderQ() * Eigen::MatrixXd::Identity(Jk.rows(), kept);
}

}  // namespace

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
  for (std::size_t i = 0; i < n; ++i)
    lin.r[static_cast<long>(i)] = std::sqrt(w[i]) * (y[i] - lin.eta_hat[i]);
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
    // NOLINTBEGIN(bugprone-branch-clone): the first and last cases step alike, said apart
    if (up[k] < 0.5 * h[k] && down[k] < 0.5 * h[k])
      up[k] = down[k] = h[k];  // a range narrower than the step: both sides
    else if (up[k] < 0.5 * h[k])
      up[k] = 0.0, down[k] = h[k];
    else if (down[k] < 0.5 * h[k])
      down[k] = 0.0, up[k] = h[k];
    else
      up[k] = down[k] = h[k];
    // NOLINTEND(bugprone-branch-clone)
  }
  parallelFor(2 * dim, d.options.threads, [&](std::size_t t, int) {
    const std::size_t k = t / 2;
    auto th = lin.theta_hat;
    th[k] += t % 2 == 0 ? up[k] : -down[k];
    (t % 2 == 0 ? plus[k] : minus[k]) =
        (t % 2 == 0 ? up[k] : down[k]) == 0.0 ? lin.eta_hat : obj.predict(th);
  });
  for (std::size_t k = 0; k < dim; ++k) {
    if (plus[k].empty() || minus[k].empty())
      throw std::runtime_error("diagnose: a sensitivity run at the base optimum failed (" +
                               obj.names()[k] + " = " + fmt("%.6g", lin.theta_hat[k]) + ")");
    for (std::size_t i = 0; i < n; ++i)
      J(static_cast<long>(i), static_cast<long>(k)) =
          std::sqrt(w[i]) * (plus[k][i] - minus[k][i]) / (up[k] + down[k]);
  }
  lin.qr.compute(J);
  lin.J = std::move(J);
  std::vector<bool> at_lower(dim), at_upper(dim);
  for (std::size_t k = 0; k < dim; ++k) at_lower[k] = down[k] == 0.0, at_upper[k] = up[k] == 0.0;
  setProjection(lin, at_lower, at_upper);
  return lin;
}

void setProjection(Linearisation& lin, const std::vector<bool>& at_lower,
                   const std::vector<bool>& at_upper) {
  // A value on a bound that the residual pushes beyond (a compensation the range stops, e.g. an
  // inertia at its lower bound): re-calibrating cannot move it that way.
  const Eigen::VectorXd push = lin.J.transpose() * lin.r;  // the unconstrained step's direction
  const auto dim = static_cast<std::size_t>(lin.J.cols());
  lin.held.assign(dim, 0);
  std::vector<bool> skip(dim, false);
  for (std::size_t k = 0; k < dim; ++k) {
    const auto kk = static_cast<long>(k);
    lin.held[k] = at_lower[k] && push[kk] < 0.0 ? 1 : at_upper[k] && push[kk] > 0.0 ? -1 : 0;
    skip[k] = lin.held[k] != 0;
  }
  lin.Q = basisWithout(lin.J, skip);
}

Eigen::MatrixXd Linearisation::projectWithout(std::size_t k, const Eigen::MatrixXd& G) const {
  std::vector<bool> skip(held.size());
  for (std::size_t c = 0; c < held.size(); ++c) skip[c] = held[c] != 0 || c == k;
  const Eigen::MatrixXd Qk = basisWithout(J, skip);
  return G - Qk * (Qk.transpose() * G);
}

double Linearisation::score(const Eigen::MatrixXd& Gp, long skip, Eigen::VectorXd& coef,
                            long& rank) const {
  // The held values' columns, signed inward and projected as Gp is (at most kMaxHeld: beyond, the
  // rest stay fixed on their bounds).
  constexpr std::size_t kMaxHeld = 6;
  std::vector<std::size_t> hk;
  for (std::size_t k = 0; k < held.size(); ++k)
    if (held[k] != 0 && static_cast<long>(k) != skip && hk.size() < kMaxHeld) hk.push_back(k);
  Eigen::MatrixXd H(J.rows(), static_cast<long>(hk.size()));
  for (std::size_t i = 0; i < hk.size(); ++i)
    H.col(static_cast<long>(i)) = held[hk[i]] * J.col(static_cast<long>(hk[i]));
  if (!hk.empty()) H = skip >= 0 ? projectWithout(static_cast<std::size_t>(skip), H) : project(H);
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod_g(Gp);
  rank = cod_g.rank();
  coef = Eigen::VectorXd::Zero(Gp.cols());
  // Bounded least squares by its active sets: for each subset of the held columns let free, the
  // unconstrained fit; the best fit whose held coefficients are all ≥ 0 is the bounded minimum.
  auto best = [&](bool with_g, Eigen::VectorXd* c_out) {
    double top = 0.0;
    for (std::size_t mask = 0; mask < (std::size_t{1} << hk.size()); ++mask) {
      const long nh = __builtin_popcountll(mask);
      Eigen::MatrixXd M(J.rows(), nh + (with_g ? Gp.cols() : 0));
      for (long i = 0, o = 0; i < static_cast<long>(hk.size()); ++i)
        if (mask >> i & 1U) M.col(o++) = H.col(i);
      if (with_g) M.rightCols(Gp.cols()) = Gp;
      if (M.cols() == 0) continue;
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(M);
      const Eigen::VectorXd x = cod.solve(r);
      if (nh > 0 && x.head(nh).minCoeff() < 0.0) continue;
      const double s = (M * x).squaredNorm();
      if (s <= top) continue;
      top = s;
      if (c_out) *c_out = x.tail(Gp.cols());
    }
    return top;
  };
  if (rank == 0) return 0.0;
  const double with = best(true, &coef);
  return hk.empty() ? with : std::max(0.0, with - best(false, nullptr));
}

/// The probes of effect `e` (docs/diagnosis.md, screening): every strength parameter at 5, 20 and
/// 60 % of the way to its far prior end, for every point of the scan (10, 30, 60 % of the prior)
/// of the parameters whose off value lies inside their prior.
std::vector<ProbeGroup> probesOf(std::size_t e, const CandidateSpec& candidate, double at,
                                 long theta_index) {
  if (candidate.kind == "option") return {};  // not nested: no score test (always confirmed)
  if (candidate.kind == "range") {
    // Beyond the study's bound the value sits at (the upper one when unknown), 5, 20 and 60 % of
    // the way to its physical limit.
    const bool lower = std::isfinite(at) && at - candidate.study_lower < candidate.study_upper - at;
    const double b = lower ? candidate.study_lower : candidate.study_upper;
    const double lim =
        lower ? candidate.parameters[0].prior_lower : candidate.parameters[0].prior_upper;
    std::vector<ProbeGroup> groups;
    if (lim == b) return groups;
    for (double level : {0.05, 0.2, 0.6})
      groups.push_back({e, {{b + level * (lim - b)}}, theta_index});
    return groups;
  }
  const auto& ps = candidate.parameters;
  const std::vector<double> off = offValues(candidate);
  std::vector<std::size_t> strength, scan;
  // A sensor's place enters its reading linearly (a = heave − x·pitch'' + y·roll''): both
  // coordinates are directions of one group, so the test sees any place, not only the scanned ones.
  const bool linear = candidate.kind == "place";
  for (std::size_t k = 0; k < ps.size(); ++k)
    (k == 0 || linear || isStrength(ps[k]) ? strength : scan).push_back(k);
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

namespace {

/// The predictions at every probe column, in group then column order (empty: a failed run), on
/// `eff_obj` (per catalogue effect; the reference model for a range candidate's probes). A probe
/// whose run throws fails its candidate: `failed` (per catalogue effect) gets the message of its
/// first such probe, in job order (whatever the thread count).
std::vector<std::vector<double>> simulateProbes(
    const Diagnosis& d, const std::vector<ProbeGroup>& groups, const std::vector<double>& theta_hat,
    const std::vector<std::unique_ptr<calib::LabObjective>>& eff_obj,
    std::vector<std::string>& failed) {
  std::vector<std::pair<std::size_t, std::size_t>> jobs;  // (group, column)
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t c = 0; c < groups[g].cols.size(); ++c) jobs.push_back({g, c});
  std::vector<std::vector<double>> probe_eta(jobs.size());
  std::vector<std::string> errors(jobs.size());
  d.report("screening: probes", 0, jobs.size());
  parallelFor(jobs.size(), d.options.threads, [&](std::size_t j, int) {
    const auto& g = groups[jobs[j].first];
    try {
      auto th = theta_hat;
      if (g.theta_index >= 0) {
        th[static_cast<std::size_t>(g.theta_index)] = g.cols[jobs[j].second][0];
        probe_eta[j] = d.base_obj->predict(th);
        return;
      }
      for (double v : g.cols[jobs[j].second]) th.push_back(v);
      probe_eta[j] = eff_obj[g.effect]->predict(th);
    } catch (const std::exception&
                 e) {  // this candidate's alone (an InputError is a failed run: LabObjective)
      probe_eta[j].clear();
      errors[j] = oneLine(e.what());
    }
  });
  d.report("screening: probes", jobs.size(), jobs.size());
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    auto& f = failed[groups[jobs[j].first].effect];
    if (!errors[j].empty() && f.empty()) f = "its screening failed: " + errors[j];
  }
  return probe_eta;
}

/// Scores every probe group: S = rᵀ P r, P the projection on span(g⊥) (g⊥ the group's
/// contributions with span(J) projected out), rank(g⊥) degrees of freedom. Each candidate keeps its
/// largest S, its largest ‖g⊥‖², and the linearised estimate of the effect's and the base
/// parameters at its best probe. Returns, per catalogue effect, whether every probe group failed.
std::vector<bool> scoreProbes(Diagnosis& d, const Linearisation& lin,
                              const std::vector<ProbeGroup>& groups,
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
        G(static_cast<long>(i), static_cast<long>(c)) =
            std::sqrt(w[i]) * (probe_eta[j][i] - lin.eta_hat[i]);
    }
    if (failed) continue;
    all_failed[e] = false;
    const long k_range = groups[g].theta_index;
    const Eigen::MatrixXd Gp =
        k_range >= 0 ? lin.projectWithout(static_cast<std::size_t>(k_range), G) : lin.project(G);
    auto& cand = d.stage()[e];
    cand.max_signal = std::max(cand.max_signal, Gp.squaredNorm());
    // S = rᵀ Gp (Gpᵀ Gp)⁺ Gpᵀ r (rank-revealing: a column the base absorbs entirely drops out),
    // with a value held on its bound free to move back inside only (Linearisation::score).
    Eigen::VectorXd coef;
    long rank = 0;
    const double S = lin.score(Gp, k_range, coef, rank);
    if (rank == 0) continue;
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
          const double v = ps[k].default_value + coef[static_cast<long>(col)] *
                                                     (groups[g].cols[col][k] - ps[k].default_value);
          est[k] = std::clamp(v, ps[k].prior_lower, ps[k].prior_upper);
        }
    cand.screening_estimate = est;
    // The base parameters of the joint linearised fit r ≈ J δθ + G c: δθ = J⁺ (r − G c).
    const Eigen::VectorXd dtheta = lin.qr.solve(lin.r - G * coef);
    cand.screening_theta = lin.theta_hat;
    for (std::size_t k = 0; k < dim; ++k)
      cand.screening_theta[k] = std::clamp(lin.theta_hat[k] + dtheta[static_cast<long>(k)],
                                           d.base_obj->lower()[k], d.base_obj->upper()[k]);
  }
  return all_failed;
}

/// The model's largest suspension compression [m] over the fit data at θ̂ (every corner).
double maxCompression(const Diagnosis& d, const std::vector<double>& theta_hat) {
  double max_compression = -std::numeric_limits<double>::infinity();
  for (const auto& t : d.base_obj->traces(theta_hat))
    for (const char* c : {"fl", "fr", "rl", "rr"})
      for (double q : t.column(std::string("susp_defl_") + c + "_m"))
        max_compression = std::max(max_compression, q);
  return max_compression;
}

/// The p-value of every candidate (Bonferroni over `probes`) and its gate: why an effect cannot
/// matter in these data (no plausible value changes them; an engagement threshold the travel
/// never reaches; a contribution below the noise; a failed probe).
void gateCandidates(Diagnosis& d, const std::vector<double>& theta_hat, std::size_t probes,
                    const std::vector<bool>& all_failed) {
  const double bonferroni = static_cast<double>(probes);
  std::optional<double> max_compression;  // one more run, only when a threshold gate needs it
  for (std::size_t e = 0; e < d.catalogue.size(); ++e) {
    auto& c = d.stage()[e];
    c.p_value = std::min(1.0, bonferroni * chi2Upper(c.score, c.score_dof));
    if (!c.failed.empty() || !c.gate.empty())
      continue;  // failed, or gated before its probes (screen)
    const auto& spec = d.spec(c.effect);
    if (spec.kind == "option") continue;  // not screened: always confirmed
    const auto& names = d.base_obj->names();
    if (spec.kind == "range" &&
        std::find(names.begin(), names.end(), spec.calibrated_names[0]) == names.end()) {
      c.gate = "this model has no " + spec.calibrated_names[0] + " to widen (" +
               joinEffects(d.installed) + " leaves it out)";
      continue;
    }
    if (all_failed[e]) {
      c.gate = "every probe simulation failed";
    } else if (c.max_signal == 0.0) {
      const std::string& threshold = spec.engagement_threshold;
      if (!threshold.empty()) {
        if (!max_compression) max_compression = maxCompression(d, theta_hat);
        const double smallest =
            spec.parameters[parameterIndex(spec.parameters, threshold)].prior_lower;
        c.gate = "the suspension never compresses beyond the smallest plausible " +
                 withoutUnit(threshold) + " (" + fmt("%.3g", *max_compression) + " m < " +
                 fmt("%.3g", smallest) + " m): " + inWords(c.effect) + " cannot act here";
      } else {
        c.gate = spec.kind == "effect" ? "exerts no force in these runs at any plausible value"
                                       : "changes nothing in these data at any plausible value";
      }
    } else if (c.max_signal < 1.0) {
      c.gate =
          "its largest plausible contribution, after re-calibrating the base parameters, is below "
          "the noise (" +
          fmt("%.2g", c.max_signal) + " noise variances in total): these data cannot show it";
    }
  }
}

}  // namespace

/// Screen (docs/diagnosis.md, `twin diagnose` step 2): at the base optimum θ̂, every catalogue
/// effect's contribution at a few probe values, with what re-calibrating θ could absorb projected
/// out, scored against the residual; fills res.candidates (score, p-value, gate, screening
/// estimates).
void screen(Diagnosis& d) {
  d.base_obj = std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets,
                                                     d.setupOf(d.installed));
  const Linearisation lin = linearise(d);
  std::vector<ProbeGroup> groups;
  auto& cands = d.stage();
  cands.resize(d.catalogue.size());
  const auto& names = d.base_obj->names();
  // Each candidate's screening is its own: one whose model cannot be built or whose probe throws
  // fails alone (Candidate::failed) and the others are screened.
  std::vector<std::unique_ptr<calib::LabObjective>> eff_obj(d.catalogue.size());
  std::vector<std::string> failed(d.catalogue.size());
  for (std::size_t e = 0; e < d.catalogue.size(); ++e) {
    const auto& spec = d.spec(d.catalogue[e]);
    cands[e].effect = d.catalogue[e];
    cands[e].kind = spec.kind;
    cands[e].signature = spec.signature;
    double at = std::numeric_limits<double>::quiet_NaN();
    long index = -1;
    if (spec.kind == "range") {
      const auto it = std::find(names.begin(), names.end(), spec.calibrated_names[0]);
      if (it == names.end())
        continue;  // the model lacks the value (another option left it out): gated below
      index = static_cast<long>(it - names.begin());
      at = lin.theta_hat[static_cast<std::size_t>(index)];
    }
    if (spec.kind == "option") continue;  // not nested: not screened (always confirmed)
    try {
      const auto model = d.withInstalled(d.catalogue[e]);
      if (d.options.before_candidate_step)
        d.options.before_candidate_step(joinEffects(model), "screen");
      if (spec.addsParameters())
        eff_obj[e] = std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets,
                                                           d.setupOf(model));
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& ex) {
      cands[e].failed = "its screening failed: " + oneLine(ex.what());
      continue;
    }
    // A value of the candidate that the model with the causes installed lacks (a tire's factor
    // on top of tire=hub): the candidate does not exist on this model.
    std::string lacks;
    if (eff_obj[e])
      for (const auto& n : eff_obj[e]->leftOut())
        if (std::find(spec.calibrated_names.begin(), spec.calibrated_names.end(), n) !=
            spec.calibrated_names.end())
          lacks += (lacks.empty() ? "" : ", ") + n;
    if (!lacks.empty()) {
      cands[e].gate =
          "this model has no " + lacks +
          (d.installed.empty() ? "" : " (" + joinEffects(d.installed) + " leaves it out)");
      eff_obj[e].reset();
      continue;
    }
    for (auto& g : probesOf(e, spec, at, index)) groups.push_back(std::move(g));
  }
  const auto probe_eta = simulateProbes(d, groups, lin.theta_hat, eff_obj, failed);
  for (std::size_t e = 0; e < d.catalogue.size(); ++e)
    if (!failed[e].empty()) cands[e].failed = failed[e];
  const auto all_failed = scoreProbes(d, lin, groups, probe_eta);
  gateCandidates(d, lin.theta_hat, groups.size(), all_failed);
}

}  // namespace dtwin::diag
