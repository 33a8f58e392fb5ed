// A logger's CSV imported (importLog): its rows read through the column map and resampled onto the
// output grid, the imported study and data files with their sidecar (writeImport); clock times.
#include "io/log_import.hpp"
#include "io/import_units.hpp"
#include "io/mdf_log.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include <toml++/toml.h>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/names.hpp"
#include "common/statistics.hpp"
#include "common/toml_reader.hpp"
#include "io/provenance.hpp"
#include "io/study.hpp"
#include "subsystems/time_road.hpp"
#include "twin/trace.hpp"

namespace fs = std::filesystem;

namespace dtwin {

namespace {

/// The index of `c`'s column in the header, or an InputError naming the log and the mapping field.
std::size_t columnIndex(const std::vector<std::string>& header, const ImportColumn& c,
                        const std::string& log_name) {
  std::size_t found = header.size();
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == c.column) {
      if (found != header.size())
        throw InputError(log_name + ":1",
                         "column '" + c.column + "' appears twice in the header (" + c.where + ")");
      found = i;
    }
  if (found == header.size()) {
    const std::string hint = closestName(c.column, header);
    throw InputError(log_name + ":1",
                     "no column '" + c.column + "' (" + c.where + ")" +
                         (hint.empty() ? std::string() : "; did you mean '" + hint + "'?"));
  }
  return found;
}

bool isMissing(std::string_view f) {
  if (f.empty()) return true;
  std::string s(f);
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return s == "nan" || s == "na" || s == "n/a" || s == "null" || s == "-nan";
}

/// The base study's text with every relative path (the vehicle, a scenario's speed trace or road
/// file) made absolute in place: the rest of the file (its order, which sets the assemblies, and
/// its comments) is kept byte for byte.
std::string absolutizedStudyText(const std::string& text, const toml::table& root,
                                 const fs::path& folder, const std::string& name) {
  struct Patch {
    std::size_t line, begin, end;  // 1-based line, [begin, end) 1-based columns
    std::string with;
  };
  std::vector<Patch> patches;
  auto fix = [&](const toml::node* n) {
    if (!n || !n->is_string()) return;
    const fs::path p(n->value<std::string>().value());
    if (!p.is_relative()) return;
    const auto& src = n->source();
    if (src.begin.line != src.end.line)
      throw InputError(
          name + ":" + std::to_string(src.begin.line),
          "a path written over several lines cannot be rewritten: write it on one line");
    std::string quoted = "\"";
    for (char c : (folder / p).lexically_normal().string()) {
      if (c == '\\' || c == '"') quoted += '\\';
      quoted += c;
    }
    patches.push_back({src.begin.line, src.begin.column, src.end.column, quoted + "\""});
  };
  if (const auto* st = root["study"].as_table()) fix(st->get("vehicle"));
  if (const auto* sc = root["scenarios"].as_table())
    for (auto&& [key, node] : *sc)
      if (const auto* t = node.as_table()) {
        if (const auto* sp = t->get("speed"); sp && sp->is_table()) fix(sp->as_table()->get("csv"));
        if (const auto* rd = t->get("road"); rd && rd->is_table()) fix(rd->as_table()->get("path"));
      }
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  std::sort(patches.begin(), patches.end(), [](const Patch& a, const Patch& b) {
    return a.line != b.line ? a.line > b.line : a.begin > b.begin;
  });
  for (const auto& pt : patches) {
    std::string& l = lines.at(pt.line - 1);
    const std::size_t b = pt.begin - 1, e = pt.end - 1;
    if (e > l.size() || e <= b || (l[b] != '"' && l[b] != '\'') ||
        (l[e - 1] != '"' && l[e - 1] != '\''))
      throw InputError(
          name + ":" + std::to_string(pt.line),
          "cannot locate the path on this line to make it absolute: write it as an absolute path");
    l.replace(b, e - b, pt.with);
  }
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

/// Days from 1970-01-01 to y-m-d, proleptic Gregorian (H. Hinnant's days_from_civil).
long daysFromCivil(long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long>(doe) - 719468;
}

unsigned daysInMonth(long y, unsigned m) {
  static const unsigned k[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
  return m == 2 && leap ? 29 : k[m - 1];
}

}  // namespace

bool parseClockTime(std::string_view text, ClockTime& out) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  std::size_t i = 0;
  // Exactly `n` digits (n > 0) or, with n == 0, one or two.
  auto digits = [&](int n, long& v) {
    const std::size_t begin = i;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) &&
           (n == 0 ? i - begin < 2 : static_cast<int>(i - begin) < n))
      ++i;
    const std::size_t len = i - begin;
    if (len == 0 || (n > 0 && static_cast<int>(len) != n)) return false;
    v = std::stol(std::string(text.substr(begin, len)));
    return true;
  };
  auto take = [&](char c) {
    if (i < text.size() && text[i] == c) return ++i, true;
    return false;
  };
  ClockTime r;
  long y = 0, mo = 0, d = 0;
  if (text.size() >= 10 && (text[4] == '-' || text[4] == '/')) {
    const char sep = text[4];
    if (!digits(4, y) || !take(sep) || !digits(2, mo) || !take(sep) || !digits(2, d)) return false;
    if (mo < 1 || mo > 12 || d < 1 ||
        d > static_cast<long>(daysInMonth(y, static_cast<unsigned>(mo))))
      return false;
    if (!take('T') && !take(' ')) return false;
    r.has_date = true;
    r.day = daysFromCivil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d));
  }
  long h = 0, mi = 0, sec = 0;
  if (!digits(0, h) || !take(':') || !digits(2, mi) || !take(':') || !digits(2, sec)) return false;
  if (h > 23 || mi > 59 || sec > 60) return false;  // 60: a leap second
  double frac = 0.0;
  if (i < text.size() && (text[i] == '.' || text[i] == ',')) {
    ++i;
    double scale = 0.1;
    const std::size_t begin = i;
    for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i, scale *= 0.1)
      frac += (text[i] - '0') * scale;
    if (i == begin) return false;
  }
  double offset_s = 0.0;
  if (take('Z')) {
  } else if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
    const double sign = text[i++] == '+' ? 1.0 : -1.0;
    long oh = 0, om = 0;
    if (!digits(2, oh)) return false;
    take(':');
    if (!digits(2, om) || oh > 23 || om > 59) return false;
    offset_s = sign * static_cast<double>(oh * 3600 + om * 60);
  }
  if (i != text.size()) return false;
  double s = static_cast<double>(h * 3600 + mi * 60 + sec) + frac - offset_s;  // UTC
  const double day_shift = std::floor(s / 86400.0);
  r.day += static_cast<long>(day_shift);
  r.seconds = s - day_shift * 86400.0;
  out = r;
  return true;
}

