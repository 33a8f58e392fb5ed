#pragma once
// Bounded multi-start minimisation of SSE(θ) with NLopt (docs/method.md §4 step 1).
//
// \par Problem
//     θ̂ = argmin_{l <= θ <= u} SSE(θ),   SSE_min = SSE(θ̂),   τ̂ = n / SSE_min.
//
// \par Scaling
// The calibrated parameters span orders of magnitude (tire stiffness ~1e5 N/m, damping ~1e3
// N s/m), so NLopt works on the unit cube: z_j = (θ_j − l_j)/(u_j − l_j) ∈ [0, 1],
// θ_j = l_j + z_j (u_j − l_j). Step sizes and x tolerances below are in these scaled units.
//
// \par Algorithm
// Default NLOPT_LN_BOBYQA (Powell 2009): a derivative-free trust-region method that interpolates
// a quadratic model of the objective and honours bound constraints natively. SSE is a smooth sum
// of squares near its minimum, which is exactly the case where a quadratic model converges in
// few evaluations (typically 10–30·d); every evaluation is a full vehicle simulation, so the
// evaluation count is what matters. Gradient methods would need finite differences through an
// adaptive-step ODE solver (noisy); Nelder–Mead/Subplex (LN_SBPLX) are more tolerant of noisy or
// discontinuous objectives but need several times more evaluations — choose them by name
// through OptimizerOptions::algorithm when the SSE is rough.
//
// \par Starts
// Without screening: start 0 is the box centre z = (½, .., ½); starts 1..m−1 are the rows of a
// Latin hypercube of m−1 points in [0,1]^d drawn with RandomStream(seed, kStreamOptimizerStarts, ·)
// (see lhs.hpp).
// With screening (screen_per_start = s > 0, the default): the SSE is first evaluated at the box
// centre and at a Latin hypercube of s·m points of the bounds (its own seeded stream), and the m
// starts are the best of them, in order of SSE (ties by index), skipping a candidate within 0.05
// (scaled, largest coordinate difference) of a start already taken. A local optimiser started in
// a random place stops in the nearest basin; when the SSE is rugged (a wheel that loses and regains
// contact between two sample times makes steps in it) most such basins are poor: on the demo's
// solid-axle assembly all four unscreened starts stopped 6 to 39 noise variances above the SSE of
// the true parameters in 3 seeds of 8. Screening costs s·m + 1 simulations, run in parallel.
// The best start is the one with the smallest SSE; ties go to the lowest start index, so the
// answer does not depend on the order in which a parallel hook runs the starts.
//
// \par Failed evaluations
// NLopt must never see a non-finite value. Inside the objective a non-finite SSE (failed
// simulation) is replaced by a finite penalty: 10 × (largest finite SSE seen so far in this start)
// + 1, or 1e100 when no finite value has been seen yet. The result of a start is the best FINITE
// evaluation that start made (tracked by us, not taken from NLopt), so a penalty value is never
// reported as an optimum; a start that saw no finite SSE reports sse = +inf and theta = start.
// While a start has seen only failures its landscape is flat (constant penalty), so a simplex
// method may stop there at once; the other starts cover the box (hence several starts).
// An exception thrown by the SseFunction is not swallowed: the start stops and minimiseSse
// rethrows it.
#include <cstdint>
#include <string>
#include <vector>

#include "calibration/common.hpp"

