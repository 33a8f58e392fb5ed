#include "calibration/feasible_box.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>

#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::calib {
namespace {}  // namespace

void FeasibleBoxOptions::validate() const {
  const OptionCheck check("feasible_box");
  check.require(initial_step > 0.0 && initial_step <= 1.0, "initial_step",
                "must lie in (0, 1] (scaled units), got " + formatNumber(initial_step));
  check.require(growth > 1.0 && std::isfinite(growth), "growth",
                "must be a finite number > 1, got " + formatNumber(growth));
  check.open01("tolerance", tolerance);
  check.atLeast("max_evaluations", max_evaluations, 1);
}

double BoxProblem::threshold() const { return sse_min * (1.0 + 2.0 * std::log(100.0) / n_data); }

void BoxProblem::validate() const {
  const std::string where = "feasible box";
  checkBounds(lower, upper, where);
  if (theta_hat.size() != lower.size())
    throw InputError(where, "theta_hat has " + std::to_string(theta_hat.size()) +
                                " values, the bounds have " + std::to_string(lower.size()));
  for (std::size_t j = 0; j < theta_hat.size(); ++j)
    if (!(theta_hat[j] >= lower[j] && theta_hat[j] <= upper[j]))
      throw InputError(where, "theta_hat[" + std::to_string(j) +
                                  "] = " + formatNumber(theta_hat[j], 17) + " is outside [" +
                                  formatNumber(lower[j], 17) + ", " + formatNumber(upper[j], 17) +
                                  "]");
  if (n_data < 1)
    throw InputError(where, "number of data points n must be >= 1, got " + std::to_string(n_data));
  if (!std::isfinite(sse_min) || sse_min < 0.0)
    throw InputError(where, "SSE_min must be finite and >= 0, got " + formatNumber(sse_min, 17));
  if (sse_min == 0.0)
    throw InputError(where,
                     "SSE_min is 0 (the model fits the data exactly, e.g. noise-free data): "
                     "tau_hat = n/SSE_min is infinite and the 1 % likelihood-ratio contour is the "
                     "single point theta_hat, so no box can be derived from it");
}

RaySweep sweepRay(const std::function<double(double t)>& sse_at, double t_max, double threshold,
                  double sse0, const FeasibleBoxOptions& options, double first_step,
                  double relative_tolerance) {
  options.validate();
  RaySweep r;
  auto eval = [&](double t) {
    ++r.evaluations;
    const double f = sse_at(t);
    return std::isfinite(f) ? f : std::numeric_limits<double>::infinity();
  };
  if (t_max <= 0.0) {
    r.edge_sse = sse0;
    r.clipped = true;
    return r;
  }
  // 1. Geometric stepping until outside or at t_max.
  double inside = 0.0, inside_sse = sse0;
  double outside = 0.0, outside_sse = 0.0;
  double h = first_step > 0.0 ? first_step : options.initial_step;
  for (;;) {
    if (r.evaluations >= options.max_evaluations) {
      r.t_edge = inside;
      r.edge_sse = inside_sse;
      r.budget_out = true;
      return r;
    }
    const bool at_end = h >= t_max;
    const double t = at_end ? t_max : h;
    const double f = eval(t);
    if (f <= threshold) {
      inside = t;
      inside_sse = f;
      if (at_end) {
        r.t_edge = t_max;
        r.edge_sse = f;
        r.clipped = true;
        return r;
      }
      h *= options.growth;
    } else {
      outside = t;
      outside_sse = f;
      break;
    }
  }
  // 2. Bisection of [inside, outside].
  r.bracketed = true;
  auto tol = [&] {
    return relative_tolerance > 0.0 ? relative_tolerance * outside : options.tolerance;
  };
  while (outside - inside > tol() && r.evaluations < options.max_evaluations) {
    const double mid = 0.5 * (inside + outside);
    const double f = eval(mid);
    if (f <= threshold) {
      inside = mid;
    } else {
      outside = mid;
      outside_sse = f;
    }
  }
  r.bracket = outside - inside;
  r.loose = r.bracket > tol();
  r.t_edge = outside;
  r.edge_sse = outside_sse;
  return r;
}

