// The road-type registry (twin/road_setting.hpp): every registered type reads a minimal table,
// names itself, records itself under its name, makes a road and describes a window; unknown
// types get a "did you mean". A new road type is covered by adding its minimal fields to
// kRequiredFields (when it has required fields).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "common/errors.hpp"
#include "common/toml_reader.hpp"
#include "io/study.hpp"
#include "subsystems/crg.hpp"
#include "test_util.hpp"
#include "twin/road_setting.hpp"
#include "twin/roads/iso8608.hpp"
#include "twin/scenario.hpp"

using namespace dtwin;

namespace {

std::shared_ptr<const RoadSetting> parseText(const std::string& text, const std::string& file) {
  const toml::table root = toml::parse(text);
  TableReader r(root, file, "scenarios.s");
  return parseRoadSetting(r);
}

/// An LRFI OpenCRG file: u 0..length_m by du_m, long sections at v = -1, -0.5, 0, 0.5, 1, heights
/// 5 mm sin(2 pi u / 3 m) + 2 mm/m v.
std::string crgFile(double length_m, double du_m = 0.05) {
  const int rows = static_cast<int>(std::lround(length_m / du_m)) + 1;
  std::string t =
      "$CT\nroad types test\n$\n$ROAD_CRG\nREFERENCE_LINE_START_U = 0\nREFERENCE_LINE_END_U = " +
      std::to_string(du_m * (rows - 1)) + "\nREFERENCE_LINE_INCREMENT = " + std::to_string(du_m) +
      "\n$\n$KD_Definition\n#:LRFI\n";
  const double v[5] = {-1.0, -0.5, 0.0, 0.5, 1.0};
  for (double x : v) t += "D:long section at v = " + std::to_string(x) + ",m\n";
  t += "$\n$$$$\n";
  for (int k = 0; k < rows; ++k) {
    for (double x : v) {
      char b[16];
      std::snprintf(b, sizeof b, "%10.7f",
                    0.005 * std::sin(2 * 3.14159265358979 * du_m * k / 3.0) + 0.002 * x);
      t += b;
    }
    t += "\n";
  }
  return t;
}

VehicleData demoVehicle() {
  static const Study study = loadStudy(std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml");
  return study.makeModel(study.assemblies().front())->vehicle();
}

}  // namespace

TEST(RoadTypes, EveryRegisteredTypeReadsNamesRecordsAndMakesItself) {
  const auto dir = dtwin_test::freshDir("dtwin_road_types");
  // A profile long enough for the scenario below (8 s at 4 m/s, wheelbase about 2.8 m).
  std::string csv = "distance_m,left_m,right_m\n";
  for (int k = -100; k <= 400; ++k) csv += std::to_string(0.1 * k) + ",0.001,0.002\n";
  dtwin_test::writeText(dir / "profile.csv", csv);
  std::string log = "time_s,height_m\n";
  for (int k = 0; k <= 900; ++k) log += std::to_string(0.01 * k) + ",0.001\n";
  dtwin_test::writeText(dir / "log.csv", log);
  dtwin_test::writeText(dir / "road.crg", crgFile(40.0));
  const std::map<std::string, std::string> kRequiredFields = {{"csv", "path = \"profile.csv\"\n"},
                                                              {"csv_time", "path = \"log.csv\"\n"},
                                                              {"crg", "path = \"road.crg\"\n"}};
  ASSERT_GE(roadTypes().size(), 4u);
  for (const auto& type : roadTypes()) {
    SCOPED_TRACE(type.name);
    EXPECT_FALSE(type.description.empty());
    const auto it = kRequiredFields.find(type.name);
    const auto setting = parseText(
        "[road]\ntype = \"" + type.name + "\"\n" + (it == kRequiredFields.end() ? "" : it->second),
        (dir / "s.toml").string());
    ASSERT_NE(setting, nullptr);
    EXPECT_EQ(setting->type(), type.name);
    EXPECT_EQ(setting->toJson().at("type"), type.name);
    ScenarioSpec sc;
    sc.name = "s";
    sc.duration_s = 8.0;
    sc.speed.v_final_mps = 4.0;
    sc.speed.ramp_s = 0.0;
    sc.road = setting;
    ASSERT_LT(setting->featureTime_s(), sc.duration_s);
    const auto road = makeRoad(sc, demoVehicle(), 7);
    ASSERT_NE(road, nullptr);
    EXPECT_TRUE(road->describe().is_object());
    EXPECT_FALSE(setting->describeWindow(sc, demoVehicle(), 0.0, sc.duration_s).empty());
    // Determinism: the same seed gives the same profile.
    const auto again = makeRoad(sc, demoVehicle(), 7);
    EXPECT_EQ(road->sample(Track::Left, 1.234).height_m,
              again->sample(Track::Left, 1.234).height_m);
  }
}

TEST(RoadTypes, UnknownTypesAndFieldsAreNamed) {
  try {
    parseText("[road]\ntype = \"bumb\"\n", "s.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("scenarios.s.road.type: unknown road type 'bumb' (known: flat, bump, "
                        "iso8608, csv, csv_time, crg; did you mean 'bump'?)"),
              std::string::npos)
        << what;
  }
  try {
    parseText("[road]\ntype = \"bump\"\nheigth_m = 0.1\n", "s.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("road.heigth_m: unknown field (did you mean 'height_m'?)"),
              std::string::npos)
        << e.what();
  }
}

TEST(RoadTypes, IsoRoadIsRandomWithASmoothLeadIn) {
  const auto iso = parseText("[road]\ntype = \"iso8608\"\nsmooth_until_s = 2.5\n", "s.toml");
  EXPECT_TRUE(iso->random());
  EXPECT_DOUBLE_EQ(iso->roughStart_s(), 2.5);
  EXPECT_DOUBLE_EQ(iso->featureTime_s(), 2.5);
  EXPECT_LT(parseText("[road]\ntype = \"iso8608\"\n", "s.toml")->roughStart_s(), 0.0);
  const auto bump = parseText("[road]\ntype = \"bump\"\ntime_s = 1.5\n", "s.toml");
  EXPECT_TRUE(bump->obstacle());
  EXPECT_FALSE(bump->random());
  EXPECT_DOUBLE_EQ(bump->featureTime_s(), 1.5);
}

TEST(RoadTypes, EveryRegisteredTypeIsDocumentedInTheStudyFileReference) {
  const std::string doc = dtwin_test::slurp(std::string(DTWIN_SOURCE_DIR) + "/docs/study-file.md");
  ASSERT_FALSE(doc.empty());
  for (const auto& type : roadTypes())
    EXPECT_NE(doc.find("road `type = \"" + type.name + "\""), std::string::npos)
        << "docs/study-file.md has no row for road type '" << type.name << "'";
}

// A road logged against time under the front axle: the front wheels see the logged heights at
// the logged times, and the rear wheels the same profile one wheelbase later; a log that does
// not cover the scenario, or a drift filter on a height log, is refused at the field.
TEST(RoadTypes, ARoadLoggedAgainstTimeReachesTheRearAxleAWheelbaseLater) {
  const auto dir = dtwin_test::freshDir("dtwin_road_time");
  std::string log = "time_s,left_mm,right_mm\n";
  auto height = [](double t, double phase) {
    return 8.0 * std::sin(2 * 3.14159265358979 * 1.3 * t + phase);
  };
  for (int k = 0; k <= 810; ++k)
    log += std::to_string(0.01 * k) + "," + std::to_string(height(0.01 * k, 0.0)) + "," +
           std::to_string(height(0.01 * k, 1.0)) + "\n";
  dtwin_test::writeText(dir / "log.csv", log);
  const auto setting =
      parseText("[road]\ntype = \"csv_time\"\npath = \"log.csv\"\n", (dir / "s.toml").string());
  ScenarioSpec sc;
  sc.name = "s";
  sc.duration_s = 8.0;
  sc.speed.v_final_mps = 4.0;
  sc.speed.ramp_s = 0.0;
  sc.road = setting;
  setting->check(sc, "s.toml: scenarios.s.road");
  const VehicleData v = demoVehicle();
  const auto road = makeRoad(sc, v, 1);
  const double wb = v.wheelbase();
  for (double t = 0.2; t < 7.9; t += 0.173) {
    EXPECT_NEAR(road->sample(Track::Left, 4.0 * t).height_m, 1e-3 * height(t, 0.0), 2e-5) << t;
    EXPECT_NEAR(road->sample(Track::Right, 4.0 * t).height_m, 1e-3 * height(t, 1.0), 2e-5) << t;
    // The rear axle, at distance 4 t - wb, is where the front axle was at t - wb / 4.
    if (t > wb / 4.0 + 0.05) {
      EXPECT_NEAR(road->sample(Track::Left, 4.0 * t - wb).height_m,
                  1e-3 * height(t - wb / 4.0, 0.0), 2e-5)
          << t;
    }
  }
  ScenarioSpec longer = sc;
  longer.duration_s = 9.0;
  try {
    setting->check(longer, "s.toml:3: scenarios.s.road");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("covers 0 .. 8.1 s, but the scenario runs 0 .. 9 s"),
              std::string::npos)
        << e.what();
  }
  try {
    parseText("[road]\ntype = \"csv_time\"\npath = \"log.csv\"\nhighpass_hz = 0.2\n",
              (dir / "s.toml").string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "road.highpass_hz: applies to a road-velocity or acceleration log only"),
              std::string::npos)
        << e.what();
  }
}

