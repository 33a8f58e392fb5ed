#include "study/import_drive.hpp"

#include <array>
#include <filesystem>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"

namespace dtwin {
namespace {

/// --window and --run-in over the mapping (given once: in the file or as the flag).
void applyWindowFlags(const ImportRequest& cfg, ImportMapping& m) {
  if (!cfg.window.empty()) {
    if (m.window_s)
      throw InputError("--window", "the mapping file gives window_s already (" + m.window_where +
                                       "): give the window once");
    if (cfg.window.size() != 2 || !(cfg.window[0] >= 0 && cfg.window[0] < cfg.window[1]))
      throw InputError(
          "--window",
          "expects START,END in seconds from the log's first row with 0 <= START < END");
    m.window_s = std::array<double, 2>{cfg.window[0], cfg.window[1]};
    m.window_where = "--window";
  }
  if (cfg.run_in >= 0) {
    if (!m.window_s)
      throw InputError("--run-in", "needs a window (--window or the mapping's window_s)");
    m.run_in_s = cfg.run_in;
  }
}

bool anyWheel(const ImportRequest& cfg) {
  for (const auto& w : cfg.road_wheels)
    if (!w.empty()) return true;
  return false;
}

/// --road-fl, --road-fr, --road-rl, --road-rr: each wheel's own motion, all four or none, not with
/// --road or --road-left/--road-right (as the mapping file's road_fl..road_rr).
void wheelsFromFlags(const ImportRequest& cfg, ImportMapping& m) {
  static const char* kFlags[4] = {"--road-fl", "--road-fr", "--road-rl", "--road-rr"};
  if (!anyWheel(cfg)) return;
  for (std::size_t c = 0; c < 4; ++c) {
    if (cfg.road_wheels[c].empty()) continue;
    if (m.road || m.road_left)
      throw InputError(kFlags[c], std::string("give either ") +
                                      (m.road ? "--road" : "--road-left and --road-right") +
                                      " (the road under the axles) or --road-fl, --road-fr, "
                                      "--road-rl and --road-rr (each wheel's own motion)");
  }
  for (std::size_t c = 0; c < 4; ++c)
    if (cfg.road_wheels[c].empty())
      throw InputError(kFlags[c],
                       "is required with the other wheels' columns (--road-fl, --road-fr, "
                       "--road-rl and --road-rr: all four or none)");
  for (std::size_t c = 0; c < 4; ++c)
    m.road_wheels[c] = parseImportColumn(cfg.road_wheels[c], kFlags[c]);
}

/// The mapping from the command line: --time, --speed, --road | --road-left/--road-right |
/// --road-fl..--road-rr,
/// --channel COL:CHANNEL:UNIT[:OFFSET[:SCALE]] (repeatable).
ImportMapping mappingFromFlags(const ImportRequest& cfg) {
  ImportMapping m;
  m.source = "command line";
  if (cfg.time.empty())
    throw InputError(
        "--time", "is required without --map (the log's time column, COLUMN[:UNIT], unit s or ms)");
  m.time = parseImportColumn(cfg.time, "--time", "s");
  if (cfg.speed.empty())
    throw InputError("--speed", "is required without --map (COLUMN:UNIT, unit km/h, m/s or mph)");
  m.speed = parseImportColumn(cfg.speed, "--speed");
  if (!cfg.road.empty()) m.road = parseImportColumn(cfg.road, "--road");
  if (!cfg.road_left.empty() || !cfg.road_right.empty()) {
    if (m.road)
      throw InputError("--road-left",
                       "give either --road (both tracks) or --road-left and --road-right");
    if (cfg.road_left.empty() || cfg.road_right.empty())
      throw InputError(cfg.road_left.empty() ? "--road-left" : "--road-right",
                       "is required with the other track");
    m.road_left = parseImportColumn(cfg.road_left, "--road-left");
    m.road_right = parseImportColumn(cfg.road_right, "--road-right");
  }
  wheelsFromFlags(cfg, m);
  if (cfg.highpass_hz > 0) {
    m.highpass_hz = cfg.highpass_hz;
    m.highpass_given = true;
  }
  m.speed_lowpass_hz = cfg.speed_lowpass_hz;
  if (!cfg.separator.empty()) m.separator = parseSeparator(cfg.separator, "--separator");
  if (cfg.channels.empty())
    throw InputError("--channel", "is required without --map (COLUMN:CHANNEL:UNIT, repeatable)");
  for (const auto& text : cfg.channels) {
    const auto a = text.find(':'), b = a == std::string::npos ? a : text.find(':', a + 1);
    if (b == std::string::npos)
      throw InputError("--channel",
                       "expects COLUMN:CHANNEL:UNIT[:OFFSET[:SCALE]], got '" + text + "'");
    ImportChannel c;
    c.channel = text.substr(a + 1, b - a - 1);
    c.source = parseImportColumn(text.substr(0, a) + ":" + text.substr(b + 1), "--channel " + text);
    m.channels.push_back(c);
  }
  return m;
}

}  // namespace

ImportMapping importMapping(const ImportRequest& cfg) {
  const bool flags = !cfg.time.empty() || !cfg.speed.empty() || !cfg.road.empty() ||
                     !cfg.road_left.empty() || !cfg.road_right.empty() || anyWheel(cfg) ||
                     !cfg.channels.empty() || cfg.highpass_hz > 0 || cfg.speed_lowpass_hz > 0 ||
                     !cfg.separator.empty();
  if (!cfg.map.empty() && flags)
    throw InputError("--map",
                     "give the mapping either in the file or as flags (--time, --speed, --road, "
                     "--channel), not both");
  if (cfg.map.empty() && !flags)
    throw InputError("--map", "is required (or the flags --time, --speed, --channel)");
  ImportMapping mapping = cfg.map.empty() ? mappingFromFlags(cfg) : readImportMapping(cfg.map);
  applyWindowFlags(cfg, mapping);
  return mapping;
}

ImportResult importDrive(const ImportRequest& request, const StageProgress& progress) {
  if (request.log.empty()) throw InputError("--log", "is required (the logger's CSV or MF4 file)");
  const ImportMapping mapping = importMapping(request);
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(request.log, ec);
  if (!ec && bytes > 4000000000ULL)
    throw InputError(
        request.log,
        "is " + formatNumber(static_cast<double>(bytes) / 1e9, 3) +
            " GB; twin import holds a log in memory, at most 4 GB: split it into drives");
  const std::string text = readTextFile(request.log, " (a logger's CSV or MF4 file)");
  ImportResult r = importLog(text, request.log, mapping, request.study, request.scenario, progress);
  r.sidecar["command"] = request.command;
  writeImport(r, request.out);
  return r;
}

}  // namespace dtwin