SweepResult calcBoxSweep(const SseFunction& sse, const BoxProblem& problem, int index,
                         const FeasibleBoxOptions& options) {
  problem.validate();
  options.validate();
  const int d = static_cast<int>(problem.theta_hat.size());
  if (index < 0 || index >= 2 * d)
    throw InputError("feasible box", "sweep index must be in [0, " + std::to_string(2 * d) +
                                         "), got " + std::to_string(index));
  const auto j = static_cast<std::size_t>(index / 2);
  const int dir = (index % 2 == 0) ? -1 : +1;
  const double lo = problem.lower[j], hi = problem.upper[j], range = hi - lo;
  const double bound = dir < 0 ? lo : hi;
  const double z0 = (problem.theta_hat[j] - lo) / range;
  const double to_bound = dir < 0 ? z0 : 1.0 - z0;  // scaled distance from θ̂ to the bound

  // Physical point at scaled distance t from θ̂ in direction dir (exact bound at t = to_bound).
  auto at = [&](double t) {
    return t >= to_bound ? bound : std::clamp(lo + (z0 + dir * t) * range, lo, hi);
  };
  std::vector<double> theta = problem.theta_hat;
  const RaySweep ray = sweepRay(
      [&](double t) {
        theta[j] = at(t);
        return sse(theta);
      },
      to_bound, problem.threshold(), problem.sse_min, options);

  SweepResult r;
  r.parameter = static_cast<int>(j);
  r.direction = dir;
  r.edge = at(ray.t_edge);
  r.edge_sse = ray.edge_sse;
  r.clipped = ray.clipped;
  r.bracketed = ray.bracketed;
  r.evaluations = ray.evaluations;
  std::ostringstream os;
  if (ray.budget_out) {
    os << "parameter " << j << (dir < 0 ? " lower" : " upper") << " edge: the 1 % contour was "
       << "not bracketed within " << options.max_evaluations
       << " evaluations; the box edge is the farthest point known inside, so the box may be "
          "too small here";
  } else if (ray.loose) {
    os << "parameter " << j << (dir < 0 ? " lower" : " upper")
       << " edge: bisection stopped by max_evaluations at a bracket of " << ray.bracket
       << " (scaled), wider than the tolerance " << options.tolerance;
  }
  r.message = os.str();
  return r;
}

FeasibleBox calcFeasibleBox(const SseFunction& sse, const BoxProblem& problem,
                            const FeasibleBoxOptions& options, const ParallelFor& parallel_for) {
  problem.validate();
  options.validate();
  const int d = static_cast<int>(problem.theta_hat.size());
  const int count = 2 * d;
  std::vector<SweepResult> sweeps(static_cast<std::size_t>(count));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(count));
  std::vector<char> done(static_cast<std::size_t>(count), 0);
  const ParallelFor& run = parallel_for ? parallel_for : ParallelFor(sequentialFor);
  run(count, [&](int i) {
    DTWIN_CHECK(i >= 0 && i < count, "parallel_for called a task index out of range");
    const auto k = static_cast<std::size_t>(i);
    try {
      sweeps[k] = calcBoxSweep(sse, problem, i, options);
    } catch (...) {
      errors[k] = std::current_exception();
    }
    done[k] = 1;
  });
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  for (int i = 0; i < count; ++i)
    DTWIN_CHECK(done[static_cast<std::size_t>(i)], "parallel_for did not run every sweep");
  return collectFeasibleBox(problem, std::move(sweeps));
}

FeasibleBox collectFeasibleBox(const BoxProblem& problem, std::vector<SweepResult> sweeps) {
  const int d = static_cast<int>(problem.theta_hat.size());
  const int count = 2 * d;
  DTWIN_CHECK(static_cast<int>(sweeps.size()) == count, "a box needs 2d sweeps");
  FeasibleBox box;
  box.threshold = problem.threshold();
  box.lower.resize(static_cast<std::size_t>(d));
  box.upper.resize(static_cast<std::size_t>(d));
  box.lower_clipped.resize(static_cast<std::size_t>(d));
  box.upper_clipped.resize(static_cast<std::size_t>(d));
  for (int i = 0; i < count; ++i) {
    const SweepResult& s = sweeps[static_cast<std::size_t>(i)];
    const auto j = static_cast<std::size_t>(s.parameter);
    (s.direction < 0 ? box.lower : box.upper)[j] = s.edge;
    (s.direction < 0 ? box.lower_clipped : box.upper_clipped)[j] = s.clipped;
    box.evaluations += s.evaluations;
  }
  box.sweeps = std::move(sweeps);
  return box;
}

bool FeasibleBox::complete() const {
  return std::all_of(sweeps.begin(), sweeps.end(),
                     [](const SweepResult& s) { return s.bracketed || s.clipped; });
}

std::string FeasibleBox::briefReport() const {
  std::ostringstream os;
  os.precision(6);
  os << "feasible box (SSE <= " << threshold << "): ";
  for (std::size_t j = 0; j < lower.size(); ++j) {
    os << (j ? ", " : "") << (lower_clipped[j] ? "[*" : "[") << lower[j] << ", " << upper[j]
       << (upper_clipped[j] ? "*]" : "]");
  }
  os << " (* = at the calibration bound; " << evaluations << " evaluations)";
  for (const auto& s : sweeps)
    if (!s.message.empty()) os << "\n  warning: " << s.message;
  return os.str();
}

}  // namespace dtwin::calib
