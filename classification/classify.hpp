#pragma once
// Bayesian classification of field records among candidate assemblies (docs/method.md §5).
//
// \par Theory
// For record r and model m with log-likelihood ℓ_{r,m} = ln p(y_r | M_m) and prior π_m:
//     log posterior (unnormalised)   λ_{r,m} = ℓ_{r,m} + ln π_m
//     log marginal                   ln p(y_r) = LSE_m(λ_{r,m})
//     posterior probability          P(M_m | y_r) = exp(λ_{r,m} − LSE_m(λ_{r,m}))
// with the stable log-sum-exp LSE(λ) = λ_max + ln Σ_m exp(λ_m − λ_max): the largest term is
// exp(0) = 1, so nothing overflows and the sum never underflows to 0 (no NaN even when every ℓ is
// −1e6). The differences λ_m − λ_max are formed as (ℓ_m − ℓ_max) + (ln π_m − ln π_max), so the
// probabilities keep full relative accuracy even where λ itself is rounded (ulp 1e-10 at 1e6).
// Over all records, assumed independent given the model:
//     joint log likelihood          L_m = Σ_r ℓ_{r,m}
//     log Bayes factor of a vs b    ln B_ab = Σ_r (ℓ_{r,a} − ℓ_{r,b}) = L_a − L_b  (priors cancel)
//     joint posterior               P(M_m | y_1..y_R) = softmax_m(L_m + ln π_m)
// 2 ln B_ab is reported on the Kass & Raftery (1995, JASA 90, 773–795) scale, by |2 ln B|:
//     [0, 2) "not worth more than a bare mention", [2, 6) "positive", [6, 10) "strong",
//     >= 10 "very strong" (so the boundary 10 itself counts as decisive, as in recommend.hpp).
//
// \par Winner and ties
// The winner of a record is the model with the largest λ. Two values count as tied when
//     λ_max − λ_m <= tie_tolerance · max(1, |λ_max|, |λ_m|)      (default tie_tolerance 1e-12),
// i.e. relative, with an absolute floor near zero. The winner is the LOWEST index among the
// models tied with the maximum, and the record's `tie` flag is set when there are two or more.
//
// \par Boxplot of the paper
// For each model, the distribution over records of P(M_m | y_r): min, quartiles, median, max
// (quantiles of type 7, Hyndman & Fan 1996, as R and NumPy) and mean.
//
// \par Invalid input (InputError)
// ℓ must be R×M with R, M >= 1; an entry may be −∞ (the model gives the record zero density) but
// not NaN or +∞, and at least one model per record must be finite. Priors: one per model, each
// finite and > 0, summing to 1 within 1e-9. A pair of models that both give −∞ to some record
// has an undefined Bayes factor: it is reported as NaN with the category "undefined".
#include <Eigen/Core>
#include <string>
#include <vector>

namespace dtwin::classify {

struct ClassifyOptions {
  /// π_m, one per model; empty means uniform 1/M.
  std::vector<double> prior;
  /// Names used in the reports, one per model; empty means "M1", "M2", ... (index + 1).
  std::vector<std::string> model_ids;
  /// Relative tolerance for ties between log posteriors, finite and >= 0.
  double tie_tolerance = 1e-12;
  /// InputError whose where() is "classify.<field>" (common/validate.hpp): tie_tolerance, each
  /// prior finite and > 0, the priors summing to 1 within 1e-9.
  void validate() const;
  /// validate(), and `prior` and `model_ids` each empty or with one entry per model.
  void validate(int models) const;
};

struct ProbabilitySpread {
  double min = 0.0, q1 = 0.0, median = 0.0, q3 = 0.0, max = 0.0, mean = 0.0;
};

struct PairwiseEvidence {
  int a = 0, b = 0;               ///< model indices, a < b
  double log_bayes_factor = 0.0;  ///< ln B_ab = Σ_r (ℓ_{r,a} − ℓ_{r,b})
  double two_ln_b = 0.0;          ///< 2 ln B_ab
  int favoured = -1;              ///< a if ln B_ab > 0, b if < 0, −1 if 0 or NaN
  std::string category;           ///< Kass–Raftery category of |2 ln B_ab|
};

struct ClassificationResult {
  int records = 0;  ///< R
  int models = 0;   ///< M
  std::vector<std::string> model_ids;
  Eigen::VectorXd log_prior;              ///< M: ln π_m
  Eigen::MatrixXd log_posterior;          ///< R×M: λ_{r,m} = ℓ_{r,m} + ln π_m (unnormalised)
  Eigen::VectorXd log_marginal;           ///< R: LSE_m λ_{r,m}
  Eigen::MatrixXd probability;            ///< R×M: P(M_m | y_r), rows sum to 1
  std::vector<int> winner;                ///< R: winning model index
  std::vector<bool> tie;                  ///< R: the winner was tied (see header)
  int tied_records = 0;                   ///< number of records with tie set
  std::vector<int> wins;                  ///< M: records won by each model (Σ = R)
  std::vector<ProbabilitySpread> spread;  ///< M: distribution of P(M_m | y_r) over records
  Eigen::VectorXd total_log_likelihood;   ///< M: L_m = Σ_r ℓ_{r,m}
  Eigen::VectorXd joint_probability;      ///< M: softmax(L_m + ln π_m); NaN if every L_m = −∞
  Eigen::MatrixXd log_bayes_factor;       ///< M×M: (a, b) = ln B_ab (antisymmetric)
  std::vector<PairwiseEvidence> pairs;    ///< every pair a < b, in order (0,1), (0,2), ..
  std::string briefReport() const;        ///< a few lines: wins and the joint evidence
  std::string fullReport() const;         ///< + the probability spread and every Bayes factor
};

/// Classifies the R records of `log_likelihood` (R×M, ℓ_{r,m} in row r, column m).
ClassificationResult classifyRecords(const Eigen::MatrixXd& log_likelihood,
                                     const ClassifyOptions& options = {});

/// Stable ln Σ exp(v_i); −∞ if every v_i is −∞ (or v is empty).
double logSumExp(const Eigen::Ref<const Eigen::VectorXd>& v);

/// Kass–Raftery category of |two_ln_b| (see header); "undefined" for NaN.
std::string kassRafteryCategory(double two_ln_b);

}  // namespace dtwin::classify
