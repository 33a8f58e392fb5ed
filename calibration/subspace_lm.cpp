#include "calibration/subspace_lm.hpp"

#include <algorithm>
#include <vector>

#include "common/parallel.hpp"

namespace dtwin::calib {

namespace {

/// Differences of r(z0 + B u) along each column of B, inside the bounds of `set`: central (2m
/// runs; one-sided at a bound) or, with set.forward, from r0 = r(u) to one point (m runs; backward
/// where the forward point would leave the box). The runs go to set.threads workers; false when a
/// simulation fails.
bool differenceJacobian(const ScaledResiduals& residuals, const Eigen::VectorXd& z0,
                        const Eigen::MatrixXd& B, const Eigen::VectorXd& h,
                        const Eigen::VectorXd& u, const Eigen::VectorXd& r0,
                        const SubspaceLmSettings& set, Eigen::MatrixXd& J) {
  const Eigen::Index m = B.cols(), n = r0.size();
  const bool bounded = set.lower.size() == m && set.upper.size() == m;
  const std::size_t per = set.forward ? 1 : 2;
  // Column c: points[per c] (+ h side) and, central, points[per c + 1] (− h side).
  std::vector<Eigen::VectorXd> points(per * static_cast<std::size_t>(m), u), res(points.size());
  for (Eigen::Index c = 0; c < m; ++c) {
    const std::size_t i = per * static_cast<std::size_t>(c);
    double up = u(c) + h(c), dn = u(c) - h(c);
    if (bounded) {
      up = std::min(up, set.upper(c));
      dn = std::max(dn, set.lower(c));
    }
    if (set.forward) {
      points[i](c) = up > u(c) ? up : dn;
    } else {
      points[i](c) = up;
      points[i + 1](c) = dn;
    }
  }
  std::vector<char> ok(points.size(), 0);
  parallelFor(points.size(), set.threads, [&](std::size_t i, int) {
    ok[i] = residuals(z0 + B * points[i], res[i]) && res[i].size() == n;
  });
  if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return false;
  J.resize(n, m);
  for (Eigen::Index c = 0; c < m; ++c) {
    const std::size_t i = per * static_cast<std::size_t>(c);
    const double hi = points[i](c), lo = set.forward ? u(c) : points[i + 1](c);
    const Eigen::VectorXd& r_lo = set.forward ? r0 : res[i + 1];
    const double span = hi - lo;
    J.col(c) = span != 0 ? Eigen::VectorXd((res[i] - r_lo) / span) : Eigen::VectorXd::Zero(n);
  }
  return true;
}

/// The damped Gauss–Newton step −(JᵀJ + μ diag JᵀJ)⁻¹ Jᵀr. With bounds, a coordinate resting on
/// a bound whose step points out of the box is held there and the step solved again for the
/// others (until no such coordinate is left): clipping the full step instead would move the free
/// coordinates as if the held one had moved, and stall short of the bounded minimum.
Eigen::VectorXd dampedStep(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, double mu,
                           const Eigen::VectorXd& u, const SubspaceLmSettings& set, bool bounded) {
  const Eigen::Index m = J.cols();
  const Eigen::MatrixXd A = J.transpose() * J;
  const Eigen::VectorXd g = J.transpose() * r;
  std::vector<Eigen::Index> free;
  for (Eigen::Index c = 0; c < m; ++c) free.push_back(c);
  Eigen::VectorXd step = Eigen::VectorXd::Zero(m);
  while (!free.empty()) {
    const auto k = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd Af(k, k);
    Eigen::VectorXd gf(k);
    for (Eigen::Index i = 0; i < k; ++i) {
      gf(i) = g(free[static_cast<std::size_t>(i)]);
      for (Eigen::Index j = 0; j < k; ++j)
        Af(i, j) = A(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
      Af(i, i) += mu * std::max(Af(i, i), 1e-300);
    }
    const Eigen::VectorXd sf = Af.ldlt().solve(-gf);
    step.setZero();
    std::vector<Eigen::Index> keep;
    for (Eigen::Index i = 0; i < k; ++i) {
      const Eigen::Index c = free[static_cast<std::size_t>(i)];
      step(c) = sf(i);
      const bool held =
          bounded && ((u(c) >= set.upper(c) && sf(i) > 0) || (u(c) <= set.lower(c) && sf(i) < 0));
      if (!held) keep.push_back(c);
    }
    if (keep.size() == free.size()) break;
    free = std::move(keep);
    step.setZero();
  }
  return step;
}

}  // namespace

bool minimiseOnSubspace(const ScaledResiduals& residuals, const Eigen::VectorXd& z0,
                        const Eigen::MatrixXd& B, const Eigen::VectorXd& h, int iterations,
                        double min_gain, Eigen::VectorXd& u, Eigen::VectorXd& r, double& f,
                        SubspaceJacobian* carried, const SubspaceLmSettings& settings) {
  auto point = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return z0 + B * v; };
  if (!residuals(point(u), r)) return false;
  f = r.squaredNorm();
  const Eigen::Index m = B.cols();
  if (m == 0) return true;
  const bool bounded = settings.lower.size() == m && settings.upper.size() == m;
  SubspaceJacobian local;
  SubspaceJacobian& jac = carried ? *carried : local;
  if (jac.J.rows() != r.size() || jac.J.cols() != m) jac.clear();
  double mu = 1e-3;
  for (int it = 0; it < iterations; ++it) {
    bool fresh = jac.J.size() == 0;
    if (fresh) {
      if (!differenceJacobian(residuals, z0, B, h, u, r, settings, jac.J)) {
        jac.clear();
        break;
      }
      ++jac.computed;
    } else {
      ++jac.reused;
    }
    bool improved = false;
    for (int round = 0; round < 2 && !improved; ++round) {
      if (round == 1) {  // the carried Jacobian found no better point: differences, and again
        if (fresh) break;
        if (!differenceJacobian(residuals, z0, B, h, u, r, settings, jac.J)) {
          jac.clear();  // half overwritten: never carried on
          break;
        }
        ++jac.computed;
        fresh = true;
        mu = 1e-3;
      }
      for (int tries = 0; tries < settings.tries && !improved; ++tries) {
        Eigen::VectorXd cand = u + dampedStep(jac.J, r, mu, u, settings, bounded);
        if (bounded) cand = cand.cwiseMax(settings.lower).cwiseMin(settings.upper);
        const Eigen::VectorXd step = cand - u;
        Eigen::VectorXd rc;
        const bool ok = residuals(point(cand), rc) && rc.size() == r.size() && rc.allFinite();
        // Broyden: the secant condition along the step, unless the step is so short (below a
        // millionth of the difference steps h) that rc − r is rounding noise: divided by |step|²
        // it would wreck the Jacobian (at a floor point, where the gradient is ~0, it did).
        if (ok && step.cwiseQuotient(h).norm() > 1e-6)
          jac.J += ((rc - r) - jac.J * step) * (step.transpose() / step.squaredNorm());
        if (ok && rc.squaredNorm() < f) {
          const double gain = f - rc.squaredNorm();
          const bool small = gain < min_gain || gain < settings.min_rel_gain * f;
          u = cand;
          r = rc;
          f = rc.squaredNorm();
          mu = std::max(mu / 10, 1e-9);
          improved = true;
          if (small && (fresh || !settings.converge_on_fresh))
            it = iterations;  // converged
          else if (small)
            jac.clear();  // a carried Jacobian's small step: fresh differences next
        } else {
          mu *= 10;
        }
      }
    }
    if (!improved) break;
  }
  return true;
}

}  // namespace dtwin::calib
