// The joint region (calibration/region.hpp, "The joint region"): the plan of the sweeps, the
// straight sweeps and the ridge traces, and the region collected from them. The Region itself (its
// scaling, JSON and the paper's box) is calibration/region.cpp's.
#include "calibration/region.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>

#include "calibration/eigen_json.hpp"
#include "calibration/subspace_lm.hpp"
#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::calib {
namespace {

/// Where the ray ẑ + s·t·a leaves [0,1]^d (t >= 0).
double rayExit(const Eigen::VectorXd& z0, const Eigen::VectorXd& a, int s) {
  double t = std::numeric_limits<double>::infinity();
  for (Eigen::Index j = 0; j < z0.size(); ++j) {
    const double v = s * a(j);
    if (v > 1e-15)
      t = std::min(t, (1.0 - z0(j)) / v);
    else if (v < -1e-15)
      t = std::min(t, -z0(j) / v);
  }
  return std::max(t, 0.0);
}

/// Reach of the unit cube from z0 along −a (lower) and +a (upper).
void cubeReach(const Eigen::VectorXd& z0, const Eigen::VectorXd& a, double& lower, double& upper) {
  lower = upper = 0.0;
  for (Eigen::Index j = 0; j < z0.size(); ++j) {
    upper += std::max(-z0(j) * a(j), (1.0 - z0(j)) * a(j));
    lower += std::max(z0(j) * a(j), -(1.0 - z0(j)) * a(j));
  }
}

}  // namespace

// ------------------------------------------------------------------ joint region
void JointRegionOptions::validate() const {
  const OptionCheck check("joint_region");
  check.require(jacobian_step > 0.0 && jacobian_step <= 0.5, "jacobian_step",
                "must lie in (0, 0.5] (scaled units), got " + formatNumber(jacobian_step));
  check.require(margin >= 1.0 && std::isfinite(margin), "margin",
                "must be a finite number >= 1, got " + formatNumber(margin));
  check.open01("relative_tolerance", relative_tolerance);
  check.require(growth > 1.0 && std::isfinite(growth), "growth",
                "must be a finite number > 1, got " + formatNumber(growth));
  check.atLeast("max_evaluations", max_evaluations, 2);
  check.require(ridge_ratio >= 1.0 && std::isfinite(ridge_ratio), "ridge_ratio",
                "must be a finite number >= 1, got " + formatNumber(ridge_ratio));
  check.atLeast("ridge_steps", ridge_steps, 0);
}

nlohmann::json JointRegionOptions::toJson() const {
  return {{"rule",
           "principal axes of the Gauss-Newton Hessian at the optimum; extents = margin * the "
           "crossings of the 1 % contour by "
           "straight sweeps and, along the weak axes, by ridge traces (profiles)"},
          {"jacobian_step_scaled", jacobian_step},
          {"margin", margin},
          {"relative_tolerance", relative_tolerance},
          {"growth", growth},
          {"max_evaluations_per_sweep", max_evaluations},
          {"ridge_ratio", ridge_ratio},
          {"ridge_steps", ridge_steps}};
}

std::vector<std::vector<double>> jacobianStencil(const BoxProblem& problem,
                                                 const JointRegionOptions& options) {
  problem.validate();
  options.validate();
  const std::size_t d = problem.theta_hat.size();
  std::vector<std::vector<double>> pts;
  for (std::size_t j = 0; j < d; ++j)
    for (int s : {-1, +1}) {
      auto th = problem.theta_hat;
      const double range = problem.upper[j] - problem.lower[j];
      th[j] =
          std::clamp(th[j] + s * options.jacobian_step * range, problem.lower[j], problem.upper[j]);
      pts.push_back(th);
    }
  return pts;
}

