#pragma once
// Ledoit–Wolf shrinkage of a sample covariance towards a scaled identity, computed from a
// streaming MomentAccumulator (docs/method.md §5: "Ledoit–Wolf shrinkage as an option").
//
// \par Theory (Ledoit & Wolf 2004, "A well-conditioned estimator for large-dimensional
// covariance matrices", J. Multivariate Anal. 88, 365–411, Lemma 3.2 and Theorem 3.2)
// With the n vectors centred at their sample mean, x_k = x̃_k − μ, the inner product
// ⟨A, B⟩ = tr(A Bᵀ) / p and its norm ‖A‖² = ‖A‖²_F / p:
//     S_n  = (1/n) Σ_k x_k x_kᵀ = M2 / n               (the 1/n sample covariance)
//     m    = ⟨S_n, I⟩ = tr(S_n) / p                    (scale of the target m I)
//     d²   = ‖S_n − m I‖² = (‖S_n‖²_F − p m²) / p
//     b̄²   = (1/n²) Σ_k ‖x_k x_kᵀ − S_n‖²
//     b²   = min(b̄², d²),   a² = d² − b²
//     Σ*   = (b²/d²) m I + (a²/d²) S_n = ρ m I + (1 − ρ) S_n,   ρ = b²/d² ∈ [0, 1].
// This is also what scikit-learn's ledoit_wolf(assume_centered=False) computes.
//
// \par Streaming form of b̄²
// ‖x xᵀ − S‖²_F = ‖x‖⁴ − 2 xᵀ S x + ‖S‖²_F and Σ_k x_kᵀ S_n x_k = tr(S_n Σ_k x_k x_kᵀ) = n
// ‖S_n‖²_F, so Σ_k ‖x_k x_kᵀ − S_n‖²_F = Q − n ‖S_n‖²_F with Q = Σ_k ‖x_k − μ‖⁴, the scalar fourth
// moment that MomentAccumulator keeps when MomentOptions::track_fourth_moment is set (its streaming
// update needs the p-vector T = Σ ‖x − μ‖² (x − μ) and one O(p²) symmetric matrix-vector product
// per update; see moments.hpp). Hence
//     b̄² = (Q − n ‖S_n‖²_F) / (p n²).
// We chose this identity over accumulating Σ_k (x_k − μ)_i² (x_k − μ)_j² (a second p×p matrix,
// another 8 p² bytes and O(p²) per vector) because it needs only p + 1 extra numbers.
// Cost of calcLedoitWolf: O(p²) for ‖S_n‖²_F and, when forming Σ*, one p×p matrix.
//
// \par Degenerate case
// If d² = 0, S_n already equals m I; then ρ = 0 and Σ* = S_n.
//
// Note that Σ* is built on the 1/n covariance S_n, as in the paper; the unshrunk path of the
// classifier uses the unbiased M2 / (n − 1). The two differ by the factor n / (n − 1).
#include <Eigen/Core>
#include <cstdint>

#include "classification/moments.hpp"

namespace dtwin::classify {

struct LedoitWolfEstimate {
  std::int64_t count = 0;     ///< n
  int dimension = 0;          ///< p
  double target_scale = 0.0;  ///< m = tr(S_n) / p
  double d2 = 0.0;            ///< d² = ‖S_n − m I‖²  (normalised Frobenius, / p)
  double b2_bar = 0.0;        ///< b̄² (before the min with d²)
  double intensity = 0.0;     ///< ρ = min(b̄², d²) / d² ∈ [0, 1], the weight on the target
  /// Σ* = ρ m I + (1 − ρ) S_n, full symmetric p×p (empty when form_matrix is false).
  Eigen::MatrixXd covariance;
};

/// The Ledoit–Wolf estimate from `acc`. Throws InputError if `acc` does not track the fourth
/// moment or holds fewer than 2 vectors. With form_matrix = false only the scalars are computed.
LedoitWolfEstimate calcLedoitWolf(const MomentAccumulator& acc, bool form_matrix = true);

}  // namespace dtwin::classify
