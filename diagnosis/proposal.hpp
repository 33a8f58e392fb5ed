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

/// The strut's state a term is sized on: its deflection and rate, and the differences from the
/// other strut on its axle (the user-effect variables q, v, dq, dv).
struct StrutSample {
  double q = 0, v = 0, dq = 0, dv = 0;
};

struct LibraryTerm {
  std::string expr;  ///< in the strut variables q, v, dq, dv (subsystems/user_effect.hpp), e.g.
                     ///< "max(q - 0.012, 0)^2"
  std::string unit;  ///< of its coefficient a (the force a·TERM is in N)
  std::function<double(const StrutSample&)> f;  ///< the same term, to size its probe
  /// Knees: the gap g [m] the expression writes as a number; the pasted table writes `g_expr`
  /// with g a shape parameter (so the units check: a bare number is dimensionless). 0: none.
  double gap = 0;
  std::string g_expr;
};

/// The library: odd and even polynomials in q and v (q|q|, q², q³, v|v|, v³, q v), friction-like
/// sign(v) and sign(v)√|v|, one-sided damping (rebound only), knees max(q − g, 0)^p
/// (compression) and max(−q − g, 0)^p (rebound) for p = 1, 2 at g = 20, 40, 60, 80 % of the
/// largest compression `q_comp` and rebound `q_reb` [m] the base model reaches, and terms across
/// an axle's corners: dq|dq|, dq³ (a progressive roll stiffness), dv (a roll damper) and q·dq.
std::vector<LibraryTerm> termLibrary(double q_comp, double q_reb);

/// The best subset S (|S| ≤ max_terms) of the columns of G for the residual r by BIC = ‖r − G_S c‖²
/// + |S| ln n (r in noise units, so the SSE is a χ²). Exhaustive over every subset.
struct SubsetFit {
  std::vector<std::size_t>
      chosen;                ///< column indices, ascending; empty: nothing beats the empty model
  std::vector<double> coef;  ///< least-squares coefficients of the chosen columns
  double sse_empty = 0, sse = 0;  ///< ‖r‖² and the chosen subset's SSE
  double bic_empty = 0, bic = 0;
  std::vector<double> drop_sse;  ///< per chosen column: the SSE of the subset without it
};
SubsetFit bestSubsetByBic(const Eigen::MatrixXd& G, const Eigen::VectorXd& r, int max_terms);

/// One proposed term, ready to paste.
struct ProposedTerm {
  std::string name;        ///< proposed_1, ...
  std::string force;       ///< "a * (TERM)", a knee's gap written g
  std::string unit;        ///< of a
  double gap = 0;          ///< a knee's g [m] (a shape parameter in the table); 0: none
  double coefficient = 0;  ///< the linearised estimate of a
  double delta_bic = 0;    ///< BIC without this term − BIC with it, negated: < 0 favours the term
  double explained =
      0;  ///< share of the residual's excess over the noise it removes (alone, given the others)
  /// The [user_effects.NAME] table: a = { value = 0, unit, prior [0, 5 â] (or [5 â, 0]) }, and a
  /// knee's g = { value = gap, unit = "m", range [gap / 2, 2 gap], shape = true }.
  std::string toml() const;
  nlohmann::json toJson() const;
};

}  // namespace dtwin::diag