JointRegionPlan planJointRegion(const BoxProblem& problem,
                                const std::vector<std::vector<double>>& residuals,
                                const JointRegionOptions& options) {
  problem.validate();
  options.validate();
  const int d = static_cast<int>(problem.theta_hat.size());
  DTWIN_CHECK(static_cast<int>(residuals.size()) == 2 * d,
              "planJointRegion needs 2d stencil residuals");
  JointRegionPlan plan;
  plan.problem = problem;
  plan.evaluations = 2 * d;
  const auto stencil = jacobianStencil(problem, options);
  std::size_t n = 0;
  for (const auto& r : residuals) n = std::max(n, r.size());
  plan.jacobian = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), d);
  for (int j = 0; j < d; ++j) {
    const auto& rm = residuals[2 * static_cast<std::size_t>(j)];
    const auto& rp = residuals[2 * static_cast<std::size_t>(j) + 1];
    const auto k = static_cast<std::size_t>(j);
    const double range = problem.upper[k] - problem.lower[k];
    const double dz = (stencil[2 * static_cast<std::size_t>(j) + 1][k] -
                       stencil[2 * static_cast<std::size_t>(j)][k]) /
                      range;
    bool ok = rm.size() == n && rp.size() == n && dz > 0.0;
    for (std::size_t i = 0; ok && i < n; ++i) ok = std::isfinite(rm[i]) && std::isfinite(rp[i]);
    if (!ok) {
      plan.messages.push_back(
          "parameter " + std::to_string(j) +
          ": a simulation of the Jacobian stencil failed; the region spans this parameter's range");
      continue;
    }
    for (std::size_t i = 0; i < n; ++i)
      plan.jacobian(static_cast<Eigen::Index>(i), j) = (rp[i] - rm[i]) / dz;
  }
  const Eigen::MatrixXd H = plan.jacobian.transpose() * plan.jacobian;
  Eigen::VectorXd zhat(d);
  for (int j = 0; j < d; ++j) {
    const auto k = static_cast<std::size_t>(j);
    zhat(j) = (problem.theta_hat[k] - problem.lower[k]) / (problem.upper[k] - problem.lower[k]);
  }
  // Parameters whose optimum sits on a bound (an effect switched off, say) are the active set.
  // An eigen-axis that mixes one of them leaves the bounds at once in one direction, and a
  // parallelepiped on such axes lies mostly outside the bounds. So the free parameters get the
  // eigen-axes of their own block of H, and each active parameter its coordinate axis (pointing
  // into the bounds from one side only), ranked by its profile curvature, the Schur complement
  // H_aa - H_aF H_FF^-1 H_Fa: how fast the SSE rises along it when the free parameters follow.
  // "On a bound": within 0.1 % of the narrowest quadratic half-width along its coordinate.
  const double dT = problem.threshold() - problem.sse_min;
  std::vector<int> active, free;
  auto onBound = [&](int j) {
    const double gap = std::min(zhat(j), 1.0 - zhat(j));
    return gap <= 1e-9 || (H(j, j) > 0.0 && gap < 1e-3 * std::sqrt(dT / H(j, j)));
  };
  for (int j = 0; j < d; ++j) (onBound(j) ? active : free).push_back(j);
  if (active.empty()) {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(H);
    DTWIN_CHECK(es.info() == Eigen::Success,
                "eigen-decomposition of the Gauss-Newton Hessian failed");
    plan.eigenvalues = es.eigenvalues();
    plan.axes = es.eigenvectors();
  } else {
    const auto nf = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd Hff(nf, nf);
    for (Eigen::Index a = 0; a < nf; ++a)
      for (Eigen::Index b = 0; b < nf; ++b)
        Hff(a, b) = H(free[static_cast<std::size_t>(a)], free[static_cast<std::size_t>(b)]);
    std::vector<std::pair<double, Eigen::VectorXd>> pairs;
    Eigen::MatrixXd pinv = Eigen::MatrixXd::Zero(nf, nf);
    if (nf > 0) {
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Hff);
      DTWIN_CHECK(es.info() == Eigen::Success,
                  "eigen-decomposition of the Gauss-Newton Hessian failed");
      const double top = std::max(es.eigenvalues().maxCoeff(), 0.0);
      for (Eigen::Index c = 0; c < nf; ++c) {
        Eigen::VectorXd v = Eigen::VectorXd::Zero(d);
        for (Eigen::Index a = 0; a < nf; ++a)
          v(free[static_cast<std::size_t>(a)]) = es.eigenvectors()(a, c);
        pairs.emplace_back(es.eigenvalues()(c), v);
        const double lam = es.eigenvalues()(c);
        if (lam > 1e-12 * top && lam > 0.0)
          pinv += es.eigenvectors().col(c) * es.eigenvectors().col(c).transpose() / lam;
      }
    }
    for (int j : active) {
      Eigen::VectorXd hf(nf);
      for (Eigen::Index a = 0; a < nf; ++a) hf(a) = H(j, free[static_cast<std::size_t>(a)]);
      Eigen::VectorXd e = Eigen::VectorXd::Zero(d);
      e(j) = 1.0;
      pairs.emplace_back(std::max(H(j, j) - (nf > 0 ? hf.dot(pinv * hf) : 0.0), 0.0), e);
      plan.messages.push_back("parameter " + std::to_string(j) + " sits on its " +
                              (zhat(j) < 0.5 ? "lower" : "upper") +
                              " bound at the optimum: its axis is its own, one-sided");
    }
    std::stable_sort(pairs.begin(), pairs.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    plan.eigenvalues.resize(d);
    plan.axes.resize(d, d);
    for (int c = 0; c < d; ++c) {
      plan.eigenvalues(c) = pairs[static_cast<std::size_t>(c)].first;
      plan.axes.col(c) = pairs[static_cast<std::size_t>(c)].second;
    }
  }
  const double cap = std::sqrt(static_cast<double>(d));
  plan.half_width.resize(d);
  plan.reach_lower.resize(d);
  plan.reach_upper.resize(d);
  const double lam_max = std::max(plan.eigenvalues.maxCoeff(), 0.0);
  for (int i = 0; i < d; ++i) {
    Eigen::Index big = 0;
    plan.axes.col(i).cwiseAbs().maxCoeff(&big);
    if (plan.axes(big, i) < 0) plan.axes.col(i) *= -1.0;
    const double lam = plan.eigenvalues(i);
    const bool identified = lam > 1e-12 * lam_max && lam > 0.0;
    plan.half_width(i) = identified ? std::min(std::sqrt(dT / lam), cap) : cap;
    cubeReach(zhat, plan.axes.col(i), plan.reach_lower(i), plan.reach_upper(i));
  }
  return plan;
}

