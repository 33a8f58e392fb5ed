// RosenbrockIntegrator (ROS34PW2 Rosenbrock-W) on small Simbody systems with closed-form answers:
// the tableau's W-method order conditions, a damped oscillator against its analytic solution
// (including a stiff, heavily damped case where it must need far fewer steps than RK-Merson),
// the measured order of convergence (also with a frozen Jacobian and time-dependent forcing:
// the W property), Euler-angle kinematics (qdot = N(q) u), step bounds, and failures.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <vector>

#include <Simbody.h>

#include "twin/rosenbrock.hpp"

using namespace SimTK;
using dtwin::RosenbrockIntegrator;
using dtwin::RosenbrockOptions;

namespace {

/// m xi'' + c xi' + k xi = 0, xi = x - x_eq: the exact solution.
struct DampedOscillator {
  double m, k, c, xi0, v0;
  double x(double t) const {
    const double disc = c * c - 4 * m * k;
    if (disc < 0) {
      const double s = c / (2 * m), wd = std::sqrt(-disc) / (2 * m);
      return std::exp(-s * t) * (xi0 * std::cos(wd * t) + (v0 + s * xi0) / wd * std::sin(wd * t));
    }
    const double r = std::sqrt(disc);
    const double s1 = (-c + r) / (2 * m), s2 = (-c - r) / (2 * m);
    const double A = (v0 - s2 * xi0) / (s1 - s2), B = xi0 - A;
    return A * std::exp(s1 * t) + B * std::exp(s2 * t);
  }
};

/// Extra mobility force on a slider: -k3 xi^3 + F0 sin(W t) (time-dependent and nonlinear), or
/// NaN once t >= nan_after.
class ExtraForce : public Force::Custom::Implementation {
 public:
  ExtraForce(MobilizedBody b, double x_eq, double k3, double F0, double W, double nan_after)
      : b_(b), x_eq_(x_eq), k3_(k3), F0_(F0), W_(W), nan_after_(nan_after) {}
  void calcForce(const State& s, Vector_<SpatialVec>&, Vector_<Vec3>&,
                 Vector& mobilityForces) const override {
    const double t = s.getTime();
    if (t >= nan_after_) {
      b_.applyOneMobilityForce(s, 0, std::numeric_limits<double>::quiet_NaN(), mobilityForces);
      return;
    }
    const double xi = b_.getOneQ(s, 0) - x_eq_;
    b_.applyOneMobilityForce(s, 0, -k3_ * xi * xi * xi + F0_ * std::sin(W_ * t), mobilityForces);
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  MobilizedBody b_;
  double x_eq_, k3_, F0_, W_, nan_after_;
};

/// A mass on a Slider with a linear spring-damper (equilibrium x_eq) and optional extra force.
struct SliderSystem {
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody::Slider body;
  static constexpr double x_eq = 0.25;

