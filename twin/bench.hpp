#pragma once
// Speed measurement of the twin: wall time per run, median over repeated runs.
#include <string>
#include <vector>

#include "twin/study.hpp"

namespace dtwin {

struct BenchRow {
  std::string assembly, label, scenario;
  double median_wall_s = 0, min_wall_s = 0, max_wall_s = 0;
  double simulated_s = 0;
  double real_time_factor = 0;  ///< simulated seconds per wall second
  long steps = 0;
  double peak_fl_N = 0;         ///< peak front-left hub force of the run
  double reference_peak_fl_N = 0;  ///< same at tight tolerance (bump scenarios; 0 if not computed)
  bool ok = true;
};

/// Runs `scenario` `runs` times (after one warm-up) for the assembly and returns the figures.
/// If `reference` is true, also runs once at tight tolerance (accuracy 1e-8, steps <= 2.5e-5 s
/// near obstacles) to compare the peak front-left force.
BenchRow benchAssembly(const Study& study, const AssemblySpec& a, const ScenarioSpec& scenario, int runs, bool reference);

/// `twin import` on a synthetic logger CSV of `rows` rows at 100 Hz (time with clock jitter,
/// speed in km/h, left and right road heights in mm, two accelerometers in g, two unused
/// columns), read, converted and written into a fresh temporary folder `runs` times.
struct BenchImport {
  long rows = 0;
  double bytes = 0;             ///< size of the log
  double median_s = 0, min_s = 0, max_s = 0;  ///< importLog + writeImport, wall
};
BenchImport benchImport(const std::string& study_path, long rows, int runs);

/// The cost of a user-defined strut effect (subsystems/user_effect.hpp) against the built-in
/// effect of the same form: damper_asymmetry, and "v < 0 ? (ratio - 1) * c * v : 0", each
/// evaluated `evaluations` times over a sweep of strut states (median of `runs`). Also checks that
/// the two agree at every state (max_abs_difference).
/// Then, inside the twin: the study's first assembly on `scenario` with each effect (ratio 2.2),
/// `runs` runs each after a warm-up, alternating: the median wall per run, and whether the two
/// traces are identical.
struct BenchUserEffect {
  long evaluations = 0;
  double builtin_ns = 0, user_ns = 0;  ///< median wall per evaluation
  double max_abs_difference = 0;       ///< [N]
  std::string scenario;
  double builtin_run_s = 0, user_run_s = 0;  ///< median wall per run
  long steps = 0;                            ///< integrator steps of the built-in run
  bool identical_traces = false;
};
BenchUserEffect benchUserEffect(const Study& study, const std::string& scenario, long evaluations, int runs);

}  // namespace dtwin
