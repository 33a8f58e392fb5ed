// Multi-start bounded SSE minimisation: known minima of badly scaled analytic functions, a
// minimum on the bound, failed evaluations, and independence of the execution order.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "calibration/optimize.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::calib;

namespace {
// The paper's bounds: stiffnesses ~1e5, dampings ~1e3.
const std::vector<double> kLo = {120e3, 500.0, 10e3, 500.0};
const std::vector<double> kHi = {800e3, 7000.0, 180e3, 30e3};
const std::vector<double> kTrue = {180e3, 3000.0, 30e3, 2500.0};

/// Shifted, badly scaled quadratic with cross terms (a correlated SSE valley):
/// SSE = f0 + Σ_j w_j e_j² + 0.5 e_0 e_2, e_j = (θ_j − c_j)/c_j.
double quadratic(const std::vector<double>& t) {
  const double w[4] = {4e6, 1e5, 2e6, 3e4};
  double e[4];
  for (int j = 0; j < 4; ++j) e[j] = (t[j] - kTrue[j]) / kTrue[j];
  double f = 1234.5;
  for (int j = 0; j < 4; ++j) f += w[j] * e[j] * e[j];
  return f + 0.5 * w[0] * e[0] * e[2];
}

/// Rosenbrock valley in physical units: x = (θ1 − 2e5)/1e5, y = (θ2 − 3000)/1000,
/// SSE = 7 + 100 (y − x²)² + (1 − x)², minimum 7 at x = y = 1, i.e. θ = (3e5, 4000).
double rosenbrock(const std::vector<double>& t) {
  const double x = (t[0] - 2e5) / 1e5, y = (t[1] - 3000.0) / 1000.0;
  return 7.0 + 100.0 * (y - x * x) * (y - x * x) + (1.0 - x) * (1.0 - x);
}

void expectSame(const Optimum& a, const Optimum& b) {
  ASSERT_EQ(a.starts.size(), b.starts.size());
  EXPECT_EQ(a.theta, b.theta);
  EXPECT_EQ(a.sse, b.sse);
  EXPECT_EQ(a.best_start, b.best_start);
  for (std::size_t i = 0; i < a.starts.size(); ++i) {
    EXPECT_EQ(a.starts[i].start, b.starts[i].start);
    EXPECT_EQ(a.starts[i].theta, b.starts[i].theta);
    EXPECT_EQ(a.starts[i].evaluations, b.starts[i].evaluations);
  }
}
}  // namespace

TEST(Optimize, FindsMinimumOfBadlyScaledQuadratic) {
  const Optimum o = minimiseSse(quadratic, kLo, kHi, 4, 42);
  ASSERT_EQ(o.starts.size(), 4u);
  for (int j = 0; j < 4; ++j)
    EXPECT_NEAR(o.theta[j], kTrue[j], 1e-5 * (kHi[j] - kLo[j])) << "parameter " << j;
  EXPECT_NEAR(o.sse, 1234.5, 1e-6);
  EXPECT_EQ(o.sse, quadratic(o.theta));  // the reported SSE is the SSE of the reported point
  int total = 0;
  for (const auto& s : o.starts) total += s.evaluations;
  EXPECT_EQ(o.evaluations, total);
  std::cout << o.fullReport();
}

TEST(Optimize, FindsRosenbrockMinimum) {
  const std::vector<double> lo = {1e5, 500.0}, hi = {8e5, 7000.0};
  OptimizerOptions opt;
  opt.xtol_rel = 1e-10;
  opt.ftol_rel = 1e-14;
  const Optimum o = minimiseSse(rosenbrock, lo, hi, 3, 1, opt);
  EXPECT_NEAR(o.theta[0], 3e5, 1e-4 * 1e5);
  EXPECT_NEAR(o.theta[1], 4000.0, 2e-4 * 1e3);
  EXPECT_NEAR(o.sse, 7.0, 1e-7);
}

TEST(Optimize, MinimumOnTheBound) {
  // The unconstrained minimum of θ1 lies below the lower bound 120e3: the answer is the bound.
  auto f = [](const std::vector<double>& t) {
    const double e0 = (t[0] - 50e3) / 1e5, e1 = (t[1] - 3000.0) / 1e3;
    return 10.0 + e0 * e0 + e1 * e1;
  };
  const std::vector<double> lo = {120e3, 500.0}, hi = {800e3, 7000.0};
  const Optimum o = minimiseSse(f, lo, hi, 3, 9);
  EXPECT_NEAR(o.theta[0], 120e3, 1e-6 * (hi[0] - lo[0]));
  EXPECT_GE(o.theta[0], 120e3);  // never outside the bounds
  EXPECT_NEAR(o.theta[1], 3000.0, 1e-4 * (hi[1] - lo[1]));
  const double e0 = (120e3 - 50e3) / 1e5;
  EXPECT_NEAR(o.sse, 10.0 + e0 * e0, 1e-9);
}

