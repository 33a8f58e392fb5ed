#include "calibration/profile.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>

#include "calibration/subspace_lm.hpp"
#include "common/errors.hpp"

namespace dtwin::calib {
namespace {

/// Continued fraction of the incomplete beta function (modified Lentz), x < (a+1)/(a+b+2).
double betaContinuedFraction(double a, double b, double x) {
  const double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::abs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 500; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
    d = 1.0 + aa * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < 1e-15) break;
  }
  return h;
}

/// Regularized incomplete beta I_x(a, b), with y = 1 − x given separately (no cancellation).
double incompleteBeta(double a, double b, double x, double y) {
  if (x <= 0.0) return 0.0;
  if (y <= 0.0) return 1.0;
  const double lbt =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log(y);
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(lbt) * betaContinuedFraction(a, b, x) / a;
  return 1.0 - std::exp(lbt) * betaContinuedFraction(b, a, y) / b;
}

/// Student t CDF: P(T <= t) = 1 − I_x(ν/2, 1/2)/2 for t >= 0, x = ν/(ν + t²).
double studentCdf(double t, double nu) {
  const double x = nu / (nu + t * t), y = t * t / (nu + t * t);
  const double tail = 0.5 * incompleteBeta(0.5 * nu, 0.5, x, y);
  return t >= 0.0 ? 1.0 - tail : tail;
}

}  // namespace

