// compareModel on the real twin: data made by the model itself are covered by the band and show
// no lack of fit; an injected burst is found as a window at the right place, labelled with what
// the vehicle was doing, and the lack-of-fit test flags it.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <regex>

#include "diagnosis/compare.hpp"
#include "io/log_import.hpp"
#include "study/generate.hpp"
#include "subsystems/effect.hpp"

using namespace dtwin;
using namespace dtwin::diag;
namespace fs = std::filesystem;

namespace {
const std::string kDemo = std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml";

using dtwin_test::truthOf;

calib::DataSet labSet(const Study& s, std::uint64_t seed) {
  LabOptions o;
  o.scenario = "diag_bump";
  o.times_mode = LabTimesMode::All;
  o.window = std::make_pair(0.5, 2.5);
  o.rate_hz = 100.0;
  o.repetitions = 4;
  o.seed = seed;
  o.channels = {"hub_force_fl_N", "hub_force_rl_N"};
  return {"bump.csv", "diag_bump", generateLab(s, s.assemblies().front(), o).data};
}
}  // namespace

TEST(Compare, ModelDataAreCoveredAndShowNoLackOfFit) {
  const Study s = loadStudy(kDemo);
  const auto ds = labSet(s, 11);
  calib::LabObjective obj(s, s.assemblies().front(), {ds}, {});
  const auto noise = estimateChannelNoise(s, {ds});
  ASSERT_EQ(noise.size(), 2u);
  // The pure-error estimate of the noise variance (18000 N²) from 4 repetitions x 201 times.
  EXPECT_NEAR(noise.at("hub_force_fl_N").variance / s.noise_variance_N2, 1.0, 0.15);
  const auto c = compareModel(obj, {ds}, {truthOf(s)}, noise);
  ASSERT_EQ(c.series.size(), 2u);
  for (const auto& x : c.series) {
    EXPECT_NEAR(x.coverage, 0.95, 0.03) << x.channel;
    EXPECT_LT(x.systematic_rms, 0.35 * std::sqrt(x.noise_variance)) << x.channel;
    EXPECT_EQ(x.t.size(), 201u);
    EXPECT_NEAR(x.rms, std::sqrt(x.noise_variance), 0.1 * std::sqrt(x.noise_variance));
    // The fit percentage: 100 (1 − ‖y − ŷ‖ / ‖y − mean y‖) = 100 (1 − RMS / sd(y)) over the
    // records.
    double sum = 0, sq = 0, n = 0;
    for (const auto& r : ds.data.records)
      if (r.channel == x.channel) {
        sum += r.value;
        sq += r.value * r.value;
        n += 1;
      }
    const double sd = std::sqrt(sq / n - (sum / n) * (sum / n));
    EXPECT_NEAR(x.fit_percent, 100.0 * (1.0 - x.rms / sd), 1e-6) << x.channel;
    EXPECT_GT(x.fit_percent, 50.0) << x.channel;  // the bump's forces stand well above the noise
    EXPECT_LT(x.fit_percent, 100.0) << x.channel;
  }
  EXPECT_GT(c.lack_of_fit_p, 1e-3) << "z = " << c.lack_of_fit_z;
  // Every band is checked; pure noise should rarely be flagged.
  int flagged = 0;
  for (const auto& x : c.series)
    for (const auto& b : x.bands) flagged += b.significant;
  EXPECT_LE(flagged, 2);
  // The frequency response from the road under each wheel: the model's own data differ from it in
  // few bands (each at 95 %), and compare.json carries it with its bins.
  int differ = 0;
  for (const auto& x : c.series) {
    const SeriesResponse& fr = x.frequency_response;
    ASSERT_TRUE(fr.computed) << x.channel << ": " << fr.note;
    EXPECT_EQ(fr.input, x.channel == "hub_force_fl_N" ? "road_fl_m" : "road_rl_m");
    EXPECT_NEAR(fr.fs_hz, 100.0, 1e-9);
    for (const auto& b : fr.response.bands) differ += b.differs;
  }
  EXPECT_LE(differ, 2);
  const nlohmann::json j = c.toJson(true).at("series").at(0).at("frequency_response");
  EXPECT_EQ(j.at("f_hz").size(), j.at("measured").at("magnitude").size());
  EXPECT_EQ(j.at("differs").size(), j.at("f_hz").size());
  EXPECT_FALSE(c.toJson(false).at("series").at(0).at("frequency_response").contains("f_hz"));
}

