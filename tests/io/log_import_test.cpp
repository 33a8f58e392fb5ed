// `twin import`: a logger's wide CSV into measurements, a speed trace, a road against time and a
// study holding the drive. Units and offsets convert exactly; every bad-log case is one line
// naming the file, the line and the column, with exit code 2 and nothing written.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "common/errors.hpp"
#include "io/log_import.hpp"
#include "io/study.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;
namespace fs = std::filesystem;

namespace {

const std::string kDemo = std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml";

const char* kMapping = R"([import]
time = { column = "t", unit = "ms" }
speed = { column = "v", unit = "km/h" }
road = { column = "zr", unit = "mm" }

[[import.channels]]
column = "az"
channel = "seat_mps2"
unit = "g"
offset = 1.0

[[import.channels]]
column = "defl"
channel = "susp_defl_fl_m"
unit = "mm"
scale = -1.0

[sensors.seat]
position_m = [0.5, 0.3, 0.1]
quantity = "acceleration_z"
noise_sd = 0.05
)";

/// A 4 s log at 100 Hz starting at logger time 5000 ms; `edit(k, line)` may spoil row k.
std::string makeLog(const std::function<void(int, std::string&)>& edit = {}) {
  std::string log = "t,v,zr,az,defl,unused\n";
  for (int k = 0; k <= 400; ++k) {
    std::string line = std::to_string(5000 + 10 * k) + ",36," +
                       std::to_string(2.0 * std::sin(0.05 * k)) + "," +
                       std::to_string(1.0 + 0.01 * k / 400.0) + ",3,x";
    if (edit) edit(k, line);
    log += line + "\n";
  }
  return log;
}

struct Cli {
  int code;
  std::string err;
};
Cli twin(const std::string& args) {
  const std::string dir = ::testing::TempDir();
  const std::string cmd = std::string(DTWIN_TWIN_EXE) + " " + args + " > " + dir +
                          "/imp_out.txt 2> " + dir + "/imp_err.txt";
  const int st = std::system(cmd.c_str());
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, dtwin_test::slurp(dir + "/imp_err.txt")};
}

}  // namespace

// Units, offsets and scales convert exactly; times start at 0; the study holds the drive with its
// speed trace, its road and the mapping's sensor, and reads back.
TEST(LogImport, ConvertsUnitsAndWritesAStudyThatReadsBack) {
  const fs::path dir = dtwin_test::freshDir("import_ok");
  dtwin_test::writeText(dir / "map.toml", kMapping);
  const ImportMapping m = readImportMapping((dir / "map.toml").string());
  const ImportResult r = importLog(makeLog(), "log.csv", m, kDemo, "drive");
  EXPECT_EQ(r.rows, 401);
  EXPECT_DOUBLE_EQ(r.t0_s, 5.0);
  EXPECT_DOUBLE_EQ(r.duration_s, 4.0);
  ASSERT_EQ(r.data.records.size(), 802u);
  EXPECT_EQ(r.data.records[0].channel, "seat_mps2");
  EXPECT_EQ(r.data.records[0].time_s, 0.0);
  EXPECT_NEAR(r.data.records[800].value, 0.01 * 9.80665, 1e-12);  // (1.01 g − 1 g) in m/s²
  EXPECT_DOUBLE_EQ(r.data.records[801].value, -0.003);            // 3 mm, scale −1
  EXPECT_DOUBLE_EQ(r.data.records[801].time_s, 4.0);
  EXPECT_NE(r.speed_csv.find("\n0.01,10\n"), std::string::npos);  // 36 km/h = 10 m/s, at 10 ms
  EXPECT_EQ(r.road_csv.substr(0, 16), "time_s,height_m\n");
  writeImport(r, (dir / "out").string());
  const Study s = loadStudy((dir / "out" / "study.toml").string());
  const ScenarioSpec& sc = s.scenario("drive");
  EXPECT_DOUBLE_EQ(sc.duration_s, 4.0);
  EXPECT_DOUBLE_EQ(sc.speed.speed(2.0), 10.0);
  EXPECT_EQ(sc.road->type(), "csv_time");
  ASSERT_EQ(s.sensors.size(), 1u);
  EXPECT_EQ(s.sensors[0].channel(), "seat_mps2");
  // The base study's text is kept: the same assemblies under the same ids (the subsystems'
  // order sets them), and its comments.
  const auto base = loadStudy(kDemo).assemblies(), now = s.assemblies();
  ASSERT_EQ(now.size(), base.size());
  for (std::size_t i = 0; i < base.size(); ++i)
    EXPECT_EQ(now[i].id + " " + now[i].label(), base[i].id + " " + base[i].label());
  EXPECT_NE(dtwin_test::slurp(dir / "out" / "study.toml").find("# The paper's demonstration study"),
            std::string::npos);
  const LabData back =
      readLabCsv((dir / "out" / "measurements.csv").string(), measurableChannels(s.sensors));
  EXPECT_EQ(back.records.size(), 802u);
  const auto side = nlohmann::json::parse(dtwin_test::slurp(dir / "out" / "measurements.json"));
  EXPECT_EQ(side["scenario"]["name"], "drive");
  EXPECT_EQ(side["source"]["rows"], 401);
  EXPECT_FALSE(fs::exists(dir / "out.import-tmp"));
}

