// `twin import`: a logger's wide CSV or MF4 log into the twin's files and a study holding the drive
// (io/log_import.hpp, docs/measurements.md).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "io/log_import.hpp"

namespace dtwin::cli {
namespace {

struct ImportConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string log, positional, map, out, study = defaultStudy(), scenario = "drive";
  std::string time, speed, road, road_left, road_right, separator;
  std::vector<std::string> channels;
  double highpass_hz = 0.0, speed_lowpass_hz = 0.0;
  std::vector<double> window;  ///< --window A,B
  double run_in = -1;          ///< --run-in S (-1: the mapping's, or 10 s)
  bool quiet = false;
};

/// --window and --run-in over the mapping (given once: in the file or as the flag).
void applyWindowFlags(const ImportConfig& cfg, ImportMapping& m) {
  if (!cfg.window.empty()) {
    if (m.window_s) throw InputError("--window", "the mapping file gives window_s already (" + m.window_where + "): give the window once");
    if (cfg.window.size() != 2 || !(cfg.window[0] >= 0 && cfg.window[0] < cfg.window[1]))
      throw InputError("--window", "expects START,END in seconds from the log's first row with 0 <= START < END");
    m.window_s = std::array<double, 2>{cfg.window[0], cfg.window[1]};
    m.window_where = "--window";
  }
  if (cfg.run_in >= 0) {
    if (!m.window_s) throw InputError("--run-in", "needs a window (--window or the mapping's window_s)");
    m.run_in_s = cfg.run_in;
  }
}

/// The mapping from the command line: --time, --speed, --road | --road-left/--road-right,
/// --channel COL:CHANNEL:UNIT[:OFFSET[:SCALE]] (repeatable).
ImportMapping mappingFromFlags(const ImportConfig& cfg) {
  ImportMapping m;
  m.source = "command line";
  if (cfg.time.empty()) throw InputError("--time", "is required without --map (the log's time column, COLUMN[:UNIT], unit s or ms)");
  m.time = parseImportColumn(cfg.time, "--time", "s");
  if (cfg.speed.empty()) throw InputError("--speed", "is required without --map (COLUMN:UNIT, unit km/h, m/s or mph)");
  m.speed = parseImportColumn(cfg.speed, "--speed");
  if (!cfg.road.empty()) m.road = parseImportColumn(cfg.road, "--road");
  if (!cfg.road_left.empty() || !cfg.road_right.empty()) {
    if (m.road) throw InputError("--road-left", "give either --road (both tracks) or --road-left and --road-right");
    if (cfg.road_left.empty() || cfg.road_right.empty()) throw InputError(cfg.road_left.empty() ? "--road-left" : "--road-right", "is required with the other track");
    m.road_left = parseImportColumn(cfg.road_left, "--road-left");
    m.road_right = parseImportColumn(cfg.road_right, "--road-right");
  }
  if (cfg.highpass_hz > 0) {
    m.highpass_hz = cfg.highpass_hz;
    m.highpass_given = true;
  }
  m.speed_lowpass_hz = cfg.speed_lowpass_hz;
  if (!cfg.separator.empty()) m.separator = parseSeparator(cfg.separator, "--separator");
  if (cfg.channels.empty()) throw InputError("--channel", "is required without --map (COLUMN:CHANNEL:UNIT, repeatable)");
  for (const auto& text : cfg.channels) {
    const auto a = text.find(':'), b = a == std::string::npos ? a : text.find(':', a + 1);
    if (b == std::string::npos) throw InputError("--channel", "expects COLUMN:CHANNEL:UNIT[:OFFSET[:SCALE]], got '" + text + "'");
    ImportChannel c;
    c.channel = text.substr(a + 1, b - a - 1);
    c.source = parseImportColumn(text.substr(0, a) + ":" + text.substr(b + 1), "--channel " + text);
    m.channels.push_back(c);
  }
  return m;
}

int runImport(ImportConfig cfg, const std::string& command) {
  if (!cfg.positional.empty()) {  // the older shape `twin import FILE`
    if (!cfg.log.empty()) throw InputError("--log", "give the logger's CSV once (--log FILE)");
    deprecationNote("twin import FILE", "twin import --log FILE", cfg.processes);
    cfg.log = cfg.positional;
  }
  if (cfg.log.empty()) throw InputError("--log", "is required (the logger's CSV or MF4 file)");
  const bool flags = !cfg.time.empty() || !cfg.speed.empty() || !cfg.road.empty() || !cfg.road_left.empty() ||
                     !cfg.road_right.empty() || !cfg.channels.empty() || cfg.highpass_hz > 0 || cfg.speed_lowpass_hz > 0 || !cfg.separator.empty();
  if (!cfg.map.empty() && flags) throw InputError("--map", "give the mapping either in the file or as flags (--time, --speed, --road, --channel), not both");
  if (cfg.map.empty() && !flags) throw InputError("--map", "is required (or the flags --time, --speed, --channel)");
  ImportMapping mapping = cfg.map.empty() ? mappingFromFlags(cfg) : readImportMapping(cfg.map);
  applyWindowFlags(cfg, mapping);
  const auto t0 = std::chrono::steady_clock::now();
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(cfg.log, ec);
  if (!ec && bytes > 4000000000ULL)
    throw InputError(cfg.log, "is " + formatNumber(static_cast<double>(bytes) / 1e9, 3) +
                                  " GB; twin import holds a log in memory, at most 4 GB: split it into drives");
  const std::string text = readTextFile(cfg.log, " (a logger's CSV or MF4 file)");
  ProgressBar bar("import " + cfg.log, progressOn(cfg.quiet, cfg.processes), stderrIsTerminal());
  ImportResult r = importLog(text, cfg.log, mapping, cfg.study, cfg.scenario,
                             [&bar](const std::string&, std::size_t done, std::size_t total) { bar.update(done, total); });
  r.sidecar["command"] = command;
  writeImport(r, cfg.out);
  bar.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!cfg.quiet) {
    std::printf("imported %ld rows (%s s of driving, %zu records, %ld empty cells skipped) in %.2f s\n", r.rows,
                formatNumber(r.duration_s, 6).c_str(), r.data.records.size(), r.dropped_cells, wall);
    std::printf("wrote %s/: measurements.csv (+ .json), speed.csv, %sstudy.toml (scenario '%s')\n", cfg.out.c_str(),
                r.road_csv.empty() ? "" : "road.csv, ", r.scenario.c_str());
    if (r.road_csv.empty()) std::printf("note: no road column was mapped: the drive's scenario has a flat road\n");
    if (r.outside_window > 0 || !r.masked.empty()) {
      std::string dropped = std::to_string(r.outside_window) + " rows outside the window";
      for (const auto& [text, count] : r.masked) dropped += ", " + std::to_string(count) + " masked by " + text;
      std::printf("not measured (neither fitted nor scored; measurements.json says why): %s; the run starts at log time %s s, %s m down the road\n",
                  dropped.c_str(), formatNumber(r.t0_s, 6).c_str(), formatNumber(r.start_m, 6).c_str());
    }
    std::printf("next: twin compare --study %s/study.toml --calibration CAL_DIR --data %s/measurements.csv\n", cfg.out.c_str(), cfg.out.c_str());
  }
  return 0;
}

}  // namespace