TEST(Optimize, StartsAreCentreThenLatinHypercubeInsideBounds) {
  const auto s = optimizerStarts(kLo, kHi, 6, 3);
  ASSERT_EQ(s.size(), 6u);
  for (int j = 0; j < 4; ++j) EXPECT_DOUBLE_EQ(s[0][j], 0.5 * (kLo[j] + kHi[j]));
  for (std::size_t i = 1; i < s.size(); ++i)
    for (int j = 0; j < 4; ++j) {
      EXPECT_GE(s[i][j], kLo[j]);
      EXPECT_LE(s[i][j], kHi[j]);
    }
  EXPECT_EQ(s, optimizerStarts(kLo, kHi, 6, 3));
  EXPECT_NE(s, optimizerStarts(kLo, kHi, 6, 4));
}

TEST(Optimize, FailedEvaluationsDoNotCrashAndAreNeverTheOptimum) {
  // Simulations "fail" (+inf, or NaN) in a band and in a corner; the start at the box centre is
  // inside the failing band. The minimum (θ1 = 150e3) is in the finite region.
  std::atomic<int> failures{0};
  auto f = [&](const std::vector<double>& t) {
    if (t[0] > 400e3 && t[0] < 500e3) {
      ++failures;
      return std::numeric_limits<double>::infinity();
    }
    if (t[1] > 6500.0) {
      ++failures;
      return std::numeric_limits<double>::quiet_NaN();
    }
    const double e0 = (t[0] - 150e3) / 1e5, e1 = (t[1] - 2000.0) / 1e3;
    return 3.0 + e0 * e0 + e1 * e1;
  };
  const std::vector<double> lo = {120e3, 500.0}, hi = {800e3, 7000.0};
  for (const char* alg : {"LN_BOBYQA", "LN_SBPLX"}) {
    SCOPED_TRACE(alg);
    OptimizerOptions opt;
    opt.algorithm = alg;
    opt.screen_per_start = 0;  // the unscreened starts: the centre lies in the failing band
    const Optimum o = minimiseSse(f, lo, hi, 5, 2, opt);
    std::cout << alg << "\n" << o.fullReport();
    EXPECT_GT(failures.load(), 0);
    EXPECT_TRUE(std::isfinite(o.sse));
    EXPECT_NEAR(o.theta[0], 150e3, 1e-3 * (hi[0] - lo[0]));
    EXPECT_NEAR(o.theta[1], 2000.0, 1e-3 * (hi[1] - lo[1]));
    int counted = 0;
    for (const auto& s : o.starts) {
      counted += s.nonfinite_evaluations;
      if (std::isfinite(s.sse)) {
        EXPECT_EQ(s.sse, f(s.theta));
      }
    }
    EXPECT_GT(counted, 0);
    // The centre start (460e3, 3750) lies in the failing band itself.
    EXPECT_GE(o.starts[0].nonfinite_evaluations, 1);
  }
}

// A broad, shallow basin around the centre of the bounds and a narrow, deep one near a corner:
// unscreened starts all stop in the shallow basin, the screened ones find the deep one.
TEST(Optimize, ScreeningFindsTheDeepBasinUnscreenedStartsMiss) {
  auto f = [](const std::vector<double>& t) {
    const double a = (t[0] - 0.5) / 0.3, b = (t[1] - 0.5) / 0.3;
    const double c = (t[0] - 0.9) / 0.12, d = (t[1] - 0.12) / 0.12;
    return 10.0 - 2.0 * std::exp(-(a * a + b * b)) - 9.0 * std::exp(-(c * c + d * d));
  };
  OptimizerOptions opt;
  opt.screen_per_start = 0;
  const Optimum plain = minimiseSse(f, {0.0, 0.0}, {1.0, 1.0}, 2, 3, opt);
  EXPECT_GT(plain.sse, 7.0) << plain.fullReport();
  opt.screen_per_start = 25;
  const Optimum screened = minimiseSse(f, {0.0, 0.0}, {1.0, 1.0}, 2, 3, opt);
  EXPECT_LT(screened.sse, 1.5) << screened.fullReport();
  EXPECT_NEAR(screened.theta[0], 0.9, 0.01);
  EXPECT_NEAR(screened.theta[1], 0.12, 0.01);
  // The chosen starts are the best candidates, at least 0.05 apart.
  const auto cand = screeningPoints({0.0, 0.0}, {1.0, 1.0}, 2, 25, 3);
  ASSERT_EQ(cand.size(), 51u);
  EXPECT_EQ(cand[0], (std::vector<double>{0.5, 0.5}));
  std::vector<double> fs;
  for (const auto& c : cand) fs.push_back(f(c));
  const auto starts = bestStarts(cand, fs, {0.0, 0.0}, {1.0, 1.0}, 2);
  ASSERT_EQ(starts.size(), 2u);
  EXPECT_EQ(f(starts[0]), *std::min_element(fs.begin(), fs.end()));
  EXPECT_GE(std::max(std::abs(starts[0][0] - starts[1][0]), std::abs(starts[0][1] - starts[1][1])),
            0.05);
}

