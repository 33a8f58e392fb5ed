#pragma once
// Latin hypercube designs (McKay, Beckman & Conover 1979), portable and seeded.
//
// \par Theory
// For n points in the box [l, u] ⊂ R^d, each dimension j is cut into n equal strata
//     S_jm = [l_j + m h_j, l_j + (m+1) h_j),   h_j = (u_j − l_j)/n,   m = 0 .. n−1,
// and a uniformly random permutation π_j of {0..n−1} assigns stratum π_j(i) to point i:
//     x_ij = l_j + (π_j(i) + U_ij) h_j,   U_ij ~ U[0, 1)  ("jitter" inside the cell).
// Every stratum of every dimension then holds exactly one point; the permutations of different
// dimensions are independent.
//
// \par Reproducibility
// Dimension j draws from its own RandomStream(seed, kStreamLhs, j): first the Fisher–Yates
// permutation, then the n jitters. Column j therefore depends only on (seed, n, j, l_j, u_j) —
// not on d, the thread count, or the standard library (no std::shuffle or std::*_distribution,
// whose output is implementation-defined).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "common/statistics.hpp"  // normalQuantile

#include "subsystems/random.hpp"

namespace dtwin::calib {

/// Uniform integer in [0, m) from rng.bits() by rejection (unbiased, portable). m >= 1.
std::uint64_t uniformIndex(RandomStream& rng, std::uint64_t m);

/// A uniformly random permutation of {0, .., n−1} by Fisher–Yates (Durstenfeld) with
/// uniformIndex: for i = n−1 down to 1, swap p[i] with p[uniformIndex(i+1)].
std::vector<int> randomPermutation(RandomStream& rng, int n);

/// n x d Latin hypercube in [lower, upper] (d = lower.size()); row i is point i.
/// lower[j] == upper[j] is allowed (that column is constant). n >= 1.
/// Throws InputError for n < 1 or invalid bounds.
Eigen::MatrixXd latinHypercube(int n, const std::vector<double>& lower,
                               const std::vector<double>& upper, std::uint64_t seed);

}  // namespace dtwin::calib