  SliderSystem(double m, double k, double c, double k3 = 0, double F0 = 0, double W = 0,
               double nan_after = std::numeric_limits<double>::infinity()) {
    body = MobilizedBody::Slider(matter.Ground(), Transform(),
                                 Body::Rigid(MassProperties(m, Vec3(0), Inertia(1))), Transform());
    Force::MobilityLinearSpring(forces, body, MobilizerQIndex(0), k, x_eq);
    Force::MobilityLinearDamper(forces, body, MobilizerUIndex(0), c);
    if (k3 != 0 || F0 != 0 || std::isfinite(nan_after))
      Force::Custom(forces, new ExtraForce(body, x_eq, k3, F0, W, nan_after));
    system.realizeTopology();
  }
  State initial(double xi0, double v0) {
    State s = system.getDefaultState();
    body.setOneQ(s, 0, x_eq + xi0);
    body.setOneU(s, 0, v0);
    system.realize(s, Stage::Velocity);
    return s;
  }
  double x(const State& s) const { return body.getOneQ(s, 0) - x_eq; }
  double v(const State& s) const { return body.getOneU(s, 0); }
};

/// Largest |x - x_exact| over samples every `dt` up to T (the integrator lands on each sample).
double maxErrorAgainstExact(RosenbrockIntegrator& integ, const SliderSystem& sys,
                            const DampedOscillator& ex, double T, double dt) {
  double worst = 0;
  for (int i = 1; i * dt <= T + 1e-12; ++i) {
    const double ts = i * dt;
    while (integ.getTime() < ts) integ.step(ts);
    EXPECT_EQ(integ.getTime(), ts);
    worst = std::max(worst, std::abs(sys.x(integ.getState()) - ex.x(ts)));
  }
  return worst;
}

struct RkStats {
  long steps, realizations;
  double x_end;
};
RkStats rkMerson(SliderSystem& sys, const State& s0, double accuracy, double hmax, double T) {
  RungeKuttaMersonIntegrator rk(sys.system);
  rk.setAccuracy(accuracy);
  rk.setMaximumStepSize(hmax);
  rk.initialize(s0);
  while (rk.getTime() < T) rk.stepTo(T);
  return {rk.getNumStepsTaken(), rk.getNumRealizations(), sys.x(rk.getState())};
}

/// Fixed-step error at T for step counts N: returns the observed orders log2(e_N / e_2N).
std::vector<double> observedOrders(SliderSystem& sys, const State& s0, double T,
                                   const std::vector<int>& Ns, const RosenbrockOptions& base,
                                   double x_ref, double v_ref, double v_scale) {
  std::vector<double> errs;
  for (int N : Ns) {
    RosenbrockOptions o = base;
    o.fixed_step_s = T / N;
    o.max_step_s = T;
    RosenbrockIntegrator integ(sys.system, o);
    integ.initialize(s0);
    while (integ.getTime() < T) integ.step(T);
    EXPECT_EQ(integ.steps(), N);
    const State& s = integ.getState();
    errs.push_back(std::max(std::abs(sys.x(s) - x_ref), std::abs(sys.v(s) - v_ref) / v_scale));
  }
  std::vector<double> p;
  for (std::size_t i = 0; i + 1 < errs.size(); ++i) {
    p.push_back(std::log2(errs[i] / errs[i + 1]));
    std::cout << "  N=" << Ns[i] << " err=" << errs[i] << "  N=" << Ns[i + 1]
              << " err=" << errs[i + 1] << "  order " << p.back() << "\n";
  }
  return p;
}

}  // namespace

TEST(Rosenbrock, Ros34pw2SatisfiesTheWMethodOrderConditions) {
  // Expanding k_i = h f(Y_i) + h A sum_{j<=i} gamma_ij k_j for an ARBITRARY matrix A gives, up to
  // h^3, the elementary differentials f, f'f, Af, f''(f,f), f'f'f, f'Af, Af'f, AAf. Matching the
  // Taylor series of the exact solution (coefficients 1, 1/2, 0, 1/6, 1/6, 0, 0, 0) gives the
  // conditions below with alpha_i = sum_j a_ij and g_i = sum_{j<=i} gamma_ij. Order 3 needs all
  // eight, the embedded order-2 method the first three.
  const auto& T = dtwin::rosenbrock_detail::ros34pw2();
  const int S = T.kStages;
  double alpha[4] = {}, g[4] = {};
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j) {
      alpha[i] += T.a[i][j];
      if (j <= i) g[i] += T.gamma[i][j];
      if (j >= i) {
        EXPECT_EQ(T.a[i][j], 0.0) << "a must be strictly lower triangular";
      }
      if (j > i) {
        EXPECT_EQ(T.gamma[i][j], 0.0) << "gamma must be lower triangular";
      }
    }
  for (int i = 0; i < S; ++i)
    EXPECT_EQ(T.gamma[i][i], T.gamma[0][0]) << "one LU per step size needs a constant diagonal";
  auto conditions = [&](const double* b) {
    double c[8] = {};
    for (int i = 0; i < S; ++i) {
      c[0] += b[i];
      c[1] += b[i] * alpha[i];
      c[2] += b[i] * g[i];
      c[3] += b[i] * alpha[i] * alpha[i];
      for (int j = 0; j < S; ++j) {
        c[4] += b[i] * T.a[i][j] * alpha[j];
        c[5] += b[i] * T.a[i][j] * g[j];
        c[6] += b[i] * T.gamma[i][j] * alpha[j];
        c[7] += b[i] * T.gamma[i][j] * g[j];
      }
    }
    return std::vector<double>(c, c + 8);
  };
  const double want[8] = {1.0, 0.5, 0.0, 1.0 / 3.0, 1.0 / 6.0, 0.0, 0.0, 0.0};
  const auto c3 = conditions(T.b), c2 = conditions(T.b_hat);
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(c3[k], want[k], 1e-14) << "order-3 condition " << k;
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(c2[k], want[k], 1e-14) << "embedded order-2 condition " << k;
  // The embedded method is genuinely of order 2 only (else the error estimate would vanish).
  double off = 0;
  for (int k = 3; k < 8; ++k) off += std::abs(c2[k] - want[k]);
  EXPECT_GT(off, 1e-3);
  // L-stability: gamma is the root of g^3 - 3g^2 + 3g/2 - 1/6 = 0 in (1/3, 1/2).
  const double gm = T.gamma[0][0];
  EXPECT_NEAR(gm * gm * gm - 3 * gm * gm + 1.5 * gm - 1.0 / 6.0, 0.0, 1e-15);
}

