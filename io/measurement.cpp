#include "io/measurement.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"
#include "twin/parameters.hpp"
#include "twin/run_types.hpp"

namespace dtwin {
namespace {

constexpr const char* kLabColumns[4] = {"repetition", "time_s", "channel", "value"};

/// Parses a whole field of decimal digits as an unsigned integer.
bool parseUnsigned(std::string_view s, std::uint64_t& v) {
  if (s.empty() || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

std::string inQuotes(std::string_view s) { return "'" + std::string(s) + "'"; }

/// The reader's semantic rules, applied record by record in file order.
class LabChecker {
 public:
  explicit LabChecker(const std::vector<Channel>& known) : known_(known) {}

  /// `at()` names the record; asked for only when a rule is broken (a name costs more than a
  /// check).
  template <class At>
  void check(const LabRecord& r, const At& at) {
    if (r.repetition <= 0)
      throw InputError(at() + ": repetition",
                       "must be a positive integer, got " + std::to_string(r.repetition));
    if (!std::isfinite(r.time_s))
      throw InputError(at() + ": time_s", "must be finite, got " + formatExact(r.time_s));
    if (r.time_s < 0)
      throw InputError(at() + ": time_s", "must be >= 0 (seconds since the scenario start), got " +
                                              formatExact(r.time_s));
    const std::string rule = checkChannelName(r.channel, known_);
    if (!rule.empty()) throw InputError(at() + ": channel", rule);
    if (!std::isfinite(r.value))
      throw InputError(at() + ": value", "must be finite, got " + formatExact(r.value));
    if (r.time_s > plausibleLimit("s"))
      throw InputError(at() + ": time_s", "must be <= " + formatExact(plausibleLimit("s")) +
                                              " s (plausible range), got " + formatExact(r.time_s));
    for (const auto& k : known_)
      if (k.name == r.channel && std::abs(r.value) > plausibleLimit(k.unit))
        throw InputError(at() + ": value", "must lie in the plausible range [-" +
                                               formatExact(plausibleLimit(k.unit)) + ", " +
                                               formatExact(plausibleLimit(k.unit)) + "] " + k.unit +
                                               " for " + r.channel + ", got " +
                                               formatExact(r.value));
    auto key = std::make_pair(r.repetition, r.channel);
    auto it = last_.find(key);
    if (it != last_.end() && !(r.time_s > it->second))
      throw InputError(at() + ": time_s",
                       std::string(r.time_s == it->second ? "repeated" : "not increasing") +
                           " for repetition " + std::to_string(r.repetition) + " channel " +
                           r.channel + " (" + formatExact(r.time_s) + " after " +
                           formatExact(it->second) + ")");
    last_[key] = r.time_s;
  }

 private:
  const std::vector<Channel>& known_;
  std::map<std::pair<long, std::string>, double> last_;
};

}  // namespace

std::vector<std::string> LabData::channels() const {
  std::vector<std::string> out;
  for (const auto& r : records)
    if (std::find(out.begin(), out.end(), r.channel) == out.end()) out.push_back(r.channel);
  return out;
}

std::vector<long> LabData::repetitions() const {
  std::set<long> s;
  for (const auto& r : records) s.insert(r.repetition);
  return {s.begin(), s.end()};
}

std::vector<double> LabData::times(const std::string& channel) const {
  std::set<double> s;
  for (const auto& r : records)
    if (r.channel == channel) s.insert(r.time_s);
  return {s.begin(), s.end()};
}

double plausibleLimit(const std::string& unit) {
  static const std::map<std::string, double> limits = {
      {"N", 1e6},                    // 1 MN: about 70 times the weight of the vehicle on one wheel
      {"m", 10.0},                   // travel, deflection, heave, road height
      {"m/s", 200.0},                // speeds and deflection rates
      {"rad", 10.0},                 // pitch and roll angles
      {"m/s^2", 1e4},                // about 1000 g
      {"rad/s^2", 1e5}, {"s", 1e6},  // time since the scenario start: 11 days
  };
  const auto it = limits.find(unit);
  return it == limits.end() ? 1e12 : it->second;
}

std::vector<Channel> measurableChannels() { return measurableChannels({}); }

std::vector<Channel> measurableChannels(const std::vector<SensorSpec>& sensors) {
  std::vector<Channel> out;
  for (auto& c : runChannels(sensors))
    if (c.name != "time_s") out.push_back(c);
  return out;
}

std::string channelUnit(const std::vector<Channel>& known, const std::string& name) {
  for (const auto& c : known)
    if (c.name == name) return c.unit;
  return "";
}

std::string checkChannelName(const std::string& channel, const std::vector<Channel>& known) {
  for (const auto& k : known)
    if (k.name == channel) return {};
  if (channel.empty())
    return "is empty (expected a channel name with its unit suffix, e.g. hub_force_fl_N)";
  const auto us = channel.rfind('_');
  if (us != std::string::npos && us > 0) {
    const std::string stem = channel.substr(0, us), suffix = channel.substr(us + 1);
    for (const auto& k : known) {
      const auto ku = k.name.rfind('_');
      if (ku != std::string::npos && k.name.substr(0, ku) == stem)
        return "wrong unit suffix '_" + suffix + "' for " + stem + ": values must be in " + k.unit +
               ", named '" + k.name + "'";
    }
  }
  std::vector<std::string> names;
  names.reserve(known.size());
  for (const auto& k : known) names.push_back(k.name);
  const std::string hint = closestName(channel, names);
  return "unknown channel " + inQuotes(channel) +
         (hint.empty() ? std::string(" (`twin list` shows the channels; names end in their unit, "
                                     "e.g. hub_force_fl_N)")
                       : " (did you mean " + inQuotes(hint) + "?)");
}

void validateLabData(const LabData& data, const std::string& name,
                     const std::vector<Channel>& known) {
  if (data.records.empty()) throw InputError(name, "no records");
  validateLabData(
      data, [&](std::size_t i) { return name + ":" + std::to_string(i + 2); }, known);
}

void validateLabData(const LabData& data, const std::function<std::string(std::size_t)>& where,
                     const std::vector<Channel>& known) {
  LabChecker checker(known);
  for (std::size_t i = 0; i < data.records.size(); ++i)
    checker.check(data.records[i], [&] { return where(i); });
}

std::string labCsvText(const LabData& data, const std::vector<Channel>& known) {
  return labCsvText(
      data, [](std::size_t i) { return "lab data:" + std::to_string(i + 2); }, known);
}

std::string labCsvText(const LabData& data, const std::function<std::string(std::size_t)>& where,
                       const std::vector<Channel>& known) {
  if (data.records.empty()) throw InputError("lab data", "no records");
  validateLabData(data, where, known);
  std::string out = std::string(kLabHeader) + "\n";
  out.reserve(out.size() + data.records.size() * 48);
  for (const auto& r : data.records) {
    out += std::to_string(r.repetition);
    out += ',';
    out += formatExact(r.time_s);
    out += ',';
    out += r.channel;
    out += ',';
    out += formatExact(r.value);
    out += '\n';
  }
  return out;
}

void writeLabCsv(const std::string& path, const LabData& data, const std::vector<Channel>& known) {
  writeFileAtomic(path, labCsvText(data, known));
}

LabData parseLabCsv(const std::string& text, const std::string& name,
                    const std::vector<Channel>& known) {
  CsvReader csv(text, name);
  if (!csv.next())
    throw InputError(name, std::string("empty file (expected the header ") + kLabHeader + ")");
  // Header: exactly the four columns, in any order.
  const long header_line = csv.line();
  const std::string hwhere = csv.where() + ": header";
  const std::vector<std::string> header(csv.fields().begin(), csv.fields().end());
  int col[4] = {-1, -1, -1, -1};
  for (std::size_t i = 0; i < header.size(); ++i) {
    int which = -1;
    for (int c = 0; c < 4; ++c)
      if (header[i] == kLabColumns[c]) which = c;
    if (which < 0) {
      std::vector<std::string> names(std::begin(kLabColumns), std::end(kLabColumns));
      const std::string hint = closestName(header[i], names);
      throw InputError(
          hwhere, "unexpected column " + inQuotes(header[i]) +
                      (hint.empty() ? std::string() : " (did you mean " + inQuotes(hint) + "?)") +
                      "; expected exactly " + kLabHeader);
    }
    if (col[which] >= 0)
      throw InputError(hwhere, "column " + inQuotes(header[i]) + " appears twice");
    col[which] = static_cast<int>(i);
  }
  for (int c = 0; c < 4; ++c)
    if (col[c] < 0)
      throw InputError(hwhere, "missing column " + inQuotes(kLabColumns[c]) +
                                   "; expected exactly " + kLabHeader);

  LabData data;
  LabChecker checker(known);
  while (csv.next()) {
    const std::string at = csv.where();
    const auto& f = csv.fields();
    if (f.size() != 4)
      throw InputError(at, "expected 4 fields (" + std::string(kLabHeader) + "), got " +
                               std::to_string(f.size()));
    LabRecord r;
    const std::string_view rep = f[static_cast<std::size_t>(col[0])];
    std::uint64_t u = 0;
    if (!parseUnsigned(rep, u) || u == 0 || u > 1000000000ULL)
      throw InputError(at + ": repetition", "must be a positive integer, got " + inQuotes(rep));
    r.repetition = static_cast<long>(u);
    const std::string_view ts = f[static_cast<std::size_t>(col[1])];
    if (!parseNumber(ts, r.time_s))
      throw InputError(at + ": time_s", "must be a number (seconds), got " + inQuotes(ts));
    r.channel = std::string(f[static_cast<std::size_t>(col[2])]);
    const std::string_view vs = f[static_cast<std::size_t>(col[3])];
    if (!parseNumber(vs, r.value))
      throw InputError(at + ": value", "must be a number, got " + inQuotes(vs));
    // NOLINTNEXTLINE(performance-no-automatic-move): `at` is captured, not the lambda's own
    checker.check(r, [&] { return at; });
    data.records.push_back(std::move(r));
  }
  if (data.records.empty())
    throw InputError(name,
                     "no records after the header (line " + std::to_string(header_line) + ")");
  return data;
}

LabData readLabCsv(const std::string& path, const std::vector<Channel>& known) {
  return parseLabCsv(readTextFile(path), path, known);
}

// ------------------------------------------------------------------------------------ field

std::string fieldCsvText(const FieldData& d) {
  DTWIN_CHECK(d.values.size() == d.runs.size() * d.times_s.size(), "field data shape");
  DTWIN_CHECK(d.road_seeds.empty() || d.road_seeds.size() == d.runs.size(), "field road seeds");
  // Fewest decimals (up to 9) that write every time exactly enough to read it back to the grid.
  int dec = 0;
  for (; dec < 9; ++dec) {
    const double scale = std::pow(10.0, dec);
    bool ok = true;
    for (double t : d.times_s)
      ok = ok && std::abs(std::round(t * scale) / scale - t) <= 1e-9 * std::max(1.0, std::abs(t));
    if (ok) break;
  }
  std::string out = "run";
  if (!d.road_seeds.empty()) out += ",road_seed";
  for (double t : d.times_s) out += formatPrintf(",t_%.*f", dec, t);
  out += '\n';
  out.reserve(out.size() + d.values.size() * 19);
  char buf[32];  // the shortest exact form of a double fits in 24 characters
  for (std::size_t i = 0; i < d.rowCount(); ++i) {
    out += std::to_string(d.runs[i]);
    if (!d.road_seeds.empty()) {
      out += ',';
      out += std::to_string(d.road_seeds[i]);
    }
    for (std::size_t j = 0; j < d.columnCount(); ++j) {
      out += ',';
      auto r = std::to_chars(buf, buf + sizeof buf, d.at(i, j));
      out.append(buf, r.ptr);
    }
    out += '\n';
  }
  return out;
}

void writeFieldCsv(const std::string& path, const FieldData& data) {
  writeFileAtomic(path, fieldCsvText(data));
}

FieldData parseFieldCsv(const std::string& text, const std::string& name) {
  CsvReader csv(text, name);
  if (!csv.next())
    throw InputError(name, "empty file (expected the header run,road_seed,t_<seconds>,...)");
  const std::string hwhere = csv.where() + ": header";
  const std::vector<std::string> header(csv.fields().begin(), csv.fields().end());
  if (header.empty() || header[0] != "run")
    throw InputError(hwhere, "first column must be 'run', got " +
                                 inQuotes(header.empty() ? "" : header[0]) +
                                 " (expected run,road_seed,t_<seconds>,...)");
  FieldData d;
  const bool has_seed = header.size() > 1 && header[1] == "road_seed";
  const std::size_t first = has_seed ? 2 : 1;
  for (std::size_t i = first; i < header.size(); ++i) {
    const std::string& h = header[i];
    double t = 0;
    if (h.size() < 3 || h.compare(0, 2, "t_") != 0 || !parseNumber(h.substr(2), t))
      throw InputError(hwhere, "column " + std::to_string(i + 1) +
                                   " must be a time column 't_<seconds>' (e.g. t_10.000), got " +
                                   inQuotes(h));
    if (!std::isfinite(t) || t < 0)
      throw InputError(hwhere, "column " + inQuotes(h) + ": time must be finite and >= 0");
    if (!d.times_s.empty() && !(t > d.times_s.back()))
      throw InputError(hwhere,
                       "column " + inQuotes(h) + ": times must increase from column to column (" +
                           formatExact(t) + " after " + formatExact(d.times_s.back()) + ")");
    d.times_s.push_back(t);
  }
  if (d.times_s.empty())
    throw InputError(hwhere, "no time columns 't_<seconds>' after " +
                                 std::string(has_seed ? "run,road_seed" : "run"));
  std::set<long> seen;
  while (csv.next()) {
    const std::string at = csv.where();
    const auto& f = csv.fields();
    if (f.size() != header.size())
      throw InputError(at, "expected " + std::to_string(header.size()) +
                               " fields (one per header column), got " + std::to_string(f.size()));
    std::uint64_t u = 0;
    if (!parseUnsigned(f[0], u) || u == 0 || u > 1000000000ULL)
      throw InputError(at + ": run", "must be a positive integer, got " + inQuotes(f[0]));
    if (!seen.insert(static_cast<long>(u)).second)
      throw InputError(at + ": run", "run " + std::string(f[0]) + " appears twice");
    d.runs.push_back(static_cast<long>(u));
    if (has_seed) {
      std::uint64_t s = 0;
      if (!parseUnsigned(f[1], s))
        throw InputError(at + ": road_seed",
                         "must be an integer in [0, 2^64), got " + inQuotes(f[1]));
      d.road_seeds.push_back(s);
    }
    for (std::size_t i = first; i < f.size(); ++i) {
      double v = 0;
      if (!parseNumber(f[i], v))
        throw InputError(at + ": " + header[i], "must be a number, got " + inQuotes(f[i]));
      if (!std::isfinite(v))
        throw InputError(at + ": " + header[i], "must be finite, got " + std::string(f[i]));
      // The file does not name its channel: the widest plausible range of any unit.
      if (std::abs(v) > plausibleLimit(""))
        throw InputError(at + ": " + header[i],
                         "must lie in [-1e12, 1e12] (the plausible range of any channel), got " +
                             std::string(f[i]));
      d.values.push_back(v);
    }
  }
  if (d.runs.empty()) throw InputError(name, "no runs after the header");
  return d;
}

FieldData readFieldCsv(const std::string& path) { return parseFieldCsv(readTextFile(path), path); }

}  // namespace dtwin
