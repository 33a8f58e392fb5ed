#include "twin/rosenbrock.hpp"

#include "common/format.hpp"
#include "twin/ros34pw2_core.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Simbody.h>
#include <Eigen/Dense>

namespace dtwin {

// ----------------------------------------------------------------------------- the method
//
// ROS34PW2: J. Rang and L. Angermann, "New Rosenbrock W-methods of order 3 for partial
// differential algebraic equations of index 1", BIT Numerical Mathematics 45 (2005) 761-787,
// Table "ROS34PW2". The 17-digit values below are those of PETSc's TSROSWRA34PW2
// (src/ts/impls/rosw/rosw.c), which uses the same Hairer-Wanner form as rosenbrock.hpp:
// gamma = 0.435866521508459 (the L-stability root of g^3 - 3g^2 + 3g/2 - 1/6), alpha = row sums
// of a = (0, 0.871733043016918, 0.731579957788852, 1).
//
// rosenbrock_test.cpp checks all eight order-3 W-method conditions (valid for any matrix in
// place of the Jacobian; derived there) for (a, gamma, b) and the three order-2 ones for b_hat,
// and measures the order of convergence on Simbody systems.
//
// Time dependence. The system is non-autonomous (road under the vehicle, speed profile). Write
// it autonomously as Y = (y, t), Y' = (f(t, y), 1) and use, in place of its Jacobian, the matrix
// [[J, f_t], [0, 0]]. Because a W-method keeps its order for ANY such matrix, the t-row of the
// stages gives exactly stage times t + alpha_i h and the y-rows give the non-autonomous form of
// rosenbrock.hpp with f_t multiplied by gamma_i = sum_{j<=i} gamma_ij. Hence any f_t is
// admissible: f_t = 0 (the default) and the finite difference computed with the Jacobian
// (options.time_derivative, reused as long as the Jacobian is) both keep order 3. The term can
// only improve the error constant when the forcing drives stiff components, and a stale f_t
// hurts when the forcing changes fast (a tire on a bump), hence the default.
//
// Implementation: the usual transformed variables u_i = sum_{j<=i} gamma_ij k_j
// (Hairer & Wanner, Solving ODEs II, Sec. IV.7, eq. (7.25)), which avoid products with J:
//   (I - h gamma J) u_i = h gamma [ f(t + alpha_i h, y + sum_{j<i} at_ij u_j)
//                                    + sum_{j<i} (c_ij / h) u_j + gamma_i h f_t ],
//   y_new = y + sum_i m_i u_i,  err = sum_i e_i u_i,
// with Gi = gamma^{-1}: at = a Gi, c_ij = -Gi_ij (j < i), m = b^T Gi, e = (b - b_hat)^T Gi.
// This is an algebraic identity valid for any matrix J, so the W property is kept.

namespace rosenbrock_detail {
const Tableau& ros34pw2() {
  static const Tableau t = [] {
    Tableau r{};
    const double g = 4.3586652150845900e-01;
    const double a[4][4] = {{0, 0, 0, 0},
                            {8.7173304301691801e-01, 0, 0, 0},
                            {8.4457060015369423e-01, -1.1299064236484185e-01, 0, 0},
                            {0, 0, 1.0, 0}};
    const double gm[4][4] = {
        {g, 0, 0, 0},
        {-8.7173304301691801e-01, g, 0, 0},
        {-9.0338057013044082e-01, 5.4180672388095326e-02, g, 0},
        {2.4212380706095346e-01, -1.2232505839045147e+00, 5.4526025533510214e-01, g}};
    const double b[4] = {2.4212380706095346e-01, -1.2232505839045147e+00, 1.5452602553351020e+00,
                         4.3586652150845900e-01};
    const double bh[4] = {3.7810903145819369e-01, -9.6042292212423178e-02, 5.0000000000000000e-01,
                          2.1793326075422950e-01};
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        r.a[i][j] = a[i][j];
        r.gamma[i][j] = gm[i][j];
      }
      r.b[i] = b[i];
      r.b_hat[i] = bh[i];
    }
    return r;
  }();
  return t;
}
}  // namespace rosenbrock_detail

