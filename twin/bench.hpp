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

}  // namespace dtwin
