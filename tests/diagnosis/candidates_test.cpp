// twin diagnose's candidates (diagnosis/candidates.hpp): effects, freed vehicle values and sensor
// models, their names, groups, parameters, setups and findings; a sensor model inside the
// calibration objective is the channel read through subsystems/sensor.hpp's distortChannel.
#include <gtest/gtest.h>

#include <algorithm>

#include "common/errors.hpp"
#include "diagnosis/candidates.hpp"
#include "test_util.hpp"

using namespace dtwin;
using namespace dtwin::diag;

namespace {
Study demo() {
  return loadStudy(
      dtwin_test::writeDemoStudy(dtwin_test::freshDir("cands") / "study.toml", "").string());
}
const std::vector<std::string> kHub = {"hub_force_fl_N", "hub_force_fr_N", "hub_force_rl_N",
                                       "hub_force_rr_N"};

/// The objective of the candidate `name` installed in the study's first assembly, on `data`
/// (diag_bump), and the study's true base parameters.
struct WithCandidate {
  std::vector<calib::DataSet> sets;
  calib::CalibrationSetup setup;
  std::vector<double> truth;
  WithCandidate(const Study& s, const std::string& name, const LabData& data)
      : sets{{"d", "diag_bump", data}} {
    candidateSpec(name, s, s.assemblies().front(), kHub, "t").install(setup);
    for (const auto& p : s.calibrated) truth.push_back(*p.truth);
  }
  calib::LabObjective objective(const Study& s) const {
    return calib::LabObjective(s, s.assemblies().front(), sets, setup);
  }
  calib::LabObjective base(const Study& s) const {
    return calib::LabObjective(s, s.assemblies().front(), sets, {});
  }
};
}  // namespace

TEST(Candidates, ChannelGroupsAreNamedByUnitAndCommonPrefix) {
  auto g = channelGroups({"hub_force_fl_N", "hub_force_fr_N", "seat_mps2"});
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].first, "hub_force");
  EXPECT_EQ(g[0].second.size(), 2u);
  EXPECT_EQ(g[1].first, "seat");
  g = channelGroups({"a_mps2", "b_mps2"});
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0].first, "mps2");  // nothing in common: the unit names the group
}

TEST(Candidates, DefaultCatalogueHoldsEffectsFreedValuesAndSensorModels) {
  const Study s = demo();
  const auto names = defaultCandidates(s, s.assemblies().front(), kHub);
  auto has = [&](const std::string& n) {
    return std::find(names.begin(), names.end(), n) != names.end();
  };
  EXPECT_TRUE(has("bump_stop"));
  EXPECT_TRUE(has("free:wheel.mass_kg"));
  EXPECT_FALSE(has("free:solid_axle.mass_kg"));  // M1 is MacPherson
  EXPECT_TRUE(has("lowpass:hub_force"));
  EXPECT_TRUE(has("delay:hub_force"));
  for (const auto& n : names) EXPECT_TRUE(isCandidateName(n, s.effectCatalog())) << n;
  EXPECT_FALSE(isCandidateName("highpass:hub_force", s.effectCatalog()));
  EXPECT_FALSE(isCandidateName("free:", s.effectCatalog()));
}

