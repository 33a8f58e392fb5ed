#include "subsystems/crg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string_view>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"

namespace dtwin {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

bool startsWithNoCase(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && lower(s.substr(0, prefix.size())) == lower(prefix);
}

/// A number of a header value or a data field: fixpoint or scientific, Fortran's 'D' exponent
/// accepted (as the C API does); nan and inf are not numbers here.
bool crgNumber(std::string_view s, double& v) {
  std::string t(trim(s));
  for (char& c : t)
    if (c == 'd' || c == 'D') c = 'e';
  return parseNumber(t, v) && std::isfinite(v);
}

enum class Section { None, Comment, Road, Options, Modifiers, FileRef, Projection, DataDef };

enum class Channel { U, X, Y, Phi, Bank, Slope, ZAtV, ZIndex };

struct ChannelDef {
  Channel kind;
  double value = 0.0;  ///< v position (ZAtV) or section number (ZIndex)
  long line = 0;
};

// The keys of $ROAD_CRG (lower case). Those the heights use are read below; the plan-view ones
// (x, y, heading, offsets in x/y/heading, WGS 84 positions) place the road on a map and do not
// change z(u, v).
const std::set<std::string> kRoadKeys = {
    "reference_line_start_u",   "reference_line_end_u",     "reference_line_increment",
    "long_section_v_right",     "long_section_v_left",      "long_section_v_increment",
    "reference_line_start_s",   "reference_line_end_s",     "reference_line_start_b",
    "reference_line_end_b",     "reference_line_start_x",   "reference_line_start_y",
    "reference_line_end_x",     "reference_line_end_y",     "reference_line_offset_x",
    "reference_line_offset_y",  "reference_line_offset_z",  "reference_line_offset_phi",
    "reference_line_start_phi", "reference_line_end_phi",   "reference_line_start_z",
    "reference_line_end_z",     "reference_line_start_lon", "reference_line_start_lat",
    "reference_line_end_lon",   "reference_line_end_lat",   "reference_line_start_alt",
    "reference_line_end_alt"};

// $ROAD_CRG_OPTS: the options that change heights, with the one value the twin evaluates with
// (the C API's defaults); the others steer messages, checks and the x/y search, not z(u, v).
const std::map<std::string, double> kHeightOptions = {
    {"border_mode_u", 2.0},       {"border_mode_v", 2.0},      {"border_offset_u", 0.0},
    {"border_offset_v", 0.0},     {"border_smooth_ubeg", 0.0}, {"border_smooth_uend", 0.0},
    {"refline_continuation", 0.0}};
const std::set<std::string> kOtherOptions = {"refline_search_far", "refline_search_close",
                                             "refline_search_u",   "refline_search_ufrac",
                                             "warn_msgs",          "warn_curv_local",
                                             "warn_curv_global",   "log_msgs",
                                             "log_eval",           "log_eval_freq",
                                             "log_hist",           "log_hist_freq",
                                             "log_stat",           "log_stat_freq",
                                             "check_eps",          "check_inc",
                                             "check_tol",          "check_pro",
                                             "check_wgs"};

class Parser {
 public:
  Parser(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  CrgSurface run();

 private:
  [[noreturn]] void fail(long line, const std::string& rule) const {
    throw InputError(name_ + ":" + std::to_string(line), rule);
  }
  [[noreturn]] void failFile(const std::string& rule) const { throw InputError(name_, rule); }

  void header();
  void keyValue(std::string_view body, long line, bool options);
  void channel(std::string_view body, long line);
  std::optional<double> key(const std::string& k) const {
    auto it = road_.find(k);
    return it == road_.end() ? std::nullopt : std::optional<double>(it->second);
  }
  std::string keyWhere(const std::string& k) const {
    auto it = road_line_.find(k);
    return it == road_line_.end() ? name_ : name_ + ":" + std::to_string(it->second);
  }
  std::vector<std::vector<double>> asciiRecords() const;
  std::vector<std::vector<double>> binaryRecords() const;
  double field(std::string_view f, long line, std::size_t column) const;
  void positions(CrgSurface& s);
  void heights(CrgSurface& s, const std::vector<std::vector<double>>& rec);
  void referenceLine(CrgSurface& s, const std::vector<std::vector<double>>& rec);

  const std::string& text_;
  const std::string& name_;
  bool seen_road_ = false, seen_def_ = false;
  std::map<std::string, double> road_;
  std::map<std::string, long> road_line_;
  std::string format_;
  long format_line_ = 0;
  std::vector<ChannelDef> channels_;
  std::size_t data_offset_ = std::string::npos;  ///< first byte after the $$$$ line
  long data_line_ = 0;                           ///< the $$$$ line's number
};

void Parser::header() {
  Section section = Section::None;
  std::size_t pos = text_.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // a byte-order mark
  long line_no = 0;
  while (pos < text_.size()) {
    std::size_t end = text_.find('\n', pos);
    const std::size_t next = end == std::string::npos ? text_.size() : end + 1;
    if (end == std::string::npos) end = text_.size();
    const std::string_view raw(text_.data() + pos, end - pos);
    pos = next;
    ++line_no;
    const std::string_view line = trim(raw);
    if (!raw.empty() && raw.front() == '$') {
      if (raw.rfind("$$$$", 0) == 0) {  // the data section starts after this line
        data_offset_ = pos;
        data_line_ = line_no;
        return;
      }
      // A '$' line ends the open section; a keyword opens the next one.
      const std::string_view word = trim(raw.substr(0, raw.find_first_of(" \t!\r")));
      const std::string kw = lower(word);
      if (kw == "$") {
        section = Section::None;
        continue;
      }
      if (kw == "$ct")
        section = Section::Comment;
      else if (kw == "$road_crg") {
        if (seen_road_) fail(line_no, "a second $ROAD_CRG section");
        seen_road_ = true;
        section = Section::Road;
      } else if (kw == "$road_crg_opts")
        section = Section::Options;
      else if (kw == "$road_crg_mods")
        section = Section::Modifiers;
      else if (kw == "$road_crg_file")
        section = Section::FileRef;
      else if (kw == "$road_crg_mpro")
        section = Section::Projection;
      else if (kw == "$kd_definition") {
        if (seen_def_) fail(line_no, "a second $KD_Definition section");
        seen_def_ = true;
        section = Section::DataDef;
      } else
        fail(line_no, "unknown section '" + std::string(word) +
                          "' (known: $CT, $ROAD_CRG, $ROAD_CRG_OPTS, $ROAD_CRG_MODS, "
                          "$ROAD_CRG_FILE, $ROAD_CRG_MPRO, $KD_Definition, $$$$ before the data)");
      continue;
    }
    if (section == Section::Comment || section == Section::Projection) continue;
    // '*' first: a comment line; '!' starts an inline comment.
    if (line.empty() || line.front() == '*') continue;
    const std::string_view body = trim(line.substr(0, line.find('!')));
    if (body.empty()) continue;
    switch (section) {
      case Section::None:
        fail(line_no,
             "text outside a section (comments start with '*'): '" + std::string(body) + "'");
      case Section::Road:
        keyValue(body, line_no, false);
        break;
      case Section::Options:
        keyValue(body, line_no, true);
        break;
      case Section::Modifiers:
        fail(line_no,
             "$ROAD_CRG_MODS: modifiers (scaling, offsets, NaN modes) are not supported: "
             "apply them to the file, or remove them");
      case Section::FileRef:
        fail(line_no, "$ROAD_CRG_FILE: references to other CRG files are not supported");
      case Section::DataDef:
        if (startsWithNoCase(body, "#:")) {
          if (!format_.empty()) fail(line_no, "a second data format (#:) line");
          const std::string_view f = trim(body.substr(2));
          format_ = std::string(f.substr(0, f.find_first_of(" \t")));
          for (char& c : format_)
            c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
          format_line_ = line_no;
          static const std::set<std::string> kFormats = {"LRFI", "LDFI", "KRBI",
                                                         "KDBI", "LRBI", "LDBI"};
          if (!kFormats.count(format_))
            fail(line_no, "data format '" + format_ +
                              "' is not supported (LRFI, LDFI, KRBI, KDBI, LRBI, LDBI are)");
        } else if (startsWithNoCase(body, "U:")) {
          // a virtual channel: derived from other data, not a column of the data section
        } else if (startsWithNoCase(body, "D:")) {
          channel(trim(body.substr(2)), line_no);
        } else
          fail(line_no, "$KD_Definition: expected a '#:', 'D:' or 'U:' line, got '" +
                            std::string(body) + "'");
        break;
      default:
        break;
    }
  }
}

void Parser::keyValue(std::string_view body, long line, bool options) {
  const std::size_t eq = body.find('=');
  const char* sec = options ? "$ROAD_CRG_OPTS" : "$ROAD_CRG";
  if (eq == std::string_view::npos)
    fail(line, std::string(sec) + ": expected 'KEY = value', got '" + std::string(body) + "'");
  const std::string written(trim(body.substr(0, eq)));  // for messages, as the file spells it
  const std::string k = lower(written);
  const std::string_view text = trim(body.substr(eq + 1));
  double v = 0;
  if (!crgNumber(text, v))
    fail(line, std::string(sec) + ": " + written + " = '" + std::string(text) +
                   "' is not a finite number");
  if (options) {
    if (auto it = kHeightOptions.find(k); it != kHeightOptions.end()) {
      if (v != it->second)
        fail(line, "$ROAD_CRG_OPTS: " + written + " = " + std::string(text) +
                       " is not supported: the twin evaluates with " + written + " = " +
                       formatNumber(it->second) +
                       " (the C API's default: the border's value held, no offset, no "
                       "smoothing, an open reference line)");
    } else if (!kOtherOptions.count(k))
      fail(line, "$ROAD_CRG_OPTS: unknown option '" + written + "'");
    return;
  }
  if (!kRoadKeys.count(k)) fail(line, "$ROAD_CRG: unknown key '" + written + "'");
  if (road_.count(k))
    fail(line, "$ROAD_CRG: " + written + " given twice (first on line " +
                   std::to_string(road_line_.at(k)) + ")");
  road_[k] = v;
  road_line_[k] = line;
}

void Parser::channel(std::string_view body, long line) {
  const std::size_t comma = body.find(',');
  if (comma == std::string_view::npos)
    fail(line, "$KD_Definition: channel 'D:" + std::string(body) + "' has no unit ('NAME,UNIT')");
  const std::string what = lower(trim(body.substr(0, comma)));
  const std::string unit = lower(trim(body.substr(comma + 1)));
  auto needUnit = [&](const char* u) {
    if (unit != u)
      fail(line, "$KD_Definition: channel '" + what + "' must be in " + u + ", got '" + unit + "'");
  };
  ChannelDef c{Channel::U, 0.0, line};
  if (what.rfind("long section", 0) == 0) {
    std::string_view rest = trim(std::string_view(what).substr(12));
    needUnit("m");
    if (rest.rfind("at v", 0) == 0) {
      rest = trim(rest.substr(4));
      if (rest.empty() || rest.front() != '=' || !crgNumber(rest.substr(1), c.value))
        fail(line, "$KD_Definition: 'long section at v = X' needs a number X, got '" + what + "'");
      c.kind = Channel::ZAtV;
    } else {
      double n = 0;
      if (!crgNumber(rest, n) || n < 1 || n != std::floor(n))
        fail(line,
             "$KD_Definition: 'long section N' needs a whole number N >= 1, got '" + what + "'");
      c.kind = Channel::ZIndex;
      c.value = n;
    }
  } else if (what.rfind("reference line ", 0) == 0) {
    const std::string q(trim(std::string_view(what).substr(15)));
    static const std::map<std::string, std::pair<Channel, const char*>> kRef = {
        {"u", {Channel::U, "m"}},
        {"x", {Channel::X, "m"}},
        {"y", {Channel::Y, "m"}},
        {"phi", {Channel::Phi, "rad"}},
        {"banking", {Channel::Bank, "m/m"}},
        {"slope", {Channel::Slope, "m/m"}}};
    auto it = kRef.find(q);
    if (it == kRef.end())
      fail(line, "$KD_Definition: unknown reference-line channel '" + what +
                     "' (known: u, x, y, phi, banking, slope)");
    needUnit(it->second.second);
    c.kind = it->second.first;
    for (const auto& o : channels_)
      if (o.kind == c.kind)
        fail(line, "$KD_Definition: channel '" + what + "' defined twice (first on line " +
                       std::to_string(o.line) + ")");
  } else
    fail(line, "$KD_Definition: unknown channel 'D:" + std::string(trim(body)) +
                   "' (known: reference line u/x/y/phi/banking/slope, long section N, long "
                   "section at v = X)");
  channels_.push_back(c);
}

double Parser::field(std::string_view f, long line, std::size_t column) const {
  const std::string_view t = trim(f);
  if (t == "**unused**") return 0.0;  // as the C API reads it
  if (!t.empty() && t.front() == '*') return kNaN;
  double v = 0;
  if (t.empty()) fail(line, "field " + std::to_string(column + 1) + " of the row is blank");
  if (!crgNumber(t, v))
    fail(line, "field " + std::to_string(column + 1) + " '" + std::string(t) +
                   "' is not a number (a missing value is written with a leading '*')");
  return v;
}

std::vector<std::vector<double>> Parser::asciiRecords() const {
  const std::size_t width = format_[1] == 'D' ? 20 : 10, per_line = 80 / width;
  const std::size_t n = channels_.size();
  std::vector<std::vector<double>> out;
  std::vector<double> row;
  std::size_t pos = data_offset_;
  long line_no = data_line_;
  long row_line = 0;
  while (pos < text_.size()) {
    std::size_t end = text_.find('\n', pos);
    const std::size_t next = end == std::string::npos ? text_.size() : end + 1;
    if (end == std::string::npos) end = text_.size();
    std::string_view raw(text_.data() + pos, end - pos);
    pos = next;
    ++line_no;
    while (!raw.empty() && (raw.back() == '\r' || raw.back() == ' ' || raw.back() == '\t'))
      raw.remove_suffix(1);
    if (raw.empty()) continue;
    if (row.empty()) row_line = line_no;
    const std::size_t first = row.size(), want = std::min(per_line, n - first);
    // The fields are fixed-width: "0.0111111-0.0111111" is two numbers.
    const std::size_t got = (raw.size() + width - 1) / width;
    if (got < want)
      fail(line_no, "too few columns: " + std::to_string(got) + " field(s) of " +
                        std::to_string(width) + " characters, the row needs " +
                        std::to_string(want) + " here (" + std::to_string(n) + " channels, " +
                        std::to_string(per_line) + " per line)");
    if (got > want)
      fail(line_no, "too many columns: " + std::to_string(got) + " field(s) of " +
                        std::to_string(width) + " characters, the row needs " +
                        std::to_string(want) + " here (" + std::to_string(n) + " channels, " +
                        std::to_string(per_line) + " per line)");
    for (std::size_t c = 0; c < want; ++c)
      row.push_back(field(raw.substr(c * width, width), line_no, first + c));
    if (row.size() == n) {
      out.push_back(std::move(row));
      row.clear();
    }
  }
  if (!row.empty())
    fail(row_line, "the last row is incomplete: " + std::to_string(row.size()) + " of " +
                       std::to_string(n) + " values");
  return out;
}

std::vector<std::vector<double>> Parser::binaryRecords() const {
  const bool dbl = format_[1] == 'D';
  const std::size_t size = dbl ? 8 : 4, n = channels_.size();
  std::size_t record = size * n;
  if (format_[0] == 'L') record = (record + 79) / 80 * 80;  // rows padded to 80-byte records
  const std::size_t bytes = text_.size() - data_offset_;
  // The row count comes from the header: the data may end in a padded last record.
  const auto end_u = key("reference_line_end_u"), inc = key("reference_line_increment");
  if (!end_u || !inc || !(*inc > 0))
    failFile(
        "$ROAD_CRG: REFERENCE_LINE_END_U and REFERENCE_LINE_INCREMENT are required with "
        "binary data (" +
        format_ + "): they give the row count");
  const double m = (*end_u - key("reference_line_start_u").value_or(0.0)) / *inc;
  if (!(m >= 1.0 && m < 1e9))
    throw InputError(keyWhere("reference_line_end_u"),
                     "$ROAD_CRG: REFERENCE_LINE_END_U must lie at least one increment after "
                     "START_U");
  const std::size_t rows = static_cast<std::size_t>(std::llround(m)) + 1;
  if (rows * record > bytes)
    failFile("binary data (" + format_ + ") holds " + std::to_string(bytes) +
             " bytes, fewer than " + std::to_string(rows) + " rows of " + std::to_string(record) +
             " bytes (REFERENCE_LINE_START_U/END_U/INCREMENT give the row count)");
  if (bytes - rows * record > 81)
    failFile("binary data (" + format_ + ") holds " + std::to_string(bytes - rows * record) +
             " bytes after its " + std::to_string(rows) + " rows of " + std::to_string(record) +
             " bytes, more than a padded last record (REFERENCE_LINE_START_U/END_U/INCREMENT "
             "give the row count)");
  std::vector<std::vector<double>> out(rows, std::vector<double>(n));
  const auto* p = reinterpret_cast<const unsigned char*>(text_.data() + data_offset_);
  for (std::size_t k = 0; k < rows; ++k)
    for (std::size_t c = 0; c < n; ++c) {
      const unsigned char* q = p + k * record + c * size;
      std::uint64_t bits = 0;
      for (std::size_t b = 0; b < size; ++b) bits = (bits << 8) | q[b];  // big endian
      if (dbl) {
        double d;
        std::memcpy(&d, &bits, 8);
        out[k][c] = d;
      } else {
        const auto b32 = static_cast<std::uint32_t>(bits);
        float f;
        std::memcpy(&f, &b32, 4);
        out[k][c] = f;
      }
      if (std::isinf(out[k][c]))
        failFile("binary data: row " + std::to_string(k + 1) + ", channel " +
                 std::to_string(c + 1) + " is infinite");
    }
  return out;
}

void Parser::positions(CrgSurface& s) {
  bool at_v = false, index = false;
  for (const auto& c : channels_) {
    at_v |= c.kind == Channel::ZAtV;
    index |= c.kind == Channel::ZIndex;
  }
  if (at_v && index)
    failFile("$KD_Definition: 'long section N' and 'long section at v = X' channels mixed");
  const auto right = key("long_section_v_right"), left = key("long_section_v_left"),
             inc = key("long_section_v_increment");
  std::vector<double> v;
  for (const auto& c : channels_)
    if (c.kind == Channel::ZAtV || c.kind == Channel::ZIndex) v.push_back(c.value);
  const std::size_t nv = v.size();
  if (nv < 2)
    failFile("$KD_Definition: at least two long sections are needed, got " + std::to_string(nv));
  constexpr double kTol = 1e-4;  // 0.1 mm: a header value against the positions
  if (index) {
    std::vector<double> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t j = 0; j < nv; ++j)
      if (sorted[j] != static_cast<double>(j + 1))
        failFile("$KD_Definition: the long sections must be numbered 1.." + std::to_string(nv) +
                 " once each");
    if (!inc || !(*inc > 0))
      failFile(
          "$ROAD_CRG: LONG_SECTION_V_INCREMENT (> 0) is required with 'long section N' "
          "channels");
    const double span = *inc * static_cast<double>(nv - 1);
    double first = -0.5 * span;  // centred on the reference line when neither border is given
    if (right)
      first = *right;
    else if (left)
      first = *left - span;
    if (right && left && std::abs(*left - (*right + span)) > kTol)
      throw InputError(keyWhere("long_section_v_left"),
                       "$ROAD_CRG: LONG_SECTION_V_LEFT = " + formatNumber(*left) +
                           " but V_RIGHT + (" + std::to_string(nv) +
                           " - 1) V_INCREMENT = " + formatNumber(*right + span));
    for (double& x : v) x = first + (x - 1.0) * *inc;
  } else {
    std::vector<double> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t j = 1; j < nv; ++j)
      if (!(sorted[j] - sorted[j - 1] >= 1e-6))
        failFile("$KD_Definition: long sections at v = " + formatNumber(sorted[j]) +
                 " are closer than 1e-6 m (or given twice)");
    if (right && std::abs(*right - sorted.front()) > kTol)
      throw InputError(
          keyWhere("long_section_v_right"),
          "$ROAD_CRG: LONG_SECTION_V_RIGHT = " + formatNumber(*right) +
              " but the rightmost long section is at v = " + formatNumber(sorted.front()));
    if (left && std::abs(*left - sorted.back()) > kTol)
      throw InputError(
          keyWhere("long_section_v_left"),
          "$ROAD_CRG: LONG_SECTION_V_LEFT = " + formatNumber(*left) +
              " but the leftmost long section is at v = " + formatNumber(sorted.back()));
    if (inc) {
      const double step = (sorted.back() - sorted.front()) / static_cast<double>(nv - 1);
      for (std::size_t j = 1; j < nv; ++j)
        if (std::abs(sorted[j] - sorted[j - 1] - *inc) > kTol)
          throw InputError(keyWhere("long_section_v_increment"),
                           "$ROAD_CRG: LONG_SECTION_V_INCREMENT = " + formatNumber(*inc) +
                               " but the long sections are " +
                               formatNumber(sorted[j] - sorted[j - 1]) + " m apart (mean " +
                               formatNumber(step) + ")");
    }
  }
  s.v_m = v;  // in channel order here; heights() sorts
}

