#pragma once
// `twin import` as one library call: a logger's CSV, with its column map (a mapping file or the
// columns given one by one), into the twin's files and a study that holds the drive
// (io/log_import.hpp, docs/measurements.md). The CLI and the Python module fill the request
// from their flags and keywords, call, and print.
#include <array>
#include <string>
#include <vector>

#include "common/progress.hpp"
#include "io/log_import.hpp"

namespace dtwin {

struct ImportRequest {
  std::string log;  ///< the logger's CSV file
  std::string
      map;  ///< the mapping file (TOML, [import]); "" gives the mapping as the columns below
  std::string out;                 ///< the new output folder
  std::string study;               ///< the study the drive joins
  std::string scenario = "drive";  ///< the drive's scenario in the written study
  /// The mapping without a file (--time, --speed, --road, --road-left, --road-right, --channel
  /// COLUMN:CHANNEL:UNIT[:OFFSET[:SCALE]], --separator); all empty with a mapping file.
  std::string time, speed, road, road_left, road_right, separator;
  /// Each wheel's own motion (--road-fl, --road-fr, --road-rl, --road-rr, COLUMN:UNIT[:OFFSET[:
  /// SCALE]]): all four or none, not with road or road_left/road_right; fl, fr, rl, rr.
  std::array<std::string, 4> road_wheels;
  std::vector<std::string> channels;
  double highpass_hz = 0.0, speed_lowpass_hz = 0.0;  ///< 0: not given
  std::vector<double> window;  ///< START,END (s from the log's first row); empty: the mapping's
  double run_in = -1;          ///< seconds before the window (-1: the mapping's, or 10 s)
  std::string command;         ///< recorded in measurements.json
};

/// The mapping of `request`: its file, or the columns given (InputError when both or neither are
/// given, or a column is malformed), with its window and run-in.
ImportMapping importMapping(const ImportRequest& request);

/// Reads the log (at most 4 GB), converts it with importMapping(request) (importLog) and writes
/// the folder (writeImport). `progress` sees the bytes read.
ImportResult importDrive(const ImportRequest& request, const StageProgress& progress = {});

}  // namespace dtwin