TEST(Candidates, SpecsCarryOffValuesPriorsAndSetups) {
  const Study s = demo();
  const auto a = s.assemblies().front();
  const auto m = candidateSpec("free:wheel.mass_kg", s, a, kHub, "t");
  EXPECT_EQ(m.kind, "parameter");
  ASSERT_EQ(m.parameters.size(), 1u);
  EXPECT_DOUBLE_EQ(m.parameters[0].default_value, 29.46);
  EXPECT_DOUBLE_EQ(m.parameters[0].prior_lower, 0.5 * 29.46);
  EXPECT_DOUBLE_EQ(m.parameters[0].prior_upper, 1.5 * 29.46);
  EXPECT_EQ(m.finding({35.3}), "the wheel mass is about 35.3 kg, not 29.46 kg");
  calib::CalibrationSetup setup;
  m.install(setup);
  EXPECT_EQ(setup.freed, std::vector<std::string>{"wheel.mass_kg"});
  EXPECT_EQ(setup.extra_calibrated.at(0).name, "wheel.mass_kg");

  // A fixed value of the assembly's laws (the tire radius) is a run parameter already: calibrated
  // without a rebuild, so it is not among the freed; a calibrated value cannot be freed.
  const auto r0 = candidateSpec("free:tire.unloaded_radius_m", s, a, kHub, "t");
  EXPECT_EQ(r0.kind, "parameter");
  EXPECT_TRUE(r0.law_value);
  EXPECT_DOUBLE_EQ(r0.parameters.at(0).default_value, 0.31);
  EXPECT_DOUBLE_EQ(r0.parameters.at(0).prior_upper, 1.5 * 0.31);
  calib::CalibrationSetup setup_r0;
  r0.install(setup_r0);
  EXPECT_TRUE(setup_r0.freed.empty());
  EXPECT_EQ(setup_r0.extra_calibrated.at(0).name, "tire.unloaded_radius_m");
  try {
    candidateSpec("free:" + s.calibrated.at(0).name, s, a, kHub, "--effects");
    ADD_FAILURE() << "a calibrated value was freed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is calibrated already"), std::string::npos) << e.what();
  }

  const auto lp = candidateSpec("lowpass:hub_force", s, a, kHub, "t");
  EXPECT_EQ(lp.kind, "sensor");
  EXPECT_EQ(lp.channels, kHub);
  EXPECT_EQ(lp.finding({1.0 / (2 * kPi * 25.0)}),
            "the hub_force channels look filtered at about 25 Hz (first-order low-pass)");
  EXPECT_EQ(candidateSpec("delay:hub_force_fl_N", s, a, kHub, "t").channels,
            std::vector<std::string>{"hub_force_fl_N"});

  const auto bs = candidateSpec("bump_stop", s, a, kHub, "t");
  EXPECT_EQ(bs.kind, "effect");
  EXPECT_FALSE(bs.engagement_threshold.empty());
  for (const char* bad : {"free:wheel.mas_kg", "free:solid_axle.mass_kg", "lowpass:seat",
                          "highpass:hub_force", "bump_stopp"})
    EXPECT_THROW(candidateSpec(bad, s, a, kHub, "t"), InputError) << bad;
}

TEST(Candidates, ARangeThatWouldLeaveTheValidSetIsClippedAndSaysSo) {
  // The CG 0.1 m behind the front axle: +10 % of the 1.604 m wheelbase (0.16 m) forward would put
  // it ahead of the axle; the range stops at 90 % of the way (0.09 m) and the text says why.
  const Study s =
      loadStudy(dtwin_test::writeDemoStudy(dtwin_test::freshDir("cands_clip") / "study.toml",
                                           "\n[fixed]\n\"geometry.cg_to_front_axle_m\" = 0.1\n")
                    .string());
  const auto cg = candidateSpec("free:chassis.cg_x_m", s, s.assemblies().front(), kHub, "t");
  ASSERT_EQ(cg.parameters.size(), 1u);
  EXPECT_DOUBLE_EQ(cg.parameters[0].prior_upper, 0.9 * 0.1);
  EXPECT_NEAR(cg.parameters[0].prior_lower, -0.1 * (0.1 + 1.504),
              1e-12);  // the rear end is not clipped
  EXPECT_NE(cg.range_note.find("clipped"), std::string::npos) << cg.range_note;
  EXPECT_NE(cg.range_note.find("front axle"), std::string::npos) << cg.range_note;
  EXPECT_EQ(cg.range_note.find("rear axle"), std::string::npos) << cg.range_note;
  EXPECT_NE(cg.signature.find(cg.range_note), std::string::npos);
  // A mass's ±50 % stays positive: nothing to clip, nothing said.
  EXPECT_TRUE(
      candidateSpec("free:wheel.mass_kg", s, s.assemblies().front(), kHub, "t").range_note.empty());
}

