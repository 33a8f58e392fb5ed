#pragma once
// The feasible box around the optimum (docs/method.md §4 step 2).
//
// \par Theory
// With Gaussian errors of precision τ the likelihood ratio of θ against θ̂ is
//     LR(θ) = exp(−τ̂ (SSE(θ) − SSE_min) / 2),   τ̂ = n / SSE_min.
// LR(θ) >= 1 % is equivalent to
//     SSE(θ) <= T,   T = SSE_min · (1 + 2 ln(100) / n),
// the "1 % likelihood-ratio contour". For a quadratic SSE(θ) = SSE_min + c (θ_j − θ̂_j)² along
// axis j the contour crosses at θ̂_j ± sqrt((T − SSE_min)/c).
//
// \par Procedure (one "sweep" per parameter j and direction s = ±1; the others fixed at θ̂)
// In scaled coordinates z_j = (θ_j − l_j)/(u_j − l_j):
//  1. steps h_k = initial_step · growth^k (geometric, k = 0, 1, ..): evaluate SSE at
//     z = ẑ_j + s·h_k, clipped to [0, 1], until SSE > T (bracketed) or the clipped point, i.e.
//     the bound, still has SSE <= T (edge clipped at the bound);
//  2. bisection between the last point inside (SSE <= T) and the first point outside until
//     their distance is below `tolerance`; the edge reported is the OUTER end of the final
//     bracket, so the box contains the crossing (conservative by at most `tolerance`).
// The first crossing met is used: if SSE is not monotone along the ray, islands of low SSE
// farther out are not found. A non-finite SSE (failed simulation) counts as outside (> T).
// If θ̂_j already lies on the bound in direction s, the edge is that bound (clipped, 0 evals).
// If the evaluation budget runs out before the crossing is bracketed, the edge is the farthest
// point known to be inside, `bracketed` is false and `message` says so: the box is then too
// small in that direction and the caller should warn or enlarge `max_evaluations`.
//
// \par SSE_min = 0
// An exact fit (noise-free data) gives τ̂ = ∞ and T = SSE_min: the contour degenerates to the
// point θ̂. calcFeasibleBox then throws InputError (saying so) rather than return a zero-width
// box; a non-finite or negative SSE_min is rejected the same way.
#include <functional>
#include <string>
#include <vector>

#include "calibration/common.hpp"

namespace dtwin::calib {

struct FeasibleBoxOptions {
  double initial_step = 0.01;  ///< first step, scaled units (fraction of the bound range), > 0
  double growth = 2.0;         ///< geometric step growth factor, > 1
  double tolerance = 1e-3;     ///< bisection stops when the bracket is below this (scaled), > 0
  int max_evaluations = 60;    ///< budget per sweep (stepping + bisection), >= 1
  /// Throws InputError whose where() is "feasible_box.<field>" (common/validate.hpp).
  void validate() const;
};

/// The problem every sweep shares.
struct BoxProblem {
  std::vector<double> theta_hat;     ///< θ̂ (physical units), inside the bounds
  double sse_min = 0.0;              ///< SSE(θ̂) > 0
  int n_data = 0;                    ///< n, number of scalar residuals in the SSE, >= 1
  std::vector<double> lower, upper;  ///< bounds (physical units)
  /// T = SSE_min (1 + 2 ln(100) / n).
  double threshold() const;
  /// Throws InputError for inconsistent sizes, θ̂ outside the bounds, bad n or SSE_min.
  void validate() const;
};

/// Result of one one-sided sweep.
struct SweepResult {
  int parameter = 0;       ///< j
  int direction = 0;       ///< −1 (towards the lower bound) or +1 (towards the upper bound)
  double edge = 0.0;       ///< edge in physical units
  double edge_sse = 0.0;   ///< SSE at `edge`: > T (or inf) when bracketed, <= T when clipped
                           ///< (SSE_min, not re-evaluated, when θ̂ itself is on the bound)
  bool clipped = false;    ///< the contour reaches the bound: edge = bound
  bool bracketed = false;  ///< the crossing was bracketed (false with clipped = true is normal)
  int evaluations = 0;
  std::string message;  ///< empty unless something needs the user's attention
};

struct FeasibleBox {
  std::vector<double> lower, upper;                ///< box edges, physical units
  std::vector<bool> lower_clipped, upper_clipped;  ///< edge sits on the calibration bound
  double threshold = 0.0;                          ///< T
  int evaluations = 0;                             ///< total over all sweeps
  std::vector<SweepResult> sweeps;                 ///< 2d sweeps, index 2j (lower), 2j+1 (upper)
  /// False when any sweep ran out of budget before bracketing (see SweepResult::message).
  bool complete() const;
  std::string briefReport() const;
};

/// One sweep along a ray from θ̂: t >= 0 is the scaled distance from θ̂, t_max where the ray leaves
/// the calibration bounds. The stepping and bisection of the procedure above, on any ray.
struct RaySweep {
  double t_edge = 0.0;    ///< the edge: outer end of the final bracket, or t_max when clipped
  double edge_sse = 0.0;  ///< SSE at t_edge (as SweepResult::edge_sse)
  bool clipped = false;   ///< the contour reaches t_max
  bool bracketed = false;
  bool budget_out = false;  ///< max_evaluations ran out before bracketing (t_edge: farthest inside)
  bool loose = false;       ///< bracketed, but bisection stopped by the budget above the tolerance
  double bracket = 0.0;     ///< final bracket width (scaled)
  int evaluations = 0;
};

/// Sweeps `sse_at(t)` (SSE at scaled distance t along the ray, t in (0, t_max]) for the crossing
/// of `threshold`, starting with steps of `options.initial_step` (or `first_step` when > 0).
/// `sse0` is the SSE at t = 0. t_max <= 0: clipped at once (0 evaluations). With
/// `relative_tolerance` > 0 the bisection stops when the bracket is below that fraction of its
/// outer end (instead of options.tolerance).
RaySweep sweepRay(const std::function<double(double t)>& sse_at, double t_max, double threshold,
                  double sse0, const FeasibleBoxOptions& options, double first_step = 0.0,
                  double relative_tolerance = 0.0);

/// The one-sided sweep `index` in [0, 2d): parameter j = index / 2, direction −1 for even
/// indices and +1 for odd ones. Independent of every other sweep (run them in any order).
SweepResult calcBoxSweep(const SseFunction& sse, const BoxProblem& problem, int index,
                         const FeasibleBoxOptions& options = {});

/// All 2d sweeps through `parallel_for` (task i = sweep i), assembled into a box.
FeasibleBox calcFeasibleBox(const SseFunction& sse, const BoxProblem& problem,
                            const FeasibleBoxOptions& options = {},
                            const ParallelFor& parallel_for = sequentialFor);

/// The box of finished sweeps (index i = sweep i, as calcBoxSweep): what calcFeasibleBox returns.
/// For callers that run the sweeps themselves (e.g. spread over MPI ranks).
FeasibleBox collectFeasibleBox(const BoxProblem& problem, std::vector<SweepResult> sweeps);

}  // namespace dtwin::calib
