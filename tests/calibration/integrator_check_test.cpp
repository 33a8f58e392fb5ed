// The integrator check of a calibration (calib::assessIntegrator): the jitter the integrator's
// error puts into the SSE, against the 95 % intervals' threshold, computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "calibration/calibrate.hpp"

using dtwin::calib::assessIntegrator;

TEST(IntegratorCheck, JitterIsTheLargerOfTheSseChangeAndTheCrossTerm) {
  // n = 4 residuals of ±1 (SSE 4), weights 1/σ² = 4; the finer run moves each prediction by
  // +0.05, so δ = 0.05·2 per record in weighted units, ‖δ‖ = √(4·4·0.0025) = 0.2.
  const std::vector<double> y = {0, 0, 0, 0}, w = {4, 4, 4, 4};
  const std::vector<double> eta = {0.5, -0.5, 0.5, -0.5}, fine = {0.55, -0.45, 0.55, -0.45};
  const auto c = assessIntegrator(eta, fine, y, w, 3e-4, 10.0);
  EXPECT_DOUBLE_EQ(c.sse, 4.0);
  EXPECT_NEAR(c.sse_check, 4.04, 1e-12);  // 2 · 4 · (0.55² + 0.45²)
  EXPECT_NEAR(c.prediction_change, 0.2, 1e-12);
  // |ΔSSE| = |4 − 4.04| = 0.04; the cross term 2 ‖e‖ ‖δ‖ / √n = 2·2·0.2/2 = 0.4.
  EXPECT_NEAR(c.jitter, 0.4, 1e-12);
  EXPECT_NEAR(c.accuracy_check, 3e-5, 1e-18);
  EXPECT_TRUE(c.ok);
  EXPECT_TRUE(c.message.empty());
}

TEST(IntegratorCheck, FailsWhenTheJitterReachesHalfTheThreshold) {
  const std::vector<double> y = {0, 0, 0, 0}, w = {4, 4, 4, 4};
  const std::vector<double> eta = {0.5, -0.5, 0.5, -0.5}, fine = {0.55, -0.45, 0.55, -0.45};
  EXPECT_TRUE(assessIntegrator(eta, fine, y, w, 3e-4, 0.81).ok);
  const auto c = assessIntegrator(eta, fine, y, w, 3e-4, 0.79);
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.message.find("moves the SSE by about 0.4"), std::string::npos) << c.message;
  EXPECT_NE(c.message.find("tighten [simulation] accuracy (to 3e-05 or less)"), std::string::npos)
      << c.message;
  // No interval threshold (no profile): nothing to compare with.
  EXPECT_TRUE(assessIntegrator(eta, fine, y, w, 3e-4, 0.0).ok);
}

// The frozen-steps figures. quadraticRoughness: 0 for points on a quadratic, and for a jump of
// size J at the middle of five points the least-squares quadratic leaves a residual of 18/35 J
// there (the hat matrix of the quadratic fit at x = 0 of -2..2 has diagonal 17/35).
TEST(IntegratorCheck, QuadraticRoughnessIsZeroOnAQuadraticAndSeesAJump) {
  const std::vector<double> x = {-2, -1, 0, 1, 2};
  std::vector<double> f;
  for (double v : x) f.push_back(3.0 - 0.5 * v + 2.0 * v * v);
  EXPECT_LT(dtwin::calib::quadraticRoughness(x, f), 1e-12);
  f[2] += 1.0;
  EXPECT_NEAR(dtwin::calib::quadraticRoughness(x, f), 18.0 / 35.0, 1e-12);
  EXPECT_THROW(dtwin::calib::quadraticRoughness({0, 1, 2}, {0, 1, 4}), std::exception);
}

