#pragma once
// Profile-likelihood intervals of the calibrated parameters (docs/calibration.md, "Two 95 %
// intervals").
//
// \par Definition
// For one parameter θ_j and a value v, the profile SSE is SSE_p(v) = min SSE(θ) over the other
// parameters with θ_j = v. With the noise variance estimated, the likelihood-ratio statistic
// F = (SSE_p(v) − SSE*) / s²,  s² = SSE* / (n − d),  SSE* the best fit,
// follows F(1, n − d) when v is the truth (exactly for a linear model, asymptotically otherwise).
// The 95 % profile interval is
//     { v : SSE_p(v) <= SSE* + c s² },   c = F_{1, n−d}(0.95) = t²_{n−d, 0.975}.
// For a logged drive, whose residuals are correlated in time, parameter j's threshold is
// SSE* + t²_{B−1} s² κ_j instead (correlated.hpp). The interval does not depend on the prior.
// Where the data leave a long valley of nearly equal fits that ends at a bound, the posterior
// spreads its mass along the valley in proportion to parameter volume, and its central interval can
// exclude a truth at the valley's steep end (the demo's solid-axle assembly, seeds 1001–1008); the
// profile interval holds every value the data do not reject.
//
// \par Computation (no new simulations for step 1)
// 1. From every evaluated point (the design, the traced ridge floor, the optimum): SSE* is the
//    smallest SSE, and the interval of θ_j starts as [min, max] of θ_j over the points with
//    SSE <= SSE* + c s².
// 2. Each end is pushed outwards by profile points: θ_j set to v with the other parameters
//    re-optimised (Levenberg–Marquardt, subspace_lm.hpp, `lm_iterations` iterations, warm-started
//    from the end's values; central differences of 5 % of each parameter's interval, once per
//    end: the Jacobian is then carried from point to point with Broyden updates, and computed
//    afresh for a point that ends outside the threshold before it counts as outside). The search
//    uses g(v) = sqrt(SSE_p(v) − SSE*), linear in v for a quadratic profile, and the target
//    g_T = sqrt(c s²): secant steps through the last two inside points (at first the best fit and
//    the end) while no outside point is known, at most 4 times the distance covered so far, then
//    regula falsi in the bracket [last inside, first outside], kept 10 % inside it. At most `steps`
//    profile points, or until the bracket is below 1 % of the interval, or the bound is reached.
//    A warm start that ends above the threshold first gets `polish_iterations` more LM iterations
//    (a curved valley needs more than a straight one). Where the SSE has several basins, a warm
//    start can stop in the wrong one and overstate
//    SSE_p(v), cutting the interval short. So when the warm start ends above the threshold, the
//    step is retried from up to `restarts` other starts: the evaluated points of lowest SSE whose
//    θ_j lies near v (within the step just taken, at least 5 % of the interval), moved to θ_j = v;
//    the lowest fit counts.
//    The design places few points where the posterior has little volume; the profile reaches there.
//    Every end is a point whose SSE is within the threshold, so an end can only be short of the
//    true profile end, never beyond it; a short end is what the coverage benchmark would show.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/correlated.hpp"
#include "calibration/region.hpp"