RaySweep calcRegionSweep(const SseFunction& sse, const JointRegionPlan& plan, int index,
                         const JointRegionOptions& options) {
  options.validate();
  const auto& p = plan.problem;
  const int d = static_cast<int>(p.theta_hat.size());
  DTWIN_CHECK(index >= 0 && index < 2 * d, "region sweep index out of range");
  const int i = index / 2, s = index % 2 == 0 ? -1 : +1;
  Eigen::VectorXd zhat(d);
  for (int j = 0; j < d; ++j) {
    const auto k = static_cast<std::size_t>(j);
    zhat(j) = (p.theta_hat[k] - p.lower[k]) / (p.upper[k] - p.lower[k]);
  }
  const Eigen::VectorXd a = plan.axes.col(i);
  const double t_max = rayExit(zhat, a, s);
  const double half = plan.half_width(i);
  FeasibleBoxOptions fo;
  fo.initial_step = 0.5 * std::min(half, 0.2);
  fo.growth = options.growth;
  fo.max_evaluations = options.max_evaluations;
  std::vector<double> theta(static_cast<std::size_t>(d));
  return sweepRay(
      [&](double t) {
        const Eigen::VectorXd z = zhat + (s * t) * a;
        for (int j = 0; j < d; ++j) {
          const auto k = static_cast<std::size_t>(j);
          const double zj = std::clamp(z(j), 0.0, 1.0);
          theta[k] = zj >= 1.0 ? p.upper[k] : p.lower[k] + zj * (p.upper[k] - p.lower[k]);
        }
        return sse(theta);
      },
      t_max, p.threshold(), p.sse_min, fo, fo.initial_step, options.relative_tolerance);
}

std::vector<int> ridgeAxes(const JointRegionPlan& plan, const JointRegionOptions& options) {
  std::vector<int> axes;
  if (options.ridge_steps == 0 || plan.eigenvalues.size() == 0) return axes;
  const double lam_min = std::max(plan.eigenvalues(0), 0.0);
  for (Eigen::Index i = 0; i < plan.eigenvalues.size(); ++i)
    if (i == 0 || plan.eigenvalues(i) <= options.ridge_ratio * lam_min)
      axes.push_back(static_cast<int>(i));
  return axes;
}

