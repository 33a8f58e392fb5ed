#pragma once
// The region of θ the design covers (docs/method.md §4 step 2): the paper's one-at-a-time box, or
// the joint region that holds the whole 1 % likelihood-ratio contour (the default,
// docs/calibration.md).
//
// \par Coordinates
// Scaled z_j = (θ_j − l_j)/(u_j − l_j) ∈ [0, 1] over the calibration bounds l, u (as the
// optimiser). A region is a parallelepiped with orthonormal axes in these coordinates,
//     P = { c + A t : t_i ∈ [t_lo_i, t_hi_i] },   A orthonormal (columns a_i),
// of volume Π_i (t_hi_i − t_lo_i) (scaled units). The prior of θ is uniform on the bounds
// [0, 1]^d; the design lives in P ∩ [0, 1]^d (points of P outside the bounds have prior 0 and are
// never simulated).
//
// \par The paper's box (region = "paper")
// A = I, c = ẑ and the extents of the one-at-a-time sweeps of feasible_box.hpp: each parameter
// moved alone, the others held at θ̂. When parameters trade off (a ridge in the SSE) this box is
// a thin slice through the contour and the posterior inside it is far too narrow.
//
// \par The joint region (region = "joint", the default)
// With weighted residuals r(θ) = sqrt(w)(η(θ) − y), SSE = |r|², the Gauss–Newton model at ẑ is
//     SSE(z) ≈ SSE_min + (z − ẑ)ᵀ H (z − ẑ),   H = JᵀJ,   J = ∂r/∂z
// (J by central differences of step h, one-sided at a bound: 2d simulations). The 1 % contour
// SSE <= T (T = SSE_min (1 + 2 ln 100 / n), feasible_box.hpp) is then the ellipsoid
// (z − ẑ)ᵀ H (z − ẑ) <= ΔT, ΔT = T − SSE_min, with axes the eigenvectors v_i of H (eigenvalues
// λ_i) and semi-axes s_i = sqrt(ΔT / λ_i). For an ellipsoid the cross-section along a principal
// axis equals the projection on it, so the parallelepiped with axes v_i and extents ±s_i is the
// smallest one with these axes that holds the contour; for a Gaussian posterior it holds 99.8 % of
// each principal component and, for d = 4, 99 % of the joint mass.
// The quadratic gives the axes; the extents are measured: a sweep along ±v_i from ẑ (the stepping
// and bisection of feasible_box.hpp, first step min(s_i, 0.2)/2, bisection to 5 % of the
// crossing) finds the real crossing e_i^± of the contour, and the extent is
//     t_i^± = margin · e_i^±                                  (margin default 1.25)
// — the margin covers a contour that bends away from the axes (and the adaptive design's kernels
// reach past the region where the posterior does). The sweep is what
// counts where the quadratic is poor: along a ridge J is nearly rank-deficient, λ_i is close to 0
// (within the integrator's noise) and s_i means nothing, while the SSE still rises to T at a
// finite distance the sweep finds. Extents never exceed the reach of the bounds along the axis
// (max over the cube's corners of ±(corner − ẑ)·v_i), and a sweep that reaches the bound still
// inside the contour takes that reach: the contour may then extend to the bound all over. An
// unidentified direction (λ_i <= 0 or tiny) gets s_i = √d. A stencil simulation that fails leaves
// that parameter's column of J zero (unidentified) and is reported.
//
// \par Ridges (profile traces)
// A straight sweep measures the contour along a line. When the SSE has a weakly identified
// direction (a ridge: two parameters that trade off), the ridge floor is often curved, and a line
// leaves it long before the contour ends — on the demo, a truth inside the 1 % contour lay 0.375
// down the ridge but 2.6 crossings off the straight line in the stiffest direction. The weak axes
// (the weakest, and every axis with λ_i <= ridge_ratio · λ_min) are therefore traced as profiles:
// step t along ±v_i and re-optimise the other coordinates u (z = ẑ ± t v_i + B u, B the other
// axes) by Levenberg–Marquardt on the residuals (at most 3 iterations, warm-started by
// extrapolating the last two floor points; the Jacobian starts as the plan's J·B and is carried
// along the trace with Broyden updates, subspace_lm.hpp; a floor point that lands outside the
// contour is re-minimised with central differences of 10 % of each axis's crossing first),
// until the profile SSE exceeds T (the crossing is interpolated between the last two floor points,
// linearly in sqrt(SSE − SSE_min), exact for a quadratic profile), the bounds' reach is passed,
// or 30 steps (halvings included) are used. Steps start
// at a quarter of the straight crossing and grow x1.5 while the profile rises by less than
// σ̂²/2 per step (shrink x0.6 above 3 σ̂², σ̂² = SSE_min/n). A step whose floor lies outside the
// contour is halved and retried from the last floor point, down to 1/16 of the first step, before
// the trace concludes that the contour ends there: a grown step can jump off a thin, bending
// ridge (on the demo's solid-axle assembly one did, and the truth lay beyond it). The region then
// holds every traced floor point with the margin (along the traced axis: margin · the crossing;
// across it: the floor point's offset plus margin · that axis's crossing), and the floor points
// inside the contour are kept (`ridge`) so the adaptive design can put kernels on them.
//
// The region also carries a Gaussian guess of the posterior: mean ẑ + Σ_i a_i (e_i^+ − e_i^−)/2 and
// sd (e_i^+ + e_i^−) / (2 sqrt(2 ln 100)) along a_i — the Gaussian whose 1 % contour has the
// measured crossings (adaptive_design.hpp starts from it).
// Sign of each v_i: its largest-magnitude component is positive (a deterministic choice).
// A contour that is not convex or bends strongly is caught later: the adaptive design
// (adaptive_design.hpp) measures the posterior weight near the region's edges and widens it.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/common.hpp"
#include "calibration/feasible_box.hpp"

