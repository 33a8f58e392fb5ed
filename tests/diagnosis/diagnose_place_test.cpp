// Where the road signal enters and where a sensor sits, as causes the diagnosis weighs
// (docs/diagnosis.md, "Candidates of structure" and "Where a sensor sits"). Known answers: data
// made by a car whose road signal is the front-left wheel's alone (road.fl_only = 1) and whose body
// accelerometer sits over the front-left wheel, diagnosed with a study that reads the signal under
// both axles and puts the accelerometer at the centre of mass: the form and the sensor's place are
// named, over the front-left wheel, the residual left at the noise, each hidden value near its
// estimate (the share within 0.02, the place within 15 cm fore-aft and 10 cm across). The null
// case: the same car with its sensor where the study says and the signal under both axles gives
// no place and no form. Label `places` (ctest -L places), kept out of the default run for time.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>

#include "diagnosis/diagnose.hpp"
#include "diagnosis_lab_data.hpp"
#include "io/study.hpp"
#include "test_util.hpp"

using namespace dtwin;
using namespace dtwin::diag;
namespace fs = std::filesystem;

namespace {

constexpr double kSeatNoise = 0.03;  // m/s^2

/// The demo study with a body accelerometer at `seat` (x, y, z) and `fixed` lines in [fixed].
Study placeStudy(const std::string& name, const std::string& seat, const std::string& fixed) {
  const fs::path p =
      dtwin_test::writeDemoStudy(dtwin_test::freshDir("diag_place_" + name) / "study.toml",
                                 "lab_repetitions = 3\noptimizer_starts = 2\n");
  std::string text = dtwin_test::slurp(p);
  text += "\n[sensors.seat]\nquantity = \"acceleration_z\"\nposition_m = " + seat +
          "\nnoise_sd = " + std::to_string(kSeatNoise) + "\n";
  if (!fixed.empty()) text += "\n[fixed]\n" + fixed + "\n";
  std::ofstream(p) << text;
  return loadStudy(p.string());
}

/// Lab data of `truth` (hub forces with the study's noise, the accelerometer with its noise_sd,
/// drawn here: the generator leaves non-force channels noise-free).
std::vector<calib::DataSet> placeData(const Study& truth, std::uint64_t seed) {
  auto sets = dtwin_test::diagnosisLabData(
      truth, "", seed, [](LabOptions& o) { o.channels.push_back("seat_mps2"); });
  std::mt19937_64 rng(seed * 7919 + 11);
  std::normal_distribution<double> n(0.0, kSeatNoise);
  for (auto& s : sets)
    for (auto& r : s.data.records)
      if (r.channel == "seat_mps2") r.value += n(rng);
  return sets;
}

DiagnoseOptions placeOptions(const Study& s) {
  DiagnoseOptions o = dtwin_test::smallDiagnosisOptions(s);
  o.calibration.profile.steps = 2;
  o.calibration.profile.restarts = 0;
  o.calibration.profile.polish_iterations = 0;
  o.candidates = 3;
  o.causes = 3;
  o.propose_terms = 0;
  // The place candidates beside their look-alikes: other forms of the signal, its gain, a
  // controller.
  o.effects = {"free:road.fl_only", "free:road.left_only", "free:road.all_at_once",
               "free:road.gain",    "place:seat",          "skyhook"};
  return o;
}

/// |optimum − truth| within `tolerance`. These tests run the diagnosis at small sizes (the paper's
/// region, two profile points), whose intervals are not the ones a user gets: coverage is the
/// calibration tests' job (tests/calibration); here the estimate must land near the truth.
void expectNear(const Cause& k, const std::string& name, double truth, double tolerance,
                const std::string& text) {
  for (const auto& p : k.parameters)
    if (p.name == name) {
      EXPECT_LE(std::abs(p.optimum - truth), tolerance)
          << name << " " << p.optimum << " [" << p.q025 << ", " << p.q975 << "]\n"
          << text;
      return;
    }
  ADD_FAILURE() << "no parameter " << name << " in cause " << k.name << "\n" << text;
}

}  // namespace

TEST(Places, TheRoadSignalsCornerAndTheSensorsPlaceAreNamed) {
  const Study truth = placeStudy("truth", "[1.515, 0.775, 0.25]", "\"road.fl_only\" = 1.0");
  const Study s = placeStudy("study", "[0.0, 0.0, 0.25]", "");
  const auto r = diagnose(s, s.assemblies().front(), placeData(truth, 5), {}, placeOptions(s),
                          dtwin_test::freshDir("diag_place_run"));
  const std::string text = r.text();
  ASSERT_EQ(r.verdict, "effect") << text;
  std::set<std::string> named;
  for (const auto& k : r.causes) named.insert(k.name);
  EXPECT_TRUE(named.count("free:road.fl_only")) << text;
  EXPECT_TRUE(named.count("place:seat")) << text;
  EXPECT_FALSE(named.count("skyhook")) << text;
  for (const auto& k : r.causes) {
    if (k.name == "free:road.fl_only") {
      EXPECT_EQ(k.kind, "input");
      EXPECT_NE(k.finding.find("the front-left wheel's road alone"), std::string::npos)
          << k.finding;
      expectNear(k, "road.fl_only", 1.0, 0.02, text);
    }
    if (k.name == "place:seat") {
      EXPECT_EQ(k.kind, "place");
      EXPECT_NE(k.finding.find("over the front-left wheel"), std::string::npos) << k.finding;
      expectNear(k, "sensors.seat.x_m", 1.515, 0.15, text);
      expectNear(k, "sensors.seat.y_m", 0.775, 0.1, text);
    }
  }
  EXPECT_NE(text.find("Sensor place: "), std::string::npos) << text;
  ASSERT_FALSE(r.causes.empty());
  EXPECT_LT(r.causes.back().fit.comparison.lack_of_fit_z, 3.0) << text;
}

TEST(Places, ASensorWhereTheStudySaysAndTheSignalUnderBothAxlesGiveNoPlace) {
  const Study s = placeStudy("null", "[0.4, -0.35, 0.25]", "");
  auto o = placeOptions(s);
  const auto r = diagnose(s, s.assemblies().front(), placeData(s, 6), {}, o,
                          dtwin_test::freshDir("diag_place_null"));
  EXPECT_EQ(r.verdict, "none") << r.text();
  for (const auto& k : r.causes) EXPECT_NE(k.kind, "place") << r.text();
}
