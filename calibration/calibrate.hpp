#pragma once
// Calibration of one assembly against lab data (docs/method.md §4): bounded multi-start SSE
// minimisation, the region (the joint 1 % contour by default, or the paper's one-at-a-time box),
// a design simulated in parallel (a Latin hypercube, then adaptive rounds where the posterior
// lies), the two-block Griddy Gibbs with design weights, posterior summaries. Every stage is
// persisted in the assembly's output folder as it finishes, so a killed calibration rerun with the
// same inputs continues where it stopped and ends with identical results (design points are
// journalled one by one). In calibration_run.cpp and calibration_run_intervals.cpp each stage is
// one method of CalibrationRun, and calibrateAssembly lists them in order: objective, optimum,
// region, design, profile, sampler, summary.
//
// Outputs in `out_dir` (docs/calibration.md describes every file):
//   optimum.json        every start of the optimiser and the optimum (stage 1)
//   box.json            the region (joint: Gauss–Newton axes and sweeps; paper: the box) (stage 2)
//   design_journal.csv  design points as they finish (resume); design.csv the full table with
//                       each point's round and log design weight (stage 3)
//   profile.json        the profile-likelihood intervals (stage 4)
//   posterior.csv       θ_1..θ_d, τ, design index per kept Gibbs iteration (stage 5)
//   summary.json        everything a script needs (see CalibrationResult::toJson)
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "calibration/adaptive_design.hpp"
#include "calibration/bounds.hpp"
#include "calibration/feasible_box.hpp"
#include "calibration/gibbs.hpp"
#include "calibration/optimize.hpp"
#include "calibration/profile.hpp"
#include "calibration/region.hpp"
#include "calibration/summary.hpp"
#include "common/distributed.hpp"
#include "common/progress.hpp"
#include "io/measurement.hpp"
#include "io/provenance.hpp"
#include "io/study.hpp"
#include "twin/simulator.hpp"

namespace dtwin::calib {

struct SubspaceJacobian;  // subspace_lm.hpp

/// One set of measurements tied to the scenario it was measured on (a file of the tidy lab
/// layout: several channels, any times inside the scenario (off the output grid the run adds
/// them as extra output times), any number of repetitions).
struct DataSet {
  std::string name;      ///< names the data in errors and reports (e.g. the file path)
  std::string scenario;  ///< a scenario of the study
  LabData data;
  /// The seed of the scenario's random road the data were measured on (e.g. from the data's
  /// sidecar); unset: the study's seed.
  std::optional<std::uint64_t> road_seed = std::nullopt;
};

/// What a calibration adds to the study's [[calibrated]] parameters: effects installed in the
/// assembly (their values fixed, e.g. shape parameters), effect parameters calibrated along with
/// θ (bounds: the effect's prior range), and weights of the channels in the SSE. Empty: the plain
/// calibration of docs/method.md §4 (bit for bit as before these existed).
/// A model of how the logger distorted some channels (subsystems/sensor.hpp, sensorModelKinds()):
/// applied to the predictions of those channels, its parameter calibrated as
/// "<name>.<parameter>" (an entry of extra_calibrated).
struct SensorModelSetting {
  std::string name;                   ///< e.g. "lowpass:hub_force"
  std::string kind;                   ///< lowpass | lowpass2 | gain | delay
  std::vector<std::string> channels;  ///< the channels it distorts
};

struct CalibrationSetup {
  std::vector<EffectSetting> extra_effects;
  std::vector<CalibratedParameter> extra_calibrated;
  /// Fixed vehicle values made run parameters (AssemblySpec::freed), calibrated by the entry of
  /// extra_calibrated of the same name.
  std::vector<std::string> freed;
  std::vector<SensorModelSetting> sensor_models;
  /// Subsystem options that replace the assembly's ((subsystem, option), e.g. ("tire", "hub"):
  /// the road enters at the hub). A calibrated value the new option lacks is left out
  /// (LabObjective::leftOut).
  std::vector<std::pair<std::string, std::string>> options;
  /// Bounds that replace the study's for a calibrated value (name -> (lower, upper)): a range
  /// widened toward its physical limit (docs/calibration.md, "Values on their bounds").
  std::map<std::string, std::pair<double, double>> bounds;
  /// SSE = Σ w_c (y − η)², w_c = channel_weights[channel] (1 when absent). With w_c = 1/σ_c² the
  /// SSE is a χ² in standard units, so channels of different units can be fitted together.
  std::map<std::string, double> channel_weights;
  bool empty() const {
    return extra_effects.empty() && extra_calibrated.empty() && channel_weights.empty() &&
           freed.empty() && sensor_models.empty() && options.empty() && bounds.empty();
  }
  /// Everything that changes the numbers (part of the resume fingerprint when not empty).
  nlohmann::json toJson() const;
  /// Inverse of toJson (reads summary.json's "setup"); null gives an empty setup.
  static CalibrationSetup fromJson(const nlohmann::json& j);
};

/// The SSE of one assembly against measurements: simulates each data set's scenario (cut just
/// after its last measured time) for θ and sums w_c (y − η(θ))² over every record of every
/// repetition of every data set. θ is the study's calibrated parameters, then the setup's
/// extra_calibrated ones.
/// Thread-safe: each call takes a Simulator from an internal pool (one per concurrent caller).
class LabObjective {
 public:
  LabObjective(const Study& study, const AssemblySpec& assembly, const LabData& data,
               const std::string& scenario, const std::vector<EffectSetting>& extra_effects = {});
  LabObjective(const Study& study, const AssemblySpec& assembly, const std::vector<DataSet>& data,
               const CalibrationSetup& setup);
  ~LabObjective();
  LabObjective(const LabObjective&) = delete;
  LabObjective& operator=(const LabObjective&) = delete;

