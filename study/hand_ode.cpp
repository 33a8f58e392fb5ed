#include "study/hand_ode.hpp"

#include "twin/ros34pw2_core.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include <Eigen/Dense>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace dtwin {

// ----------------------------------------------------------------------------- the stepper
/// The ROS34PW2 core of RosenbrockIntegrator (twin/ros34pw2_core.hpp) over a function: the same
/// stage equations, error norm (unit changes 1, as Simbody's weights are for the vehicle), step-
/// size rule and Jacobian reuse, so that the two integrations differ only in how f is evaluated.
struct Ros34pw2Stepper::Impl : rosenbrock_detail::Ros34pw2Core {
  Rhs rhs_fn;

  Impl(Rhs fn, RosenbrockOptions o) : Ros34pw2Core(o, "Ros34pw2Stepper"), rhs_fn(std::move(fn)) {
    if (!rhs_fn) throw std::invalid_argument("Ros34pw2Stepper: no right-hand side");
  }

  void evaluate(double tt, const Eigen::VectorXd& y, Eigen::VectorXd& out) override {
    ++n_evals;
    rhs_fn(tt, y, out);
  }

  void initialize(double t0, const Eigen::VectorXd& y) {
    reset(static_cast<int>(y.size()), t0);
    y0 = y;
    evaluate(t, y0, f0);
    checkStart();
  }
};

Ros34pw2Stepper::Ros34pw2Stepper(Rhs f, RosenbrockOptions options)
    : impl_(std::make_unique<Impl>(std::move(f), options)) {}
Ros34pw2Stepper::~Ros34pw2Stepper() = default;
Ros34pw2Stepper::Ros34pw2Stepper(Ros34pw2Stepper&&) noexcept = default;
Ros34pw2Stepper& Ros34pw2Stepper::operator=(Ros34pw2Stepper&&) noexcept = default;
void Ros34pw2Stepper::initialize(double t0, const Eigen::VectorXd& y0) {
  impl_->initialize(t0, y0);
}
void Ros34pw2Stepper::setMaximumStepSize(double h) { impl_->setMaximumStepSize(h); }
void Ros34pw2Stepper::step(double t_stop) { impl_->step(t_stop); }
double Ros34pw2Stepper::time() const { return impl_->t; }
const Eigen::VectorXd& Ros34pw2Stepper::state() const { return impl_->y0; }
const Eigen::VectorXd& Ros34pw2Stepper::derivative() const { return impl_->f0; }
long Ros34pw2Stepper::steps() const { return impl_->n_steps; }
long Ros34pw2Stepper::attempts() const { return impl_->n_attempts; }
long Ros34pw2Stepper::evaluations() const { return impl_->n_evals; }
long Ros34pw2Stepper::jacobians() const { return impl_->n_jacs; }

