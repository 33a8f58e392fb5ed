#pragma once
// ASAM MDF 4 logs (.mf4), read and written through the vendored mdflib (third_party/mdflib): the
// channels of a log with the file's conversions applied (readMdfLog, for `twin import`,
// docs/measurements.md "MF4 logs"), and a writer of such logs (writeMdfLog: the tests' fixtures and
// `twin bench --import`). No mdflib type appears here.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace dtwin {

/// True when `name` ends in .mf4 or .mdf (any case) or `bytes` begin with the MDF identification
/// "MDF     ".
bool isMdfLog(const std::string& name, std::string_view bytes);

/// One channel of a log: its values (physical, after the file's conversion; NaN where the file
/// marks a sample invalid) at its group's master times.
struct MdfChannelData {
  std::string name, unit;
  std::string conversion =
      "identity";  ///< identity, linear, rational, value-to-value, range-to-value
  std::vector<double> values;
};

/// One channel group: its master channel (time) and the channels read from it.
struct MdfGroupData {
  std::string name;  ///< the group's acquisition name ("" when the file gives none)
  std::string master = "Time", master_unit = "s";
  std::vector<double> time;  ///< the master's values, as the file gives them
  std::vector<MdfChannelData> channels;
};

/// The channels a log holds and where: every group's name, master and channel names (no values).
struct MdfDirectory {
  struct Channel {
    std::string name, unit, conversion;
    bool master = false;
    bool text = false;  ///< a text conversion (value to text, ...) or a text channel: not a number
  };
  struct Group {
    std::string name;
    std::vector<Channel> channels;
    unsigned long long samples = 0;
  };
  std::string version;  ///< "4.10"
  std::vector<Group> groups;
};

/// Reads the log's blocks but not its data. InputError(name, ...) for a file that is not MDF 4,
/// is truncated or damaged (its block structure: io/mdf_structure.hpp), or is not finalised.
MdfDirectory readMdfDirectory(const std::string& bytes, const std::string& name);

/// Reads the named channels of group `group` (an index into MdfDirectory::groups) with their
/// master. InputError for a channel with a text conversion or whose data is cut short, and for a
/// file whose DZ blocks do not inflate cleanly to their declared sizes.
MdfGroupData readMdfGroup(const std::string& bytes, const std::string& name, std::size_t group,
                          const std::vector<std::string>& channels);

/// A conversion written with a channel (writeMdfLog): the stored values are raw, the file's
/// conversion makes them physical. linear: phys = p[0] + p[1] raw; rational: phys = (p[0] raw² +
/// p[1] raw + p[2]) / (p[3] raw² + p[4] raw + p[5]); value_to_text: keys p[0], p[1], ... to texts.
struct MdfWriteConversion {
  std::string kind = "identity";  ///< identity, linear, rational, value_to_text
  std::array<double, 6> p{};
  std::vector<std::string> texts;
};
struct MdfWriteChannel {
  std::string name, unit;
  std::vector<double> values;  ///< written as 64-bit floats (raw when a conversion is given)
  MdfWriteConversion conversion;
};
struct MdfWriteGroup {
  std::string name, master = "Time", master_unit = "s";
  std::vector<double> time;  ///< written as the master's 64-bit float values
  std::vector<MdfWriteChannel> channels;
};
/// Writes an MF4 file of one data group holding `groups` (each a channel group with its own
/// master), its data in DZ blocks (deflate) when `compress`. std::runtime_error when mdflib fails.
void writeMdfLog(const std::string& path, const std::vector<MdfWriteGroup>& groups, bool compress);

}  // namespace dtwin
