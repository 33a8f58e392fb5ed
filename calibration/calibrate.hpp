#pragma once
// Calibration of one assembly against lab data (method.md §4): bounded multi-start SSE
// minimisation, feasible box, Latin-hypercube design simulated in parallel, two-block Griddy
// Gibbs, posterior summaries. Every stage is persisted in the assembly's output folder as it
// finishes, so a killed calibration rerun with the same inputs continues where it stopped and
// ends with identical results (design points are journalled one by one).
//
// Outputs in `out_dir` (docs/calibration.md describes every file):
//   optimum.json        every start of the optimiser and the optimum (stage 1)
//   box.json            the feasible box and its sweeps (stage 2)
//   design_journal.csv  design points as they finish (resume); design.csv the full table (stage 3)
//   posterior.csv       θ_1..θ_d, τ, design index per kept Gibbs iteration (stage 4)
//   summary.json        everything a script needs (see CalibrationResult::toJson)
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "calibration/feasible_box.hpp"
#include "calibration/gibbs.hpp"
#include "calibration/optimize.hpp"
#include "calibration/summary.hpp"
#include "twin/measurement.hpp"
#include "twin/provenance.hpp"
#include "twin/simulator.hpp"
#include "twin/study.hpp"

namespace dtwin::calib {

/// The SSE of one assembly against lab data: simulates the lab scenario (cut just after the last
/// measured time) for θ and sums (y − η(θ))² over every record of every repetition.
/// Thread-safe: each call takes a Simulator from an internal pool (one per concurrent caller).
class LabObjective {
 public:
  LabObjective(const Study& study, const AssemblySpec& assembly, const LabData& data, const std::string& scenario,
               const std::vector<EffectSetting>& extra_effects = {});
  ~LabObjective();
  LabObjective(const LabObjective&) = delete;
  LabObjective& operator=(const LabObjective&) = delete;

  /// Calibrated parameter names, bounds and (when known) truths, in study order.
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<double>& lower() const { return lower_; }
  const std::vector<double>& upper() const { return upper_; }
  /// Number of scalar residuals n.
  int dataCount() const { return static_cast<int>(y_.size()); }
  const Model& model() const { return *model_; }
  const ScenarioSpec& scenario() const { return scenario_; }

  /// SSE(θ); +inf when the simulation fails (counted in failures()).
  double sse(const std::vector<double>& theta) const;
  /// Model predictions at every record (same order as the lab data records); empty on failure.
  std::vector<double> predict(const std::vector<double>& theta) const;
  long failures() const;
  long evaluations() const;
  /// Median wall time of the simulations so far [s].
  double medianWallSeconds() const;

 private:
  struct Pool;
  std::shared_ptr<const Model> model_;
  ScenarioSpec scenario_;
  std::shared_ptr<const Road> road_;
  std::vector<std::string> names_;
  std::vector<double> lower_, upper_;
  std::vector<int> slots_;
  std::vector<double> base_values_;
  std::vector<double> y_;
  std::vector<std::pair<int, std::size_t>> where_;  ///< (channel column, output row) per record
  std::unique_ptr<Pool> pool_;
};

struct CalibrationOptions {
  int threads = 0;  ///< 0: all cores
  int optimizer_starts = 4;
  int lhs_points = 2000;
  int gibbs_iterations = 50000;
  int gibbs_burn_in = 15000;
  double tau_prior_a = 1e-3, tau_prior_b = 1e-3;
  std::uint64_t seed = 1;
  OptimizerOptions optimizer;
  FeasibleBoxOptions box;
  /// Recorded in summary.json, not part of the resume fingerprint.
  std::string command, data_path;
  /// The sizes (optimizer_starts, lhs_points, gibbs_iterations, gibbs_burn_in) and seed of a study.
  static CalibrationOptions fromStudy(const Study& study);
  void validate() const;
  /// What changes the numbers (the resume fingerprint includes it).
  nlohmann::json toJson() const;
};

/// Progress: stage name, points done, points in the stage.
using StageProgress = std::function<void(const std::string& stage, std::size_t done, std::size_t total)>;

struct CalibrationResult {
  std::string assembly, label;
  std::vector<std::string> names;
  std::vector<std::optional<double>> truth;
  int n_data = 0;
  Optimum optimum;
  FeasibleBox box;
  Eigen::MatrixXd design;   ///< lhs_points x d
  std::vector<double> sse;  ///< per design point (+inf: failed)
  long design_failures = 0;
  long resumed_points = 0;  ///< design points found in the journal
  GibbsChains chains;
  PosteriorSummary posterior;
  std::vector<std::pair<std::string, double>> stage_wall_s;
  double median_run_wall_s = 0.0;  ///< wall time of one simulation (median)
  nlohmann::json toJson() const;
};

/// Calibrates `assembly` against `data`, persisting every stage in `out_dir` (created) and
/// resuming from what is there. `fingerprint_extra` goes into the resume fingerprint (e.g. the
/// lab data's content hash) so a resume against different inputs is refused.
CalibrationResult calibrateAssembly(const Study& study, const AssemblySpec& assembly, const LabData& data,
                                    const std::string& scenario, const CalibrationOptions& options,
                                    const std::string& out_dir, const std::string& fingerprint_extra,
                                    const StageProgress& progress = {});

using ::dtwin::fnv1a64;  // twin/provenance.hpp

}  // namespace dtwin::calib
