#pragma once
// The ROS34PW2 step of rosenbrock.hpp, written once for every way of evaluating y' = f(t, y):
// the stage equations in the transformed variables, the weighted RMS error norm, the step-size
// rule, the forward-difference Jacobian and its reuse, and the planned steps of a frozen step
// sequence. RosenbrockIntegrator evaluates f by realizing a SimTK::State; the hand ODE's stepper
// (hand_ode.hpp) calls a function. Each says only how f is evaluated (the virtual hooks below),
// so the two integrations cannot drift apart.
#include <array>
#include <string>

#include <Eigen/Dense>

#include "twin/rosenbrock.hpp"

namespace dtwin::rosenbrock_detail {

class Ros34pw2Core {
 public:
  static constexpr int S = Tableau::kStages;
  /// Validates `options` (std::invalid_argument naming `who`, the integrator's class, as every
  /// message does).
  Ros34pw2Core(RosenbrockOptions options, std::string who);
  virtual ~Ros34pw2Core() = default;
  Ros34pw2Core(const Ros34pw2Core&) = delete;
  Ros34pw2Core& operator=(const Ros34pw2Core&) = delete;

  /// Sizes the work space (zeros) for `n` variables at time `t0` and resets counters, Jacobian and
  /// step size; `unit` is 1 (a caller with other unit changes sets it afterwards).
  void reset(int n, double t0);
  /// After the caller set y0 and f0 = f(t, y0): std::runtime_error when either is not finite;
  /// else the integrator is ready to step.
  void checkStart();
  void setMaximumStepSize(double h);
  void step(double t_stop);
  void stepTo(double t_next, bool new_jacobian);
  double stepToIfAccurate(double t_next, bool new_jacobian, double max_error);

  RosenbrockOptions opt;
  std::string who;
  Transformed tab{ros34pw2()};
  bool initialized = false;
  int n = 0;
  double t = 0, hmax = 0;
  double h_prop = 0;  ///< proposed next step
  bool last_rejected = false;
  Eigen::VectorXd y0, f0, fprev, ynew, err, tmp, rhs, f, ft, unit;
  std::array<Eigen::VectorXd, S> u;
  Eigen::MatrixXd J, W;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  bool have_jac = false, jac_fresh = false;
  bool step_new_jac = false;  ///< a Jacobian was computed during the current (last) step
  int jac_age = 0;
  double h_factored = -1;
  long n_steps = 0, n_attempts = 0, n_evals = 0, n_jacs = 0;

 protected:
  /// f(tt, y) into `out` (a stage, or the time derivative's second point); counts n_evals.
  virtual void evaluate(double tt, const Eigen::VectorXd& y, Eigen::VectorXd& out) = 0;
  /// f(t, y0 with component j set to v) into `out`, for column j of the Jacobian (called for
  /// j = 0 .. n-1 in turn after beginJacobian; `restore` is y0[j]). The default copies y0.
  virtual void beginJacobian() { tmp = y0; }
  virtual void evaluateComponent(int j, double v, double restore, Eigen::VectorXd& out);
  /// f at the accepted state (t_new, y) into `out`: the state the integrator reports.
  virtual void evaluateAccepted(double t_new, const Eigen::VectorXd& y, Eigen::VectorXd& out) {
    evaluate(t_new, y, out);
  }
  /// The accepted state back at (t, y0) after a step end whose f was not finite.
  virtual void restoreAccepted() {}
  /// A step of a system with no variables to time `t_new`.
  virtual void advanceEmpty(double t_new) {}

 private:
  void computeJacobian();
  bool attempt(double h);
  double errorNorm() const;
  bool commit(double t_new);
  void accept(double t_next);
  void checkPlannedStep(const char* what, double t_next) const;
};

}  // namespace dtwin::rosenbrock_detail