// A logger's clock: one repetition at 100 Hz with up to ±2 ms of jitter, so no time is on the
// 1 kHz output grid. Data made by the model at their own times are covered and show no lack of
// fit; the same values stamped 20 ms late (a clock offset of two samples, on a bump) are flagged.
// The spectrum is still drawn, resampled to a uniform grid with a note on the jitter; across a
// gap, on the longest stretch.
TEST(Compare, JitteredSampleTimesAreComparedAtTheirOwnTimes) {
  const Study s = loadStudy(kDemo);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.002, 0.002);
  std::normal_distribution<double> noise(0.0, std::sqrt(s.noise_variance_N2));
  calib::DataSet at_own{"jitter.csv", "diag_bump", {}};
  for (int k = 1; k < 280; ++k) {
    const double t = 0.01 * k + jitter(rng);
    for (const char* ch : {"hub_force_fl_N", "hub_force_rl_N"})
      at_own.data.records.push_back({1, t, ch, 0.0});
  }
  {  // the model's values at the jittered times, plus noise
    calib::LabObjective truth(s, s.assemblies().front(), {at_own}, {});
    const auto eta = truth.predict(truthOf(s));
    ASSERT_EQ(eta.size(), at_own.data.records.size());
    for (std::size_t i = 0; i < eta.size(); ++i) at_own.data.records[i].value = eta[i] + noise(rng);
  }
  calib::LabObjective obj(s, s.assemblies().front(), {at_own}, {});
  const auto c = compareModel(obj, {at_own}, {truthOf(s)}, estimateChannelNoise(s, {at_own}));
  ASSERT_EQ(c.series.size(), 2u);
  for (const auto& x : c.series) {
    EXPECT_EQ(x.noise_source, "study [noise]") << x.channel;
    EXPECT_NEAR(x.coverage, 0.95, 0.04) << x.channel;
    EXPECT_NE(x.bands_note.find("jitter"), std::string::npos) << x.bands_note;
    EXPECT_NE(x.bands_note.find("resampled to a uniform 100.0 Hz grid"), std::string::npos)
        << x.bands_note;
    EXPECT_FALSE(x.bands.empty()) << x.channel;
  }
  EXPECT_GT(c.lack_of_fit_p, 1e-3) << "z = " << c.lack_of_fit_z;

  calib::DataSet nominal = at_own;
  for (std::size_t i = 0; i < nominal.data.records.size(); ++i)
    nominal.data.records[i].time_s += 0.02;
  calib::LabObjective obj_nominal(s, s.assemblies().front(), {nominal}, {});
  const auto bad =
      compareModel(obj_nominal, {nominal}, {truthOf(s)}, estimateChannelNoise(s, {nominal}));
  EXPECT_LT(bad.lack_of_fit_p, 1e-6) << "z = " << bad.lack_of_fit_z;

  // A gap of 0.2 s in the log: compared all the same; the spectrum is the longest stretch's,
  // 1.2 s to the end (about 159 of 259 times), and the note says so.
  const auto without = [&](std::vector<std::pair<double, double>> holes) {
    calib::DataSet gap = at_own;
    auto& recs = gap.data.records;
    recs.erase(std::remove_if(recs.begin(), recs.end(),
                              [&](const LabRecord& r) {
                                for (const auto& [a, b] : holes)
                                  if (r.time_s > a && r.time_s < b) return true;
                                return false;
                              }),
               recs.end());
    calib::LabObjective obj_gap(s, s.assemblies().front(), {gap}, {});
    return compareModel(obj_gap, {gap}, {truthOf(s)}, estimateChannelNoise(s, {gap}));
  };
  const auto g = without({{1.0, 1.2}});
  for (const auto& x : g.series) {
    EXPECT_FALSE(x.bands.empty()) << x.channel;
    EXPECT_NE(x.bands_note.find("longest stretch between gaps, 1.2"), std::string::npos)
        << x.bands_note;
    EXPECT_NE(x.bands_note.find("jitter"), std::string::npos) << x.bands_note;
  }
  // Gaps every 0.6 s: no stretch holds 64 times, so no spectrum (and the note says why).
  const auto h = without({{0.6, 0.7}, {1.2, 1.3}, {1.8, 1.9}, {2.4, 2.5}});
  for (const auto& x : h.series) {
    EXPECT_TRUE(x.bands.empty()) << x.channel;
    EXPECT_NE(x.bands_note.find("no stretch between gaps holds 64 times"), std::string::npos)
        << x.bands_note;
  }
}

