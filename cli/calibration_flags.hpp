#pragma once
// The calibration flags that `twin calibrate`, `twin coverage` and `twin diagnose` share
// (--lhs-points, --iterations, --burn-in, --starts, --region, --design, --interval, --steps,
// --max-rounds, --ridge-steps): declared once, read into calib::CalibrationOptions once
// (CalibrationOverrides, study/calibrate.hpp, which the Python module fills from its keywords).
#include <CLI/CLI.hpp>

#include <string>

#include "cli/commands.hpp"
#include "study/calibrate.hpp"

namespace dtwin::cli {

/// The values of the shared flags as given (-1 or "": not given, the study's value holds), read
/// into the options by CalibrationOverrides::applyTo (study/calibrate.hpp).
struct CalibrationFlags : CalibrationOverrides {
  /// Which flags a command offers (an OR of these).
  enum Set : unsigned {
    kSizes = 1,   ///< --lhs-points, --iterations, --burn-in, --starts
    kRegion = 2,  ///< --region, --design, --interval
    kSteps = 4,   ///< --steps
    kRounds = 8,  ///< --max-rounds, --ridge-steps
  };

  /// Adds the flags of `which` to `app`, storing into this object (which must outlive the parse).
  void addTo(CLI::App* app, unsigned which);
  /// Library errors name CalibrationOptions fields ("calibration.gibbs_burn_in"): the flags of
  /// those whose flag is not "--" + the field with '_' as '-'.
  static void addFieldFlags(CommandHandle& handle);
};

}  // namespace dtwin::cli