namespace {

/// Scaled point -> physical θ (clamped to the bounds).
std::vector<double> physical(const BoxProblem& p, const Eigen::VectorXd& z) {
  std::vector<double> th(p.theta_hat.size());
  for (std::size_t k = 0; k < th.size(); ++k) {
    const double zk = std::clamp(z(static_cast<Eigen::Index>(k)), 0.0, 1.0);
    th[k] = zk >= 1.0 ? p.upper[k] : p.lower[k] + zk * (p.upper[k] - p.lower[k]);
  }
  return th;
}

/// The straight sweep's crossing along axis i, direction s (the reach when it was clipped).
double crossingOf(const JointRegionPlan& plan, const std::vector<RaySweep>& sweeps, int i, int s) {
  const RaySweep& w = sweeps[2 * static_cast<std::size_t>(i) + (s > 0 ? 1 : 0)];
  const double reach = s > 0 ? plan.reach_upper(i) : plan.reach_lower(i);
  return (w.clipped || w.budget_out) ? reach : std::max(w.t_edge, 1e-12);
}

/// The rise of a ridge trace's floor, followed as a line in g = √(SSE − SSE_min) (exact for a
/// quadratic profile) through its last two floor points; the optimum (t = 0, g = 0) is the first.
struct RiseLine {
  double sse_min = 0.0, threshold = 0.0;
  double t_before = 0.0, f_before = 0.0, t_last = 0.0, f_last = 0.0;
  RiseLine(double sse_min_, double threshold_)
      : sse_min(sse_min_), threshold(threshold_), f_before(sse_min_), f_last(sse_min_) {}
  double g(double f) const { return std::sqrt(std::max(f - sse_min, 0.0)); }
  /// dg/dt through the last two floor points (0 before there are two).
  double slope() const {
    return t_last > t_before ? (g(f_last) - g(f_before)) / (t_last - t_before) : 0.0;
  }
  void push(double t, double f) {
    t_before = t_last;
    f_before = f_last;
    t_last = t;
    f_last = f;
  }
  /// Whether a floor point outside the contour at t_out continues the rise: its g at most twice as
  /// far above the last point's as the line predicts. A point far above it may have left a
  /// bending ridge.
  bool continues(double f_out, double t_out) const {
    return t_last > t_before &&
           g(f_out) <= g(f_last) + 2.0 * std::max(slope(), 0.0) * (t_out - t_last);
  }
  /// How far ahead of the last point the line reaches the threshold (+inf when it does not rise).
  double reach() const {
    return slope() > 0 ? (g(threshold) - g(f_last)) / slope()
                       : std::numeric_limits<double>::infinity();
  }
};

/// σ² B (JᵀJ)⁻¹ Bᵀ (the posterior's cross-section at a floor point), or an empty matrix when J
/// is missing, not finite or JᵀJ is not positive definite.
Eigen::MatrixXd crossSection(const Eigen::MatrixXd& J, const Eigen::MatrixXd& B, double sigma2) {
  if (J.cols() != B.cols() || J.rows() == 0 || !J.allFinite()) return {};
  const Eigen::LLT<Eigen::MatrixXd> llt(J.transpose() * J);
  if (llt.info() != Eigen::Success) return {};
  const Eigen::MatrixXd inv = llt.solve(Eigen::MatrixXd::Identity(B.cols(), B.cols()));
  if (!inv.allFinite()) return {};
  return sigma2 * B * inv * B.transpose();
}

/// Region::ridge_cov of floor point q of `tr` (see region.hpp); empty when its cross-section is.
Eigen::MatrixXd ridgeKernel(const RidgeTrace& tr, std::size_t q, const Eigen::VectorXd& start) {
  if (q >= tr.cross.size() || tr.cross[q].size() == 0) return {};
  const double t_prev = q == 0 ? 0.0 : tr.t[q - 1];
  const Eigen::VectorXd z_prev = q == 0 ? start : tr.z[q - 1];
  const bool has_next = q + 1 < tr.z.size();
  const double t_next = has_next ? tr.t[q + 1] : tr.t[q];
  const Eigen::VectorXd z_next = has_next ? tr.z[q + 1] : tr.z[q];
  if (!(t_next > t_prev)) return {};
  const Eigen::VectorXd g = (z_next - z_prev) / (t_next - t_prev);
  const double ell = 0.5 * std::max(tr.t[q] - t_prev, t_next - tr.t[q]);
  return ell * ell * g * g.transpose() + tr.cross[q];
}
/// The frame of one ridge trace along axis `i`: the optimum in unit coordinates (z0), the traced
/// axis (a), the other axes (B) and their central-difference steps (h, 10 % of their crossings).
struct RidgeFrame {
  Eigen::VectorXd z0, a, h;
  Eigen::MatrixXd B;
};
RidgeFrame ridgeFrame(const JointRegionPlan& plan, const std::vector<RaySweep>& sweeps, int i) {
  const auto& p = plan.problem;
  const int d = static_cast<int>(p.theta_hat.size());
  RidgeFrame f;
  f.z0.resize(d);
  for (int j = 0; j < d; ++j) {
    const auto k = static_cast<std::size_t>(j);
    f.z0(j) = (p.theta_hat[k] - p.lower[k]) / (p.upper[k] - p.lower[k]);
  }
  f.a = plan.axes.col(i);
  f.B.resize(d, d - 1);
  f.h.resize(d - 1);
  for (int j = 0, c = 0; j < d; ++j) {
    if (j == i) continue;
    f.B.col(c) = plan.axes.col(j);
    f.h(c) =
        std::max(0.05 * (crossingOf(plan, sweeps, j, -1) + crossingOf(plan, sweeps, j, +1)), 1e-9);
    ++c;
  }
  return f;
}
}  // namespace

