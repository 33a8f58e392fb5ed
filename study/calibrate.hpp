#pragma once
// `twin calibrate` as one library call: one or every assembly of a study calibrated against a lab
// data file (calibration/calibrate.hpp), each into OUT/<id>/ (resumable), and OUT/calibration.json
// indexing them with how they were made. The CLI parses its flags into the request, checks the
// work, calls, and prints.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "calibration/calibrate.hpp"
#include "common/distributed.hpp"
#include "common/progress.hpp"
#include "diagnosis/candidates.hpp"
#include "io/study.hpp"

namespace dtwin {

struct CalibrateRequest {
  std::string data;                     ///< the lab data CSV
  std::vector<std::string> assemblies;  ///< assembly ids; empty: every assembly of the study
  std::string scenario = "lab";         ///< the scenario the data were measured on
  std::string out;                      ///< the folder; each assembly writes OUT/<id>/
  calib::CalibrationOptions options;    ///< command and data_path are set from the request
  /// Fixed values calibrated too, each over its prior range as `twin diagnose` frees it
  /// (diagnosis/candidates.hpp): a per-corner or per-axle factor ("suspension.damping@rr", over
  /// [0.2, 2]), a freeable vehicle value or a law's fixed value (±50 % about the file's value).
  std::vector<std::string> free;
  std::string command;  ///< recorded in every output
  /// InputError naming the field ("calibrate.data", "calibrate.out", ...) or the options' own.
  void validate(const Study& study) const;
};

/// The calibration settings a user may override for one call (the flags of `twin calibrate`,
/// `twin coverage` and `twin diagnose`, the keywords of the Python module): -1 or "" leaves the
/// study's value.
struct CalibrationOverrides {
  long lhs_points = -1, iterations = -1, burn_in = -1, starts = -1, max_rounds = -1,
       ridge_steps = -1;
  std::string region, design, interval, steps;

  /// The given values over `opt` (the study's options, CalibrationOptions::fromStudy): a region
  /// without a design also sets the region's default design (adaptive for joint, lhs for paper).
  void applyTo(calib::CalibrationOptions& opt) const;
  /// `study` with its sizes overridden by lhs_points, iterations and starts, each checked
  /// against its limit (for the work estimate, io/work.hpp).
  Study sized(const Study& study) const;
};

/// The lab data of `twin calibrate --data FILE[@SCENARIO]`: the file, and the scenario it was
/// measured on: `scenario` when given, else the one after '@', else the one its JSON sidecar
/// names, else lab (InputError when the sidecar names another). `field` names the argument.
std::pair<std::string, std::string> calibrationData(const std::string& data,
                                                    const std::string& field,
                                                    const std::string& scenario = "");

/// The work of `request` with `overrides` checked against the limits (io/work.hpp; InputError
/// above them unless `force`), before anything runs.
void checkCalibrateWork(const Study& study, const CalibrateRequest& request,
                        const CalibrationOverrides& overrides, bool force);

/// The older shape `--data FILE --scenario NAME`: InputError("--scenario") when FILE@SCENARIO
/// names another scenario than `scenario`.
void checkDataScenario(const std::string& data, const std::string& scenario);

/// One calibration as a front end gives it (the flags of `twin calibrate`, the keywords of the
/// Python module's Study.calibrate).
struct CalibrateSettings {
  std::string data;                        ///< the lab data, FILE[@SCENARIO]
  std::string scenario;                    ///< the scenario given apart ("": FILE@SCENARIO's, ...)
  std::vector<std::string> assemblies;     ///< assembly ids; empty: every assembly of the study
  std::string out;                         ///< the folder; each assembly writes OUT/<id>/
  std::vector<std::string> free;           ///< CalibrateRequest::free
  int threads = 0;                         ///< worker threads per process (0: all cores)
  const Distributed* processes = nullptr;  ///< the process context; nullptr: this process alone
  std::optional<std::uint64_t> seed;       ///< unset: the study's
  CalibrationOverrides overrides;          ///< the sizes and settings given
  bool force = false;                      ///< run even above the work limits
  std::string command;                     ///< recorded in every output
};

/// The request of `settings` on `study`: the data and their scenario (calibrationData, errors
/// naming --data), the study's calibration options with the settings over them; validated
/// (CalibrateRequest::validate) and its work checked (checkCalibrateWork) before anything runs.
CalibrateRequest calibrateRequest(const Study& study, const CalibrateSettings& settings);

/// One calibrated assembly.
struct CalibrateRun {
  AssemblySpec assembly;
  calib::CalibrationResult result;
  /// The SSE weight 1/σ_c² of each channel when the data hold several (channelWeights); empty
  /// with one channel, whose noise the sampler's τ estimates.
  std::map<std::string, double> weights;
  /// The unit of the data when they are unweighted ("N" for forces, "m/s^2" for one accelerometer).
  std::string unit = "N";
  /// The lines `twin calibrate` prints: SSE, noise, design, then each parameter's mean, sd and
  /// both 95 % intervals (the chosen one first), the truth when known, and the notes.
  std::string text() const;
};

/// The SSE weights of a calibration against `set`. One channel, or forces only: none (the SSE in
/// newtons; the Gibbs sampler's τ estimates their one noise, docs/method.md). Other channels, which
/// may be in different units (an accelerometer and a string pot): 1/σ_c², σ_c from the data's
/// repetitions, else the sensor's noise_sd, else the study's [noise] for forces, so that the SSE
/// is a χ² and τ ≈ 1 when the stated noises are right. A channel with none of these is an
/// InputError naming it: fitted unweighted, a channel in metres would weigh nothing beside one in
/// m/s², and one in N would swamp both.
std::map<std::string, double> channelWeights(const Study& study, const calib::DataSet& set);

/// How `value` of CalibrateRequest::free is calibrated in `assembly`: the diagnosis's "free:"
/// candidate. InputError("calibrate.free", rule) for a value that cannot be freed there (unknown,
/// calibrated already, a factor of a value the assembly lacks, ...).
diag::CandidateSpec freedValueSpec(const Study& study, const AssemblySpec& assembly,
                                   const std::string& value);

/// The targets of `request` (every assembly when none is named).
std::vector<AssemblySpec> calibrationTargets(const Study& study, const CalibrateRequest& request);

/// Calibrates every target in turn. `say` receives the plan (what is calibrated against what,
/// with which sizes) once the data are read, before the work; `progress_of(assembly)` gives the
/// progress callback of that assembly's stages (may return an empty function); `on_done` is
/// called after each assembly. OUT/calibration.json is written (atomically, on the root rank)
/// when all are done.
void calibrateAssemblies(const Study& study, const CalibrateRequest& request, const SayFn& say,
                         const std::function<StageProgress(const AssemblySpec&)>& progress_of,
                         const std::function<void(const CalibrateRun&)>& on_done);

}  // namespace dtwin
