// An MF4 log's rows for `twin import` (readMdfRows, io/import_units.hpp): the mapping's channels
// found by name or GROUP/NAME, their units checked, every group resampled onto the time base of
// the time channel's group, then the checks a CSV's rows get (docs/measurements.md, "MF4 logs").
#include "io/import_units.hpp"
#include "io/log_import.hpp"
#include "io/mdf_log.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/names.hpp"

namespace dtwin {

namespace {

/// What one mapped column of the log is: the mapping's column, the role it plays, and where the
/// file holds it (group index, channel name).
struct MdfColumnRef {
  const ImportColumn* column = nullptr;
  std::string role;  ///< time, speed, road, channel, mask
  std::size_t group = 0;
  std::string channel;
};

/// A unit as a file may write it, normalised: "m/s²" is "m/s^2".
std::string mdfUnitText(std::string u) {
  while (!u.empty() && u.front() == ' ') u.erase(u.begin());
  while (!u.empty() && u.back() == ' ') u.pop_back();
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"\xc2\xb2", "^2"}, {"\xc2\xb3", "^3"}, {"\xc2\xb0", "deg"}})
    for (std::size_t at; (at = u.find(from)) != std::string::npos;) u.replace(at, from.size(), to);
  return u;
}

/// True when the file's unit is the mapping's: the same text, or two names of one unit (km/h and
/// kph). A file that gives no unit takes the mapping's.
bool mdfUnitFits(const std::string& file_unit, const std::string& declared) {
  const std::string f = mdfUnitText(file_unit), d = mdfUnitText(declared);
  if (f.empty() || f == d) return true;
  const Unit *uf = nullptr, *ud = nullptr;
  for (const auto& k : kUnits) {
    if (f == k.name) uf = &k;
    if (d == k.name) ud = &k;
  }
  return uf && ud && std::string(uf->si) == ud->si && uf->factor == ud->factor && f != "clock" &&
         d != "clock";
}

std::string mdfGroupLabel(const MdfDirectory& dir, std::size_t g) {
  return dir.groups[g].name.empty() ? "channel group " + std::to_string(g + 1)
                                    : "group '" + dir.groups[g].name + "'";
}

/// Every (group, channel) the column text names: NAME in any group, else GROUP/NAME.
std::vector<std::pair<std::size_t, std::string>> mdfMatches(const MdfDirectory& dir,
                                                            const std::string& text) {
  std::vector<std::pair<std::size_t, std::string>> out;
  for (std::size_t g = 0; g < dir.groups.size(); ++g)
    for (const auto& c : dir.groups[g].channels)
      if (c.name == text) out.emplace_back(g, c.name);
  const auto slash = text.rfind('/');
  if (out.empty() && slash != std::string::npos && slash > 0)
    for (std::size_t g = 0; g < dir.groups.size(); ++g)
      if (dir.groups[g].name == text.substr(0, slash))
        for (const auto& c : dir.groups[g].channels)
          if (c.name == text.substr(slash + 1)) out.emplace_back(g, c.name);
  return out;
}

/// "no channel 'X' (...); near: 'A', 'B/A'".
InputError mdfMissing(const MdfDirectory& dir, const std::string& name, const ImportColumn& c) {
  std::vector<std::string> all;
  for (const auto& g : dir.groups)
    for (const auto& ch : g.channels) {
      all.push_back(ch.name);
      if (!g.name.empty()) all.push_back(g.name + "/" + ch.name);
    }
  std::vector<std::string> near;
  std::vector<std::string> pool = all;
  for (int k = 0; k < 3; ++k) {
    const std::string hint = closestName(c.column, pool);
    if (hint.empty()) break;
    near.push_back("'" + hint + "'");
    pool.erase(std::remove(pool.begin(), pool.end(), hint), pool.end());
  }
  std::string rule = "no channel '" + c.column + "' (" + c.where + ")";
  if (!near.empty()) {
    rule += "; near: " + near[0];
    for (std::size_t i = 1; i < near.size(); ++i) rule += ", " + near[i];
  } else {
    rule += "; the file holds " + std::to_string(all.size()) + " channel names";
  }
  return InputError(name, rule);
}