TEST(Compare, InjectedBurstIsLocatedAndLabelled) {
  const Study s = loadStudy(kDemo);
  auto ds = labSet(s, 8);
  for (auto& r : ds.data.records)
    if (r.channel == "hub_force_fl_N" && r.time_s >= 1.6 - 1e-9 && r.time_s <= 1.7 + 1e-9)
      r.value += 700.0;
  calib::LabObjective obj(s, s.assemblies().front(), {ds}, {});
  const auto c = compareModel(obj, {ds}, {truthOf(s)}, estimateChannelNoise(s, {ds}));
  const auto& fl = c.series[0];
  ASSERT_EQ(fl.channel, "hub_force_fl_N");
  ASSERT_FALSE(fl.windows.empty());
  // The largest window covers the burst, holds most of the residual and is labelled.
  const auto* best = &fl.windows[0];
  for (const auto& w : fl.windows)
    if (w.window.share > best->window.share) best = &w;
  EXPECT_NEAR(best->window.t_begin, 1.6, 0.011);
  EXPECT_NEAR(best->window.t_end, 1.7, 0.011);
  EXPECT_GT(best->window.share, 0.6);
  EXPECT_FALSE(best->label.empty());
  EXPECT_NEAR(best->speed_mps, 4.0, 1e-12);
  EXPECT_LT(c.lack_of_fit_p, 1e-6);
  // The systematic RMS matches the injected burst: 700 N over 11 of 201 times.
  EXPECT_NEAR(fl.systematic_rms, 700.0 * std::sqrt(11.0 / 201.0), 40.0);
}

// What the vehicle is doing, from the scenario's geometry: diag_bump's bump (2.5 m) is reached by
// the front axle at 1.0 s at 4 m/s, so the front wheels are on it from 1.0 to 1.625 s (climbing
// until 1.3125 s) and the rear wheels one wheelbase (a + b) later.
TEST(Compare, WindowsAreLabelledFromTheScenario) {
  const Study s = loadStudy(kDemo);
  const auto m = s.makeModel(s.assemblies().front());
  const auto& sc = s.scenario("diag_bump");
  const double wb = m->vehicle().wheelbase();
  EXPECT_NE(describeScenarioWindow(sc, m->vehicle(), 1.05, 1.10).find("front wheels climbing"),
            std::string::npos);
  EXPECT_NE(describeScenarioWindow(sc, m->vehicle(), 1.45, 1.50).find("front wheels leaving"),
            std::string::npos);
  const double tr = 1.0 + wb / 4.0;
  EXPECT_NE(
      describeScenarioWindow(sc, m->vehicle(), tr + 0.01, tr + 0.02).find("rear wheels climbing"),
      std::string::npos);
  EXPECT_NE(describeScenarioWindow(sc, m->vehicle(), 0.1, 0.2).find("before the bump"),
            std::string::npos);
  EXPECT_EQ(describeScenarioWindow(sc, m->vehicle(), 0.1, 0.2).find("rear"), std::string::npos);
  EXPECT_NE(
      describeScenarioWindow(s.scenario("diag_rough"), m->vehicle(), 1.0, 1.2).find("rough road"),
      std::string::npos);
}

