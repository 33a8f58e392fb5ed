#pragma once
// `twin changes` as one call: what changed between two calibrations of one car (two drives), the
// list diagnosis/changes.hpp makes, written to OUT/changes.json with how it was made and drawn on
// OUT/changes.html.
#include <string>

#include "diagnosis/changes.hpp"

namespace dtwin {

struct ChangesRequest {
  std::string before;   ///< the first drive's calibration folder (`twin calibrate`'s OUT/<id>)
  std::string after;    ///< the second drive's
  std::string out;      ///< folder for changes.json and changes.html; "" writes nothing
  double level = 0.05;  ///< family-wise error rate of the significance rule, in (0, 0.5)
  std::string command;  ///< recorded in changes.json
};

/// Reads both folders (InputError naming the folder or file and the field), compares them and,
/// with `out`, writes OUT/changes.json (the list, program, command, time) and OUT/changes.html
/// (the list as a page).
diag::ChangeReport detectChanges(const ChangesRequest& request);

}  // namespace dtwin