// integratorOptimumShift against its closed form for a linear model: residuals r(z) = r0 + J z,
// the integrator's bias a fixed δ, so g = 2 Jᵀδ and the shift is ‖P δ‖², P = J (JᵀJ)⁻¹ Jᵀ; this is
// also how much the exact SSE at the biased optimum exceeds the exact minimum, computed directly.
TEST(IntegratorCheck, OptimumShiftIsTheProjectedBiasOfALinearModel) {
  Eigen::MatrixXd J(6, 2);
  J << 1, 0, 1, 1, 1, 2, 1, 3, 1, 4, 1, 5;
  Eigen::VectorXd r0(6), delta(6);
  r0 << 0.3, -0.2, 0.1, 0.4, -0.5, 0.2;
  delta << 0.05, -0.01, 0.02, 0.03, 0.0, -0.04;
  const Eigen::VectorXd g = 2.0 * J.transpose() * delta;
  const double shift = dtwin::calib::integratorOptimumShift(J, g);
  const Eigen::MatrixXd P = J * (J.transpose() * J).inverse() * J.transpose();
  EXPECT_NEAR(shift, (P * delta).squaredNorm(), 1e-14);
  const Eigen::VectorXd z_exact = -(J.transpose() * J).ldlt().solve(J.transpose() * r0);
  const Eigen::VectorXd z_biased = -(J.transpose() * J).ldlt().solve(J.transpose() * (r0 + delta));
  EXPECT_NEAR(shift, (r0 + J * z_biased).squaredNorm() - (r0 + J * z_exact).squaredNorm(), 1e-14);
  // A rank-deficient J (a parameter the data do not see): the unseen direction adds nothing.
  Eigen::MatrixXd J3(6, 3);
  J3 << J, Eigen::VectorXd::Zero(6);
  Eigen::VectorXd g3(3);
  g3 << g, 0.0;
  EXPECT_NEAR(dtwin::calib::integratorOptimumShift(J3, g3), shift, 1e-12);
}

// probeStepsFromJacobian against the closed form for a linear model: the SSE |r0 + J z|² rises by
// the threshold c along parameter k's profile at z_k = ±√(c (JᵀJ)⁻¹_kk) from the minimum, so the
// probe step is a tenth of that, clamped to [1e-4, 1e-2]; a parameter the data do not see (a zero
// column) gets the widest step.
TEST(IntegratorCheck, ProbeStepsAreATenthOfTheGaussNewtonHalfWidths) {
  Eigen::MatrixXd J(6, 3);
  J << 1, 0, 0, 1, 1, 0, 1, 2, 0, 1, 3, 0, 1, 4, 0, 1, 5, 0;
  J.leftCols(2) *= 400.0;
  const double c = 4.0;
  const Eigen::MatrixXd cov = (J.leftCols(2).transpose() * J.leftCols(2)).inverse();
  const std::vector<double> h = dtwin::calib::probeStepsFromJacobian(J, c);
  ASSERT_EQ(h.size(), 3u);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(h[k], std::sqrt(c * cov(k, k)) / 10, 1e-12) << k;
  EXPECT_DOUBLE_EQ(h[2], 1e-2);
  // Clamped: a very sharp parameter gets 1e-4, and no threshold gives the widest steps.
  EXPECT_DOUBLE_EQ(dtwin::calib::probeStepsFromJacobian(J * 1e4, c)[0], 1e-4);
  EXPECT_DOUBLE_EQ(dtwin::calib::probeStepsFromJacobian(J, 0.0)[1], 1e-2);
}

TEST(IntegratorCheck, FrozenStepsJudgeByRoughnessAndShift) {
  const std::vector<double> y = {0, 0, 0, 0}, w = {4, 4, 4, 4};
  const std::vector<double> eta = {0.5, -0.5, 0.5, -0.5}, fine = {0.55, -0.45, 0.55, -0.45};
  auto c = assessIntegrator(eta, fine, y, w, 3e-4, 0.79);
  ASSERT_FALSE(c.ok);  // the adaptive-steps jitter, 0.4
  dtwin::calib::applyProbes(c, 0.01, 0.2);
  EXPECT_EQ(c.steps, "frozen");
  EXPECT_DOUBLE_EQ(c.jitter, 0.2);
  EXPECT_TRUE(c.ok);
  EXPECT_TRUE(c.message.empty());
  dtwin::calib::applyProbes(c, 0.5, 0.2);
  EXPECT_FALSE(c.ok);
  // A shift within 4 times the floor the roughness sets is not resolved: the roughness decides.
  dtwin::calib::applyProbes(c, 0.01, 0.6, 0.2);
  EXPECT_DOUBLE_EQ(c.jitter, 0.01);
  EXPECT_TRUE(c.ok);
  dtwin::calib::applyProbes(c, 0.01, 0.6, 0.1);
  EXPECT_DOUBLE_EQ(c.jitter, 0.6);
  dtwin::calib::applyProbes(c, 0.5, 0.2);
  EXPECT_NE(c.message.find("with its steps frozen"), std::string::npos) << c.message;
  EXPECT_EQ(c.toJson().at("steps"), "frozen");
  EXPECT_DOUBLE_EQ(c.toJson().at("roughness").get<double>(), 0.5);
}