// A sensor's position and offset may well be 0, where ±50 % is no range: ±0.5 m about the
// position, ±20 noise sd about the offset (refused, in one line, without a noise_sd).
TEST(Candidates, ASensorsPositionAndOffsetGetAbsoluteRanges) {
  const Study s = loadStudy(
      dtwin_test::writeDemoStudy(
          dtwin_test::freshDir("cands_sensor") / "study.toml",
          "\n[sensors.seat]\nquantity = \"acceleration_z\"\nposition_m = [0.9, 0.0, 0.3]\n"
          "noise_sd = 0.03\n[sensors.bare]\nquantity = \"acceleration_z\"\n")
          .string());
  const AssemblySpec a = s.assemblies().front();
  const std::vector<std::string> ch{"seat_mps2", "bare_mps2"};
  // Not declared measured: searched to the physical limit (a place, not a wrong vehicle value).
  const auto y = candidateSpec("free:sensors.seat.y_m", s, a, ch, "t");
  ASSERT_EQ(y.parameters.size(), 1u);
  EXPECT_EQ(y.kind, "place");
  EXPECT_DOUBLE_EQ(y.parameters[0].prior_lower, -1.3);
  EXPECT_DOUBLE_EQ(y.parameters[0].prior_upper, 1.3);
  const auto x = candidateSpec("free:sensors.seat.x_m", s, a, ch, "t");
  EXPECT_DOUBLE_EQ(x.parameters[0].prior_lower, -4.0);
  EXPECT_DOUBLE_EQ(x.parameters[0].prior_upper, 4.0);
  const auto off = candidateSpec("free:sensors.seat.offset", s, a, ch, "t");
  EXPECT_DOUBLE_EQ(off.parameters[0].prior_lower, -0.6);
  EXPECT_DOUBLE_EQ(off.parameters[0].prior_upper, 0.6);
  try {
    (void)candidateSpec("free:sensors.bare.offset", s, a, ch, "--effects");
    FAIL() << "an offset without a noise_sd got a range";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("noise_sd"), std::string::npos) << m;
    EXPECT_NE(m.find("--effects"), std::string::npos) << m;
  }
}

// A vehicle value the study calibrates already cannot be freed again (the diagnosis's default
// catalogue leaves it out; named, it is a one-line error).
TEST(Candidates, AVehicleValueTheStudyCalibratesIsNoCandidate) {
  const Study s =
      loadStudy(dtwin_test::writeDemoStudy(
                    dtwin_test::freshDir("cands_calibrated") / "study.toml",
                    "\n[[calibrated]]\nname = \"chassis.mass_kg\"\nlower = 1100\nupper = 1700\n")
                    .string());
  try {
    (void)candidateSpec("free:chassis.mass_kg", s, s.assemblies().front(), kHub, "--effects");
    FAIL() << "a calibrated value was freed again";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("calibrated already"), std::string::npos) << e.what();
  }
}

TEST(Candidates, ASensorModelInTheObjectiveIsTheChannelThroughDistortChannel) {
  const Study s = demo();
  LabData data;
  for (int k = 200; k <= 2800; k += 5)
    data.records.push_back({1, k / 1000.0, "hub_force_fl_N", 0.0});
  data.records.push_back({1, 1.2345, "hub_force_fl_N", 0.0});  // off the grid
  const WithCandidate wc(s, "lowpass:hub_force", data);
  const auto with = wc.objective(s), without = wc.base(s);
  std::vector<double> th = wc.truth;
  const auto raw = without.predict(th);
  th.push_back(0.0);
  EXPECT_EQ(with.predict(th), raw);  // off: the base model's predictions exactly
  th.back() = 0.01;
  const auto filtered = with.predict(th);
  const auto runs = without.runs(std::vector<double>(th.begin(), th.end() - 1));
  ASSERT_EQ(runs.size(), 1u);
  SensorDistortion d;
  d.set("lowpass", 0.01);
  std::vector<double> times;
  for (const auto& r : data.records) times.push_back(r.time_s);
  const auto expect =
      distortChannel(runs[0].trace.column("hub_force_fl_N"), s.simulation.output_rate_hz, times, d);
  for (std::size_t i = 0; i < times.size(); ++i) EXPECT_EQ(filtered[i], expect[i]) << times[i];
  double most = 0;
  for (std::size_t i = 0; i < raw.size(); ++i)
    most = std::max(most, std::abs(filtered[i] - raw[i]));
  EXPECT_GT(most, 10.0);  // the bump's hub force is filtered visibly
}

// A fixed law value (the tire radius) freed as a candidate enters the objective as a run
// parameter: at the file's value the predictions are the base model's exactly.
TEST(Candidates, AFreedLawValueIsARunParameterOfTheObjective) {
  const Study s = demo();
  LabData data;
  for (int k = 200; k <= 2800; k += 50)
    data.records.push_back({1, k / 1000.0, "hub_force_fl_N", 0.0});
  const WithCandidate wc(s, "free:tire.unloaded_radius_m", data);
  const auto with = wc.objective(s), without = wc.base(s);
  std::vector<double> th = wc.truth;
  const auto raw = without.predict(th);
  th.push_back(0.31);
  EXPECT_EQ(with.predict(th), raw);
  th.back() = 0.36;
  const auto moved = with.predict(th);
  ASSERT_EQ(moved.size(), raw.size());
  for (double v : moved) EXPECT_TRUE(std::isfinite(v));
}

