#include "calibration/subspace_lm.hpp"

#include <algorithm>

namespace dtwin::calib {

namespace {

/// Central differences of r(z0 + B u) along each column of B; false when a simulation fails.
bool differenceJacobian(const ScaledResiduals& residuals, const Eigen::VectorXd& z0, const Eigen::MatrixXd& B,
                        const Eigen::VectorXd& h, const Eigen::VectorXd& u, Eigen::Index n, Eigen::MatrixXd& J) {
  const Eigen::Index m = B.cols();
  J.resize(n, m);
  for (Eigen::Index c = 0; c < m; ++c) {
    Eigen::VectorXd rp, rm, e = Eigen::VectorXd::Zero(m);
    e(c) = h(c);
    if (!(residuals(z0 + B * (u + e), rp) && residuals(z0 + B * (u - e), rm) && rp.size() == n && rm.size() == n)) return false;
    J.col(c) = (rp - rm) / (2 * h(c));
  }
  return true;
}

}  // namespace

bool minimiseOnSubspace(const ScaledResiduals& residuals, const Eigen::VectorXd& z0, const Eigen::MatrixXd& B,
                        const Eigen::VectorXd& h, int iterations, double min_gain, Eigen::VectorXd& u, Eigen::VectorXd& r,
                        double& f, SubspaceJacobian* carried) {
  auto point = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return z0 + B * v; };
  if (!residuals(point(u), r)) return false;
  f = r.squaredNorm();
  const Eigen::Index m = B.cols();
  if (m == 0) return true;
  SubspaceJacobian local;
  SubspaceJacobian& jac = carried ? *carried : local;
  if (jac.J.rows() != r.size() || jac.J.cols() != m) jac.clear();
  double mu = 1e-3;
  for (int it = 0; it < iterations; ++it) {
    bool fresh = jac.J.size() == 0;
    if (fresh) {
      if (!differenceJacobian(residuals, z0, B, h, u, r.size(), jac.J)) {
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
        if (!differenceJacobian(residuals, z0, B, h, u, r.size(), jac.J)) {
          jac.clear();  // half overwritten: never carried on
          break;
        }
        ++jac.computed;
        fresh = true;
        mu = 1e-3;
      }
      for (int tries = 0; tries < 3 && !improved; ++tries) {
        const Eigen::MatrixXd A = jac.J.transpose() * jac.J;
        Eigen::MatrixXd Al = A;
        for (Eigen::Index c = 0; c < m; ++c) Al(c, c) += mu * std::max(A(c, c), 1e-300);
        const Eigen::VectorXd step = Al.ldlt().solve(-(jac.J.transpose() * r));
        const Eigen::VectorXd cand = u + step;
        Eigen::VectorXd rc;
        const bool ok = residuals(point(cand), rc) && rc.size() == r.size() && rc.allFinite();
        if (ok && step.squaredNorm() > 0.0)  // Broyden: the secant condition along the step
          jac.J += ((rc - r) - jac.J * step) * (step.transpose() / step.squaredNorm());
        if (ok && rc.squaredNorm() < f) {
          const double gain = f - rc.squaredNorm();
          u = cand;
          r = rc;
          f = rc.squaredNorm();
          mu = std::max(mu / 10, 1e-9);
          improved = true;
          if (gain < min_gain) it = iterations;  // converged
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
