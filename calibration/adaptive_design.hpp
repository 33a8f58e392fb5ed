#pragma once
// The design the Griddy Gibbs samples over (docs/method.md §4 step 3, made adaptive).
//
// \par Rounds
// Round 0 is the paper's design: a Latin hypercube in the region (region.hpp), uniform over it.
// When the posterior is much smaller than the region (the usual case once the region holds the
// whole contour), few of these points carry weight. Each further round ("adaptive") places points
// where the posterior mass lies, from a mixture of K Gaussian kernels with a common covariance
// (population Monte Carlo, Cappé, Guillin, Marin & Robert 2004):
//     q_r(z) = (1/K) Σ_c N(z; z_c, h² C),
// the centres z_c drawn from the design so far in proportion to the posterior weights (systematic
// resampling; round 1 adds the region's traced ridge floor points, region.hpp), except a share
// ν0/(ESS + ν0) of them taken from what the region knows: where the traced ridge is straight (every
// floor point inside the Gaussian guess's own 1 % contour, widened 1.5 times), a stratified sample
// of N(m, C) with m the weighted mean shrunk towards the region's guess mean with the same weight;
// where it bends (a thin curved tube, which no common covariance follows), the floor points
// themselves, each kernel with its own local Gaussian (Region::ridge_cov, sd widened 1.5 times),
// allotted in proportion to posterior(z_q)·sqrt(det Σ_q); C the weighted posterior covariance
// shrunk towards the region's Gaussian guess with the weight of ν0 = 10 (d + 1) points, C =
// (ESS·C_w + ν0·C_guess)/(ESS + ν0), so that a round resting on a handful of heavy points still
// explores around them with a sensible shape; and h = max(h_min, Silverman's factor
// (4/(d+2))^{1/(d+4)} ESS^{−1/(d+4)}). Kernels on the heavy points follow a curved ridge, which no
// single Gaussian or box does, and reach past the region where the posterior does (their support is
// unbounded). A fraction `broad_share` (0.2) of every such round comes instead from one broad
// Gaussian, N(m, (broad_scale)² C) at the weighted mean m (broad_scale 2): a defensive component
// (Hesterberg 1995) that keeps the weights bounded in the tails, where the kernels are thin.
// A round's points are a Latin hypercube in (0,1)^d mapped through Φ⁻¹ (a stratified normal
// sample); the first round(broad_share · M_r) take the broad component, the others kernel i mod K.
// Points outside the bounds [0,1]^d have prior 0: they are drawn and counted, never simulated. Each
// round draws M_r points, enough that about the requested number fall inside the bounds (the inside
// fraction is measured on a seeded pilot sample of 4096 draws, without simulating).
//
// \par Design weights (deterministic mixture)
// Together the rounds are one sample from the mixture of their proposals, of point density
//     q(z) = Σ_r M_r q_r(z)       (q_r: uniform 1/V_r on the region, or the round's Gaussian
//                                   mixture, each component weighted by its share of the points),
// and with the prior uniform on the bounds a design point stands for a volume ∝ 1/q(z_k). The
// posterior over the design is therefore
//     P(k | τ) ∝ exp(−τ SSE_k / 2) / q(z_k),
// the Griddy Gibbs with design weights ω_k = −log q(z_k) (gibbs.hpp). These are the
// deterministic-mixture ("balance heuristic") importance weights of Veach & Guibas (1995) and
// Owen & Zhou (2000), used adaptively as in AMIS (Cornuet, Marin, Mira & Robert 2012). The uniform
// round 0 stays in the mixture: it keeps every weight bounded over the region (a defensive
// component). With a single uniform round every ω_k is equal and the sampler is the paper's,
// exactly.
//
// \par Diagnostics (after every round; τ integrated out under its Gamma(a, b) prior)
//     w_k ∝ (b + SSE_k / 2)^−(a + n/2) / q(z_k)
// ESS = (Σ w)² / Σ w² (Kish), the largest single share max w / Σ w, the weighted mean and sd of
// every parameter, and the edge share: the weight of points in the outer `edge_fraction` of the
// region along an axis whose side can still grow (below the reach of the bounds). A one-round
// design ("lhs") whose edge share is above `edge_share_max` is warned about: the region may cut
// the posterior off.
//
// \par Stopping
// After an adaptive round r >= 1: stop when ESS >= target_ess and no parameter's weighted mean
// moved by more than `settle` of its sd, nor its sd changed by more than the fraction `settle`,
// since the previous round. Otherwise go on until max_rounds adaptive rounds; the result says
// which rule stopped it and warns, in words, when the posterior is still resolved by too few
// points.
//
// \par Reproducibility
// Round r draws from seeds derived from (seed, r); its points depend only on the SSEs of the
// rounds before it, so a resumed design regenerates the same points.
#include <Eigen/Dense>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/region.hpp"

