// Frozen step sequences (twin/simulator.hpp StepPlan, StepControl): a run records the steps the
// Rosenbrock integrator chose, and a replay of them takes exactly those steps, so every output is
// a smooth function of the run parameters (docs/calibration.md, "A smooth objective").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "calibration/calibrate.hpp"
#include "common/errors.hpp"
#include "io/study.hpp"
#include "shipped_study.hpp"
#include "study/generate.hpp"
#include "twin/roads/iso8608.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

const Study& demo() { return dtwin_test::shippedStudy("demo"); }

struct Lab {
  AssemblySpec assembly = demo().assembly("M1");
  std::shared_ptr<const Model> model = demo().makeModel(assembly);
  ScenarioSpec scenario = demo().scenario("lab");
  std::shared_ptr<const Road> road = makeRoad(scenario, model->vehicle(), demo().seed);
  std::size_t slot(const std::string& name) const {
    const auto& names = model->runParameterNames();
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  }
};

/// The largest residual of the least-squares quadratic through f at x = -m..m, in units of f's
/// range.
double relativeRoughness(const std::vector<double>& f) {
  std::vector<double> x;
  for (std::size_t i = 0; i < f.size(); ++i)
    x.push_back(static_cast<double>(i) - 0.5 * static_cast<double>(f.size() - 1));
  const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
  return calib::quadraticRoughness(x, f) / std::max(*hi - *lo, 1e-300);
}

/// A run of `values` that records its steps in `plan`.
RunResult recordedRun(Simulator& sim, const Lab& s, const std::vector<double>& values,
                      StepPlan& plan) {
  StepControl record;
  record.record = &plan;
  return sim.run(values, *s.road, s.scenario, record);
}

}  // namespace

// Replaying the steps a run chose, at the same parameters, gives that run again: the same knots
// and so the same output, to rounding (a replayed step's size is t_next - t, which may differ
// from the chosen h in its last bit).
TEST(StepPlan, ReplayAtTheSameParametersReproducesTheRun) {
  Lab s;
  Simulator sim(s.model, demo().simulation);
  const auto values = s.model->defaultRunValues();
  StepPlan plan;
  const RunResult a = recordedRun(sim, s, values, plan);
  ASSERT_TRUE(a.stats.ok) << a.stats.message;
  ASSERT_EQ(static_cast<long>(plan.size()), a.stats.steps);
  ASSERT_EQ(plan.times.size(), plan.new_jacobian.size());
  EXPECT_TRUE(std::is_sorted(plan.times.begin(), plan.times.end()));
  EXPECT_EQ(plan.new_jacobian.front(), 1);  // the first step needs a Jacobian
  EXPECT_NEAR(plan.times.back(), s.scenario.duration_s, 1e-12);
  StepControl replay;
  replay.replay = &plan;
  const RunResult b = sim.run(values, *s.road, s.scenario, replay);
  ASSERT_TRUE(b.stats.ok) << b.stats.message;
  EXPECT_EQ(b.stats.steps, a.stats.steps);
  EXPECT_EQ(b.stats.steps_attempted, a.stats.steps);  // no rejections in a replay
  const auto& fa = a.trace.column("hub_force_fl_N");
  const auto& fb = b.trace.column("hub_force_fl_N");
  ASSERT_EQ(fa.size(), fb.size());
  double worst = 0, peak = 0;
  for (std::size_t i = 0; i < fa.size(); ++i) {
    worst = std::max(worst, std::abs(fa[i] - fb[i]));
    peak = std::max(peak, std::abs(fa[i]));
  }
  EXPECT_LT(worst, 1e-6 * peak) << "largest difference " << worst << " N";
}

