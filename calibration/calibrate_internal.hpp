// Private to calibration/ (not installed): what the files of calibrateAssembly share, the JSON of
// the stage files (result_json.cpp), readStage and secondsSince (calibration_run.cpp) and
// CalibrationRun, one calibration run, whose stages are in calibration_run.cpp and
// calibration_run_intervals.cpp.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "calibration/bounds.hpp"
#include "calibration/calibrate.hpp"
#include "calibration/correlated.hpp"
#include "calibration/design_journal.hpp"
#include "calibration/subspace_lm.hpp"
#include "common/distributed.hpp"

namespace fs = std::filesystem;

namespace dtwin::calib {

// ------------------------------------------------------------------ stage files (result_json.cpp)
nlohmann::json optimumJson(const Optimum& o);
Optimum optimumFrom(const nlohmann::json& j);
nlohmann::json boxJson(const FeasibleBox& b);
FeasibleBox boxFrom(const nlohmann::json& j);
/// box.json's "gauss_newton" of a joint region: the Gauss–Newton model, the sweeps along its
/// axes and the ridge traces.
nlohmann::json gaussNewtonJson(const JointRegionPlan& plan, const std::vector<RaySweep>& sweeps,
                               const std::vector<RidgeTrace>& traces);

// ------------------------------------------------------------------ calibration_run.cpp
/// Reads a stage file when it exists and carries `fingerprint`; null otherwise. Under MPI the
/// root reads it and every rank decides on the same bytes. The stage files are written sealed
/// (common/checksum.hpp sealJson): one that is not JSON or fails its checksum was damaged on disk;
/// the root sets it aside (<file>.corrupt, one note on stderr) and null is returned, so the stage
/// is redone. A file of another calibration (its fingerprint differs) is an InputError.
nlohmann::json readStage(const Distributed* processes, const fs::path& p,
                         const std::string& fingerprint);
double secondsSince(std::chrono::steady_clock::time_point t0);

// ------------------------------------------------------------------ CalibrationRun
/// One calibration of one assembly (docs/method.md §4; docs/calibration.md lists its files): the
/// inputs, the state its stages share and the result they fill in, one method per stage, run in
/// order by calibrateAssembly. A stage that takes long persists what it found in the output folder
/// under the resume fingerprint as it finishes (readStage, the design journal) and reads it back
/// on a rerun with the same inputs. Starts, sweeps and design points are spread over the MPI ranks
/// and the threads of each rank (distributedMap: task i on rank i % size, results by index on
/// every rank); only the root writes files (rootWrites).
class CalibrationRun {
 public:
  CalibrationRun(const Study& study, const AssemblySpec& assembly, const std::vector<DataSet>& data,
                 const CalibrationSetup& setup, const CalibrationOptions& options,
                 const std::string& out_dir, const std::string& fingerprint_extra,
                 const StageProgress& progress)
      : study_(study),
        assembly_(assembly),
        data_(data),
        setup_(setup),
        options_(options),
        out_dir_(out_dir),
        fingerprint_extra_(fingerprint_extra),
        progress_(progress),
        t_all_(Clock::now()) {}

  void objective();
  void optimum();
  void region();
  void design();
  void profile();
  void sampler();
  void integratorCheck();
  /// What probeBias measured: ok false when a run failed.
  struct BiasProbe {
    bool ok = false;
    double roughness = 0.0, shift = 0.0;
    /// The shift central differences would show from the roughness alone (gradient errors of
    /// roughness_k / h_k per axis): below it a shift is not resolved. 0 with three points.
    double shift_floor = 0.0;
  };
  LabObjective fineObjective(double accuracy) const;
  BiasProbe probeBias(const LabObjective& fine, const std::vector<double>& theta,
                      const std::vector<double>& h, bool five, const std::string& stage) const;
  void chooseStepAccuracy();
  void summary();
  CalibrationResult take() { return std::move(res_); }
  /// After optimum() alone: the result with the optimum, the stages' wall times and the run cost.
  CalibrationResult takeOptimum() {
    res_.stage_wall_s.push_back({"total", secondsSince(t_all_)});
    res_.median_run_wall_s = objective_->medianWallSeconds();
    findBoundFindings();
    return take();
  }
  /// res_.bounds from what the stages so far found (the optimum; the intervals and the posterior
  /// when they exist).
  void findBoundFindings() {
    BoundInputs in;
    in.names = res_.names;
    in.units = res_.units;
    in.lower = res_.lower;
    in.upper = res_.upper;
    in.optimum = res_.optimum.theta;
    if (res_.posterior.parameters.size() == d_) {
      for (std::size_t k = 0; k < d_; ++k) {
        const bool prof = res_.interval == "profile" && k < res_.profile.lower.size();
        in.interval_lo.push_back(prof ? res_.profile.lower[k] : res_.posterior.parameters[k].q025);
        in.interval_hi.push_back(prof ? res_.profile.upper[k] : res_.posterior.parameters[k].q975);
      }
      in.design = &res_.design;
      in.draws = res_.chains.index;
    }
    in.limit_lower = limit_lower_;
    in.limit_upper = limit_upper_;
    in.limit_basis = limit_basis_;
    res_.bounds = findBounds(in);
  }

