#pragma once
// `twin import`: a logger's wide CSV (one row per sample time, one column per signal) turned into
// what the twin reads (docs/measurements.md, "Importing a log"): the tidy measurement file with
// its sidecar, the speed trace, the road logged against time, and a study file holding the drive
// as a scenario, so that `twin compare` and `twin diagnose` run on it with no hand editing.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/progress.hpp"
#include "io/measurement.hpp"
#include "subsystems/sensor.hpp"

namespace dtwin {

/// One source column and how to read it: SI value = (raw − offset) × scale × unit factor.
struct ImportColumn {
  std::string column;  ///< the header name in the log
  std::string unit;    ///< as the log gives it: "g", "m/s^2", "km/h", "mm", "ms", ...
  double offset =
      0.0;  ///< in the log's unit (e.g. 1 for an accelerometer in g that reads 1 g at rest)
  double scale = 1.0;      ///< e.g. -1 for a sensor mounted upside down
  std::string where;       ///< names it in errors (mapping file:line: field, or the flag)
  std::string unit_where;  ///< names the unit in errors (its own line); empty: `where`
  const std::string& unitWhere() const { return unit_where.empty() ? where : unit_where; }
};

struct ImportChannel {
  ImportColumn source;
  std::string channel;  ///< a channel of the twin or of a sensor ("seat_mps2")
};

/// A mask (docs/measurements.md, "Windows and masks"): a row whose magnitude |value| of `source`
/// (converted to SI) is above `above` or below `below` is neither fitted nor scored; the run still
/// goes through it. A row whose mask cell is empty is masked too (it cannot be told).
struct ImportMask {
  ImportColumn source;
  std::optional<double> above, below;  ///< thresholds in SI (the mask's unit converted)
  std::string si;                      ///< the SI unit of the thresholds
  /// Rows within this many seconds of a row past a threshold are masked too: a turn's edges, where
  /// the yaw rate is under its threshold but the body still rolls (0: none).
  double pad_s = 0.0;
  /// "|yaw_rate| > 0.1 rad/s" (SI thresholds).
  std::string text() const;
};

struct ImportMapping {
  ImportColumn time;                  ///< unit s or ms
  std::optional<ImportColumn> speed;  ///< unit km/h, m/s or mph (required)
  /// The road under the front axle, against time: one column for both tracks or left and right;
  /// unit m or mm (height) or m/s or mm/s (vertical road velocity). None: a flat road.
  std::optional<ImportColumn> road, road_left, road_right;
  /// Each wheel's own vertical motion (road_fl, road_fr, road_rl, road_rr: all four or none, not
  /// with road or road_left/road_right), as a wheel-carrier sensor logs it: unit m or mm
  /// (height), m/s (velocity), m/s^2 or g (acceleration; gravity removed by the column's offset,
  /// e.g. 1 for g). Written as a four-corner road.csv (subsystems/time_road.hpp).
  std::array<std::optional<ImportColumn>, 4> road_wheels;
  /// Drift removal of a road velocity, or of each integration of a wheel's acceleration
  /// (docs/measurements.md).
  double highpass_hz = 0.1;
  bool highpass_given =
      false;  ///< set explicitly: then the road must be a velocity or acceleration
  /// > 0: the speed is smoothed by a zero-phase low-pass at this cut-off before it becomes the
  /// trace (a GPS speed in 0.1 km/h steps otherwise gives the model acceleration spikes).
  double speed_lowpass_hz = 0.0;
  std::vector<ImportChannel> channels;  ///< at least one
  std::vector<SensorSpec> sensors;      ///< sensors the channels may name, added to the study
  char separator = ',';                 ///< ' ': whitespace (a run of spaces and tabs)
  bool decimal_comma = false;  ///< numbers written 1,25 (then the separator may not be ',')
  long header_line = 1;  ///< the line holding the column names (a logger's preamble comes before)
  long skip_rows = 0;    ///< rows after the header that are not data (e.g. a row of units)
  long max_dropout_rows = 5;  ///< longest run of empty/NaN cells a channel may have (skipped)
  /// Only rows with a time in [a, b] (s from the log's first row) are measurements. The run starts
  /// run_in_s before a (at the log's start at the earliest), on the log's speed and road from
  /// there, so the model has settled when the window opens; the distance travelled before the
  /// run's start is the speed's start_m (a road measured against distance stays in place).
  std::optional<std::array<double, 2>> window_s;
  std::string window_where;  ///< names it in errors
  double run_in_s = 10.0;
  std::vector<ImportMask> exclude;  ///< masks, any of which drops a row
  std::string source;               ///< the mapping file, or "command line"
};

/// Reads a mapping TOML ([import] table: time, speed, road | road_left + road_right | road_fl +
/// road_fr + road_rl + road_rr, highpass_hz,
/// separator, max_dropout_rows, [[import.channels]]; optional [sensors.NAME] as in a study).
/// Unknown keys and bad values: InputError naming file:line: field.
ImportMapping readImportMapping(const std::string& path);
/// "COL[:UNIT[:OFFSET[:SCALE]]]" from the command line (`flag` names it in errors).
ImportColumn parseImportColumn(const std::string& text, const std::string& flag,
                               const std::string& default_unit = "");

/// A log's field separator as a mapping or a flag gives it: one character (not a letter, digit,
/// quote, '.', '-' or '+'), "tab", or "whitespace" / " " (a run of spaces and tabs, returned as '
/// ').
char parseSeparator(const std::string& text, const std::string& where);

/// The factor from `unit` to SI for a target of SI unit `si` ("m/s^2", "m", "m/s", "N", "rad",
/// "rad/s^2", "s", "m/s (speed)"); InputError(where, ...) for a unit it does not know or that
/// does not fit (g for a channel in m).
double unitFactor(const std::string& unit, const std::string& si, const std::string& where);

/// A time of day as loggers write it: `HH:MM:SS[.fff]`, optionally after a date `YYYY-MM-DD`
/// (or `YYYY/MM/DD`) and 'T' or a space, optionally followed by 'Z' or a UTC offset ±HH:MM or
/// ±HHMM. The fraction may be written with '.' or ','. `has_date` false: day is 0.
struct ClockTime {
  long day = 0;  ///< days since 1970-01-01 (proleptic Gregorian), with the offset applied
  double seconds =
      0.0;  ///< seconds since that day's midnight, UTC when an offset is given, [0, 86401)
  bool has_date = false;
};
/// Parses `text` (surrounding spaces allowed); false when it is not such a time or a field is out
/// of range (month 13, 25:00:00, 30 February).
bool parseClockTime(std::string_view text, ClockTime& out);

struct ImportResult {
  std::string scenario;  ///< the scenario name of the drive
  double t0_s =
      0.0;  ///< the log's time of its first row (scenario time 0); a clock time: seconds of its day
  double duration_s = 0.0;
  long rows = 0, dropped_cells = 0;
  /// Rows not measured: outside the window, and by each mask (its text), in the mapping's order.
  long outside_window = 0;
  std::vector<std::pair<std::string, long>> masked;
  double start_m = 0.0;  ///< the distance travelled before the run's start (0 without a window)
  /// The run's first row as a UTC date and time ("2026-03-09T07:35:00.000Z") when the log's time
  /// column is a clock time with dates; "" otherwise. `twin changes` orders drives by it.
  std::string start_utc;
  LabData data;                              ///< the measurements (repetition 1), times from 0
  std::string lab_csv, speed_csv, road_csv;  ///< file texts (road_csv empty: flat road)
  std::string study_toml;  ///< the study with the drive's scenario and the mapping's sensors
  nlohmann::json sidecar;  ///< how the files were made
};

/// Converts the log text. `base_study` is the study file the drive is added to (its scenarios,
/// vehicle and sensors are kept; relative paths become absolute). Every check is done here,
/// before anything is written: missing columns, non-numeric cells, NaN runs longer than
/// max_dropout_rows, time going backwards or repeating, unknown units, a scenario name already
/// in the study. Errors: InputError(log:line, "column 'X': rule"). `progress` sees bytes read.
ImportResult importLog(const std::string& log_text, const std::string& log_name,
                       const ImportMapping& mapping, const std::string& base_study,
                       const std::string& scenario, const StageProgress& progress = {});

/// Writes `r` into the new folder `out_dir` (measurements.csv + .json, speed.csv, road.csv,
/// study.toml): all files go into a temporary sibling folder, the study written there is read
/// back with loadStudy (so it is known to work), and the folder is renamed into place. On any
/// error nothing is left behind. `out_dir` must not exist, or be an empty folder.
void writeImport(const ImportResult& r, const std::string& out_dir);

}  // namespace dtwin