namespace {
constexpr int S = rosenbrock_detail::Tableau::kStages;

std::string fmt(double v) { return formatNumber(v, 10); }
}  // namespace

// ----------------------------------------------------------------------------- the core
namespace rosenbrock_detail {

Ros34pw2Core::Ros34pw2Core(RosenbrockOptions o, std::string w) : opt(o), who(std::move(w)) {
  if (!(opt.accuracy > 0 && opt.accuracy < 1))
    throw std::invalid_argument(who + ": accuracy must be in (0, 1), got " + fmt(opt.accuracy));
  if (!(opt.max_step_s > 0))
    throw std::invalid_argument(who + ": max_step_s must be > 0, got " + fmt(opt.max_step_s));
  if (!(opt.initial_step_s > 0))
    throw std::invalid_argument(who + ": initial_step_s must be > 0, got " +
                                fmt(opt.initial_step_s));
  if (opt.jacobian_max_age < 0)
    throw std::invalid_argument(who + ": jacobian_max_age must be >= 0");
  if (opt.jacobian_refresh_rejections < 1)
    throw std::invalid_argument(who + ": jacobian_refresh_rejections must be >= 1");
  if (opt.max_steps <= 0) throw std::invalid_argument(who + ": max_steps must be > 0");
  if (!(opt.fixed_step_s >= 0)) throw std::invalid_argument(who + ": fixed_step_s must be >= 0");
  hmax = opt.max_step_s;
}

void Ros34pw2Core::reset(int size, double t0) {
  n = size;
  t = t0;
  for (Eigen::VectorXd* v : {&y0, &f0, &fprev, &ynew, &err, &tmp, &rhs, &f, &ft}) v->setZero(n);
  unit.setOnes(n);
  for (auto& v : u) v.setZero(n);
  J.setZero(n, n);
  W.setZero(n, n);
  lu = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  n_steps = n_attempts = n_evals = n_jacs = 0;
  have_jac = jac_fresh = false;
  jac_age = 0;
  h_factored = -1;
  last_rejected = false;
  h_prop = opt.fixed_step_s > 0 ? opt.fixed_step_s : opt.initial_step_s;
  initialized = false;
}

void Ros34pw2Core::checkStart() {
  if (!y0.allFinite())
    throw std::runtime_error(who + ": initial state is not finite at t = " + fmt(t) + " s");
  if (!f0.allFinite())
    throw std::runtime_error(
        who + ": non-finite state derivative at the initial state, t = " + fmt(t) + " s");
  initialized = true;
}

void Ros34pw2Core::setMaximumStepSize(double h) {
  if (!(h > 0)) throw std::invalid_argument(who + ": maximum step size must be > 0, got " + fmt(h));
  hmax = h;
}

void Ros34pw2Core::evaluateComponent(int j, double v, double restore, Eigen::VectorXd& out) {
  tmp[j] = v;
  evaluate(t, tmp, out);
  tmp[j] = restore;
}

/// Forward-difference d(YDot)/dY at (t, y0), and d(YDot)/dt if requested.
void Ros34pw2Core::computeJacobian() {
  const double sq = std::sqrt(std::numeric_limits<double>::epsilon());
  beginJacobian();
  for (int j = 0; j < n; ++j) {
    const double yj = y0[j];
    const double yp = yj + sq * std::max(std::abs(yj), unit[j]);
    const double d = yp - yj;  // exactly representable increment
    evaluateComponent(j, yp, yj, f);
    J.col(j) = (f - f0) / d;
  }
  if (opt.time_derivative) {
    const double tp = t + sq * std::max(std::abs(t), 1.0);
    const double dt = tp - t;
    evaluate(tp, y0, f);
    ft = (f - f0) / dt;
  }
  if (!J.allFinite() || !ft.allFinite())
    throw std::runtime_error(who + ": the finite-difference Jacobian is not finite at t = " +
                             fmt(t) + " s (NaN/Inf from a force next to the current state?)");
  ++n_jacs;
  step_new_jac = true;
  have_jac = true;
  jac_fresh = true;
  jac_age = 0;
  h_factored = -1;
}

/// Stages, solution and error estimate of a step of size h from (t, y0). Returns false if a
/// stage derivative or the result is not finite.
bool Ros34pw2Core::attempt(double h) {
  if (h != h_factored) {
    W.noalias() = (-h * tab.gamma) * J;
    W.diagonal().array() += 1.0;
    lu.compute(W);
    h_factored = h;
  }
  const double hg = h * tab.gamma;
  for (int i = 0; i < S; ++i) {
    const Eigen::VectorXd* fi = &f0;
    if (i > 0) {
      tmp = y0;
      for (int j = 0; j < i; ++j) tmp.noalias() += tab.at[i][j] * u[j];
      evaluate(t + tab.alpha[i] * h, tmp, f);
      if (!f.allFinite()) return false;
      fi = &f;
    }
    rhs = *fi;
    for (int j = 0; j < i; ++j) rhs.noalias() += (tab.c[i][j] / h) * u[j];
    if (opt.time_derivative && have_jac) rhs.noalias() += (tab.gsum[i] * h) * ft;
    rhs *= hg;
    u[i].noalias() = lu.solve(rhs);
  }
  ynew = y0;
  err.setZero();
  for (int i = 0; i < S; ++i) {
    ynew.noalias() += tab.m[i] * u[i];
    err.noalias() += tab.e[i] * u[i];
  }
  return ynew.allFinite() && err.allFinite();
}

double Ros34pw2Core::errorNorm() const {
  const double rtol = opt.accuracy;
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const double sc = rtol * unit[i] + rtol * std::max(std::abs(y0[i]), std::abs(ynew[i]));
    const double r = err[i] / sc;
    s += r * r;
  }
  return n > 0 ? std::sqrt(s / n) : 0.0;
}

