#include "calibration/correlated.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "calibration/profile.hpp"
#include "common/errors.hpp"

namespace dtwin::calib {

namespace {
/// H⁻¹ by a pseudo-inverse: a direction the data do not determine gets no weight (and κ 1).
Eigen::MatrixXd pseudoInverse(const Eigen::MatrixXd& H) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  const double tol = sv.size() ? sv(0) * 1e-12 * static_cast<double>(H.cols()) : 0.0;
  Eigen::VectorXd inv = Eigen::VectorXd::Zero(sv.size());
  for (Eigen::Index k = 0; k < sv.size(); ++k)
    if (sv(k) > tol) inv(k) = 1.0 / sv(k);
  return svd.matrixV() * inv.asDiagonal() * svd.matrixU().transpose();
}
}  // namespace

std::vector<int> timeBlocks(const std::vector<double>& time_s, const std::vector<int>& set_of,
                            const std::vector<long>& repetition) {
  const std::size_t n = time_s.size();
  DTWIN_CHECK(set_of.size() == n && repetition.size() == n,
              "timeBlocks needs a set and a repetition per record");
  std::vector<int> none(n, -1);
  std::map<int, std::vector<double>> times;  // per set, its distinct times (sorted)
  for (std::size_t i = 0; i < n; ++i) {
    if (repetition[i] != 1) return none;
    times[set_of[i]].push_back(time_s[i]);
  }
  std::map<int, int> first_block;
  int next = 0;
  for (auto& [set, t] : times) {
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    if (t.size() < static_cast<std::size_t>(kBlocks) * kMinTimesPerBlock) return none;
    first_block[set] = next;
    next += kBlocks;
  }
  std::vector<int> block(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = times[set_of[i]];
    const auto rank =
        static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), time_s[i]) - t.begin());
    block[i] = first_block[set_of[i]] + static_cast<int>(rank * kBlocks / t.size());
  }
  return block;
}

CorrelationAdjustment blockAdjustment(const Eigen::MatrixXd& J, const Eigen::VectorXd& r,
                                      const std::vector<int>& block, double s2, double level) {
  const Eigen::Index n = J.rows(), d = J.cols();
  DTWIN_CHECK(r.size() == n && static_cast<Eigen::Index>(block.size()) == n,
              "blockAdjustment needs a residual and a block per row");
  CorrelationAdjustment a;
  a.kappa.assign(static_cast<std::size_t>(d), 1.0);
  const int B = n ? *std::max_element(block.begin(), block.end()) + 1 : 0;
  if (B < 2 || !(s2 > 0) || !J.allFinite() || !r.allFinite()) return a;
  // Per block: g_b = J_bᵀ r_b and H_b = J_bᵀ J_b.
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(d, B);
  std::vector<Eigen::MatrixXd> Hb(static_cast<std::size_t>(B), Eigen::MatrixXd::Zero(d, d));
  for (Eigen::Index i = 0; i < n; ++i) {
    const int b = block[static_cast<std::size_t>(i)];
    DTWIN_CHECK(b >= 0, "blockAdjustment: every row needs a block");
    g.col(b) += r(i) * J.row(i).transpose();
    Hb[static_cast<std::size_t>(b)].noalias() += J.row(i).transpose() * J.row(i);
  }
  const Eigen::MatrixXd H = J.transpose() * J;
  const Eigen::MatrixXd A = pseudoInverse(H);
  // The block jackknife: θ̂ without block b moves by δ_b = −(H − H_b)⁻¹ g_b (one Gauss–Newton
  // step, exact for a linear model); Cov(θ̂) = (B − 1)/B Σ (δ_b − δ̄)(δ_b − δ̄)ᵀ. A block without
  // which H is singular (it alone informs a parameter) moves by −H⁻¹ g_b instead.
  Eigen::MatrixXd delta(d, B);
  for (int b = 0; b < B; ++b) {
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(H - Hb[static_cast<std::size_t>(b)]);
    const bool ok = ldlt.info() == Eigen::Success && ldlt.isPositive() &&
                    (ldlt.vectorD().array() > 1e-12 * H.diagonal().maxCoeff()).all();
    delta.col(b) = ok ? Eigen::VectorXd(ldlt.solve(g.col(b))) : Eigen::VectorXd(A * g.col(b));
  }
  const Eigen::VectorXd mean = delta.rowwise().mean();
  delta.colwise() -= mean;
  const Eigen::MatrixXd cov = (static_cast<double>(B - 1) / B) * (delta * delta.transpose());
  for (Eigen::Index j = 0; j < d; ++j)
    if (A(j, j) > 0 && std::isfinite(cov(j, j)))
      a.kappa[static_cast<std::size_t>(j)] = cov(j, j) / (s2 * A(j, j));
  a.blocks = B;
  const double t = studentQuantile(0.5 + 0.5 * level, B - 1);
  a.quantile = t * t;
  return a;
}

nlohmann::json CorrelationAdjustment::toJson() const {
  return {{"blocks", blocks}, {"kappa", kappa}, {"quantile", quantile}};
}

CorrelationAdjustment CorrelationAdjustment::fromJson(const nlohmann::json& j) {
  CorrelationAdjustment a;
  if (j.is_null()) return a;
  a.blocks = j.at("blocks").get<int>();
  a.kappa = j.at("kappa").get<std::vector<double>>();
  a.quantile = j.at("quantile").get<double>();
  return a;
}

}  // namespace dtwin::calib
