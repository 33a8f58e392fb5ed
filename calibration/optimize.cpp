#include "calibration/optimize.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>

#include "calibration/lhs.hpp"
#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::calib {
namespace {

const char* const kAllowedAlgorithms[] = {"LN_BOBYQA", "LN_SBPLX",        "LN_NELDERMEAD",
                                          "LN_COBYLA", "LN_NEWUOA_BOUND", "LN_PRAXIS"};

std::string allowedList() {
  std::string s;
  for (const char* a : kAllowedAlgorithms) s += (s.empty() ? "" : ", ") + std::string(a);
  return s;
}

/// State of one local run, reached from the C callback through `void* data`.
struct RunContext {
  const SseFunction* sse = nullptr;
  const std::vector<double>* lower = nullptr;
  const std::vector<double>* upper = nullptr;
  nlopt::opt* opt = nullptr;
  std::vector<double> theta;  // scratch: physical point of the current evaluation
  std::vector<double> best_theta;
  double best_sse = std::numeric_limits<double>::infinity();
  double largest_finite = -1.0;
  int evaluations = 0;
  int nonfinite = 0;
  std::exception_ptr error;
};

void toPhysical(const double* z, const std::vector<double>& lo, const std::vector<double>& hi,
                std::vector<double>& theta) {
  for (std::size_t j = 0; j < lo.size(); ++j) {
    const double zj = std::clamp(z[j], 0.0, 1.0);
    theta[j] = std::clamp(lo[j] + zj * (hi[j] - lo[j]), lo[j], hi[j]);
  }
}

double objective(unsigned n, const double* z, double* grad, void* data) {
  auto& c = *static_cast<RunContext*>(data);
  DTWIN_CHECK(grad == nullptr, "a derivative-free algorithm asked for a gradient");
  DTWIN_CHECK(n == c.theta.size(), "NLopt dimension mismatch");
  if (c.error) return 1e100;  // already stopping
  toPhysical(z, *c.lower, *c.upper, c.theta);
  double f;
  try {
    f = (*c.sse)(c.theta);
  } catch (...) {
    c.error = std::current_exception();
    c.opt->force_stop();
    return 1e100;
  }
  ++c.evaluations;
  if (!std::isfinite(f)) {
    ++c.nonfinite;
    // Finite penalty, worse than anything seen: NLopt's models stay finite.
    return c.largest_finite >= 0.0 ? 10.0 * c.largest_finite + 1.0 : 1e100;
  }
  c.largest_finite = std::max(c.largest_finite, f);
  if (f < c.best_sse) {
    c.best_sse = f;
    c.best_theta = c.theta;
  }
  return f;
}

}  // namespace

void OptimizerOptions::validate() const {
  const OptionCheck check("optimizer");
  check.require(std::find(std::begin(kAllowedAlgorithms), std::end(kAllowedAlgorithms),
                          algorithm) != std::end(kAllowedAlgorithms),
                "algorithm", "must be one of " + allowedList() + ", got '" + algorithm + "'");
  check.nonNegative("xtol_rel", xtol_rel);
  check.nonNegative("xtol_abs", xtol_abs);
  check.nonNegative("ftol_rel", ftol_rel);
  check.nonNegative("ftol_abs", ftol_abs);
  check.atLeast("maxeval", maxeval, 1);
  check.require(initial_step > 0.0 && initial_step <= 0.5, "initial_step",
                "must lie in (0, 0.5] (scaled units), got " + formatNumber(initial_step));
  check.atLeast("screen_per_start", screen_per_start, 0);
}

std::vector<std::vector<double>> screeningPoints(const std::vector<double>& lower,
                                                 const std::vector<double>& upper, int starts,
                                                 int per_start, std::uint64_t seed) {
  checkBounds(lower, upper, "optimizer");
  const std::size_t d = lower.size();
  std::vector<std::vector<double>> out;
  std::vector<double> centre(d);
  for (std::size_t j = 0; j < d; ++j) centre[j] = 0.5 * (lower[j] + upper[j]);
  out.push_back(centre);
  const int n = std::max(starts, 1) * std::max(per_start, 0);
  if (n > 0) {
    constexpr std::uint64_t kStreamScreen = 0x5343'5200'0000'0007ULL;  // "SCR"
    const Eigen::MatrixXd x = latinHypercube(n, lower, upper, splitmix64(seed ^ kStreamScreen));
    for (int i = 0; i < n; ++i) {
      std::vector<double> p(d);
      for (std::size_t j = 0; j < d; ++j) p[j] = x(i, static_cast<Eigen::Index>(j));
      out.push_back(std::move(p));
    }
  }
  return out;
}

