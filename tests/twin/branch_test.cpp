// Simulator::runBranched: the smooth start of a random-road scenario is integrated once and each
// road continues from the saved State (docs/method.md §5).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "io/study.hpp"
#include "shipped_study.hpp"
#include "twin/roads/iso8608.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

const Study& demo() { return dtwin_test::shippedStudy("demo"); }

double rmsDiff(const std::vector<double>& t, const std::vector<double>& a,
               const std::vector<double>& b, double lo, double hi) {
  double s = 0;
  long n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= lo - 1e-12 && t[i] <= hi + 1e-12) {
      s += (a[i] - b[i]) * (a[i] - b[i]);
      ++n;
    }
  return std::sqrt(s / static_cast<double>(n));
}

struct RoadSet {
  AssemblySpec assembly;
  std::shared_ptr<const Model> model;
  ScenarioSpec scenario = demo().scenario("field");
  std::vector<std::shared_ptr<const Road>> roads;
  std::vector<const Road*> ptrs;
  explicit RoadSet(const std::string& id)
      : assembly(demo().assembly(id)), model(demo().makeModel(assembly)) {
    for (std::uint64_t seed : {11ULL, 2024ULL, 777777ULL}) {
      roads.push_back(makeRoad(scenario, model->vehicle(), seed));
      ptrs.push_back(roads.back().get());
    }
  }
};
}  // namespace

// The accuracy claim of runBranched: each branch equals an unbranched run on the same road within
// the integrator's accuracy. Tolerance: 20 N RMS on hub_force_fl_N over the 10-15 s field window,
// against a measurement noise sigma of 134 N (sqrt(18000 N^2)). Rows up to the branch time are
// bit-identical (same knots, same road there).
TEST(Branch, EachBranchAgreesWithAnUnbranchedRun) {
  for (const char* id : {"M3", "M4"}) {
    SCOPED_TRACE(id);
    RoadSet s(id);
    Simulator sim(s.model, demo().simulation);
    const double tb = sim.branchTime(s.scenario);
    ASSERT_NEAR(tb, s.scenario.road->roughStart_s() - demo().simulation.obstacle_margin_before_s,
                1e-15);
    const auto values = s.model->defaultRunValues();
    const auto t0 = std::chrono::steady_clock::now();
    const auto branched = sim.runBranched(values, s.ptrs, s.scenario);
    const double wall_branched =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(branched.size(), s.ptrs.size());
    double wall_plain = 0;
    for (std::size_t r = 0; r < s.ptrs.size(); ++r) {
      SCOPED_TRACE("road " + std::to_string(r));
      const auto t1 = std::chrono::steady_clock::now();
      const RunResult plain = sim.run(values, *s.ptrs[r], s.scenario);
      wall_plain += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      const RunResult& b = branched[r];
      ASSERT_TRUE(plain.stats.ok) << plain.stats.message;
      ASSERT_TRUE(b.stats.ok) << b.stats.message;
      ASSERT_EQ(b.trace.rows(), plain.trace.rows());
      EXPECT_DOUBLE_EQ(b.stats.sim_s, plain.stats.sim_s);
      const auto& t = b.trace.column("time_s");
      // Before the branch: every channel bit-identical to the unbranched run.
      for (std::size_t c = 0; c < b.trace.channels().size(); ++c)
        for (std::size_t i = 0; i < t.size() && t[i] <= tb; ++i)
          ASSERT_EQ(b.trace.column(c)[i], plain.trace.column(c)[i])
              << b.trace.channels()[c].name << " t = " << t[i];
      const double rms = rmsDiff(t, b.trace.column("hub_force_fl_N"),
                                 plain.trace.column("hub_force_fl_N"), 10.0, 15.0);
      std::printf(
          "%s road %zu: branched vs unbranched hub_force_fl_N RMS difference over 10-15 s: %.3g "
          "N\n",
          id, r, rms);
      EXPECT_LT(rms, 20.0);
      // The branch really followed its own road: the rough part differs from road 0's.
      if (r > 0) {
        EXPECT_GT(rmsDiff(t, b.trace.column("hub_force_fl_N"),
                          branched[0].trace.column("hub_force_fl_N"), 10.0, 15.0),
                  200.0);
      }
    }
    std::printf("%s: %zu roads branched %.3f s, unbranched %.3f s\n", id, s.ptrs.size(),
                wall_branched, wall_plain);
  }
}

TEST(Branch, OutputsBeforeTheBranchTimeAreIdenticalAcrossRoads) {
  RoadSet s("M3");
  Simulator sim(s.model, demo().simulation);
  const double tb = sim.branchTime(s.scenario);
  const auto res = sim.runBranched(s.model->defaultRunValues(), s.ptrs, s.scenario);
  const auto& t = res[0].trace.column("time_s");
  std::size_t rows_before = 0;
  for (std::size_t r = 1; r < res.size(); ++r)
    for (std::size_t c = 0; c < res[0].trace.channels().size(); ++c)
      for (std::size_t i = 0; i < t.size() && t[i] <= tb; ++i) {
        ASSERT_EQ(res[r].trace.column(c)[i], res[0].trace.column(c)[i])
            << res[0].trace.channels()[c].name << " t = " << t[i];
        rows_before = std::max(rows_before, i + 1);
      }
  EXPECT_EQ(rows_before, static_cast<std::size_t>(std::floor(tb * 1000.0 + 1e-9)) + 1);
}

TEST(Branch, DeterministicOnRerunAndIndependentOfTheOtherRoads) {
  RoadSet s("M3");
  Simulator sim(s.model, demo().simulation);
  const auto values = s.model->defaultRunValues();
  const auto a = sim.runBranched(values, s.ptrs, s.scenario);
  const auto b = sim.runBranched(values, s.ptrs, s.scenario);
  // Road 2 alone, on a fresh simulator: the same as within the group.
  Simulator sim2(s.model, demo().simulation);
  const auto c = sim2.runBranched(values, {s.ptrs[2]}, s.scenario);
  for (std::size_t r = 0; r < a.size(); ++r)
    for (std::size_t k = 0; k < a[r].trace.channels().size(); ++k)
      ASSERT_EQ(a[r].trace.column(k), b[r].trace.column(k));
  for (std::size_t k = 0; k < a[2].trace.channels().size(); ++k)
    ASSERT_EQ(a[2].trace.column(k), c[0].trace.column(k));
  EXPECT_EQ(a[2].stats.steps, c[0].stats.steps);
}

TEST(Branch, RefusesScenariosWithoutASmoothStart) {
  RoadSet s("M3");
  Simulator sim(s.model, demo().simulation);
  const auto values = s.model->defaultRunValues();
  const ScenarioSpec lab = demo().scenario("lab");
  auto bump = makeRoad(lab, s.model->vehicle(), 1);
  EXPECT_LT(sim.branchTime(lab), 0.0);
  EXPECT_THROW(sim.runBranched(values, {bump.get()}, lab), InputError);
  ScenarioSpec rough = s.scenario;
  auto rough_from_start =
      std::make_shared<IsoRoadSetting>(dynamic_cast<const IsoRoadSetting&>(*rough.road));
  rough_from_start->smooth_until_s = 0.0;
  rough.road = rough_from_start;
  auto r0 = makeRoad(rough, s.model->vehicle(), 1);
  EXPECT_THROW(sim.runBranched(values, {r0.get()}, rough), InputError);
  EXPECT_THROW(sim.runBranched(values, {}, s.scenario), InputError);
  // A road that differs before the branch point (here: a fully rough road) is refused.
  EXPECT_THROW(sim.runBranched(values, {s.ptrs[0], r0.get()}, s.scenario), InputError);
}
