#pragma once
// A linearly implicit Rosenbrock-W integrator (ROS34PW2) that drives any SimTK::System.
//
// Why: the solid-axle wheel/axle interface is stiff and heavily damped (eigenvalue ~ -1000 1/s),
// so explicit Runge-Kutta methods are limited by stability, not accuracy. A Rosenbrock-W method
// is L-stable, needs no Newton iteration (one LU factorisation per step size, four linear solves
// per step) and tolerates an approximate, reused Jacobian (the "W" property): the Jacobian is
// computed by finite differences every `jacobian_max_age` accepted steps only.
//
// Method: ROS34PW2 of Rang & Angermann (BIT Numer. Math. 45 (2005) 761-787): 4 stages, order 3,
// embedded order 2 (for error control), L-stable (R(inf) = 0; embedded R(inf) = 0.48), W-method
// order 3 for ANY matrix in place of the Jacobian. Coefficients and references: rosenbrock.cpp.
//
// What the integrated system may contain (checked in initialize(), std::invalid_argument else):
//  * no constraints (no projection is done) and, for a MultibodySystem, no quaternions in use (a
//    quaternion's norm would drift without Simbody's projection; Euler angles are fine). Any
//    qdot = N(q) u kinematics (Euler angles, Pin, Slider, Universal, ...) is handled exactly, also
//    when nq != nu (Simbody keeps an unused 7th q for a Free mobilizer with Euler angles): the
//    right-hand side is Simbody's
//    own State::getYDot() = [qdot; udot; zdot], and the Jacobian is d(YDot)/dY, so N(q) and its
//    q-dependence enter the integration like any other term.
//  * event triggers and scheduled events are ignored (our systems have none).
//
// Cost model: one "evaluation" = set (t, Y) on a scratch State and realize(Stage::Acceleration).
// An accepted step costs 4 evaluations (stages 2..4 and the step end, which is stage 1 of the
// next step); a rejected one 3; a Jacobian n = nq + nu + nz (+ 1 with `time_derivative`).
// The step loop allocates nothing (Eigen work space is sized in initialize()).
//
// Step-size control: h_new = h * min(5, max(0.2, 0.9 err^(-1/3))) (no growth right after a
// rejection); the weighted RMS error norm is described at RosenbrockOptions::accuracy. A step
// that would leave less than one step before t_stop is split into two equal ones.
#include <memory>

namespace SimTK {
class System;
class State;
}  // namespace SimTK

namespace dtwin {

struct RosenbrockOptions {
  /// Relative tolerance rtol. Absolute tolerances: atol_i = accuracy * unit_i, where unit_i is
  /// the variable's "unit change" from Simbody's weights (1/State::getUWeights() for u and, if
  /// nq == nu, for the q with the same index; 1/State::getZWeights() for z; all 1 unless a
  /// subsystem sets them; 1 for q when nq != nu). A step is accepted when the weighted RMS norm of
  /// the embedded error estimate, sqrt(mean_i (err_i / sc_i)^2) with sc_i = atol_i + rtol *
  /// max(|y_i|, |y_new_i|), is <= 1.
  double accuracy = 1e-3;
  double max_step_s = 0.02;
  double initial_step_s = 1e-3;
  int jacobian_max_age = 50;  ///< accepted steps a Jacobian may be reused (0: a new one every step)
  /// Consecutive rejections of one step after which a (not fresh) Jacobian is recomputed before
  /// the retry: 1 = after every rejection; 2 = only when the smaller step failed as well (and at
  /// once after a non-finite stage). On the rough (ISO 8608 D) road most rejections come from
  /// the road, not the Jacobian: 2 cut the Jacobians from ~300 to ~45 per 15 s run and the
  /// evaluations by 30 %, with unchanged accuracy.
  int jacobian_refresh_rejections = 2;
  long max_steps = 2000000;  ///< step() throws once this many steps were taken
  /// Include the (finite-difference) d(YDot)/dt term of the non-autonomous Rosenbrock form,
  /// computed together with the Jacobian (1 extra evaluation) and reused with it. Either choice
  /// keeps order 3 (rosenbrock.cpp, "Time dependence"). Off by default: on the vehicle a stale
  /// f_t taken while a tire crosses the bump (|f_t| ~ 5e5) and reused after it gave an 8 %
  /// hub-force error at accuracy 1e-3; without it the error was 8e-4 for the same cost.
  bool time_derivative = false;
  /// Test/diagnostic hook: > 0 disables error control and takes steps of exactly this size
  /// (shortened only to land on t_stop). Used to measure the order of convergence.
  double fixed_step_s = 0.0;
};

class RosenbrockIntegrator {
 public:
  /// `system` must have been realizeTopology()'d and must outlive the integrator.
  RosenbrockIntegrator(const SimTK::System& system, RosenbrockOptions options);
  ~RosenbrockIntegrator();
  RosenbrockIntegrator(RosenbrockIntegrator&&) noexcept;
  RosenbrockIntegrator& operator=(RosenbrockIntegrator&&) noexcept;
  RosenbrockIntegrator(const RosenbrockIntegrator&) = delete;
  RosenbrockIntegrator& operator=(const RosenbrockIntegrator&) = delete;