// The per-corner and per-axle factors (twin/parameters.hpp) are candidates of the default
// catalogue: every corner of each value the laws have, and the front axle alone when the study
// calibrates the whole value (the rear's is the same model). Freed without a rebuild over their
// prior [0.2, 2]; at 1 the objective's predictions are the base model's exactly, away from 1 they
// move.
TEST(Candidates, PerCornerFactorsAreCandidates) {
  const Study s = demo();
  const auto a = s.assemblies().front();
  const auto all = defaultCandidates(s, a, kHub, false);
  std::vector<std::string> factors, at_corner;
  for (const auto& n : all)
    if (n.find('@') != std::string::npos)
      (n.rfind("free:", 0) == 0 ? factors : at_corner).push_back(n);
  // demo calibrates all four values as a whole: four corners and the front axle each.
  ASSERT_EQ(factors.size(), 20u);
  for (const char* v :
       {"suspension.stiffness", "suspension.damping", "tire.stiffness", "tire.damping"}) {
    for (const char* place : {"fl", "fr", "rl", "rr", "front"})
      EXPECT_NE(std::find(all.begin(), all.end(), std::string("free:") + v + "@" + place),
                all.end())
          << v << "@" << place;
    EXPECT_EQ(std::find(all.begin(), all.end(), std::string("free:") + v + "@rear"), all.end())
        << v;
  }
  // The effects of a part that wears at one strut, at each corner.
  EXPECT_EQ(
      at_corner,
      (std::vector<std::string>{
          "bump_stop@fl", "bump_stop@fr", "bump_stop@rl", "bump_stop@rr", "damper_asymmetry@fl",
          "damper_asymmetry@fr", "damper_asymmetry@rl", "damper_asymmetry@rr", "strut_friction@fl",
          "strut_friction@fr", "strut_friction@rl", "strut_friction@rr", "top_mount_compliance@fl",
          "top_mount_compliance@fr", "top_mount_compliance@rl", "top_mount_compliance@rr"}));
  auto both = factors;
  both.insert(both.end(), at_corner.begin(), at_corner.end());
  EXPECT_EQ(cornerCandidates(s, a), both);
  const auto stop = candidateSpec("bump_stop@rr", s, a, kHub, "t");
  EXPECT_EQ(stop.kind, "effect");
  EXPECT_EQ(stop.calibrated_names.front().rfind("bump_stop@rr.", 0), 0u);
  EXPECT_EQ(stop.signature.rfind("at the rear-right corner only: ", 0), 0u) << stop.signature;
  // The hub input has no tire compliance: no tire factor.
  AssemblySpec hub = a;
  for (auto& [sub, opt] : hub.options)
    if (sub == "tire") opt = "hub";
  for (const auto& n : cornerCandidates(s, hub))
    EXPECT_EQ(n.find("free:tire."), std::string::npos) << n;
  EXPECT_EQ(factorPlaceInWords("suspension.damping@rr"), "the rear-right damper");
  EXPECT_EQ(factorPlaceInWords("suspension.damping@rear"), "both rear dampers");
  EXPECT_EQ(factorPlaceInWords("tire.stiffness@fl"), "the front-left tire");
  const auto front = candidateSpec("free:suspension.stiffness@front", s, a, kHub, "t");
  EXPECT_TRUE(front.relative);
  EXPECT_EQ(front.finding({0.7}, 0.65, 0.75),
            "the front springs give about 70 % of the stiffness of the rear ones (95 %: 65 % to 75 "
            "%) (which axle changed, these data "
            "cannot tell while the whole stiffness is calibrated)");
  // Above 1: said of the other axle, the one with the lower value.
  EXPECT_EQ(front.finding({2.0}, 1.6, 2.5),
            "the rear springs give about 50 % of the stiffness of the front ones (95 %: 40 % to 62 "
            "%) (which axle changed, these data "
            "cannot tell while the whole stiffness is calibrated)");
}

