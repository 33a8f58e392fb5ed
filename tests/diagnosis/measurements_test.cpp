// Measurement files for the diagnosis: parsing FILE[@SCENARIO], validation (unknown scenario or
// channel, time base, NaN), and the pure-error noise estimate against its closed form.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "diagnosis/measurements.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::diag;

namespace {
const std::string kDemo = std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml";

fs::path writeFile(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p;
}

std::string errorOf(const Study& s, const std::string& arg) {
  try {
    loadMeasurement(s, parseMeasurementArg(arg, "--data"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Measurements, ParsesFileAndScenario) {
  auto a = parseMeasurementArg("data/x@y.csv@diag_bump", "--data");
  EXPECT_EQ(a.path, "data/x@y.csv");
  EXPECT_EQ(a.scenario, "diag_bump");
  a = parseMeasurementArg("x.csv", "--data");
  EXPECT_EQ(a.path, "x.csv");
  EXPECT_EQ(a.scenario, "");
  EXPECT_THROW(parseMeasurementArg("x.csv@", "--data"), InputError);
  EXPECT_THROW(parseMeasurementArg("@lab", "--data"), InputError);
}

TEST(Measurements, LoadsAValidFileTiedToItsScenario) {
  const Study s = loadStudy(kDemo);
  const auto p = writeFile(
      "ok.csv",
      "repetition,time_s,channel,value\n1,1.0,hub_force_fl_N,3700\n1,1.005,hub_force_fl_N,3710\n");
  const auto ds = loadMeasurement(s, parseMeasurementArg(p.string() + "@diag_bump", "--data"));
  EXPECT_EQ(ds.scenario, "diag_bump");
  EXPECT_EQ(ds.data.records.size(), 2u);
}

TEST(Measurements, BadInputsGiveOneLineErrorsNamingTheProblem) {
  const Study s = loadStudy(kDemo);
  const auto ok =
      writeFile("m.csv", "repetition,time_s,channel,value\n1,1.0,hub_force_fl_N,3700\n");
  // Unknown scenario: names it and lists the known ones.
  std::string e = errorOf(s, ok.string() + "@nowhere");
  EXPECT_NE(e.find("nowhere"), std::string::npos) << e;
  // No scenario and no sidecar.
  e = errorOf(s, ok.string());
  EXPECT_NE(e.find("no scenario"), std::string::npos) << e;
  // Unknown channel (with the closest known name).
  const auto ch =
      writeFile("ch.csv", "repetition,time_s,channel,value\n1,1.0,hub_force_fx_N,3700\n");
  e = errorOf(s, ch.string() + "@diag_bump");
  EXPECT_NE(e.find("hub_force_fx_N"), std::string::npos) << e;
  EXPECT_NE(e.find("ch.csv:2"), std::string::npos) << e;
  // Wrong unit suffix.
  const auto unit =
      writeFile("unit.csv", "repetition,time_s,channel,value\n1,1.0,hub_force_fl_kN,3.7\n");
  e = errorOf(s, unit.string() + "@diag_bump");
  EXPECT_NE(e.find("wrong unit suffix"), std::string::npos) << e;
  // NaN value.
  const auto nan =
      writeFile("nan.csv", "repetition,time_s,channel,value\n1,1.0,hub_force_fl_N,nan\n");
  e = errorOf(s, nan.string() + "@diag_bump");
  EXPECT_NE(e.find("nan.csv:2"), std::string::npos) << e;
  // A time off the 1 kHz output grid is accepted (compared with the output interpolated there).
  const auto grid =
      writeFile("grid.csv", "repetition,time_s,channel,value\n1,1.0003,hub_force_fl_N,3700\n");
  EXPECT_NO_THROW(loadMeasurement(s, parseMeasurementArg(grid.string() + "@diag_bump", "--data")));
  // A time after the end of the scenario (diag_bump lasts 3 s).
  const auto late =
      writeFile("late.csv", "repetition,time_s,channel,value\n1,3.5,hub_force_fl_N,3700\n");
  e = errorOf(s, late.string() + "@diag_bump");
  EXPECT_NE(e.find("after the end"), std::string::npos) << e;
  // A missing file.
  e = errorOf(s, "/nonexistent/file.csv@diag_bump");
  EXPECT_NE(e.find("no such file"), std::string::npos) << e;
}

TEST(Measurements, ScenarioComesFromTheSidecarWhenNotGiven) {
  const Study s = loadStudy(kDemo);
  const auto p =
      writeFile("side.csv", "repetition,time_s,channel,value\n1,1.0,hub_force_fl_N,3700\n");
  writeFile("side.json", R"({"scenario": {"name": "diag_rough"}})");
  EXPECT_EQ(loadMeasurement(s, parseMeasurementArg(p.string(), "--data")).scenario, "diag_rough");
}

// Pure error: Σ_t Σ_r (y_tr − ȳ_t)² / Σ_t (R_t − 1), here by hand.
TEST(Measurements, NoiseFromRepetitionsIsThePooledPureError) {
  const Study s = loadStudy(kDemo);
  LabData d;
  // t = 1.0: 1, 2, 3 (mean 2, SS 2); t = 1.001: 10, 14 (mean 12, SS 8). dof = 2 + 1 = 3.
  d.records = {{1, 1.0, "hub_force_fl_N", 1},   {1, 1.001, "hub_force_fl_N", 10},
               {2, 1.0, "hub_force_fl_N", 2},   {2, 1.001, "hub_force_fl_N", 14},
               {3, 1.0, "hub_force_fl_N", 3},   {1, 1.0, "susp_defl_fl_m", 0.01},
               {2, 1.0, "susp_defl_fl_m", 0.01}};
  const auto n = estimateNoise(s, d, "hub_force_fl_N");
  EXPECT_DOUBLE_EQ(n.variance, 10.0 / 3.0);
  EXPECT_EQ(n.dof, 3);
  EXPECT_EQ(n.source, "repetitions");
  std::vector<std::string> left;
  const auto all = estimateChannelNoise(s, {calib::DataSet{"d", "diag_bump", d}}, &left);
  EXPECT_EQ(all.count("hub_force_fl_N"), 1u);
  // The deflection's repetitions agree exactly: no noise to weigh it by, so it is left out.
  EXPECT_EQ(all.count("susp_defl_fl_m"), 0u);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_NE(left[0].find("susp_defl_fl_m"), std::string::npos);
  // One repetition of a force channel: the study's [noise] variance.
  LabData one;
  one.records = {{1, 1.0, "hub_force_fr_N", 5}};
  const auto n1 = estimateNoise(s, one, "hub_force_fr_N");
  EXPECT_DOUBLE_EQ(n1.variance, s.noise_variance_N2);
  EXPECT_EQ(n1.source, "study [noise]");
}

// A sensor channel with one repetition is weighed by its sensor's noise_sd; repetitions, when
// there are some, still win; a sensor without noise_sd is left out with the reason; a file may
// name the sensor's channel.
TEST(Measurements, SensorNoiseWeighsASingleRepetition) {
  const fs::path dir = dtwin_test::freshDir("meas_sensor_noise");
  const Study s =
      loadStudy(dtwin_test::writeDemoStudy(
                    dir / "study.toml",
                    "lab_repetitions = 2\n[sensors.seat]\nquantity = \"acceleration_z\"\n"
                    "noise_sd = 0.05\n[sensors.bare]\nquantity = \"acceleration_z\"\n")
                    .string());
  LabData one;
  for (int k = 0; k < 10; ++k) {
    one.records.push_back({1, 0.1 * k, "seat_mps2", 0.01 * k});
    one.records.push_back({1, 0.1 * k, "bare_mps2", 0.01 * k});
  }
  const ChannelNoise n = estimateNoise(s, one, "seat_mps2");
  EXPECT_EQ(n.source, "sensor noise_sd");
  EXPECT_DOUBLE_EQ(n.variance, 0.0025);
  std::vector<std::string> left_out;
  const auto all = estimateChannelNoise(s, {{"one.csv", "diag_rough", one}}, &left_out);
  EXPECT_EQ(all.count("seat_mps2"), 1u);
  EXPECT_EQ(all.count("bare_mps2"), 0u);
  ASSERT_EQ(left_out.size(), 1u);
  EXPECT_NE(left_out[0].find("noise_sd"), std::string::npos) << left_out[0];
  LabData two = one;
  for (int k = 0; k < 10; ++k)
    two.records.push_back({2, 0.1 * k, "seat_mps2", 0.01 * k + (k % 2 ? 0.1 : -0.1)});
  EXPECT_EQ(estimateNoise(s, two, "seat_mps2").source, "repetitions");
  const auto f = writeFile("sensor.csv", "repetition,time_s,channel,value\n1,0.5,seat_mps2,0.2\n");
  EXPECT_NO_THROW(loadMeasurement(s, parseMeasurementArg(f.string() + "@diag_rough", "--data")));
  EXPECT_NE(errorOf(loadStudy(kDemo), f.string() + "@diag_rough").find("seat_mps2"),
            std::string::npos);
}
