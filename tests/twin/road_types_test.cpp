// The road-type registry (twin/road_setting.hpp): every registered type reads a minimal table,
// names itself, records itself under its name, makes a road and describes a window; unknown
// types get a "did you mean". A new road type is covered by adding its minimal fields to
// kRequiredFields (when it has required fields).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "common/toml_reader.hpp"
#include "io/study.hpp"
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
  const std::map<std::string, std::string> kRequiredFields = {{"csv", "path = \"profile.csv\"\n"},
                                                              {"csv_time", "path = \"log.csv\"\n"}};
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
                        "iso8608, csv, csv_time; did you mean 'bump'?)"),
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
