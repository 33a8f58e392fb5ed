#pragma once
// Shared vocabulary of the calibration layer (dtwin::calib).
//
// The calibration layer is pure mathematics: it never sees a vehicle, only a callback that maps a
// parameter vector θ (physical units, length d) to the sum of squared errors
//     SSE(θ) = Σ_i (y_i − η_i(θ))²                                   [output unit²]
// between the measurements y and the model output η. A simulation that fails (diverges, throws
// inside the model, ...) is reported by the callback as +inf, never as an exception: in the hot
// loops of the calibration a failed evaluation is a value (docs/architecture.md, "Errors").
//
// Parallelism is injected, not owned: every component that runs independent tasks (optimiser
// starts, feasible-box sweeps) accepts a ParallelFor hook. The hook must call task(i) exactly once
// for every i in [0, count), in any order and on any threads, and return when all are done.
// Each task writes only its own result slot, so results never depend on the execution order
// or the number of threads. When the hook runs tasks concurrently, the SseFunction must be
// thread-safe.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/format.hpp"
#include "io/study_sizes.hpp"

namespace dtwin::calib {

/// θ (physical units, length d) -> SSE(θ) >= 0, or +inf for a failed simulation.
using SseFunction = std::function<double(const std::vector<double>& theta)>;

/// Runs task(i) for i = 0 .. count-1 (any order, any threads), returns when all have finished.
using ParallelFor = std::function<void(int count, const std::function<void(int)>& task)>;

using ::dtwin::formatNumber;  // common/format.hpp

/// The default hook: a plain loop on the calling thread.
void sequentialFor(int count, const std::function<void(int)>& task);

/// Checks that lower/upper describe a box: same size d >= 1, all finite, and lower[j] < upper[j]
/// (or <= when `allow_degenerate`). Throws InputError naming `where`, the index and the values.
void checkBounds(const std::vector<double>& lower, const std::vector<double>& upper,
                 const std::string& where, bool allow_degenerate = false);

/// The default sizes of a calibration (docs/method.md §4: the paper's), read from the one set
/// of study-size defaults (io/study_sizes.hpp StudySizes). GibbsOptions, CalibrationOptions and
/// AdaptiveDesignOptions take their defaults from them.
inline constexpr int kDefaultOptimizerStarts =
    static_cast<int>(StudySizes{}.optimizer_starts);  ///< multi-start optimiser starts
inline constexpr int kDefaultLhsPoints =
    static_cast<int>(StudySizes{}.lhs_points);  ///< design points of the first Latin hypercube
inline constexpr int kDefaultGibbsIterations =
    static_cast<int>(StudySizes{}.gibbs_iterations);  ///< Gibbs iterations S, burn-in included
inline constexpr int kDefaultGibbsBurnIn =
    static_cast<int>(StudySizes{}.gibbs_burn_in);  ///< Gibbs iterations discarded from the start
inline constexpr double kDefaultTauPrior = 1e-3;   ///< shape a and rate b of the Gamma prior of τ

/// Stream identifiers for RandomStream(seed, stream, index): one purpose, one stream, so that two
/// components given the same user seed still draw independent numbers.
inline constexpr std::uint64_t kStreamLhs = 0x4c48'5300'0000'0001ULL;              // "LHS"
inline constexpr std::uint64_t kStreamOptimizerStarts = 0x4f50'5400'0000'0002ULL;  // "OPT"
inline constexpr std::uint64_t kStreamGibbs = 0x4742'4200'0000'0003ULL;            // "GBB"

}  // namespace dtwin::calib
