#pragma once
// `twin changes` as one call: what changed between two calibrations of one car (two drives), the
// list diagnosis/changes.hpp makes, written to OUT/changes.json with how it was made and drawn on
// OUT/changes.html.
#include <string>
#include <vector>

#include "diagnosis/changes.hpp"
#include "diagnosis/changes_series.hpp"

namespace dtwin {

struct ChangesRequest {
  std::string before;   ///< the first drive's calibration folder (`twin calibrate`'s OUT/<id>)
  std::string after;    ///< the second drive's
  std::string out;      ///< folder for changes.json and changes.html; "" writes nothing
  double level = 0.05;  ///< family-wise error rate of the significance rule, in (0, 0.5)
  std::string command;  ///< recorded in changes.json
  /// A series of drives instead of before/after: three or more calibration folders, in any order.
  std::vector<std::string> calibrations;
  /// Each calibration's drive date ("2026-03-09", or with a time), in the order of `calibrations`;
  /// empty: each is read from its data's sidecar (measurements.json's source.start_utc, written by
  /// `twin import` from a log whose time column is a clock time with dates).
  std::vector<std::string> dates;
};

/// Reads both folders (InputError naming the folder or file and the field), compares them and,
/// with `out`, writes OUT/changes.json (the list, program, command, time) and OUT/changes.html
/// (the list as a page).
diag::ChangeReport detectChanges(const ChangesRequest& request);

/// The series of `request.calibrations` (at least three) ordered by their drives' dates: each
/// value's estimate drive by drive, its trend and the first-to-last change; with `out`, writes
/// OUT/changes.json and OUT/changes.html (each value against the drive's date). InputError naming
/// changes.calibrations or changes.dates (a date missing, malformed or repeated, a count that
/// differs), or the folder and field.
diag::SeriesReport detectChangesOverDrives(const ChangesRequest& request);

}  // namespace dtwin