// A few empty or NaN cells in a channel are skipped and counted; more in a row than
// max_dropout_rows is an error at the first of them.
TEST(LogImport, ShortDropoutsAreSkippedLongOnesRefused) {
  const fs::path dir = dtwin_test::freshDir("import_dropouts");
  dtwin_test::writeText(dir / "map.toml", kMapping);
  const ImportMapping m = readImportMapping((dir / "map.toml").string());
  const auto gap = [](int from, int to) {
    return [from, to](int k, std::string& line) {
      if (k < from || k >= to) return;
      std::size_t at = 0;
      for (int comma = 0; comma < 3; ++comma) at = line.find(',', at) + 1;  // the az field
      line = line.substr(0, at) + "NaN" + line.substr(line.find(',', at));
    };
  };
  const ImportResult r = importLog(makeLog(gap(10, 15)), "log.csv", m, kDemo, "drive");
  EXPECT_EQ(r.dropped_cells, 5);
  EXPECT_EQ(r.data.records.size(), 797u);
  try {
    importLog(makeLog(gap(10, 16)), "log.csv", m, kDemo, "drive");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("log.csv:17: column 'az': empty or NaN from line 12 on"),
              std::string::npos)
        << e.what();
  }
}

// Every bad log and bad mapping from the command line: exit 2, one line naming the file, the
// line and the column (or the mapping field), and no output folder.
TEST(LogImport, BadLogsGiveOneLineErrorsAndWriteNothing) {
  const fs::path dir = dtwin_test::freshDir("import_bad");
  dtwin_test::writeText(dir / "map.toml", kMapping);
  struct Case {
    std::string name, log, map, expect;
  };
  const std::string map = (dir / "map.toml").string();
  auto spoil = [](int row, const std::string& with) {
    return makeLog([row, with](int k, std::string& line) {
      if (k == row) line = with;
    });
  };
  std::string renamed = makeLog();
  renamed.replace(0, 4, "tt,v");
  std::string bad_unit = kMapping;
  bad_unit.replace(bad_unit.find("\"km/h\""), 6, "\"km/s\"");
  std::string wrong_unit = kMapping;
  wrong_unit.replace(wrong_unit.find("unit = \"mm\"\nscale"), 11, "unit = \"g\"");
  dtwin_test::writeText(dir / "bad_unit.toml", bad_unit);
  dtwin_test::writeText(dir / "wrong_unit.toml", wrong_unit);
  const std::vector<Case> cases = {
      {"missing_column", renamed, map, "log.csv:1: no column 't' ("},
      {"non_numeric", spoil(7, "5070,36,0.1,1.0,abc,x"), map,
       "log.csv:9: column 'defl': 'abc' is not a number"},
      {"backwards", spoil(7, "5055,36,0.1,1.0,3,x"), map,
       "log.csv:9: column 't': time goes backwards: 5055 after 5060"},
      {"duplicated", spoil(7, "5060,36,0.1,1.0,3,x"), map,
       "log.csv:9: column 't': time 5060 repeats the row before (line 8)"},
      {"nan_time", spoil(7, "nan,36,0.1,1.0,3,x"), map,
       "log.csv:9: column 't': 'nan' is not a finite number"},
      {"empty_speed", spoil(7, "5070,,0.1,1.0,3,x"), map, "log.csv:9: column 'v': is empty or NaN"},
      {"columns", spoil(7, "5070,36,0.1,1.0,3"), map,
       "log.csv:9: expected 6 columns (as the header), got 5"},
      {"unknown_unit", makeLog(), (dir / "bad_unit.toml").string(),
       "bad_unit.toml:3: import.speed.unit: unknown unit 'km/s'"},
      {"wrong_unit", makeLog(), (dir / "wrong_unit.toml").string(),
       "wrong_unit.toml:15: import.channels[1].unit: unit 'g' is in m/s^2, but this needs m"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path log = dir / "log.csv";
    dtwin_test::writeText(log, c.log);
    const fs::path out = dir / ("out_" + c.name);
    const Cli r =
        twin("import --log " + log.string() + " --map " + c.map + " --out " + out.string());
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(dir / ("out_" + c.name + ".import-tmp")));
  }
}

