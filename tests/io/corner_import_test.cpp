// `twin import` of each wheel's own motion: four wheel accelerometers (in g, gravity removed by
// their offset) become a four-corner road.csv and a study whose drive runs; the mapping's bad
// combinations are one-line errors naming the mapping file and the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "common/errors.hpp"
#include "io/log_import.hpp"
#include "io/study.hpp"
#include "subsystems/time_road.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;
namespace fs = std::filesystem;

namespace {

const std::string kDemo = std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml";

const char* kHead = R"([import]
time = { column = "t", unit = "s" }
speed = { column = "v", unit = "m/s" }
)";

std::string wheel(const char* key, const char* column) {
  return std::string(key) + " = { column = \"" + column + "\", unit = \"g\", offset = 1.0 }\n";
}

const char* kChannel = R"(
[[import.channels]]
column = "az"
channel = "seat_mps2"
unit = "m/s^2"

[sensors.seat]
position_m = [0.5, 0.3, 0.1]
quantity = "acceleration_z"
noise_sd = 0.05
)";

std::string fourWheels() {
  return wheel("road_fl", "a_fl") + wheel("road_fr", "a_fr") + wheel("road_rl", "a_rl") +
         wheel("road_rr", "a_rr");
}

/// 6 s at 100 Hz, 8 m/s; each wheel's accelerometer reads 1 g plus its own sine.
std::string makeLog() {
  std::string log = "t,v,a_fl,a_fr,a_rl,a_rr,az\n";
  for (int k = 0; k <= 600; ++k) {
    const double t = 0.01 * k;
    log += std::to_string(t) + ",8";
    for (int c = 0; c < 4; ++c)
      log += "," + std::to_string(1.0 + 0.05 * std::sin(6.283185307179586 * (2.0 + c) * t));
    log += ",0\n";
  }
  return log;
}

std::string errorOf(const fs::path& dir, const std::string& mapping) {
  dtwin_test::writeText(dir / "bad.toml", mapping);
  try {
    const ImportMapping m = readImportMapping((dir / "bad.toml").string());
    importLog(makeLog(), "log.csv", m, kDemo, "drive");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CornerImport, FourWheelAccelerometersMakeAFourCornerRoadThatRuns) {
  const fs::path dir = dtwin_test::freshDir("corner_import");
  dtwin_test::writeText(dir / "map.toml", kHead + fourWheels() + kChannel);
  const ImportMapping m = readImportMapping((dir / "map.toml").string());
  const ImportResult r = importLog(makeLog(), "log.csv", m, kDemo, "drive");
  ASSERT_EQ(r.road_csv.substr(0, r.road_csv.find('\n')), "time_s,fl_mps2,fr_mps2,rl_mps2,rr_mps2");
  EXPECT_EQ(r.sidecar["mapping"]["road"]["tracks"], "four corners");
  EXPECT_EQ(r.sidecar["mapping"]["road"]["form"], "acceleration");
  EXPECT_EQ(r.sidecar["mapping"]["road"]["columns"][2]["offset"], 1.0);
  writeImport(r, (dir / "out").string());
  // road.csv: four columns, in m/s² with gravity removed (the offset), × 9.80665.
  const TimeRoadLog log = readTimeRoadCsv((dir / "out" / "road.csv").string());
  ASSERT_TRUE(log.four_corners);
  EXPECT_EQ(log.form, TimeRoadLog::Form::Acceleration);
  ASSERT_EQ(log.t_s.size(), 601u);
  const double t = log.t_s[37];
  EXPECT_NEAR(log.rear_left[37], 9.80665 * 0.05 * std::sin(6.283185307179586 * 4.0 * t), 1e-5);
  // The study reads back and its drive runs on the four-corner road.
  const Study s = loadStudy((dir / "out" / "study.toml").string());
  const ScenarioSpec& sc = s.scenario("drive");
  EXPECT_EQ(sc.road->toJson()["tracks"], "four corners");
  const auto model = s.makeModel(s.assemblies().front(), {});
  const auto road = makeRoad(sc, model->vehicle(), 0);
  Simulator sim(model, s.simulation);
  const RunResult run = sim.run(model->defaultRunValues(), *road, sc);
  ASSERT_TRUE(run.stats.ok) << run.stats.message;
  // Each wheel moved by its own sine: the hub forces differ between the corners.
  const auto &fl = run.trace.column("hub_force_fl_N"), &rr = run.trace.column("hub_force_rr_N");
  double differ = 0;
  for (std::size_t i = 0; i < fl.size(); ++i) differ = std::max(differ, std::abs(fl[i] - rr[i]));
  EXPECT_GT(differ, 10.0);
}

TEST(CornerImport, BadWheelCombinationsAreOneLineErrors) {
  const fs::path dir = dtwin_test::freshDir("corner_import_bad");
  const std::string three =
      wheel("road_fl", "a_fl") + wheel("road_fr", "a_fr") + wheel("road_rl", "a_rl");
  std::string e = errorOf(dir, kHead + three + kChannel);
  EXPECT_NE(e.find("bad.toml:1: import.road_rr: is required with the other wheels' columns"),
            std::string::npos)
      << e;
  e = errorOf(dir, kHead + std::string("road = { column = \"a_fl\", unit = \"mm\" }\n") +
                       fourWheels() + kChannel);
  EXPECT_NE(e.find("import.road_fl: give either road"), std::string::npos) << e;
  EXPECT_NE(e.find("bad.toml:"), std::string::npos) << e;
  // Mixed kinds: a height among accelerations.
  std::string mixed = fourWheels();
  mixed.replace(mixed.find("unit = \"g\", offset = 1.0 }\nroad_rr"), 26, "unit = \"mm\" }");
  e = errorOf(dir, kHead + mixed + kChannel);
  EXPECT_NE(e.find("import.road_rl"), std::string::npos) << e;
  EXPECT_NE(e.find("must all be heights"), std::string::npos) << e;
  // Gravity left in: the offset forgotten.
  std::string no_offset = fourWheels();
  no_offset.replace(no_offset.find(", offset = 1.0"), 14, "");
  e = errorOf(dir, kHead + no_offset + kChannel);
  EXPECT_NE(e.find("import.road_fl"), std::string::npos) << e;
  EXPECT_NE(e.find("reads gravity too"), std::string::npos) << e;
}

// The same mapping given as flags (--road-fl COLUMN:UNIT:OFFSET, ...): the same road.csv, byte for
// byte, as the mapping file's; three of the four, or the four beside --road, are one line naming
// the flag, exit 2, nothing written.
TEST(CornerImport, TheFourWheelsAsFlagsAreTheMappingFilesRoad) {
  const fs::path dir = dtwin_test::freshDir("corner_import_flags");
  dtwin_test::writeText(dir / "log.csv", makeLog());
  const std::string channel = R"(
[[import.channels]]
column = "az"
channel = "chassis_heave_acc_mps2"
unit = "m/s^2"
)";
  dtwin_test::writeText(dir / "map.toml", kHead + fourWheels() + channel);
  const std::string log = " --log " + (dir / "log.csv").string() + " --quiet --out ";
  const auto file = dtwin_test::runTwin(
      "import" + log + (dir / "a").string() + " --map " + (dir / "map.toml").string(), dir);
  ASSERT_EQ(file.code, 0) << file.err;
  const std::string base = "import" + log +
                           "%OUT% --time t:s --speed v:m/s --channel "
                           "az:chassis_heave_acc_mps2:m/s^2";
  auto with = [&](const std::string& out, const std::string& extra) {
    std::string args = base;
    args.replace(args.find("%OUT%"), 5, (dir / out).string());
    return dtwin_test::runTwin(args + extra, dir);
  };
  const std::string wheels =
      " --road-fl a_fl:g:1 --road-fr a_fr:g:1 --road-rl a_rl:g:1 --road-rr a_rr:g:1";
  const auto flags = with("b", wheels);
  ASSERT_EQ(flags.code, 0) << flags.err;
  const std::string a = dtwin_test::slurp(dir / "a" / "road.csv"),
                    b = dtwin_test::slurp(dir / "b" / "road.csv");
  EXPECT_EQ(a.substr(0, a.find('\n')), "time_s,fl_mps2,fr_mps2,rl_mps2,rr_mps2");
  EXPECT_EQ(a, b);
  const auto three = with("c", " --road-fl a_fl:g:1 --road-fr a_fr:g:1 --road-rl a_rl:g:1");
  EXPECT_EQ(three.code, 2);
  EXPECT_NE(three.err.find("twin: error: --road-rr: is required with the other wheels' columns"),
            std::string::npos)
      << three.err;
  const auto both = with("d", " --road a_fl:mm" + wheels);
  EXPECT_EQ(both.code, 2);
  EXPECT_NE(both.err.find("--road-fl: give either --road"), std::string::npos) << both.err;
  const auto gravity = with("e",
                            " --road-fl a_fl:g --road-fr a_fr:g:1 --road-rl a_rl:g:1 "
                            "--road-rr a_rr:g:1");
  EXPECT_EQ(gravity.code, 2);
  EXPECT_NE(gravity.err.find("--road-fl: column 'a_fl' reads"), std::string::npos) << gravity.err;
  for (const char* out : {"c", "d", "e"}) EXPECT_FALSE(fs::exists(dir / out)) << out;
}

