#include "calibration/subspace_lm.hpp"

#include <algorithm>

namespace dtwin::calib {

bool minimiseOnSubspace(const ScaledResiduals& residuals, const Eigen::VectorXd& z0, const Eigen::MatrixXd& B,
                        const Eigen::VectorXd& h, int iterations, double min_gain, Eigen::VectorXd& u, Eigen::VectorXd& r,
                        double& f) {
  auto point = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return z0 + B * v; };
  if (!residuals(point(u), r)) return false;
  f = r.squaredNorm();
  const Eigen::Index m = B.cols();
  if (m == 0) return true;
  double mu = 1e-3;
  for (int it = 0; it < iterations; ++it) {
    Eigen::MatrixXd J(r.size(), m);
    bool ok = true;
    for (Eigen::Index c = 0; c < m && ok; ++c) {
      Eigen::VectorXd rp, rm, e = Eigen::VectorXd::Zero(m);
      e(c) = h(c);
      ok = residuals(point(u + e), rp) && residuals(point(u - e), rm) && rp.size() == r.size() && rm.size() == r.size();
      if (ok) J.col(c) = (rp - rm) / (2 * h(c));
    }
    if (!ok) break;
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 3 && !improved; ++tries) {
      Eigen::MatrixXd Al = A;
      for (Eigen::Index c = 0; c < m; ++c) Al(c, c) += mu * std::max(A(c, c), 1e-300);
      const Eigen::VectorXd cand = u + Al.ldlt().solve(-g);
      Eigen::VectorXd rc;
      if (residuals(point(cand), rc) && rc.size() == r.size() && rc.squaredNorm() < f) {
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
    if (!improved) break;
  }
  return true;
}

}  // namespace dtwin::calib