namespace dtwin::calib {

/// Quantile of Student's t with ν > 0 degrees of freedom at p ∈ (0, 1) (bisection on the CDF,
/// which is the regularized incomplete beta function by its continued fraction; |error| < 1e-10).
double studentQuantile(double p, double nu);

struct ProfileOptions {
  double level = 0.95;    ///< in (0, 1)
  int steps = 12;         ///< profile points per end (0: the evaluated points only)
  int lm_iterations = 2;  ///< Levenberg–Marquardt iterations per profile point, >= 1
  int restarts = 2;       ///< extra starts of a profile point whose warm start ends outside, >= 0
  int polish_iterations =
      2;  ///< further LM iterations, from the warm start's end, when it ends outside, >= 0
  /// Forward differences (d − 1 runs per Jacobian, not 2(d − 1)): for a smooth SSE (frozen steps;
  /// calibrateAssembly sets it then, and records it in profile.json, not in the options: it
  /// follows from the steps).
  bool forward_differences = false;
  void validate() const;
  nlohmann::json toJson() const;
};

/// Step 1: the threshold and the ends found among the evaluated points.
struct ProfilePlan {
  std::vector<double> lower, upper;  ///< the calibration bounds (physical)
  int n_data = 0, dof = 0;           ///< n and n − d (n when n <= d)
  double sse_best = 0.0, s2 = 0.0, c = 0.0, threshold = 0.0;
  /// Per parameter: threshold, or SSE* + t²_{B−1} s² κ_j when the residuals are correlated in
  /// time (correlated.hpp).
  std::vector<double> thresholds;
  CorrelationAdjustment correlation;
  double thresholdOf(int j) const { return thresholds[static_cast<std::size_t>(j)]; }
  std::vector<std::vector<double>> low_point, high_point;  ///< θ at each parameter's ends
  std::vector<double> low_sse, high_sse;
  Eigen::MatrixXd points;          ///< every evaluated point (physical), for restarts
  std::vector<double> sse;         ///< their SSE (+inf: failed)
  std::vector<double> best_point;  ///< the point whose SSE is sse_best
};

/// `points` N x d (physical), `sse` N (+inf: failed). Throws InputError when no SSE is finite.
/// `correlation` (blockAdjustment; empty: independent residuals) sets each parameter's threshold.
ProfilePlan planProfile(const Eigen::MatrixXd& points, const std::vector<double>& sse, int n_data,
                        const std::vector<double>& lower, const std::vector<double>& upper,
                        const ProfileOptions& options,
                        const CorrelationAdjustment& correlation = {});

struct ProfileEnd {
  std::vector<double> theta;  ///< the end (physical), inside the threshold
  double sse = 0.0;
  bool at_bound = false;  ///< the profile stays inside up to the calibration bound
  int evaluations = 0;
  int steps_taken = 0;  ///< profile points that moved the end
  int jacobians = 0;  ///< finite-difference Jacobians computed (the rest carried, subspace_lm.hpp)
  int outside_points =
      0;  ///< profile points that landed outside the threshold (brackets of the end)
};

/// Step 2 for end `index` in [0, 2d): parameter index / 2, lower end for even indices.
ProfileEnd refineProfileEnd(const ResidualFunction& residuals, const ProfilePlan& plan, int index,
                            const ProfileOptions& options);

struct ProfileIntervals {
  std::vector<double> lower, upper;
  std::vector<bool> lower_at_bound, upper_at_bound;
  double level = 0.95, c = 0.0, s2 = 0.0, sse_best = 0.0, threshold = 0.0;
  std::vector<double> thresholds;     ///< per parameter (ProfilePlan::thresholds)
  CorrelationAdjustment correlation;  ///< blocks 0: the residuals taken as independent
  int dof = 0, evaluations = 0;
  /// The evaluated point whose SSE is sse_best (physical); empty when read from an older
  /// profile.json. Below the optimiser's optimum, it is the calibration's optimum
  /// (CalibrationRun::profile).
  std::vector<double> best_point;
  /// Per end, in index order (parameter j's lower end at 2j): simulations, profile points that
  /// moved the end, finite-difference Jacobians. Empty when read from an older profile.json.
  std::vector<int> end_evaluations, end_steps, end_jacobians, end_outside;
  nlohmann::json toJson() const;
  static ProfileIntervals fromJson(const nlohmann::json& j);
};

/// The intervals from the plan and its 2d refined ends (index order).
ProfileIntervals collectProfile(const ProfilePlan& plan, const std::vector<ProfileEnd>& ends,
                                const ProfileOptions& options);

}  // namespace dtwin::calib
