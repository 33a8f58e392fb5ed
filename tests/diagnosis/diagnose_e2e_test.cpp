// NOT REGISTERED IN tests/CMakeLists.txt YET: this is issue 5's acceptance test and it does not
// pass yet (session 3: with seed 3 the bump stop is named but its stiffness is off by more than
// 20 %, and with seed 4 the null case names an effect). Register it (LABEL slow) once it passes.
// The diagnosis loop end to end on the real twin (slow): data with a hidden effect on two
// scenarios (diag_bump, diag_rough), `diagnose` from the base assembly M1 names it, recovers its
// main parameter within 20 %, and adding it cuts the systematic residual RMS by >= 50 %; data
// without a hidden effect give "none"; data with an effect outside the catalogue given to the
// diagnosis give "unexplained", not a misnamed effect (not yet covered here: see docs/diagnosis.md).
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <cmath>
#include <filesystem>

#include "diagnosis/diagnose.hpp"
#include "twin/generate.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::diag;

namespace {

struct Case {
  std::string hidden;  ///< "effect:param=value,..." or "" (null case)
  std::string main_parameter;
  double main_value;
};

std::vector<calib::DataSet> makeData(const Study& s, const std::string& hidden, std::uint64_t seed) {
  std::vector<calib::DataSet> sets;
  for (const std::string sc : {"diag_bump", "diag_rough"}) {
    LabOptions o;
    o.scenario = sc;
    o.times_mode = LabTimesMode::All;
    o.rate_hz = 200.0;
    o.repetitions = 3;
    o.seed = seed;
    o.channels = {"hub_force_fl_N", "hub_force_fr_N", "hub_force_rl_N", "hub_force_rr_N"};
    if (!hidden.empty()) o.hidden_effects.push_back(parseEffectSetting(hidden, "test"));
    const auto lab = generateLab(s, s.assemblies().front(), o);
    sets.push_back({sc + ".csv", sc, lab.data, seed});  // the rough road was made with `seed`
  }
  return sets;
}

DiagnoseOptions smallOptions(const Study& s) {
  DiagnoseOptions o;
  o.calibration = calib::CalibrationOptions::fromStudy(s);
  o.calibration.lhs_points = 40;
  o.calibration.gibbs_iterations = 3000;
  o.calibration.gibbs_burn_in = 1000;
  o.calibration.optimizer_starts = 2;
  o.candidates = 2;
  o.compare_draws = 10;
  return o;
}

Study study() {
  static const fs::path p = dtwin_test::writeDemoStudy(fs::temp_directory_path() / "diag_study.toml",
                                                        "lab_repetitions = 3\noptimizer_starts = 2\n");
  return loadStudy(p.string());
}

}  // namespace

class HiddenEffect : public ::testing::TestWithParam<Case> {};

TEST_P(HiddenEffect, IsNamedRecoveredAndAddingItCutsTheError) {
  const Case c = GetParam();
  const Study s = study();
  const std::string effect = c.hidden.substr(0, c.hidden.find(':'));
  auto o = smallOptions(s);
  o.apply = {effect};
  const auto out = fs::temp_directory_path() / ("diag_" + effect);
  const auto r = diagnose(s, s.assemblies().front(), makeData(s, c.hidden, 3), {}, o, out.string());
  ASSERT_EQ(r.verdict, "effect") << r.text();
  EXPECT_EQ(r.named_effect, effect) << r.text();
  const Candidate* named = nullptr;
  for (const auto& k : r.candidates)
    if (k.effect == effect) named = &k;
  ASSERT_NE(named, nullptr);
  ASSERT_TRUE(named->fit);
  double estimate = std::nan("");
  for (const auto& p : named->fit->effect_parameters)
    if (p.name == effect + "." + c.main_parameter) estimate = p.mean;
  EXPECT_NEAR(estimate / c.main_value, 1.0, 0.2) << r.text();
  ASSERT_EQ(r.steps.size(), 2u);
  const double before = r.steps[0].comparison.systematic_rms_sd, after = r.steps[1].comparison.systematic_rms_sd;
  EXPECT_LE(after, 0.5 * before) << "systematic RMS " << before << " -> " << after;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, HiddenEffect,
                         ::testing::Values(Case{"bump_stop:stiffness=5e6,gap_m=0.02", "stiffness", 5e6}),
                         [](const auto& info) { return info.param.hidden.substr(0, info.param.hidden.find(':')); });

TEST(Diagnose, NoHiddenEffectGivesNone) {
  const Study s = study();
  const auto r = diagnose(s, s.assemblies().front(), makeData(s, "", 4), {}, smallOptions(s),
                          (fs::temp_directory_path() / "diag_null").string());
  EXPECT_EQ(r.verdict, "none") << r.text();
  EXPECT_TRUE(r.named_effect.empty());
}
