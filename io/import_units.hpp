// Private to io/ (not installed): the units a logger's columns may give, each with its SI unit and
// factor, shared by the column map reader (import_mapping.cpp), the import (log_import.cpp) and the
// MF4 reader (mdf_import.cpp); the resolved units and the rows read, shared by the import and the
// MF4 reader.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/statistics.hpp"
#include "io/log_import.hpp"

namespace dtwin {

struct Unit {
  const char* name;
  const char* si;
  double factor;
};
// Every unit a log may give, with the SI unit it converts to.
const Unit kUnits[] = {
    {"s", "s", 1.0},
    {"ms", "s", 1e-3},
    {"us", "s", 1e-6},
    {"ns", "s", 1e-9},
    {"clock", "s", 1.0},  // HH:MM:SS[.fff], optionally after a date (parseClockTime)
    {"m/s", "m/s", 1.0},
    {"mps", "m/s", 1.0},
    {"km/h", "m/s", 1.0 / 3.6},
    {"kmh", "m/s", 1.0 / 3.6},
    {"kph", "m/s", 1.0 / 3.6},
    {"mph", "m/s", 0.44704},
    {"kn", "m/s", 1852.0 / 3600.0},
    {"ft/s", "m/s", 0.3048},
    {"mm/s", "m/s", 1e-3},
    {"m", "m", 1.0},
    {"mm", "m", 1e-3},
    {"cm", "m", 1e-2},
    {"in", "m", 0.0254},
    {"m/s^2", "m/s^2", 1.0},
    {"m/s2", "m/s^2", 1.0},
    {"mps2", "m/s^2", 1.0},
    {"g", "m/s^2", 9.80665},
    {"ft/s^2", "m/s^2", 0.3048},
    {"N", "N", 1.0},
    {"kN", "N", 1e3},
    {"rad", "rad", 1.0},
    {"deg", "rad", kPi / 180.0},
    {"rad/s^2", "rad/s^2", 1.0},
    {"deg/s^2", "rad/s^2", kPi / 180.0},
    {"rad/s", "rad/s", 1.0},
    {"deg/s", "rad/s", kPi / 180.0},
};

/// Every mapped column's factor to SI, resolved before a row is read (a wrong unit is named
/// before a million rows are read).
struct ImportUnits {
  double time = 1.0, speed = 1.0;
  /// none, one (both tracks), left and right, or four (each wheel's: fl, fr, rl, rr)
  std::vector<const ImportColumn*> road_cols;
  bool road_velocity = false;      ///< the road columns are velocities, not heights
  bool road_acceleration = false;  ///< the road columns are accelerations (four wheels' only)
  std::vector<double> road, channel;
};

/// The road columns' units (road, road_left/road_right or the four wheels'): their factors and
/// form into `u`. Errors name the column's mapping entry (import_road.cpp).
void resolveRoadUnits(const ImportMapping& m, ImportUnits& u);
/// road.csv's text of the run's road columns (SI, times from 0); "" without a mapped road.
std::string roadCsvText(const ImportUnits& u, const std::vector<double>& t,
                        const std::vector<std::vector<double>>& road);
/// The sidecar's "road" entry (null without a mapped road).
nlohmann::json roadSidecar(const ImportMapping& m, const ImportUnits& u);
/// The four wheels' accelerations (SI) must have had gravity removed (the column's offset): a
/// mean beyond half a g is refused, naming the column's mapping entry.
void checkWheelAccelerations(const ImportUnits& u, const std::vector<std::vector<double>>& road);

/// The log's rows in SI units: times (as logged), speeds, road columns, and the channels (NaN: a
/// dropout).
struct LogRows {
  std::vector<double> t, v;
  std::vector<std::vector<double>> road, values;
  std::vector<std::vector<double>> mask;  ///< per mask: |value| in SI, NaN for an empty cell
  long dropped_cells = 0;
  /// A clock time column with dates: the first row's day (days since 1970-01-01, UTC); else -1.
  long first_day = -1;
};

/// The rows of an MF4 log (mdf_import.cpp): the mapped channels, each found by name (or
/// GROUP/NAME), its unit checked against the mapping's, on the time base of the time channel's
/// group (others interpolated linearly onto it), with the CSV's checks. `provenance`: the groups
/// and channels read, the resampling and the rows it dropped.
LogRows readMdfRows(const std::string& bytes, const std::string& name, const ImportMapping& m,
                    const ImportUnits& u, nlohmann::json& provenance);

/// A mask's unit: its factor to SI and the SI unit (import_mapping.cpp).
std::pair<double, std::string> anyUnit(const std::string& unit, const std::string& where);

}  // namespace dtwin