namespace dtwin::calib {

struct AdaptiveDesignOptions {
  bool adaptive = true;        ///< false: round 0 only (the paper's design)
  int first_points = 200;      ///< round 0 (sizes.lhs_points), >= 2
  int round_points = 200;      ///< each adaptive round, >= 2
  int max_rounds = 8;          ///< adaptive rounds after round 0, >= 0
  double target_ess = 400;     ///< stop only when the importance ESS reaches this, > 0
  double settle = 0.1;         ///< stop when means moved < settle·sd and sds changed < settle, > 0
  double kernel_min = 0.5;     ///< smallest kernel factor h_min, in (0, 2]
  int kernels = 50;            ///< kernels K of a mixture round, >= 1
  double broad_share = 0.2;    ///< share of a round from the defensive component, in [0, 1)
  double broad_scale = 2.0;    ///< its sd scale, >= 1
  double edge_fraction = 0.1;  ///< outer shell of the region checked, in (0, 0.5)
  double edge_share_max = 0.01;  ///< posterior weight in that shell above which a one-round design
                                 ///< is warned about, in (0, 1)
  double tau_a = kDefaultTauPrior,
         tau_b = kDefaultTauPrior;  ///< Gamma prior of τ (diagnostic weights), finite, >= 0
  std::uint64_t seed = 1;
  /// Throws InputError whose where() is "design.<field>" (common/validate.hpp).
  void validate() const;
  nlohmann::json toJson() const;
};

struct DesignRound {
  int index = 0;
  std::string kind;         ///< "uniform" (on `region`) or "gaussian" (kernels at `centres`)
  Region region;            ///< uniform rounds
  Eigen::MatrixXd centres;  ///< gaussian rounds: K x d kernel centres, scaled
  Eigen::MatrixXd cov;      ///< gaussian rounds: the kernels' covariance, scaled
  Eigen::MatrixXd chol;     ///< its lower Cholesky factor (set by prepare())
  /// Gaussian rounds: empty, or one entry per centre: that kernel's own covariance (a ridge
  /// kernel's local Gaussian, Region::ridge_cov), or an empty matrix for `cov`.
  std::vector<Eigen::MatrixXd> own_cov;
  std::vector<Eigen::MatrixXd> own_chol;  ///< their Cholesky factors (set by prepare())
  std::vector<double> own_logdet;  ///< log det of each own_chol (0 where the kernel uses `cov`)
  double logdet = 0.0;             ///< log det of `chol` (set by prepare())
  /// The lower Cholesky factor of centre c's kernel, and its log determinant.
  bool ownKernel(Eigen::Index c) const {
    const auto k = static_cast<std::size_t>(c);
    return k < own_chol.size() && own_chol[k].size() > 0;
  }
  const Eigen::MatrixXd& cholOf(Eigen::Index c) const {
    return ownKernel(c) ? own_chol[static_cast<std::size_t>(c)] : chol;
  }
  double logdetOf(Eigen::Index c) const {
    return ownKernel(c) ? own_logdet[static_cast<std::size_t>(c)] : logdet;
  }
  /// Gaussian rounds: the defensive component, taking the first round(broad_share · M) points.
  double broad_share = 0.0;
  Eigen::VectorXd broad_mean;
  Eigen::MatrixXd broad_cov, broad_chol;
  /// Computes the Cholesky factors (call once the round is filled in).
  void prepare();
  /// Points of a draw of m that the defensive component takes (the rest cycle over the kernels).
  long broadCount(long m) const;
  long drawn = 0;            ///< M_r, points drawn (also those outside the bounds)
  int first = 0, count = 0;  ///< its rows of the design
  // Posterior diagnostics over every point up to and including this round.
  double ess = 0.0, top_share = 0.0, edge_share = 0.0;
  std::vector<double> mean_theta, sd_theta;  ///< physical units
  nlohmann::json toJson(const std::vector<std::string>& names) const;
};

/// SSE of the rows of `points` (physical units), which are design rows first .. first+rows−1.
/// +inf for a failed simulation.
using DesignEvaluator =
    std::function<std::vector<double>(const Eigen::MatrixXd& points, int first)>;

struct AdaptiveDesign {
  Eigen::MatrixXd points;          ///< N x d, physical units
  std::vector<double> sse;         ///< N
  std::vector<double> log_weight;  ///< ω_k = −log q(z_k), shifted so the largest is 0
  std::vector<DesignRound> rounds;
  std::string stop_reason;
  std::vector<std::string> warnings;
  double ess = 0.0, top_share = 0.0;  ///< after the last round
  nlohmann::json toJson(const std::vector<std::string>& names) const;
};

/// The points of one round (scaled coordinates, every one inside [0,1]^d): uniform on `region` or
/// Gaussian N(mean, cov), about `inside` of them; `drawn` receives M_r (also those outside).
Eigen::MatrixXd drawRound(const DesignRound& round, int inside, std::uint64_t seed, long& drawn);

/// Runs the rounds from `region` (round 0), evaluating each round's points with `evaluate`.
AdaptiveDesign runAdaptiveDesign(const Region& region, int n_data,
                                 const AdaptiveDesignOptions& options,
                                 const DesignEvaluator& evaluate);

/// log q(z) of the design's mixture at scaled point z (q as above, up to no constant).
double logMixtureDensity(const std::vector<DesignRound>& rounds, const Eigen::VectorXd& z);

}  // namespace dtwin::calib