// The mapping can be given as flags instead of a file; an existing folder is not overwritten.
TEST(LogImport, FlagsMapTheLogAndAnExistingFolderIsKept) {
  const fs::path dir = dtwin_test::freshDir("import_flags");
  dtwin_test::writeText(dir / "log.csv", makeLog());
  const std::string base =
      "import --log " + (dir / "log.csv").string() +
      " --time t:ms --speed v:km/h --road zr:mm --channel defl:susp_defl_fl_m:mm";
  Cli r = twin(base + " --out " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const Study s = loadStudy((dir / "out" / "study.toml").string());
  EXPECT_EQ(s.scenario("drive").road->type(), "csv_time");
  const std::string before = dtwin_test::slurp(dir / "out" / "measurements.csv");
  r = twin(base + " --out " + (dir / "out").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("exists and is not an empty folder"), std::string::npos) << r.err;
  EXPECT_EQ(dtwin_test::slurp(dir / "out" / "measurements.csv"), before);
  r = twin(base + " --map x.toml --out " + (dir / "out2").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--map: give the mapping either in the file or as flags"), std::string::npos)
      << r.err;
  r = twin("import --log " + (dir / "log.csv").string() +
           " --time t:ms --speed v:km/h --channel defl:susp_defl_fl_m:furlong --out " +
           (dir / "out3").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown unit 'furlong'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out3"));
  // A drift filter for a road that is a height, and a separator of two characters: refused.
  r = twin(base + " --highpass-hz 0.2 --out " + (dir / "out4").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--highpass-hz: applies to a road velocity"), std::string::npos) << r.err;
  r = twin(base + " --separator ';;' --out " + (dir / "out5").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--separator: must be one character"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out4"));
  EXPECT_FALSE(fs::exists(dir / "out5"));
}

// A GPS speed in 0.1 km/h steps is smoothed by speed_lowpass_hz: zero phase (a ramp passes
// through unchanged away from the ends), never negative, and the sidecar records it.
TEST(LogImport, SpeedLowPassSmoothsAQuantisedSpeed) {
  std::string log = "t,v,defl\n";
  for (int k = 0; k <= 1000; ++k) {
    const double v = k < 200 ? 0.0 : 0.02 * (k - 200);  // km/h: rest, then a ramp of 2 km/h/s
    char line[64];
    std::snprintf(line, sizeof line, "%d,%.1f,3\n", 10 * k, std::round(v * 10) / 10);
    log += line;
  }
  ImportMapping m;
  m.source = "test";
  m.time = {"t", "ms", 0, 1, "time", ""};
  m.speed = ImportColumn{"v", "km/h", 0, 1, "speed", ""};
  m.channels.push_back({{"defl", "mm", 0, 1, "defl", ""}, "susp_defl_fl_m"});
  m.speed_lowpass_hz = 1.0;
  const ImportResult r = importLog(log, "log.csv", m, kDemo, "drive");
  std::vector<double> v;
  std::istringstream in(r.speed_csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) v.push_back(std::stod(line.substr(line.find(',') + 1)));
  ASSERT_EQ(v.size(), 1001u);
  for (double x : v) EXPECT_GE(x, 0.0);
  for (int k = 500; k <= 900; k += 50)
    EXPECT_NEAR(v[static_cast<std::size_t>(k)], 0.02 * (k - 200) / 3.6, 0.01) << k;
  // The steps of 0.1 km/h (0.028 m/s every 5th sample) are gone: neighbouring samples differ by
  // about the ramp's 0.0056 m/s per sample.
  for (int k = 500; k < 900; ++k)
    EXPECT_LT(std::abs(v[static_cast<std::size_t>(k) + 1] - v[static_cast<std::size_t>(k)]), 0.008)
        << k;
  EXPECT_EQ(r.sidecar["mapping"]["speed"]["lowpass_hz"], 1.0);
}

// A log as some loggers write it: a preamble before the header, a row of units after it,
// semicolons between fields and decimal commas.
TEST(LogImport, PreambleUnitsRowSemicolonsAndDecimalCommas) {
  const fs::path dir = dtwin_test::freshDir("import_european");
  std::string log = "Logger;XY-200\nDate;2026-11-26\n\nZeit;Geschw;Beschl\ns;km/h;g\n";
  for (int k = 0; k <= 200; ++k)
    log += std::to_string(k / 100) + "," + (k % 100 < 10 ? "0" : "") + std::to_string(k % 100) +
           ";36,0;1,0" + std::to_string(k % 10) + "\n";
  dtwin_test::writeText(dir / "log.csv", log);
  dtwin_test::writeText(dir / "map.toml", R"([import]
time = "Zeit"
speed = { column = "Geschw", unit = "km/h" }
separator = ";"
decimal_comma = true
header_line = 4
skip_rows = 1

[[import.channels]]
column = "Beschl"
channel = "chassis_heave_acc_mps2"
unit = "g"
offset = 1.0
)");
  const ImportMapping m = readImportMapping((dir / "map.toml").string());
  const ImportResult r =
      importLog(dtwin_test::slurp(dir / "log.csv"), "log.csv", m, kDemo, "drive");
  EXPECT_EQ(r.rows, 201);
  EXPECT_DOUBLE_EQ(r.duration_s, 2.0);
  EXPECT_NEAR(r.data.records[3].value, 0.03 * 9.80665, 1e-12);
  EXPECT_DOUBLE_EQ(r.data.records[3].time_s, 0.03);
  EXPECT_NE(r.speed_csv.find("\n0.03,10\n"), std::string::npos);
  // A comma separator with decimal commas is refused at the field.
  std::string bad = dtwin_test::slurp(dir / "map.toml");
  bad.replace(bad.find("separator = \";\"\n"), 16, "");
  dtwin_test::writeText(dir / "bad.toml", bad);
  try {
    readImportMapping((dir / "bad.toml").string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("import.decimal_comma: needs a separator other than ','"),
              std::string::npos)
        << e.what();
  }
}

// Clock times as loggers write them, checked against days and seconds counted by hand.
TEST(LogImport, ClockTimesParseWithDatesFractionsAndOffsets) {
  ClockTime c;
  ASSERT_TRUE(parseClockTime("14:03:07.25", c));
  EXPECT_FALSE(c.has_date);
  EXPECT_EQ(c.day, 0);
  EXPECT_DOUBLE_EQ(c.seconds, 14 * 3600 + 3 * 60 + 7.25);
  ASSERT_TRUE(parseClockTime(" 9:00:00,5 ", c));  // one-digit hour, decimal comma, spaces
  EXPECT_DOUBLE_EQ(c.seconds, 9 * 3600 + 0.5);
  ASSERT_TRUE(parseClockTime("1970-01-02T00:00:01Z", c));
  EXPECT_TRUE(c.has_date);
  EXPECT_EQ(c.day, 1);
  EXPECT_DOUBLE_EQ(c.seconds, 1.0);
  // 2000-03-01: 30 years of 365 days, 7 leap days (1972..1996), and 2000's Jan + Feb (31 + 29).
  ASSERT_TRUE(parseClockTime("2000/03/01 12:00:00", c));
  EXPECT_EQ(c.day, 30 * 365 + 7 + 31 + 29);
  // An offset moves the time to UTC, across midnight when it must.
  ASSERT_TRUE(parseClockTime("2000-03-01T01:30:00+02:00", c));
  EXPECT_EQ(c.day, 30 * 365 + 7 + 31 + 29 - 1);
  EXPECT_DOUBLE_EQ(c.seconds, 23.5 * 3600);
  ASSERT_TRUE(parseClockTime("2000-03-01T23:30:00-0100", c));
  EXPECT_EQ(c.day, 30 * 365 + 7 + 31 + 29 + 1);
  EXPECT_DOUBLE_EQ(c.seconds, 0.5 * 3600);
  for (const char* bad :
       {"", "12:00", "25:00:00", "12:60:00", "12:00:00.", "12:00:00x", "2001-02-29 12:00:00",
        "2000-13-01 00:00:00", "2000-01-01T12:00:00+2", "1.5", "12:0:00"})
    EXPECT_FALSE(parseClockTime(bad, c)) << bad;
}

// A log whose time column is a date and clock time runs from its first row; a drive past midnight
// without a date goes on the next day; a cell that is not a clock time is one line naming it.
TEST(LogImport, ATimeColumnOfClockTimes) {
  const fs::path dir = dtwin_test::freshDir("import_clock");
  dtwin_test::writeText(dir / "map.toml", R"([import]
time = { column = "stamp", unit = "clock" }
speed = { column = "v", unit = "kph" }

[[import.channels]]
column = "az"
channel = "chassis_heave_acc_mps2"
unit = "m/s^2"
)");
  const ImportMapping m = readImportMapping((dir / "map.toml").string());
  auto log = [](const std::function<std::string(int)>& stamp) {
    std::string s = "stamp,v,az\n";
    for (int k = 0; k <= 300; ++k) s += stamp(k) + ",36," + std::to_string(0.001 * k) + "\n";
    return s;
  };
  auto hms = [](double t) {  // seconds of the day as HH:MM:SS.ss
    char b[32];
    const int h = static_cast<int>(t / 3600) % 24, mi = static_cast<int>(t / 60) % 60;
    std::snprintf(b, sizeof b, "%02d:%02d:%05.2f", h, mi, t - 60.0 * std::floor(t / 60));
    return std::string(b);
  };
  // 23:59:58.50 for 3 s at 100 Hz, with a date, then without one.
  const ImportResult dated =
      importLog(log([&](int k) {
                  return (k < 150 ? "2026-11-26T" : "2026-11-27T") + hms(86398.5 + 0.01 * k);
                }),
                "dated.csv", m, kDemo, "drive");
  const ImportResult bare =
      importLog(log([&](int k) { return hms(86398.5 + 0.01 * k); }), "bare.csv", m, kDemo, "drive");
  for (const auto* r : {&dated, &bare}) {
    EXPECT_EQ(r->rows, 301);
    EXPECT_DOUBLE_EQ(r->t0_s, 86398.5);
    EXPECT_NEAR(r->duration_s, 3.0, 1e-9);
    EXPECT_NEAR(r->data.records[200].time_s, 2.0, 1e-9);
    EXPECT_DOUBLE_EQ(r->data.records[200].value, 0.2);
  }
  try {
    importLog(log([&](int k) { return k == 7 ? std::string("12:00:0x") : hms(100 + 0.01 * k); }),
              "odd.csv", m, kDemo, "drive");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("odd.csv:9: column 'stamp': '12:00:0x' is not a clock time"),
        std::string::npos)
        << e.what();
  }
  try {
    importLog(log([&](int k) { return hms(100 + 0.01 * (k == 7 ? 5 : k)); }), "back.csv", m, kDemo,
              "drive");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "back.csv:9: column 'stamp': time goes backwards: 00:01:40.05 after 00:01:40.06"),
              std::string::npos)
        << e.what();
  }
}

