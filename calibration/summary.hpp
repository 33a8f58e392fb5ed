#pragma once
// Posterior summaries of Griddy Gibbs chains (docs/method.md §4 step 6).
//
// \par Definitions (draws x_1..x_S of one quantity)
//  * mean  x̄ = Σ x_t / S;  sd = sqrt(Σ (x_t − x̄)² / (S − 1))  (0 when S = 1).
//  * quantile q(p): Hyndman & Fan (1996) type 7, the default of R and NumPy: with the sorted
//    draws x_(0) <= .. <= x_(S−1), h = (S − 1) p, q = x_(⌊h⌋) + (h − ⌊h⌋)(x_(⌊h⌋+1) − x_(⌊h⌋)).
//    The 95 % interval is [q(0.025), q(0.975)].
//  * effective sample size: Geyer's (1992) initial monotone sequence estimator. With the
//    autocorrelations ρ_t (biased autocovariance / lag-0 autocovariance, computed by FFT in
//    O(S log S)), the pair sums P_m = ρ_{2m} + ρ_{2m+1} are summed while positive and forced to
//    be non-increasing; τ_int = −1 + 2 Σ_m P_m and ESS = S / τ_int. For a chain with zero
//    variance (every draw identical) the ESS is undefined and reported as NaN.
// For θ_j the draws are θ_j(k_t), the design-point coordinates along the index chain.
//
// \par Degeneracy check
// If a single design point carries more than `dominance_threshold` (default 0.9) of the draws,
// the posterior is essentially that one point: the design is too coarse for the data (the
// likelihood is narrower than the spacing of the design points). The summary flags this and
// says so; the remedy is more design points or the adaptive design (adaptive_design.hpp).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "calibration/gibbs.hpp"
#include "common/statistics.hpp"

namespace dtwin::calib {

struct DrawSummary {
  std::string name;
  double mean = 0.0;
  double sd = 0.0;
  double q025 = 0.0;  ///< 2.5 % quantile (type 7)
  double q975 = 0.0;  ///< 97.5 % quantile (type 7)
  double ess = 0.0;   ///< effective sample size (Geyer IMSE); NaN for a constant chain
};

struct SummaryOptions {
  double dominance_threshold = 0.9;  ///< in (0, 1]; flag when one point's share exceeds it
  /// Throws InputError whose where() is "summary.<field>" (common/validate.hpp).
  void validate() const;
};

struct PosteriorSummary {
  std::vector<DrawSummary> parameters;  ///< one per column of the design
  DrawSummary tau;                      ///< error precision τ [1/output unit²]
  int draws = 0;                        ///< S (after burn-in)
  int distinct_points = 0;              ///< design points visited at least once
  int top_point = -1;                   ///< the most visited design point (lowest index on ties)
  double top_share = 0.0;               ///< its share of the draws, in (0, 1]
  bool design_too_coarse = false;       ///< top_share > dominance_threshold
  std::string message;                  ///< explanation when design_too_coarse, else empty
  std::string briefReport() const;
  std::string fullReport() const;
};

/// Geyer initial-monotone-sequence ESS of one chain (S >= 1). NaN for a constant chain.
double effectiveSampleSize(const std::vector<double>& x);

/// Mean, sd, 2.5 %/97.5 % quantiles and ESS of one chain (non-empty).
DrawSummary summariseDraws(const std::vector<double>& x, const std::string& name = "");

/// Summaries of θ (design row chains.index[t]) and τ. `design` is N x d with N =
/// chains.design_points; `names` (optional) has d entries, default "theta_1".."theta_d".
/// Throws InputError on inconsistent sizes or an empty chain.
PosteriorSummary summarisePosterior(const Eigen::MatrixXd& design, const GibbsChains& chains,
                                    const std::vector<std::string>& names = {},
                                    const SummaryOptions& options = {});

}  // namespace dtwin::calib
