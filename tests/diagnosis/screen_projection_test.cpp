// The screening's score (diagnosis/diagnose_screen.cpp, setProjection and Linearisation::score):
// what re-calibrating the base values could absorb is projected out of a candidate's
// contribution, except that a value the data push beyond the bound it sits on may only move back
// inside. Checked on hand-made sensitivities, where the bounded least-squares answer is known in
// closed form.
#include <gtest/gtest.h>

#include <vector>

#include <Eigen/Dense>

#include "diagnosis/diagnose_internal.hpp"

using namespace dtwin::diag;

namespace {

/// The score a probe column G gets, as the screening computes it.
double score(const Linearisation& lin, const Eigen::MatrixXd& G) {
  Eigen::VectorXd coef;
  long rank = 0;
  return lin.score(lin.project(G), -1, coef, rank);
}

/// Three records, two base values: e1 and e2 their sensitivities; the residual r = −2 e2 + 3 e3
/// (the base optimum has absorbed nothing along e1; along e2 the data want the value 2 lower).
Linearisation threeRecords() {
  Linearisation lin;
  lin.J = Eigen::MatrixXd::Zero(3, 2);
  lin.J(0, 0) = 1.0;
  lin.J(1, 1) = 1.0;
  lin.r = Eigen::Vector3d(0.0, -2.0, 3.0);
  return lin;
}

}  // namespace

TEST(ScreenProjection, AFreeValueAbsorbsWhatItCan) {
  auto lin = threeRecords();
  setProjection(lin, {false, false}, {false, false});
  EXPECT_EQ(lin.held[0], 0);
  EXPECT_EQ(lin.held[1], 0);
  // A candidate along e2 + e3: the base absorbs its e2 part, the rest explains 3 of r's e3.
  Eigen::MatrixXd G(3, 1);
  G << 0.0, 1.0, 1.0;
  EXPECT_NEAR(score(lin, G), 9.0, 1e-12);
}

TEST(ScreenProjection, AValueTheDataPushBeyondItsBoundAbsorbsNothing) {
  auto lin = threeRecords();
  // The second value on its lower bound, the data wanting it lower (Jᵀr < 0 along it): held.
  setProjection(lin, {false, true}, {false, false});
  EXPECT_EQ(lin.held[0], 0);
  EXPECT_EQ(lin.held[1], 1);  // it may only rise
  // The candidate along e2 + e3 now explains r's projection on it: (rᵀg)² / gᵀg = (1)² / 2.
  Eigen::MatrixXd G(3, 1);
  G << 0.0, 1.0, 1.0;
  EXPECT_NEAR(score(lin, G), 0.5, 1e-12);
  // A candidate along e2 alone takes the whole push the bound stopped: 4.
  G << 0.0, 1.0, 0.0;
  EXPECT_NEAR(score(lin, G), 4.0, 1e-12);
  // The value's own column beyond its bound (projectWithout, a range candidate's probe) keeps all
  // of itself: nothing else can absorb it.
  const Eigen::MatrixXd Gk = lin.projectWithout(1, G);
  EXPECT_NEAR((Gk - G).norm(), 0.0, 1e-12);
}

TEST(ScreenProjection, AValueOnItsBoundThatTheDataPullInsideStaysFree) {
  auto lin = threeRecords();
  // On its upper bound, the data wanting it lower: inside the range, so it absorbs as usual.
  setProjection(lin, {false, false}, {false, true});
  EXPECT_EQ(lin.held[1], 0);
  Eigen::MatrixXd G(3, 1);
  G << 0.0, 1.0, 0.0;
  EXPECT_NEAR(score(lin, G), 0.0, 1e-12);
  // On its upper bound with the data wanting it higher: held, it may only fall.
  lin.r = Eigen::Vector3d(0.0, 2.0, 3.0);
  setProjection(lin, {false, false}, {false, true});
  EXPECT_EQ(lin.held[1], -1);
  EXPECT_NEAR(score(lin, G), 4.0, 1e-12);
}

TEST(ScreenProjection, ACandidateThatPullsAHeldValueBackInsideGetsTheWholeFit) {
  auto lin = threeRecords();
  setProjection(lin, {false, true}, {false, false});
  // g = −e2 + e3: at c = 3 it leaves r − 3 g = +e2, which the held value takes by rising 1 (inside
  // its range): the residual falls to zero, S = ‖r‖² = 13. Held fixed, g alone gives (rᵀg)²/gᵀg
  // = 12.5; free both ways, 9.
  Eigen::MatrixXd G(3, 1);
  G << 0.0, -1.0, 1.0;
  EXPECT_NEAR(score(lin, G), 13.0, 1e-12);
  Eigen::VectorXd coef;
  long rank = 0;
  lin.score(lin.project(G), -1, coef, rank);
  EXPECT_EQ(rank, 1);
  EXPECT_NEAR(coef[0], 3.0, 1e-12);
}
