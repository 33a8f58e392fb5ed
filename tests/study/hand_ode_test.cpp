// The hand-written 7-DOF ODE of M3 and its generic ROS34PW2 stepper (study/hand_ode.hpp,
// `twin bench --hand-ode`): the stepper against closed forms, the ODE at rest against the static
// loads, and the ODE on the bump against the Simbody twin. No timing here (that is the bench's).
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "io/study.hpp"
#include "study/hand_ode.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

const Study& demoStudy() {
  static const Study s = [] {
    const auto dir = dtwin_test::freshDir("hand_ode_test");
    return loadStudy(
        dtwin_test::writeDemoStudy(dir / "study.toml", "lab_repetitions = 2\n").string());
  }();
  return s;
}

/// 1 + 4 per accepted step + 3 per rejected one + n per Jacobian: the cost model both integrators
/// state (twin/rosenbrock.hpp), which `twin bench --hand-ode` uses to count the Simbody run's.
void expectCostModel(const Ros34pw2Stepper& st, long n) {
  EXPECT_EQ(st.evaluations(),
            1 + 4 * st.steps() + 3 * (st.attempts() - st.steps()) + n * st.jacobians());
}

}  // namespace

// y' = -k y with k = 1e4: stiff (an explicit method would need steps below 2.8e-4 s for 10 s, some
// 36 000). L-stable ROS34PW2 follows the transient and then takes the largest steps allowed.
TEST(HandOdeStepper, StiffDecayMatchesTheClosedForm) {
  const double k = 1e4, acc = 1e-6;
  RosenbrockOptions o;
  o.accuracy = acc;
  o.max_step_s = 1.0;
  Ros34pw2Stepper st([k](double, const Eigen::VectorXd& y, Eigen::VectorXd& yd) { yd = -k * y; },
                     o);
  st.initialize(0.0, Eigen::VectorXd::Constant(1, 1.0));
  double worst = 0;
  for (double t_out : {1e-4, 2e-4, 5e-4, 1e-3, 1e-2, 1.0, 10.0}) {
    while (st.time() < t_out) st.step(t_out);
    worst = std::max(worst, std::abs(st.state()[0] - std::exp(-k * t_out)));
  }
  std::printf("y' = -1e4 y to 10 s: %ld steps (%ld attempts), worst error %.2e (accuracy %.0e)\n",
              st.steps(), st.attempts(), worst, acc);
  // The absolute tolerance is accuracy x 1 (unit 1): the global error stays within it.
  EXPECT_LT(worst, acc);
  EXPECT_LT(st.steps(), 200);
  expectCostModel(st, 1);
}

// x'' = -w^2 x, x(0) = 1, five periods at accuracy 1e-6. The accuracy bounds the error of each
// step; on an oscillator those errors (mostly phase) add up, by 3.8e-6 per period (236 steps)
// here, linearly: the check is 5x the accuracy per period elapsed.
TEST(HandOdeStepper, HarmonicOscillatorMatchesTheClosedForm) {
  const double w = 2 * 3.141592653589793, acc = 1e-6;
  RosenbrockOptions o;
  o.accuracy = acc;
  Ros34pw2Stepper st(
      [w](double, const Eigen::VectorXd& y, Eigen::VectorXd& yd) {
        yd.resize(2);
        yd << y[1], -w * w * y[0];
      },
      o);
  Eigen::VectorXd y0(2);
  y0 << 1.0, 0.0;
  st.initialize(0.0, y0);
  double worst = 0;
  for (int k = 1; k <= 50; ++k) {
    const double t_out = 0.1 * k;
    while (st.time() < t_out) st.step(t_out);
    worst = std::max(worst, std::abs(st.state()[0] - std::cos(w * t_out)));
    worst = std::max(worst, std::abs(st.state()[1] / w + std::sin(w * t_out)));
    EXPECT_LT(worst, 5 * acc * std::ceil(t_out - 1e-9)) << "at t = " << t_out;
  }
  std::printf("harmonic oscillator, 5 periods: %ld steps, worst error %.2e (accuracy %.0e)\n",
              st.steps(), worst, acc);
  EXPECT_GT(st.steps(), 50);  // error-controlled, not the maximum step
  expectCostModel(st, 2);
}