RidgeTrace calcRidgeTrace(const ResidualFunction& residuals, const JointRegionPlan& plan,
                          const std::vector<RaySweep>& sweeps, int index,
                          const JointRegionOptions& options) {
  options.validate();
  const auto& p = plan.problem;
  const int d = static_cast<int>(p.theta_hat.size());
  const std::vector<int> ridge = ridgeAxes(plan, options);
  DTWIN_CHECK(index >= 0 && index < 2 * static_cast<int>(ridge.size()),
              "ridge trace index out of range");
  RidgeTrace tr;
  tr.axis = ridge[static_cast<std::size_t>(index / 2)];
  tr.direction = index % 2 == 0 ? -1 : +1;
  const int i = tr.axis, s = tr.direction;
  const RidgeFrame frame = ridgeFrame(plan, sweeps, i);
  const Eigen::VectorXd& z0 = frame.z0;
  const Eigen::VectorXd& a = frame.a;
  const Eigen::MatrixXd& B = frame.B;
  const Eigen::VectorXd& h = frame.h;
  const double T = p.threshold();
  const double sigma2 = p.sse_min / p.n_data;
  const double reach = s > 0 ? plan.reach_upper(i) : plan.reach_lower(i);
  auto res = [&](const Eigen::VectorXd& z, Eigen::VectorXd& r) {
    ++tr.evaluations;
    const auto v = residuals(physical(p, z));
    if (v.empty()) return false;
    r = Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
    return r.allFinite();
  };
  auto point = [&](double t, const Eigen::VectorXd& u) -> Eigen::VectorXd {
    return z0 + (s * t) * a + B * u;
  };
  if (d < 2) {
    tr.message = "one parameter: nothing to re-optimise";
    return tr;
  }
  double step = 0.25 * crossingOf(plan, sweeps, i, s);
  const double min_step = step / 16.0;
  double t = 0.0, prev_step = step;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(d - 1), u_prev = u;
  // The floor at t: Levenberg–Marquardt on u from `un` (at most 4 iterations). False when the
  // simulation at the start point fails.
  const ScaledResiduals scaled = [&](const Eigen::VectorXd& z, Eigen::VectorXd& r) {
    return res(z, r);
  };
  // The Jacobian is carried along the trace, seeded from the plan's (subspace_lm.hpp); a floor
  // point that lands outside the contour is re-minimised with fresh differences before it counts.
  SubspaceJacobian jac;
  if (plan.jacobian.cols() == d && plan.jacobian.allFinite()) jac.J = plan.jacobian * B;
  SubspaceLmSettings lm;
  lm.forward = options.forward_differences;
  auto floorAt = [&](double tt, Eigen::VectorXd& un, Eigen::VectorXd& r, double& f) {
    const int computed = jac.computed;
    if (!minimiseOnSubspace(scaled, z0 + (s * tt) * a, B, h, 3, 0.05 * sigma2, un, r, f, &jac, lm))
      return false;
    if (f > T && jac.computed == computed) {
      jac.clear();
      Eigen::VectorXd uf = un, rf;
      double ff = 0.0;
      if (minimiseOnSubspace(scaled, z0 + (s * tt) * a, B, h, 3, 0.05 * sigma2, uf, rf, ff, &jac,
                             lm) &&
          ff < f) {
        un = uf;
        r = rf;
        f = ff;
      }
    }
    return true;
  };
  RiseLine rise(p.sse_min, T);
  for (int k = 0; k < options.ridge_steps; ++k) {
    if (t > reach) {
      tr.clipped = true;
      return tr;
    }
    const double t_next = t + step;
    // Warm start: extrapolate the floor.
    Eigen::VectorXd un = u + (u - u_prev) * (step / prev_step), r;
    double f = 0.0;
    if (!floorAt(t_next, un, r, f)) {
      un = u;
      if (!floorAt(t_next, un, r, f)) {
        tr.message = "a simulation on the ridge failed at t = " + formatNumber(t_next) +
                     "; the trace stops there";
        return tr;
      }
    }
    if (f > T && step > min_step && !rise.continues(f, t_next)) {
      // A step that lands far above the floor's rise may have jumped off a thin, bending ridge
      // rather than reached the contour's end: halve it, from the last floor point, before
      // concluding (down to 1/16 of the first step). One that continues the rise closes the trace.
      step *= 0.5;
      continue;
    }
    u_prev = u;
    u = un;
    prev_step = step;
    t = t_next;
    rise.push(t, f);
    tr.t.push_back(t);
    tr.z.push_back(point(t, u));
    tr.sse.push_back(f);
    tr.cross.push_back(crossSection(jac.J, B, sigma2));
    if (f > T) {  // the crossing, interpolated between the last two floor points
      tr.closed = true;
      const double g_in = rise.g(rise.f_before), g_out = rise.g(f);
      tr.crossing = g_out > g_in
                        ? rise.t_before + (rise.g(T) - g_in) / (g_out - g_in) * (t - rise.t_before)
                        : t;
      return tr;
    }
    const double risen = f - rise.f_before;
    if (risen < 0.5 * sigma2)
      step *= 1.5;
    else if (risen > 3.0 * sigma2)
      step *= 0.6;
    // Near the end, aim just past the crossing the rise predicts, so that the next point closes the
    // trace.
    if (rise.reach() < 1.5 * step) step = std::max(1.15 * rise.reach(), min_step);
  }
  if (t > reach)
    tr.clipped = true;
  else
    tr.message = "the ridge trace used its " + std::to_string(options.ridge_steps) +
                 " steps inside the contour";
  return tr;
}

