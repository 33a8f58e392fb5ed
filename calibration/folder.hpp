#pragma once
// The calibration folder, read back: what `twin calibrate` (and `twin diagnose`, for its base and
// candidate calibrations) writes into OUT/<id>/, and the one reader of it that synthesis,
// diagnosis, the study and the CLI use.
//
//   OUT/<id>/summary.json   the result (CalibrationResult::toJson) plus program, command, study,
//                           scenario, data, data_sets, setup, options and threads
//   OUT/<id>/posterior.csv  one row per kept Gibbs iteration: the calibrated parameters, then
//                           tau, then design_index (written with posteriorCsv)
//   OUT/<id>/box.json       the region stage (its fingerprint, the region and its axes, the box)
//   OUT/<id>/stage_*.json, design journal: resumable stages (calibrate.hpp)
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/calibrate.hpp"
#include "io/posterior_file.hpp"

namespace dtwin::calib {

// posterior.csv, its reader and writer: io/posterior_file.hpp.
using dtwin::checkPosteriorChecksum;
using dtwin::parsePosteriorCsv;
using dtwin::posteriorCsv;
using dtwin::PosteriorSample;
using dtwin::readPosteriorCsv;

/// A calibration folder read back.
struct CalibrationFolder {
  std::string dir;
  nlohmann::json summary;     ///< summary.json as written
  std::string assembly;       ///< summary.json "assembly" (checked: a non-empty string)
  CalibrationSetup setup;     ///< summary.json "setup" (empty when absent: a plain calibration)
  PosteriorSample posterior;  ///< posterior.csv
  /// summary.json "bound_findings": values on their bounds and values the data do not determine
  /// (empty when absent, as in folders written before they were recorded).
  std::vector<BoundFinding> bound_findings;
};

/// Reads `dir`: InputError naming the folder when it is not one or has no summary.json, naming
/// summary.json and the field when it is not valid JSON, has no string "assembly" or a malformed
/// "setup", and the posterior.csv rules above.
CalibrationFolder readCalibrationFolder(const std::string& dir);

/// The study's assembly that `folder` calibrated; InputError naming summary.json's "assembly"
/// (not the study file) when the study has no such assembly.
AssemblySpec calibratedAssembly(const Study& study, const CalibrationFolder& folder);

}  // namespace dtwin::calib