double studentQuantile(double p, double nu) {
  if (!(p > 0.0 && p < 1.0))
    throw InputError("student quantile", "p must lie in (0, 1), got " + formatNumber(p));
  if (!(nu > 0.0 && std::isfinite(nu)))
    throw InputError("student quantile",
                     "degrees of freedom must be finite and > 0, got " + formatNumber(nu));
  double lo = -1.0, hi = 1.0;
  while (studentCdf(lo, nu) > p) lo *= 2.0;
  while (studentCdf(hi, nu) < p) hi *= 2.0;
  for (int it = 0; it < 200 && hi - lo > 1e-12 * std::max(1.0, std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (studentCdf(mid, nu) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void ProfileOptions::validate() const {
  const std::string where = "profile options";
  if (!(level > 0.0 && level < 1.0))
    throw InputError(where, "level must lie in (0, 1), got " + formatNumber(level));
  if (steps < 0) throw InputError(where, "steps must be >= 0, got " + std::to_string(steps));
  if (lm_iterations < 1)
    throw InputError(where, "lm_iterations must be >= 1, got " + std::to_string(lm_iterations));
  if (restarts < 0)
    throw InputError(where, "restarts must be >= 0, got " + std::to_string(restarts));
  if (polish_iterations < 0)
    throw InputError(where,
                     "polish_iterations must be >= 0, got " + std::to_string(polish_iterations));
}

nlohmann::json ProfileOptions::toJson() const {
  return {
      {"rule", "{v : SSE_profile(v) <= SSE* + c s^2}, c = F(1, n-d) quantile, s^2 = SSE*/(n-d)"},
      {"level", level},
      {"steps_per_end", steps},
      {"lm_iterations", lm_iterations},
      {"restarts", restarts},
      {"polish_iterations", polish_iterations}};
}

ProfilePlan planProfile(const Eigen::MatrixXd& points, const std::vector<double>& sse, int n_data,
                        const std::vector<double>& lower, const std::vector<double>& upper,
                        const ProfileOptions& options, const CorrelationAdjustment& correlation) {
  options.validate();
  DTWIN_CHECK(static_cast<std::size_t>(points.rows()) == sse.size(),
              "planProfile needs one SSE per point");
  const int d = static_cast<int>(points.cols());
  ProfilePlan p;
  p.lower = lower;
  p.upper = upper;
  p.n_data = n_data;
  p.points = points;
  p.sse = sse;
  p.dof = n_data > d ? n_data - d : n_data;
  p.sse_best = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < points.rows(); ++k)
    if (const double s = sse[static_cast<std::size_t>(k)]; std::isfinite(s) && s < p.sse_best) {
      p.sse_best = s;
      p.best_point.resize(static_cast<std::size_t>(d));
      for (int j = 0; j < d; ++j) p.best_point[static_cast<std::size_t>(j)] = points(k, j);
    }
  if (!std::isfinite(p.sse_best))
    throw InputError("profile interval", "no evaluated point has a finite SSE");
  p.s2 = p.sse_best / p.dof;
  const double t = studentQuantile(0.5 + 0.5 * options.level, p.dof);
  p.c = t * t;
  p.threshold = p.sse_best + p.c * p.s2;
  p.thresholds.assign(static_cast<std::size_t>(d), p.threshold);
  if (correlation.blocks > 0) {
    DTWIN_CHECK(static_cast<int>(correlation.kappa.size()) == d,
                "planProfile: one kappa per parameter");
    p.correlation = correlation;
    for (int j = 0; j < d; ++j)
      p.thresholds[static_cast<std::size_t>(j)] =
          p.sse_best + correlation.quantile * p.s2 * correlation.kappa[static_cast<std::size_t>(j)];
  }
  p.low_point.assign(static_cast<std::size_t>(d), {});
  p.high_point.assign(static_cast<std::size_t>(d), {});
  p.low_sse.assign(static_cast<std::size_t>(d), 0.0);
  p.high_sse.assign(static_cast<std::size_t>(d), 0.0);
  for (Eigen::Index k = 0; k < points.rows(); ++k) {
    const double s = sse[static_cast<std::size_t>(k)];
    if (!std::isfinite(s)) continue;
    std::vector<double> th(static_cast<std::size_t>(d));
    for (int j = 0; j < d; ++j) th[static_cast<std::size_t>(j)] = points(k, j);
    for (int j = 0; j < d; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      if (!(s <= p.thresholds[jj])) continue;
      if (p.low_point[jj].empty() || th[jj] < p.low_point[jj][jj]) {
        p.low_point[jj] = th;
        p.low_sse[jj] = s;
      }
      if (p.high_point[jj].empty() || th[jj] > p.high_point[jj][jj]) {
        p.high_point[jj] = th;
        p.high_sse[jj] = s;
      }
    }
  }
  return p;
}

namespace {

/// θ (physical) in the plan's scaled coordinates z = (θ − lower) / (upper − lower).
Eigen::VectorXd scaledOf(const ProfilePlan& plan, const std::vector<double>& th) {
  Eigen::VectorXd z(static_cast<Eigen::Index>(plan.lower.size()));
  for (std::size_t k = 0; k < plan.lower.size(); ++k)
    z(static_cast<Eigen::Index>(k)) = (th[k] - plan.lower[k]) / (plan.upper[k] - plan.lower[k]);
  return z;
}

/// A scaled point back in physical units, clamped to the bounds (the upper bound exactly at z = 1).
std::vector<double> physicalOf(const ProfilePlan& plan, const Eigen::VectorXd& z) {
  std::vector<double> th(plan.lower.size());
  for (std::size_t k = 0; k < th.size(); ++k) {
    const double zk = std::clamp(z(static_cast<Eigen::Index>(k)), 0.0, 1.0);
    th[k] = zk >= 1.0 ? plan.upper[k] : plan.lower[k] + zk * (plan.upper[k] - plan.lower[k]);
  }
  return th;
}

/// Restart points for a profile point of parameter j at v (scaled): the evaluated points of lowest
/// SSE with |z_j − v| <= band, their other coordinates (not the warm start's own, nor each
/// other's), best first, at most `count`.
std::vector<Eigen::VectorXd> restartsNear(const ProfilePlan& plan, int j, double v, double band,
                                          const Eigen::VectorXd& warm, int count) {
  const auto d = static_cast<int>(plan.lower.size());
  std::vector<std::pair<double, Eigen::VectorXd>> cand;
  for (Eigen::Index q = 0; q < plan.points.rows(); ++q) {
    const double f = plan.sse[static_cast<std::size_t>(q)];
    if (!std::isfinite(f)) continue;
    std::vector<double> th(static_cast<std::size_t>(d));
    for (int k = 0; k < d; ++k) th[static_cast<std::size_t>(k)] = plan.points(q, k);
    const Eigen::VectorXd zq = scaledOf(plan, th);
    if (std::abs(zq(j) - v) > band) continue;
    Eigen::VectorXd uq(d - 1);
    for (int k = 0, c = 0; k < d; ++k)
      if (k != j) uq(c++) = zq(k);
    if ((uq - warm).norm() < 1e-3) continue;
    cand.emplace_back(f, uq);
  }
  std::stable_sort(cand.begin(), cand.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Eigen::VectorXd> out;
  for (const auto& c : cand) {
    if (static_cast<int>(out.size()) >= count) break;
    bool distinct = true;
    for (const auto& o : out) distinct = distinct && (o - c.second).norm() >= 1e-3;
    if (distinct) out.push_back(c.second);
  }
  return out;
}

/// One profile point at z0: the other coordinates u re-minimised from the warm start `u` with the
/// end's carried Jacobian; a point that ends outside the threshold gets `polish_iterations` more
/// with a fresh Jacobian (a curved valley, or a stale Jacobian), then the restarts `starts()`
/// (another basin), the lowest fit counting. False when no simulation of it succeeded.
bool profilePoint(const ScaledResiduals& res, const Eigen::VectorXd& z0, const Eigen::MatrixXd& B,
                  const Eigen::VectorXd& h, const ProfilePlan& plan, double threshold,
                  const ProfileOptions& options, SubspaceJacobian& jac, Eigen::VectorXd& u,
                  double& f, const std::function<std::vector<Eigen::VectorXd>()>& starts) {
  Eigen::VectorXd r;
  SubspaceLmSettings lm;
  lm.forward = options.forward_differences;
  bool ok =
      minimiseOnSubspace(res, z0, B, h, options.lm_iterations, 0.05 * plan.s2, u, r, f, &jac, lm);
  if (ok && f > threshold && options.polish_iterations > 0) {
    Eigen::VectorXd up = u, rp;
    double fp = 0.0;
    jac.clear();
    if (minimiseOnSubspace(res, z0, B, h, options.polish_iterations, 0.05 * plan.s2, up, rp, fp,
                           &jac, lm) &&
        fp < f) {
      f = fp;
      u = up;
    }
  }
  if (ok && f <= threshold) return true;
  for (const Eigen::VectorXd& start : starts()) {
    Eigen::VectorXd ur = start, rr;
    double fr = 0.0;
    if (minimiseOnSubspace(res, z0, B, h, options.lm_iterations, 0.05 * plan.s2, ur, rr, fr, &jac,
                           lm) &&
        (!ok || fr < f)) {
      ok = true;
      f = fr;
      u = ur;
    }
    if (ok && f <= threshold) break;
  }
  return ok;
}

/// Where a profile end's search (refineProfileEnd) looks next, in v = z_j, from what it knows:
/// the last inside point (v_in, g_in), the secant's other point (v_prev, g_prev) and, once a point
/// was outside, that point (v_out, g_out); g = √(SSE_p − SSE*), the end where g = g_T.
struct EndBracket {
  double v_in, g_in, v_prev, g_prev;
  bool have_out;
  double v_out, g_out;
};

/// The next v of a profile end (direction s = ±1), or none when the last inside point is the end:
/// before anything outside is known, a secant step (aimed half a tolerance short of the crossing
/// it predicts; a point landing there is inside and ends the search, one just past it would be
/// an outside point, which costs a polish and restarts), or, without a secant, a growing step;
/// in a bracket, linear interpolation of g, kept 10 % inside it and aimed the same way. It stops
/// when the predicted crossing is within `tol` of v_in, or the bracket is narrower than that.
std::optional<double> nextEndTarget(const EndBracket& b, double g_T, double tol, double width_j,
                                    int s, int step) {
  if (!b.have_out) {
    const double dist = std::abs(b.v_in - b.v_prev);
    const bool secant = dist > 0.0 && b.g_in > b.g_prev;
    const double ahead = secant ? (g_T - b.g_in) * dist / (b.g_in - b.g_prev) : 0.0;
    if (secant && step > 0 && ahead < tol) return std::nullopt;
    const double grow = 4.0 * std::max(dist, 0.25 * std::max(width_j, 0.08));
    // A secant that puts the end close ahead is followed (down to the tolerance): a step
    // stretched to a minimum length would land outside.
    const double reach = std::clamp(secant ? ahead - 0.5 * tol : grow,
                                    secant ? tol : 0.05 * std::max(width_j, 0.02), grow);
    return std::clamp(b.v_in + s * reach, 0.0, 1.0);
  }
  const double span = std::abs(b.v_out - b.v_in);
  if (span < tol) return std::nullopt;
  const double ahead = b.g_out > b.g_in ? span * (g_T - b.g_in) / (b.g_out - b.g_in) : 0.5 * span;
  if (b.g_out > b.g_in && ahead < tol) return std::nullopt;
  return b.v_in + std::clamp((ahead - 0.5 * tol) / span, 0.1, 0.9) * (b.v_out - b.v_in);
}

}  // namespace

// Kept whole on purpose: the secant / regula falsi search shares its bracket (v_in, g_in, v_prev,
// g_prev, v_out, g_out) and the subspace coordinates with the restarts of each step; the scaling,
// the restart choice and one profile point are the functions above.
ProfileEnd refineProfileEnd(const ResidualFunction& residuals, const ProfilePlan& plan, int index,
                            const ProfileOptions& options) {
  options.validate();
  const int d = static_cast<int>(plan.lower.size());
  DTWIN_CHECK(index >= 0 && index < 2 * d, "profile end index out of range");
  const int j = index / 2, s = index % 2 == 0 ? -1 : +1;
  const auto jj = static_cast<std::size_t>(j);
  ProfileEnd end;
  end.theta = s < 0 ? plan.low_point[jj] : plan.high_point[jj];
  end.sse = s < 0 ? plan.low_sse[jj] : plan.high_sse[jj];
  auto physical = [&](const Eigen::VectorXd& zz) { return physicalOf(plan, zz); };
  Eigen::VectorXd z = scaledOf(plan, end.theta);
  const double bound = s < 0 ? 0.0 : 1.0;
  if (std::abs(z(j) - bound) < 1e-12) {
    end.at_bound = true;
    return end;
  }
  if (options.steps == 0 || d < 1) return end;
  // The interval of every parameter among the inside points, in scaled units (step sizes).
  Eigen::VectorXd width(d);
  for (int k = 0; k < d; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    width(k) =
        (plan.high_point[kk][kk] - plan.low_point[kk][kk]) / (plan.upper[kk] - plan.lower[kk]);
  }
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(d, d - 1);
  Eigen::VectorXd h(d - 1);
  for (int k = 0, c = 0; k < d; ++k) {
    if (k == j) continue;
    B(k, c) = 1.0;
    h(c) = std::clamp(0.05 * width(k), 1e-6, 0.02);
    ++c;
  }
  const ScaledResiduals res = [&](const Eigen::VectorXd& zz, Eigen::VectorXd& r) {
    ++end.evaluations;
    const auto v = residuals(physical(zz));
    if (v.empty()) return false;
    r = Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
    return r.allFinite();
  };
  // The search in v = z_j: g(v) = sqrt(SSE_p(v) − SSE*) is linear in v for a quadratic profile;
  // the end is where g = g_T = sqrt(threshold − SSE*). Secant steps on the last two inside points
  // while nothing outside is known (at most 4 times the distance covered, and to the bound), then
  // regula falsi in the bracket (nextEndTarget); the tolerance is 1 % of the interval's width.
  const double threshold = plan.thresholdOf(j);
  const double g_T = std::sqrt(threshold - plan.sse_best);
  auto gOf = [&](double f) { return std::sqrt(std::max(f - plan.sse_best, 0.0)); };
  // v at the best fit (the evaluated point of lowest SSE; it holds the optimum), where g = 0: the
  // other end of the secant to start with.
  double best_v = 0.0;
  {
    const auto best = std::min_element(plan.sse.begin(), plan.sse.end()) - plan.sse.begin();
    best_v = (plan.points(best, j) - plan.lower[jj]) / (plan.upper[jj] - plan.lower[jj]);
  }
  double v_in = z(j), g_in = gOf(end.sse), v_prev = best_v, g_prev = 0.0;
  bool in_is_floor =
      false;  // v_in is a profile point (not the evaluated point the end starts from)
  bool have_out = false;
  double v_out = bound, g_out = 0.0;
  const double tol = std::max(0.01 * std::max(width(j), 1e-3), 1e-9);
  Eigen::VectorXd u(d - 1);
  for (int k = 0, c = 0; k < d; ++k)
    if (k != j) u(c++) = z(k);
  SubspaceJacobian jac;  // carried from one profile point to the next (subspace_lm.hpp)
  for (int step = 0; step < options.steps; ++step) {
    const std::optional<double> next = nextEndTarget(
        {v_in, g_in, v_prev, g_prev, have_out, v_out, g_out}, g_T, tol, width(j), s, step);
    if (!next) break;
    const double target = *next;
    if (std::abs(target - v_in) < 1e-12) break;
    Eigen::VectorXd z0 = Eigen::VectorXd::Zero(d);
    z0(j) = target;
    Eigen::VectorXd un = u;
    double f = 0.0;
    const bool ok = profilePoint(res, z0, B, h, plan, threshold, options, jac, un, f, [&] {
      return restartsNear(plan, j, target,
                          std::max(std::abs(target - v_in), 0.05 * std::max(width(j), 0.02)), un,
                          options.restarts);
    });
    if (ok && f <= threshold) {
      // The secant's other point: the last profile point, or, after the first, the best fit (g =
      // 0), not the evaluated point the end started from, whose SSE is above the profile's there
      // and would flatten the secant into overshooting.
      v_prev = in_is_floor ? v_in : best_v;
      g_prev = in_is_floor ? g_in : 0.0;
      in_is_floor = true;
      v_in = target;
      g_in = gOf(f);
      u = un;
      z = z0 + B * u;
      end.theta = physical(z);
      end.sse = f;
      ++end.steps_taken;
      if (std::abs(target - bound) < 1e-12) {
        end.at_bound = true;
        break;
      }
    } else {
      ++end.outside_points;
      have_out = true;
      v_out = target;
      g_out = ok ? gOf(f) : std::numeric_limits<double>::infinity();
      if (!std::isfinite(g_out)) g_out = 10.0 * g_T;
    }
  }
  end.jacobians = jac.computed;
  return end;
}

ProfileIntervals collectProfile(const ProfilePlan& plan, const std::vector<ProfileEnd>& ends,
                                const ProfileOptions& options) {
  const int d = static_cast<int>(plan.lower.size());
  DTWIN_CHECK(static_cast<int>(ends.size()) == 2 * d, "a profile needs 2d ends");
  ProfileIntervals out;
  out.level = options.level;
  out.c = plan.c;
  out.s2 = plan.s2;
  out.sse_best = plan.sse_best;
  out.best_point = plan.best_point;
  out.threshold = plan.threshold;
  out.thresholds = plan.thresholds;
  out.correlation = plan.correlation;
  out.dof = plan.dof;
  for (int j = 0; j < d; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    const ProfileEnd& lo = ends[2 * static_cast<std::size_t>(j)];
    const ProfileEnd& hi = ends[2 * static_cast<std::size_t>(j) + 1];
    out.lower.push_back(std::min(lo.theta[jj], plan.low_point[jj][jj]));
    out.upper.push_back(std::max(hi.theta[jj], plan.high_point[jj][jj]));
    out.lower_at_bound.push_back(lo.at_bound);
    out.upper_at_bound.push_back(hi.at_bound);
    out.evaluations += lo.evaluations + hi.evaluations;
  }
  for (const ProfileEnd& e : ends) {
    out.end_evaluations.push_back(e.evaluations);
    out.end_steps.push_back(e.steps_taken);
    out.end_jacobians.push_back(e.jacobians);
    out.end_outside.push_back(e.outside_points);
  }
  return out;
}

nlohmann::json ProfileIntervals::toJson() const {
  return {{"level", level},
          {"c", c},
          {"s2", s2},
          {"dof", dof},
          {"sse_best", sse_best},
          {"threshold", threshold},
          {"lower", lower},
          {"upper", upper},
          {"lower_at_bound", lower_at_bound},
          {"upper_at_bound", upper_at_bound},
          {"evaluations", evaluations},
          {"end_evaluations", end_evaluations},
          {"end_points", end_steps},
          {"end_jacobians", end_jacobians},
          {"end_outside_points", end_outside},
          {"thresholds", thresholds},
          {"correlation", correlation.toJson()},
          {"best_point", best_point}};
}

ProfileIntervals ProfileIntervals::fromJson(const nlohmann::json& j) {
  ProfileIntervals p;
  p.level = j.at("level").get<double>();
  p.c = j.at("c").get<double>();
  p.s2 = j.at("s2").get<double>();
  p.dof = j.at("dof").get<int>();
  p.sse_best = j.at("sse_best").get<double>();
  p.threshold = j.at("threshold").get<double>();
  p.thresholds = j.value("thresholds", std::vector<double>{});
  if (j.contains("correlation"))
    p.correlation = CorrelationAdjustment::fromJson(j.at("correlation"));
  p.lower = j.at("lower").get<std::vector<double>>();
  p.upper = j.at("upper").get<std::vector<double>>();
  p.lower_at_bound = j.at("lower_at_bound").get<std::vector<bool>>();
  p.upper_at_bound = j.at("upper_at_bound").get<std::vector<bool>>();
  p.evaluations = j.at("evaluations").get<int>();
  p.end_evaluations = j.value("end_evaluations", std::vector<int>{});
  p.end_steps = j.value("end_points", std::vector<int>{});
  p.end_jacobians = j.value("end_jacobians", std::vector<int>{});
  p.end_outside = j.value("end_outside_points", std::vector<int>{});
  p.best_point = j.value("best_point", std::vector<double>{});
  return p;
}

}  // namespace dtwin::calib