TEST(Candidates, APerCornerFactorIsACandidateWhenNamed) {
  const Study s = demo();
  const auto a = s.assemblies().front();
  const auto f = candidateSpec("free:suspension.damping@rr", s, a, kHub, "t");
  EXPECT_EQ(f.kind, "parameter");
  EXPECT_FALSE(f.law_value);
  ASSERT_EQ(f.parameters.size(), 1u);
  EXPECT_EQ(f.parameters[0].default_value, 1.0);
  EXPECT_EQ(f.parameters[0].prior_lower, 0.2);
  EXPECT_EQ(f.parameters[0].prior_upper, 2.0);
  EXPECT_TRUE(f.relative);  // demo calibrates the whole damping
  EXPECT_NE(f.signature.find("the rear-right damper's damping differs from the other corners'"),
            std::string::npos)
      << f.signature;
  EXPECT_EQ(f.finding({0.45}),
            "the rear-right damper gives about 45 % of the damping of the other three");
  EXPECT_EQ(f.finding({0.5512}, 0.5107, 0.5822),
            "the rear-right damper gives about 55 % of the damping of the other three (95 %: 51 % "
            "to 58 %)");
  for (const char* bad : {"free:suspension.damping@xx", "free:chassis.mass_kg@fl"})
    EXPECT_THROW(candidateSpec(bad, s, a, kHub, "t"), InputError) << bad;

  LabData data;
  for (int k = 200; k <= 2800; k += 50)
    data.records.push_back({1, k / 1000.0, "hub_force_rr_N", 0.0});
  const WithCandidate wc(s, "free:suspension.damping@rr", data);
  EXPECT_EQ(wc.setup.freed, std::vector<std::string>{"suspension.damping@rr"});
  const auto with = wc.objective(s), without = wc.base(s);
  std::vector<double> th = wc.truth;
  const auto raw = without.predict(th);
  th.push_back(1.0);
  EXPECT_EQ(with.predict(th), raw);
  th.back() = 0.5;
  EXPECT_NE(with.predict(th), raw);
}

// Where a sensor sits (docs/diagnosis.md, "Where a sensor sits"): a chassis sensor of a fitted
// channel whose position is not declared measured has its fore-aft and lateral place among the
// default candidates; a measured one is searched five of its standard deviations about the
// study's value when named, and is no default candidate; the finding names the place against the
// axles and the wheels.
TEST(Candidates, ASensorWhosePositionIsNotDeclaredMeasuredHasItsPlaceAsCandidates) {
  const Study s = loadStudy(
      dtwin_test::writeDemoStudy(
          dtwin_test::freshDir("cands_place") / "study.toml",
          "\n[sensors.seat]\nquantity = \"acceleration_z\"\nposition_m = [0.0, 0.0, 0.3]\n"
          "[sensors.known]\nquantity = \"acceleration_z\"\nposition_m = [0.5, 0.2, 0.3]\n"
          "position_sd_m = 0.02\n")
          .string());
  const AssemblySpec a = s.assemblies().front();
  const std::vector<std::string> ch{"seat_mps2", "known_mps2"};
  const auto names = defaultCandidates(s, a, ch);
  auto has = [&](const std::string& n) {
    return std::find(names.begin(), names.end(), n) != names.end();
  };
  EXPECT_TRUE(has("place:seat"));
  EXPECT_FALSE(has("free:sensors.seat.x_m"));  // fore-aft and across as one place
  EXPECT_FALSE(has("place:known"));
  // Not fitted: no candidate.
  const auto only_known = defaultCandidates(s, a, {"known_mps2"});
  EXPECT_EQ(std::count(only_known.begin(), only_known.end(), "place:seat"), 0);
  const auto both = candidateSpec("place:seat", s, a, ch, "t");
  EXPECT_EQ(both.kind, "place");
  ASSERT_EQ(both.calibrated_names,
            (std::vector<std::string>{"sensors.seat.x_m", "sensors.seat.y_m"}));
  EXPECT_DOUBLE_EQ(both.parameters[1].prior_lower, -1.3);
  EXPECT_EQ(both.finding({1.5, 0.76}),
            "the sensor seat acts as if it sat 1.50 m ahead of the CG and 0.76 m left of the "
            "centre line: over the front-left wheel "
            "(the study puts it 0.00 m ahead of the CG, on the centre line)");
  EXPECT_EQ(both.finding({-1.45, 0.02}),
            "the sensor seat acts as if it sat 1.45 m behind the CG and 0.02 m left of the centre "
            "line: over the middle of the rear axle "
            "(the study puts it 0.00 m ahead of the CG, on the centre line)");
  EXPECT_THROW((void)candidateSpec("place:nosuch", s, a, ch, "t"), InputError);
  const auto known = candidateSpec("free:sensors.known.x_m", s, a, ch, "t");
  EXPECT_DOUBLE_EQ(known.parameters[0].prior_lower, 0.4);
  EXPECT_DOUBLE_EQ(known.parameters[0].prior_upper, 0.6);
  // The finding: the sedan's front axle is 1.515 m ahead of the CG, its track 1.55 m.
  const auto x = candidateSpec("free:sensors.seat.x_m", s, a, ch, "t");
  EXPECT_EQ(x.finding({1.49}),
            "the sensor seat acts as if it sat 1.49 m ahead of the CG, over the front axle (the "
            "study puts it 0.00 m ahead of the CG)");
  EXPECT_EQ(x.finding({2.4}),
            "the sensor seat acts as if it sat 2.40 m ahead of the CG, ahead of the front axle "
            "(the study puts it 0.00 m ahead of the CG)");
  EXPECT_EQ(x.finding({-0.5}),
            "the sensor seat acts as if it sat 0.50 m behind the CG, between the axles (the study "
            "puts it 0.00 m ahead of the CG)");
  const auto y = candidateSpec("free:sensors.seat.y_m", s, a, ch, "t");
  EXPECT_EQ(y.finding({0.77}),
            "the sensor seat acts as if it sat 0.77 m left of the centre line, over the left "
            "wheels (the study puts it on the centre line)");
  EXPECT_EQ(y.finding({-0.1}),
            "the sensor seat acts as if it sat 0.10 m right of the centre line, between the wheels "
            "(the study puts it on the centre line)");
  // A calibrated position is no candidate either.
  EXPECT_THROW(
      (void)loadStudy(dtwin_test::writeDemoStudy(
                          dtwin_test::freshDir("cands_place_bad") / "study.toml",
                          "\n[sensors.w]\nbody = \"wheel_fl\"\nquantity = \"acceleration_z\"\n"
                          "position_sd_m = 0.02\n")
                          .string()),
      InputError);
}