/// The time base: the group of the time channel. A time name several groups' masters share is
/// taken from the group of the first mapped channel that has it, else the speed's.
std::size_t mdfTimeGroup(const MdfDirectory& dir, const std::string& name, const ImportMapping& m,
                         const std::vector<std::pair<std::size_t, std::string>>& time,
                         const std::vector<MdfColumnRef>& refs) {
  for (const auto& [g, ch] : time)
    for (const auto& c : dir.groups[g].channels)
      if (c.name == ch && !c.master)
        throw InputError(
            name + ": channel '" + ch + "' (" + mdfGroupLabel(dir, g) + ")",
            "is not its group's master channel: the time must be a master (" + m.time.where + ")");
  if (time.size() == 1) return time[0].first;
  for (const char* role : {"channel", "speed"})
    for (const auto& r : refs)
      if (r.role == role)
        for (const auto& [g, ch] : time)
          if (g == r.group) return g;
  std::string groups;
  for (const auto& [g, ch] : time) groups += (groups.empty() ? "" : ", ") + mdfGroupLabel(dir, g);
  throw InputError(name, "the time channel '" + m.time.column + "' is the master of " + groups +
                             ", and no mapped channel is in one of them: write GROUP/" +
                             m.time.column + " (" + m.time.where + ")");
}

/// `y` (at times `ts`) at the base times `t`: linear interpolation between the two samples around
/// each time, the sample itself at a time it has; NaN where either neighbour is NaN. Times
/// outside [ts.front(), ts.back()] are never asked for.
std::vector<double> mdfResample(const std::vector<double>& ts, const std::vector<double>& y,
                                const std::vector<double>& t) {
  std::vector<double> out(t.size());
  std::size_t j = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    while (j + 1 < ts.size() && ts[j + 1] <= t[i]) ++j;
    if (ts[j] == t[i] || j + 1 >= ts.size()) {
      out[i] = y[j];
      continue;
    }
    const double w = (t[i] - ts[j]) / (ts[j + 1] - ts[j]);
    out[i] = y[j] + (y[j + 1] - y[j]) * w;
  }
  return out;
}

/// The rows on the time base `tb` with the checks a CSV's rows get, sample by sample
/// (log_import.cpp, LogRowReader): `refs` in the order speed, roads, channels, masks; `column`
/// gives a ref's values on the base, `sampleWhere` names a sample in an error.
template <class Column, class Where>
LogRows mdfCheckedRows(const ImportMapping& m, const ImportUnits& u,
                       const std::vector<MdfColumnRef>& refs, const std::vector<double>& tb,
                       const Column& column, const Where& sampleWhere) {
  LogRows rows;
  rows.t = tb;
  std::size_t k = 0;
  {
    const auto& r = refs[k++];
    const auto v = column(r);
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!std::isfinite(v[i]))
        throw InputError(sampleWhere(r, i), "is invalid or NaN (a required channel has no gaps)");
      double vi = (v[i] - m.speed->offset) * m.speed->scale * u.speed;
      if (vi < 0 && vi >= -0.2) vi = 0.0;  // a logger's noise about standstill
      if (vi < 0)
        throw InputError(sampleWhere(r, i),
                         "speed " + formatNumber(v[i]) + " " + m.speed->unit +
                             " is negative (beyond the 0.2 m/s of noise at rest)");
      if (vi > 100)
        throw InputError(sampleWhere(r, i),
                         "speed " + formatNumber(v[i]) + " " + m.speed->unit + " exceeds 100 m/s");
      rows.v.push_back(vi);
    }
  }
  for (std::size_t q = 0; q < u.road_cols.size(); ++q) {
    const auto& r = refs[k++];
    auto v = column(r);
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!std::isfinite(v[i]))
        throw InputError(sampleWhere(r, i), "is invalid or NaN (a required channel has no gaps)");
      v[i] = (v[i] - r.column->offset) * r.column->scale * u.road[q];
    }
    rows.road.push_back(std::move(v));
  }
  for (std::size_t q = 0; q < m.channels.size(); ++q) {
    const auto& r = refs[k++];
    auto v = column(r);
    long run = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (std::isnan(v[i])) {
        if (++run > m.max_dropout_rows)
          throw InputError(sampleWhere(r, i - static_cast<std::size_t>(run) + 1),
                           "invalid or NaN from here on: more than max_dropout_rows = " +
                               std::to_string(m.max_dropout_rows) + " samples in a row");
        ++rows.dropped_cells;
        continue;
      }
      if (!std::isfinite(v[i])) throw InputError(sampleWhere(r, i), "is not a finite number");
      run = 0;
      v[i] = (v[i] - r.column->offset) * r.column->scale * u.channel[q];
    }
    rows.values.push_back(std::move(v));
  }
  for (const auto& mk : m.exclude) {
    const auto& r = refs[k++];
    auto v = column(r);
    const double f = anyUnit(mk.source.unit, mk.source.where).first;
    for (auto& x : v)
      x = std::isnan(x) ? x : std::abs((x - mk.source.offset) * mk.source.scale * f);
    rows.mask.push_back(std::move(v));
  }
  return rows;
}