// A column-aligned log (runs of spaces and tabs between fields), read with separator "whitespace".
TEST(LogImport, AColumnAlignedLogWithWhitespaceBetweenFields) {
  const fs::path dir = dtwin_test::freshDir("import_aligned");
  std::string log = "  time_ms     speed_kph    acc\n";
  for (int k = 0; k <= 200; ++k) {
    char row[96];
    std::snprintf(row, sizeof row, "%8d  %10.1f \t %8.4f\n", 10 * k, 54.0, 0.001 * k);
    log += row;
  }
  dtwin_test::writeText(dir / "log.txt", log);
  const Cli r =
      twin("import --log " + (dir / "log.txt").string() +
           " --time time_ms:ms --speed speed_kph:kph --channel acc:chassis_heave_acc_mps2:m/s^2" +
           " --separator whitespace --quiet --out " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const LabData back = readLabCsv((dir / "out" / "measurements.csv").string());
  ASSERT_EQ(back.records.size(), 201u);
  EXPECT_DOUBLE_EQ(back.records[150].time_s, 1.5);
  EXPECT_DOUBLE_EQ(back.records[150].value, 0.15);
  EXPECT_NE(dtwin_test::slurp(dir / "out" / "speed.csv").find("\n1.5,15\n"),
            std::string::npos);  // 54 km/h
  for (const char* bad : {"'a'", "'.'", "'\"'"}) {
    const Cli b =
        twin("import --log " + (dir / "log.txt").string() +
             " --time time_ms:ms --speed speed_kph:kph --channel acc:chassis_heave_acc_mps2:m/s^2" +
             " --separator " + bad + " --out " + (dir / "bad").string());
    EXPECT_EQ(b.code, 2) << bad;
    EXPECT_NE(b.err.find("--separator: must be one character such as"), std::string::npos) << b.err;
  }
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

// The issue's promise: import -> compare with no hand editing. The shipped demonstration drive is
// imported and compared with a calibration at the truth without its hidden effect. The twin fails
// all along the drive, and compare prints how many windows there were in words, the eight windows
// holding the most of the residual, largest first, then one line for the rest, and the failing
// bands of the spectrum (of the longest stretch between the log's dropouts).
TEST(LogImport, TheDemonstrationDriveComparesWithNoHandEditing) {
  const fs::path dir = dtwin_test::freshDir("import_compare");
  const std::string drive = std::string(DTWIN_SOURCE_DIR) + "/data/drives/";
  Cli r = twin("import --log " + drive + "stop_and_go.csv --map " + drive +
               "stop_and_go_map.toml --quiet --out " + (dir / "drive").string());
  ASSERT_EQ(r.code, 0) << r.err;
  fs::create_directories(dir / "cal");
  dtwin_test::writeText(dir / "cal" / "summary.json", R"({"assembly": "M1"})");
  dtwin_test::writeText(
      dir / "cal" / "posterior.csv",
      "tire.stiffness,tire.damping,suspension.stiffness,suspension.damping,tau,design_index\n"
      "180000,3000,30000,2500,1,0\n");
  const std::string out = (dir / "out.txt").string();
  const std::string cmd =
      std::string(DTWIN_TWIN_EXE) + " compare --study " + (dir / "drive" / "study.toml").string() +
      " --calibration " + (dir / "cal").string() + " --data " +
      (dir / "drive" / "measurements.csv").string() + " --draws 1 > " + out + " 2>&1";
  const int st = std::system(cmd.c_str());
  ASSERT_EQ(WEXITSTATUS(st), 0) << dtwin_test::slurp(out);
  std::istringstream text(dtwin_test::slurp(out));
  std::vector<double> shares;
  int rest = 0, bands = 0, counted = 0;
  for (std::string line; std::getline(text, line);) {
    if (line.find("  windows: drive seat_mps2: ") == 0 &&
        line.find(" windows over ") != std::string::npos)
      ++counted;
    if (line.find("  fails: drive seat_mps2 ") != 0) continue;
    if (line.find("  fails: drive seat_mps2 band ") ==
        0) {  // the spectrum, of the longest stretch between the dropouts
      ++bands;
      continue;
    }
    if (line.find(" more windows holding ") != std::string::npos) {
      ++rest;
      continue;
    }
    const auto pct = line.find(" % of its residual");
    ASSERT_NE(pct, std::string::npos) << line;
    shares.push_back(std::stod(line.substr(line.rfind(", ", pct) + 2)));
  }
  EXPECT_EQ(counted, 1) << dtwin_test::slurp(out);
  EXPECT_EQ(shares.size(), 8u) << dtwin_test::slurp(out);
  EXPECT_EQ(rest, 1) << dtwin_test::slurp(out);
  EXPECT_GE(bands, 1) << "the hidden damper asymmetry shows in the spectrum: "
                      << dtwin_test::slurp(out);
  EXPECT_TRUE(std::is_sorted(shares.rbegin(), shares.rend()))
      << "largest share first: " << dtwin_test::slurp(out);
  EXPECT_NE(dtwin_test::slurp(out).find("lack of fit: chi2 = "), std::string::npos);
}

// A window keeps rows [a, b] as measurements, the run starts run_in_s before a with the
// log's speed and road, and the distance driven before it becomes the speed's start_m; a mask
// drops the rows where a column's magnitude is above (or below) its threshold. The sidecar says
// how many rows were dropped and why.
TEST(LogImport, AWindowAndAMaskChooseTheMeasuredRows) {
  const fs::path dir = dtwin_test::freshDir("import_window");
  dtwin_test::writeText(
      dir / "map.toml",
      std::string(kMapping).replace(std::string(kMapping).find("\n\n[[import.channels]]"), 0,
                                    "\nwindow_s = [1.0, 3.0]\nrun_in_s = 0.5\n"
                                    "exclude = { column = \"zr\", unit = \"mm\", above = 1.5 }"));
  const ImportMapping m = readImportMapping((dir / "map.toml").string());
  ASSERT_TRUE(m.window_s);
  ASSERT_EQ(m.exclude.size(), 1u);
  const ImportResult r = importLog(makeLog(), "log.csv", m, kDemo, "drive");
  EXPECT_NEAR(r.t0_s, 5.5, 1e-12);  // logger time of the run's first row: 1.0 − 0.5 s in
  EXPECT_NEAR(r.duration_s, 3.0,
              1e-12);                 // 0.5 s of run-in, the 2 s window, 0.5 s past it (the inputs)
  EXPECT_NEAR(r.start_m, 5.0, 1e-9);  // 0.5 s at 10 m/s
  long masked = 0, kept_rows = 0;
  for (int k = 100; k <= 300; ++k) {  // the window's rows: |2 sin(0.05 k)| mm against 1.5 mm
    const double zr = std::stod(std::to_string(2.0 * std::sin(0.05 * k)));
    (std::abs(zr) > 1.5 ? masked : kept_rows) += 1;
  }
  EXPECT_EQ(r.outside_window,
            401 - 201);  // the run-in and run-out rows are simulated, not measured
  ASSERT_EQ(r.masked.size(), 1u);
  EXPECT_EQ(r.masked[0].second, masked);
  EXPECT_EQ(r.masked[0].first, "|zr| > 0.0015 m");
  EXPECT_EQ(static_cast<long>(r.data.records.size()), 2 * kept_rows);
  for (const auto& rec : r.data.records) {
    EXPECT_GE(rec.time_s, 0.5 - 1e-12);
    EXPECT_LE(rec.time_s, 2.5 + 1e-12);
  }
  EXPECT_EQ(r.speed_csv.substr(0, 22), "time_s,speed_mps\n0,10\n");
  writeImport(r, (dir / "out").string());
  const Study s = loadStudy((dir / "out" / "study.toml").string());
  EXPECT_NEAR(s.scenario("drive").speed.start_m, 5.0, 1e-9);
  EXPECT_NEAR(s.scenario("drive").speed.distance(1.0), 15.0, 1e-9);
  const auto side = nlohmann::json::parse(dtwin_test::slurp(dir / "out" / "measurements.json"));
  EXPECT_EQ(side["window"]["rows_outside_window"], 200);
  EXPECT_EQ(side["window"]["masks"][0]["rows_dropped"], masked);
}

// A mask's pad_s drops the rows within that time of a row past its threshold too (a turn's edges):
// the count is the brute-force one, and the sidecar's text says so.
TEST(LogImport, AMaskPadDropsTheRowsAroundWhatItMasks) {
  const fs::path dir = dtwin_test::freshDir("import_pad");
  dtwin_test::writeText(
      dir / "map.toml",
      std::string(kMapping).replace(
          std::string(kMapping).find("\n\n[[import.channels]]"), 0,
          "\nexclude = { column = \"zr\", unit = \"mm\", above = 1.5, pad_s = 0.05 }"));
  const ImportMapping m = readImportMapping((dir / "map.toml").string());
  ASSERT_EQ(m.exclude.size(), 1u);
  EXPECT_EQ(m.exclude[0].pad_s, 0.05);
  const ImportResult r = importLog(makeLog(), "log.csv", m, kDemo, "drive");
  std::vector<bool> past(401);
  for (int k = 0; k <= 400; ++k)
    past[static_cast<std::size_t>(k)] =
        std::abs(std::stod(std::to_string(2.0 * std::sin(0.05 * k)))) > 1.5;
  long masked = 0, past_only = 0;
  for (int k = 0; k <= 400; ++k) {
    bool near = false;
    for (int j = std::max(0, k - 5); j <= std::min(400, k + 5); ++j)
      near = near || past[static_cast<std::size_t>(j)];  // 10 ms rows: ±50 ms
    masked += near;
    past_only += past[static_cast<std::size_t>(k)];
  }
  ASSERT_EQ(r.masked.size(), 1u);
  EXPECT_EQ(r.masked[0].second, masked);
  EXPECT_GT(masked, past_only + 20);  // the pad drops more than the threshold alone
  EXPECT_EQ(r.masked[0].first, "|zr| > 0.0015 m (and 0.05 s around)");
  EXPECT_EQ(static_cast<long>(r.data.records.size()), 2 * (401 - masked));
  dtwin_test::writeText(
      dir / "bad.toml",
      std::string(kMapping).replace(
          std::string(kMapping).find("\n\n[[import.channels]]"), 0,
          "\nexclude = { column = \"zr\", unit = \"mm\", above = 1.5, pad_s = -1 }"));
  try {
    readImportMapping((dir / "bad.toml").string());
    FAIL() << "a negative pad accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pad_s"), std::string::npos) << e.what();
  }
}