void Parser::heights(CrgSurface& s, const std::vector<std::vector<double>>& rec) {
  // Column of each long section, ascending in v.
  std::vector<std::size_t> col;
  std::vector<double> v;
  {
    std::size_t j = 0;
    for (std::size_t c = 0; c < channels_.size(); ++c)
      if (channels_[c].kind == Channel::ZAtV || channels_[c].kind == Channel::ZIndex) {
        col.push_back(c);
        v.push_back(s.v_m[j++]);
      }
  }
  std::vector<std::size_t> order(col.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  const std::size_t nv = order.size();
  s.v_m.resize(nv);
  for (std::size_t j = 0; j < nv; ++j) s.v_m[j] = v[order[j]];
  s.z_m.assign(s.rows * nv, 0.0);
  for (std::size_t k = 0; k < s.rows; ++k) {
    double* z = &s.z_m[k * nv];
    for (std::size_t j = 0; j < nv; ++j) z[j] = rec[k][col[order[j]]];
    // NaNs (missing heights: the measured width varies, a scanner drops a point) are filled as
    // the C API's default modifier (GRID_NAN_MODE keep-last, offset 0) fills them: with the
    // nearest valid height to the right (lower v) in the same cross section, and those right of
    // the first valid height with that one. A cross section without a valid height is refused.
    std::size_t lo = 0;
    while (lo < nv && std::isnan(z[lo])) ++lo;
    if (lo == nv)
      failFile("data row " + std::to_string(k + 1) +
               " (u = " + formatNumber(s.u0_m + s.du_m * static_cast<double>(k)) +
               "): every height is missing (NaN)");
    for (std::size_t j = 0; j < lo; ++j) z[j] = z[lo];
    std::size_t hi = nv;
    while (std::isnan(z[hi - 1])) --hi;
    for (std::size_t j = lo + 1; j < nv; ++j)
      if (std::isnan(z[j])) {
        z[j] = z[j - 1];
        if (j < hi) ++s.nan_inside;
      }
    s.nan_filled += lo + (nv - hi);
  }
}

void Parser::referenceLine(CrgSurface& s, const std::vector<std::vector<double>>& rec) {
  const std::size_t n = s.rows;
  auto columnOf = [&](Channel kind) -> std::optional<std::size_t> {
    for (std::size_t c = 0; c < channels_.size(); ++c)
      if (channels_[c].kind == kind) return c;
    return std::nullopt;
  };
  // The first row's slope is not used (the C API integrates it from the second row on): it may
  // be missing.
  auto values = [&](std::size_t c, const char* what) {
    std::vector<double> out(n);
    const bool first_unused = channels_[c].kind == Channel::Slope;
    for (std::size_t k = 0; k < n; ++k) {
      out[k] = rec[k][c];
      if (k == 0 && first_unused && std::isnan(out[k])) out[k] = 0.0;
      if (std::isnan(out[k]))
        fail(channels_[c].line, std::string("reference-line ") + what + " channel: data row " +
                                    std::to_string(k + 1) +
                                    " is missing (NaN); only heights may be missing");
    }
    return out;
  };
  // The plan-view channels (x, y, heading) place the road on a map: they do not change z(u, v)
  // and are not read further (the shipped samples have missing headings).
  if (columnOf(Channel::X).has_value() != columnOf(Channel::Y).has_value())
    failFile("$KD_Definition: reference line x and y must be both given or both not");
  const auto phi0 = key("reference_line_start_phi"), phi1 = key("reference_line_end_phi");
  s.plan_geometry =
      columnOf(Channel::X) || columnOf(Channel::Phi) || (phi0 && phi1 && *phi0 != *phi1);
  if (const double off = key("reference_line_offset_z").value_or(0.0); off != 0.0)
    throw InputError(keyWhere("reference_line_offset_z"),
                     "$ROAD_CRG: REFERENCE_LINE_OFFSET_Z = " + formatNumber(off) +
                         " is not supported (the C API ignores it, the specification adds it): "
                         "add it to REFERENCE_LINE_START_Z and END_Z");
  // Banking: the channel, else a constant REFERENCE_LINE_START_B (as the C API).
  if (auto c = columnOf(Channel::Bank))
    s.bank = values(*c, "banking");
  else if (const double b = key("reference_line_start_b").value_or(0.0);
           b != 0.0 || key("reference_line_end_b").value_or(0.0) != 0.0) {
    if (key("reference_line_end_b").value_or(b) != b)
      throw InputError(keyWhere("reference_line_end_b"),
                       "$ROAD_CRG: REFERENCE_LINE_END_B differs from START_B without a banking "
                       "channel: a varying bank needs 'D:reference line banking,m/m'");
    s.bank.assign(n, b);
  }
  // Elevation of the reference line: the slope integrated as the C API integrates it.
  const double z0 = key("reference_line_start_z").value_or(0.0);
  const auto z1 = key("reference_line_end_z");
  std::vector<double> slope;
  if (auto c = columnOf(Channel::Slope))
    slope = values(*c, "slope");
  else if (const double sl = key("reference_line_start_s").value_or(0.0); sl != 0.0) {
    if (key("reference_line_end_s").value_or(sl) != sl)
      throw InputError(keyWhere("reference_line_end_s"),
                       "$ROAD_CRG: REFERENCE_LINE_END_S differs from START_S without a slope "
                       "channel: a varying slope needs 'D:reference line slope,m/m'");
    slope.assign(n, sl);
  } else if (key("reference_line_end_s").value_or(0.0) != 0.0)
    throw InputError(keyWhere("reference_line_end_s"),
                     "$ROAD_CRG: REFERENCE_LINE_END_S differs from START_S without a slope "
                     "channel: a varying slope needs 'D:reference line slope,m/m'");
  auto& z = s.ref_z_m;
  z.assign(n, z0);
  if (slope.empty()) {
    if (z1 && *z1 != z0)
      throw InputError(keyWhere("reference_line_end_z"),
                       "$ROAD_CRG: REFERENCE_LINE_END_Z differs from START_Z but no slope is "
                       "given (REFERENCE_LINE_START_S or a slope channel)");
    return;
  }
  const double du = s.du_m;
  if (z1) {
    // Backward from END_Z, then forward from START_Z weighted towards the backward pass.
    z[n - 1] = *z1;
    for (std::size_t i = n - 1; i > 0; --i) z[i - 1] = z[i] - slope[i] * du;
    z[0] = z0;
    for (std::size_t i = 0; i + 2 < n; ++i) {
      const double f = static_cast<double>(i) / static_cast<double>(n - 1);
      z[i + 1] = (1.0 - f) * (z[i] + slope[i + 1] * du) + f * z[i + 1];
    }
  } else {
    for (std::size_t i = 0; i + 1 < n; ++i) z[i + 1] = z[i] + slope[i + 1] * du;
  }
}

CrgSurface Parser::run() {
  header();
  if (data_offset_ == std::string::npos)
    failFile("no road data: the data section starts after a line beginning with '$$$$'");
  if (!seen_road_) failFile("no $ROAD_CRG section (required with road data)");
  if (!seen_def_) failFile("no $KD_Definition section (required with road data)");
  if (format_.empty()) format_ = "KRBI";  // the specification's default
  CrgSurface s;
  s.name = name_;
  s.format = format_;
  const auto inc = key("reference_line_increment");
  if (!inc) failFile("$ROAD_CRG: REFERENCE_LINE_INCREMENT is required");
  if (!(*inc > 0))
    throw InputError(keyWhere("reference_line_increment"),
                     "$ROAD_CRG: REFERENCE_LINE_INCREMENT must be > 0, got " + formatNumber(*inc));
  s.du_m = *inc;
  s.u0_m = key("reference_line_start_u").value_or(0.0);
  const auto rec = format_[2] == 'F' ? asciiRecords() : binaryRecords();
  s.rows = rec.size();
  if (s.rows < 2)
    failFile("road data: at least two rows (cross sections) are needed, got " +
             std::to_string(s.rows));
  // An explicit u channel: uniformly spaced, its first value the start.
  for (std::size_t c = 0; c < channels_.size(); ++c)
    if (channels_[c].kind == Channel::U) {
      const double first = rec.front()[c];
      for (std::size_t k = 0; k < s.rows; ++k)
        if (!(std::abs(rec[k][c] - (first + s.du_m * static_cast<double>(k))) <= 0.01 * s.du_m))
          fail(channels_[c].line, "reference line u channel: row " + std::to_string(k + 1) +
                                      " has u = " + formatNumber(rec[k][c]) +
                                      ", not u0 + (row - 1) REFERENCE_LINE_INCREMENT = " +
                                      formatNumber(first + s.du_m * static_cast<double>(k)));
      if (auto u0 = key("reference_line_start_u"); u0 && std::abs(*u0 - first) > 0.01 * s.du_m)
        throw InputError(keyWhere("reference_line_start_u"),
                         "$ROAD_CRG: REFERENCE_LINE_START_U = " + formatNumber(*u0) +
                             " but the u channel starts at " + formatNumber(first));
      s.u0_m = first;
    }
  if (auto u1 = key("reference_line_end_u")) {
    const double end = s.u1_m();
    if (std::abs(*u1 - end) > 0.01 * s.du_m) {
      const double m = (*u1 - s.u0_m) / s.du_m + 1.0;
      throw InputError(keyWhere("reference_line_end_u"),
                       "$ROAD_CRG: REFERENCE_LINE_END_U = " + formatNumber(*u1) + " but " +
                           std::to_string(s.rows) + " data rows at REFERENCE_LINE_INCREMENT " +
                           formatNumber(s.du_m) + " from u = " + formatNumber(s.u0_m) +
                           " end at u = " + formatNumber(end) + " (END_U asks for " +
                           formatNumber(m) + " rows)");
    }
  }
  positions(s);
  heights(s, rec);
  referenceLine(s, rec);
  // The C API's default modifiers (REFPOINT_X/Y/Z/PHI = 0, completed by its check to
  // REFPOINT_U_FRACTION = REFPOINT_V_FRACTION = 0) put the reference point, the first cross
  // section's rightmost long section (u0, v_right), at z = 0: every height shifts by as much.
  s.z_offset_m = -s.height(s.u0_m, s.v_m.front());
  return s;
}

}  // namespace

