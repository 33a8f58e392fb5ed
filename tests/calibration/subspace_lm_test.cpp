// Levenberg–Marquardt on a box with a carried Jacobian (calibration/subspace_lm.hpp), the
// optimiser of every frozen-step calibration start (polishLeastSquares): checked against the
// closed-form minimum of a fit whose unconstrained optimum lies outside the box.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <vector>

#include "calibration/subspace_lm.hpp"

using namespace dtwin::calib;

namespace {

// r_i = y_i − a − b t_i − c t_i² with y from (a, b, c) = (0.2, 1.4, −0.3) plus a small wiggle:
// linear in z, so the box minimum is the bounded least-squares solution, known in closed form
// once the active set is known: b = 1 (its upper bound), a and c the least squares of y − t.
struct Quadratic {
  std::vector<double> t, y;
  std::atomic<int> runs{0};
  Quadratic() {
    for (int i = 0; i < 30; ++i) {
      t.push_back(i / 29.0);
      y.push_back(0.2 + 1.4 * t.back() - 0.3 * t.back() * t.back() + 0.01 * std::sin(7.0 * i));
    }
  }
  ScaledResiduals residuals() {
    return [this](const Eigen::VectorXd& z, Eigen::VectorXd& r) {
      ++runs;
      r.resize(static_cast<Eigen::Index>(t.size()));
      for (std::size_t i = 0; i < t.size(); ++i)
        r(static_cast<Eigen::Index>(i)) = y[i] - z(0) - z(1) * t[i] - z(2) * t[i] * t[i];
      return true;
    };
  }
  /// a and c with b held at `b`: the normal equations of the two free columns.
  Eigen::Vector3d boundedMinimum(double b) const {
    Eigen::MatrixXd A(static_cast<Eigen::Index>(t.size()), 2);
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(t.size()));
    for (std::size_t i = 0; i < t.size(); ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      A(k, 0) = 1.0;
      A(k, 1) = t[i] * t[i];
      rhs(k) = y[i] - b * t[i];
    }
    const Eigen::Vector2d x = A.colPivHouseholderQr().solve(rhs);
    return {x(0), b, x(1)};
  }
};

SubspaceLmSettings box(int threads) {
  SubspaceLmSettings s;
  s.tries = 8;
  s.min_rel_gain = 1e-12;
  s.converge_on_fresh = true;
  s.lower = Eigen::Vector3d(-1.0, -1.0, -1.0);
  s.upper = Eigen::Vector3d(1.0, 1.0, 1.0);
  s.threads = threads;
  return s;
}

// y = 2 exp(−0.7 t) + 0.3 sin(3 t) + a small wiggle, fitted as a exp(−b t) + c sin(3 t) with
// (a, b, c) = (z(ia), z(ib), z(ic)); `runs` counts the residual evaluations.
ScaledResiduals expSineFit(int ia, int ib, int ic, int& runs) {
  std::vector<double> t, y;
  for (int i = 0; i < 40; ++i) {
    t.push_back(0.1 * i);
    y.push_back(2.0 * std::exp(-0.7 * t.back()) + 0.3 * std::sin(3.0 * t.back()) +
                0.01 * std::cos(17.0 * i));
  }
  return [t, y, ia, ib, ic, &runs](const Eigen::VectorXd& z, Eigen::VectorXd& r) {
    ++runs;
    r.resize(static_cast<Eigen::Index>(t.size()));
    for (std::size_t i = 0; i < t.size(); ++i)
      r(static_cast<Eigen::Index>(i)) =
          y[i] - z(ia) * std::exp(-z(ib) * t[i]) - z(ic) * std::sin(3.0 * t[i]);
    return true;
  };
}

}  // namespace

TEST(SubspaceLm, BoxedFitReachesTheClosedFormBoundedMinimum) {
  Quadratic q;
  const Eigen::Vector3d expect = q.boundedMinimum(1.0);
  // The unconstrained optimum has b ≈ 1.4, outside the box, so b must end on its bound.
  ASSERT_GT(expect(0), -1.0);
  ASSERT_LT(expect(2), 1.0);
  Eigen::VectorXd u = Eigen::Vector3d(0.9, -0.5, 0.8), r;  // from far away, near a corner
  double f = 0.0;
  SubspaceJacobian jac;
  ASSERT_TRUE(
      minimiseOnSubspace(q.residuals(), Eigen::VectorXd::Zero(3), Eigen::MatrixXd::Identity(3, 3),
                         Eigen::VectorXd::Constant(3, 1e-3), 50, 0.0, u, r, f, &jac, box(1)));
  EXPECT_DOUBLE_EQ(u(1), 1.0) << "b must rest on its upper bound";
  EXPECT_NEAR(u(0), expect(0), 1e-6);
  EXPECT_NEAR(u(2), expect(2), 1e-6);
  // Stopped only after a step from a fresh Jacobian: at least the first and one more.
  EXPECT_GE(jac.computed, 1);
}

