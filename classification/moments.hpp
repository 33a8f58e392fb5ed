#pragma once
// Streaming mean and covariance of p-dimensional vectors (docs/method.md §5: "fit a multivariate
// normal per assembly ... no need to hold all outputs").
//
// \par State of an accumulator over a set A of n vectors x_1..x_n (each of length p)
//  * n                                   count
//  * μ  = (1/n) Σ x_k                    mean, p-vector
//  * M2 = Σ (x_k − μ)(x_k − μ)ᵀ          scatter matrix, p×p symmetric
//  * (optional, MomentOptions::track_fourth_moment, needed by Ledoit–Wolf, see shrinkage.hpp)
//    T  = Σ ‖x_k − μ‖² (x_k − μ)         p-vector (a third moment)
//    Q  = Σ ‖x_k − μ‖⁴                   scalar (a fourth moment)
// The unbiased covariance is S = M2 / (n − 1).
//
// \par Storage
// M2 is held in a dense p×p column-major matrix of which ONLY THE UPPER TRIANGLE (i <= j) is
// kept up to date (the strictly lower part is never read or written). Dense storage lets Eigen's
// selfadjointView<Upper>().rankUpdate run its blocked SYR/SYRK kernels; a packed triangle would
// halve the memory but has no fast kernels in Eigen. Memory: 8 p² bytes (p = 5001: 200 MB), plus
// 8 p² for each full covariance() returned. Serialisation (toVector, toBytes, save) writes only
// the packed upper triangle, p(p+1)/2 values (p = 5001: 100 MB).
//
// \par Updates (all are instances of one merge of two sets A and B into C = A ∪ B)
// With n = n_A + n_B, δ = μ_B − μ_A (Chan, Golub & LeVeque 1979; Welford 1962 for n_B = 1):
//     μ_C  = (n_A μ_A + n_B μ_B) / n            (merge; add() uses μ_A + δ / n)
//     M2_C = M2_A + M2_B + (n_A n_B / n) δ δᵀ
// For the optional moments, each side is first moved to the new centre. With d = μ_C − μ_A,
// z_k = x_k − μ_A (so Σ z_k = 0) and x_k − μ_C = z_k − d:
//     Q_A→C = Q_A + 4 dᵀ M2_A d + n_A ‖d‖⁴ − 4 T_Aᵀ d + 2 ‖d‖² tr(M2_A)
//     T_A→C = T_A − 2 M2_A d − tr(M2_A) d − n_A ‖d‖² d
// (expand ‖z − d‖² = ‖z‖² − 2 zᵀd + ‖d‖², use Σ z = 0, Σ (zᵀd)² = dᵀ M2_A d, Σ ‖z‖² z = T_A);
// likewise for B with d = μ_C − μ_B; then Q_C = Q_A→C + Q_B→C and T_C = T_A→C + T_B→C.
//  * add(x)      : B = {x} (n_B = 1, M2_B = 0, T_B = 0, Q_B = 0). Rank-1 update, O(p²).
//  * addBlock(X) : B = the k columns of X. μ_B = X 1 / k, C = X − μ_B 1ᵀ, M2_B = C Cᵀ (one SYRK,
//                  O(p² k) but at matrix-matrix speed), q_j = ‖c_j‖², T_B = C q, Q_B = Σ q_j².
//  * merge(other): the general case.
// Cost of the optional moments: one symmetric matrix-vector product M2_A d (O(p²)) per add,
// addBlock or merge; for add() this roughly doubles the cost of the rank-1 update, for addBlock
// it is negligible next to the SYRK. Without tracking, T and Q are neither stored nor updated.
// Measured for p = 5001 (one core, -O2, no -march): add 10 ms (21 ms tracked); addBlock of 64
// vectors 100 ms (1.6 ms per vector; 110 ms tracked); merge 23 ms (47 ms tracked); covariance()
// 160 ms; toVector/fromVector 60/70 ms; save/load 0.15–0.4 s / 0.23 s (100 MB file).
// Prefer addBlock: 50 000 vectors cost ~80 s that way against ~500 s by single adds.
//
// \par Determinism
// Floating-point addition is not associative, so the result depends (at the level of rounding,
// ~1e-16 relative) on how the vectors are grouped. merge() is commutative bit for bit
// (merge(a, b) == merge(b, a)), but not associative. addBlock(X) equals k calls of add() only
// within rounding. Bitwise reproducibility therefore needs a FIXED blocking and a FIXED merge
// order (e.g. by task block index), which the caller guarantees; given those, the result does not
// depend on the number of threads or ranks. No operation here uses threads or randomness.
//
// \par Invalid input
// A vector with a non-finite entry, or of the wrong length, is rejected with an InputError before
// anything is changed (a diverged simulation must be filtered out by the caller, not averaged in).
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace dtwin::classify {

struct MomentOptions {
  /// Also accumulate T and Q (needed by calcLedoitWolf). Costs one extra O(p²) symmetric
  /// matrix-vector product per add/addBlock/merge and 8 (p + 1) bytes.
  bool track_fourth_moment = false;
  /// The one convention (common/validate.hpp); a flag has no range, so nothing can be wrong.
  void validate() const {}
};

class MomentAccumulator {
 public:
  /// An empty accumulator for vectors of length `dimension` (>= 1, else InputError).
  explicit MomentAccumulator(int dimension, const MomentOptions& options = {});

  /// Adds one vector x (length p, all finite): Welford rank-1 update.
  void add(const Eigen::VectorXd& x);
  /// Adds the k columns of X (p×k, k >= 1, all finite) at once: one SYRK and one rank-1 update.
  /// Equal to k calls of add() within rounding (see "Determinism").
  void addBlock(const Eigen::MatrixXd& X);
  /// Adds the vectors accumulated in `other` (same dimension and options, else InputError).
  void merge(const MomentAccumulator& other);

  int dimension() const { return p_; }
  std::int64_t count() const { return n_; }
  bool tracksFourthMoment() const { return track_; }
  /// μ (length p; zeros while count() == 0).
  const Eigen::VectorXd& mean() const { return mean_; }
  /// M2 = Σ (x − μ)(x − μ)ᵀ; ONLY the upper triangle (i <= j) is meaningful.
  const Eigen::MatrixXd& getScatterUpper() const { return m2_; }
  /// Unbiased covariance M2 / (n − 1) as a full symmetric p×p matrix (a new 8 p² byte matrix).
  /// Throws InputError when count() < 2.
  Eigen::MatrixXd covariance() const;
  /// T = Σ ‖x − μ‖² (x − μ); InputError unless tracksFourthMoment().
  const Eigen::VectorXd& getThirdMoment() const;
  /// Q = Σ ‖x − μ‖⁴; InputError unless tracksFourthMoment().
  double getFourthMoment() const;

  /// Flat serialisation (exact round trip; for MPI transfer). Layout, all doubles:
  ///   [0] kFlatMagic  [1] format version (1)  [2] p  [3] n  [4] track flag (0 or 1)
  ///   [5, 5+p)                 μ
  ///   next p(p+1)/2            upper triangle of M2, column by column (j = 0..p−1, i = 0..j)
  ///   if tracked: next p       T, then 1 value Q
  std::vector<double> toVector() const;
  /// Inverse of toVector(); InputError (naming the field) on a malformed vector.
  static MomentAccumulator fromVector(const std::vector<double>& v);
  /// The bytes of toVector() in host byte order (IEEE 754 binary64, little-endian on every
  /// supported platform); fromBytes() rejects a blob whose length or header does not match.
  std::vector<std::uint8_t> toBytes() const;
  static MomentAccumulator fromBytes(const std::vector<std::uint8_t>& bytes);
  /// Persists the accumulator for resuming: the 8-byte tag "DTWMOM01" followed by toBytes(),
  /// written to `path + ".tmp"`, flushed, then renamed over `path` (readers never see a partial
  /// file). InputError if the file cannot be written.
  void save(const std::string& path) const;
  /// Reads a file written by save(); InputError naming the file if it is missing or malformed.
  static MomentAccumulator load(const std::string& path);

  static constexpr double kFlatMagic = 1297043278.0;  ///< "MOMN" as a 32-bit integer

 private:
  // Merges a set B given by its count, mean, and (when tracking) M2_B d for any d, tr(M2_B),
  // T_B and Q_B; `addScatterB` adds M2_B to the upper triangle of m2_.
  template <class M2Times, class AddScatter>
  void mergeSet(std::int64_t nb, const Eigen::VectorXd& mean_b, M2Times m2b_times, double trace_m2b,
                const Eigen::VectorXd* t_b, double q_b, AddScatter add_scatter_b,
                bool welford_mean);
  void checkVector(const Eigen::Ref<const Eigen::VectorXd>& x, const char* what,
                   Eigen::Index column) const;

  int p_ = 0;
  bool track_ = false;
  std::int64_t n_ = 0;
  Eigen::VectorXd mean_;
  Eigen::MatrixXd m2_;  // upper triangle only
  Eigen::VectorXd t_;   // size p when tracking, else empty
  double q_ = 0.0;
};

}  // namespace dtwin::classify