/// The long sections' interval j and the fraction fv of v in it, as crgEvaluv2z finds them: held
/// at the outer sections (fv 0 at the rightmost, 1 at the leftmost).
static void vInterval(const std::vector<double>& v_m, double v, std::size_t& j, double& fv) {
  j = 0;
  fv = 0.0;
  if (v <= v_m.front()) return;
  if (v >= v_m.back()) {
    j = v_m.size() - 2;
    fv = 1.0;
    return;
  }
  j = static_cast<std::size_t>(std::upper_bound(v_m.begin(), v_m.end(), v) - v_m.begin()) - 1;
  fv = (v - v_m[j]) / (v_m[j + 1] - v_m[j]);
}

double CrgSurface::nodeHeight(std::size_t k, double v) const {
  std::size_t j = 0;
  double fv = 0.0;
  vInterval(v_m, v, j, fv);
  const double z0 = gridHeight(k, j), z1 = gridHeight(k, j + 1);
  double z = fv == 0.0 ? z0 : fv == 1.0 ? z1 : z0 + (z1 - z0) * fv;
  z += ref_z_m[k];
  if (!bank.empty()) z += bank[k] * std::clamp(v, v_m.front(), v_m.back());
  return z + z_offset_m;
}

double CrgSurface::height(double u, double v) const {
  // u: the interval and fraction as crgEvaluv2z finds them, held at the ends.
  double fu = (u - u0_m) / du_m;
  std::size_t k = 0;
  if (fu < 0.0) {
    fu = 0.0;
  } else {
    k = static_cast<std::size_t>(fu);
    if (k >= rows - 1) {
      k = rows - 2;
      fu = 1.0;
    } else {
      fu -= static_cast<double>(k);
    }
  }
  std::size_t j = 0;
  double fv = 0.0;
  vInterval(v_m, v, j, fv);
  // Bilinear, written as the C API writes it.
  const double z00 = gridHeight(k, j);
  const double z10 = gridHeight(k + 1, j) - z00;
  double z01 = gridHeight(k, j + 1);
  const double z11 = gridHeight(k + 1, j + 1) - (z10 + z01);
  z01 -= z00;
  double z = (z11 * fv + z10) * fu + z01 * fv + z00;
  z += ref_z_m[k] + fu * (ref_z_m[k + 1] - ref_z_m[k]);
  if (!bank.empty())
    z += (bank[k] + fu * (bank[k + 1] - bank[k])) * std::clamp(v, v_m.front(), v_m.back());
  return z + z_offset_m;
}