// A window outside the log, a mask on a column the log lacks, a mask without a threshold: one line
// naming the mapping's field or the log, and nothing written.
TEST(LogImport, BadWindowsAndMasksAreOneLineErrors) {
  const fs::path dir = dtwin_test::freshDir("import_window_bad");
  auto errorOf = [&](const std::string& extra) {
    dtwin_test::writeText(
        dir / "map.toml",
        std::string(kMapping).replace(std::string(kMapping).find("\n\n[[import.channels]]"), 0,
                                      "\n" + extra));
    try {
      importLog(makeLog(), "log.csv", readImportMapping((dir / "map.toml").string()), kDemo,
                "drive");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string e = errorOf("window_s = [2.0, 9.0]");
  EXPECT_NE(e.find("import.window_s"), std::string::npos) << e;
  EXPECT_NE(e.find("ends after the log"), std::string::npos) << e;
  e = errorOf("window_s = [3.0, 2.0]");
  EXPECT_NE(e.find("0 <= start < end"), std::string::npos) << e;
  e = errorOf("exclude = { column = \"yaw\", unit = \"rad/s\", above = 0.1 }");
  EXPECT_NE(e.find("no column 'yaw'"), std::string::npos) << e;
  e = errorOf("exclude = { column = \"zr\", unit = \"mm\" }");
  EXPECT_NE(e.find("needs above or below"), std::string::npos) << e;
  e = errorOf("exclude = { column = \"zr\", unit = \"furlong\", above = 1 }");
  EXPECT_NE(e.find("unknown unit 'furlong'"), std::string::npos) << e;
  e = errorOf("run_in_s = 3");
  EXPECT_NE(e.find("needs window_s"), std::string::npos) << e;
}

// a window cut from a drive predicts what the whole drive predicts over
// the same stretch, once the run-in has let the start's equilibrium transient die away.
TEST(LogImport, AWindowPredictsWhatTheWholeDrivePredictsThere) {
  const fs::path dir = dtwin_test::freshDir("import_window_same");
  const std::string drive = std::string(DTWIN_SOURCE_DIR) + "/data/drives/";
  const ImportMapping whole_m = readImportMapping(drive + "stop_and_go_map.toml");
  ImportMapping win_m = whole_m;
  win_m.window_s = std::array<double, 2>{30.0, 45.0};
  win_m.window_where = "test";
  const std::string log = dtwin_test::slurp(drive + "stop_and_go.csv");
  const ImportResult whole = importLog(log, "stop_and_go.csv", whole_m, kDemo, "drive");
  const ImportResult win = importLog(log, "stop_and_go.csv", win_m, kDemo, "drive");
  writeImport(whole, (dir / "whole").string());
  writeImport(win, (dir / "win").string());
  // Both runs at a tight integrator accuracy: the comparison is of the inputs and the settling,
  // not of two step sequences' truncation errors (about the accuracy, 1e-4 of the signal).
  auto run = [](const fs::path& study, const std::vector<double>& at) {
    Study s = loadStudy(study.string());
    s.simulation.accuracy = 1e-9;
    const auto model = s.makeModel(s.assemblies().front());
    Simulator sim(model, s.simulation);
    ScenarioSpec sc = s.scenario("drive");
    sc.sample_times_s = at;
    auto r = sim.run(model->defaultRunValues(), *makeRoad(sc, model->vehicle(), s.seed), sc);
    EXPECT_TRUE(r.stats.ok) << r.stats.message;
    return r;
  };
  const double shift = win.t0_s - whole.t0_s;  // the window's run starts this far into the drive
  const RunResult b = run(dir / "win" / "study.toml", {});
  const auto& tb = b.trace.column("time_s");
  std::vector<double> at;  // the window's output times on the whole drive's clock
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < tb.size(); i += 5)
    if (tb[i] + shift >= 30.0 && tb[i] + shift <= 45.0) {
      at.push_back(tb[i] + shift);
      rows.push_back(i);
    }
  const RunResult a = run(dir / "whole" / "study.toml", at);
  // The state (pitch, roll, the struts; the heave channel counts from each run's start): within
  // 1e-6 of its range. The accelerometer, read between integrator steps by the dense output (a
  // cubic Hermite of the velocity), carries that interpolation's error, which differs between two
  // step sequences: about 1e-5 of its range at a 1 ms step, so within 1e-4.
  for (const auto& [channel, tol] :
       std::vector<std::pair<std::string, double>>{{"chassis_pitch_rad", 1e-6},
                                                   {"chassis_roll_rad", 1e-6},
                                                   {"susp_defl_fl_m", 1e-6},
                                                   {"susp_defl_rl_m", 1e-6},
                                                   {"seat_mps2", 1e-4}}) {
    const auto& ya = a.samples.column(channel);
    const auto& yb = b.trace.column(channel);
    ASSERT_EQ(ya.size(), at.size());
    double worst = 0, lo = 1e300, hi = -1e300;
    for (std::size_t k = 0; k < at.size(); ++k) {
      worst = std::max(worst, std::abs(ya[k] - yb[rows[k]]));
      lo = std::min(lo, ya[k]);
      hi = std::max(hi, ya[k]);
    }
    EXPECT_GT(at.size(), 2000u);
    EXPECT_GT(hi - lo, 0.0) << channel;
    EXPECT_LT(worst, tol * (hi - lo))
        << channel << ": worst " << worst << " of a range " << hi - lo;
  }
}

// A second drive of the same car goes into the first drive's study: the mapping's sensors, the
// same as the study's, are kept as they are; a sensor of the same name mounted otherwise is an
// error naming both.
TEST(LogImport, ASecondDriveJoinsTheFirstDrivesStudy) {
  const fs::path dir = dtwin_test::freshDir("import_second");
  dtwin_test::writeText(dir / "map.toml", kMapping);
  const ImportMapping m = readImportMapping((dir / "map.toml").string());
  writeImport(importLog(makeLog(), "a.csv", m, kDemo, "drive_a"), (dir / "a").string());
  const std::string first = (dir / "a" / "study.toml").string();
  writeImport(importLog(makeLog(), "b.csv", m, first, "drive_b"), (dir / "b").string());
  const Study s = loadStudy((dir / "b" / "study.toml").string());
  EXPECT_EQ(s.sensors.size(), 1u);
  EXPECT_NO_THROW((void)s.scenario("drive_a"));
  EXPECT_NO_THROW((void)s.scenario("drive_b"));
  ImportMapping moved = m;
  moved.sensors[0].position_m[0] = 0.7;
  try {
    importLog(makeLog(), "c.csv", moved, first, "drive_c");
    FAIL() << "a sensor mounted otherwise was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sensors.seat"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("otherwise"), std::string::npos) << e.what();
  }
}
