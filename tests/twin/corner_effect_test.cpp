// Effects at one corner ("bump_stop@rr", subsystems/effect.hpp splitEffectPlace; docs/model.md,
// "Effects at one corner"): one effect installed at each of the four corners with the same values
// is the effect at all four, bit for bit; at one corner it breaks the left/right symmetry of a
// symmetric run, which the effect at all four keeps; effects that do not act at one corner and
// places that are no corner are one-line input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/study.hpp"
#include "shipped_study.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

const Study& demoStudy() { return dtwin_test::shippedStudy("demo"); }

/// The effect `effect` with `values` ("param" -> value) installed as `as` ("bump_stop@rr").
EffectSetting installed(const std::string& as,
                        const std::vector<std::pair<std::string, double>>& values) {
  EffectSetting e;
  e.name = as;
  for (const auto& [p, v] : values) e.values.push_back({as + "." + p, v, "test: " + as, "test"});
  return e;
}

RunResult runWith(const std::vector<EffectSetting>& effects,
                  const std::string& scenario = "diag_bump") {
  const Study& s = demoStudy();
  const auto model = s.makeModel(s.assembly("M1"), effects);
  Simulator sim(model, s.simulation);
  const auto& sc = s.scenario(scenario);
  const auto road = makeRoad(sc, model->vehicle(), 1);
  RunResult r = sim.run(model->defaultRunValues(), *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r;
}

std::vector<double> channel(const RunResult& r, const std::string& name) {
  for (std::size_t i = 0; i < r.trace.channels().size(); ++i)
    if (r.trace.channels()[i].name == name) return r.trace.column(i);
  ADD_FAILURE() << "no channel " << name;
  return {};
}

double maxDiff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

const std::vector<std::pair<std::string, double>> kBump{{"stiffness", 5e6}, {"gap_m", 0.02}};

}  // namespace

TEST(CornerEffects, AnEffectAtEachCornerIsTheEffectAtAllFourBitForBit) {
  for (const auto& [effect, values] :
       std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>>{
           {"bump_stop", kBump},
           {"strut_friction", {{"force_N", 150}}},
           {"top_mount_compliance", {{"compliance_m_per_N", 3e-6}}}}) {
    SCOPED_TRACE(effect);
    const RunResult all = runWith({installed(effect, values)});
    std::vector<EffectSetting> each;
    for (const char* c : kEffectCorners) each.push_back(installed(effect + "@" + c, values));
    const RunResult four = runWith(each);
    ASSERT_EQ(all.trace.channels().size(), four.trace.channels().size());
    ASSERT_EQ(all.trace.rows(), four.trace.rows());
    for (std::size_t i = 0; i < all.trace.channels().size(); ++i)
      EXPECT_EQ(all.trace.column(i), four.trace.column(i)) << all.trace.channels()[i].name;
  }
}

TEST(CornerEffects, AtOneCornerItBreaksTheLeftRightSymmetryOfASymmetricRun) {
  // diag_bump: the same bump under both tracks, so the base and the effect at all four corners
  // keep left and right alike; a bump stop at the front-left strut alone does not.
  const RunResult all = runWith({installed("bump_stop", kBump)});
  const RunResult fl = runWith({installed("bump_stop@fl", kBump)});
  EXPECT_LT(maxDiff(channel(all, "susp_defl_fl_m"), channel(all, "susp_defl_fr_m")), 1e-9);
  EXPECT_LT(maxDiff(channel(all, "chassis_roll_rad"), std::vector<double>(all.trace.rows(), 0.0)),
            1e-9);
  const double fl_fr = maxDiff(channel(fl, "susp_defl_fl_m"), channel(fl, "susp_defl_fr_m"));
  EXPECT_GT(fl_fr, 1e-3);  // the stop holds the front-left strut back over the bump
  EXPECT_GT(maxDiff(channel(fl, "chassis_roll_rad"), std::vector<double>(fl.trace.rows(), 0.0)),
            1e-4);
  // Where the stop acts, the front-left strut compresses less than at the front right.
  const auto qfl = channel(fl, "susp_defl_fl_m"), qfr = channel(fl, "susp_defl_fr_m");
  double most_fl = -1, most_fr = -1;
  for (std::size_t i = 0; i < qfl.size(); ++i) {
    most_fl = std::max(most_fl, qfl[i]);
    most_fr = std::max(most_fr, qfr[i]);
  }
  EXPECT_LT(most_fl, most_fr);
  EXPECT_GT(most_fr, 0.02);  // beyond the gap at the front right, where no stop acts
}

TEST(CornerEffects, EffectsThatDoNotActAtOneCornerAndUnknownPlacesAreRefused) {
  const Study& s = demoStudy();
  for (const char* bad : {"anti_roll_bar@fl", "bump_stop@xx", "bump_stop@front"}) {
    SCOPED_TRACE(bad);
    try {
      (void)s.makeModel(s.assembly("M1"), {installed(bad, {})});
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(bad), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
  EXPECT_TRUE(s.effectCatalog().contains("bump_stop@rr"));
  EXPECT_FALSE(s.effectCatalog().contains("anti_roll_bar@rr"));
  EXPECT_FALSE(s.effectCatalog().contains("bump_stop@xx"));
}
