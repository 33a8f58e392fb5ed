// A scenario whose speed comes from a measured trace (`speed = { csv = "FILE" }`): a constant
// trace drives the vehicle exactly as the constant-speed profile does, a varying one changes the
// run, the fingerprint follows the file's numbers, and bad traces are refused at the study field.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "common/errors.hpp"
#include "io/study.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;
namespace fs = std::filesystem;

namespace {

/// The demo study with the diag_bump scenario's speed replaced by `speed` (a TOML inline table).
fs::path studyWithSpeed(const fs::path& dir, const std::string& speed) {
  const fs::path p = dtwin_test::writeDemoStudy(dir / "study.toml", "lab_repetitions = 2\n");
  std::string s = dtwin_test::slurp(p);
  s = std::regex_replace(s, std::regex(R"(speed = \{ v_final_mps = 4\.0, ramp_s = 0\.0 \})"),
                         speed);
  dtwin_test::writeText(p, s);
  return p;
}

const ScenarioSpec& scenario(const Study& s, const std::string& name) {
  for (const auto& sc : s.scenarios)
    if (sc.name == name) return sc;
  throw std::runtime_error("no scenario " + name);
}

/// diag_bump on M1, at `accuracy` (the demo's 3e-4 leaves integration errors of some newtons,
/// which a changed step sequence moves).
Trace runBump(const Study& s, double accuracy = 3e-4) {
  const auto model = s.makeModel(s.assemblies().front());
  SimulationOptions o = s.simulation;
  o.accuracy = accuracy;
  Simulator sim(model, o);
  const ScenarioSpec& sc = scenario(s, "diag_bump");
  const auto road = makeRoad(sc, model->vehicle(), s.seed);
  const auto r = sim.run(model->defaultRunValues(), *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r.trace;
}

std::string errorOf(const fs::path& study) {
  try {
    loadStudy(study.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SpeedTraceScenario, AConstantTraceDrivesLikeTheConstantSpeedProfile) {
  const fs::path dir = dtwin_test::freshDir("speed_trace_constant");
  const Study ramp =
      loadStudy(studyWithSpeed(dir, "speed = { v_final_mps = 4.0, ramp_s = 0.0 }").string());
  dtwin_test::writeText(dir / "speed.csv", "time_s,speed_kmh\n0,14.4\n1.7,14.4\n3.0,14.4\n");
  const Study traced = loadStudy(studyWithSpeed(dir, R"(speed = { csv = "speed.csv" })").string());
  ASSERT_TRUE(scenario(traced, "diag_bump").speed.trace);
  EXPECT_EQ(scenario(traced, "diag_bump").speed.toJson()["samples"], 3);
  const Trace a = runBump(ramp, 1e-8), b = runBump(traced, 1e-8);
  ASSERT_EQ(a.rows(), b.rows());
  const auto &fa = a.column("hub_force_fl_N"), &fb = b.column("hub_force_fl_N");
  // Row 0 differs by design: the ramp profile is at rest at exactly t = 0 (its speed(0) is 0),
  // a trace is at its first sample's speed there. From the next sample on they must agree.
  EXPECT_EQ(a.column("speed_mps")[0], 0.0);
  EXPECT_EQ(b.column("speed_mps")[0], 4.0);
  double peak = 0, diff = 0;
  for (std::size_t i = 1; i < fa.size(); ++i) {
    peak = std::max(peak, std::abs(fa[i]));
    diff = std::max(diff, std::abs(fa[i] - fb[i]));
  }
  EXPECT_GT(peak, 1000.0);
  EXPECT_LT(diff, 1e-5 * peak)
      << "the same speed, distance and acceleration: the same run up to the integration error";
}

TEST(SpeedTraceScenario, AVaryingTraceChangesTheRunAndTheFingerprint) {
  const fs::path dir = dtwin_test::freshDir("speed_trace_varying");
  dtwin_test::writeText(dir / "speed.csv", "time_s,speed_mps\n0,4\n3,4\n");
  const Study constant =
      loadStudy(studyWithSpeed(dir, R"(speed = { csv = "speed.csv" })").string());
  const auto constant_json = scenario(constant, "diag_bump").toJson();
  const Trace a = runBump(constant);
  // Braking from 6 to 2 m/s over the bump: the wheels reach it at another time.
  dtwin_test::writeText(dir / "speed.csv", "time_s,speed_mps\n0,6\n1,5\n2,3\n3,2\n");
  const Study braking = loadStudy((dir / "study.toml").string());
  EXPECT_NE(scenario(braking, "diag_bump").toJson()["speed"]["content"],
            constant_json["speed"]["content"]);
  EXPECT_EQ(scenario(braking, "diag_bump").toJson()["speed"]["csv"], constant_json["speed"]["csv"]);
  const Trace b = runBump(braking);
  const auto &fa = a.column("hub_force_fl_N"), &fb = b.column("hub_force_fl_N");
  double diff = 0;
  for (std::size_t i = 0; i < std::min(fa.size(), fb.size()); ++i)
    diff = std::max(diff, std::abs(fa[i] - fb[i]));
  EXPECT_GT(diff, 100.0);
}

TEST(SpeedTraceScenario, BadTracesAreRefusedAtTheStudyField) {
  const fs::path dir = dtwin_test::freshDir("speed_trace_bad");
  const std::regex field("^" + (dir / "study.toml").string() +
                         R"(:[0-9]+: scenarios\.diag_bump\.speed\.csv: )");
  dtwin_test::writeText(dir / "short.csv", "time_s,speed_mps\n0,4\n2.5,4\n");
  fs::path p = studyWithSpeed(dir, R"(speed = { csv = "short.csv" })");
  EXPECT_TRUE(std::regex_search(errorOf(p), field)) << errorOf(p);
  EXPECT_NE(errorOf(p).find("covers 0..2.5 s but the scenario needs 0..3 s"), std::string::npos)
      << errorOf(p);
  dtwin_test::writeText(dir / "late.csv", "time_s,speed_mps\n0.5,4\n3,4\n");
  p = studyWithSpeed(dir, R"(speed = { csv = "late.csv" })");
  EXPECT_NE(errorOf(p).find("covers 0.5..3 s"), std::string::npos) << errorOf(p);
  dtwin_test::writeText(dir / "fast.csv", "time_s,speed_kmh\n0,40\n3,400\n");
  p = studyWithSpeed(dir, R"(speed = { csv = "fast.csv" })");
  EXPECT_NE(errorOf(p).find("reaches 111.111 m/s at sample 1; at most 100 m/s"), std::string::npos)
      << errorOf(p);
  p = studyWithSpeed(dir, R"(speed = { csv = "short.csv", ramp_s = 1.0 })");
  EXPECT_NE(errorOf(p).find("speed.ramp_s: give either csv"), std::string::npos) << errorOf(p);
  p = studyWithSpeed(dir, R"(speed = { csv = "missing.csv" })");
  EXPECT_EQ(errorOf(p), (dir / "missing.csv").string() +
                            ": cannot be read (a speed trace: time_s,speed_<unit>)");
  dtwin_test::writeText(dir / "bad.csv", "time_s,speed_mps\n0,4\n1,-4\n3,4\n");
  p = studyWithSpeed(dir, R"(speed = { csv = "bad.csv" })");
  EXPECT_EQ(errorOf(p), (dir / "bad.csv").string() + ":3: speed_mps: must be >= 0, got -4");
}