std::vector<std::vector<double>> bestStarts(const std::vector<std::vector<double>>& candidates,
                                            const std::vector<double>& sse,
                                            const std::vector<double>& lower,
                                            const std::vector<double>& upper, int starts) {
  DTWIN_CHECK(candidates.size() == sse.size() && !candidates.empty(),
              "bestStarts needs one SSE per candidate");
  std::vector<std::size_t> order(candidates.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto key = [&](std::size_t i) {
    return std::isfinite(sse[i]) ? sse[i] : std::numeric_limits<double>::infinity();
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<std::vector<double>> out;
  for (std::size_t i : order) {
    if (static_cast<int>(out.size()) >= starts) break;
    bool near = false;
    for (const auto& s : out) {
      double dmax = 0.0;
      for (std::size_t j = 0; j < s.size(); ++j)
        dmax = std::max(dmax, std::abs(s[j] - candidates[i][j]) / (upper[j] - lower[j]));
      near = near || dmax < 0.05;
    }
    if (!near) out.push_back(candidates[i]);
  }
  for (std::size_t i : order)  // fewer distinct candidates than starts: fill up in SSE order
    if (static_cast<int>(out.size()) < starts &&
        std::find(out.begin(), out.end(), candidates[i]) == out.end())
      out.push_back(candidates[i]);
  return out;
}

std::vector<std::vector<double>> optimizerStarts(const std::vector<double>& lower,
                                                 const std::vector<double>& upper, int starts,
                                                 std::uint64_t seed) {
  checkBounds(lower, upper, "optimizer");
  if (starts < 1)
    throw InputError("optimizer", "number of starts must be >= 1, got " + std::to_string(starts));
  const std::size_t d = lower.size();
  std::vector<std::vector<double>> out;
  out.reserve(static_cast<std::size_t>(starts));
  std::vector<double> centre(d);
  for (std::size_t j = 0; j < d; ++j) centre[j] = 0.5 * (lower[j] + upper[j]);
  out.push_back(centre);
  if (starts > 1) {
    // The LHS uses kStreamLhs internally; scrambling the seed with kStreamOptimizerStarts keeps
    // the starts independent of a design drawn with the same user seed.
    const Eigen::MatrixXd u =
        latinHypercube(starts - 1, std::vector<double>(d, 0.0), std::vector<double>(d, 1.0),
                       splitmix64(seed ^ kStreamOptimizerStarts));
    for (int i = 0; i < starts - 1; ++i) {
      std::vector<double> s(d);
      for (std::size_t j = 0; j < d; ++j)
        s[j] = std::clamp(lower[j] + u(i, static_cast<Eigen::Index>(j)) * (upper[j] - lower[j]),
                          lower[j], upper[j]);
      out.push_back(std::move(s));
    }
  }
  return out;
}

StartResult minimiseFrom(const SseFunction& sse, const std::vector<double>& lower,
                         const std::vector<double>& upper, const std::vector<double>& start,
                         const OptimizerOptions& options) {
  checkBounds(lower, upper, "optimizer");
  options.validate();
  const std::size_t d = lower.size();
  if (start.size() != d)
    throw InputError("optimizer", "start has " + std::to_string(start.size()) +
                                      " values, the bounds have " + std::to_string(d));
  std::vector<double> z(d);
  for (std::size_t j = 0; j < d; ++j) {
    if (!(start[j] >= lower[j] && start[j] <= upper[j]))
      throw InputError("optimizer", "start value " + std::to_string(j) + " = " +
                                        formatNumber(start[j], 17) + " is outside [" +
                                        formatNumber(lower[j], 17) + ", " +
                                        formatNumber(upper[j], 17) + "]");
    z[j] = (start[j] - lower[j]) / (upper[j] - lower[j]);
  }

  const nlopt_algorithm alg = nlopt_algorithm_from_string(options.algorithm.c_str());
  DTWIN_CHECK(static_cast<int>(alg) >= 0, "validated algorithm name not known to NLopt");
  nlopt::opt opt(static_cast<nlopt::algorithm>(alg), static_cast<unsigned>(d));
  RunContext ctx;
  ctx.sse = &sse;
  ctx.lower = &lower;
  ctx.upper = &upper;
  ctx.opt = &opt;
  ctx.theta.resize(d);
  opt.set_min_objective(objective, &ctx);
  opt.set_lower_bounds(std::vector<double>(d, 0.0));
  opt.set_upper_bounds(std::vector<double>(d, 1.0));
  opt.set_xtol_rel(options.xtol_rel);
  opt.set_xtol_abs(options.xtol_abs);
  opt.set_ftol_rel(options.ftol_rel);
  opt.set_ftol_abs(options.ftol_abs);
  opt.set_maxeval(options.maxeval);
  opt.set_initial_step(std::vector<double>(d, options.initial_step));

  StartResult r;
  r.start = start;
  double fz = 0.0;
  // The start itself counts: BOBYQA moves a start lying within the initial step of a bound before
  // its first evaluation (Powell 2009, §2), so a start that is already optimal (a nested model's
  // optimum with an added effect off) would otherwise be lost.
  objective(static_cast<unsigned>(d), z.data(), nullptr, &ctx);
  try {
    opt.optimize(z, fz);
    r.status = nlopt_result_to_string(static_cast<nlopt_result>(opt.last_optimize_result()));
  } catch (const nlopt::roundoff_limited&) {
    r.status = "ROUNDOFF_LIMITED";  // not an error: the best point so far is kept
  } catch (const nlopt::forced_stop&) {
    r.status = "FORCED_STOP";
  } catch (const std::invalid_argument& e) {
    if (ctx.error) std::rethrow_exception(ctx.error);
    throw InputError("optimizer", std::string("NLopt rejected the problem: ") + e.what());
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::runtime_error& e) {
    r.status = std::string("FAILURE: ") + e.what();
  }
  if (ctx.error) std::rethrow_exception(ctx.error);

  r.evaluations = ctx.evaluations;
  r.nonfinite_evaluations = ctx.nonfinite;
  r.sse = ctx.best_sse;
  r.theta = ctx.best_theta.empty() ? start : ctx.best_theta;
  return r;
}

Optimum minimiseSse(const SseFunction& sse, const std::vector<double>& lower,
                    const std::vector<double>& upper, int starts, std::uint64_t seed,
                    const OptimizerOptions& options, const ParallelFor& parallel_for) {
  options.validate();
  checkBounds(lower, upper, "optimizer");
  if (starts < 1)
    throw InputError("optimizer", "number of starts must be >= 1, got " + std::to_string(starts));
  std::vector<std::vector<double>> x0;
  const ParallelFor& run = parallel_for ? parallel_for : ParallelFor(sequentialFor);
  if (options.screen_per_start > 0) {
    const auto cand = screeningPoints(lower, upper, starts, options.screen_per_start, seed);
    std::vector<double> f(cand.size());
    std::vector<std::exception_ptr> errs(cand.size());
    run(static_cast<int>(cand.size()), [&](int i) {
      try {
        f[static_cast<std::size_t>(i)] = sse(cand[static_cast<std::size_t>(i)]);
      } catch (...) {
        errs[static_cast<std::size_t>(i)] = std::current_exception();
      }
    });
    for (const auto& e : errs)
      if (e) std::rethrow_exception(e);
    x0 = bestStarts(cand, f, lower, upper, starts);
  } else {
    x0 = optimizerStarts(lower, upper, starts, seed);
  }
  std::vector<StartResult> results(x0.size());
  std::vector<std::exception_ptr> errors(x0.size());
  run(starts, [&](int i) {
    DTWIN_CHECK(i >= 0 && i < starts, "parallel_for called a task index out of range");
    const auto k = static_cast<std::size_t>(i);
    try {
      results[k] = minimiseFrom(sse, lower, upper, x0[k], options);
    } catch (...) {
      errors[k] = std::current_exception();  // never let an exception cross the hook
    }
  });
  for (const auto& e : errors)  // the lowest-index error, whatever the execution order
    if (e) std::rethrow_exception(e);

  return collectOptimum(std::move(results));
}

Optimum collectOptimum(std::vector<StartResult> results) {
  DTWIN_CHECK(!results.empty(), "no optimiser start");
  Optimum opt;
  opt.starts = std::move(results);
  for (std::size_t i = 0; i < opt.starts.size(); ++i) {
    const StartResult& s = opt.starts[i];
    DTWIN_CHECK(!s.status.empty(), "parallel_for did not run every start");
    opt.evaluations += s.evaluations;
    if (opt.best_start < 0 || s.sse < opt.starts[static_cast<std::size_t>(opt.best_start)].sse)
      opt.best_start = static_cast<int>(i);  // strict <: ties go to the lowest index
  }
  const StartResult& best = opt.starts[static_cast<std::size_t>(opt.best_start)];
  opt.theta = best.theta;
  opt.sse = best.sse;
  return opt;
}

std::string Optimum::briefReport() const {
  std::ostringstream os;
  os.precision(6);
  os << "SSE_min " << sse << " at [";
  for (std::size_t j = 0; j < theta.size(); ++j) os << (j ? ", " : "") << theta[j];
  os << "] (start " << best_start << " of " << starts.size() << ", " << evaluations
     << " evaluations)";
  if (!std::isfinite(sse)) os << " -- no start found a finite SSE";
  return os.str();
}

std::string Optimum::fullReport() const {
  std::ostringstream os;
  os.precision(6);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const StartResult& s = starts[i];
    os << "start " << i << ": SSE " << s.sse << " at [";
    for (std::size_t j = 0; j < s.theta.size(); ++j) os << (j ? ", " : "") << s.theta[j];
    os << "], " << s.evaluations << " evaluations";
    if (s.nonfinite_evaluations) os << " (" << s.nonfinite_evaluations << " failed)";
    os << ", " << s.status << "\n";
  }
  os << briefReport() << "\n";
  return os.str();
}

}  // namespace dtwin::calib
