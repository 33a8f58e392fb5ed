#include "classification/shrinkage.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"

namespace dtwin::classify {

LedoitWolfEstimate calcLedoitWolf(const MomentAccumulator& acc, bool form_matrix) {
  if (!acc.tracksFourthMoment())
    throw InputError("Ledoit-Wolf shrinkage",
                     "the accumulator does not track the fourth moment (create it with "
                     "MomentOptions::track_fourth_moment = true)");
  if (acc.count() < 2)
    throw InputError("Ledoit-Wolf shrinkage",
                     "needs at least 2 vectors, got " + std::to_string(acc.count()));
  const int p = acc.dimension();
  const double n = static_cast<double>(acc.count());
  const Eigen::MatrixXd& m2 = acc.getScatterUpper();  // upper triangle only

  // ‖M2‖²_F from the upper triangle: Σ_i M2_ii² + 2 Σ_{i<j} M2_ij².
  double diag_sq = 0.0, off_sq = 0.0, trace_m2 = 0.0;
  for (Eigen::Index j = 0; j < p; ++j) {
    off_sq += m2.col(j).head(j).squaredNorm();
    diag_sq += m2(j, j) * m2(j, j);
    trace_m2 += m2(j, j);
  }
  const double s_frob2 = (diag_sq + 2.0 * off_sq) / (n * n);  // ‖S_n‖²_F
  LedoitWolfEstimate r;
  r.count = acc.count();
  r.dimension = p;
  r.target_scale = trace_m2 / n / p;  // m
  // d² = ‖S_n − m I‖²_F / p, summed term by term (no cancellation when S_n ≈ m I).
  double diag_dev = 0.0;
  for (Eigen::Index j = 0; j < p; ++j) {
    const double e = m2(j, j) / n - r.target_scale;
    diag_dev += e * e;
  }
  r.d2 = (2.0 * off_sq / (n * n) + diag_dev) / p;
  r.b2_bar = std::max(0.0, (acc.getFourthMoment() - n * s_frob2) / (p * n * n));  // b̄²
  r.intensity = r.d2 > 0.0 ? std::min(r.b2_bar, r.d2) / r.d2 : 0.0;               // ρ
  if (form_matrix) {
    r.covariance = m2.selfadjointView<Eigen::Upper>();
    r.covariance *= (1.0 - r.intensity) / n;
    r.covariance.diagonal().array() += r.intensity * r.target_scale;
  }
  return r;
}

}  // namespace dtwin::classify
