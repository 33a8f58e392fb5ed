#include "classification/mvn.hpp"
#include "common/format.hpp"

#include <Eigen/Cholesky>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::classify {

namespace {

constexpr double kLn2Pi = 1.83787706640934548356065947281123527;  // ln(2π)
constexpr const char* kGaussianWhere = "Gaussian model";

}  // namespace

void FactorOptions::validate() const {
  const OptionCheck check("factor");
  check.finite("pivot_tolerance", pivot_tolerance);  // negative: the default p · 2.2e-16
  check.positive("jitter_initial", jitter_initial);
  check.require(std::isfinite(jitter_growth) && jitter_growth > 1.0, "jitter_growth",
                "must be a finite number > 1, got " + formatNumber(jitter_growth));
  check.require(std::isfinite(jitter_max) && jitter_max >= jitter_initial, "jitter_max",
                "must be a finite number >= jitter_initial (" + formatNumber(jitter_initial) +
                    "), got " + formatNumber(jitter_max));
}

GaussianModel::GaussianModel(const Eigen::VectorXd& mean, const Eigen::MatrixXd& cov,
                             const FactorOptions& options) {
  options.validate();
  const Eigen::Index p = mean.size();
  if (p < 1) throw InputError(kGaussianWhere, "mean is empty");
  if (cov.rows() != p || cov.cols() != p)
    throw InputError(kGaussianWhere, "covariance is " + std::to_string(cov.rows()) + "x" +
                                         std::to_string(cov.cols()) + ", expected " +
                                         std::to_string(p) + "x" + std::to_string(p) +
                                         " (the length of the mean)");
  if (!mean.allFinite()) throw InputError(kGaussianWhere, "mean has a non-finite entry");
  if (!cov.allFinite()) throw InputError(kGaussianWhere, "covariance has a non-finite entry");
  const double max_abs = cov.cwiseAbs().maxCoeff();
  for (Eigen::Index j = 0; j < p; ++j) {
    if (cov(j, j) < 0.0)
      throw InputError(kGaussianWhere, "covariance diagonal entry " + std::to_string(j) + " is " +
                                           formatNumber(cov(j, j)) + " (a variance must be >= 0)");
    for (Eigen::Index i = 0; i < j; ++i)
      if (std::abs(cov(i, j) - cov(j, i)) > 1e-10 * max_abs)
        throw InputError(kGaussianWhere, "covariance is not symmetric: entry (" +
                                             std::to_string(i) + ", " + std::to_string(j) +
                                             ") = " + formatNumber(cov(i, j)) + " but (" +
                                             std::to_string(j) + ", " + std::to_string(i) +
                                             ") = " + formatNumber(cov(j, i)));
  }
  const double max_diag = cov.diagonal().maxCoeff();
  const double mean_diag = cov.diagonal().mean();
  if (!(max_diag > 0.0))
    throw InputError(kGaussianWhere, "covariance is zero on its whole diagonal");
  const double rel_tol = options.pivot_tolerance < 0.0 ? static_cast<double>(p) * DBL_EPSILON
                                                       : options.pivot_tolerance;
  const double tol = rel_tol * max_diag;
  mean_ = mean;
  std::string tried;  // what failed, for the error message

  // Cholesky of cov + add·I in place in factor_; accepted if every L_ii² > tol.
  auto tryCholesky = [&](double add) {
    factor_ = cov;
    if (add > 0.0) factor_.diagonal().array() += add;
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> llt(factor_);
    if (llt.info() != Eigen::Success) return false;
    const double min_pivot = factor_.diagonal().array().square().minCoeff();
    min_pivot_rel_ = min_pivot / max_diag;
    return min_pivot > tol;
  };

  bool done = false;
  if (options.try_cholesky) {
    done = tryCholesky(0.0);
    if (done)
      factorization_ = "cholesky";
    else
      tried += "Cholesky failed; ";
  }
  if (!done && options.try_ldlt) {
    Eigen::LDLT<Eigen::MatrixXd, Eigen::Lower> ldlt(cov);
    if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > tol) {
      // P Σ Pᵀ = L̂ D L̂ᵀ = (L̂ D^½)(L̂ D^½)ᵀ: scale column j of the unit factor by √D_j.
      factor_ = ldlt.matrixLDLT();
      for (Eigen::Index j = 0; j < p; ++j) {
        const double s = std::sqrt(factor_(j, j));
        factor_(j, j) = s;
        factor_.col(j).tail(p - j - 1) *= s;
      }
      min_pivot_rel_ = ldlt.vectorD().minCoeff() / max_diag;
      // P as an index map: apply the transpositions to 0, 1, .., p−1.
      Eigen::VectorXd index = Eigen::VectorXd::LinSpaced(p, 0.0, static_cast<double>(p - 1));
      index = ldlt.transpositionsP() * index;
      perm_ = index.cast<int>();
      factorization_ = "ldlt";
      done = true;
    } else {
      tried +=
          "LDLT has a non-positive pivot (smallest D = " + formatNumber(ldlt.vectorD().minCoeff()) +
          "); ";
    }
  }
  if (!done) {
    for (int k = 0;; ++k) {
      const double eps = options.jitter_initial * std::pow(options.jitter_growth, k);
      if (eps > options.jitter_max * (1.0 + 1e-12)) break;
      if (tryCholesky(eps * mean_diag)) {
        jitter_ = eps;
        jitter_abs_ = eps * mean_diag;
        factorization_ = "cholesky+jitter(" + formatNumber(eps) + ")";
        done = true;
        break;
      }
    }
    if (!done) {
      factor_.resize(0, 0);
      throw InputError(kGaussianWhere,
                       "covariance is not positive definite: " + tried +
                           "Cholesky with jitter up to " + formatNumber(options.jitter_max) +
                           " x mean(diag) = " + formatNumber(options.jitter_max * mean_diag) +
                           " also failed (relative pivot tolerance " + formatNumber(rel_tol) + ")");
    }
  }
  log_det_ = 2.0 * factor_.diagonal().array().log().sum();
}

