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
  EXPECT_NE(c.message.find("tighten [simulation] accuracy (to 3e-05 or less)"), std::string::npos) << c.message;
  // No interval threshold (no profile): nothing to compare with.
  EXPECT_TRUE(assessIntegrator(eta, fine, y, w, 3e-4, 0.0).ok);
}