// An OpenCRG road: the tracks at +/- half the track width unless given, the front axle at
// u_start_m at time 0 (the rear one a wheelbase behind, on the held first cross section), the
// heights the surface's; a run past the file's end, tracks off the file and bad files refused.
TEST(RoadTypes, ACrgRoadPutsTheTracksAtTheirOffsetsAlongU) {
  const auto dir = dtwin_test::freshDir("dtwin_road_crg");
  dtwin_test::writeText(dir / "road.crg", crgFile(40.0));
  const std::string study = (dir / "s.toml").string();
  const CrgSurface surface = readCrg((dir / "road.crg").string());
  ScenarioSpec sc;
  sc.name = "s";
  sc.duration_s = 5.0;
  sc.speed.v_final_mps = 4.0;
  sc.speed.ramp_s = 0.0;
  const VehicleData v = demoVehicle();
  sc.road = parseText("[road]\ntype = \"crg\"\npath = \"road.crg\"\n", study);
  auto road = makeRoad(sc, v, 1);
  EXPECT_EQ(road->describe().at("left_v_m").get<double>(), 0.5 * v.track);
  EXPECT_EQ(road->describe().at("right_v_m").get<double>(), -0.5 * v.track);
  for (double x = 0.0; x < 20.0; x += 0.377) {
    EXPECT_NEAR(road->sample(Track::Left, x).height_m, surface.height(x, 0.5 * v.track), 2e-4);
    EXPECT_NEAR(road->sample(Track::Right, x).height_m, surface.height(x, -0.5 * v.track), 2e-4);
  }
  EXPECT_DOUBLE_EQ(road->sample(Track::Left, -v.wheelbase()).height_m,
                   surface.height(0.0, 0.5 * v.track));
  // Given offsets and start: x = 0 is u = 12.
  sc.road = parseText(
      "[road]\ntype = \"crg\"\npath = \"road.crg\"\nleft_v_m = 0.6\nright_v_m = -0.9\n"
      "u_start_m = 12.0\n",
      study);
  road = makeRoad(sc, v, 1);
  EXPECT_NEAR(road->sample(Track::Left, 3.1).height_m, surface.height(15.1, 0.6), 2e-4);
  EXPECT_NEAR(road->sample(Track::Right, 3.1).height_m, surface.height(15.1, -0.9), 2e-4);
  EXPECT_EQ(sc.road->toJson().at("u_start_m").get<double>(), 12.0);
  EXPECT_NE(sc.road->describeWindow(sc, v, 1.0, 2.0).front().find("u = 16 .. 20 m"),
            std::string::npos)
      << sc.road->describeWindow(sc, v, 1.0, 2.0).front();
  // 5 s at 4 m/s from u = 30 ends at u = 50, past the file's 40 m.
  auto refused = [&](const std::string& table, const std::string& what) {
    try {
      sc.road = parseText(table, study);
      makeRoad(sc, v, 1);
      ADD_FAILURE() << "no error for " << table;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused("[road]\ntype = \"crg\"\npath = \"road.crg\"\nu_start_m = 30.0\n",
          "the front axle drives from u = 30 to 50 in scenario 's', past the file's last cross "
          "section at u = 40");
  refused("[road]\ntype = \"crg\"\npath = \"road.crg\"\nleft_v_m = 1.5\n",
          "road.left_v_m: v = 1.5 lies outside the long sections of");
  refused("[road]\ntype = \"crg\"\npath = \"road.crg\"\nleft_v_m = -0.5\nright_v_m = 0.5\n",
          "road.left_v_m: must be greater than right_v_m");
  refused("[road]\ntype = \"crg\"\n", "road.path: is required for a crg road");
  refused("[road]\ntype = \"crg\"\npath = \"none.crg\"\n",
          "none.crg: cannot be read (an OpenCRG road file)");
}

// `twin simulate` over a CRG road: hub forces, all finite; `twin list` names the type.
TEST(RoadTypes, ACrgRoadRunsEndToEnd) {
  const auto dir = dtwin_test::freshDir("dtwin_road_crg_e2e");
  dtwin_test::writeText(dir / "sample.crg", crgFile(60.0));
  const auto study = dtwin_test::writeDemoStudy(
      dir / "crg.toml",
      "lab_repetitions = 3\n\n[scenarios.crg]\nduration_s = 3.0\n"
      "speed = { v_final_mps = 8.0, ramp_s = 0.0 }\n"
      "road = { type = \"crg\", path = \"sample.crg\", left_v_m = 0.775, right_v_m = -0.775, "
      "u_start_m = 5.0 }\n");
  const std::string out = (dir / "run.csv").string();
  const auto r = dtwin_test::runTwin(
      "simulate --study " + study.string() + " --assembly M1 --scenario crg --out " + out, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = dtwin_test::slurp(out);
  const std::string header = csv.substr(0, csv.find('\n'));
  ASSERT_NE(header.find("hub_force_fl_N"), std::string::npos) << header;
  const auto column = static_cast<std::size_t>(
      std::count(header.begin(), header.begin() + header.find("hub_force_fl_N"), ','));
  std::size_t rows = 0, at = csv.find('\n') + 1;
  double spread = 0.0, first = std::nan("");
  while (at < csv.size()) {
    const std::size_t end = csv.find('\n', at);
    const std::string line = csv.substr(at, end - at);
    at = end + 1;
    ++rows;
    std::size_t p = 0;
    for (std::size_t c = 0; p != std::string::npos; ++c) {
      const std::size_t q = line.find(',', p);
      const double x = std::stod(line.substr(p, q == std::string::npos ? q : q - p));
      EXPECT_TRUE(std::isfinite(x)) << line;
      if (c == column) {
        if (std::isnan(first)) first = x;
        spread = std::max(spread, std::abs(x - first));
      }
      p = q == std::string::npos ? q : q + 1;
    }
  }
  EXPECT_GT(rows, 100u);
  EXPECT_GT(spread, 10.0);  // the ripple moves the hub
  const auto sidecar = nlohmann::json::parse(dtwin_test::slurp(dir / "run.json"));
  EXPECT_EQ(sidecar.dump().find("\"crg\"") != std::string::npos, true);
  const auto list = dtwin_test::runTwin("list", dir);
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_NE(list.out.find("crg"), std::string::npos) << list.out;
}