// ----------------------------------------------------------------------------- the vehicle
//
// Kinematics (those the simulator's VehicleSystem builds): the chassis frame sits at the CG, height
// z, with rotation R = Rx(phi) Ry(theta) (Simbody's Universal: about x, then about the new y).
// Wheel i's centre, body and strut slide along the chassis z through (x_i, y_i, w) in the chassis,
// w the wheel centre below the CG (R0 - cg_height): s_i = R (x_i, y_i, w + u_i) from the CG. The
// wheel bodies turn with the chassis (inertia 1e-3 kg m^2 about every axis, as in the simulator).
//
// Equations of motion (Kane's form, no simplification: full rotation, every velocity product):
//   sum_b [ Jv_b^T m_b (Jv_b qdd + a_b) + Jw_b^T (I_b (Jw_b qdd + wd_b) + w x I_b w) ] = Q,
// with the partial velocities, for q = (z, phi, theta, u_1..u_4):
//   angular velocity w = phid e_x + thetad e_y',  e_y' = Rx(phi) e_y,  so Jw = [0, e_x, e_y',
//   0...], and its velocity-product part wd = phid thetad (e_x x e_y'); wheel i: v_i = zd e_z + w x
//   s_i + ud_i e_z',  e_z' = R e_z, so Jv_i = [e_z, e_x x s_i, e_y' x s_i, e_z' (column 3 + i)],
//   a_i = wd x s_i + w x (w x s_i) + 2 ud_i w x e_z'; chassis: v = zd e_z (the heave slider), its
//   rotation Jw above, I_b = R diag(ixx, iyy, izz) R^T.
// A wheel's isotropic inertia only adds iw to the roll and pitch diagonal (e_x . e_y' = 0, and
// its velocity-product terms vanish). Applied loads (force_elements.hpp's force elements): gravity
// and the d'Alembert load -m a(t) e_x at every mass centre; at each hub the tire (traction, 0, Fz)
// and the traction's moment (0, -(z_hub - h_road) F_x, 0) about it; the strut as the generalised
// force -F on u_i (a mobility force, as StrutGeometry::apply does for a slider).
HandOde::HandOde(const Model& m, std::vector<double> values, const Road& road,
                 const SpeedProfile& speed)
    : model_(m), values_(std::move(values)), road_(road), speed_(speed) {
  if (m.topology() != SuspensionTopology::MacPherson)
    throw InputError("assembly " + m.assembly().id,
                     "the hand-written ODE models a MacPherson suspension only");
  if (!m.effects().empty())
    throw InputError("assembly " + m.assembly().id,
                     "the hand-written ODE models no effects (it has " +
                         std::to_string(m.effects().size()) + ")");
  if (values_.size() != m.runParameterNames().size())
    throw InputError("run parameters",
                     "expected " + std::to_string(m.runParameterNames().size()) + " values");
  if (m.tire().followsSignal())
    throw InputError("assembly " + m.assembly().id,
                     "the hand-written ODE models a tire under the road, not the '" +
                         m.tire().name() + "' input");
  if (values_[static_cast<std::size_t>(m.roadGainSlot())] != 1.0 ||
      values_[static_cast<std::size_t>(m.roadDelaySlot())] != 0.0)
    throw InputError("run parameters",
                     "the hand-written ODE reads the road as logged (road.gain 1, road.delay_s 0)");
  for (std::size_t f = 0; f < roadSignalForms().size(); ++f)
    if (values_[static_cast<std::size_t>(m.roadFormSlot()) + f] != 0.0)
      throw InputError("run parameters",
                       std::string("the hand-written ODE reads the road under both axles (") +
                           roadSignalForms()[f].name + " 0)");
  for (int c = 0; c < 4; ++c)
    if (!m.strutFactors()[static_cast<std::size_t>(c)].empty() ||
        !m.tireFactors()[static_cast<std::size_t>(c)].empty())
      throw InputError("assembly " + m.assembly().id,
                       "the hand-written ODE has the same struts and tires at every corner (no "
                       "per-corner factors)");
  const VehicleData& d = m.vehicle();
  mc_ = d.chassis_mass;
  mw_ = d.wheel_mass;
  g_ = d.gravity;
  a_ = d.a;
  inertia_ = Eigen::Vector3d(d.ixx, d.iyy, d.izz);
  R0_ = m.table().value("tire.unloaded_radius_m");
  w_ = -(d.cg_height - R0_);
  traction_per_accel_ = d.total_mass(m.topology()) / 4.0;
  tire0_ = static_cast<std::size_t>(m.tireSlots().front());
  ntire_ = m.tireSlots().size();
  strut0_ = static_cast<std::size_t>(m.suspensionSlots().front());
  nstrut_ = m.suspensionSlots().size();
  for (int c = 0; c < 4; ++c) {
    Corner& k = corners_[static_cast<std::size_t>(c)];
    k.front = isFront(c);
    k.track = cornerTrack(c);
    k.x = k.front ? d.a : -d.b;
    k.y = (k.track == Track::Left ? 0.5 : -0.5) * d.track;
    k.preload = m.staticStrutForce(c);
  }
}

