#pragma once
// Measurement files: the tidy lab layout (repetition,time_s,channel,value) and the field matrix
// (run,road_seed,t_10.000,...). `twin generate` writes them; a user brings real measurements in
// the same layout. Readers validate everything and throw InputError with one line naming
// file:line, the field and the rule broken. docs/data-files.md describes both layouts.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/format.hpp"  // formatExact
#include "subsystems/sensor.hpp"
#include "twin/trace.hpp"

namespace dtwin {

/// One measured value.
struct LabRecord {
  long repetition = 1;  ///< 1, 2, ... (positive integer)
  double time_s = 0.0;  ///< seconds since the start of the scenario
  std::string channel;  ///< channel name with its unit suffix, e.g. "hub_force_fl_N"
  double value = 0.0;   ///< in the channel's unit
};

/// Lab data in tidy form, records in file order.
struct LabData {
  std::vector<LabRecord> records;
  /// Channels in order of first appearance.
  std::vector<std::string> channels() const;
  /// Repetition numbers, ascending, each once.
  std::vector<long> repetitions() const;
  /// Times of one channel, ascending, each once (over all repetitions).
  std::vector<double> times(const std::string& channel) const;
};

/// The channels a measurement may name: every simulator output channel except time_s, then the
/// channels of `sensors` (a study's [sensors]).
std::vector<Channel> measurableChannels();
std::vector<Channel> measurableChannels(const std::vector<SensorSpec>& sensors);
/// The unit of channel `name` among `known` (e.g. measurableChannels(study.sensors)); "" when it
/// is none of them.
std::string channelUnit(const std::vector<Channel>& known, const std::string& name);

/// The header of the lab layout.
inline constexpr const char* kLabHeader = "repetition,time_s,channel,value";

/// CSV text of lab data: header `repetition,time_s,channel,value`, one record per line, numbers
/// in the shortest form that reads back exactly. Validates first (same rules as the reader).
std::string labCsvText(const LabData& data,
                       const std::vector<Channel>& known = measurableChannels());
/// The same, record i named by `where(i)` in an error (an import names the log and the sample).
std::string labCsvText(const LabData& data, const std::function<std::string(std::size_t)>& where,
                       const std::vector<Channel>& known);
/// Writes labCsvText atomically (common/files.hpp writeFileAtomic).
void writeLabCsv(const std::string& path, const LabData& data,
                 const std::vector<Channel>& known = measurableChannels());

/// Parses lab CSV text; `name` (the file name) prefixes errors. Rules: the header names exactly
/// the four columns (any order); every line has four fields; repetition is a positive integer;
/// time_s is a finite number >= 0, strictly increasing within each (repetition, channel);
/// channel is a known channel with its unit suffix; value is a finite number; at least one
/// record. A UTF-8 byte-order mark, CR line ends, spaces around fields, double quotes around a
/// field and blank lines are accepted.
LabData parseLabCsv(const std::string& text, const std::string& name,
                    const std::vector<Channel>& known = measurableChannels());
/// Reads and validates a lab CSV file.
LabData readLabCsv(const std::string& path,
                   const std::vector<Channel>& known = measurableChannels());
/// Validates lab data held in memory (the reader's rules; "record i" stands for line i + 2).
void validateLabData(const LabData& data, const std::string& name,
                     const std::vector<Channel>& known = measurableChannels());
/// The same, record i named by `where(i)` (an import names the log and the sample it came from).
void validateLabData(const LabData& data, const std::function<std::string(std::size_t)>& where,
                     const std::vector<Channel>& known);

/// The largest magnitude a measured value in `unit` may have (the plausibility range [-limit,
/// limit] of docs/data-files.md, "Plausible values"): far beyond what a road vehicle produces,
/// so that only corrupt numbers (1e308 N, a mis-scaled column) are refused. Unknown units: 1e12.
double plausibleLimit(const std::string& unit);

/// Checks one channel name against `known`: "" if known, else the rule broken (unknown channel
/// with the closest known name, or a wrong unit suffix with the expected one).
std::string checkChannelName(const std::string& channel,
                             const std::vector<Channel>& known = measurableChannels());

/// Field data: one row per run, one column per time of a window of one channel.
struct FieldData {
  std::vector<double> times_s;            ///< column times, strictly increasing
  std::vector<long> runs;                 ///< run numbers (1-based), one per row
  std::vector<std::uint64_t> road_seeds;  ///< one per row, or empty (measured data: no seed)
  std::vector<double> values;             ///< row-major, runs.size() x times_s.size()
  std::size_t rowCount() const { return runs.size(); }
  std::size_t columnCount() const { return times_s.size(); }
  double& at(std::size_t row, std::size_t col) { return values[row * times_s.size() + col]; }
  double at(std::size_t row, std::size_t col) const { return values[row * times_s.size() + col]; }
};

/// CSV text of field data: header `run,road_seed,t_10.000,t_10.001,...` (time columns with the
/// fewest decimals that represent every time exactly; road_seed left out if there are no seeds),
/// one row per run, numbers in the shortest exact form.
std::string fieldCsvText(const FieldData& data);
void writeFieldCsv(const std::string& path, const FieldData& data);
/// Parses field CSV text. Rules: header `run[,road_seed],t_<seconds>,...` with at least one time
/// column, times finite and strictly increasing; every row has one field per column; run is a
/// positive integer, unique; road_seed an integer in [0, 2^64); values finite, |v| <= 1e12.
FieldData parseFieldCsv(const std::string& text, const std::string& name);
FieldData readFieldCsv(const std::string& path);

}  // namespace dtwin