namespace {

/// The mapping's sensors the study does not have yet. One it has, mounted and filtered the same
/// (a second drive of the same car imported into the first drive's study), is kept as it is; a
/// sensor of the same name mounted otherwise is an error.
std::vector<SensorSpec> newSensors(const Study& base, const ImportMapping& m,
                                   const std::string& base_study) {
  std::vector<SensorSpec> out;
  for (const auto& x : m.sensors) {
    bool known = false;
    for (const auto& y : base.sensors)
      if (y.name == x.name) {
        if (y.toJson() != x.toJson())
          throw InputError(m.source + ": sensors." + x.name,
                           "the study " + base_study +
                               " has a sensor of this name already, otherwise (" +
                               y.toJson().dump() + "): rename one");
        known = true;
      }
    if (!known) out.push_back(x);
  }
  return out;
}

/// The channels a log may fill: the study's sensors and the mapping's, and a check of the
/// scenario's name against the study.
std::vector<Channel> checkTarget(const Study& base, const ImportMapping& m,
                                 const std::string& base_study, const std::string& scenario) {
  std::vector<SensorSpec> sensors = base.sensors;
  for (const auto& x : newSensors(base, m, base_study)) sensors.push_back(x);
  for (const auto& sc : base.scenarios)
    if (sc.name == scenario)
      throw InputError("--scenario " + scenario,
                       "the study " + base_study + " already has a scenario of this name");
  bool name_ok = !scenario.empty();
  for (char ch : scenario)
    name_ok = name_ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-');
  if (!name_ok) throw InputError("--scenario " + scenario, "must be letters, digits, '_' and '-'");
  return measurableChannels(sensors);
}

ImportUnits resolveUnits(const ImportMapping& m, const std::vector<Channel>& known) {
  ImportUnits u;
  u.time = unitFactor(m.time.unit, "s", m.time.unitWhere());
  if (!m.speed) throw InputError(m.source + ": import.speed", "is required");
  u.speed = unitFactor(m.speed->unit, "m/s", m.speed->unitWhere());
  resolveRoadUnits(m, u);
  for (const auto& c : m.channels) {
    const std::string rule = checkChannelName(c.channel, known);
    if (!rule.empty()) throw InputError(c.source.where, "channel '" + c.channel + "' " + rule);
    std::string si;
    for (const auto& k : known)
      if (k.name == c.channel) si = k.unit;
    u.channel.push_back(unitFactor(c.source.unit, si, c.source.unitWhere()));
  }
  return u;
}

/// "YYYY-MM-DDTHH:MM:SS.sssZ": `seconds` after the midnight of `day` (days since 1970-01-01).
std::string utcText(long day, double seconds) {
  const double whole = std::floor(seconds);
  const std::time_t t = static_cast<std::time_t>(day) * 86400 + static_cast<std::time_t>(whole);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[40];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf + formatPrintf(".%03dZ", std::min(999, static_cast<int>((seconds - whole) * 1000)));
}

/// Clock times (unit "clock") count from the first row's day. Without a date, a time that falls
/// back by more than 12 hours is the next day (a drive past midnight).
class ClockCounter {
 public:
  /// Seconds since the first row's midnight; false if `cell` is not a clock time.
  bool seconds(std::string_view cell, bool first, double& out) {
    ClockTime c;
    if (!parseClockTime(cell, c)) return false;
    if (first) {
      day0_ = c.day;
      dated_ = c.has_date;
    } else if (!c.has_date && c.seconds < previous_ - 43200.0)
      ++day_;
    if (c.has_date) day_ = c.day - day0_;
    previous_ = c.seconds;
    out = static_cast<double>(day_) * 86400.0 + c.seconds;
    return true;
  }
  /// The first row's day (days since 1970-01-01), or -1 when it had no date.
  long firstDay() const { return dated_ ? day0_ : -1; }