/// What an MF4 import read, for the sidecar: the groups and channels, the time base, the samples
/// dropped outside other groups' spans and the resampling rule.
nlohmann::json mdfProvenance(const MdfDirectory& dir,
                             const std::map<std::size_t, MdfGroupData>& data, std::size_t base,
                             std::size_t dropped) {
  nlohmann::json groups = nlohmann::json::array();
  for (const auto& [g, d] : data) {
    nlohmann::json chans = nlohmann::json::array();
    for (const auto& c : d.channels)
      chans.push_back({{"name", c.name}, {"unit", c.unit}, {"conversion", c.conversion}});
    groups.push_back({{"group", dir.groups[g].name},
                      {"index", g + 1},
                      {"master", d.master},
                      {"master_unit", d.master_unit},
                      {"samples", d.time.size()},
                      {"time_base", g == base},
                      {"channels", chans}});
  }
  return {
      {"format", "MDF " + dir.version},
      {"groups_read", groups},
      {"time_base",
       {{"group", dir.groups[base].name}, {"index", base + 1}, {"master", data.at(base).master}}},
      {"samples_outside_other_groups", static_cast<long>(dropped)},
      {"rule",
       "every mapped channel is read on the time base (the master of the time channel's group); a "
       "channel of another group is "
       "interpolated linearly between its two samples around each base time (its own sample at a "
       "time it has); base samples "
       "outside another used group's first..last time are dropped (no extrapolation) and counted "
       "here"}};
}

}  // namespace