Region collectJointRegion(const JointRegionPlan& plan, const std::vector<RaySweep>& sweeps,
                          const std::vector<RidgeTrace>& traces,
                          const JointRegionOptions& options) {
  const auto& p = plan.problem;
  const int d = static_cast<int>(p.theta_hat.size());
  DTWIN_CHECK(static_cast<int>(sweeps.size()) == 2 * d, "a joint region needs 2d sweeps");
  Region r;
  r.kind = "joint";
  r.lower = p.lower;
  r.upper = p.upper;
  r.centre = r.toScaled(p.theta_hat);
  r.axes = plan.axes;
  r.t_lower.resize(d);
  r.t_upper.resize(d);
  r.reach_lower = plan.reach_lower;
  r.reach_upper = plan.reach_upper;
  r.threshold = p.threshold();
  r.sse_min = p.sse_min;
  r.evaluations = plan.evaluations;
  r.messages = plan.messages;
  r.guess_mean = r.centre;
  r.guess_sd.resize(d);
  const double k = std::sqrt(2.0 * std::log(100.0));
  // Straight sweeps.
  Eigen::MatrixXd crossing(d, 2);  // column 0: towards −a_i, 1: towards +a_i
  std::vector<bool> traced(static_cast<std::size_t>(d), false);
  for (const auto& tr : traces) traced[static_cast<std::size_t>(tr.axis)] = true;
  for (int i = 0; i < d; ++i)
    for (int s : {-1, +1}) {
      const RaySweep& w = sweeps[2 * static_cast<std::size_t>(i) + (s > 0 ? 1 : 0)];
      r.evaluations += w.evaluations;
      if (w.budget_out)
        r.messages.push_back("axis " + std::to_string(i) + (s > 0 ? " (+)" : " (-)") +
                             ": the sweep did not bracket the 1 % contour within its budget; the "
                             "region takes the bounds' reach");
      crossing(i, s > 0 ? 1 : 0) = crossingOf(plan, sweeps, i, s);
    }
  // Ridge traces: the crossing along a traced axis is where its profile crossed T.
  std::vector<Eigen::VectorXd> floor;
  std::vector<double> floor_sse;
  for (const auto& tr : traces) {
    r.evaluations += tr.evaluations;
    if (!tr.message.empty())
      r.messages.push_back("ridge along axis " + std::to_string(tr.axis) +
                           (tr.direction > 0 ? " (+)" : " (-)") + ": " + tr.message);
    const int col = tr.direction > 0 ? 1 : 0;
    const double reach = tr.direction > 0 ? plan.reach_upper(tr.axis) : plan.reach_lower(tr.axis);
    const double along =
        tr.closed ? tr.crossing : (tr.clipped ? reach : (tr.t.empty() ? 0.0 : tr.t.back()));
    crossing(tr.axis, col) = std::max(crossing(tr.axis, col), along);
    for (std::size_t q = 0; q < tr.z.size(); ++q)
      if (tr.sse[q] <= r.threshold) {
        floor.push_back(tr.z[q]);
        floor_sse.push_back(tr.sse[q]);
        r.ridge_cov.push_back(ridgeKernel(tr, q, r.centre));
      }
  }
  for (int i = 0; i < d; ++i) {
    for (int s : {-1, +1}) {
      const double reach = s > 0 ? plan.reach_upper(i) : plan.reach_lower(i);
      double e = options.margin * crossing(i, s > 0 ? 1 : 0);
      // Across a ridge: room for the contour's cross-section around every floor point.
      if (!traced[static_cast<std::size_t>(i)])
        for (const auto& z : floor)
          e = std::max(
              e, s * r.axes.col(i).dot(z - r.centre) + options.margin * crossing(i, s > 0 ? 1 : 0));
      e = std::min(e, reach);
      (s > 0 ? r.t_upper(i) : r.t_lower(i)) = s * std::max(e, 1e-12);
    }
    r.guess_mean += r.axes.col(i) * (0.5 * (crossing(i, 1) - crossing(i, 0)));
    r.guess_sd(i) = 0.5 * (crossing(i, 0) + crossing(i, 1)) / k;
  }
  r.ridge.resize(static_cast<Eigen::Index>(floor.size()), d);
  for (std::size_t q = 0; q < floor.size(); ++q)
    r.ridge.row(static_cast<Eigen::Index>(q)) = floor[q].transpose();
  r.ridge_sse = floor_sse;
  return r;
}

