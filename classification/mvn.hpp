#pragma once
// Multivariate normal model of one assembly's outputs (docs/method.md §5): built once per assembly,
// then evaluated for every field record.
//
// \par Theory
// For y ∈ ℝᵖ, y ~ N(μ, Σ) and a factor Σ = Pᵀ L Lᵀ P (L lower triangular with positive diagonal,
// P a permutation, identity for plain Cholesky):
//     ln N(y; μ, Σ) = −½ ( p ln 2π + ln det Σ + ‖z‖² ),   z = L⁻¹ P (y − μ),
//     ln det Σ = 2 Σ_i ln L_ii.
// z comes from one forward triangular solve; Σ⁻¹ and det Σ are never formed (det Σ under- or
// overflows for p in the thousands, Σ⁻¹ loses accuracy). logPdfBatch solves for all records at
// once (one triangular solve with R right-hand sides, a level-3 TRSM).
//
// \par Factorisation (in this order; the first that is accepted wins)
//  1. "cholesky": Σ = L Lᵀ (Eigen::LLT, unpivoted).
//  2. "ldlt": the pivoted (robust) Cholesky P Σ Pᵀ = L̂ D L̂ᵀ of Eigen::LDLT (symmetric diagonal
//     pivoting: the largest remaining diagonal first), accepted only if every D_i is positive;
//     then L = L̂ D^½. (In exact arithmetic its smallest pivot is never larger than Cholesky's, so
//     this step only rescues matrices where the two differ by rounding.)
//  3. "cholesky+jitter(ε)": Σ + ε · mean(diag Σ) · I with ε = jitter_initial, ×jitter_growth, ...
//     up to jitter_max (defaults 1e-10, ×10, 1e-3), the first ε whose Cholesky is accepted.
//     The label prints ε with %g, e.g. "cholesky+jitter(1e-08)".
// A factor is accepted when every squared pivot (L_ii², resp. D_i) exceeds
//     pivot_tolerance · max_i Σ_ii,     pivot_tolerance default p · 2.2e-16,
// i.e. a pivot must be above the rounding level of the matrix: a rank-deficient Σ (e.g. fewer
// samples than dimensions) often "succeeds" in floating point with pivots of order 1e-17 that are
// pure rounding noise and would give meaningless likelihoods. If even ε = jitter_max fails, the
// constructor throws an InputError. Because the jitter is relative to the MEAN diagonal, outputs
// of very different scales should be standardised before fitting.
//
// \par Cost (p = dimension)
// Memory: one p×p matrix (the factor; p = 5001: 200 MB); the LDLT step holds a second one while
// it runs. Time: Cholesky p³/3 flops (blocked); LDLT is unblocked in Eigen and ~4x slower; logPdf
// p² flops; logPdfBatch p² R flops at matrix-matrix speed. Measured for p = 5001 (one core, -O2,
// no -march): Cholesky 2.7 s, LDLT 11 s, logPdf 4.9 ms, logPdfBatch 2 ms per record (R = 64).
#include <Eigen/Core>
#include <string>

namespace dtwin::classify {

struct FactorOptions {
  /// Relative pivot threshold (see header); a negative value means p · 2.2e-16.
  double pivot_tolerance = -1.0;
  bool try_cholesky = true;       ///< step 1 (false skips straight to LDLT/jitter)
  bool try_ldlt = true;           ///< step 2
  double jitter_initial = 1e-10;  ///< first ε of step 3, > 0
  double jitter_growth = 10.0;    ///< factor between successive ε, > 1
  double jitter_max = 1e-3;       ///< largest ε tried, >= jitter_initial
  /// InputError whose where() is "factor.<field>" (common/validate.hpp).
  void validate() const;
};

class GaussianModel {
 public:
  /// Factors `cov` (p×p, symmetric within 1e-10 · max|Σ_ij|, finite, positive diagonal) for the
  /// mean `mean` (length p, finite). Throws InputError on bad input or when no step is accepted.
  GaussianModel(const Eigen::VectorXd& mean, const Eigen::MatrixXd& cov,
                const FactorOptions& options = {});

  int dimension() const { return static_cast<int>(mean_.size()); }
  const Eigen::VectorXd& mean() const { return mean_; }
  /// "cholesky", "ldlt" or "cholesky+jitter(1e-08)" (ε printed with %g).
  const std::string& factorization() const { return factorization_; }
  /// ε of step 3 (relative to mean(diag Σ)); 0 when no jitter was added.
  double jitter() const { return jitter_; }
  /// The absolute amount added to every diagonal entry, ε · mean(diag Σ); 0 without jitter.
  double jitterAbsolute() const { return jitter_abs_; }
  /// ln det of the factored matrix (Σ, or Σ + jitter I) = 2 Σ ln L_ii.
  double logDeterminant() const { return log_det_; }
  /// Smallest squared pivot / max diag Σ of the accepted factor (a conditioning indicator).
  double relativeMinPivot() const { return min_pivot_rel_; }
  /// The lower-triangular factor L (only the lower triangle is meaningful).
  const Eigen::MatrixXd& getFactor() const { return factor_; }

  /// ln N(y; μ, Σ) for one record y (length p, else InputError). Non-finite y gives NaN.
  double logPdf(const Eigen::VectorXd& y) const;
  /// ln N(y_r; μ, Σ) for the R columns y_r of Y (p×R, records as columns). Equal to logPdf of
  /// each column within rounding.
  Eigen::VectorXd logPdfBatch(const Eigen::MatrixXd& Y) const;

 private:
  Eigen::VectorXd mean_;
  Eigen::MatrixXd factor_;  // L, lower triangle
  Eigen::VectorXi perm_;    // P as an index map: (P r)_i = r[perm_[i]]; empty = identity
  std::string factorization_;
  double jitter_ = 0.0;
  double jitter_abs_ = 0.0;
  double log_det_ = 0.0;
  double min_pivot_rel_ = 0.0;
};

}  // namespace dtwin::classify