 private:
  bool dated_ = false;
  long day0_ = 0, day_ = 0;
  double previous_ = 0.0;
};

/// Reads the log row by row with every check of importLog (io/log_import.hpp).
class LogRowReader {
 public:
  LogRowReader(const std::string& text, const std::string& name, const ImportMapping& m,
               const ImportUnits& u)
      : csv_(text, name, m.separator), name_(name), m_(m), u_(u) {}

  LogRows read(const StageProgress& progress) {
    header();
    rows_.road.resize(u_.road_cols.size());
    rows_.values.resize(m_.channels.size());
    rows_.mask.resize(m_.exclude.size());
    run_.assign(m_.channels.size(), 0);
    run_start_.assign(m_.channels.size(), 0);
    while (csv_.next()) {
      row();
      if (progress && (rows_.t.size() & 4095) == 0) progress("import", csv_.offset(), csv_.size());
    }
    if (progress) progress("import", csv_.size(), csv_.size());
    rows_.first_day = clock_.firstDay();
    return std::move(rows_);
  }

 private:
  /// The header row (after a logger's preamble), the mapped columns' indices, then skip_rows.
  void header() {
    bool any = csv_.next();
    while (any && csv_.line() < m_.header_line) any = csv_.next();
    if (!any)
      throw InputError(name_ + ":" + std::to_string(m_.header_line),
                       "no header row of column names at or after this line (header_line)");
    for (auto f : csv_.fields()) header_.emplace_back(f);
    i_time_ = columnIndex(header_, m_.time, name_);
    i_speed_ = columnIndex(header_, *m_.speed, name_);
    for (const auto* c : u_.road_cols) i_road_.push_back(columnIndex(header_, *c, name_));
    for (const auto& c : m_.channels) i_ch_.push_back(columnIndex(header_, c.source, name_));
    for (const auto& k : m_.exclude) i_mask_.push_back(columnIndex(header_, k.source, name_));
    for (long k = 0; k < m_.skip_rows; ++k)
      if (!csv_.next()) break;  // a row of units, say
  }

