// The proposal's pieces (diagnosis/proposal.hpp): the exhaustive best subset by BIC against a
// sparse truth in noise and against its closed-form BIC, the library's knees placed on the states
// reached, a library term as an effect (a * TERM), and the ready-to-paste table read back as a
// user-defined effect.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "common/errors.hpp"
#include "diagnosis/proposal.hpp"
#include "io/study.hpp"
#include "subsystems/effect.hpp"
#include "subsystems/user_effect.hpp"
#include "test_util.hpp"

using namespace dtwin;
using namespace dtwin::diag;

TEST(Proposal, BestSubsetFindsTheSparseTruthAndItsBic) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> z;
  const long n = 2000, m = 12;
  Eigen::MatrixXd G(n, m);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < m; ++j)
      G(i, j) = z(rng) + (j > 0 ? 0.3 * G(i, j - 1) : 0.0);  // correlated columns
  Eigen::VectorXd r(n);
  for (long i = 0; i < n; ++i) r[i] = 0.4 * G(i, 3) - 0.25 * G(i, 8) + z(rng);
  const auto fit = bestSubsetByBic(G, r, 3);
  ASSERT_EQ(fit.chosen, (std::vector<std::size_t>{3, 8}));
  EXPECT_NEAR(fit.coef[0], 0.4, 0.05);
  EXPECT_NEAR(fit.coef[1], -0.25, 0.05);
  // Closed form: the SSE of the least-squares fit on the chosen columns, BIC = SSE + k ln n.
  Eigen::MatrixXd Gs(n, 2);
  Gs << G.col(3), G.col(8);
  const Eigen::VectorXd c = Gs.colPivHouseholderQr().solve(r);
  const double sse = (r - Gs * c).squaredNorm();
  EXPECT_NEAR(fit.sse, sse, 1e-8 * sse);
  EXPECT_NEAR(fit.bic, sse + 2 * std::log(static_cast<double>(n)), 1e-8 * sse);
  EXPECT_NEAR(fit.bic_empty, r.squaredNorm(), 1e-9);
  ASSERT_EQ(fit.drop_sse.size(), 2u);
  for (double d : fit.drop_sse) EXPECT_GT(d, fit.sse);
  // Pure noise: nothing beats the empty model by much (BIC's penalty, ln n = 7.6 a term).
  for (long i = 0; i < n; ++i) r[i] = z(rng);
  const auto none = bestSubsetByBic(G, r, 3);
  EXPECT_LT(none.bic_empty - none.bic, 10.0);
}

TEST(Proposal, LibraryKneesSitOnTheStatesReached) {
  const auto lib = termLibrary(0.03, 0.05);
  int knees = 0;
  for (const auto& t : lib)
    if (t.expr.rfind("max(", 0) == 0) {
      ++knees;
      EXPECT_EQ(t.f({-1.0, 0.0, 0.0, 0.0}) == 0.0, t.expr.rfind("max(q", 0) == 0)
          << t.expr;  // a compression knee is 0 in rebound
      EXPECT_GT(t.gap, 0.0) << t.expr;
    }
  EXPECT_EQ(knees, 16);
  bool has = false;
  for (const auto& t : lib)
    has = has || t.expr == "max(-q - 0.03, 0)^2";  // 60 % of the 5 cm rebound
  EXPECT_TRUE(has);
  EXPECT_EQ(termLibrary(0.0, 0.0).size(), lib.size() - 16);  // no travel: no knees
}

TEST(Proposal, ALibraryTermIsAnEffectAndTheTableReadsBack) {
  const auto e = makeEffect(std::string(kTermPrefix) + "max(-q - 0.03, 0)^2", "test");
  ASSERT_EQ(e->parameters().size(), 1u);
  EXPECT_EQ(e->parameters()[0].name, "a");
  const auto names = effectNames();
  EXPECT_EQ(std::find(names.begin(), names.end(), std::string(kTermPrefix) + "max(-q - 0.03, 0)^2"),
            names.end());
  ProposedTerm t;
  t.name = "proposed_test_1";
  t.force = "a * (max(-q - g, 0)^2)";
  t.unit = "N/m^2";
  t.gap = 0.03;
  t.coefficient = -9.7e5;
  const auto dir = dtwin_test::freshDir("proposal_toml");
  dtwin_test::writeText(dir / "p.toml", t.toml());
  const auto specs = loadUserEffects((dir / "p.toml").string());
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_EQ(specs[0].force, t.force);
  EXPECT_DOUBLE_EQ(specs[0].parameters[0].lower, -4.85e6);
  EXPECT_DOUBLE_EQ(specs[0].parameters[0].upper, 0.0);
  // The knee's gap is a shape parameter in metres (the units check needs it: a bare number is
  // dimensionless), at the value the term was simulated with.
  ASSERT_EQ(specs[0].parameters.size(), 2u);
  EXPECT_EQ(specs[0].parameters[1].name, "g");
  EXPECT_EQ(specs[0].parameters[1].unit, "m");
  EXPECT_DOUBLE_EQ(specs[0].parameters[1].value, 0.03);
  EXPECT_TRUE(specs[0].parameters[1].shape);
  // Every library term's pasted form passes the units check.
  for (const auto& term : termLibrary(0.05, 0.04)) {
    ProposedTerm p;
    p.force = "a * (" + (term.gap > 0 ? term.g_expr : term.expr) + ")";
    p.unit = term.unit;
    p.gap = term.gap;
    p.coefficient = 1.0;
    UserEffectSpec u;
    u.name = "lib";
    u.element = "strut";
    u.force = p.force;
    u.parameters = {{"a", p.unit, 0.0, 0.0, 5.0}};
    if (p.gap > 0) u.parameters.push_back({"g", "m", p.gap, 0.5 * p.gap, 2 * p.gap, true});
    u.where = "lib";
    EXPECT_NO_THROW(makeUserEffect(u)) << p.force;
  }
  dtwin_test::writeText(dir / "q.toml", t.toml() + "\n[effects.bump_stop]\n");
  EXPECT_THROW(loadUserEffects((dir / "q.toml").string()), InputError);
}