namespace dtwin::calib {

/// Weighted residuals r(θ) = sqrt(w)(η(θ) − y), so SSE = |r|²; empty for a failed simulation.
/// Must be thread-safe when run through a concurrent hook.
using ResidualFunction = std::function<std::vector<double>(const std::vector<double>& theta)>;

struct Region {
  std::string kind;  ///< "paper" (one-at-a-time box) or "joint"
  std::vector<double> lower,
      upper;               ///< the calibration bounds (physical units): the prior's support
  Eigen::VectorXd centre;  ///< c, scaled
  Eigen::MatrixXd axes;    ///< A, d x d, orthonormal columns (scaled)
  Eigen::VectorXd t_lower, t_upper;  ///< extents along each axis, t_lower <= 0 <= t_upper (scaled)
  /// How far the bounds reach from the centre along −a_i / +a_i (max over the cube's corners):
  /// an extent at its reach cannot grow (the prior ends there).
  Eigen::VectorXd reach_lower, reach_upper;
  /// The Gaussian guess of the posterior (scaled): mean `guess_mean`, sd `guess_sd` along each
  /// axis.
  Eigen::VectorXd guess_mean, guess_sd;
  /// Traced ridge floor points inside the contour (rows, scaled) and their SSE; empty for the
  /// paper's box.
  Eigen::MatrixXd ridge;
  std::vector<double> ridge_sse;
  /// Per ridge row: a local Gaussian of the posterior there (scaled), the floor's cross-section
  /// (RidgeTrace::cross) plus its tangent dz/dt times ℓ, half the larger gap to the neighbouring
  /// floor points of its trace (the trace's start counts as one at t = 0):
  ///     Σ_q = ℓ² g gᵀ + cross_q,   g = the floor's tangent per unit t (central difference).
  /// Where the posterior is a thin bent tube these follow it, which no common covariance does
  /// (adaptive_design.hpp). Empty matrices where the cross-section is unknown; the whole vector
  /// is empty for the paper's box and for a box.json written before it existed.
  std::vector<Eigen::MatrixXd> ridge_cov;
  double threshold = 0.0;  ///< T of the 1 % contour
  double sse_min = 0.0;
  int evaluations = 0;                ///< simulations spent building the region
  std::vector<std::string> messages;  ///< anything that needs the user's attention