CommandHandle addImportCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<ImportConfig>();
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "import");
  c->add_option("--log", cfg->log, "The logger's file: a CSV, or an MF4 log (.mf4, .mdf; docs/measurements.md)");
  c->add_option("log_file", cfg->positional, "Deprecated: give --log FILE");
  c->add_option("--out", cfg->out, "New output folder: measurements.csv + .json, speed.csv, road.csv (when a road column is mapped), study.toml")->required();
  c->add_option("--map", cfg->map, "Mapping file (TOML, [import] table); or give the mapping as the flags below");
  c->add_option("--study", cfg->study, "The study the drive joins (its vehicle, assemblies, sensors)")->capture_default_str();
  c->add_option("--scenario", cfg->scenario, "Name of the drive's scenario in the written study")->capture_default_str();
  c->add_option("--time", cfg->time, "Time column, COLUMN[:UNIT] (s or ms)");
  c->add_option("--speed", cfg->speed, "Speed column, COLUMN:UNIT[:OFFSET[:SCALE]] (km/h, m/s, mph)");
  c->add_option("--road", cfg->road, "Road under the front axle, both tracks, COLUMN:UNIT (m, mm: height; m/s, mm/s: road velocity)");
  c->add_option("--road-left", cfg->road_left, "Left track's road column, COLUMN:UNIT");
  c->add_option("--road-right", cfg->road_right, "Right track's road column, COLUMN:UNIT");
  c->add_option("--channel", cfg->channels, "A measured channel, COLUMN:CHANNEL:UNIT[:OFFSET[:SCALE]] (repeatable), e.g. az:seat_mps2:g:1");
  c->add_option("--highpass-hz", cfg->highpass_hz, "Drift removal of a road velocity [Hz] (default 0.1)")->check(CLI::Range(1e-3, 10.0));
  c->add_option("--speed-lowpass-hz", cfg->speed_lowpass_hz, "Smooth the speed by a zero-phase low-pass at this cut-off [Hz] (default: none)")
      ->check(CLI::Range(0.01, 100.0));
  c->add_option("--separator", cfg->separator, "Field separator of the log: one character, 'tab', or 'whitespace' (a run of spaces and tabs; default ',')");
  c->add_option("--window", cfg->window,
                "Only rows in START,END (s from the log's first row) are measurements; the run starts --run-in before START")
      ->delimiter(',')
      ->expected(2);
  c->add_option("--run-in", cfg->run_in, "Seconds of the log simulated before the window, for the model to settle (default 10)")
      ->check(CLI::Range(0.0, 3600.0));
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  addExamples(c, {
               "twin import --log data/drives/stop_and_go.csv --map data/drives/stop_and_go_map.toml --out out/drive"});
  return {c, [cfg, command_line] { return runImport(*cfg, command_line); }, {}};
}

}  // namespace dtwin::cli