 private:
  using Clock = std::chrono::steady_clock;
  using ResumedPoints =
      std::map<long, std::pair<std::vector<double>, double>>;  ///< design index -> (θ, SSE)

  void report(const std::string& stage, std::size_t done, std::size_t total) const {
    if (progress_) progress_(stage, done, total);
  }
  fs::path file(const char* name) const { return fs::path(out_dir_) / name; }
  std::string resumeFingerprint() const;
  std::vector<std::vector<double>> optimiserStarts(nlohmann::json& screening) const;
  void polish(std::vector<StartResult>& starts) const;
  void polishOnOwnSteps();
  void polishFrozen();
  nlohmann::json stepsJson() const;
  BoxProblem boxProblem() const;
  void paperBox(const BoxProblem& bp, nlohmann::json& stage);
  void jointRegion(const BoxProblem& bp, nlohmann::json& stage);
  ResumedPoints openJournal(const std::string& journal_path,
                            std::unique_ptr<DesignJournal>& journal) const;
  std::vector<double> evaluateRound(const Eigen::MatrixXd& pts, int first, const std::string& stage,
                                    DesignJournal* journal, const std::string& journal_path,
                                    ResumedPoints& resumed);
  void writeDesignTable() const;
  void evaluatedPoints(Eigen::MatrixXd& pts, std::vector<double>& f) const;
  void appendStartEnds(Eigen::MatrixXd& pts, std::vector<double>& f) const;
  void warnOtherBasins(const nlohmann::json& basins);
  /// The residuals' correlation in time at the optimum (correlated.hpp): blocks 0 unless every
  /// data set is a drive (one repetition, enough sample times).
  CorrelationAdjustment timeCorrelation();
  void writePosterior();

  const Study& study_;
  const AssemblySpec& assembly_;
  const std::vector<DataSet>& data_;
  const CalibrationSetup& setup_;
  const CalibrationOptions& options_;
  const std::string& out_dir_;
  const std::string& fingerprint_extra_;
  const StageProgress& progress_;
  const Clock::time_point t_all_;
  std::unique_ptr<LabObjective> objective_;
  SseFunction sse_;    ///< objective_->sse
  std::size_t d_ = 0;  ///< calibrated parameters
  int n_ = 0;          ///< scalar residuals
  std::string
      fingerprint_;  ///< of everything that changes the numbers; every stage file carries it
  std::string posterior_checksum_;  ///< of posterior.csv's bytes (contentChecksum), recorded in
                                    ///< summary.json
  CalibrationResult res_;
  nlohmann::json steps_log_ = nlohmann::json::array();  ///< chooseStepAccuracy's tries
  /// The Jacobian of the last polish on frozen steps (scaled units): the next polish's first, and
  /// the source of the integrator probes' steps (probeStepsFromJacobian).
  SubspaceJacobian polish_jacobian_;
  std::vector<double> reference_;  ///< the θ the screening's and the starts' steps were frozen at
  /// Per calibrated value: its physical limits (NaN: none known) and their basis (physicalLimit).
  std::vector<double> limit_lower_, limit_upper_;
  std::vector<std::string> limit_basis_;
};

}  // namespace dtwin::calib