/// Moves the accepted state to (t_new, ynew) and evaluates f there. False (state restored)
/// if that derivative is not finite.
bool Ros34pw2Core::commit(double t_new) {
  fprev.swap(f0);
  evaluateAccepted(t_new, ynew, f0);
  if (f0.allFinite()) return true;
  restoreAccepted();
  f0.swap(fprev);
  return false;
}

/// Bookkeeping of an accepted step to `t_next` whose result ynew was committed.
void Ros34pw2Core::accept(double t_next) {
  y0.swap(ynew);
  t = t_next;
  ++n_steps;
  ++jac_age;
  jac_fresh = false;
}

void Ros34pw2Core::step(double t_stop) {
  if (!initialized) throw std::logic_error(who + ": step() before initialize()");
  if (!(t_stop > t))
    throw std::invalid_argument(who + ": t_stop = " + fmt(t_stop) +
                                " is not after the current time " + fmt(t));
  if (n_steps >= opt.max_steps)
    throw std::runtime_error(who + ": more than " + std::to_string(opt.max_steps) +
                             " steps (t = " + fmt(t) + " s)");
  const bool fixed = opt.fixed_step_s > 0;
  int rejections = 0;  // of this step
  step_new_jac = false;
  for (;;) {
    double h = fixed ? opt.fixed_step_s : std::min(h_prop, hmax);
    const double remaining = t_stop - t;
    bool land = false, limited = false;
    if (remaining <= h * (1 + 1e-12)) {
      land = true;
      limited = remaining < h;
      h = remaining;
    } else if (!fixed && remaining < 2 * h) {
      h = 0.5 * remaining;  // two equal steps rather than a long one and a sliver
      limited = true;
    }
    if (n == 0) {  // nothing to integrate
      t = land ? t_stop : t + h;
      advanceEmpty(t);
      ++n_attempts;
      ++n_steps;
      return;
    }
    if (!have_jac || (jac_age >= opt.jacobian_max_age && !jac_fresh)) computeJacobian();
    ++n_attempts;
    const bool ok = attempt(h);
    const double e = ok ? (fixed ? 0.0 : errorNorm()) : std::numeric_limits<double>::infinity();
    const double t_new = land ? t_stop : t + h;
    const bool passed = ok && std::isfinite(e) && e <= 1.0;
    const bool committed = passed && commit(t_new);
    if (committed) {
      accept(t_new);
      if (!fixed) {
        double fac = e == 0 ? 5.0 : std::min(5.0, std::max(0.2, 0.9 * std::pow(e, -1.0 / 3.0)));
        if (last_rejected) fac = std::min(fac, 1.0);
        const double next = h * fac;
        h_prop = limited ? std::max(h_prop, next) : next;
      }
      last_rejected = false;
      return;
    }
    // Rejected (error too large, or something non-finite).
    if (fixed)
      throw std::runtime_error(who + ": non-finite state or derivative at t = " + fmt(t) +
                               " s (fixed step " + fmt(h) + " s)");
    const bool nonfinite =
        !ok || !std::isfinite(e) || passed;  // passed but not committed: f(y_new) not finite
    const double fac =
        nonfinite ? 0.2 : std::min(0.9, std::max(0.2, 0.9 * std::pow(e, -1.0 / 3.0)));
    h_prop = h * fac;
    last_rejected = true;
    const double hmin = 64 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t));
    if (h_prop < hmin) {
      std::string why = nonfinite ? "the state derivative is not finite (NaN/Inf from a force?)"
                                  : "the error test keeps failing (error norm " + fmt(e) + ")";
      throw std::runtime_error(who + ": step size underflow at t = " + fmt(t) +
                               " s (h = " + fmt(h_prop) + " s): " + why);
    }
    ++rejections;
    if (!jac_fresh && (rejections >= opt.jacobian_refresh_rejections || nonfinite))
      computeJacobian();
  }
}