double HandOde::tireForce(int corner, double t, double hub_x, double hub_z, double hub_zd,
                          double* hub_above_road) const {
  const ParamValues p(values_.data() + tire0_, ntire_);
  const double v = speed_.speed(t);
  const double x_road = speed_.distance(t) + hub_x - a_;  // docs/model.md, "Forward motion"
  const RoadSample rs = road_.sampleAt(corner, x_road);
  const double rho = R0_ - (hub_z - rs.height_m);
  if (hub_above_road) *hub_above_road = hub_z - rs.height_m;
  TireState ts;
  ts.deflection_m = rho;
  ts.deflection_rate_mps = -hub_zd;  // the hub's vertical velocity (docs/model.md, "tire damping")
  ts.wheel_speed_radps = v / (R0_ - std::max(0.0, rho) / 3.0);
  ts.forward_speed_mps = v;
  ts.fx_N = traction_per_accel_ * speed_.accel(t);
  ts.road_height_m = rs.height_m;
  ts.time_s = t;
  ts.front = isFront(corner);
  return model_.tire().calcNormalForce(ts, p);
}

double HandOde::strutForce(int corner, double q, double qd) const {
  StrutState ss;
  ss.deflection_m = q;
  ss.rate_mps = qd;
  ss.preload_N = corners_[static_cast<std::size_t>(corner)].preload;
  ss.base_stiffness = values_[strut0_];
  ss.base_damping = values_[strut0_ + 1];
  return model_.strut().calcForce(ss, ParamValues(values_.data() + strut0_, nstrut_));
}

namespace {
/// R = Rx(phi) Ry(theta) and the rotation's partial angular velocities.
struct HandFrame {
  Eigen::Matrix3d R;
  Eigen::Vector3d ex{1, 0, 0}, eyp, ezc, w, wd;
  HandFrame(double phi, double theta, double phid, double thetad) {
    const double cp = std::cos(phi), sp = std::sin(phi), ct = std::cos(theta), st = std::sin(theta);
    R << ct, 0, st, sp * st, cp, -sp * ct, -cp * st, sp, cp * ct;
    eyp = Eigen::Vector3d(0, cp, sp);
    ezc = R.col(2);
    w = phid * ex + thetad * eyp;
    wd = phid * thetad * Eigen::Vector3d(0, -sp, cp);  // e_x x e_y'
  }
};
}  // namespace

void HandOde::rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) const {
  using Mat7 = Eigen::Matrix<double, kDof, kDof>;
  using Vec7 = Eigen::Matrix<double, kDof, 1>;
  const HandFrame fr(y[1], y[2], y[8], y[9]);
  const double acc = speed_.accel(t), fx = traction_per_accel_ * acc;
  Mat7 M = Mat7::Zero();
  Vec7 Q = Vec7::Zero();
  // Chassis: heave mass, rotational inertia in ground, gyroscopic and velocity-product terms.
  M(0, 0) = mc_;
  Q(0) = -mc_ * g_;
  const Eigen::Matrix3d Ig = fr.R * inertia_.asDiagonal() * fr.R.transpose();
  Eigen::Matrix<double, 3, 2> Jw;
  Jw << fr.ex, fr.eyp;
  M.block<2, 2>(1, 1) = Jw.transpose() * Ig * Jw;
  Q.segment<2>(1) = -Jw.transpose() * (Ig * fr.wd + fr.w.cross(Ig * fr.w));
  const Eigen::Vector3d ez(0, 0, 1);
  for (int c = 0; c < 4; ++c) {
    const Corner& k = corners_[static_cast<std::size_t>(c)];
    const double u = y[3 + c], ud = y[10 + c];
    const Eigen::Vector3d s = fr.R * Eigen::Vector3d(k.x, k.y, w_ + u);
    const Eigen::Vector3d cols[4] = {ez, fr.ex.cross(s), fr.eyp.cross(s), fr.ezc};
    const int idx[4] = {0, 1, 2, 3 + c};
    const Eigen::Vector3d v = y[7] * ez + fr.w.cross(s) + ud * fr.ezc;
    const Eigen::Vector3d a_bias =
        fr.wd.cross(s) + fr.w.cross(fr.w.cross(s)) + 2.0 * ud * fr.w.cross(fr.ezc);
    const double hub_z = y[0] + s.z();
    double above = 0;  // hub height above the road: the traction's lever arm
    const double fz = tireForce(c, t, s.x(), hub_z, v.z(), &above);
    // Tire (traction at the contact point: its moment about the hub), gravity, d'Alembert load.
    const Eigen::Vector3d F(fx - mw_ * acc, 0.0, fz - mw_ * g_);
    const Eigen::Vector3d load = F - mw_ * a_bias;
    for (int i = 0; i < 4; ++i) {
      Q(idx[i]) += cols[i].dot(load);
      for (int j = 0; j < 4; ++j) M(idx[i], idx[j]) += mw_ * cols[i].dot(cols[j]);
    }
    Q(2) += fr.eyp.y() * (-above * fx);  // e_y' . (0, -h fx, 0)
    M(1, 1) += iw_;
    M(2, 2) += iw_;
    Q(3 + c) -= strutForce(c, u, ud);
  }
  ydot.resize(kStates);
  ydot.head<kDof>() = y.segment<kDof>(kDof);
  ydot.tail<kDof>() = M.llt().solve(Q);
}