// The point of frozen steps: along a line in θ the output is smooth. The tire stiffness moves in
// 11 steps of 0.2 % around its default; the front-left hub force at the bump's peak time is read
// from adaptive runs and from runs that replay the default's steps. The replayed outputs lie on
// a quadratic to 1e-6 of their range; the adaptive ones jump (printed, not asserted: whether the
// steps change along one particular line is up to the error control).
TEST(StepPlan, AReplayedRunIsASmoothFunctionOfTheParameters) {
  Lab s;
  Simulator sim(s.model, demo().simulation);
  auto values = s.model->defaultRunValues();
  const std::size_t k = s.slot("tire.stiffness");
  ASSERT_LT(k, values.size());
  StepPlan plan;
  const RunResult base = recordedRun(sim, s, values, plan);
  ASSERT_TRUE(base.stats.ok);
  const auto& f0 = base.trace.column("hub_force_fl_N");
  const std::size_t peak =
      static_cast<std::size_t>(std::max_element(f0.begin(), f0.end()) - f0.begin());
  std::vector<double> frozen, adaptive;
  const double k0 = values[k];
  for (int i = -5; i <= 5; ++i) {
    values[k] = k0 * (1 + 2e-3 * i);
    StepControl replay;
    replay.replay = &plan;
    const RunResult r = sim.run(values, *s.road, s.scenario, replay);
    const RunResult a = sim.run(values, *s.road, s.scenario);
    ASSERT_TRUE(r.stats.ok && a.stats.ok);
    frozen.push_back(r.trace.column("hub_force_fl_N")[peak]);
    adaptive.push_back(a.trace.column("hub_force_fl_N")[peak]);
  }
  const double rf = relativeRoughness(frozen), ra = relativeRoughness(adaptive);
  std::printf(
      "[ figures  ] peak hub force along the tire stiffness: departure from a quadratic, in units "
      "of its range: "
      "frozen steps %.3g, adaptive steps %.3g\n",
      rf, ra);
  EXPECT_LT(rf, 1e-6);
}

// A plan recorded on another scenario does not fit: the run fails and says why; and a plan needs
// the rosenbrock integrator.
TEST(StepPlan, APlanThatDoesNotFitFailsTheRunWithAReason) {
  Lab s;
  Simulator sim(s.model, demo().simulation);
  const auto values = s.model->defaultRunValues();
  StepPlan plan;
  ASSERT_TRUE(recordedRun(sim, s, values, plan).stats.ok);
  StepPlan short_plan = plan;
  short_plan.times.resize(plan.size() / 2);
  short_plan.new_jacobian.resize(plan.size() / 2);
  StepControl replay;
  replay.replay = &short_plan;
  const RunResult r = sim.run(values, *s.road, s.scenario, replay);
  EXPECT_FALSE(r.stats.ok);
  EXPECT_NE(r.stats.message.find("frozen step sequence does not fit"), std::string::npos)
      << r.stats.message;

  SimulationOptions merson = demo().simulation;
  merson.integrator = "rk-merson";
  Simulator other(s.model, merson);
  replay.replay = &plan;
  EXPECT_THROW(other.run(values, *s.road, s.scenario, replay), InputError);
}

// The objective with frozen steps: the same SSE at the θ it was frozen at as an adaptive run
// (within the replay's rounding), the same SSE twice, and back to adaptive when thawed.
TEST(StepPlan, TheObjectiveFreezesAndThawsItsSteps) {
  const Study& st = demo();
  Lab s;
  LabOptions lo;
  lo.repetitions = 2;
  const LabData lab = generateLab(st, s.assembly, lo).data;
  calib::LabObjective obj(st, s.assembly, lab, "lab");
  std::vector<double> theta;
  for (const auto& c : st.calibrated) theta.push_back(0.5 * (c.lower + c.upper));
  const double adaptive = obj.sse(theta);
  ASSERT_TRUE(obj.freezeSteps(theta));
  EXPECT_TRUE(obj.stepsFrozen());
  EXPECT_EQ(obj.stepsFrozenAt(), theta);
  ASSERT_EQ(obj.frozenStepCounts().size(), 1u);
  EXPECT_GT(obj.frozenStepCounts()[0], 10u);
  const double frozen = obj.sse(theta);
  EXPECT_NEAR(frozen, adaptive, 1e-9 * adaptive);
  EXPECT_EQ(obj.sse(theta), frozen);
  obj.thawSteps();
  EXPECT_FALSE(obj.stepsFrozen());
  EXPECT_EQ(obj.sse(theta), adaptive);
}
