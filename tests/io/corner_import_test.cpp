// `twin import` of each wheel's own motion: four wheel accelerometers (in g, gravity removed by
// their offset) become a four-corner road.csv and a study whose drive runs; the mapping's bad
// combinations are one-line errors naming the mapping file and the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
