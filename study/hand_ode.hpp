#pragma once
// The Simbody twin against a hand-written ODE of the same vehicle ("one 15 s bump run
// against the hand-written 7-DOF ODE of the same model: <= 3x, or the measured reason why not").
//
// Three parts:
//  * Ros34pw2Stepper: the ROS34PW2 Rosenbrock-W scheme of twin/rosenbrock.hpp (same tableau, same
//    error norm, step control and Jacobian reuse) over a plain right-hand side f(t, y, ydot), so
//    that both models are integrated by the same method at the same tolerance.
//  * HandOde: the nonlinear equations of motion of a MacPherson assembly (chassis heave z, roll
//    phi, pitch theta, four wheel travels u_i along the chassis z), derived by hand from the
//    kinematics the simulator builds in Simbody (twin/vehicle_system.cpp), with the project's own
//    force laws (the model's tire law, its strut law) and the scenario's road and speed.
//  * benchHandOde: the wall time of one run of each, their step and evaluation counts, and how
//    closely their front-left hub forces agree (`twin bench --hand-ode`, docs/performance.md).
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "subsystems/road.hpp"
#include "twin/model.hpp"
#include "twin/rosenbrock.hpp"
#include "twin/scenario.hpp"
#include "twin/simulator.hpp"

namespace dtwin {

/// ROS34PW2 over y' = f(t, y): RosenbrockIntegrator's own core (twin/ros34pw2_core.hpp, the
/// same code) with every option of RosenbrockOptions, for a right-hand side that is a function,
/// not a SimTK::System. Unit changes ("atol_i = accuracy * unit_i") are all 1, which is what
/// Simbody's weights are for the vehicle's system (State::getUWeights() is 1 for every mobility),
/// so the error norm is the same. Counts: an evaluation is one call of f; an accepted step costs
/// 4, a rejected one 3, a Jacobian n (+ 1 with time_derivative), initialize() 1.
class Ros34pw2Stepper {
 public:
  using Rhs = std::function<void(double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot)>;
  /// std::invalid_argument for options RosenbrockIntegrator refuses as well.
  Ros34pw2Stepper(Rhs f, RosenbrockOptions options);
  ~Ros34pw2Stepper();
  Ros34pw2Stepper(Ros34pw2Stepper&&) noexcept;
  Ros34pw2Stepper& operator=(Ros34pw2Stepper&&) noexcept;

  /// Sets the initial state and evaluates f there; resets counters, Jacobian and step size.
  /// std::runtime_error if y0 or f(t0, y0) is not finite.
  void initialize(double t0, const Eigen::VectorXd& y0);
  void setMaximumStepSize(double h);
  /// One accepted step, never beyond t_stop (lands on it when within reach); the exceptions of
  /// RosenbrockIntegrator::step().
  void step(double t_stop);

  double time() const;
  const Eigen::VectorXd& state() const;       ///< y at time()
  const Eigen::VectorXd& derivative() const;  ///< f(time(), state())
  long steps() const;
  long attempts() const;
  long evaluations() const;
  long jacobians() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The 7-DOF vehicle of a MacPherson assembly without effects. State y (14): q = (z, phi, theta,
/// u_fl, u_fr, u_rl, u_rr), then their rates: z the CG height above ground, phi roll (about x,
/// positive right side down), theta pitch (about the rolled y, positive nose down), u_i the
/// wheel's travel along the chassis z (the strut deflection, compression positive). The layout,
/// the rotation R = Rx(phi) Ry(theta) and the absolute heave are those of the simulator's Simbody
/// State (heave slider, Universal joint, one slider per wheel), so the error norms agree too.
class HandOde {
 public:
  static constexpr int kDof = 7, kStates = 14;
  /// InputError when the assembly is not MacPherson or has effects (neither is modelled here).
  /// `values` is a run vector of `m` (m.defaultRunValues()); `road` must outlive this object.
  HandOde(const Model& m, std::vector<double> values, const Road& road, const SpeedProfile& speed);

  /// The simulator's start state (the simulator's StaticStart, twin/static_start.hpp): wheels at
  /// zero travel and rest, and heave, pitch and roll such that the FL, FR and RL hubs sit at the
  /// road height plus R0 minus the static deflection under their static tire loads.
  Eigen::VectorXd equilibrium() const;
  /// ydot = f(t, y) (sizes kStates).
  void rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) const;

  struct Hub {
    double x = 0, xd = 0, z = 0, zd = 0, zdd = 0;  ///< hub centre in ground [m, m/s, m/s^2]
  };
  /// The hub of `corner` (0 fl, 1 fr, 2 rl, 3 rr) for state y; zdd from ydot = f(t, y).
  Hub hub(int corner, const Eigen::VectorXd& y, const Eigen::VectorXd& ydot) const;
  /// The tire's normal force [N] for a hub at (x, z) moving at zd: TireCorner::eval of the
  /// simulator. `hub_above_road` (if given) receives z minus the road height under the hub.
  double tireForce(int corner, double t, double hub_x, double hub_z, double hub_zd,
                   double* hub_above_road = nullptr) const;
  /// The main strut's force [N] at travel q and rate qd (its preload: Model::staticStrutForce).
  double strutForce(int corner, double q, double qd) const;

 private:
  struct Corner {
    double x = 0, y = 0;  ///< strut (and wheel centre) position in the chassis, at height w
    double preload = 0;
    bool front = true;
    Track track = Track::Left;
  };
  const Model& model_;
  std::vector<double> values_;
  const Road& road_;
  SpeedProfile speed_;
  double mc_ = 0, mw_ = 0, iw_ = 1e-3, g_ = 0, w_ = 0, R0_ = 0, a_ = 0, traction_per_accel_ = 0;
  Eigen::Vector3d inertia_;  ///< chassis principal inertias (ixx, iyy, izz)
  std::array<Corner, 4> corners_;
  std::size_t tire0_ = 0, ntire_ = 0, strut0_ = 0, nstrut_ = 0;
};

/// One run of the hand ODE over a scenario: the integrator segments of the simulator (a step
/// bound of obstacle_max_step_s while a wheel crosses an obstacle), ROS34PW2 at the options'
/// accuracy and maximum step, and the four hub forces on the simulator's output grid (cubic
/// Hermite of the hub motion recorded at every step, as Simulator's dense output).
struct HandOdeRun {
  std::vector<double> time_s;
  std::array<std::vector<double>, 4> hub_force_N;  ///< fl, fr, rl, rr
  long steps = 0, attempts = 0, evaluations = 0, jacobians = 0;
  double wall_s = 0;  ///< equilibrium, integration and output
};
HandOdeRun runHandOde(const Model& m, const std::vector<double>& values, const Road& road,
                      const ScenarioSpec& scenario, const SimulationOptions& options);

}  // namespace dtwin