TEST(Optimize, AllEvaluationsFailingGivesInfiniteSse) {
  auto f = [](const std::vector<double>&) { return std::numeric_limits<double>::infinity(); };
  OptimizerOptions opt;
  opt.maxeval = 30;
  const Optimum o = minimiseSse(f, {0.0}, {1.0}, 2, 1, opt);
  EXPECT_TRUE(std::isinf(o.sse));
  EXPECT_EQ(o.best_start, 0);
  EXPECT_EQ(o.theta, o.starts[0].start);
  EXPECT_NE(o.briefReport().find("no start found a finite SSE"), std::string::npos);
}

TEST(Optimize, ExceptionFromTheModelIsRethrown) {
  auto f = [](const std::vector<double>& t) -> double {
    if (t[0] > 0.7) throw std::runtime_error("model exploded at 0.7");
    return (t[0] - 0.9) * (t[0] - 0.9);
  };
  try {
    minimiseSse(f, {0.0}, {1.0}, 3, 1);
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "model exploded at 0.7");
  }
}

TEST(Optimize, ResultDoesNotDependOnExecutionOrderOrThreads) {
  const Optimum seq = minimiseSse(quadratic, kLo, kHi, 6, 77);
  const Optimum rev =
      minimiseSse(quadratic, kLo, kHi, 6, 77, {}, [](int n, const std::function<void(int)>& task) {
        for (int i = n - 1; i >= 0; --i) task(i);
      });
  const Optimum thr =
      minimiseSse(quadratic, kLo, kHi, 6, 77, {}, [](int n, const std::function<void(int)>& task) {
        std::vector<std::thread> pool;
        for (int i = 0; i < n; ++i) pool.emplace_back(task, i);
        for (auto& t : pool) t.join();
      });
  expectSame(seq, rev);
  expectSame(seq, thr);
}

TEST(Optimize, OptionsAreValidatedWithClearMessages) {
  OptimizerOptions opt;
  opt.algorithm = "LD_LBFGS";
  try {
    minimiseSse(quadratic, kLo, kHi, 2, 1, opt);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "optimizer.algorithm");
    EXPECT_NE(e.rule().find("must be one of LN_BOBYQA"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("got 'LD_LBFGS'"), std::string::npos) << e.what();
  }
  opt = {};
  opt.maxeval = 0;
  EXPECT_THROW(opt.validate(), InputError);
  try {
    minimiseSse(quadratic, kLo, kHi, 0, 1);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("number of starts must be >= 1, got 0"), std::string::npos)
        << e.what();
  }
}

TEST(Optimize, EveryAllowedAlgorithmSolvesTheQuadratic) {
  for (const char* alg :
       {"LN_BOBYQA", "LN_SBPLX", "LN_NELDERMEAD", "LN_COBYLA", "LN_NEWUOA_BOUND", "LN_PRAXIS"}) {
    OptimizerOptions opt;
    opt.algorithm = alg;
    opt.maxeval = 5000;
    const Optimum o = minimiseSse(quadratic, kLo, kHi, 2, 5, opt);
    EXPECT_NEAR(o.sse, 1234.5, 1e-3) << alg << ": " << o.fullReport();
  }
}

// BOBYQA moves a start lying within its initial step of a bound before evaluating it; a start that
// already sits in a narrow well (a nested model's optimum with an added effect off) must still be
// the answer when nothing better is found.
TEST(Optimize, AStartNearABoundIsEvaluatedAndKept) {
  auto f = [](const std::vector<double>& t) {
    const double u = (t[0] - 0.02) / 0.005;
    return -std::exp(-u * u) + 0.1 * (t[0] - 0.6) * (t[0] - 0.6);
  };
  OptimizerOptions opt;
  opt.initial_step = 0.1;
  const StartResult r = minimiseFrom(f, {0.0}, {1.0}, {0.02}, opt);
  EXPECT_LT(r.sse, -0.9);
  EXPECT_NEAR(r.theta[0], 0.02, 1e-3);
}