TEST(Rosenbrock, DampedOscillatorMatchesTheAnalyticSolution) {
  const DampedOscillator ex{1.0, 400.0, 4.0, 0.1, 0.0};  // omega = 20 rad/s, zeta = 0.1
  SliderSystem sys(ex.m, ex.k, ex.c);
  std::vector<double> errs;
  for (double acc : {1e-3, 1e-5}) {
    RosenbrockOptions o;
    o.accuracy = acc;
    o.max_step_s = 0.1;
    RosenbrockIntegrator integ(sys.system, o);
    integ.initialize(sys.initial(ex.xi0, ex.v0));
    const double e = maxErrorAgainstExact(integ, sys, ex, 3.0, 0.05);
    std::cout << "accuracy " << acc << ": max |x error| " << e << " m over 3 s (amplitude 0.1 m), "
              << integ.steps() << " steps, " << integ.evaluations() << " evaluations, "
              << integ.jacobians() << " Jacobians\n";
    // Global error of a locally controlled method: a small multiple of the tolerance times the
    // scale (atol unit 1 + |y| <= 2.1 here) accumulated over ~10 periods.
    EXPECT_LT(e, 10 * acc);
    errs.push_back(e);
  }
  EXPECT_LT(errs[1], errs[0] / 10) << "a 100x tighter accuracy must give a much smaller error";
}

TEST(Rosenbrock, StiffHeavilyDampedCaseNeedsFarFewerStepsThanRkMerson) {
  // c/m = 1000 1/s: eigenvalues -10.1 and -989.9 1/s. After the fast transient (a few ms) the
  // solution is smooth, but an explicit method stays stability-limited to h ~ 3/990 s.
  const DampedOscillator ex{1.0, 1.0e4, 1000.0, 0.1, 0.0};
  SliderSystem sys(ex.m, ex.k, ex.c);
  const State s0 = sys.initial(ex.xi0, ex.v0);
  const double T = 2.0, acc = 1e-4, hmax = 0.1;
  RosenbrockOptions o;
  o.accuracy = acc;
  o.max_step_s = hmax;
  RosenbrockIntegrator integ(sys.system, o);
  integ.initialize(s0);
  const double e = maxErrorAgainstExact(integ, sys, ex, T, 0.25);
  const RkStats rk = rkMerson(sys, s0, acc, hmax, T);
  std::cout << "stiff: Rosenbrock " << integ.steps() << " steps (" << integ.attempts()
            << " attempts, " << integ.evaluations() << " evaluations, " << integ.jacobians()
            << " Jacobians), RK-Merson " << rk.steps << " steps (" << rk.realizations
            << " realizations); max |x error| " << e << " (RK-Merson end error "
            << std::abs(rk.x_end - ex.x(T)) << ")\n";
  EXPECT_LT(e, 10 * acc);
  EXPECT_LT(integ.steps() * 5, rk.steps);
  EXPECT_LT(integ.evaluations() * 5, rk.realizations);
}

TEST(Rosenbrock, FixedStepErrorFallsAtOrderThreeOnTheLinearOscillator) {
  const DampedOscillator ex{1.0, 400.0, 4.0, 0.1, 0.0};
  SliderSystem sys(ex.m, ex.k, ex.c);
  const double T = 1.0;
  // Exact velocity at T from the closed form (derivative of x(t)).
  const double s = ex.c / (2 * ex.m), wd = std::sqrt(4 * ex.m * ex.k - ex.c * ex.c) / (2 * ex.m);
  const double B = (ex.v0 + s * ex.xi0) / wd;
  const double v_T =
      std::exp(-s * T) * (-s * (ex.xi0 * std::cos(wd * T) + B * std::sin(wd * T)) +
                          (-ex.xi0 * wd * std::sin(wd * T) + B * wd * std::cos(wd * T)));
  for (int age : {0, 1000000}) {  // fresh Jacobian every step, and one frozen Jacobian
    RosenbrockOptions o;
    o.jacobian_max_age = age;
    std::cout << "linear, jacobian_max_age " << age << "\n";
    const auto p =
        observedOrders(sys, sys.initial(ex.xi0, ex.v0), T, {40, 80, 160}, o, ex.x(T), v_T, 20.0);
    for (double q : p) {
      EXPECT_GT(q, 2.7);
      EXPECT_LT(q, 3.3);
    }
  }
}

