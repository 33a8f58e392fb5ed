#pragma once
// Cost-aware choice of an assembly (docs/method.md §5): recommend the cheapest assembly whose
// evidence is not decisively worse than the best one.
//
// \par Rule
// Given per model m its log evidence ℓ_m (e.g. Σ_r ℓ_{r,m} from classify.hpp, or a log marginal
// likelihood) and its cost c_m (median wall seconds per simulated second), and a threshold t on
// the Kass–Raftery scale (default 10, "very strong"):
//     best         = argmax_m ℓ_m                         (ties: the lower index)
//     2 ln B_m     = 2 (ℓ_best − ℓ_m) >= 0                (evidence of best against m)
//     candidates   = { m : 2 ln B_m < t }                 (best is always one)
//     recommended  = the cheapest candidate               (ties: higher ℓ, then lower index)
// So a model is "decisively worse" when 2 ln B_m >= t. ℓ_m = −∞ (zero likelihood) is allowed and
// never a candidate unless it is the best, which is an error.
//
// \par Explanation (one sentence), e.g.
//   "M3 is recommended: it is 8.1x cheaper than M1 (the best by evidence) and its evidence is not
//    decisively worse (2 ln B = 4.2 < 10)."
//   "M1 is recommended: it has the strongest evidence and every cheaper assembly is decisively
//    worse (2 ln B ≥ 10)."
//   "M1 is recommended: it has the strongest evidence and no other assembly is cheaper."
// Numbers are printed with one decimal, or more where one decimal would break the stated
// inequality (a ratio of 1.03 prints "1.03x", a 2 ln B of 9.996 prints "9.996").
#include <string>
#include <vector>

namespace dtwin::classify {

struct ModelCost {
  std::string id;             ///< e.g. "M3"; non-empty, unique
  double log_evidence = 0.0;  ///< ℓ_m; finite or −∞
  double cost = 0.0;          ///< wall seconds per simulated second, finite and > 0
};

struct RecommendOptions {
  double threshold = 10.0;  ///< t on 2 ln B, finite and > 0
  void validate() const;  ///< InputError whose where() is "recommend.<field>" (common/validate.hpp)
};

struct Recommendation {
  int recommended_index = -1;
  int best_index = -1;
  std::string recommended;              ///< id of the recommended model
  std::string best;                     ///< id of the model with the highest evidence
  std::vector<int> candidate_indices;   ///< in input order
  std::vector<std::string> candidates;  ///< ids, in input order
  std::vector<double> two_ln_b;  ///< per model, 2 (ℓ_best − ℓ_m) (+∞ for ℓ_m = −∞)
  double cost_ratio = 1.0;       ///< c_best / c_recommended (>= 1)
  std::string explanation;       ///< one plain-English sentence
};

/// Applies the rule above. InputError on an empty list, a duplicate or empty id, a NaN or +∞
/// evidence, a best evidence of −∞, a cost that is not finite and > 0, or invalid options.
Recommendation recommendAssembly(const std::vector<ModelCost>& models,
                                 const RecommendOptions& options = {});

}  // namespace dtwin::classify