  /// A number as the log writes it (1,25 with decimal_comma).
  bool parse(std::string_view f, double& x) {
    if (!m_.decimal_comma) return parseNumber(f, x);
    buffer_.assign(f);
    std::replace(buffer_.begin(), buffer_.end(), ',', '.');
    return parseNumber(buffer_, x);
  }
  std::vector<double> maskFactors() const {
    std::vector<double> f;
    for (const auto& k : m_.exclude) f.push_back(anyUnit(k.source.unit, k.source.where).first);
    return f;
  }
  InputError cellError(std::size_t col, const std::string& rule) const {
    return InputError(csv_.where(), "column '" + header_[col] + "': " + rule);
  }
  /// A required cell's finite number.
  double number(std::size_t col) {
    double x = 0;
    const auto f = csv_.fields()[col];
    if (!parse(f, x))
      throw cellError(col, isMissing(f) ? "is empty or NaN (a required column has no gaps)"
                                        : "'" + std::string(f) + "' is not a number");
    if (!std::isfinite(x)) throw cellError(col, "'" + std::string(f) + "' is not a finite number");
    return x;
  }

  void row() {
    const auto& f = csv_.fields();
    if (f.size() != header_.size())
      throw InputError(csv_.where(), "expected " + std::to_string(header_.size()) +
                                         " columns (as the header), got " +
                                         std::to_string(f.size()));
    auto& t = rows_.t;
    const bool clock = m_.time.unit == "clock";
    double ti = 0;
    if (!clock)
      ti = number(i_time_) * u_.time;
    else if (!clock_.seconds(f[i_time_], t.empty(), ti))
      throw cellError(i_time_, "'" + std::string(f[i_time_]) +
                                   "' is not a clock time (HH:MM:SS[.fff], optionally after a date "
                                   "YYYY-MM-DD and 'T' or a space)");
    if (!t.empty() && ti == t.back())
      throw cellError(i_time_, "time " + std::string(f[i_time_]) +
                                   " repeats the row before (line " +
                                   std::to_string(lines_.back()) + ")");
    if (!t.empty() && ti < t.back())
      throw cellError(i_time_, "time goes backwards: " + std::string(f[i_time_]) + " after " +
                                   (clock ? previous_time_ : formatNumber(t.back() / u_.time, 12)) +
                                   " (line " + std::to_string(lines_.back()) + ")");
    if (clock) previous_time_.assign(f[i_time_]);
    double vi = (number(i_speed_) - m_.speed->offset) * m_.speed->scale * u_.speed;
    if (vi < 0 && vi >= -0.2) vi = 0.0;  // a logger's noise about standstill
    if (vi < 0)
      throw cellError(i_speed_, "speed " + std::string(f[i_speed_]) + " " + m_.speed->unit +
                                    " is negative (beyond the 0.2 m/s of noise at rest)");
    if (vi > 100)
      throw cellError(i_speed_, "speed " + std::string(f[i_speed_]) + " " + m_.speed->unit +
                                    " exceeds 100 m/s");
    t.push_back(ti);
    rows_.v.push_back(vi);
    lines_.push_back(csv_.line());
    for (std::size_t k = 0; k < u_.road_cols.size(); ++k)
      rows_.road[k].push_back((number(i_road_[k]) - u_.road_cols[k]->offset) *
                              u_.road_cols[k]->scale * u_.road[k]);
    for (std::size_t k = 0; k < m_.channels.size(); ++k) channelCell(k);
    for (std::size_t k = 0; k < m_.exclude.size(); ++k) maskCell(k);
  }

  /// Mask k's cell of this row: its magnitude in SI, NaN when empty.
  void maskCell(std::size_t k) {
    const auto cell = csv_.fields()[i_mask_[k]];
    double x = 0;
    if (isMissing(cell) || (parse(cell, x) && std::isnan(x))) {
      rows_.mask[k].push_back(std::numeric_limits<double>::quiet_NaN());
      return;
    }
    if (!parse(cell, x) || !std::isfinite(x))
      throw cellError(i_mask_[k],
                      "'" + std::string(cell) + "' is not a finite number (a mask's column)");
    const auto& src = m_.exclude[k].source;
    rows_.mask[k].push_back(std::abs((x - src.offset) * src.scale * mask_factor_[k]));
  }