TEST(Rosenbrock, OrderThreeHoldsWithAFrozenJacobianAndTimeDependentForcing) {
  // Nonlinear (cubic spring) and non-autonomous (sinusoidal force): a Jacobian frozen at t = 0 is
  // a genuinely wrong matrix later on; a W-method must keep order 3 with it, with and without
  // the f_t term. Reference: RK-Merson at accuracy 1e-12.
  SliderSystem sys(1.0, 100.0, 2.0, 2.0e4, 5.0, 7.0);
  const State s0 = sys.initial(0.1, 0.0);
  const double T = 1.0;
  RungeKuttaMersonIntegrator rk(sys.system);
  rk.setAccuracy(1e-12);
  rk.initialize(s0);
  while (rk.getTime() < T) rk.stepTo(T);
  const double x_ref = sys.x(rk.getState()), v_ref = sys.v(rk.getState());
  for (bool td : {true, false}) {
    for (int age : {0, 1000000}) {
      RosenbrockOptions o;
      o.time_derivative = td;
      o.jacobian_max_age = age;
      std::cout << "nonlinear forced, time_derivative " << td << ", jacobian_max_age " << age
                << "\n";
      const auto p = observedOrders(sys, s0, T, {80, 160, 320}, o, x_ref, v_ref, 20.0);
      for (double q : p) {
        EXPECT_GT(q, 2.6);
        EXPECT_LT(q, 3.4);
      }
    }
  }
}

TEST(Rosenbrock, EulerAngleKinematicsUseSimbodysQDot) {
  // A free sphere with Euler angles (qdot = N(q) u, N != I) spinning torque-free: the angular
  // velocity w is constant in Ground and R(T) = rot(|w| T, w/|w|) R0.
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  MobilizedBody::Free ball(matter.Ground(), Transform(),
                           Body::Rigid(MassProperties(2.0, Vec3(0), Inertia(0.3))), Transform());
  system.realizeTopology();
  State s = system.getDefaultState();
  matter.setUseEulerAngles(s, true);
  system.realizeModel(s);
  const Rotation R0(BodyRotationSequence, 0.2, XAxis, -0.1, YAxis, 0.3, ZAxis);
  const Vec3 w(0.3, -0.2, 0.5);
  ball.setQToFitRotation(s, R0);
  ball.setUToFitAngularVelocity(s, w);
  system.realize(s, Stage::Velocity);
  ASSERT_EQ(matter.getNumQuaternionsInUse(s), 0);
  ASSERT_EQ(s.getNQ(), 7);  // Simbody keeps the quaternion's 4th slot, unused, with Euler angles
  const double T = 1.0;
  RosenbrockOptions o;
  o.accuracy = 1e-8;
  RosenbrockIntegrator integ(system, o);
  integ.initialize(s);
  while (integ.getTime() < T) integ.step(T);
  const Rotation expected = Rotation(w.norm() * T, UnitVec3(w)) * R0;
  const Rotation actual = ball.getBodyRotation(integ.getState());
  const double angle_err = std::abs((~expected * actual).convertRotationToAngleAxis()[0]);
  std::cout << "Euler angles: rotation error " << angle_err << " rad after " << integ.steps()
            << " steps\n";
  EXPECT_LT(angle_err, 1e-6);
  // The same body with quaternions is refused: no normalisation is done.
  State sq = system.getDefaultState();
  system.realize(sq, Stage::Velocity);
  RosenbrockIntegrator integ2(system, o);
  EXPECT_THROW(integ2.initialize(sq), std::invalid_argument);
}