  /// Calibrated parameter names, bounds and (when known) truths, in study order then setup order.
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<double>& lower() const { return lower_; }
  const std::vector<double>& upper() const { return upper_; }
  const std::vector<std::optional<double>>& truths() const { return truths_; }
  /// The study's calibrated values this assembly does not have (Model::lacksOptionParameter: the
  /// tire's stiffness and damping when the road enters at the hub), left out of θ.
  const std::vector<std::string>& leftOut() const { return left_out_; }
  /// Number of scalar residuals n.
  int dataCount() const { return static_cast<int>(y_.size()); }
  const Model& model() const { return *model_; }
  std::shared_ptr<const Model> modelPtr() const { return model_; }
  /// The scenario of the first data set (cut after its last measured time).
  const ScenarioSpec& scenario() const { return sets_.front().scenario; }
  /// The data sets' scenarios, cut after their last measured time.
  std::vector<ScenarioSpec> scenarios() const;
  /// Measured values, their SSE weights and the data set each record belongs to, in record order
  /// (data set by data set, each in its file's order).
  const std::vector<double>& measured() const { return y_; }
  const std::vector<double>& weights() const { return w_; }
  const std::vector<int>& dataSetOf() const { return set_of_; }
  /// Per record, in the same order: its time [s] and its repetition.
  const std::vector<double>& times() const { return t_; }
  const std::vector<long>& repetitions() const { return rep_; }