TEST(SubspaceLm, DifferencesAtABoundAreOneSidedAndExact) {
  // r_i = y_i − z0 − z1 t_i − z2 (t_i² − 1/3) on t ∈ [−1, 1] (nearly orthogonal columns, so a
  // lightly damped step is nearly the Gauss–Newton one), the model clamping z to [−2, 2] as the
  // calibration's objective clamps to its box. From z1 on its lower bound with the minimum inside,
  // a central stencil would see half of z1's slope; differences kept inside the bounds are exact
  // for a linear residual, and one step lands on the least-squares solution.
  std::vector<double> t, y;
  for (int i = 0; i < 41; ++i) {
    t.push_back(-1.0 + i / 20.0);
    y.push_back(0.2 + 1.4 * t.back() - 0.3 * (t.back() * t.back() - 1.0 / 3.0) +
                0.01 * std::sin(7.0 * i));
  }
  const ScaledResiduals res = [&](const Eigen::VectorXd& zz, Eigen::VectorXd& r) {
    const Eigen::VectorXd z = zz.cwiseMax(-2.0).cwiseMin(2.0);
    r.resize(static_cast<Eigen::Index>(t.size()));
    for (std::size_t i = 0; i < t.size(); ++i)
      r(static_cast<Eigen::Index>(i)) =
          y[i] - z(0) - z(1) * t[i] - z(2) * (t[i] * t[i] - 1.0 / 3.0);
    return true;
  };
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Eigen::Vector3d x(1.0, t[i], t[i] * t[i] - 1.0 / 3.0);
    A += x * x.transpose();
    rhs += x * y[i];
  }
  const Eigen::Vector3d expect = A.ldlt().solve(rhs);
  SubspaceLmSettings set = box(1);
  set.lower = Eigen::Vector3d::Constant(-2.0);
  set.upper = Eigen::Vector3d::Constant(2.0);
  Eigen::VectorXd u = Eigen::Vector3d(0.5, -2.0, 0.5), r;
  double f = 0.0;
  ASSERT_TRUE(minimiseOnSubspace(res, Eigen::VectorXd::Zero(3), Eigen::MatrixXd::Identity(3, 3),
                                 Eigen::VectorXd::Constant(3, 0.1), 1, 0.0, u, r, f, nullptr, set));
  EXPECT_NEAR(u(0), expect(0), 0.01);
  EXPECT_NEAR(u(1), expect(1), 0.01);
  EXPECT_NEAR(u(2), expect(2), 0.01);
}

TEST(SubspaceLm, ThreadCountDoesNotChangeTheResult) {
  Quadratic q1, q2;
  Eigen::VectorXd u1 = Eigen::Vector3d(0.9, -0.5, 0.8), u2 = u1, r1, r2;
  double f1 = 0.0, f2 = 0.0;
  const Eigen::MatrixXd B = Eigen::MatrixXd::Identity(3, 3);
  const Eigen::VectorXd h = Eigen::VectorXd::Constant(3, 1e-3);
  ASSERT_TRUE(minimiseOnSubspace(q1.residuals(), Eigen::VectorXd::Zero(3), B, h, 50, 0.0, u1, r1,
                                 f1, nullptr, box(1)));
  ASSERT_TRUE(minimiseOnSubspace(q2.residuals(), Eigen::VectorXd::Zero(3), B, h, 50, 0.0, u2, r2,
                                 f2, nullptr, box(2)));
  EXPECT_EQ(u1, u2);
  EXPECT_EQ(f1, f2);
  EXPECT_EQ(q1.runs.load(), q2.runs.load());
}