TEST(Rosenbrock, MaximumStepIsHonouredAndStopTimesAreLandedOnExactly) {
  SliderSystem sys(1.0, 400.0, 4.0);
  RosenbrockOptions o;
  o.accuracy = 1e-2;  // loose: the controller would like large steps
  o.max_step_s = 0.01;
  RosenbrockIntegrator integ(sys.system, o);
  integ.initialize(sys.initial(0.1, 0.0));
  double hmax = 0.01, longest = 0;
  const double t1 = 0.123456789, t2 = 0.5, t3 = 1.0;
  for (double t_stop : {t1, t2, t3}) {
    if (t_stop == t3) {
      hmax = 0.003;
      integ.setMaximumStepSize(hmax);
    }
    while (integ.getTime() < t_stop) {
      const double before = integ.getTime();
      integ.step(t_stop);
      const double h = integ.getTime() - before;
      EXPECT_LE(h, hmax * (1 + 1e-12)) << "at t = " << before;
      EXPECT_LE(integ.getTime(), t_stop);
      if (t_stop == t2) longest = std::max(longest, h);
    }
    EXPECT_EQ(integ.getTime(), t_stop);
    EXPECT_EQ(integ.getState().getTime(), t_stop);
    EXPECT_GE(integ.getState().getSystemStage(), Stage::Acceleration);
  }
  EXPECT_GT(longest, 0.5 * 0.01) << "the bound, not the controller, should have limited the steps";
  EXPECT_THROW(integ.step(integ.getTime()), std::invalid_argument);
}

TEST(Rosenbrock, NonFiniteForcesAndStepLimitsGiveRuntimeErrors) {
  {  // NaN from a force after t = 0.5: a clear error, not a hang or a crash
    SliderSystem sys(1.0, 400.0, 4.0, 0, 0, 0, 0.5);
    RosenbrockIntegrator integ(sys.system, RosenbrockOptions{});
    integ.initialize(sys.initial(0.1, 0.0));
    bool threw = false;
    try {
      for (int i = 0; i < 100000 && integ.getTime() < 1.0; ++i) integ.step(1.0);
    } catch (const std::runtime_error& e) {
      threw = true;
      std::cout << "NaN force: " << e.what() << "\n";
      EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos);
    }
    EXPECT_TRUE(threw);
    EXPECT_LT(integ.getTime(), 0.5 + 1e-12) << "no state past the NaN may be accepted";
  }
  {  // NaN already at the initial state
    SliderSystem sys(1.0, 400.0, 4.0, 0, 0, 0, 0.0);
    RosenbrockIntegrator integ(sys.system, RosenbrockOptions{});
    EXPECT_THROW(integ.initialize(sys.initial(0.1, 0.0)), std::runtime_error);
  }
  {  // too many steps
    SliderSystem sys(1.0, 400.0, 4.0);
    RosenbrockOptions o;
    o.max_steps = 5;
    RosenbrockIntegrator integ(sys.system, o);
    integ.initialize(sys.initial(0.1, 0.0));
    EXPECT_THROW(
        {
          for (int i = 0; i < 1000; ++i) integ.step(10.0);
        },
        std::runtime_error);
    EXPECT_EQ(integ.steps(), 5);
  }
  {  // fixed step into the NaN region
    SliderSystem sys(1.0, 400.0, 4.0, 0, 0, 0, 0.05);
    RosenbrockOptions o;
    o.fixed_step_s = 0.01;
    RosenbrockIntegrator integ(sys.system, o);
    integ.initialize(sys.initial(0.1, 0.0));
    EXPECT_THROW(
        {
          for (int i = 0; i < 1000; ++i) integ.step(1.0);
        },
        std::runtime_error);
  }
}

TEST(Rosenbrock, InvalidOptionsAreRefused) {
  SliderSystem sys(1.0, 400.0, 4.0);
  auto with = [](auto edit) {
    RosenbrockOptions o;
    edit(o);
    return o;
  };
  EXPECT_THROW(RosenbrockIntegrator(sys.system, with([](RosenbrockOptions& o) { o.accuracy = 0; })),
               std::invalid_argument);
  EXPECT_THROW(
      RosenbrockIntegrator(sys.system, with([](RosenbrockOptions& o) { o.max_step_s = 0; })),
      std::invalid_argument);
  EXPECT_THROW(
      RosenbrockIntegrator(sys.system, with([](RosenbrockOptions& o) { o.initial_step_s = -1; })),
      std::invalid_argument);
  EXPECT_THROW(
      RosenbrockIntegrator(sys.system, with([](RosenbrockOptions& o) { o.jacobian_max_age = -1; })),
      std::invalid_argument);
  EXPECT_THROW(RosenbrockIntegrator(sys.system, with([](RosenbrockOptions& o) {
                                      o.jacobian_refresh_rejections = 0;
                                    })),
               std::invalid_argument);
  RosenbrockIntegrator integ(sys.system, RosenbrockOptions{});
  EXPECT_THROW(integ.setMaximumStepSize(0), std::invalid_argument);
  EXPECT_THROW(integ.step(1.0), std::logic_error) << "step() before initialize()";
}