  /// SSE(θ); +inf when a simulation fails (counted in failures()).
  double sse(const std::vector<double>& theta) const;
  /// Model predictions at every record (same order as measured()); empty on failure.
  std::vector<double> predict(const std::vector<double>& theta) const;
  /// Weighted residuals sqrt(w)(η(θ) − y), so SSE = |r|²; empty on failure.
  std::vector<double> residuals(const std::vector<double>& theta) const;
  /// The full traces of each data set's run at θ (empty vector on failure).
  std::vector<Trace> traces(const std::vector<double>& theta) const;
  /// Each data set's run at θ, with its output at the data's off-grid times (empty on failure).
  std::vector<RunResult> runs(const std::vector<double>& theta) const;
  /// Channel `column` (Simulator::channels() order) of `run` (the run of record's data set) at
  /// record `record`'s time: its output-grid row, or its row of run.samples when off the grid.
  double read(const RunResult& run, std::size_t record, std::size_t column) const;
  /// The run vector (model().runParameterNames() layout) θ maps to.
  std::vector<double> runValues(const std::vector<double>& theta) const;
  /// Freezes the integrator's steps (docs/calibration.md, "A smooth objective"): each data set's
  /// run at θ is made adaptively and its steps recorded; every later evaluation replays them, so
  /// the SSE is a smooth function of θ. Returns false (and leaves the steps adaptive) when a run
  /// at θ fails, or when the study's integrator is not rosenbrock. Not thread-safe: call it
  /// between stages, while no evaluation runs.
  /// `accuracy` > 0: the steps are chosen at that accuracy instead of the study's.
  bool freezeSteps(const std::vector<double>& theta, double accuracy = 0.0);
  /// Back to adaptive steps.
  void thawSteps() {
    plans_.clear();
    frozen_at_.clear();
    frozen_accuracy_ = 0.0;
  }
  /// The accuracy the frozen steps were chosen at (0 when not frozen).
  double stepsFrozenAccuracy() const { return frozen_accuracy_; }
  /// Whether the steps are frozen, and the θ they were frozen at (empty when not).
  bool stepsFrozen() const { return !plans_.empty(); }
  const std::vector<double>& stepsFrozenAt() const { return frozen_at_; }
  /// Steps per data set of the frozen sequences (empty when not frozen).
  std::vector<std::size_t> frozenStepCounts() const;
  long failures() const;
  long evaluations() const;
  /// Median wall time of the simulations so far [s] (one data set's run).
  double medianWallSeconds() const;