TEST(SubspaceLm, CarriedJacobianNeedsFewerRunsOnANonlinearFit) {
  // y = 2 exp(−0.7 t) + 0.3 sin(3 t): the same minimum whether the Jacobian is carried (Broyden)
  // or recomputed at every iteration, for fewer simulations.
  int runs = 0;
  const ScaledResiduals res = expSineFit(0, 1, 2, runs);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Identity(3, 3);
  const Eigen::VectorXd h = Eigen::VectorXd::Constant(3, 1e-4);
  SubspaceLmSettings set = box(1);
  set.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
  set.upper = Eigen::Vector3d(5.0, 5.0, 5.0);
  Eigen::VectorXd u_carry = Eigen::Vector3d(1.0, 1.5, 0.0), u_fresh = u_carry, r;
  double f_carry = 0.0, f_fresh = 0.0;
  SubspaceJacobian jac;
  ASSERT_TRUE(minimiseOnSubspace(res, Eigen::VectorXd::Zero(3), B, h, 50, 0.0, u_carry, r, f_carry,
                                 &jac, set));
  const int runs_carry = runs;
  // Fresh differences at every iteration: one iteration per call, the Jacobian never carried.
  runs = 0;
  for (int it = 0; it < 50; ++it) {
    const double before = f_fresh;
    ASSERT_TRUE(minimiseOnSubspace(res, Eigen::VectorXd::Zero(3), B, h, 1, 0.0, u_fresh, r, f_fresh,
                                   nullptr, set));
    if (it > 0 && before - f_fresh <= 1e-12 * before) break;
  }
  EXPECT_NEAR(f_carry, f_fresh, 1e-9 * f_fresh + 1e-12);
  EXPECT_NEAR(u_carry(0), u_fresh(0), 1e-5);
  EXPECT_NEAR(u_carry(1), u_fresh(1), 1e-5);
  EXPECT_NEAR(u_carry(2), u_fresh(2), 1e-5);
  EXPECT_LT(runs_carry, runs) << runs_carry << " runs carried, " << runs << " fresh";
  EXPECT_GT(jac.reused, 0);
}

// The Jacobian carried along a profile's points (subspace_lm.hpp): on a smooth nonlinear fit,
// each point of a sequence, with the profile's few iterations, ends as close to the true floor
// as with fresh differences at every iteration, for far fewer simulations.
TEST(Profile, CarriedJacobianReachesTheSameFloorForFewerRuns) {
  // r_i = y_i − u1 exp(−u2 t_i) − v sin(3 t_i), the profile parameter v in z(0), u = z(1), z(2).
  int runs = 0;
  const ScaledResiduals res = expSineFit(1, 2, 0, runs);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3, 2);
  B(1, 0) = B(2, 1) = 1.0;
  const Eigen::VectorXd h = Eigen::VectorXd::Constant(2, 1e-4);
  Eigen::VectorXd u_fresh(2), u_carry(2), u_true(2);
  u_fresh << 2.0, 0.7;
  u_carry = u_true = u_fresh;
  SubspaceJacobian jac;
  int runs_fresh = 0, runs_carry = 0;
  for (double v = 0.3; v <= 0.6001; v += 0.025) {
    Eigen::VectorXd z0 = Eigen::VectorXd::Zero(3), r;
    z0(0) = v;
    double f_fresh = 0.0, f_carry = 0.0, f_true = 0.0;
    ASSERT_TRUE(minimiseOnSubspace(res, z0, B, h, 50, 0.0, u_true, r, f_true));
    runs = 0;
    ASSERT_TRUE(minimiseOnSubspace(res, z0, B, h, 2, 1e-6, u_fresh, r, f_fresh));
    runs_fresh += runs;
    runs = 0;
    ASSERT_TRUE(minimiseOnSubspace(res, z0, B, h, 2, 1e-6, u_carry, r, f_carry, &jac));
    runs_carry += runs;
    const double tol = std::max(2.0 * (f_fresh - f_true), 1e-4 * f_true);
    EXPECT_LE(f_carry - f_true, tol)
        << "v = " << v << ": carried " << f_carry << ", fresh " << f_fresh << ", floor " << f_true;
  }
  std::printf("carried %d runs, fresh %d\n", runs_carry, runs_fresh);
  EXPECT_LT(runs_carry, runs_fresh / 2)
      << runs_carry << " runs carried, " << runs_fresh << " fresh";
  EXPECT_GE(jac.computed, 1);
  EXPECT_GT(jac.reused, jac.computed);
}
