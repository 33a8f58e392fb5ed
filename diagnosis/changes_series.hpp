#pragma once
// What changed over several drives of one car (more than two calibrations, each dated): every value
// all of them calibrated, drive by drive in the order of their dates with each calibration's
// estimate and 95 % interval (diagnosis/changes.hpp reads them), its trend, and the change from the
// first drive to the last.
//
// The trend is the weighted least-squares line through the estimates against the drive's date, on
// the log scale for a positive value (a rate: the value's ratio per year) and on the linear scale
// otherwise (a difference per year), each estimate weighted by 1/sd² from its own interval
// (sd = (hi - lo) / (2 z_0.975)). The drives have independent noise, so the slope's sd is
// 1/sqrt(Σ w (t - t̄_w)²) and z = slope / sd. Holm's step-down rule over the values' trends at a
// family-wise `level` says which trends are significant. A straight line is a summary: the drives'
// own estimates and intervals are listed beside it, and the scatter about the line is given as a
// χ² per degree of freedom (about 1 when the line and the intervals tell the same story; well above
// 1: the value did not move along a line, or the intervals are too narrow).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/folder.hpp"
#include "diagnosis/changes.hpp"

namespace dtwin::diag {

/// One drive's calibration: its folder and its date.
struct DatedCalibration {
  calib::CalibrationFolder folder;
  std::string date;  ///< as given or found ("2026-03-09" or "2026-03-09T07:35:00Z")
  double day = 0;    ///< days since 1970-01-01 (UTC), with the time of day as a fraction
};

struct SeriesValue {
  std::string name, unit;
  bool ratio = false;                 ///< a positive value: the trend is a ratio per year
  std::vector<ValueEstimate> drives;  ///< in the order of the series' dates
  std::vector<double> line;           ///< the trend line's value at each drive's date
  double slope = 0, lo = 0, hi = 0;   ///< per year: a ratio (ratio) or a difference
  double z = 0, p = 1,
         chi2_dof = 0;       ///< the slope's z, its two-sided p, the scatter about the line
  bool significant = false;  ///< by Holm's rule over every value's trend at `level`
  bool trusted = true;       ///< every drive's estimate trusted
  std::string sentence;
};

struct SeriesReport {
  std::string assembly;
  std::vector<std::string> dirs, dates;  ///< in date order
  std::vector<double> days;
  double level = 0.05;
  std::vector<SeriesValue> values;  ///< significant trends first, then by |z|
  ChangeReport first_to_last;       ///< the pairwise list of the first and last drives
  std::vector<std::string> notes;
  std::size_t significantCount() const;
  nlohmann::json toJson() const;
  /// The lines `twin changes` prints for a series.
  std::string text() const;
};

/// Days since 1970-01-01 of a date "YYYY-MM-DD" (optionally followed by 'T' or a space and a time
/// of day, and 'Z' or a UTC offset); false when it is not one.
bool parseDriveDate(const std::string& text, double& day);

/// The series over `drives` (at least three, each with its date; sorted here by date, two on the
/// same date refused): InputError naming `where` for fewer drives or equal dates; `level` in
/// (0, 0.5).
SeriesReport compareSeries(std::vector<DatedCalibration> drives, double level,
                           const std::string& where);

}  // namespace dtwin::diag