CrgSurface parseCrg(const std::string& text, const std::string& name) {
  return Parser(text, name).run();
}

CrgSurface readCrg(const std::string& path) {
  return parseCrg(readTextFile(path, " (an OpenCRG road file)"), path);
}

std::shared_ptr<const GridRoad> makeCrgRoad(const CrgSurface& s, double left_v_m, double right_v_m,
                                            double u_at_x0, nlohmann::json description) {
  std::vector<double> left(s.rows), right(s.rows);
  for (std::size_t k = 0; k < s.rows; ++k) {
    left[k] = s.nodeHeight(k, left_v_m);
    right[k] = s.nodeHeight(k, right_v_m);
  }
  // |C1 Hermite - piecewise linear| on an interval <= (|D2_k| + |D2_k+1|) t (1 - t) / 2 <= 1/8 of
  // the larger second difference D2 of the node heights (Catmull-Rom slopes).
  double bound = 0.0;
  for (const auto* h : {&left, &right})
    for (std::size_t k = 1; k + 1 < h->size(); ++k)
      bound = std::max(bound, std::abs((*h)[k + 1] - 2.0 * (*h)[k] + (*h)[k - 1]) / 8.0);
  description["c1_vs_bilinear_bound_m"] = bound;
  return std::make_shared<GridRoad>(s.u0_m - u_at_x0, s.du_m, std::move(left), std::move(right),
                                    std::move(description));
}

}  // namespace dtwin
