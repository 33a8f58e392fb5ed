// Where the road signal enters (twin/model.hpp roadSignalForms; docs/model.md, "Where the road
// signal is"): each form's share moves a run from the axle form (the signal under the front
// wheels, the rear a wheelbase later) to the form, corner by corner. Known answers from the base
// run's own road channels: at share 1 a corner the form leaves out meets no road, a corner it
// keeps meets the base's road bit for bit, a rear corner read without the lag meets the front
// road of the same moment; at share 1/2 a left-out corner meets half the road; at share 0 the run
// is the base run, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "io/study.hpp"
#include "shipped_study.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

const Study& demoStudy() { return dtwin_test::shippedStudy("demo"); }

RunResult runWith(const std::vector<std::pair<std::string, double>>& set,
                  const std::string& scenario) {
  const Study& s = demoStudy();
  const auto model = s.makeModel(s.assembly("M1"), {});
  Simulator sim(model, s.simulation);
  const auto& sc = s.scenario(scenario);
  const auto road = makeRoad(sc, model->vehicle(), 1);
  auto values = model->defaultRunValues();
  const auto& names = model->runParameterNames();
  for (const auto& [n, v] : set) {
    const auto it = std::find(names.begin(), names.end(), n);
    EXPECT_NE(it, names.end()) << n;
    if (it != names.end()) values[static_cast<std::size_t>(it - names.begin())] = v;
  }
  RunResult r = sim.run(values, *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r;
}

std::vector<double> channel(const RunResult& r, const std::string& name) {
  for (std::size_t i = 0; i < r.trace.channels().size(); ++i)
    if (r.trace.channels()[i].name == name) return r.trace.column(i);
  ADD_FAILURE() << "no channel " << name;
  return {};
}

double maxAbs(const std::vector<double>& a) {
  double m = 0;
  for (double x : a) m = std::max(m, std::fabs(x));
  return m;
}

double maxDiff(const std::vector<double>& a, const std::vector<double>& b, double scale = 1.0) {
  double m = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    m = std::max(m, std::fabs(a[i] - scale * b[i]));
  return m;
}

/// a is b (within 3 % of b's largest height: the wheel centre's place moves with the body).
void expectSameRoad(const std::vector<double>& a, const std::vector<double>& b,
                    const std::string& what, double scale = 1.0) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_LT(maxDiff(a, b, scale), 0.03 * scale * maxAbs(b)) << what;
}

const char* const kRoad[] = {"road_fl_m", "road_fr_m", "road_rl_m", "road_rr_m"};

}  // namespace

TEST(RoadSignalForms, EveryFormIsARunParameterAtZero) {
  const Study& s = demoStudy();
  const auto model = s.makeModel(s.assembly("M1"), {});
  const auto& names = model->runParameterNames();
  const auto values = model->defaultRunValues();
  ASSERT_GE(model->roadFormSlot(), 0);
  for (std::size_t f = 0; f < roadSignalForms().size(); ++f) {
    const std::size_t slot = static_cast<std::size_t>(model->roadFormSlot()) + f;
    EXPECT_EQ(names[slot], roadSignalForms()[f].name);
    EXPECT_EQ(values[slot], 0.0);
  }
}

TEST(RoadSignalForms, OneCornerAloneMeetsTheBaseRoadAndTheOthersNone) {
  // diag_rough: independent tracks, so every corner's road differs.
  const RunResult base = runWith({}, "diag_rough");
  ASSERT_GT(maxAbs(channel(base, "road_fr_m")), 1e-3);
  const RunResult fl = runWith({{"road.fl_only", 1.0}}, "diag_rough");
  expectSameRoad(channel(fl, "road_fl_m"), channel(base, "road_fl_m"), "fl");
  for (int c = 1; c < 4; ++c) EXPECT_EQ(maxAbs(channel(fl, kRoad[c])), 0.0) << kRoad[c];
  // The body moves otherwise: the run is not the base run.
  EXPECT_GT(maxDiff(channel(fl, "chassis_roll_rad"), channel(base, "chassis_roll_rad")), 1e-4);
  // Half-way: the left-out corners meet half the road.
  const RunResult half = runWith({{"road.fl_only", 0.5}}, "diag_rough");
  expectSameRoad(channel(half, "road_fl_m"), channel(base, "road_fl_m"), "fl");
  for (int c = 1; c < 4; ++c)
    expectSameRoad(channel(half, kRoad[c]), channel(base, kRoad[c]), kRoad[c], 0.5);
}

TEST(RoadSignalForms, OneTrackKeepsItsRearWheelsLag) {
  const RunResult base = runWith({}, "diag_rough");
  const RunResult left = runWith({{"road.left_only", 1.0}}, "diag_rough");
  expectSameRoad(channel(left, "road_fl_m"), channel(base, "road_fl_m"), "fl");
  expectSameRoad(channel(left, "road_rl_m"), channel(base, "road_rl_m"), "rl");
  EXPECT_EQ(maxAbs(channel(left, "road_fr_m")), 0.0);
  EXPECT_EQ(maxAbs(channel(left, "road_rr_m")), 0.0);
}

TEST(RoadSignalForms, ARearCornerOrAllFourReadTheSignalWithoutTheWheelbasesLag) {
  // diag_bump at a constant 4 m/s: the same bump under both tracks. In the base run the rear
  // wheels meet it a wheelbase later; read without the lag they meet it with the front ones.
  const RunResult base = runWith({}, "diag_bump");
  const auto fl = channel(base, "road_fl_m"), rl = channel(base, "road_rl_m");
  ASSERT_GT(maxDiff(fl, rl), 1e-2);
  const RunResult all = runWith({{"road.all_at_once", 1.0}}, "diag_bump");
  for (int c = 0; c < 4; ++c) expectSameRoad(channel(all, kRoad[c]), fl, kRoad[c]);
  const RunResult rl_only = runWith({{"road.rl_only", 1.0}}, "diag_bump");
  expectSameRoad(channel(rl_only, "road_rl_m"), fl, "rl");
  for (const char* c : {"road_fl_m", "road_fr_m", "road_rr_m"})
    EXPECT_EQ(maxAbs(channel(rl_only, c)), 0.0) << c;
  // The bump at the rear alone pitches the body the other way from the bump at the front alone.
  const RunResult fl_only = runWith({{"road.fl_only", 1.0}}, "diag_bump");
  const auto pf = channel(fl_only, "chassis_pitch_rad"), pr = channel(rl_only, "chassis_pitch_rad");
  double extreme_f = 0, extreme_r = 0;
  for (std::size_t i = 0; i < pf.size(); ++i) {
    if (std::fabs(pf[i]) > std::fabs(extreme_f)) extreme_f = pf[i];
    if (std::fabs(pr[i]) > std::fabs(extreme_r)) extreme_r = pr[i];
  }
  EXPECT_LT(extreme_f * extreme_r, 0.0) << extreme_f << " " << extreme_r;
}

TEST(RoadSignalForms, AFormBeyondItsValidRangeIsRefused) {
  const Study& s = demoStudy();
  const auto model = s.makeModel(s.assembly("M1"), {});
  auto values = model->defaultRunValues();
  values[static_cast<std::size_t>(model->roadFormSlot())] = 3.0;
  const std::string rule = model->checkRunValues(values);
  EXPECT_NE(rule.find("road.fl_only"), std::string::npos) << rule;
}
