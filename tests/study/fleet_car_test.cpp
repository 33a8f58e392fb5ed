// A fleet car's faults from its accelerometers, end to end through the program (label `fleet`;
// each case within a few minutes on 2 cores): data/drives/fleet_car_*.csv, made by
// scripts/make_fleet_car_drives.py with the twin itself (a sedan on PAC2002 tires over random roads
// nobody profiled; an accelerometer on each wheel carrier and three on the body, each through a
// logger's anti-alias filter, with noise and a jittered clock), imported with
// data/drives/fleet_car_map.toml into data/drives/fleet_car_study.toml (the four wheels given, the
// hub input), then `twin diagnose` with the study's sizes. Each hidden fault is named with its
// place and its printed 95 % interval holds the truth; four corners alike give "none"; the six
// drives of a wearing damper, calibrated with its corner's factor, show its decline in
// `twin changes`.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

const std::string kSrc = DTWIN_SOURCE_DIR;

/// Imports drive `name` into DIR/drive (the study with the drive as scenario `drive`).
fs::path importDrive(const fs::path& dir, const std::string& name) {
  fs::create_directories(dir);
  const auto r = dtwin_test::runTwin(
      "import --log " + kSrc + "/data/drives/fleet_car_" + name + ".csv --map " + kSrc +
          "/data/drives/fleet_car_map.toml --study " + kSrc +
          "/data/drives/fleet_car_study.toml --quiet --out " + (dir / "drive").string(),
      dir);
  EXPECT_EQ(r.code, 0) << r.err;
  return dir / "drive";
}

nlohmann::json diagnoseDrive(const std::string& name) {
  const fs::path dir = dtwin_test::freshDir("fleet_" + name);
  const fs::path drive = importDrive(dir, name);
  const auto r = dtwin_test::runTwin("diagnose --study " + (drive / "study.toml").string() +
                                         " --data " + (drive / "measurements.csv").string() +
                                         " --out " + (dir / "diag").string(),
                                     dir);
  EXPECT_EQ(r.code, 0) << r.err;
  std::printf("%s", r.out.c_str());
  return nlohmann::json::parse(dtwin_test::slurp(dir / "diag" / "diagnosis.json"));
}

/// The first cause is `factor` (or the effect `cause` with parameter `factor`); the printed 95 %
/// interval of `factor` holds `truth`; the summary says `words`.
void expectNamed(const nlohmann::json& d, const std::string& cause, const std::string& factor,
                 double truth, const std::string& words) {
  ASSERT_EQ(d["verdict"], "effect") << d["summary"];
  ASSERT_FALSE(d["causes"].empty()) << d["summary"];
  const auto& k = d["causes"][0];
  EXPECT_EQ(k["name"], cause) << d["summary"];
  ASSERT_TRUE(k["parameters"].contains(factor)) << d["summary"];
  const auto& p = k["parameters"][factor];
  const double mean = p["mean"], lo = p["ci95"][0], hi = p["ci95"][1];
  std::printf("%s: %.4f, 95 %% [%.4f, %.4f], truth %.4f (%s)\n", factor.c_str(), mean, lo, hi,
              truth, lo <= truth && truth <= hi ? "inside" : "outside");
  EXPECT_LE(lo, truth) << d["summary"];
  EXPECT_GE(hi, truth) << d["summary"];
  EXPECT_NE(d["summary"].get<std::string>().find(words), std::string::npos) << d["summary"];
}

}  // namespace

TEST(FleetCar, AWornDamperIsNamedWithItsCorner) {
  expectNamed(diagnoseDrive("damper_rr"), "free:suspension.damping@rr", "suspension.damping@rr",
              0.55, "the rear-right damper");
}

TEST(FleetCar, ASoftSpringIsNamedWithItsCorner) {
  expectNamed(diagnoseDrive("spring_fl"), "free:suspension.stiffness@fl", "suspension.stiffness@fl",
              0.7, "the front-left spring");
}

TEST(FleetCar, AStickyStrutIsNamedWithItsCorner) {
  expectNamed(diagnoseDrive("friction_rl"), "strut_friction@rl", "strut_friction@rl.force_N", 150,
              "strut friction at the rear-left corner");
}

// Both rear dampers at 60 %: with the whole damping calibrated only the ratio between the axles is
// known, the front factor at 1/0.6, said of the rear axle.
TEST(FleetCar, WornDampersOnOneAxleAreNamedAsARatioBetweenTheAxles) {
  expectNamed(diagnoseDrive("damper_rear"), "free:suspension.damping@front",
              "suspension.damping@front", 1 / 0.6, "the rear dampers");
}

TEST(FleetCar, FourCornersAlikeGiveNone) {
  const auto d = diagnoseDrive("null");
  EXPECT_EQ(d["verdict"], "none") << d["summary"];
  EXPECT_TRUE(d["causes"].empty()) << d["summary"];
}

// Six drives over a year, the front-left damper wearing from 100 % to 50 %: each drive calibrated
// with that corner's factor, `twin changes` over the six (their dates from the logs' clock, through
// the import's sidecar) names the factor's decline first, every drive's interval holds its truth,
// and the trend's interval holds the true yearly ratio.
TEST(FleetCar, AWearingDamperDeclinesAcrossSixDrives) {
  const fs::path dir = dtwin_test::freshDir("fleet_wear");
  const double truth[6] = {1.0, 0.9, 0.8, 0.7, 0.6, 0.5};
  std::string calibrations;
  for (int k = 5; k >= 0; --k) {  // in reverse: `twin changes` orders them by date
    const std::string name = "wear_" + std::to_string(k + 1);
    const fs::path drive = importDrive(dir / name, name);
    const auto r = dtwin_test::runTwin(
        "calibrate --study " + (drive / "study.toml").string() + " --assembly M1 --data " +
            (drive / "measurements.csv").string() + " --free suspension.damping@fl --quiet --out " +
            (dir / name / "cal").string(),
        dir);
    ASSERT_EQ(r.code, 0) << r.err;
    calibrations += (calibrations.empty() ? "" : ",") + (dir / name / "cal" / "M1").string();
  }
  const auto r = dtwin_test::runTwin(
      "changes --calibrations " + calibrations + " --out " + (dir / "changes").string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  std::printf("%s", r.out.c_str());
  const auto j = nlohmann::json::parse(dtwin_test::slurp(dir / "changes" / "changes.json"));
  ASSERT_EQ(j["drives"].size(), 6u);
  EXPECT_EQ(j["drives"][0]["date"].get<std::string>().substr(0, 10), "2026-01-12");
  const auto& v = j["values"][0];
  EXPECT_EQ(v["name"], "suspension.damping@fl") << r.out;
  EXPECT_TRUE(v["significant"].get<bool>()) << r.out;
  int inside = 0;
  for (int k = 0; k < 6; ++k) {
    const auto& d = v["drives"][static_cast<std::size_t>(k)];
    const double lo = d["ci95"][0], hi = d["ci95"][1];
    inside += lo <= truth[k] && truth[k] <= hi ? 1 : 0;
    std::printf("drive %d: %.4f [%.4f, %.4f], truth %.2f\n", k + 1, d["estimate"].get<double>(), lo,
                hi, truth[k]);
  }
  // A 95 % interval misses in one case of twenty: at most one of six may miss.
  EXPECT_GE(inside, 5) << r.out;
  EXPECT_LT(v["trend"].get<double>(), 1.0) << r.out;
  EXPECT_TRUE(fs::exists(dir / "changes" / "changes.html"));
}
