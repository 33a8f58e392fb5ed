#pragma once
// Speed trace files (a scenario's speed_trace_csv: time and speed along the straight path;
// docs/data-files.md).
#include <string>

#include "subsystems/speed_trace.hpp"

namespace dtwin {

/// Reads a speed trace from a CSV file: a header `time_s,speed_<unit>` with the unit one of `mps`
/// (m/s), `kmh` (km/h) or `mph`, then one `time,speed` row per sample; a UTF-8 byte-order mark,
/// CRLF line ends and blank lines are accepted. Throws InputError naming the file and line (and the
/// column) for a bad header, a cell that is not a finite number, a time that does not increase, a
/// negative speed, or fewer than two rows.
SpeedTrace readSpeedTraceCsv(const std::string& path);

/// The same, from the text of such a file; `name` names it in errors.
SpeedTrace parseSpeedTraceCsv(const std::string& text, const std::string& name);

}  // namespace dtwin
