#pragma once
// Speed measurement of the twin: wall time per run, median over repeated runs.
#include <functional>
#include <string>
#include <vector>

#include "io/study.hpp"
#include "study/hand_ode.hpp"

namespace dtwin {

struct BenchRow {
  std::string assembly, label, scenario;
  double median_wall_s = 0, min_wall_s = 0, max_wall_s = 0;
  double simulated_s = 0;
  double real_time_factor = 0;  ///< simulated seconds per wall second
  long steps = 0;
  double peak_fl_N = 0;            ///< peak front-left hub force of the run
  double reference_peak_fl_N = 0;  ///< same at tight tolerance (bump scenarios; 0 if not computed)
  bool ok = true;
};

/// Runs `scenario` `runs` times (after one warm-up) for the assembly and returns the figures.
/// If `reference` is true, also runs once at tight tolerance (accuracy 1e-8, steps <= 2.5e-5 s
/// near obstacles) to compare the peak front-left force.
BenchRow benchAssembly(const Study& study, const AssemblySpec& a, const ScenarioSpec& scenario,
                       int runs, bool reference);

/// `twin import` on a synthetic logger CSV of `rows` rows at 100 Hz (time with clock jitter,
/// speed in km/h, left and right road heights in mm, two accelerometers in g, two unused
/// columns), read, converted and written into a fresh temporary folder `runs` times; then the same
/// log written as MF4 (plain and compressed) into a temporary folder and imported the same way.
struct BenchImport {
  long rows = 0;
  double bytes = 0;                           ///< size of the log
  double median_s = 0, min_s = 0, max_s = 0;  ///< importLog + writeImport, wall
  /// The same log as an MF4 file (mdflib's writer, one channel group, 64-bit floats; the counter
  /// and the note left out), plain and with its data in DZ blocks: its size and the same timing.
  double mf4_bytes = 0, mf4_median_s = 0, mf4_min_s = 0, mf4_max_s = 0;
  double mf4z_bytes = 0, mf4z_median_s = 0, mf4z_min_s = 0, mf4z_max_s = 0;
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
BenchUserEffect benchUserEffect(const Study& study, const std::string& scenario, long evaluations,
                                int runs);

/// `twin bench --hand-ode`: the study's simulator and the hand ODE on `scenario` for assembly `a`,
/// `runs` timed runs each (after one warm-up), alternating, medians reported.
struct HandOdeBench {
  std::string assembly, label, scenario;
  int runs = 0;
  double accuracy = 0;
  double simbody_median_s = 0, simbody_min_s = 0, simbody_max_s = 0;
  /// The simulator with its output grid at 0.1 Hz: equilibrium and integration without the
  /// 1 kHz reconstruction of every output channel (median of `runs`).
  double simbody_integration_s = 0;
  long simbody_steps = 0, simbody_attempts = 0, simbody_jacobians = 0;
  /// 1 + 4 accepted + 3 rejected steps + 14 per Jacobian (the integrator's cost model; the
  /// Jacobians counted from the run's recorded step plan).
  long simbody_evaluations = 0;
  double hand_median_s = 0, hand_min_s = 0, hand_max_s = 0;
  double hand_integration_s = 0;  ///< the hand ODE with its output grid at 0.1 Hz (median)
  long hand_steps = 0, hand_attempts = 0, hand_evaluations = 0, hand_jacobians = 0;
  double hand_rhs_s = 0;  ///< wall time of one hand right-hand side evaluation alone (a loop)
  double peak_fl_N = 0;   ///< peak front-left hub force of the Simbody run
  double max_diff_fl_N = 0, max_diff_time_s = 0;  ///< max |Simbody - hand| over the output grid
  /// The same comparison with both integrated at accuracy 1e-8 (steps <= 2.5e-5 s at the obstacle):
  /// what remains is the difference between the models, not between the integration errors.
  double tight_max_diff_fl_N = 0;
  double ratio() const { return simbody_median_s / hand_median_s; }
};
/// InputError for an assembly the hand ODE does not model (HandOde), or `runs` < 1.
HandOdeBench benchHandOde(const Study& study, const AssemblySpec& a, const ScenarioSpec& scenario,
                          int runs);

/// Where a call puts its text as it goes: a piece of output, its line ends included.
using TextSink = std::function<void(const std::string& text)>;

/// What `twin bench` times: by default the bump and the rough road of each assembly (or those of
/// `assemblies`) as a table; instead, when set, `twin import` on a synthetic log (import_rows),
/// a user-defined effect against the built-in one (user_effect), the hand ODE (hand_ode) or a
/// synthesis's accumulation (accumulation).
struct BenchRequest {
  std::string study;                    ///< the study file
  int runs = 5;                         ///< timed runs per case (after one warm-up)
  bool markdown = false;                ///< the tables in Markdown (docs/performance.md)
  std::vector<std::string> assemblies;  ///< empty: every assembly (hand ODE: M3; else the first)
  long import_rows = 0;                 ///< > 0: rows of the synthetic log `twin import` reads
  long user_effect = 0;                 ///< > 0: evaluations of the strut effects
  std::string scenario = "field";       ///< user_effect: the scenario of the whole runs
  bool hand_ode = false;                ///< the bump run against the hand-written 7-DOF ODE
  bool accumulation = false;            ///< a synthesis's costs and its modelled wall on K ranks
  double link_gb_per_s = 10.0;          ///< accumulation: the bandwidth between ranks [GB/s]
};

/// `twin bench` as one call: runs what `request` asks and hands its text over as it goes: `print`
/// the tables (the program's standard output), `note` what is being timed (its standard error).
/// InputError for a study or request it cannot time.
void runBench(const BenchRequest& request, const TextSink& print, const TextSink& note);

}  // namespace dtwin