Region calcJointRegion(const SseFunction& sse, const ResidualFunction& residuals,
                       const BoxProblem& problem, const JointRegionOptions& options,
                       const ParallelFor& parallel_for) {
  const int d = static_cast<int>(problem.theta_hat.size());
  const ParallelFor& run = parallel_for ? parallel_for : ParallelFor(sequentialFor);
  const auto stencil = jacobianStencil(problem, options);
  std::vector<std::vector<double>> res(stencil.size());
  std::vector<std::exception_ptr> errors(stencil.size());
  run(static_cast<int>(stencil.size()), [&](int k) {
    try {
      res[static_cast<std::size_t>(k)] = residuals(stencil[static_cast<std::size_t>(k)]);
    } catch (...) {
      errors[static_cast<std::size_t>(k)] = std::current_exception();
    }
  });
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  const JointRegionPlan plan = planJointRegion(problem, res, options);
  std::vector<RaySweep> sweeps(static_cast<std::size_t>(2 * d));
  std::vector<std::exception_ptr> errs(sweeps.size());
  run(2 * d, [&](int k) {
    try {
      sweeps[static_cast<std::size_t>(k)] = calcRegionSweep(sse, plan, k, options);
    } catch (...) {
      errs[static_cast<std::size_t>(k)] = std::current_exception();
    }
  });
  for (const auto& e : errs)
    if (e) std::rethrow_exception(e);
  const int m = 2 * static_cast<int>(ridgeAxes(plan, options).size());
  std::vector<RidgeTrace> traces(static_cast<std::size_t>(m));
  std::vector<std::exception_ptr> terr(traces.size());
  run(m, [&](int k) {
    try {
      traces[static_cast<std::size_t>(k)] = calcRidgeTrace(residuals, plan, sweeps, k, options);
    } catch (...) {
      terr[static_cast<std::size_t>(k)] = std::current_exception();
    }
  });
  for (const auto& e : terr)
    if (e) std::rethrow_exception(e);
  return collectJointRegion(plan, sweeps, traces, options);
}

}  // namespace dtwin::calib