  /// Channel k's cell of this row: a number, or a dropout (at most max_dropout_rows in a row).
  void channelCell(std::size_t k) {
    const auto cell = csv_.fields()[i_ch_[k]];
    double x = 0;
    if (isMissing(cell) || (parse(cell, x) && std::isnan(x))) {
      if (run_[k]++ == 0) run_start_[k] = csv_.line();
      if (run_[k] > m_.max_dropout_rows)
        throw cellError(i_ch_[k], "empty or NaN from line " + std::to_string(run_start_[k]) +
                                      " on: more than max_dropout_rows = " +
                                      std::to_string(m_.max_dropout_rows) + " rows in a row");
      rows_.values[k].push_back(std::numeric_limits<double>::quiet_NaN());
      ++rows_.dropped_cells;
      return;
    }
    if (!parse(cell, x)) throw cellError(i_ch_[k], "'" + std::string(cell) + "' is not a number");
    if (!std::isfinite(x))
      throw cellError(i_ch_[k], "'" + std::string(cell) + "' is not a finite number");
    run_[k] = 0;
    rows_.values[k].push_back((x - m_.channels[k].source.offset) * m_.channels[k].source.scale *
                              u_.channel[k]);
  }

  CsvReader csv_;
  const std::string& name_;
  const ImportMapping& m_;
  const ImportUnits& u_;
  std::vector<std::string> header_;
  std::size_t i_time_ = 0, i_speed_ = 0;
  std::vector<std::size_t> i_road_, i_ch_, i_mask_;
  std::vector<double> mask_factor_ = maskFactors();
  std::string buffer_, previous_time_;
  ClockCounter clock_;
  std::vector<long> run_, run_start_, lines_;
  LogRows rows_;
};

/// The speed smoothed as the mapping asks (speed_lowpass_hz), in place.
void smoothSpeed(const ImportMapping& m, const std::vector<double>& t, std::vector<double>& v) {
  if (m.speed_lowpass_hz > 0) {  // zero phase: the input minus its zero-phase high-pass
    const auto high = zeroPhaseHighPass(t, v, m.speed_lowpass_hz);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = std::max(0.0, v[i] - high[i]);
  }
}

/// The rows a run covers ([first, last]) and the window of measured times (s from the log's
/// first row).
constexpr double kRunOut_s = 0.5;

struct RunSpan {
  std::size_t first = 0, last = 0;
  double window_begin = 0, window_end = 0;
  /// The distance travelled from the log's first row to the run's first (trapezoid rule).
  double start_m(const std::vector<double>& t, const std::vector<double>& v) const {
    double x = 0;
    for (std::size_t i = 1; i <= first; ++i) x += 0.5 * (v[i] + v[i - 1]) * (t[i] - t[i - 1]);
    return x;
  }
};

RunSpan runSpan(const ImportMapping& m, const std::vector<double>& t, const std::string& log_name) {
  RunSpan s;
  s.last = t.size() - 1;
  s.window_end = t.back();
  if (!m.window_s) return s;
  const auto [a, b] = *m.window_s;
  if (b > t.back() || a >= t.back())
    throw InputError(m.window_where, "window [" + formatNumber(a) + ", " + formatNumber(b) +
                                         "] s ends after the log " + log_name +
                                         " (its rows span 0.." + formatNumber(t.back()) +
                                         " s from its first row)");
  s.window_begin = a;
  s.window_end = b;
  const double from = std::max(0.0, a - m.run_in_s);
  while (s.first + 1 < t.size() && t[s.first + 1] <= from) ++s.first;
  // The inputs run 0.5 s past the window (at most to the log's end), so the road's and the speed's
  // interpolation at the window's end is the whole drive's there, not a one-sided end of its own.
  while (s.last > s.first && t[s.last] > b + kRunOut_s) --s.last;
  if (s.last == s.first) throw InputError(m.window_where, "holds fewer than 2 rows of " + log_name);
  return s;
}

/// speed.csv and road.csv ("" without a mapped road) from the run's rows, times from 0.
void writeInputs(ImportResult& res, const ImportUnits& u, const std::vector<double>& t,
                 const std::vector<double>& v, const std::vector<std::vector<double>>& road) {
  std::string s = "time_s,speed_mps\n";
  s.reserve(t.size() * 24);
  for (std::size_t i = 0; i < t.size(); ++i)
    s += formatExact(t[i]) + "," + formatExact(v[i]) + "\n";
  res.speed_csv = std::move(s);
  res.road_csv = roadCsvText(u, t, road);
}

/// The study: the base file's text (paths made absolute), then the drive and the mapping's
/// sensors as new tables at its end.
std::string importedStudyText(const std::string& log_name, const ImportMapping& m,
                              const ImportUnits& u, const std::string& base_study,
                              const std::string& scenario, double duration_s, double start_m) {
  const std::string base_text = readTextFile(base_study);
  toml::table root;
  try {
    root = toml::parse(base_text, base_study);
  } catch (const toml::parse_error& e) {
    throw InputError(base_study + ":" + std::to_string(e.source().begin.line),
                     "malformed TOML: " + std::string(e.description()));
  }
  std::ostringstream study;
  study
      << "# Written by `twin import` from " << log_name << " (mapping " << m.source
      << "): the study " << base_study
      << "\n# with its relative paths made absolute, and the drive added at the end as scenario '"
      << scenario << "'.\n"
      << absolutizedStudyText(base_text, root, fs::absolute(base_study).parent_path(), base_study)
      << "\n"
      << "# ---- added by twin import ----\n[scenarios." << scenario
      << "]\nduration_s = " << formatExact(duration_s) << "\nspeed = { csv = \"speed.csv\""
      << (start_m != 0 ? ", start_m = " + formatExact(start_m) : std::string()) << " }"
      << (start_m != 0
              ? "  # start_m: the distance driven before the run's first row (a window of the log)"
              : "")
      << "\n";
  if (!u.road_cols.empty()) {
    study << "road = { type = \"csv_time\", path = \"road.csv\"";
    if (u.road_velocity || u.road_acceleration)
      study << ", highpass_hz = " << formatExact(m.highpass_hz);
    study << " }\n";
  } else {
    study << "road = { type = \"flat\" }  # no road column was mapped\n";
  }
  for (const auto& x : m.sensors) {
    study << "\n[sensors." << x.name << "]\nbody = \"" << x.mount << "\"\nquantity = \""
          << sensorQuantityName(x.quantity) << "\"\n";
    if (x.corner() < 0)
      study << "position_m = [" << formatExact(x.position_m[0]) << ", "
            << formatExact(x.position_m[1]) << ", " << formatExact(x.position_m[2]) << "]\n";
    if (x.filter.order > 0) {
      study << "filter = { order = " << x.filter.order
            << ", cutoff_hz = " << formatExact(x.filter.cutoff_hz);
      if (x.filter.order == 2) study << ", damping = " << formatExact(x.filter.damping);
      study << " }\n";
    }
    if (x.noise_sd > 0) study << "noise_sd = " << formatExact(x.noise_sd) << "\n";
    if (x.positionMeasured()) study << "position_sd_m = " << formatExact(x.position_sd_m) << "\n";
  }
  return study.str();
}

/// The window and the masks: what was kept and what was dropped, and why.
nlohmann::json windowJson(const ImportResult& res, const ImportMapping& m) {
  nlohmann::json masks = nlohmann::json::array();
  for (const auto& [text, count] : res.masked)
    masks.push_back({{"mask", text}, {"rows_dropped", count}});
  nlohmann::json j = {{"rows_outside_window", res.outside_window}, {"masks", masks}};
  if (m.window_s) {
    j["window_s"] = *m.window_s;
    j["run_in_s"] = m.run_in_s;
    j["run_from_log_s"] = res.t0_s;
    j["start_m"] = res.start_m;
    j["rule"] =
        "measurements are the rows with times in window_s (s from the log's first row); the run "
        "starts run_in_s before it "
        "(at the log's first row at the earliest), its speed and road are the log's from there, "
        "and start_m is the distance "
        "driven before the run's first row";
  }
  return j;
}

/// How the files were made: the log, the mapping in full, the counts.
nlohmann::json importSidecar(const ImportResult& res, const std::string& log_text,
                             const std::string& log_name, const ImportMapping& m,
                             const ImportUnits& u, const std::string& base_study) {
  nlohmann::json cols = nlohmann::json::array();
  for (const auto& c : m.channels)
    cols.push_back({{"column", c.source.column},
                    {"channel", c.channel},
                    {"unit", c.source.unit},
                    {"offset", c.source.offset},
                    {"scale", c.source.scale}});
  const nlohmann::json rj = roadSidecar(m, u);
  return {
      {"made_by", "twin import"},
      {"program", programInfo()},
      {"created_utc", utcNow()},
      {"scenario", {{"name", res.scenario}, {"duration_s", res.duration_s}}},
      {"source",
       {{"file", log_name},
        {"content", hexId(fnv1a64(log_text))},
        {"rows", res.rows},
        {"t0_s", res.t0_s},
        {"start_utc", res.start_utc.empty() ? nlohmann::json() : nlohmann::json(res.start_utc)}}},
      {"mapping",
       {{"file", m.source},
        {"time", {{"column", m.time.column}, {"unit", m.time.unit}}},
        {"speed",
         {{"column", m.speed->column},
          {"unit", m.speed->unit},
          {"lowpass_hz", m.speed_lowpass_hz}}},
        {"road", rj},
        {"channels", cols},
        {"max_dropout_rows", m.max_dropout_rows},
        {"header_line", m.header_line},
        {"skip_rows", m.skip_rows},
        {"decimal_comma", m.decimal_comma}}},
      {"dropped_cells", res.dropped_cells},
      {"window", windowJson(res, m)},
      {"records", res.data.records.size()},
      {"study", base_study}};
}

}  // namespace