namespace dtwin::calib {

struct OptimizerOptions {
  /// NLopt algorithm name without the "NLOPT_" prefix: a local derivative-free algorithm that
  /// supports bound constraints, e.g. "LN_BOBYQA" (default), "LN_SBPLX", "LN_NELDERMEAD",
  /// "LN_COBYLA", "LN_NEWUOA_BOUND".
  std::string algorithm = "LN_BOBYQA";
  double xtol_rel = 1e-6;     ///< stop when a step changes every scaled z_j by < xtol_rel·|z_j|
  double xtol_abs = 1e-9;     ///< ... or by < xtol_abs (scaled units; matters for z near 0)
  double ftol_rel = 1e-10;    ///< stop when SSE changes by < ftol_rel·|SSE|
  double ftol_abs = 0.0;      ///< ... or by < ftol_abs [SSE units]; 0 = off
  int maxeval = 2000;         ///< evaluation budget per start (>= 1)
  double initial_step = 0.1;  ///< initial step in scaled units, in (0, 0.5]
  int screen_per_start = 25;  ///< screening points per start (0: no screening), >= 0
  /// Throws InputError whose where() is "optimizer.<field>" (common/validate.hpp).
  void validate() const;
};

/// One local run.
struct StartResult {
  std::vector<double> start;      ///< starting point θ0 (physical units)
  std::vector<double> theta;      ///< best finite point found by this start (physical units)
  double sse = 0.0;               ///< SSE(theta); +inf if no evaluation of this start was finite
  int evaluations = 0;            ///< SSE evaluations made by this start
  int nonfinite_evaluations = 0;  ///< how many of them returned a non-finite SSE
  std::string status;  ///< NLopt termination reason, e.g. "XTOL_REACHED", "MAXEVAL_REACHED"
};

struct Optimum {
  std::vector<double> theta;        ///< θ̂, the best over all starts (physical units)
  double sse = 0.0;                 ///< SSE_min = SSE(θ̂); +inf if no start found a finite value
  int best_start = -1;              ///< index into `starts` of the winner
  int evaluations = 0;              ///< total over all starts
  std::vector<StartResult> starts;  ///< in start-index order (0 = box centre)
  /// One line: "SSE_min 1.234e+05 at [..] (start 2 of 5, 512 evaluations)".
  std::string briefReport() const;
  /// One line per start plus the brief report.
  std::string fullReport() const;
};

/// The unscreened starting points (physical units): row 0 the box centre, rows 1.. a Latin
/// hypercube of starts−1 points. Exposed so callers can log or replay them.
std::vector<std::vector<double>> optimizerStarts(const std::vector<double>& lower,
                                                 const std::vector<double>& upper, int starts,
                                                 std::uint64_t seed);

/// The screening candidates (physical units): the box centre, then a Latin hypercube of
/// per_start · starts points of the bounds.
std::vector<std::vector<double>> screeningPoints(const std::vector<double>& lower,
                                                 const std::vector<double>& upper, int starts,
                                                 int per_start, std::uint64_t seed);

/// The `starts` best screening candidates by SSE (ties by index, non-finite last), skipping one
/// within 0.05 scaled units (largest coordinate difference) of a start already taken.
std::vector<std::vector<double>> bestStarts(const std::vector<std::vector<double>>& candidates,
                                            const std::vector<double>& sse,
                                            const std::vector<double>& lower,
                                            const std::vector<double>& upper, int starts);

/// One local NLopt run from `start` (physical units, inside the bounds).
StartResult minimiseFrom(const SseFunction& sse, const std::vector<double>& lower,
                         const std::vector<double>& upper, const std::vector<double>& start,
                         const OptimizerOptions& options = {});

/// Multi-start bounded minimisation. `starts` >= 1. Start i runs as task i of `parallel_for`
/// (default: sequentially on this thread); with a concurrent hook `sse` must be thread-safe.
/// Throws InputError for invalid bounds/options, and rethrows any exception thrown by `sse`.
Optimum minimiseSse(const SseFunction& sse, const std::vector<double>& lower,
                    const std::vector<double>& upper, int starts, std::uint64_t seed,
                    const OptimizerOptions& options = {},
                    const ParallelFor& parallel_for = sequentialFor);

/// The optimum of finished starts (in start-index order): the smallest SSE, ties to the lowest
/// index; what minimiseSse returns. For callers that run the starts themselves (minimiseFrom on
/// optimizerStarts(), e.g. spread over MPI ranks).
Optimum collectOptimum(std::vector<StartResult> starts);

}  // namespace dtwin::calib