// At rest on a flat road the ODE starts and stays at its static equilibrium, whose closed form is
// the model's: each tire carries Model::staticTireLoad (the Fiala law is linear: its deflection
// is load / k), each strut its preload Model::staticStrutForce at zero travel. The start is the
// simulator's: the front and rear static deflections differ, so the chassis is pitched by
// -4.6e-5 rad and the struts (along the chassis z) lean by as much; what that leaves unbalanced
// is an acceleration of ~1e-4 (m/s^2, rad/s^2), and the loads settle within 0.04 N of the static
// ones (1e-5 of them).
TEST(HandOde, AtRestOnAFlatRoadStaysAtTheStaticEquilibrium) {
  const Study& s = demoStudy();
  const auto model = s.makeModel(s.assembly("M3"));
  const auto values = model->defaultRunValues();
  const FlatRoad road;
  ScenarioSpec sc;
  sc.name = "rest";
  sc.duration_s = 5.0;
  sc.speed.v_final_mps = 0.0;
  sc.speed.ramp_s = 0.0;
  const HandOde ode(*model, values, road, sc.speed);
  const Eigen::VectorXd y = ode.equilibrium();
  Eigen::VectorXd yd(HandOde::kStates);
  ode.rhs(0.0, y, yd);
  const double k = model->table().value("tire.stiffness"),
               R0 = model->table().value("tire.unloaded_radius_m");
  for (int c = 0; c < 4; ++c) {
    SCOPED_TRACE(kCornerNames[static_cast<std::size_t>(c)]);
    const HandOde::Hub h = ode.hub(c, y, yd);
    EXPECT_NEAR(h.z, R0 - model->staticTireLoad(c) / k, 1e-9);
    EXPECT_NEAR(ode.tireForce(c, 0.0, h.x, h.z, h.zd), model->staticTireLoad(c), 1e-6);
    EXPECT_DOUBLE_EQ(ode.strutForce(c, y[3 + c], y[10 + c]), model->staticStrutForce(c));
  }
  std::printf("equilibrium: z %.6f m, roll %.3e, pitch %.3e rad; largest acceleration %.3e\n", y[0],
              y[1], y[2], yd.tail<HandOde::kDof>().cwiseAbs().maxCoeff());
  EXPECT_LT(yd.tail<HandOde::kDof>().cwiseAbs().maxCoeff(),
            1e-3);  // accelerations [m/s^2, rad/s^2]
  SimulationOptions o = s.simulation;
  o.accuracy = 1e-8;
  const HandOdeRun run = runHandOde(*model, values, road, sc, o);
  double worst = 0;
  for (std::size_t c = 0; c < 4; ++c)
    for (double f : run.hub_force_N[c])
      worst = std::max(worst, std::abs(f - model->staticTireLoad(static_cast<int>(c))));
  std::printf("5 s at rest: worst hub force off its static load %.2e N (%ld steps)\n", worst,
              run.steps);
  EXPECT_LT(worst, 0.1);
}

// The same vehicle on the study's bump, both integrated by ROS34PW2 at the study's accuracy: the
// front-left hub force of the hand ODE follows the Simbody twin's within 0.1 % of its peak. The
// two are the same equations (full rotations, no simplification), so the step sequences agree as
// well; what differs is the order of floating-point operations.
TEST(HandOde, BumpHubForceAgreesWithTheSimbodyTwin) {
  const Study& s = demoStudy();
  const auto model = s.makeModel(s.assembly("M3"));
  const ScenarioSpec& sc = s.scenario("lab");
  const auto road = makeRoad(sc, model->vehicle(), s.seed);
  const auto values = model->defaultRunValues();
  const RunResult ref = Simulator(model, s.simulation).run(values, *road, sc);
  ASSERT_TRUE(ref.stats.ok) << ref.stats.message;
  const HandOdeRun hand = runHandOde(*model, values, *road, sc, s.simulation);
  const auto& fs = ref.trace.column("hub_force_fl_N");
  ASSERT_EQ(fs.size(), hand.time_s.size());
  double peak = 0, worst = 0, at = 0;
  for (std::size_t i = 0; i < fs.size(); ++i) {
    peak = std::max(peak, fs[i]);
    if (std::abs(fs[i] - hand.hub_force_N[0][i]) > worst) {
      worst = std::abs(fs[i] - hand.hub_force_N[0][i]);
      at = hand.time_s[i];
    }
  }
  std::printf("bump: peak %.0f N, max |Simbody - hand| %.3g N at %.3f s; steps %ld / %ld\n", peak,
              worst, at, ref.stats.steps, hand.steps);
  EXPECT_GT(peak, 10000.0);  // the bump was hit
  EXPECT_LT(worst, 1e-3 * peak);
  EXPECT_NEAR(static_cast<double>(hand.steps), static_cast<double>(ref.stats.steps),
              0.05 * static_cast<double>(ref.stats.steps));
}

TEST(HandOde, RefusesWhatItDoesNotModel) {
  const Study& s = demoStudy();
  const FlatRoad road;
  const auto solid = s.makeModel(s.assembly("M4"));  // fiala + solid axle
  EXPECT_THROW(HandOde(*solid, solid->defaultRunValues(), road, SpeedProfile{}), InputError);
}