ImportResult importLog(const std::string& log_text, const std::string& log_name,
                       const ImportMapping& m, const std::string& base_study,
                       const std::string& scenario, const StageProgress& progress) {
  ImportResult res;
  res.scenario = scenario;
  const Study base =
      loadStudy(base_study, /*scenarios_required=*/false);  // the drive is its scenario
  const std::vector<Channel> known = checkTarget(base, m, base_study, scenario);
  ImportMapping added = m;  // the study gains the mapping's new sensors only
  added.sensors = newSensors(base, m, base_study);
  const ImportUnits units = resolveUnits(m, known);
  // An MF4 log (by its extension or its identification) or a CSV: the same rows, the same checks.
  const bool mdf = isMdfLog(log_name, log_text);
  nlohmann::json mdf_read;
  LogRows rows = mdf ? readMdfRows(log_text, log_name, m, units, mdf_read)
                     : LogRowReader(log_text, log_name, m, units).read(progress);
  auto& t = rows.t;
  if (t.size() < 2)
    throw InputError(log_name,
                     "holds " + std::to_string(t.size()) + " data rows; a drive needs at least 2");
  res.rows = static_cast<long>(t.size());
  res.dropped_cells = rows.dropped_cells;
  const double log_t0 = t.front();
  for (double& x : t) x -= log_t0;  // from the first row
  // The run: the whole log, or from run_in_s before the window to its end.
  const RunSpan span = runSpan(m, t, log_name);
  // The speed is smoothed over the whole log before it is cut, so a window's speed is the whole
  // drive's there.
  smoothSpeed(m, t, rows.v);
  res.start_m = span.start_m(t, rows.v);
  res.t0_s = log_t0 + t[span.first];
  if (rows.first_day >= 0) res.start_utc = utcText(rows.first_day, res.t0_s);
  // Times from the run's first row, rounded to 1 ns (so 100.0129 - 100 is written 0.0129).
  const double shift = t[span.first];
  std::vector<double> tr(span.last + 1 - span.first), vr(tr.size());
  std::vector<std::vector<double>> road(rows.road.size(), std::vector<double>(tr.size()));
  for (std::size_t i = span.first; i <= span.last; ++i) {
    tr[i - span.first] = std::round((t[i] - shift) * 1e9) / 1e9;
    vr[i - span.first] = rows.v[i];
    for (std::size_t k = 0; k < road.size(); ++k) road[k][i - span.first] = rows.road[k][i];
  }
  res.duration_s = tr.back();
  res.masked.resize(m.exclude.size());
  for (std::size_t k = 0; k < m.exclude.size(); ++k) res.masked[k].first = m.exclude[k].text();
  // Per mask, the rows it masks: those past a threshold (or empty), and those within its pad_s of
  // one.
  std::vector<std::vector<char>> hit(m.exclude.size(), std::vector<char>(t.size(), 0));
  for (std::size_t k = 0; k < m.exclude.size(); ++k) {
    const auto& mk = m.exclude[k];
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double x = rows.mask[k][i];
      hit[k][i] = std::isnan(x) || (mk.above && x > *mk.above) || (mk.below && x < *mk.below);
    }
    if (mk.pad_s <= 0) continue;
    std::vector<char> padded = hit[k];
    double last = -std::numeric_limits<double>::infinity();  // the latest hit at or before row i
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (hit[k][i]) last = t[i];
      if (t[i] - last <= mk.pad_s * (1 + 1e-9))
        padded[i] = 1;  // rows exactly pad_s away count, whatever the rounding
    }
    double next = std::numeric_limits<double>::infinity();  // the earliest hit at or after row i
    for (std::size_t i = t.size(); i-- > 0;) {
      if (hit[k][i]) next = t[i];
      if (next - t[i] <= mk.pad_s * (1 + 1e-9)) padded[i] = 1;
    }
    hit[k] = std::move(padded);
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (i < span.first || i > span.last || t[i] < span.window_begin || t[i] > span.window_end) {
      ++res.outside_window;
      continue;
    }
    bool masked = false;
    for (std::size_t k = 0; k < m.exclude.size() && !masked; ++k) {
      masked = hit[k][i] != 0;
      if (masked) ++res.masked[k].second;
    }
    if (masked) continue;
    for (std::size_t k = 0; k < m.channels.size(); ++k)
      if (!std::isnan(rows.values[k][i]))
        res.data.records.push_back(
            {1, tr[i - span.first], m.channels[k].channel, rows.values[k][i]});
  }
  if (res.data.records.empty())
    throw InputError(m.window_s ? m.window_where : log_name,
                     "leaves no measurement: every row is outside the window or masked");
  // The records' checks (plausible ranges, ...), each named by the log's channel and time.
  res.lab_csv = labCsvText(
      res.data,
      [&](std::size_t i) {
        const auto& r = res.data.records[i];
        std::string column = r.channel;
        for (const auto& c : m.channels)
          if (c.channel == r.channel) column = c.source.column;
        return log_name + ": channel '" + column + "' at " + formatNumber(res.t0_s + r.time_s, 12) +
               " s";
      },
      known);
  checkWheelAccelerations(units, road);
  writeInputs(res, units, tr, vr, road);
  res.study_toml =
      importedStudyText(log_name, added, units, base_study, scenario, res.duration_s, res.start_m);
  res.sidecar = importSidecar(res, log_text, log_name, m, units, base_study);
  if (mdf) res.sidecar["source"]["mdf"] = mdf_read;  // the groups and channels read, the resampling
  return res;
}