/// The preconditions of a step to `t_next` chosen by the caller (stepTo, stepToIfAccurate).
void Ros34pw2Core::checkPlannedStep(const char* what, double t_next) const {
  if (!initialized) throw std::logic_error(who + ": " + what + " before initialize()");
  if (!(t_next > t))
    throw std::invalid_argument(who + ": t_next = " + fmt(t_next) +
                                " is not after the current time " + fmt(t));
  if (n_steps >= opt.max_steps)
    throw std::runtime_error(who + ": more than " + std::to_string(opt.max_steps) +
                             " steps (t = " + fmt(t) + " s)");
}

double Ros34pw2Core::stepToIfAccurate(double t_next, bool new_jacobian, double max_error) {
  checkPlannedStep("stepToIfAccurate()", t_next);
  step_new_jac = false;
  if (n == 0) {
    stepTo(t_next, false);
    return 0.0;
  }
  if (new_jacobian || !have_jac) computeJacobian();
  ++n_attempts;
  const double e = attempt(t_next - t) ? errorNorm() : std::numeric_limits<double>::infinity();
  if (!(std::isfinite(e) && e <= max_error)) return e;
  if (!commit(t_next)) return std::numeric_limits<double>::infinity();  // f at the end not finite
  accept(t_next);
  return e;
}

void Ros34pw2Core::stepTo(double t_next, bool new_jacobian) {
  checkPlannedStep("stepTo()", t_next);
  step_new_jac = false;
  ++n_attempts;
  if (n == 0) {
    advanceEmpty(t_next);
    accept(t_next);  // n = 0: the swap in accept() exchanges two empty vectors
    return;
  }
  if (new_jacobian || !have_jac) computeJacobian();
  if (!attempt(t_next - t) || !commit(t_next))
    throw std::runtime_error(who + ": non-finite state or derivative in the frozen step from t = " +
                             fmt(t) + " s to " + fmt(t_next) + " s");
  accept(t_next);
}

}  // namespace rosenbrock_detail

