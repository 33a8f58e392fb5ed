#pragma once
// Two-block "Griddy Gibbs" sampler over simulated design points (docs/method.md §4 steps 4–5).
//
// \par Model
// Data y ∈ R^n, model output η(θ), Gaussian errors with precision τ:
//     p(y | θ, τ) ∝ τ^{n/2} exp(−τ SSE(θ) / 2).
// θ is restricted to the N design points θ_1..θ_N (a Latin hypercube in the feasible box, so a
// uniform prior on the box becomes a uniform prior on k ∈ {1..N}); τ ~ Gamma(a, b) (shape a,
// rate b; density ∝ τ^{a−1} e^{−bτ}). The defaults a = b = 1e-3 are the customary vague choice:
// prior mean a/b = 1, prior variance a/b² = 1000; with n data points they carry the weight of
// 2a = 0.002 pseudo-observations, i.e. nothing.
//
// \par Full conditionals
//     P(k | τ, y)  ∝ exp(−τ SSE_k / 2)                          (categorical over the design)
//     τ | k, y     ~ Gamma(shape a + n/2, rate b + SSE_k / 2)
// SSE_k is the FULL sum over every repetition and every time point (not over replicate means).
// The categorical weights are computed stably: w_k = exp(−τ (SSE_k − SSE_min) / 2), i.e. the
// maximum log weight −τ SSE_min/2 is subtracted before exponentiating (the authors' script has
// this sign wrong), so the best point has weight exactly 1 and the sum never overflows or
// underflows to 0. Points with non-finite SSE (failed simulations) get weight 0.
//
// \par Design weights
// When the design points are not a uniform sample of the box (an adaptive design,
// adaptive_design.hpp), each point stands for a volume ∝ 1/q(θ_k) and carries a log design weight
// ω_k = −log q(θ_k):
//     P(k | τ, y)  ∝ exp(ω_k − τ SSE_k / 2).
// Equal ω_k (or none given) is the paper's sampler, bit for bit.
//
// \par Implementation
// The finite points are sorted once by SSE. Each iteration accumulates the cumulative weights in
// that order and stops as soon as τ (SSE_k − SSE_min)/2 > 746, where exp() underflows to exactly
// 0 in double precision — so the result is identical to summing all N terms, but a concentrated
// posterior costs only the few points that matter. k is drawn by inverse CDF: U·W_total is
// located in the cumulative sums by binary search.
//
// \par Reproducibility
// One RandomStream(seed, kStreamGibbs, chain) per chain. Per iteration exactly one uniform is
// drawn for k, then the Gamma variate (Marsaglia–Tsang, see sampleGamma).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "calibration/common.hpp"
#include "subsystems/random.hpp"

namespace dtwin::calib {

/// Gamma(shape, rate 1) variate (multiply by 1/rate for another rate). shape > 0.
/// Marsaglia & Tsang (2000), "A simple method for generating gamma variables", ACM TOMS 26(3):
/// with d = shape − 1/3, c = 1/sqrt(9d): draw x ~ N(0,1), v = (1 + c x)³ (retry if v <= 0),
/// u ~ U(0,1); accept d·v if u < 1 − 0.0331 x⁴ (squeeze) or ln u < x²/2 + d(1 − v + ln v).
/// For shape < 1 the standard boost: Gamma(shape) = Gamma(shape + 1) · u^{1/shape}.
/// Uses only RandomStream::normal/uniform, so it is portable bit for bit.
double sampleGamma(RandomStream& rng, double shape);

struct GibbsOptions {
  int iterations =
      kDefaultGibbsIterations;  ///< total iterations S (paper: 50000), including burn-in
  int burn_in =
      kDefaultGibbsBurnIn;  ///< discarded from the start (paper: 15000); 0 <= burn_in < iterations
  double a = kDefaultTauPrior;  ///< prior shape of τ, finite, >= 0
  double b =
      kDefaultTauPrior;  ///< prior rate of τ, finite, >= 0 (b = 0 needs SSE_k > 0 for every point)
  std::uint64_t seed = 1;
  std::uint64_t chain = 0;  ///< stream index: independent chains from one seed
  /// τ at the start. NaN (default) means n / SSE_min, or (a + n/2)/b when SSE_min = 0.
  double initial_tau = std::numeric_limits<double>::quiet_NaN();
  /// Throws InputError whose where() is "gibbs.<field>" (common/validate.hpp).
  void validate() const;
};

struct GibbsChains {
  std::vector<int>
      index;  ///< design-point index k_t (0-based into the SSE vector), t after burn-in
  std::vector<double> tau;   ///< τ_t, same length
  int design_points = 0;     ///< N
  int failed_points = 0;     ///< design points with non-finite SSE (weight 0)
  int n_data = 0;            ///< n
  double sse_min = 0.0;      ///< smallest finite SSE_k
  double initial_tau = 0.0;  ///< τ the chain started from (resolves the NaN default)
  GibbsOptions options;      ///< as run (records the seed)
};

/// Runs the two-block Gibbs sampler. `sse[k]` is SSE at design point k (+inf = failed);
/// n_data >= 1; `log_weight` (empty: all equal) the design weights ω_k, finite, one per point.
/// Throws InputError when there is no finite SSE, an SSE is negative, n_data < 1, the weights
/// have the wrong size or are not finite, or the options are invalid.
GibbsChains runGriddyGibbs(const std::vector<double>& sse, int n_data,
                           const GibbsOptions& options = {},
                           const std::vector<double>& log_weight = {});

}  // namespace dtwin::calib