// Where the road signal enters (twin/model.hpp roadSignalForms): each form is an input candidate
// when a road is a measured signal, searched over [-0.5, 1.5], and its finding says the place.
TEST(Candidates, TheRoadSignalsFormsAreInputCandidatesOfAMeasuredRoad) {
  const Study s = demo();
  const AssemblySpec a = s.assemblies().front();
  const auto plain = defaultCandidates(s, a, kHub, false);
  EXPECT_EQ(std::count(plain.begin(), plain.end(), "free:road.fl_only"), 0);
  const auto measured = defaultCandidates(s, a, kHub, true);
  for (const auto& f : roadSignalForms())
    EXPECT_EQ(std::count(measured.begin(), measured.end(), std::string("free:") + f.name), 1)
        << f.name;
  // Each wheel's own motion (a four-corner road): the places are known, the gain and delay stay.
  const auto wheels = defaultCandidates(s, a, kHub, true, true);
  for (const auto& f : roadSignalForms())
    EXPECT_EQ(std::count(wheels.begin(), wheels.end(), std::string("free:") + f.name), 0) << f.name;
  EXPECT_EQ(std::count(wheels.begin(), wheels.end(), "free:road.gain"), 1);
  EXPECT_EQ(std::count(wheels.begin(), wheels.end(), "free:road.delay_s"), 1);
  const auto fl = candidateSpec("free:road.fl_only", s, a, kHub, "t");
  EXPECT_EQ(fl.kind, "input");
  EXPECT_DOUBLE_EQ(fl.parameters[0].default_value, 0.0);
  EXPECT_DOUBLE_EQ(fl.parameters[0].prior_lower, -0.5);
  EXPECT_DOUBLE_EQ(fl.parameters[0].prior_upper, 1.5);
  EXPECT_EQ(fl.finding({0.99}, 0.97, 1.01),
            "the road signal behaves as the front-left wheel's road alone: the other three wheels "
            "meet none of it (share 0.99, 95 %: 0.97 to 1.01)");
  EXPECT_EQ(fl.finding({0.5}, 0.45, 0.55),
            "the road signal lies between the road under both axles and the front-left wheel's "
            "road alone (share 0.50, 95 %: 0.45 to 0.55)");
  const auto all = candidateSpec("free:road.all_at_once", s, a, kHub, "t");
  EXPECT_EQ(all.finding({1.0}),
            "the road signal reaches all four wheels at once, the rear without the wheelbase's lag "
            "(share 1.00)");
  calib::CalibrationSetup setup;
  fl.install(setup);
  ASSERT_EQ(setup.extra_calibrated.size(), 1u);
  EXPECT_EQ(setup.extra_calibrated[0].name, "road.fl_only");
  EXPECT_TRUE(setup.freed.empty());  // a run parameter already: no rebuild
}