// ----------------------------------------------------------------------------- Simbody
/// f evaluated by realizing a SimTK::State through Acceleration: Y = [q; u; z], YDot its
/// derivative.
struct RosenbrockIntegrator::Impl : rosenbrock_detail::Ros34pw2Core {
  const SimTK::System& system;
  SimTK::State state;  ///< accepted state, realized through Acceleration
  SimTK::State work;   ///< scratch for stage and Jacobian evaluations
  int nq = 0, nu = 0, nz = 0;

  Impl(const SimTK::System& sys, RosenbrockOptions o)
      : Ros34pw2Core(o, "RosenbrockIntegrator"), system(sys) {}

  void realize(SimTK::State& s) {
    ++n_evals;
    try {
      system.realize(s, SimTK::Stage::Acceleration);
    } catch (const SimTK::Exception::Base&) {
      // Simbody's own text (file, line, method) means nothing to a user: plain words instead.
      throw std::runtime_error(
          "the multibody model could not be evaluated at t = " + fmt(s.getTime()) +
          " s (Simbody refused the state: non-finite forces or a configuration it cannot realise)");
    } catch (const std::exception& e) {
      throw std::runtime_error("the multibody model could not be evaluated at t = " +
                               fmt(s.getTime()) + " s: " + e.what());
    }
  }

  void readYDot(const SimTK::State& s, Eigen::VectorXd& out) const {
    const SimTK::Vector& yd = s.getYDot();
    for (int i = 0; i < n; ++i) out[i] = yd[i];
  }

  void writeY(SimTK::State& s, const Eigen::VectorXd& y) const {
    SimTK::Vector& Y = s.updY();
    for (int i = 0; i < n; ++i) Y[i] = y[i];
  }

  void evaluate(double tt, const Eigen::VectorXd& y, Eigen::VectorXd& out) override {
    work.setTime(tt);
    writeY(work, y);
    realize(work);
    readYDot(work, out);
  }

  void beginJacobian() override {
    work.setTime(t);
    writeY(work, y0);
  }

  /// Sets one component of Y on the scratch State, invalidating only the stages it affects.
  void setComponent(int j, double v) {
    if (j < nq)
      work.updQ()[j] = v;
    else if (j < nq + nu)
      work.updU()[j - nq] = v;
    else
      work.updZ()[j - nq - nu] = v;
  }

  void evaluateComponent(int j, double v, double restore, Eigen::VectorXd& out) override {
    setComponent(j, v);
    realize(work);
    readYDot(work, out);
    setComponent(j, restore);
  }

  void evaluateAccepted(double t_new, const Eigen::VectorXd& y, Eigen::VectorXd& out) override {
    state.setTime(t_new);
    writeY(state, y);
    realize(state);
    readYDot(state, out);
  }

  void restoreAccepted() override {
    state.setTime(t);
    writeY(state, y0);
    realize(state);
  }

  void advanceEmpty(double t_new) override {
    state.setTime(t_new);
    realize(state);
  }

  void refreshDerivative() {
    if (!initialized) throw std::logic_error(who + ": refreshDerivative() before initialize()");
    state.invalidateAllCacheAtOrAbove(SimTK::Stage::Time);
    realize(state);
    readYDot(state, f0);
    if (!f0.allFinite())
      throw std::runtime_error(
          who + ": non-finite state derivative after the inputs changed at t = " + fmt(t) + " s");
  }