  /// Copies `s` (realized at least to Velocity) as the initial state and realizes the copy
  /// through Acceleration. Resets the counters, the Jacobian and the step size. Throws
  /// std::invalid_argument for an unsupported system (constraints, quaternions) and
  /// std::runtime_error if the initial state derivative is not finite.
  void initialize(const SimTK::State& s);
  /// The system's inputs changed between steps (a force element reads other values from now on,
  /// e.g. a co-simulation's road or actuator inputs): the current State's cache is invalidated and
  /// its derivative, the next step's first stage, evaluated again. The Jacobian and the proposed
  /// step are kept (a W-method tolerates a Jacobian taken before the change).
  void refreshDerivative();
  /// Largest step from now on (may be changed between steps); overrides options.max_step_s.
  void setMaximumStepSize(double h);
  /// One accepted step, never beyond t_stop (lands exactly on t_stop when within reach).
  /// Throws std::runtime_error with a clear message on failure (step-size underflow,
  /// non-finite state, too many steps); std::invalid_argument if t_stop <= getTime().
  void step(double t_stop);
  /// One step to exactly `t_next` with no error control: a replayed step of a frozen sequence
  /// (twin/simulator.hpp StepPlan). A Jacobian is computed first when `new_jacobian` is set or none
  /// exists yet. Throws std::invalid_argument if t_next <= getTime(), std::runtime_error when the
  /// step or its end derivative is not finite (the state is then left at the step's start).
  void stepTo(double t_next, bool new_jacobian);
  /// The same step, taken only when it passes the error test: returns the error norm of the
  /// attempt (the step is committed when it is <= 1; +inf when something was not finite), and
  /// leaves the state at the step's start otherwise (with the Jacobian computed, if it was).
  /// A replay that meets a step far too large for these parameters splits it into equal parts
  /// taken with stepTo().
  double stepToIfAccurate(double t_next, bool new_jacobian, double max_error = 1.0);
  /// Whether the last accepted step computed a Jacobian (at its start state) before its accepted
  /// attempt: recorded with the step's end time, it lets stepTo() replay the step exactly.
  bool lastStepNewJacobian() const;
  const SimTK::State& getState() const;  ///< realized through Stage::Acceleration at the step end
  double getTime() const;

  long steps() const;        ///< accepted steps
  long attempts() const;     ///< attempted steps (accepted + rejected)
  long evaluations() const;  ///< realize(Acceleration) calls, Jacobians included
  long jacobians() const;    ///< finite-difference Jacobians computed

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

namespace rosenbrock_detail {
/// A Rosenbrock-W tableau in the Hairer-Wanner form
///   (I - h gamma_ii J) k_i = h f(t + alpha_i h, y + sum_{j<i} a_ij k_j)
///                            + h J sum_{j<i} gamma_ij k_j + h^2 (sum_{j<=i} gamma_ij) f_t,
///   y_new = y + sum_i b_i k_i,   error estimate = sum_i (b_i - b_hat_i) k_i.
struct Tableau {
  static constexpr int kStages = 4;
  double a[kStages][kStages];
  double gamma[kStages][kStages];  ///< lower triangular, constant diagonal
  double b[kStages];
  double b_hat[kStages];
};
/// ROS34PW2 (Rang & Angermann 2005), exposed for the order-condition test.
const Tableau& ros34pw2();
/// The tableau in the transformed variables u_i = sum_j gamma_ij k_j that the steppers use
/// (rosenbrock.cpp's header comment): stage i solves (I/(h gamma) - J) u_i = f(t + alpha_i h,
/// y + sum_j at_ij u_j) + sum_j (c_ij / h) u_j (+ gsum_i h f_t); y_new = y + sum m_i u_i, error
/// = sum e_i u_i. Shared by RosenbrockIntegrator and the hand-ODE stepper (hand_ode.hpp).
struct Transformed {
  static constexpr int S = Tableau::kStages;
  double gamma = 0;
  double alpha[S] = {}, gsum[S] = {}, at[S][S] = {}, c[S][S] = {}, m[S] = {}, e[S] = {};
  explicit Transformed(const Tableau& t);
};
}  // namespace rosenbrock_detail

}  // namespace dtwin