HandOde::Hub HandOde::hub(int corner, const Eigen::VectorXd& y, const Eigen::VectorXd& ydot) const {
  const Corner& k = corners_[static_cast<std::size_t>(corner)];
  const HandFrame fr(y[1], y[2], y[8], y[9]);
  const double ud = y[10 + corner];
  const Eigen::Vector3d s = fr.R * Eigen::Vector3d(k.x, k.y, w_ + y[3 + corner]);
  const Eigen::Vector3d ez(0, 0, 1);
  const Eigen::Vector3d v = y[7] * ez + fr.w.cross(s) + ud * fr.ezc;
  const Eigen::Vector3d a_bias =
      fr.wd.cross(s) + fr.w.cross(fr.w.cross(s)) + 2.0 * ud * fr.w.cross(fr.ezc);
  const Eigen::Vector3d a = ydot[7] * ez + ydot[8] * fr.ex.cross(s) + ydot[9] * fr.eyp.cross(s) +
                            ydot[10 + corner] * fr.ezc + a_bias;
  return {s.x(), v.x(), y[0] + s.z(), v.z(), a.z()};
}

Eigen::VectorXd HandOde::equilibrium() const {
  const ParamValues tp(values_.data() + tire0_, ntire_);
  const double wb = model_.vehicle().wheelbase();
  std::array<double, 3> target{};
  for (int c = 0; c < 3; ++c) {
    const double rho = model_.tire().calcStaticDeflection(model_.staticTireLoad(c), tp);
    target[static_cast<std::size_t>(c)] =
        road_.sampleAt(c, isFront(c) ? 0.0 : -wb).height_m + R0_ - rho;
  }
  // Newton on (heave, pitch, roll) for the FL, FR, RL hub heights: the iteration of the
  // simulator's StaticStart (its start, difference step and tolerance), so both runs start from the
  // same state.
  Eigen::VectorXd y = Eigen::VectorXd::Zero(kStates);
  auto residual = [&](const Eigen::Vector3d& x) {
    const HandFrame fr(x[2], x[1], 0.0, 0.0);
    Eigen::Vector3d r;
    for (int c = 0; c < 3; ++c) {
      const Corner& k = corners_[static_cast<std::size_t>(c)];
      r[c] =
          x[0] + (fr.R * Eigen::Vector3d(k.x, k.y, w_)).z() - target[static_cast<std::size_t>(c)];
    }
    return r;
  };
  Eigen::Vector3d x(model_.vehicle().cg_height, 0, 0);
  for (int it = 0; it < 6; ++it) {
    const Eigen::Vector3d r = residual(x);
    if (r.norm() < 1e-12) break;
    Eigen::Matrix3d Jr;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d xp = x;
      xp[j] += 1e-7;
      Jr.col(j) = (residual(xp) - r) / 1e-7;
    }
    x -= Jr.inverse() * r;
  }
  y[0] = x[0];
  y[1] = x[2];
  y[2] = x[1];
  return y;
}

