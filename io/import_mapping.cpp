// The column map of a log import (log_import.hpp ImportMapping): the mapping file's reader, the
// command line's column and separator forms, the units and their factors to SI, the masks.
#include "io/import_units.hpp"
#include "io/log_import.hpp"

#include <array>
#include <cctype>
#include <cmath>

#include <toml++/toml.h>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/names.hpp"
#include "common/toml_reader.hpp"
#include "io/study.hpp"

namespace dtwin {

namespace {

std::string unitList(const std::string& si) {
  std::string out;
  for (const auto& u : kUnits)
    if (si.empty() || u.si == si) out += (out.empty() ? "" : ", ") + std::string(u.name);
  return out;
}

}  // namespace

/// A mask's unit: its factor to SI and the SI unit, whatever the quantity (a yaw rate, a speed, a
/// lateral acceleration); InputError(where) for a unit no log column may have.
std::pair<double, std::string> anyUnit(const std::string& unit, const std::string& where) {
  for (const auto& u : kUnits)
    if (unit == u.name && unit != "clock") return {u.factor, u.si};
  throw InputError(where, "unknown unit '" + unit + "' (known: " + unitList("") + ")");
}

namespace {

/// One mask table { column, unit, above and/or below, offset, scale }.
ImportMask readMask(const toml::table& t, const std::string& file, const std::string& field) {
  TableReader r(t, file, field);
  ImportMask k;
  const auto col = r.string("column");
  if (!col || col->empty())
    throw InputError(r.where("column"), "is required (the log's column the mask reads)");
  k.source.column = *col;
  k.source.where = r.where("column");
  const auto unit = r.string("unit");
  if (!unit)
    throw InputError(r.where("unit"),
                     "is required (the unit of the column and of the thresholds, e.g. \"rad/s\")");
  k.source.unit = *unit;
  const auto [factor, si] = anyUnit(*unit, r.where("unit"));
  k.si = si;
  k.source.offset = r.number("offset", 0.0);
  k.source.scale = r.number("scale", 1.0);
  if (k.source.scale == 0) throw InputError(r.where("scale"), "must not be 0");
  for (const char* side : {"above", "below"})
    if (auto v = r.number(side)) {
      if (*v < 0)
        throw InputError(
            r.where(side),
            "must be >= 0 (a mask compares the magnitude |value|), got " + formatNumber(*v));
      (std::string(side) == "above" ? k.above : k.below) = *v * factor;
    }
  if (!k.above && !k.below)
    throw InputError(r.where("above"), "a mask needs above or below (or both)");
  k.pad_s = r.number("pad_s", 0.0);
  if (!(k.pad_s >= 0 && k.pad_s <= 60))
    throw InputError(
        r.where("pad_s"),
        "must lie in [0, 60] s (rows this close to a masked one are masked too), got " +
            formatNumber(k.pad_s));
  r.finish();
  return k;
}

ImportColumn readColumn(TableReader& r, const std::string& key, const std::string& default_unit) {
  ImportColumn c;
  c.where = r.where(key);
  if (const toml::table* t = r.isTable(key) ? r.table(key) : nullptr) {
    TableReader cr(*t, r.file(), r.field(key));
    const auto col = cr.string("column");
    if (!col || col->empty())
      throw InputError(cr.where("column"), "is required (the log's column name)");
    c.column = *col;
    c.unit = cr.string("unit").value_or(default_unit);
    if (cr.has("unit")) c.unit_where = cr.where("unit");
    if (c.unit.empty()) throw InputError(cr.where("unit"), "is required (" + unitList("") + ")");
    c.offset = cr.number("offset", 0.0);
    c.scale = cr.number("scale", 1.0);
    if (c.scale == 0) throw InputError(cr.where("scale"), "must not be 0");
    cr.finish();
    return c;
  }
  const auto s = r.string(key);  // the short form: just the column name
  c.column = s.value_or("");
  c.unit = default_unit;
  if (c.column.empty())
    throw InputError(r.where(key), "must be a column name or { column, unit, offset, scale }");
  if (c.unit.empty())
    throw InputError(r.where(key),
                     "needs a unit: write { column = \"" + c.column + "\", unit = \"...\" }");
  return c;
}

/// road_fl, road_fr, road_rl, road_rr: all four or none, and then no road, road_left or road_right.
void readWheelRoads(TableReader& r, ImportMapping& m) {
  static const char* kKeys[4] = {"road_fl", "road_fr", "road_rl", "road_rr"};
  int given = 0;
  for (const char* k : kKeys) given += r.has(k) ? 1 : 0;
  if (given == 0) return;
  for (const char* k : kKeys)
    if (r.has(k) && (m.road || m.road_left))
      throw InputError(r.where(k), std::string("give either ") +
                                       (m.road ? "road" : "road_left and road_right") +
                                       " (the road under the axles) or road_fl, road_fr, road_rl "
                                       "and road_rr (each wheel's motion), not both");
  for (const char* k : kKeys)
    if (!r.has(k))
      throw InputError(r.where(k),
                       "is required with the other wheels' columns (road_fl, road_fr, road_rl and "
                       "road_rr: all four or none)");
  for (std::size_t c = 0; c < 4; ++c) m.road_wheels[c] = readColumn(r, kKeys[c], "");
}
}  // namespace

char parseSeparator(const std::string& text, const std::string& where) {
  if (text == "tab" || text == "\t") return '\t';
  if (text == "whitespace" || text == " ") return ' ';
  if (text.size() != 1 || text == "\"" || text == "\n" || text == "\r" ||
      std::isalnum(static_cast<unsigned char>(text[0])) || text == "." || text == "-" ||
      text == "+")
    throw InputError(where,
                     "must be one character such as \",\", \";\" or \"|\", or \"tab\" or "
                     "\"whitespace\" (a run of spaces and tabs), got \"" +
                         text + "\"");
  return text[0];
}

double unitFactor(const std::string& unit, const std::string& si, const std::string& where) {
  for (const auto& u : kUnits)
    if (unit == u.name) {
      if (si != u.si)
        throw InputError(where, "unit '" + unit + "' is in " + u.si + ", but this needs " + si +
                                    " (" + unitList(si) + ")");
      return u.factor;
    }
  throw InputError(where,
                   "unknown unit '" + unit + "' (known for " + si + ": " + unitList(si) + ")");
}

ImportColumn parseImportColumn(const std::string& text, const std::string& flag,
                               const std::string& default_unit) {
  const std::vector<std::string> parts = splitOn(text, ':');
  if (parts[0].empty() || parts.size() > 4)
    throw InputError(flag, "expects COLUMN[:UNIT[:OFFSET[:SCALE]]], got '" + text + "'");
  ImportColumn c;
  c.where = flag;
  c.column = parts[0];
  c.unit = parts.size() > 1 ? parts[1] : default_unit;
  if (c.unit.empty()) throw InputError(flag, "'" + text + "' needs a unit: COLUMN:UNIT");
  auto num = [&](std::size_t i, double& v) {
    if (parts.size() > i && (!parseNumber(parts[i], v) || !std::isfinite(v)))
      throw InputError(flag, "'" + parts[i] + "' in '" + text + "' is not a finite number");
  };
  num(2, c.offset);
  num(3, c.scale);
  if (c.scale == 0) throw InputError(flag, "the scale in '" + text + "' must not be 0");
  return c;
}

std::string ImportMask::text() const {
  std::string s;
  if (above) s = "|" + source.column + "| > " + formatNumber(*above) + " " + si;
  if (below)
    s += (s.empty() ? "" : " or ") + std::string("|") + source.column + "| < " +
         formatNumber(*below) + " " + si;
  if (pad_s > 0) s += " (and " + formatNumber(pad_s) + " s around)";
  return s;
}

namespace {
/// [import]'s window_s, run_in_s and exclude into `m` (docs/measurements.md, "Windows and masks").
void readWindowAndMasks(TableReader& r, const std::string& path, ImportMapping& m) {
  if (const toml::array* w = r.array("window_s")) {
    m.window_where = r.where("window_s");
    if (w->size() != 2 || !(*w)[0].is_number() || !(*w)[1].is_number())
      throw InputError(m.window_where, "must be [start, end] in seconds from the log's first row");
    m.window_s = std::array<double, 2>{*(*w)[0].value<double>(), *(*w)[1].value<double>()};
    if (!((*m.window_s)[0] >= 0 && (*m.window_s)[0] < (*m.window_s)[1]))
      throw InputError(m.window_where, "must be [start, end] with 0 <= start < end, got [" +
                                           formatNumber((*m.window_s)[0]) + ", " +
                                           formatNumber((*m.window_s)[1]) + "]");
  }
  if (r.has("run_in_s")) {
    m.run_in_s = *r.number("run_in_s");
    if (!(m.run_in_s >= 0 && m.run_in_s <= 3600))
      throw InputError(r.where("run_in_s"),
                       "must lie in [0, 3600] s, got " + formatNumber(m.run_in_s));
    if (!m.window_s)
      throw InputError(r.where("run_in_s"),
                       "needs window_s (the run-in is the log before the window)");
  }
  if (r.isTable("exclude")) {
    m.exclude.push_back(readMask(*r.table("exclude"), path, r.field("exclude")));
  } else if (const toml::array* ex = r.array("exclude")) {
    for (std::size_t i = 0; i < ex->size(); ++i) {
      const auto* t = (*ex)[i].as_table();
      const std::string field = r.field("exclude") + "[" + std::to_string(i) + "]";
      if (!t)
        throw InputError(r.where("exclude"),
                         field + " must be a table { column, unit, above, below }");
      m.exclude.push_back(readMask(*t, path, field));
    }
  }
}
}  // namespace

ImportMapping readImportMapping(const std::string& path) {
  const std::string text = readTextFile(path, " (an import mapping)");
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line),
                     "malformed TOML: " + std::string(e.description()));
  }
  TableReader top(root, path, "");
  ImportMapping m;
  m.source = path;
  auto* it = top.table("import");
  if (!it) throw InputError(path, "has no [import] table (time, speed, road, [[import.channels]])");
  TableReader r(*it, path, "import");
  if (!r.has("time")) throw InputError(r.where("time"), "is required (the log's time column)");
  m.time = readColumn(r, "time", "s");
  if (!r.has("speed"))
    throw InputError(
        r.where("speed"),
        "is required (the log's speed column, e.g. { column = \"speed\", unit = \"km/h\" })");
  m.speed = readColumn(r, "speed", "");
  if (r.has("road")) m.road = readColumn(r, "road", "");
  if (r.has("road_left") || r.has("road_right")) {
    if (m.road)
      throw InputError(r.where("road_left"),
                       "give either road (both tracks) or road_left and road_right");
    if (!r.has("road_left") || !r.has("road_right"))
      throw InputError(r.where(r.has("road_left") ? "road_right" : "road_left"),
                       "is required with the other track's column");
    m.road_left = readColumn(r, "road_left", "");
    m.road_right = readColumn(r, "road_right", "");
  }
  readWheelRoads(r, m);
  if (r.has("highpass_hz")) {
    m.highpass_given = true;
    m.highpass_hz = *r.number("highpass_hz");
    if (!(m.highpass_hz >= 1e-3 && m.highpass_hz <= 10))
      throw InputError(r.where("highpass_hz"),
                       "must lie in [1e-3, 10] Hz, got " + formatNumber(m.highpass_hz));
  }
  if (r.has("speed_lowpass_hz")) {
    m.speed_lowpass_hz = *r.number("speed_lowpass_hz");
    if (!(m.speed_lowpass_hz >= 0.01 && m.speed_lowpass_hz <= 100))
      throw InputError(r.where("speed_lowpass_hz"),
                       "must lie in [0.01, 100] Hz, got " + formatNumber(m.speed_lowpass_hz));
  }
  if (auto sep = r.string("separator")) m.separator = parseSeparator(*sep, r.where("separator"));
  m.decimal_comma = r.boolean("decimal_comma").value_or(false);
  if (auto k = r.integer("header_line")) {
    if (*k < 1 || *k > 1000)
      throw InputError(r.where("header_line"), "must lie in [1, 1000], got " + std::to_string(*k));
    m.header_line = *k;
  }
  if (auto k = r.integer("skip_rows")) {
    if (*k < 0 || *k > 1000)
      throw InputError(r.where("skip_rows"), "must lie in [0, 1000], got " + std::to_string(*k));
    m.skip_rows = *k;
  }
  if (auto k = r.integer("max_dropout_rows")) {
    if (*k < 0 || *k > 1000000)
      throw InputError(r.where("max_dropout_rows"),
                       "must lie in [0, 1e6], got " + std::to_string(*k));
    m.max_dropout_rows = *k;
  }
  if (m.decimal_comma && m.separator == ',')
    throw InputError(r.where("decimal_comma"),
                     "needs a separator other than ',' (e.g. separator = \";\")");
  readWindowAndMasks(r, path, m);
  const toml::array* chans = r.array("channels");
  if (!chans || chans->empty())
    throw InputError(r.where("channels"),
                     "needs at least one [[import.channels]] (column, channel, unit)");
  for (std::size_t i = 0; i < chans->size(); ++i) {
    const auto* t = (*chans)[i].as_table();
    const std::string field = "import.channels[" + std::to_string(i) + "]";
    if (!t)
      throw InputError(r.where("channels"), field + " must be a table (column, channel, unit)");
    TableReader cr(*t, path, field);
    ImportChannel c;
    const auto ch = cr.string("channel");
    if (!ch || ch->empty())
      throw InputError(cr.where("channel"),
                       "is required (a channel of the twin or of a sensor, e.g. seat_mps2)");
    c.channel = *ch;
    c.source.where = cr.where("column");
    const auto col = cr.string("column");
    if (!col || col->empty())
      throw InputError(cr.where("column"), "is required (the log's column name)");
    c.source.column = *col;
    const auto unit = cr.string("unit");
    if (!unit) throw InputError(cr.where("unit"), "is required (" + unitList("") + ")");
    c.source.unit = *unit;
    c.source.unit_where = cr.where("unit");
    c.source.offset = cr.number("offset", 0.0);
    c.source.scale = cr.number("scale", 1.0);
    if (c.source.scale == 0) throw InputError(cr.where("scale"), "must not be 0");
    cr.finish();
    m.channels.push_back(c);
  }
  r.finish();
  m.sensors = readSensorTables(top);
  top.finish();
  return m;
}

}  // namespace dtwin