double GaussianModel::logPdf(const Eigen::VectorXd& y) const {
  const Eigen::Index p = mean_.size();
  if (y.size() != p)
    throw InputError(kGaussianWhere, "record has length " + std::to_string(y.size()) +
                                         ", expected " + std::to_string(p));
  Eigen::VectorXd z(p);
  if (perm_.size() == 0)
    z = y - mean_;
  else
    for (Eigen::Index i = 0; i < p; ++i) z[i] = y[perm_[i]] - mean_[perm_[i]];
  factor_.triangularView<Eigen::Lower>().solveInPlace(z);  // z = L⁻¹ P (y − μ)
  return -0.5 * (static_cast<double>(p) * kLn2Pi + log_det_ + z.squaredNorm());
}

Eigen::VectorXd GaussianModel::logPdfBatch(const Eigen::MatrixXd& Y) const {
  const Eigen::Index p = mean_.size();
  if (Y.rows() != p)
    throw InputError(kGaussianWhere, "record matrix has " + std::to_string(Y.rows()) +
                                         " rows, expected " + std::to_string(p) +
                                         " (one record per column)");
  Eigen::MatrixXd Z(p, Y.cols());
  if (perm_.size() == 0)
    Z = Y.colwise() - mean_;
  else
    for (Eigen::Index i = 0; i < p; ++i) Z.row(i) = Y.row(perm_[i]).array() - mean_[perm_[i]];
  factor_.triangularView<Eigen::Lower>().solveInPlace(Z);  // one TRSM for all records
  const double c = static_cast<double>(p) * kLn2Pi + log_det_;
  return (-0.5 * (Z.colwise().squaredNorm().array() + c)).transpose();
}

}  // namespace dtwin::classify