  void initialize(const SimTK::State& s) {
    if (s.getNQErr() + s.getNUErr() + s.getNUDotErr() > 0)
      throw std::invalid_argument(
          "RosenbrockIntegrator: the system has constraints; this integrator does no projection");
    if (SimTK::MultibodySystem::isInstanceOf(system))
      if (const auto& mbs = SimTK::MultibodySystem::downcast(system);
          mbs.hasMatterSubsystem() && mbs.getMatterSubsystem().getNumQuaternionsInUse(s) > 0)
        throw std::invalid_argument(
            "RosenbrockIntegrator: the system uses quaternions, which this integrator does not "
            "normalise; use Euler angles (SimbodyMatterSubsystem::setUseEulerAngles)");
    state = s;
    work = s;
    nq = s.getNQ();
    nu = s.getNU();
    nz = s.getNZ();
    reset(s.getNY(), s.getTime());
    const SimTK::Vector& wu = s.getUWeights();
    const SimTK::Vector& wz = s.getZWeights();
    auto inv = [](double w) { return w > 0 && std::isfinite(w) ? 1.0 / w : 1.0; };
    for (int i = 0; i < nq; ++i)
      unit[i] = nq == nu ? inv(wu[i]) : 1.0;  // nq == nu: q_i has the unit of u_i
    for (int i = 0; i < nu; ++i) unit[nq + i] = inv(wu[i]);
    for (int i = 0; i < nz; ++i) unit[nq + nu + i] = inv(wz[i]);
    const SimTK::Vector& Y = state.getY();
    for (int i = 0; i < n; ++i) y0[i] = Y[i];
    realize(state);
    readYDot(state, f0);
    checkStart();
  }
};

// ----------------------------------------------------------------------------- forwarding
RosenbrockIntegrator::RosenbrockIntegrator(const SimTK::System& system, RosenbrockOptions options)
    : impl_(std::make_unique<Impl>(system, options)) {}
RosenbrockIntegrator::~RosenbrockIntegrator() = default;
RosenbrockIntegrator::RosenbrockIntegrator(RosenbrockIntegrator&&) noexcept = default;
RosenbrockIntegrator& RosenbrockIntegrator::operator=(RosenbrockIntegrator&&) noexcept = default;

void RosenbrockIntegrator::initialize(const SimTK::State& s) { impl_->initialize(s); }
void RosenbrockIntegrator::refreshDerivative() { impl_->refreshDerivative(); }
void RosenbrockIntegrator::setMaximumStepSize(double h) { impl_->setMaximumStepSize(h); }
void RosenbrockIntegrator::step(double t_stop) { impl_->step(t_stop); }
void RosenbrockIntegrator::stepTo(double t_next, bool new_jacobian) {
  impl_->stepTo(t_next, new_jacobian);
}
double RosenbrockIntegrator::stepToIfAccurate(double t_next, bool new_jacobian, double max_error) {
  return impl_->stepToIfAccurate(t_next, new_jacobian, max_error);
}
bool RosenbrockIntegrator::lastStepNewJacobian() const { return impl_->step_new_jac; }
const SimTK::State& RosenbrockIntegrator::getState() const { return impl_->state; }
double RosenbrockIntegrator::getTime() const { return impl_->t; }
long RosenbrockIntegrator::steps() const { return impl_->n_steps; }
long RosenbrockIntegrator::attempts() const { return impl_->n_attempts; }
long RosenbrockIntegrator::evaluations() const { return impl_->n_evals; }
long RosenbrockIntegrator::jacobians() const { return impl_->n_jacs; }

namespace rosenbrock_detail {
Transformed::Transformed(const Tableau& t) {
  double gi[S][S] = {};  // inverse of the lower-triangular gamma matrix
  for (int i = 0; i < S; ++i) {
    gi[i][i] = 1.0 / t.gamma[i][i];
    for (int j = 0; j < i; ++j) {
      double s = 0;
      for (int k = j; k < i; ++k) s += t.gamma[i][k] * gi[k][j];
      gi[i][j] = -s / t.gamma[i][i];
    }
  }
  gamma = t.gamma[0][0];
  for (int i = 0; i < S; ++i) {
    for (int j = 0; j < S; ++j) {
      alpha[i] += t.a[i][j];
      if (j <= i) gsum[i] += t.gamma[i][j];
      for (int k = 0; k < S; ++k) at[i][j] += t.a[i][k] * gi[k][j];
      if (j < i) c[i][j] = -gi[i][j];
      m[j] += t.b[i] * gi[i][j];
      e[j] += (t.b[i] - t.b_hat[i]) * gi[i][j];
    }
  }
}
}  // namespace rosenbrock_detail

}  // namespace dtwin