  int dim() const { return static_cast<int>(lower.size()); }
  /// log Π (t_upper − t_lower) (scaled units).
  double logVolume() const;
  Eigen::VectorXd toScaled(const std::vector<double>& theta) const;
  std::vector<double> toPhysical(const Eigen::VectorXd& z) const;
  /// c + A t (scaled).
  Eigen::VectorXd at(const Eigen::VectorXd& t) const { return centre + axes * t; }
  /// Aᵀ (z − c): the region coordinates t of a scaled point.
  Eigen::VectorXd coordinates(const Eigen::VectorXd& z) const {
    return axes.transpose() * (z - centre);
  }
  /// z lies in P (the bounds are not checked).
  bool contains(const Eigen::VectorXd& z) const;
  /// A (guess_sd²) Aᵀ: the covariance of the Gaussian guess (scaled).
  Eigen::MatrixXd guessCovariance() const {
    return axes * guess_sd.cwiseAbs2().asDiagonal() * axes.transpose();
  }
  /// The side can still grow: its extent is below the reach of the bounds.
  bool openLower(int i) const { return -t_lower(i) < reach_lower(i) * (1.0 - 1e-9); }
  bool openUpper(int i) const { return t_upper(i) < reach_upper(i) * (1.0 - 1e-9); }
  /// The axis-aligned bounding box of P ∩ [0, 1]^d in physical units (the "box" of summaries).
  void boundingBox(std::vector<double>& lo, std::vector<double>& hi) const;
  nlohmann::json toJson() const;
  static Region fromJson(const nlohmann::json& j);
  std::string briefReport() const;
};

/// z lies in [0, 1]^d (inclusive).
bool insideUnitCube(const Eigen::VectorXd& z);

/// `r` with its extents [t_lower, t_upper] narrowed to the smallest box in region coordinates
/// that still holds every point of P ∩ [0, 1]^d, by interval propagation of the cube's 2d faces
/// through z = c + A t (each pass bounds t_i by the others' current intervals; repeated until no
/// extent moves). P ∩ [0, 1]^d is unchanged, only the part of P outside the bounds shrinks. The
/// extents keep 0 (the centre). Where a sweep was clipped by a bound, an extent is the bounds'
/// reach along its axis, far beyond the cube for an axis that leaves it steeply: the narrowed
/// region is what the first design round draws from then (adaptive_design.cpp).
Region narrowedToCube(const Region& r);

/// The paper's box as a region (A = I, extents from its sweeps).
Region regionFromBox(const FeasibleBox& box, const BoxProblem& problem);

struct JointRegionOptions {
  double jacobian_step = 1e-2;  ///< central-difference step h (scaled), in (0, 0.5]
  double margin = 1.25;         ///< extents = margin · sweep crossing, >= 1
  double relative_tolerance =
      0.05;                    ///< bisection stops at this fraction of the crossing, in (0, 1)
  double growth = 2.0;         ///< sweep step growth, > 1
  int max_evaluations = 40;    ///< per sweep, >= 2
  double ridge_ratio = 100.0;  ///< trace every axis with λ_i <= ridge_ratio · λ_min, >= 1
  int ridge_steps = 30;        ///< steps per ridge trace, halvings included (0: no traces), >= 0
  /// Forward differences in the ridge traces (d − 1 runs per Jacobian, not 2(d − 1)): for a smooth
  /// SSE (frozen steps; calibrateAssembly sets it then, and records it in the stage file, not
  /// in the options: it follows from the steps).
  bool forward_differences = false;
  /// Throws InputError whose where() is "joint_region.<field>" (common/validate.hpp).
  void validate() const;
  nlohmann::json toJson() const;
};

/// The Gauss–Newton model at θ̂, from which the sweeps go out.
struct JointRegionPlan {
  BoxProblem problem;
  Eigen::MatrixXd jacobian;                  ///< n x d, ∂r/∂z (scaled)
  Eigen::VectorXd eigenvalues;               ///< λ_i of H = JᵀJ, ascending
  Eigen::MatrixXd axes;                      ///< v_i, columns
  Eigen::VectorXd half_width;                ///< s_i = sqrt(ΔT/λ_i) (capped at √d)
  Eigen::VectorXd reach_lower, reach_upper;  ///< how far the bounds reach along ∓v_i / +v_i
  std::vector<std::string> messages;
  int evaluations = 0;
};

/// The 2d stencil points (physical units) of the central differences: index 2j is θ̂ − h e_j
/// (clipped to the bound), 2j+1 is θ̂ + h e_j.
std::vector<std::vector<double>> jacobianStencil(const BoxProblem& problem,
                                                 const JointRegionOptions& options);

/// The Gauss–Newton model from the residuals at the stencil points (same order; an empty vector
/// is a failed simulation).
JointRegionPlan planJointRegion(const BoxProblem& problem,
                                const std::vector<std::vector<double>>& residuals,
                                const JointRegionOptions& options);

/// Sweep `index` in [0, 2d): axis i = index / 2, towards −v_i for even indices, +v_i for odd.
RaySweep calcRegionSweep(const SseFunction& sse, const JointRegionPlan& plan, int index,
                         const JointRegionOptions& options);

/// A ridge traced from θ̂ along a weak axis: the profile floor point at each step.
struct RidgeTrace {
  int axis = 0, direction = 0;
  std::vector<double> t;           ///< distance along the axis (scaled), one per floor point
  std::vector<Eigen::VectorXd> z;  ///< the floor points (scaled)
  std::vector<double> sse;         ///< the profile SSE there
  /// At each floor point, the posterior's cross-section there (scaled, d x d, rank d − 1):
  /// σ² B (JᵀJ)⁻¹ Bᵀ from the trace's carried Jacobian J = ∂r/∂u across the traced axis,
  /// σ² = SSE_min / n. An empty matrix where J was unknown or singular.
  std::vector<Eigen::MatrixXd> cross;
  bool closed = false;  ///< the profile crossed T (the last point lies outside)
  /// Where the profile crosses T: interpolated between the last two floor points, linearly in
  /// sqrt(SSE − SSE_min) (exact for a quadratic profile). Set when closed.
  double crossing = 0.0;
  bool clipped = false;  ///< the bounds' reach was passed inside the contour
  int evaluations = 0;
  std::string message;  ///< why it stopped early, when it did
};

/// The axes traced as ridges (ascending): the weakest and every axis with λ_i <= ridge_ratio·λ_min.
std::vector<int> ridgeAxes(const JointRegionPlan& plan, const JointRegionOptions& options);

/// Trace `index` in [0, 2·ridgeAxes().size()): ridge axis ridgeAxes()[index / 2], towards −v
/// for even indices, +v for odd ones. Needs the finished straight sweeps (their crossings set the
/// step sizes).
RidgeTrace calcRidgeTrace(const ResidualFunction& residuals, const JointRegionPlan& plan,
                          const std::vector<RaySweep>& sweeps, int index,
                          const JointRegionOptions& options);

/// The region from the plan, its 2d finished sweeps (index order) and its ridge traces.
Region collectJointRegion(const JointRegionPlan& plan, const std::vector<RaySweep>& sweeps,
                          const std::vector<RidgeTrace>& traces, const JointRegionOptions& options);

/// All of it: stencil (2d residual runs), sweeps (2d), ridge traces, each through `parallel_for`.
Region calcJointRegion(const SseFunction& sse, const ResidualFunction& residuals,
                       const BoxProblem& problem, const JointRegionOptions& options = {},
                       const ParallelFor& parallel_for = sequentialFor);

}  // namespace dtwin::calib