 private:
  struct Pool;
  struct Set {
    ScenarioSpec scenario;
    /// The same run writing only the records' times, every one a sample time (a grid time as
    /// r / rate, read bit for bit as its grid row): what predict() reads
    /// (ScenarioSpec::grid_output).
    ScenarioSpec sampled;
    std::shared_ptr<const Road> road;
    std::size_t first = 0, count = 0;  ///< its records in y_
  };
  void addDataSet(const Study& study, const DataSet& ds, bool single);
  /// Every data set's run at θ; `sampled`: the runs of Set::sampled (no output grid).
  std::vector<RunResult> runAll(const std::vector<double>& theta, bool sampled = false) const;
  /// Whether predict() may read the sampled runs: no sensor model (it distorts the grid) and no
  /// filtered sensor (its filter runs on the grid).
  bool sampledPredictions() const;
  std::shared_ptr<const Model> model_;
  std::vector<Set> sets_;
  std::vector<std::string> names_, left_out_;
  std::vector<double> lower_, upper_;
  std::vector<std::optional<double>> truths_;
  std::vector<int> slots_;
  std::vector<double> base_values_;
  std::vector<double> y_, w_;
  std::vector<int> set_of_;
  struct RecordRead {
    int column = -1;         ///< channel column
    bool at_sample = false;  ///< off the output grid: a row of RunResult::samples
    std::size_t index = 0;   ///< the row (of the grid, or of the samples)
  };
  std::vector<RecordRead> where_;         ///< per record
  std::vector<std::size_t> sampled_row_;  ///< per record: its row of the sampled run's samples
  std::vector<double> t_;                 ///< per record: its time [s]
  std::vector<long> rep_;                 ///< per record: its repetition
  /// The setup's sensor models: the channel columns each distorts and its parameter's index in θ.
  struct SensorModelUse {
    std::string kind;
    std::vector<int> columns;
    std::size_t theta_index = 0;
  };
  std::vector<SensorModelUse> sensor_models_;
  double rate_hz_ = 0.0;  ///< the output grid's rate
  /// Applies the sensor models at θ to eta (the predictions of every record).
  void distort(const std::vector<double>& theta, const std::vector<RunResult>& runs,
               std::vector<double>& eta) const;
  std::unique_ptr<Pool> pool_;
  std::vector<std::shared_ptr<const StepPlan>> plans_;  ///< per data set, when the steps are frozen
  std::vector<double> frozen_at_;
  double frozen_accuracy_ = 0.0;
};

/// The settings of one calibration. The sizes default to the paper's (calibration/common.hpp);
/// a study's are taken by fromStudy.
struct CalibrationOptions {
  int threads = 0;  ///< >= 0; 0: all cores
  const Distributed* processes =
      nullptr;  ///< the process context (common/distributed.hpp); nullptr: this process alone
  int optimizer_starts = kDefaultOptimizerStarts;  ///< >= 1
  int lhs_points = kDefaultLhsPoints;              ///< the first Latin hypercube, >= 2
  int gibbs_iterations = kDefaultGibbsIterations;  ///< >= 1, burn-in included
  int gibbs_burn_in = kDefaultGibbsBurnIn;         ///< in [0, gibbs_iterations)
  double tau_prior_a = kDefaultTauPrior,
         tau_prior_b = kDefaultTauPrior;  ///< Gamma(a, b) prior of τ, finite, >= 0
  std::uint64_t seed = 1;
  OptimizerOptions optimizer;
  /// "joint" (default): the region holds the joint 1 % contour (region.hpp); "paper": the
  /// one-at-a-time box of docs/method.md §4 step 2.
  std::string region = "joint";
  FeasibleBoxOptions box;    ///< the paper's box sweeps
  JointRegionOptions joint;  ///< the joint region
  /// Rounds after the first Latin hypercube (adaptive_design.hpp); first_points, seed and the τ
  /// prior are taken from lhs_points, seed and tau_prior_* when the calibration runs.
  AdaptiveDesignOptions design;
  /// The profile-likelihood intervals (profile.hpp), computed after the design.
  ProfileOptions profile;
  /// Which 95 % interval summaries print as ci95: "profile" (default) or "posterior" (the
  /// posterior's central interval, the paper's). Both are always in summary.json.
  std::string interval = "profile";
  /// "frozen" (default): the objective replays one step sequence per stage (LabObjective::
  /// freezeSteps): the box centre's (or the first extra start's) for the screening and the starts,
  /// then the best start's for the final Levenberg–Marquardt polish and every later stage, so the
  /// SSE the optimum, the region, the design and the profile see is smooth in θ. "adaptive": each
  /// run chooses its steps (the SSE of dense, quiet data is then jagged). docs/calibration.md.
  std::string steps = "frozen";
  /// Extra optimiser starts (physical units, θ order), run before the usual ones; e.g. a nested
  /// model's optimum with the added parameters at their off values, so the larger model's
  /// optimum is never worse than the nested one's. Part of the fingerprint when not empty.
  std::vector<std::vector<double>> extra_starts;
  /// > 0: after the starts, one more local run from the best point with this initial step
  /// (scaled units, at most 0.5), to polish a sharp minimum (dense data). 0: off (docs/method.md §4
  /// as written).
  double polish_step = 0.0;
  /// Recorded in summary.json, not part of the resume fingerprint.
  std::string command, data_path;
  /// The sizes (optimizer_starts, lhs_points, gibbs_iterations, gibbs_burn_in), the [calibration]
  /// settings (region, design, rounds) and the seed of a study.
  static CalibrationOptions fromStudy(const Study& study);
  /// `design` with first_points = lhs_points, round_points resolved (0: lhs_points), the τ prior
  /// and the seed.
  AdaptiveDesignOptions designOptions() const;
  /// The Gibbs sampler's options: iterations, burn-in, the τ prior and the seed.
  GibbsOptions gibbsOptions() const;
  /// Throws InputError whose where() is "calibration.<field>" (common/validate.hpp), or that of
  /// the nested options ("optimizer.<field>", "design.<field>", ...). calibrateAssembly calls it.
  void validate() const;
  /// What changes the numbers (the resume fingerprint includes it).
  nlohmann::json toJson() const;
};

/// Progress: stage name, points done, points in the stage.
using ::dtwin::StageProgress;  // common/progress.hpp

/// Is the integrator accurate enough for these data? (docs/calibration.md, step 7.) The SSE is
/// re-evaluated at the optimum with adaptive steps at the study's accuracy divided by 10.
///
/// Adaptive steps: each simulation's integrator error changes in jumps with θ (the steps change),
/// so it puts a jitter of about 2 ‖e‖ ‖δ‖ / √n into the SSE (e: the weighted residuals, δ: the
/// weighted change of the predictions); jitter = max(|sse − sse_check|, that).
///
/// Frozen steps: the SSE is smooth by construction and its error a smooth bias, so both are
/// measured instead (applyProbes), along each parameter's axis at five points a tenth of its
/// profile half-width apart: the roughness, the largest departure of the SSE from its
/// least-squares quadratic along an axis; and the optimum shift, how far the integrator's bias
/// moves the optimum in SSE units (integratorOptimumShift); jitter = max(roughness, shift), the
/// shift counted only when it stands above what the roughness alone would make it (4 ×
/// shift_floor).
///
/// When the jitter reaches half the 95 % intervals' threshold above the minimum (c s²), the
/// optimum and the intervals follow the integrator rather than the data: `ok` is false and
/// `message` says what to tighten.
struct IntegratorCheck {
  std::string steps = "adaptive";  ///< how the calibration's runs chose their steps
  /// Frozen steps: whose probes gave the roughness and shift: "own", or "step choice" (the step
  /// choice's last probe, made at this optimum and accuracy with the same probe steps).
  std::string probes = "own";
  double accuracy = 0.0, accuracy_check = 0.0;  ///< the study's, and the check's (one tenth)
  double sse = 0.0, sse_check = 0.0;            ///< at the optimum, with each
  double prediction_change = 0.0;  ///< ‖δ‖ (weighted: in noise sd when the weights are 1/σ²)
  double roughness = 0.0;          ///< frozen steps: the SSE's largest departure from a quadratic
  double optimum_shift = 0.0;      ///< frozen steps: ½ gᵀ H⁺ g (integratorOptimumShift)
  /// Frozen steps: the shift the roughness alone would show (gradient errors roughness/h per
  /// axis); a shift below 4 times it is not resolved and does not count in the jitter.
  double shift_floor = 0.0;
  double jitter = 0.0;     ///< what moves the optimum and the intervals (see above)
  double threshold = 0.0;  ///< the intervals' threshold above the minimum, c s²
  bool ok = true;
  std::string message;  ///< empty when ok
  nlohmann::json toJson() const;
};

/// The check from the predictions at the optimum with the study's accuracy (`eta`) and a tenth of
/// it (`eta_fine`), the data `y`, their weights `w` and the intervals' threshold above the minimum.
IntegratorCheck assessIntegrator(const std::vector<double>& eta,
                                 const std::vector<double>& eta_fine, const std::vector<double>& y,
                                 const std::vector<double>& w, double accuracy, double threshold);

/// The largest absolute residual of the least-squares quadratic through (x_i, f_i) (at least 4
/// points): 0 for a quadratic, about the size of a jump for a jagged f.
double quadraticRoughness(const std::vector<double>& x, const std::vector<double>& f);

/// How much a smooth bias b(θ) of the SSE (here the integrator's: SSE − SSE_fine) moves the
/// optimum, in SSE units: ½ gᵀ H⁺ g, with g = ∇b at the optimum and H = 2 JᵀJ the Gauss–Newton
/// Hessian of the SSE (J: the weighted residuals' Jacobian, n × d, in the same coordinates as g;
/// H⁺ its pseudo-inverse). For residuals r + δ of a linear model it is ‖P δ‖², P the projection
/// onto J's columns: the exact model's SSE at the biased optimum exceeds its minimum by this much.
double integratorOptimumShift(const Eigen::MatrixXd& J, const Eigen::VectorXd& g);

/// A frozen-steps probe's figures (probeBias): the roughness, the optimum shift and its floor.
struct ProbeFigures {
  double roughness = 0.0, optimum_shift = 0.0, shift_floor = 0.0;
};

/// The figures of the step choice's last try (`last`, an entry of optimum.json
/// steps.accuracy_choice) for the integrator check at `theta` with probe steps `h` (scaled by the
/// bounds' range) and frozen steps at `accuracy`: when the try was made at that accuracy, kept, at
/// this optimum (every parameter within a hundredth of its probe step) and with probe steps within
/// a factor 1.5 of `h`, the check's own probes would measure the same (a smooth bias's gradient and
/// the SSE's jumps do not change with the step over that range; a tenfold step does change the
/// roughness). Otherwise nullopt.
std::optional<ProbeFigures> takeOverProbe(const nlohmann::json& last,
                                          const std::vector<double>& theta,
                                          const std::vector<double>& h, double accuracy,
                                          const std::vector<double>& lower,
                                          const std::vector<double>& upper);

/// Turns an adaptive-steps check into the frozen-steps one: sets roughness, optimum_shift and
/// shift_floor, the jitter (the roughness, or the shift when it exceeds 4 × shift_floor), `ok` and
/// the message.
void applyProbes(IntegratorCheck& c, double roughness, double optimum_shift,
                 double shift_floor = 0.0);

/// Probe steps for probeBias from a residual Jacobian J (n x d, scaled units): a tenth of each
/// parameter's Gauss–Newton half-width √(threshold · (JᵀJ)⁺_kk), in [1e-4, 1e-2] (1e-2 when J is
/// empty, not finite or the threshold not positive), the steps the final integrator check takes
/// from the profile's half-widths.
std::vector<double> probeStepsFromJacobian(const Eigen::MatrixXd& J, double threshold);

struct CalibrationResult {
  std::string assembly, label;
  std::vector<std::string> names;
  std::vector<std::string> units;    ///< per name ("" when not stated)
  std::vector<double> lower, upper;  ///< the bounds calibrated within
  /// The study's calibrated values this assembly lacks (LabObjective::leftOut), left out of θ.
  std::vector<std::string> left_out;
  /// Values on their bounds, and values the data do not determine (bounds.hpp): findings.
  std::vector<BoundFinding> bounds;
  std::vector<std::optional<double>> truth;
  int n_data = 0;
  Optimum optimum;
  Region region;                     ///< what the design covers (stage 2)
  FeasibleBox box;                   ///< the paper's box and its sweeps (region = "paper" only)
  AdaptiveDesign rounds;             ///< the design's rounds, weights and diagnostics (stage 3)
  ProfileIntervals profile;          ///< the profile-likelihood intervals (stage 4)
  std::string interval = "profile";  ///< which interval ci95 is
  Eigen::MatrixXd design;            ///< N x d, every round's points
  std::vector<double> sse;           ///< per design point (+inf: failed)
  long design_failures = 0;
  long resumed_points = 0;  ///< design points found in the journal
  GibbsChains chains;
  PosteriorSummary posterior;
  IntegratorCheck integrator;  ///< stage 6: is the integrator accurate enough for these data?
  std::vector<std::pair<std::string, double>> stage_wall_s;
  double median_run_wall_s = 0.0;  ///< wall time of one simulation (median)
  std::vector<std::string>
      warnings;  ///< besides the design's (e.g. steps that could not be frozen)
  nlohmann::json toJson() const;
};

/// Calibrates `assembly` against `data`, persisting every stage in `out_dir` (created) and
/// resuming from what is there. `fingerprint_extra` goes into the resume fingerprint (e.g. the
/// lab data's content hash) so a resume against different inputs is refused.
CalibrationResult calibrateAssembly(const Study& study, const AssemblySpec& assembly,
                                    const LabData& data, const std::string& scenario,
                                    const CalibrationOptions& options, const std::string& out_dir,
                                    const std::string& fingerprint_extra,
                                    const StageProgress& progress = {});

/// The general form: several data sets (each on its own scenario) and a setup (extra effects,
/// extra calibrated parameters, channel weights). With one data set and an empty setup it is the
/// call above, bit for bit (same files, same fingerprint). summary.json records the setup and the
/// data sets so the calibration can be rebuilt from its folder (readCalibrationFolder, folder.hpp).
CalibrationResult calibrateAssembly(const Study& study, const AssemblySpec& assembly,
                                    const std::vector<DataSet>& data, const CalibrationSetup& setup,
                                    const CalibrationOptions& options, const std::string& out_dir,
                                    const std::string& fingerprint_extra,
                                    const StageProgress& progress = {});

/// Stage 1 of calibrateAssembly alone (the screening, the optimiser's starts and the polish):
/// the result holds the optimum (and the steps it was found with), nothing of the later stages
/// (no region, design, profile, posterior or integrator check). optimum.json is written in
/// `out_dir`, so a calibrateAssembly with the same inputs and options later resumes from it and
/// runs only the stages after it. twin diagnose uses it to weigh a candidate before deciding
/// whether its intervals are worth computing (docs/diagnosis.md).
CalibrationResult calibrateOptimum(const Study& study, const AssemblySpec& assembly,
                                   const std::vector<DataSet>& data, const CalibrationSetup& setup,
                                   const CalibrationOptions& options, const std::string& out_dir,
                                   const std::string& fingerprint_extra,
                                   const StageProgress& progress = {});

/// The finite-difference step (scaled units) of polishLeastSquares used by calibrateAssembly's
/// polish: well above the integrator's noise in the residuals (see calibrate.cpp).
inline constexpr double kPolishStep = 1e-2;
/// The same with frozen steps (CalibrationOptions::steps): the SSE is smooth, so a finer step
/// gives a truer Jacobian.
inline constexpr double kPolishStepFrozen = 1e-3;

/// How polishLeastSquares differentiates and when it stops.
struct PolishOptions {
  int threads = 1;         ///< workers for the runs of one difference Jacobian
  double h = kPolishStep;  ///< difference step, scaled units
  double rel_gain =
      1e-9;  ///< converged when a step from a fresh Jacobian gains less than rel_gain × SSE
  /// Forward differences (d runs, not 2d): for a start far from the optimum on frozen steps, where
  /// the Jacobian only has to point downhill and a later polish with central differences settles.
  bool forward = false;
  /// With a Jacobian (n x d, scaled units), the first iteration's, and the last one is left in it
  /// (subspace_lm.hpp): a second polish from nearly the same point (e.g. on steps chosen at a
  /// tighter accuracy) skips the first differences, and the integrator probes take their steps from
  /// it.
  SubspaceJacobian* carried = nullptr;
};

/// Levenberg–Marquardt on the weighted residuals sqrt(w) (η(θ) − y) of `obj` from `theta0`, in the
/// scaled coordinates [0,1]^d: central (or forward) differences of step h, then Broyden updates
/// after every trial point, fresh differences when the carried Jacobian finds no better point
/// (minimiseOnSubspace); an active set at the box's faces; at most 30 iterations, and it stops when
/// a step from a fresh Jacobian gains less than rel_gain × SSE. Returns the best point seen
/// (status "LM_POLISH"); sse is infinite when the run at theta0 fails.
StartResult polishLeastSquares(const LabObjective& obj, const std::vector<double>& theta0,
                               const PolishOptions& options = {});

using ::dtwin::fnv1a64;  // io/provenance.hpp

}  // namespace dtwin::calib
