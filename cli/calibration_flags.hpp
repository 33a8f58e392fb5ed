#pragma once
// The calibration flags that `twin calibrate`, `twin coverage` and `twin diagnose` share
// (--lhs-points, --iterations, --burn-in, --starts, --region, --design, --interval, --steps,
// --max-rounds, --ridge-steps): declared once, read into calib::CalibrationOptions once.
#include <CLI/CLI.hpp>

#include <string>

#include "calibration/calibrate.hpp"
#include "cli/commands.hpp"

namespace dtwin::cli {

/// The values of the shared flags as given (-1 or "": not given, the study's value holds).
struct CalibrationFlags {
  long lhs_points = -1, iterations = -1, burn_in = -1, starts = -1, max_rounds = -1, ridge_steps = -1;
  std::string region, design, interval, steps;

  /// Which flags a command offers (an OR of these).
  enum Set : unsigned {
    kSizes = 1,     ///< --lhs-points, --iterations, --burn-in, --starts
    kRegion = 2,    ///< --region, --design, --interval
    kSteps = 4,     ///< --steps
    kRounds = 8,    ///< --max-rounds, --ridge-steps
  };

  /// Adds the flags of `which` to `app`, storing into this object (which must outlive the parse).
  void addTo(CLI::App* app, unsigned which);
  /// The given flags over `opt` (the study's options, CalibrationOptions::fromStudy): a --region
  /// without --design also sets the region's default design (adaptive for joint, lhs for paper).
  void applyTo(calib::CalibrationOptions& opt) const;
  /// `study` with its sizes overridden by --lhs-points, --iterations and --starts, each checked
  /// against its limit (for the work estimate, io/work.hpp).
  Study sized(const Study& study) const;
  /// Library errors name CalibrationOptions fields ("calibration.gibbs_burn_in"): the flags of
  /// those whose flag is not "--" + the field with '_' as '-'.
  static void addFieldFlags(CommandHandle& handle);
};

}  // namespace dtwin::cli