// A time column of dated clock times: the sidecar records the run's first row as a UTC date and
// time (source.start_utc), which `twin changes` orders a car's drives by; a window moves it to the
// run's start; plain seconds record none.
TEST(CornerImport, ADatedClockRecordsTheDrivesStart) {
  std::string log = "t,v,a_fl,a_fr,a_rl,a_rr,az\n";
  for (int k = 0; k <= 600; ++k) {
    // From 07:33:00.00 UTC at 100 Hz, written as local time with its UTC offset.
    char t[64];
    std::snprintf(t, sizeof t, "2026-03-09T09:%02d:%02d.%02d+02:00", 33 + k / 6000, k / 100 % 60,
                  k % 100);
    log += std::string(t) + ",8,1,1,1,1,0\n";
  }
  const fs::path dir = dtwin_test::freshDir("corner_import_date");
  dtwin_test::writeText(
      dir / "map.toml",
      std::string("[import]\ntime = { column = \"t\", unit = \"clock\" }\nspeed = "
                  "{ column = \"v\", unit = \"m/s\" }\n") +
          fourWheels() + kChannel);
  ImportMapping m = readImportMapping((dir / "map.toml").string());
  EXPECT_EQ(importLog(log, "log.csv", m, kDemo, "drive").sidecar["source"]["start_utc"],
            "2026-03-09T07:33:00.000Z");
  m.window_s = std::array<double, 2>{3.0, 5.0};
  m.run_in_s = 1.0;
  EXPECT_EQ(importLog(log, "log.csv", m, kDemo, "drive").sidecar["source"]["start_utc"],
            "2026-03-09T07:33:02.000Z");
  dtwin_test::writeText(dir / "plain.toml", kHead + fourWheels() + kChannel);
  const ImportResult plain = importLog(
      makeLog(), "log.csv", readImportMapping((dir / "plain.toml").string()), kDemo, "drive");
  EXPECT_TRUE(plain.sidecar["source"]["start_utc"].is_null());
}
