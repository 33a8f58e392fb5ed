#pragma once
// Profile intervals when the residuals are correlated in time (docs/calibration.md, "Intervals
// from a logged drive").
//
// \par Why
// The profile interval's threshold c s² (profile.hpp) assumes independent residuals. A logged
// drive has one repetition and thousands of consecutive samples, and whatever the model leaves
// out (a filter it does not know, a roll in a turn's edge, a speed read from a quantised channel)
// leaves residuals that run in stretches of a second or more. Then n understates nothing about
// the noise but overstates how many independent looks at θ the data hold, and the interval is
// too narrow: on the unknown car's drive A (docs/measurements.md) one of twelve intervals, 0.7 mm
// wide, missed its truth.
//
// \par What
// For a scalar parameter θ_j with the others profiled out, the likelihood-ratio statistic under
// correlated (or misspecified) errors is κ_j χ²₁ instead of χ²₁, with
//     κ_j = (H⁻¹ V H⁻¹)_jj / (s² (H⁻¹)_jj),   H = JᵀJ,   V = Cov(Jᵀr),
// J the weighted residuals' Jacobian at the optimum and r the residuals there (Chandler and Bate
// 2007, "Inference for clustered data using the independence loglikelihood", Biometrika 94; with
// independent residuals H⁻¹VH⁻¹ = s² H⁻¹ and κ_j = 1). H⁻¹VH⁻¹, the covariance of θ̂, is taken
// from the block jackknife (Künsch 1989): each data set's sample times are cut into B contiguous
// blocks of equal count; without block b, one Gauss–Newton step moves θ̂ by
//     δ_b = −(H − H_b)⁻¹ g_b,   g_b = J_bᵀ r_b,  H_b = J_bᵀ J_b   (exact for a linear model),
// and Cov(θ̂) = (B − 1)/B Σ_b (δ_b − δ̄)(δ_b − δ̄)ᵀ. Correlation within a block (seconds of a drive)
// is counted; blocks are taken as independent. With the covariance estimated from B blocks the
// reference distribution is F(1, B − 1), as for cluster-robust inference with few clusters, so
// the threshold of parameter j is
//     SSE* + t²_{B−1, 0.975} s² κ_j.
// κ_j is not floored at 1. The closed-form tests (calib_correlated_test) measure the coverage of
// the resulting interval for a straight line over 400 seeds: 0.950 with independent errors
// (κ averages 1.12: the jackknife overstates a slope's variance a little), 0.943 and 0.927 with
// AR(1) errors of coefficient 0.9 and 0.95 (the independent interval: 0.305 and 0.230). Blocks
// must be long against the residuals' correlation time; the correlation across a block's ends is
// lost.
//
// \par When
// Only when every data set is a single repetition with at least kMinTimesPerBlock × kBlocks
// sample times (a drive). Lab data, whose repetitions give the noise, keep the independent
// threshold, bit for bit.
#include <Eigen/Dense>
#include <vector>

#include <nlohmann/json.hpp>

namespace dtwin::calib {

inline constexpr int kBlocks = 20;            ///< blocks per data set
inline constexpr int kMinTimesPerBlock = 20;  ///< sample times per block, at least

/// The block of each record (−1 everywhere when the adjustment does not apply): records of one
/// data set (`set_of`) with one repetition (`repetition`) are split by the rank of their time
/// (`time_s`) among the set's distinct times into kBlocks blocks; records at one time share a
/// block, so channels sampled together are counted together.
std::vector<int> timeBlocks(const std::vector<double>& time_s, const std::vector<int>& set_of,
                            const std::vector<long>& repetition);

struct CorrelationAdjustment {
  int blocks = 0;             ///< B; 0: not applied (every κ_j = 1)
  std::vector<double> kappa;  ///< κ_j per parameter
  double quantile = 0.0;      ///< t²_{B−1} at the level
  nlohmann::json toJson() const;
  static CorrelationAdjustment fromJson(const nlohmann::json& j);
};

/// κ from the Jacobian J (n × d) of the weighted residuals, the residuals r (n) at the optimum,
/// the blocks (timeBlocks; each ≥ 0) and s² = SSE*/(n − d). A parameter H does not determine
/// (a zero column) keeps κ = 1.
CorrelationAdjustment blockAdjustment(const Eigen::MatrixXd& J, const Eigen::VectorXd& r,
                                      const std::vector<int>& block, double s2, double level);

}  // namespace dtwin::calib