// Every registered effect's residual signature (Effect::residualSignature) names a force-state map
// compareModel makes and a signature fit it computes there, so the diagnosis can cite it.
TEST(Compare, EveryEffectsSignatureIsAMapAndFitTheComparisonMakes) {
  const Study s = loadStudy(kDemo);
  const auto ds = labSet(s, 11);
  calib::LabObjective obj(s, s.assemblies().front(), {ds}, {});
  const auto c = compareModel(obj, {ds}, {truthOf(s)}, estimateChannelNoise(s, {ds}));
  ASSERT_FALSE(c.maps.empty());
  for (const auto& name : effectNames()) {
    const ResidualSignature sig = makeEffect(name, "test")->residualSignature();
    if (sig.state_map.empty()) continue;
    bool found = false;
    for (const auto& cm : c.maps)
      for (const auto& m : cm.maps)
        if (m.state.rfind(sig.state_map, 0) == 0)
          for (const auto& f : m.fits) found = found || f.feature == sig.feature;
    EXPECT_TRUE(found) << name << ": no map " << sig.state_map << "* with a fit '" << sig.feature
                       << "'";
  }
}

// the unknown car's drive B (data/drives, made by
// scripts/make_unknown_car_drives.py), imported with its mapping into drive A's study and
// compared at the hidden truth, fits its string potentiometer within 1.5 noise sd once the
// logger's 30 Hz filter is declared on the travel sensor, and far outside without it.
TEST(Compare, TheUnknownCarsPotFitsAtTheTruthOnceItsFilterIsDeclared) {
  const fs::path dir = dtwin_test::freshDir("compare_unknown_car");
  const std::string drives = std::string(DTWIN_SOURCE_DIR) + "/data/drives/";
  const ImportMapping m = readImportMapping(drives + "unknown_car_map.toml");
  writeImport(
      importLog(dtwin_test::slurp(drives + "unknown_car_a.csv"), "a.csv", m, kDemo, "drive_a"),
      (dir / "A").string());
  writeImport(importLog(dtwin_test::slurp(drives + "unknown_car_b.csv"), "b.csv", m,
                        (dir / "A" / "study.toml").string(), "drive_b"),
              (dir / "B").string());
  // The car as the script made it (its HIDDEN and SEAT).
  std::string text = dtwin_test::slurp(dir / "B" / "study.toml");
  text = std::regex_replace(text, std::regex(R"(position_m = \[0\.9, -0\.4, 0\.3\])"),
                            "position_m = [1.15, -0.35, 0.25]");
  text +=
      "\n[fixed]\n\"chassis.mass_kg\" = 1620.0\n\"chassis.pitch_inertia_kgm2\" = "
      "2550.0\n\"chassis.roll_inertia_kgm2\" = 560.0\n"
      "\"chassis.cg_height_m\" = 0.58\n\"chassis.cg_x_m\" = 0.06\n";
  const std::vector<double> truth{205000.0, 2600.0, 34000.0, 2300.0};
  auto potRmsInNoiseSd = [&](const std::string& study_text, const std::string& name) {
    dtwin_test::writeText(dir / "B" / name, study_text);
    const Study s = loadStudy((dir / "B" / name).string());
    const auto set = loadMeasurement(
        s, parseMeasurementArg((dir / "B" / "measurements.csv").string() + "@drive_b", "test"));
    calib::LabObjective obj(s, s.assemblies().front(), {set}, {});
    const auto c = compareModel(obj, {set}, {truth}, estimateChannelNoise(s, {set}));
    for (const auto& x : c.series)
      if (x.channel == "pot_fl_m") return x.rms / std::sqrt(x.noise_variance);
    ADD_FAILURE() << "no pot_fl_m series";
    return 0.0;
  };
  const double with = potRmsInNoiseSd(text, "truth.toml");
  EXPECT_LT(with, 1.5);
  EXPECT_GT(with, 0.8);  // the pot's own noise is in the data
  const std::string unfiltered =
      std::regex_replace(text, std::regex(R"(filter = \{ order = 1, cutoff_hz = 30(\.0)? \})"), "");
  ASSERT_NE(unfiltered, text);
  EXPECT_GT(potRmsInNoiseSd(unfiltered, "truth_unfiltered.toml"), 3.0);
}