// ----------------------------------------------------------------------------- a run
namespace {

double handHermite(double h, double u, double y0, double m0, double y1, double m1) {
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * h * m0 + (-2 * u3 + 3 * u2) * y1 +
         (u3 - u2) * h * m1;
}

}  // namespace

HandOdeRun runHandOde(const Model& m, const std::vector<double>& values, const Road& road,
                      const ScenarioSpec& sc, const SimulationOptions& o) {
  const auto t_start = std::chrono::steady_clock::now();
  const HandOde ode(m, values, road, sc.speed);
  RosenbrockOptions ro;  // as the simulator's Stepper::integrate sets them
  ro.accuracy = o.accuracy;
  ro.max_step_s = o.max_step_s;
  ro.max_steps = o.max_internal_steps;
  Ros34pw2Stepper st(
      [&ode](double t, const Eigen::VectorXd& y, Eigen::VectorXd& yd) { ode.rhs(t, y, yd); }, ro);
  st.initialize(0.0, ode.equilibrium());
  // Knots: per step and corner the hub's (x, xd, z, zd, zdd), as the simulator's Stepper::record.
  std::vector<double> times;
  std::vector<std::array<HandOde::Hub, 4>> knots;
  auto record = [&] {
    std::array<HandOde::Hub, 4> k;
    for (int c = 0; c < 4; ++c)
      k[static_cast<std::size_t>(c)] = ode.hub(c, st.state(), st.derivative());
    knots.push_back(k);
    times.push_back(st.time());
  };
  record();
  for (const auto& [t_end, hmax] : integrationSegments(road, sc, o, m.vehicle().wheelbase())) {
    st.setMaximumStepSize(hmax);
    while (st.time() < t_end - 1e-12) {
      st.step(t_end);
      record();
    }
  }
  // The output grid and its dense output (the simulator's Recorder::makeOutput / writeRows).
  HandOdeRun r;
  const std::size_t n =
      static_cast<std::size_t>(std::floor(times.back() * o.output_rate_hz + 1e-9)) + 1;
  r.time_s.resize(n);
  for (auto& col : r.hub_force_N) col.resize(n);
  std::size_t j = 0;
  for (std::size_t row = 0; row < n; ++row) {
    const double t = std::min(static_cast<double>(row) / o.output_rate_hz, times.back());
    while (j + 2 < times.size() && times[j + 1] < t) ++j;
    const std::size_t j1 = std::min(j + 1, times.size() - 1);
    const double h = times[j1] - times[j];
    const double u = h > 0 ? std::clamp((t - times[j]) / h, 0.0, 1.0) : 0.0;
    r.time_s[row] = t;
    for (std::size_t c = 0; c < 4; ++c) {
      const HandOde::Hub &a = knots[j][c], &b = knots[j1][c];
      const double hx = h > 0 ? handHermite(h, u, a.x, a.xd, b.x, b.xd) : a.x;
      const double hz = h > 0 ? handHermite(h, u, a.z, a.zd, b.z, b.zd) : a.z;
      const double hzd = h > 0 ? handHermite(h, u, a.zd, a.zdd, b.zd, b.zdd) : a.zd;
      r.hub_force_N[c][row] = ode.tireForce(static_cast<int>(c), t, hx, hz, hzd);
    }
  }
  r.steps = st.steps();
  r.attempts = st.attempts();
  r.evaluations = st.evaluations();
  r.jacobians = st.jacobians();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return r;
}

// ----------------------------------------------------------------------------- the benchmark
}  // namespace dtwin
