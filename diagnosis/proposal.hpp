#pragma once
// What `twin diagnose` proposes when no candidate explains the residual (docs/diagnosis.md,
// "A proposal for what stays unexplained"): a sparse regression of the base's standardised
// residual on a library of strut-force terms, each simulated as a small extra force a·TERM at
// every strut (subsystems/effect.hpp kTermPrefix) and projected off what re-calibrating θ could
// absorb. The best subset of at most three terms by BIC (exhaustive, not greedy) is printed as
// ready-to-paste [user_effects] tables.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

namespace dtwin::diag {

struct LibraryTerm {
  std::string expr;  ///< in the strut variables q (compression +, m) and v (m/s), e.g. "max(q - 0.012, 0)^2"
  std::string unit;  ///< of its coefficient a (the force a·TERM is in N)
  std::function<double(double q, double v)> f;  ///< the same term, to size its probe
};

/// The library: odd and even polynomials in q and v (q|q|, q², q³, v|v|, v³, q v), friction-like
/// sign(v) and sign(v)√|v|, one-sided damping (rebound only), and knees max(q − g, 0)^p
/// (compression) and max(−q − g, 0)^p (rebound) for p = 1, 2 at g = 20, 40, 60, 80 % of the
/// largest compression `q_comp` and rebound `q_reb` [m] the base model reaches.
std::vector<LibraryTerm> termLibrary(double q_comp, double q_reb);

/// The best subset S (|S| ≤ max_terms) of the columns of G for the residual r by BIC = ‖r − G_S c‖²
/// + |S| ln n (r in noise units, so the SSE is a χ²). Exhaustive over every subset.
struct SubsetFit {
  std::vector<std::size_t> chosen;   ///< column indices, ascending; empty: nothing beats the empty model
  std::vector<double> coef;          ///< least-squares coefficients of the chosen columns
  double sse_empty = 0, sse = 0;     ///< ‖r‖² and the chosen subset's SSE
  double bic_empty = 0, bic = 0;
  std::vector<double> drop_sse;      ///< per chosen column: the SSE of the subset without it
};
SubsetFit bestSubsetByBic(const Eigen::MatrixXd& G, const Eigen::VectorXd& r, int max_terms);

/// One proposed term, ready to paste.
struct ProposedTerm {
  std::string name;          ///< proposed_1, ...
  std::string force;         ///< "a * (TERM)"
  std::string unit;          ///< of a
  double coefficient = 0;    ///< the linearised estimate of a
  double delta_bic = 0;      ///< BIC without this term − BIC with it, negated: < 0 favours the term
  double explained = 0;      ///< share of the residual's excess over the noise it removes (alone, given the others)
  /// The [user_effects.NAME] table: a = { value = 0, unit, prior [0, 5 â] (or [5 â, 0]) }.
  std::string toml() const;
  nlohmann::json toJson() const;
};

}  // namespace dtwin::diag