void writeImport(const ImportResult& r, const std::string& out_dir) {
  const fs::path out(out_dir);
  std::error_code ec;
  if (fs::exists(out) && (!fs::is_directory(out) || !fs::is_empty(out, ec)))
    throw InputError(out_dir, "exists and is not an empty folder (--out): choose a new folder");
  const fs::path tmp = out.parent_path() / (out.filename().string() + ".import-tmp");
  fs::remove_all(tmp, ec);
  try {
    fs::create_directories(tmp);
    writeFileAtomic((tmp / "measurements.csv").string(), r.lab_csv);
    writeFileAtomic((tmp / "measurements.json").string(), r.sidecar.dump(2) + "\n");
    writeFileAtomic((tmp / "speed.csv").string(), r.speed_csv);
    if (!r.road_csv.empty()) writeFileAtomic((tmp / "road.csv").string(), r.road_csv);
    writeFileAtomic((tmp / "study.toml").string(), r.study_toml);
    (void)loadStudy(
        (tmp / "study.toml").string());    // the study reads back (the drive's scenario included)
    if (fs::exists(out)) fs::remove(out);  // an empty folder
    fs::rename(tmp, out);
  } catch (const InputError& e) {
    fs::remove_all(tmp, ec);
    std::string where = e.where();
    for (std::size_t at; (at = where.find(tmp.string())) != std::string::npos;)
      where.replace(at, tmp.string().size(), out.string());
    throw InputError(where, e.rule());
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace dtwin
