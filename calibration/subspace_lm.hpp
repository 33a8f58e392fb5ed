#pragma once
// Levenberg–Marquardt on a subspace: minimise |r(z0 + B u)|² over u, the other coordinates held.
// The inner step of a profile: the ridge traces of region.hpp (z0 moves along a principal axis)
// and the profile intervals of profile.hpp (z0 moves along a parameter) share it.
#include <Eigen/Dense>
#include <functional>

namespace dtwin::calib {

/// Residuals at a scaled point z; false for a failed simulation.
using ScaledResiduals = std::function<bool(const Eigen::VectorXd& z, Eigen::VectorXd& r)>;

/// A Jacobian ∂r/∂u carried from one call to the next on the same subspace B (the steps of one
/// ridge trace or one profile end, where z0 moves a little between calls). The steps of a trace
/// or an end are close, and on a smooth objective (frozen steps, docs/calibration.md) the
/// Jacobian changes slowly along them, so finite differences once and Broyden's rank-one update
/// after every trial point (J += (Δr − J s) sᵀ / sᵀs) replace the 2m runs of each iteration.
/// An iteration whose carried Jacobian gives no improving step recomputes it by finite
/// differences and tries again; clear() forces that at the next call.
struct SubspaceJacobian {
  Eigen::MatrixXd J;  ///< n x m; empty: none yet
  int computed = 0;   ///< finite-difference Jacobians evaluated (2m runs each; m forward)
  int reused = 0;     ///< iterations that took the carried Jacobian
  void clear() { J.resize(0, 0); }
};

/// What minimiseOnSubspace may do beyond the defaults of the profile and the ridge traces.
struct SubspaceLmSettings {
  int tries = 3;  ///< trial steps per iteration (λ × 10 after each rejected one), >= 1
  double min_rel_gain =
      0.0;  ///< also converged when an accepted step gains less than this fraction of f
  /// Converged only on a step from a fresh Jacobian: a small gain from a carried one may be the
  /// carried Jacobian's fault, so the Jacobian is recomputed and the iterations go on.
  bool converge_on_fresh = false;
  /// Bounds on u (both empty: none): trial points are clipped into them, and the differences of
  /// coordinate c stay inside ((r(u + h⁺) − r(u − h⁻)) / (h⁺ + h⁻), one-sided at a bound).
  Eigen::VectorXd lower, upper;
  /// Forward differences from the current point (m runs, not 2m): for a smooth objective (frozen
  /// steps), where the step's truncation error, not the integrator's noise, limits the Jacobian.
  bool forward = false;
  int threads = 1;  ///< workers for the 2m runs of one difference Jacobian (residuals must then be
                    ///< thread-safe)
};

/// From u: at most `iterations` Levenberg–Marquardt iterations on |r(z0 + B u)|² (Jacobian by
/// central differences of step h_c along column c of B (forward with settings.forward), or the
/// carried one; damping λ·diag(JᵀJ), λ from 1e-3, ÷10 after an accepted step, ×10 after a rejected
/// one, settings.tries tries per iteration). Stops early when an accepted step gains less than
/// `min_gain` (or settings.min_rel_gain × f). On return u, r and f = |r|² are the best point seen.
/// Returns false when the simulation at the start point fails.
bool minimiseOnSubspace(const ScaledResiduals& residuals, const Eigen::VectorXd& z0,
                        const Eigen::MatrixXd& B, const Eigen::VectorXd& h, int iterations,
                        double min_gain, Eigen::VectorXd& u, Eigen::VectorXd& r, double& f,
                        SubspaceJacobian* carried = nullptr,
                        const SubspaceLmSettings& settings = {});

}  // namespace dtwin::calib
