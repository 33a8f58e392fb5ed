// `twin import`: a logger's wide CSV or MF4 log into the twin's files and a study holding the drive
// (study/import_drive.hpp, io/log_import.hpp, docs/measurements.md).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "study/import_drive.hpp"

namespace dtwin::cli {
namespace {

struct ImportConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  ImportRequest request;                   ///< the flags (study/import_drive.hpp)
  std::string positional;                  ///< the older `twin import FILE`
  bool quiet = false;
};

int runImport(ImportConfig cfg, const std::string& command) {
  ImportRequest& req = cfg.request;
  if (!cfg.positional.empty()) {  // the older shape `twin import FILE`
    if (!req.log.empty()) throw InputError("--log", "give the logger's CSV once (--log FILE)");
    deprecationNote("twin import FILE", "twin import --log FILE", cfg.processes);
    req.log = cfg.positional;
  }
  req.command = command;
  const auto t0 = std::chrono::steady_clock::now();
  ProgressBar bar("import " + req.log, progressOn(cfg.quiet, cfg.processes), stderrIsTerminal());
  const ImportResult r = importDrive(req, [&bar](const std::string&, std::size_t done,
                                                 std::size_t total) { bar.update(done, total); });
  bar.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!cfg.quiet) {
    std::printf(
        "imported %ld rows (%s s of driving, %zu records, %ld empty cells skipped) in %.2f s\n",
        r.rows, formatNumber(r.duration_s, 6).c_str(), r.data.records.size(), r.dropped_cells,
        wall);
    std::printf("wrote %s/: measurements.csv (+ .json), speed.csv, %sstudy.toml (scenario '%s')\n",
                req.out.c_str(), r.road_csv.empty() ? "" : "road.csv, ", r.scenario.c_str());
    if (r.road_csv.empty())
      std::printf("note: no road column was mapped: the drive's scenario has a flat road\n");
    if (r.outside_window > 0 || !r.masked.empty()) {
      std::string dropped = std::to_string(r.outside_window) + " rows outside the window";
      for (const auto& [text, count] : r.masked)
        dropped += ", " + std::to_string(count) + " masked by " + text;
      std::printf(
          "not measured (neither fitted nor scored; measurements.json says why): %s; the run "
          "starts at log time %s s, %s m down the road\n",
          dropped.c_str(), formatNumber(r.t0_s, 6).c_str(), formatNumber(r.start_m, 6).c_str());
    }
    std::printf(
        "next: twin compare --study %s/study.toml --calibration CAL_DIR --data "
        "%s/measurements.csv\n",
        req.out.c_str(), req.out.c_str());
  }
  return 0;
}

}  // namespace

CommandHandle addImportCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<ImportConfig>();
  cfg->request.study = defaultStudy();
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "import");
  c->add_option("--log", cfg->request.log,
                "The logger's file: a CSV, or an MF4 log (.mf4, .mdf; docs/measurements.md)");
  c->add_option("log_file", cfg->positional, "Deprecated: give --log FILE");
  c->add_option("--out", cfg->request.out,
                "New output folder: measurements.csv + .json, speed.csv, road.csv (when a road "
                "column is mapped), study.toml")
      ->required();
  c->add_option("--map", cfg->request.map,
                "Mapping file (TOML, [import] table); or give the mapping as the flags below");
  c->add_option("--study", cfg->request.study,
                "The study the drive joins (its vehicle, assemblies, sensors)")
      ->capture_default_str();
  c->add_option("--scenario", cfg->request.scenario,
                "Name of the drive's scenario in the written study")
      ->capture_default_str();
  c->add_option("--time", cfg->request.time, "Time column, COLUMN[:UNIT] (s or ms)");
  c->add_option("--speed", cfg->request.speed,
                "Speed column, COLUMN:UNIT[:OFFSET[:SCALE]] (km/h, m/s, mph)");
  c->add_option("--road", cfg->request.road,
                "Road under the front axle, both tracks, COLUMN:UNIT (m, mm: height; m/s, mm/s: "
                "road velocity)");
  c->add_option("--road-left", cfg->request.road_left, "Left track's road column, COLUMN:UNIT");
  c->add_option("--road-right", cfg->request.road_right, "Right track's road column, COLUMN:UNIT");
  static const char* kWheels[4][2] = {{"--road-fl", "front-left"},
                                      {"--road-fr", "front-right"},
                                      {"--road-rl", "rear-left"},
                                      {"--road-rr", "rear-right"}};
  for (std::size_t w = 0; w < 4; ++w)
    c->add_option(kWheels[w][0], cfg->request.road_wheels[w],
                  std::string("The ") + kWheels[w][1] +
                      " wheel's own motion, COLUMN:UNIT[:OFFSET[:SCALE]] (m, mm: height; m/s: "
                      "velocity; m/s^2, g: acceleration, gravity removed by the offset); all "
                      "four wheels or none");
  c->add_option("--channel", cfg->request.channels,
                "A measured channel, COLUMN:CHANNEL:UNIT[:OFFSET[:SCALE]] (repeatable), e.g. "
                "az:seat_mps2:g:1");
  c->add_option("--highpass-hz", cfg->request.highpass_hz,
                "Drift removal of a road velocity [Hz] (default 0.1)")
      ->check(CLI::Range(1e-3, 10.0));
  c->add_option("--speed-lowpass-hz", cfg->request.speed_lowpass_hz,
                "Smooth the speed by a zero-phase low-pass at this cut-off [Hz] (default: none)")
      ->check(CLI::Range(0.01, 100.0));
  c->add_option("--separator", cfg->request.separator,
                "Field separator of the log: one character, 'tab', or 'whitespace' (a run of "
                "spaces and tabs; default ',')");
  c->add_option("--window", cfg->request.window,
                "Only rows in START,END (s from the log's first row) are measurements; the run "
                "starts --run-in before START")
      ->delimiter(',')
      ->expected(2);
  c->add_option(
       "--run-in", cfg->request.run_in,
       "Seconds of the log simulated before the window, for the model to settle (default 10)")
      ->check(CLI::Range(0.0, 3600.0));
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  addExamples(c, {"twin import --log data/drives/stop_and_go.csv --map "
                  "data/drives/stop_and_go_map.toml --out out/drive"});
  return {c, [cfg, command_line] { return runImport(*cfg, command_line); }, {}};
}

}  // namespace dtwin::cli
