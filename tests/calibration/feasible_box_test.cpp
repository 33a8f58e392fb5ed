// Feasible box: the analytic 1 % likelihood-ratio contour of a quadratic SSE, clipping at the
// bounds, failed simulations, budget exhaustion, and SSE_min = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <thread>

#include "calibration/feasible_box.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::calib;

namespace {
const std::vector<double> kLo = {120e3, 500.0, 10e3, 500.0};
const std::vector<double> kHi = {800e3, 7000.0, 180e3, 30e3};
const std::vector<double> kHat = {180e3, 3000.0, 30e3, 2500.0};
// Curvatures [SSE unit / parameter unit²]: SSE = SSE_min + Σ c_j (θ_j − θ̂_j)².
const std::vector<double> kCurv = {2e-2, 1e-4, 1.0, 1e-4};
constexpr double kSseMin = 5.0e4;
constexpr int kN = 50;

double quadraticSse(const std::vector<double>& t) {
  double f = kSseMin;
  for (std::size_t j = 0; j < t.size(); ++j) f += kCurv[j] * (t[j] - kHat[j]) * (t[j] - kHat[j]);
  return f;
}

BoxProblem problem() {
  BoxProblem p;
  p.theta_hat = kHat;
  p.sse_min = kSseMin;
  p.n_data = kN;
  p.lower = kLo;
  p.upper = kHi;
  return p;
}
}  // namespace

TEST(FeasibleBox, MatchesAnalyticContourOfQuadraticAndClipsAtBounds) {
  FeasibleBoxOptions opt;
  opt.tolerance = 1e-5;
  const FeasibleBox box = calcFeasibleBox(quadraticSse, problem(), opt);
  const double T = kSseMin * (1.0 + 2.0 * std::log(100.0) / kN);
  EXPECT_DOUBLE_EQ(box.threshold, T);
  EXPECT_TRUE(box.complete());
  int evals = 0;
  for (const auto& s : box.sweeps) evals += s.evaluations;
  EXPECT_EQ(box.evaluations, evals);
  for (std::size_t j = 0; j < 4; ++j) {
    const double half = std::sqrt((T - kSseMin) / kCurv[j]);  // analytic axis crossing
    const double range = kHi[j] - kLo[j];
    const double want_lo = std::max(kLo[j], kHat[j] - half);
    const double want_hi = std::min(kHi[j], kHat[j] + half);
    EXPECT_NEAR(box.lower[j], want_lo, opt.tolerance * range) << "parameter " << j;
    EXPECT_NEAR(box.upper[j], want_hi, opt.tolerance * range) << "parameter " << j;
    // Conservative: the box contains the contour.
    EXPECT_LE(box.lower[j], want_lo);
    EXPECT_GE(box.upper[j], want_hi);
    EXPECT_EQ(box.lower_clipped[j], kHat[j] - half < kLo[j]) << "parameter " << j;
    EXPECT_EQ(box.upper_clipped[j], kHat[j] + half > kHi[j]) << "parameter " << j;
  }
  // T − SSE_min = 9210: θ1 (±679) and θ3 (±96) lie inside the bounds; θ2 (±9597 around 3000)
  // is clipped on both sides, θ4 (±9597 around 2500) only at its lower bound 500.
  EXPECT_FALSE(box.lower_clipped[0] || box.upper_clipped[0] || box.lower_clipped[2] ||
               box.upper_clipped[2]);
  EXPECT_TRUE(box.lower_clipped[1] && box.upper_clipped[1]);
  EXPECT_TRUE(box.lower_clipped[3]);
  EXPECT_FALSE(box.upper_clipped[3]);
  std::cout << box.briefReport() << "\n";
}

TEST(FeasibleBox, OptimumOnTheBoundGivesThatBoundWithoutEvaluations) {
  BoxProblem p = problem();
  p.theta_hat[2] = kLo[2];
  const SweepResult s = calcBoxSweep(quadraticSse, p, 4, {});  // parameter 2, lower side
  EXPECT_EQ(s.parameter, 2);
  EXPECT_EQ(s.direction, -1);
  EXPECT_TRUE(s.clipped);
  EXPECT_EQ(s.edge, kLo[2]);
  EXPECT_EQ(s.evaluations, 0);
}

TEST(FeasibleBox, FailedSimulationCountsAsOutside) {
  // Every simulation with θ1 above 185e3 fails: the upper edge of θ1 stops there although the
  // quadratic contour would reach farther.
  auto f = [](const std::vector<double>& t) {
    if (t[0] > 185e3) return std::numeric_limits<double>::infinity();
    const double e = (t[0] - kHat[0]) / 1e5;
    return kSseMin * (1.0 + e * e * 1e-3);  // nearly flat: contour far outside
  };
  BoxProblem p = problem();
  FeasibleBoxOptions opt;
  opt.tolerance = 1e-6;
  const SweepResult s = calcBoxSweep(f, p, 1, opt);  // parameter 0, upper side
  EXPECT_TRUE(s.bracketed);
  EXPECT_FALSE(s.clipped);
  EXPECT_TRUE(std::isinf(s.edge_sse));
  EXPECT_NEAR(s.edge, 185e3, 1e-6 * (kHi[0] - kLo[0]));
  EXPECT_GE(s.edge, 185e3);
}

TEST(FeasibleBox, BudgetExhaustedIsReportedNotHidden) {
  FeasibleBoxOptions opt;
  opt.initial_step = 1e-6;
  opt.max_evaluations = 5;  // 1e-6 .. 1.6e-5: far short of the crossing
  const FeasibleBox box = calcFeasibleBox(quadraticSse, problem(), opt);
  EXPECT_FALSE(box.complete());
  const SweepResult& s = box.sweeps[1];
  EXPECT_FALSE(s.bracketed);
  EXPECT_FALSE(s.clipped);
  EXPECT_EQ(s.evaluations, 5);
  EXPECT_NE(s.message.find("not bracketed within 5 evaluations"), std::string::npos) << s.message;
  EXPECT_LE(quadraticSse({s.edge, kHat[1], kHat[2], kHat[3]}), box.threshold);  // edge is inside
  EXPECT_NE(box.briefReport().find("warning"), std::string::npos);
}

TEST(FeasibleBox, SweepsAreIndependentOfExecutionOrder) {
  const FeasibleBox seq = calcFeasibleBox(quadraticSse, problem());
  const FeasibleBox thr =
      calcFeasibleBox(quadraticSse, problem(), {}, [](int n, const std::function<void(int)>& task) {
        std::vector<std::thread> pool;
        for (int i = n - 1; i >= 0; --i) pool.emplace_back(task, i);
        for (auto& t : pool) t.join();
      });
  EXPECT_EQ(seq.lower, thr.lower);
  EXPECT_EQ(seq.upper, thr.upper);
  EXPECT_EQ(seq.evaluations, thr.evaluations);
}

TEST(FeasibleBox, ZeroSseMinIsRefusedWithExplanation) {
  BoxProblem p = problem();
  p.sse_min = 0.0;
  try {
    calcFeasibleBox(quadraticSse, p);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("SSE_min is 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("contour is the single point"), std::string::npos);
  }
  p = problem();
  p.theta_hat[1] = 1e6;
  try {
    calcFeasibleBox(quadraticSse, p);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("theta_hat[1] = 1000000 is outside [500, 7000]"),
              std::string::npos)
        << e.what();
  }
  FeasibleBoxOptions opt;
  opt.growth = 1.0;
  EXPECT_THROW(calcFeasibleBox(quadraticSse, problem(), opt), InputError);
}