LogRows readMdfRows(const std::string& bytes, const std::string& name, const ImportMapping& m,
                    const ImportUnits& u, nlohmann::json& provenance) {
  if (m.time.unit == "clock")
    throw InputError(m.time.where,
                     "an MF4 log's time is a master channel in seconds: unit 'clock' is for a "
                     "CSV's times of day");
  const MdfDirectory dir = readMdfDirectory(bytes, name);
  std::vector<MdfColumnRef> refs;
  refs.push_back({&*m.speed, "speed", 0, ""});
  for (const auto* c : u.road_cols) refs.push_back({c, "road", 0, ""});
  for (const auto& c : m.channels) refs.push_back({&c.source, "channel", 0, ""});
  for (const auto& k : m.exclude) refs.push_back({&k.source, "mask", 0, ""});
  for (auto& r : refs) {
    const auto found = mdfMatches(dir, r.column->column);
    if (found.empty()) throw mdfMissing(dir, name, *r.column);
    if (found.size() > 1) {
      std::string groups;
      for (const auto& [g, ch] : found)
        groups += (groups.empty() ? "" : ", ") + mdfGroupLabel(dir, g);
      throw InputError(name, "channel '" + r.column->column + "' (" + r.column->where + ") is in " +
                                 groups + ": name one as GROUP/" + r.column->column);
    }
    r.group = found[0].first;
    r.channel = found[0].second;
  }
  const auto time = mdfMatches(dir, m.time.column);
  if (time.empty()) throw mdfMissing(dir, name, m.time);
  const std::size_t base = mdfTimeGroup(dir, name, m, time, refs);
  // Units: the file's against the mapping's, for every column before any data is read.
  for (const auto& r : refs)
    for (const auto& c : dir.groups[r.group].channels)
      if (c.name == r.channel && !mdfUnitFits(c.unit, r.column->unit))
        throw InputError(
            name + ": channel '" + r.channel + "' (" + mdfGroupLabel(dir, r.group) + ")",
            "the file gives its unit as '" + c.unit + "', the mapping declares '" + r.column->unit +
                "' (" + r.column->where + ")");
  // Each group read once: its master and the channels mapped in it.
  std::map<std::size_t, std::vector<std::string>> wanted;
  wanted[base];
  for (const auto& r : refs) {
    auto& w = wanted[r.group];
    if (std::find(w.begin(), w.end(), r.channel) == w.end()) w.push_back(r.channel);
  }
  std::map<std::size_t, MdfGroupData> data;
  std::map<std::size_t, double> time_factor;
  for (const auto& [g, channels] : wanted) {
    data[g] = readMdfGroup(bytes, name, g, channels);
    const auto& d = data[g];
    const std::string where = name + ": master '" + d.master + "' (" + mdfGroupLabel(dir, g) + ")";
    if (g == base && !mdfUnitFits(d.master_unit, m.time.unit))
      throw InputError(where, "the file gives its unit as '" + d.master_unit +
                                  "', the mapping declares '" + m.time.unit + "' (" + m.time.where +
                                  ")");
    time_factor[g] =
        g == base
            ? u.time
            : unitFactor(d.master_unit.empty() ? "s" : mdfUnitText(d.master_unit), "s", where);
    for (std::size_t i = 1; i < d.time.size(); ++i)
      if (!(d.time[i] > d.time[i - 1]))
        throw InputError(where + " at sample " + std::to_string(i),
                         d.time[i] == d.time[i - 1]
                             ? "time " + formatNumber(d.time[i], 12) + " repeats the sample before"
                             : "time goes backwards: " + formatNumber(d.time[i], 12) + " after " +
                                   formatNumber(d.time[i - 1], 12));
    if (d.time.size() < 2)
      throw InputError(
          where, "holds " + std::to_string(d.time.size()) + " samples; a drive needs at least 2");
  }
  // The base rows inside every used group's span (no extrapolation).
  const MdfGroupData& bd = data[base];
  std::vector<double> t(bd.time.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = bd.time[i] * u.time;
  std::size_t first = 0, last = t.size();  // [first, last)
  std::map<std::size_t, std::vector<double>> ts;
  for (const auto& [g, d] : data) {
    auto& s = ts[g];
    for (double x : d.time) s.push_back(x * time_factor[g]);
    while (first < last && t[first] < s.front()) ++first;
    while (last > first && t[last - 1] > s.back()) --last;
  }
  if (last - first < 2)
    throw InputError(
        name, "its channel groups' times overlap in fewer than 2 samples of the time base (" +
                  mdfGroupLabel(dir, base) + ")");
  const std::vector<double> tb(t.begin() + static_cast<std::ptrdiff_t>(first),
                               t.begin() + static_cast<std::ptrdiff_t>(last));
  auto column = [&](const MdfColumnRef& r) {
    const auto& d = data[r.group];
    for (const auto& c : d.channels)
      if (c.name == r.channel) {
        if (r.group == base)
          return std::vector<double>(c.values.begin() + static_cast<std::ptrdiff_t>(first),
                                     c.values.begin() + static_cast<std::ptrdiff_t>(last));
        return mdfResample(ts[r.group], c.values, tb);
      }
    throw InputError(name, "internal: channel '" + r.channel + "' was not read");
  };
  auto sampleWhere = [&](const MdfColumnRef& r, std::size_t i) {
    return name + ": channel '" + r.channel + "' (" + mdfGroupLabel(dir, r.group) + ") at " +
           formatNumber(tb[i], 12) + " s";
  };
  LogRows rows = mdfCheckedRows(m, u, refs, tb, column, sampleWhere);
  provenance = mdfProvenance(dir, data, base, t.size() - (last - first));
  return rows;
}

}  // namespace dtwin
