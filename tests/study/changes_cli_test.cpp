// `twin changes` end to end on the twin: one car measured twice (hub forces over a bump from M1,
// independent noise), the second time with dampers at 55 % of their value. Each drive calibrated as
// `twin calibrate` does; the change list names the damper first, significant, its ratio's interval
// holding 0.55, and nothing else significant; the same with one worn damper, named with its
// corner. Bad input exits 2 with one line.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <filesystem>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

fs::path kTmp() { return fs::temp_directory_path() / "dtwin_changes_cli"; }

dtwin_test::TwinRun twin(const std::string& args) { return dtwin_test::runTwin(args, kTmp()); }

/// The demo study with its vehicle file by absolute path and suspension.damping's truth `damping`.
fs::path study(const std::string& name, const std::string& damping) {
  std::string s = dtwin_test::slurp(fs::path(DTWIN_SOURCE_DIR) / "data/studies/demo.toml");
  s = std::regex_replace(s, std::regex(R"(vehicle = "\.\./vehicle/)"),
                         std::string("vehicle = \"") + DTWIN_SOURCE_DIR + "/data/vehicle/");
  const auto at = s.find("truth = 2500.0", s.find("name = \"suspension.damping\""));
  if (at != std::string::npos)
    s.replace(at, std::string("truth = 2500.0").size(), "truth = " + damping);
  const fs::path p = kTmp() / name;
  std::ofstream(p) << s;
  return p;
}

}  // namespace

TEST(ChangesCli, AWornDamperIsNamedFirstAndNothingElseChanged) {
  fs::remove_all(kTmp());
  fs::create_directories(kTmp());
  const fs::path s1 = study("drive1.toml", "2500.0"), s2 = study("drive2.toml", "1375.0");
  ASSERT_NE(dtwin_test::slurp(s2).find("truth = 1375.0"), std::string::npos);
  const std::string d = kTmp().string();
  // The hub forces on the diag_bump scenario, every 5 ms, three repetitions; the sidecar names the
  // scenario, which `twin calibrate --data FILE` takes from it.
  const std::string lab =
      " --scenario diag_bump --times all --rate 200 --repetitions 3 "
      "--channels hub_force_fl_N,hub_force_fr_N,hub_force_rl_N,hub_force_rr_N";
  ASSERT_EQ(twin("generate lab --quiet --study " + s1.string() + lab + " --seed 11 --out " + d +
                 "/lab1.csv")
                .code,
            0);
  ASSERT_EQ(twin("generate lab --quiet --study " + s2.string() + lab + " --seed 12 --out " + d +
                 "/lab2.csv")
                .code,
            0);
  for (const char* k : {"1", "2"}) {
    const auto r = twin("calibrate --quiet --study " + s1.string() + " --assembly M1 --data " + d +
                        "/lab" + k + ".csv --out " + d + "/cal" + k);
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const auto r =
      twin("changes --before " + d + "/cal1/M1 --after " + d + "/cal2/M1 --out " + d + "/changes");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1 of 4 values changed significantly"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(dtwin_test::slurp(kTmp() / "changes/changes.json"));
  ASSERT_EQ(j["changes"].size(), 4u);
  EXPECT_EQ(j["changes"][0]["name"], "suspension.damping") << r.out;
  EXPECT_EQ(j["changes"][0]["significant"], true) << r.out;
  EXPECT_EQ(j["changes"][0]["kind"], "ratio");
  EXPECT_LE(j["changes"][0]["ci95"][0].get<double>(), 0.55) << r.out;
  EXPECT_GE(j["changes"][0]["ci95"][1].get<double>(), 0.55) << r.out;
  for (std::size_t i = 1; i < j["changes"].size(); ++i)
    EXPECT_EQ(j["changes"][i]["significant"], false) << j["changes"][i]["sentence"];
  const std::string page = dtwin_test::slurp(kTmp() / "changes/changes.html");
  EXPECT_NE(page.find("suspension.damping"), std::string::npos);
  EXPECT_NE(page.find("<b>1 of 4</b>"), std::string::npos);
  if (!HasFailure()) fs::remove_all(kTmp());
}

// One worn damper: the second drive's rear-right damper at 55 % of the others'. Both drives
// calibrated with that corner's factor too (`twin calibrate --free`); the change list names the
// factor first, significant, its ratio's interval holding 0.55, and nothing else.
TEST(ChangesCli, OneWornDamperIsNamedFirstWithItsCorner) {
  // Its own folder: the other cases of this file (separate processes under ctest -j) clear kTmp().
  const fs::path dir = fs::temp_directory_path() / "dtwin_changes_corner";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string text = dtwin_test::slurp(fs::path(DTWIN_SOURCE_DIR) / "data/studies/demo.toml");
  text = std::regex_replace(text, std::regex(R"(vehicle = "\.\./vehicle/)"),
                            std::string("vehicle = \"") + DTWIN_SOURCE_DIR + "/data/vehicle/");
  const fs::path s = dir / "corner.toml";
  std::ofstream(s) << text;
  const auto twin = [&](const std::string& args) { return dtwin_test::runTwin(args, dir); };
  const std::string d = dir.string();
  const std::string lab =
      " --scenario diag_bump --times all --rate 200 --repetitions 3 "
      "--channels hub_force_fl_N,hub_force_fr_N,hub_force_rl_N,hub_force_rr_N";
  ASSERT_EQ(twin("generate lab --quiet --study " + s.string() + lab + " --seed 11 --out " + d +
                 "/lab1.csv")
                .code,
            0);
  ASSERT_EQ(twin("generate lab --quiet --study " + s.string() + lab +
                 " --seed 12 --hidden-value suspension.damping@rr=0.55 --out " + d + "/lab2.csv")
                .code,
            0);
  for (const char* k : {"1", "2"}) {
    const auto r = twin("calibrate --quiet --study " + s.string() +
                        " --assembly M1 --free suspension.damping@rr --data " + d + "/lab" + k +
                        ".csv --out " + d + "/cal" + k);
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const auto r =
      twin("changes --before " + d + "/cal1/M1 --after " + d + "/cal2/M1 --out " + d + "/changes");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1 of 5 values changed significantly"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(dtwin_test::slurp(dir / "changes/changes.json"));
  ASSERT_EQ(j["changes"].size(), 5u);
  EXPECT_EQ(j["changes"][0]["name"], "suspension.damping@rr") << r.out;
  EXPECT_EQ(j["changes"][0]["significant"], true) << r.out;
  EXPECT_LE(j["changes"][0]["ci95"][0].get<double>(), 0.55) << r.out;
  EXPECT_GE(j["changes"][0]["ci95"][1].get<double>(), 0.55) << r.out;
  for (std::size_t i = 1; i < j["changes"].size(); ++i)
    EXPECT_EQ(j["changes"][i]["significant"], false) << j["changes"][i]["sentence"];
  // The calibration records the freed value in its setup.
  const auto summary = nlohmann::json::parse(dtwin_test::slurp(dir / "cal1/M1/summary.json"));
  EXPECT_NE(summary.dump().find("suspension.damping@rr"), std::string::npos);
  if (!HasFailure()) fs::remove_all(dir);
}

TEST(ChangesCli, AMissingFolderIsOneLineAndExitCodeTwo) {
  fs::create_directories(kTmp());
  const auto r = twin("changes --before " + (kTmp() / "nosuch").string() + " --after " +
                      (kTmp() / "nosuch2").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nosuch"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  fs::remove_all(kTmp());
}
