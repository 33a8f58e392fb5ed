#include "twin/simulator.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include <Simbody.h>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/validate.hpp"
#include "twin/rosenbrock.hpp"

namespace dtwin {
using namespace SimTK;

// ----------------------------------------------------------------------- options
const Registry<IntegratorMaker>& integrators() {
  using P = std::unique_ptr<Integrator>;
  static const Registry<IntegratorMaker> r(
      "integrator",
      {
          {"rosenbrock", "ROS34PW2, an L-stable Rosenbrock-W method of order 3 (the project's own; the default)", nullptr},
          {"rk-merson", "Simbody's Runge-Kutta-Merson, explicit, order 4", [](System& s) { return P(std::make_unique<RungeKuttaMersonIntegrator>(s)); }},
          {"rk3", "Simbody's Runge-Kutta 3, explicit, order 3", [](System& s) { return P(std::make_unique<RungeKutta3Integrator>(s)); }},
          {"rk-feldberg", "Simbody's Runge-Kutta-Feldberg, explicit, order 5", [](System& s) { return P(std::make_unique<RungeKuttaFeldbergIntegrator>(s)); }},
          {"cpodes", "Simbody's CPodes (SUNDIALS CVODE): BDF with Newton iterations, implicit",
           [](System& s) { return P(std::make_unique<CPodesIntegrator>(s, CPodes::BDF, CPodes::Newton)); }},
          {"semi-explicit-euler2", "Simbody's semi-explicit Euler with error control, order 2",
           [](System& s) { return P(std::make_unique<SemiExplicitEuler2Integrator>(s)); }},
      });
  return r;
}

std::vector<std::string> SimulationOptions::integratorNames() { return integrators().names(); }

void SimulationOptions::validate() const {
  const OptionCheck check("simulation");
  check.require(integrators().contains(integrator), "integrator", unknownNameRule(integrators().what(), integrator, integratorNames()));
  // Lower limits keep the work bounded: below them a run would take millions of steps (or, at a
  // step of 1e-320 s, divide by a denormal) before it failed (docs/study-file.md).
  check.require(accuracy >= 1e-10 && accuracy < 1, "accuracy", "must lie in [1e-10, 1), got " + formatNumber(accuracy));
  check.require(max_step_s >= 1e-6 && max_step_s <= 10, "max_step_s", "must lie in [1e-6, 10] s, got " + formatNumber(max_step_s));
  check.require(obstacle_max_step_s >= 1e-6 && obstacle_max_step_s <= 10, "obstacle_max_step_s",
                "must lie in [1e-6, 10] s, got " + formatNumber(obstacle_max_step_s));
  check.nonNegative("obstacle_margin_before_s", obstacle_margin_before_s);
  check.nonNegative("obstacle_margin_after_s", obstacle_margin_after_s);
  check.require(output_rate_hz > 0 && output_rate_hz <= 1e6, "output_rate_hz", "must lie in (0, 1e6], got " + formatNumber(output_rate_hz));
  check.atLeast("max_internal_steps", max_internal_steps, 1);
  check.require(max_wall_s > 0 && max_wall_s <= 1e6, "max_wall_s", "must lie in (0, 1e6] s, got " + formatNumber(max_wall_s));
}

nlohmann::json SimulationOptions::toJson() const {
  return {{"integrator", integrator},
          {"integrator_note", integrator == "rosenbrock" ? "ROS34PW2 Rosenbrock-W (Rang & Angermann 2005), twin/rosenbrock.hpp"
                                                                 : "Simbody's " + integrator + " integrator"},
          {"accuracy", accuracy},
          {"max_step_s", max_step_s},
          {"obstacle_max_step_s", obstacle_max_step_s},
          {"obstacle_margin_before_s", obstacle_margin_before_s},
          {"obstacle_margin_after_s", obstacle_margin_after_s},
          {"output_rate_hz", output_rate_hz},
          {"output_method", "cubic Hermite interpolation of states recorded at every integrator step; forces from the laws"}};
}

// ----------------------------------------------------------------------- run context
namespace {

/// Why a run failed, in words a user can act on: Simbody's own exception text (its source file,
/// line and method) is replaced; the integrators' and the laws' messages are ours already.
std::string failureInWords(const std::exception& e) {
  if (dynamic_cast<const SimTK::Exception::Base*>(&e))
    return "the multibody model could not be evaluated (Simbody refused the state: non-finite forces or a configuration it "
           "cannot realise)";
  return e.what();
}

/// Per-run data the force elements read (owned by the Simulator, set before each run).
struct RunContext {
  const double* p = nullptr;
  const Road* road = nullptr;
  SpeedProfile speed;
  double traction_per_wheel_per_accel = 0.0;  ///< M/4: traction share per unit acceleration
  /// The chassis's heave, pitch and roll coordinates at the start (setEquilibrium): ChassisForce
  /// effects read the motion from there.
  double heave0 = 0.0, pitch0 = 0.0, roll0 = 0.0;
  /// Run slots of the road signal's gain and delay (Model::roadGainSlot, roadDelaySlot).
  std::size_t gain_slot = 0, delay_slot = 0;
};

struct TireEval {
  double fz = 0, rho = 0, rho_dot = 0, road_h = 0, x_road = 0;
  double hub_above_road = 0;  ///< hub height above the (effective) road: where traction acts
};

/// The tire at one corner: shared by the Simbody force element and the output reconstruction.
struct TireCorner {
  const Model* model = nullptr;
  int corner = 0;
  std::size_t p0 = 0, np = 0;  // contiguous tire slots
  std::size_t r0 = 0;          // index of unloaded_radius_m within the tire's parameters
  std::vector<std::pair<const Effect*, std::size_t>> filters;  // tire-input effects, first slot
  std::vector<std::pair<const Effect*, std::size_t>> scalers;  // tire-force effects, first slot
  std::vector<std::pair<const Effect*, std::size_t>> loads;    // tire-load effects, first slot

  /// Where the road signal is read for a wheel at road distance x_road (the delay's read-ahead,
  /// see eval) and the forward speed of that point along the signal (hub_xd: the hub's own).
  static void signalPoint(const RunContext& c, double t, double x_road, double hub_xd, double& x, double& contact_speed) {
    const double delay = c.p[c.delay_slot];
    x = x_road;
    if (delay == 0.0) {
      contact_speed = c.speed.speed(t) + hub_xd;
      return;
    }
    x += c.speed.distance(t + delay) - c.speed.distance(t);
    contact_speed = c.speed.speed(t + delay) + hub_xd;
  }
  /// The road signal's vertical velocity under the wheel (gain and delay applied, before
  /// tire-input effects) [m/s]: what a road-velocity feed-forward reads.
  double roadRate(const RunContext& c, double t, double hub_x, double hub_xd) const {
    double x = 0.0, contact_speed = 0.0;
    signalPoint(c, t, c.speed.distance(t) + hub_x - model->vehicle().a, hub_xd, x, contact_speed);
    return c.p[c.gain_slot] * c.road->sample(cornerTrack(corner), x).slope * contact_speed;
  }
  TireEval eval(const RunContext& c, double t, double hub_x, double hub_xd, double hub_z, double hub_zd) const {
    TireEval e;
    const ParamValues p(c.p + p0, np);
    const double v = c.speed.speed(t);
    e.x_road = c.speed.distance(t) + hub_x - model->vehicle().a;
    const Track tr = cornerTrack(corner);
    // The road signal's delay d relative to the measured channels (positive: logged late) and its
    // gain g: the wheel meets g h(x + s(t + d) - s(t)), read ahead by the distance travelled in d
    // (docs/model.md, "The road signal's gain and delay"). At d = 0 and g = 1 exactly the road.
    const double gain = c.p[c.gain_slot];
    double x = 0.0, contact_speed = 0.0;
    signalPoint(c, t, e.x_road, hub_xd, x, contact_speed);
    RoadSample rs = c.road->sample(tr, x);
    e.road_h = rs.height_m;  // the road under the wheel, before tire-input effects
    for (auto& [eff, s] : filters) rs = eff->filterRoad(*c.road, tr, x, ParamValues(c.p + s, eff->parameters().size()));
    if (gain != 1.0) {
      rs.height_m *= gain;
      rs.slope *= gain;
      e.road_h *= gain;
    }
    const double R0 = p[r0];
    e.hub_above_road = hub_z - rs.height_m;
    e.rho = R0 - e.hub_above_road;
    const double road_rate = rs.slope * contact_speed;
    e.rho_dot = road_rate - hub_zd;
    TireState ts;
    ts.deflection_m = e.rho;
    // Damping acts on the hub's vertical velocity, -dz_hub/dt (paper eq. 2, "- b z'"). With
    // single-point contact the full deflection rate would carry the road slope times the speed
    // (56 m/s over the 100 mm bump): an unphysical damping spike a real tire never sees.
    ts.deflection_rate_mps = -hub_zd;
    ts.wheel_speed_radps = v / (R0 - std::max(0.0, e.rho) / 3.0);
    ts.forward_speed_mps = v;
    ts.fx_N = c.traction_per_wheel_per_accel * c.speed.accel(t);
    ts.road_height_m = e.road_h;
    ts.road_rate_mps = road_rate;
    ts.time_s = t;
    ts.front = isFront(corner);
    e.fz = model->tire().calcNormalForce(ts, p);
    for (auto& [eff, s] : scalers) e.fz *= eff->tireForceFactor(ts, ParamValues(c.p + s, eff->parameters().size()));
    if (!loads.empty() && e.rho > 0) {  // added at a wheel in contact; the tire cannot pull
      ts.normal_force_N = e.fz;
      double add = 0.0;
      for (auto& [eff, s] : loads) add += eff->calcTireLoad(ts, ParamValues(c.p + s, eff->parameters().size()));
      e.fz = std::max(0.0, e.fz + add);
    }
    return e;
  }
};

class TireElement : public Force::Custom::Implementation {
 public:
  TireElement(const RunContext* ctx, TireCorner tc, MobilizedBody wheel) : ctx_(ctx), tc_(std::move(tc)), wheel_(wheel) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector&) const override {
    const Vec3 p = wheel_.getBodyOriginLocation(s), v = wheel_.getBodyOriginVelocity(s);
    const double t = s.getTime();
    const TireEval e = tc_.eval(*ctx_, t, p[0], v[0], p[2], v[2]);
    const double fx = ctx_->traction_per_wheel_per_accel * ctx_->speed.accel(t);
    SpatialVec& F = bodyForces[wheel_.getMobilizedBodyIndex()];
    F[1] += Vec3(fx, 0, e.fz);
    // Traction acts at the contact point, a height (hub_z - road) below the hub.
    F[0] += Vec3(0, -e.hub_above_road * fx, 0);
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const RunContext* ctx_;
  TireCorner tc_;
  MobilizedBody wheel_;
};

struct StrutGeometry {
  MobilizedBody upper, lower;
  Vec3 st_upper, st_lower;
  /// When `lower` is a Slider on `upper` whose axis is upper's z through st_upper, the strut
  /// length change is exactly the slider coordinate: read q, u, u-dot from the State directly
  /// (no kinematics through Simbody's body caches), and apply the force as a mobility force.
  bool is_slider = false;
  QIndex qi{};
  UIndex ui{};
  struct Kin {
    double q, qd;
  };
  /// A solid axle's spring seat: the axle hangs on a Slider (heave along the chassis z) and a
  /// Pin (roll about the chassis x) with the seat at lateral offset `seat_y` on the axle. The seat
  /// moves along the chassis z by q_h + y sin(phi): read q, u from the State. The force is applied
  /// as the generalized forces of that pair (virtual work of a force along the chassis z).
  bool is_axle_seat = false;
  QIndex qh{}, qr{};
  UIndex uh{}, ur{};
  double seat_y = 0;
  Kin kin(const State& s) const {
    if (is_slider) return {s.getQ()[qi], s.getU()[ui]};
    if (is_axle_seat) {
      const double phi = s.getQ()[qr];
      return {s.getQ()[qh] + seat_y * std::sin(phi), s.getU()[uh] + seat_y * std::cos(phi) * s.getU()[ur]};
    }
    const Vec3 pu = upper.findStationLocationInGround(s, st_upper), pl = lower.findStationLocationInGround(s, st_lower);
    const Vec3 vu = upper.findStationVelocityInGround(s, st_upper), vl = lower.findStationVelocityInGround(s, st_lower);
    const UnitVec3 z = upper.getBodyRotation(s).z();
    const Vec3 w = upper.getBodyAngularVelocity(s);
    const Vec3 d = pl - pu;
    return {~d * Vec3(z), ~(vl - vu) * Vec3(z) + ~d * (w % Vec3(z))};
  }
  double accel(const State& s) const {
    if (is_slider) return s.getUDot()[ui];
    if (is_axle_seat) {
      const double phi = s.getQ()[qr], w = s.getU()[ur];
      return s.getUDot()[uh] + seat_y * (std::cos(phi) * s.getUDot()[ur] - std::sin(phi) * w * w);
    }
    const Vec3 au = upper.findStationAccelerationInGround(s, st_upper), al = lower.findStationAccelerationInGround(s, st_lower);
    return ~(al - au) * Vec3(upper.getBodyRotation(s).z());
  }
  /// Applies the strut force F (positive pushes the ends apart along upper's z).
  void apply(const State& s, double F, Vector_<SpatialVec>& bodyForces, Vector& mobilityForces) const {
    if (is_slider) {
      mobilityForces[ui] -= F;  // compression positive: the force pushes the slider back down
      return;
    }
    if (is_axle_seat) {
      mobilityForces[uh] -= F;
      mobilityForces[ur] -= F * seat_y * std::cos(s.getQ()[qr]);
      return;
    }
    const Vec3 z(upper.getBodyRotation(s).z());
    upper.applyForceToBodyPoint(s, st_upper, F * z, bodyForces);
    lower.applyForceToBodyPoint(s, st_lower, -F * z, bodyForces);
  }
  /// Call after realizeTopology for solid-axle spring seats (`slider` carries `pin`).
  void bindAxleSeat(const State& s, const MobilizedBody& slider, const MobilizedBody& pin, double y) {
    is_axle_seat = true;
    qh = slider.getFirstQIndex(s);
    uh = slider.getFirstUIndex(s);
    qr = pin.getFirstQIndex(s);
    ur = pin.getFirstUIndex(s);
    seat_y = y;
  }
  /// Call after realizeTopology for slider struts.
  void bindSlider(const State& s) {
    is_slider = true;
    qi = lower.getFirstQIndex(s);
    ui = lower.getFirstUIndex(s);
  }
};

class StrutElement : public Force::Custom::Implementation {
 public:
  /// `filter_states`: allocate one auxiliary state (a Z of `sub`) per installed StrutFilter effect.
  StrutElement(const RunContext* ctx, const Model* m, const StrutLaw* law, StrutGeometry g, std::size_t p0, int preload_slot,
               double preload, bool with_effects, bool filter_states = false, SubsystemIndex sub = SubsystemIndex())
      : ctx_(ctx), m_(m), law_(law), g_(g), p0_(p0), preload_slot_(preload_slot), preload_(preload), effects_(with_effects), sub_(sub) {
    if (with_effects && filter_states)
      for (std::size_t i = 0; i < m->effects().size(); ++i)
        if (m->effects()[i]->kind() == EffectKind::StrutFilter) filter_effects_.push_back(i);
    if (with_effects)
      for (const auto& e : m->effects()) {
        const bool strut = e->kind() == EffectKind::Strut || e->kind() == EffectKind::StrutFilter;
        context_ = context_ || strut;
        motion_ = motion_ || (strut && e->needsMotion());
      }
  }
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector& mobilityForces) const override {
    const auto k = g_.kin(s);
    const StrutState ss = strutState(s, k);
    double F = force(ss);
    if (!filter_effects_.empty()) {
      const Vector& z = s.getZ(sub_);
      for (std::size_t j = 0; j < filter_effects_.size(); ++j) {
        const std::size_t i = filter_effects_[j];
        F += m_->effects()[i]->calcFilteredStrutForce(ss, z[zi_[j]], effectValues(i));
      }
    }
    g_.apply(s, F, bodyForces, mobilityForces);
  }
  void realizeTopology(State& s) const override {
    zi_.clear();
    for (std::size_t j = 0; j < filter_effects_.size(); ++j) zi_.push_back(s.allocateZ(sub_, Vector(1, 0.0)));
  }
  /// The auxiliary states' derivatives (z = 0 at rest: the equilibrium start needs no setting).
  void realizeAcceleration(const State& s) const override {
    if (filter_effects_.empty()) return;
    const StrutState ss = strutState(s, g_.kin(s));
    const Vector& z = s.getZ(sub_);
    Vector& zd = s.updZDot(sub_);
    for (std::size_t j = 0; j < filter_effects_.size(); ++j) {
      const std::size_t i = filter_effects_[j];
      zd[zi_[j]] = m_->effects()[i]->calcFilterRate(ss, z[zi_[j]], effectValues(i));
    }
  }
  /// Binds slider struts to their state indices (after realizeTopology).
  void bind(const State& s) {
    if (bind_slider_) g_.bindSlider(s);
    if (!seat_slider_.isEmptyHandle()) g_.bindAxleSeat(s, seat_slider_, seat_pin_, seat_y_);
  }
  bool bind_slider_ = false;
  MobilizedBody seat_slider_, seat_pin_;
  double seat_y_ = 0;
  /// A main strut's axle partner (the other main strut on its axle) and axle: the context its
  /// effects read (StrutState's time, speed and other_*). Unset on interface elements.
  const StrutGeometry* partner_ = nullptr;
  bool front_ = true;
  /// A main strut's tire and wheel: the road signal under it, for effects that read the motion.
  const TireCorner* tire_ = nullptr;
  MobilizedBody wheel_;
  StrutState strutState(const State& s, const StrutGeometry::Kin& k) const {
    const double* p = ctx_->p;
    StrutState ss;
    ss.deflection_m = k.q;
    ss.rate_mps = k.qd;
    ss.preload_N = preload_slot_ >= 0 ? p[preload_slot_] : preload_;
    ss.base_stiffness = p[p0_];
    ss.base_damping = p[p0_ + 1];
    if (context_ && partner_) {
      const auto o = partner_->kin(s);
      ss.other_deflection_m = o.q;
      ss.other_rate_mps = o.qd;
      ss.time_s = s.getTime();
      ss.speed_mps = ctx_->speed.speed(ss.time_s);
      ss.front = front_;
      if (motion_) {
        ss.body_velocity_mps = g_.upper.findStationVelocityInGround(s, g_.st_upper)[2];
        ss.wheel_velocity_mps = g_.lower.findStationVelocityInGround(s, g_.st_lower)[2];
        ss.road_velocity_mps =
            tire_->roadRate(*ctx_, ss.time_s, wheel_.getBodyOriginLocation(s)[0], wheel_.getBodyOriginVelocity(s)[0]);
      }
    }
    return ss;
  }
  ParamValues effectValues(std::size_t i) const {
    return ParamValues(ctx_->p + m_->effectSlots()[i][0], m_->effects()[i]->parameters().size());
  }
  /// Strut force without the StrutFilter effects (they need the State's auxiliary variables).
  double force(const StrutState& ss) const {
    const double* p = ctx_->p;
    double F = law_->calcForce(ss, ParamValues(p + p0_, law_->parameters().size()));
    if (effects_) {
      const auto& effs = m_->effects();
      for (std::size_t i = 0; i < effs.size(); ++i)
        if (effs[i]->kind() == EffectKind::Strut)
          F += effs[i]->calcStrutForce(ss, ParamValues(p + m_->effectSlots()[i][0], effs[i]->parameters().size()));
    }
    return F;
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const RunContext* ctx_;
  const Model* m_;
  const StrutLaw* law_;
  StrutGeometry g_;
  std::size_t p0_;
  int preload_slot_;
  double preload_;
  bool effects_;
  bool context_ = false;  ///< a strut effect is installed: fill StrutState's context
  bool motion_ = false;   ///< ... and one reads the absolute motion (Effect::needsMotion)
  SubsystemIndex sub_;
  std::vector<std::size_t> filter_effects_;  // indices into the model's effects
  mutable std::vector<ZIndex> zi_;           // their auxiliary states (set in realizeTopology)
};

/// An AxleCoupling effect on one axle: a force pair on the left and right main struts computed
/// from both deflections (kin()/apply() of the two corners' StrutGeometry: MacPherson sliders or
/// solid-axle spring seats). Installed only when such an effect is.
class AxleCouplingElement : public Force::Custom::Implementation {
 public:
  AxleCouplingElement(const RunContext* ctx, const Effect* eff, std::size_t slot, const StrutGeometry* left,
                      const StrutGeometry* right, bool front)
      : ctx_(ctx), eff_(eff), slot_(slot), left_(left), right_(right), front_(front) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector& mobilityForces) const override {
    const auto l = left_->kin(s), r = right_->kin(s);
    AxleState a;
    a.q_left = l.q;
    a.q_right = r.q;
    a.v_left = l.qd;
    a.v_right = r.qd;
    a.front = front_;
    a.time_s = s.getTime();
    a.speed_mps = ctx_->speed.speed(a.time_s);
    const double F = eff_->calcAxleForce(a, ParamValues(ctx_->p + slot_, eff_->parameters().size()));
    if (F == 0.0) return;
    left_->apply(s, F, bodyForces, mobilityForces);
    right_->apply(s, -F, bodyForces, mobilityForces);
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const RunContext* ctx_;
  const Effect* eff_;
  std::size_t slot_;
  const StrutGeometry *left_, *right_;  // the Impl's struts (bound after realizeTopology)
  bool front_;
};

/// A ChassisForce effect: a vertical force on the chassis at its mass centre (its body origin),
/// from the heave, pitch and roll coordinates relative to the start. Installed only when such an
/// effect is.
class ChassisForceElement : public Force::Custom::Implementation {
 public:
  /// `heave`: the chassis's vertical Slider; `chassis`: its Universal (q0 roll, q1 pitch).
  ChassisForceElement(const RunContext* ctx, const Effect* eff, std::size_t slot, MobilizedBody heave, MobilizedBody chassis)
      : ctx_(ctx), eff_(eff), slot_(slot), heave_(heave), chassis_(chassis) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector&) const override {
    ChassisState c;
    c.heave_m = heave_.getOneQ(s, 0) - ctx_->heave0;
    c.heave_rate_mps = heave_.getOneU(s, 0);
    c.pitch_rad = chassis_.getOneQ(s, 1) - ctx_->pitch0;
    c.roll_rad = chassis_.getOneQ(s, 0) - ctx_->roll0;
    c.time_s = s.getTime();
    c.speed_mps = ctx_->speed.speed(c.time_s);
    const double F = eff_->calcChassisForce(c, ParamValues(ctx_->p + slot_, eff_->parameters().size()));
    if (F != 0.0) bodyForces[chassis_.getMobilizedBodyIndex()][1] += Vec3(0, 0, F);
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const RunContext* ctx_;
  const Effect* eff_;
  std::size_t slot_;
  MobilizedBody heave_, chassis_;
};

/// Gravity plus the d'Alembert load of the accelerating vehicle frame: m (-g z - a(t) x) at every
/// massive body's mass centre (each body's origin is its mass centre). One element instead of
/// Simbody's UniformGravity, which walks every body's mass properties on each evaluation.
class BodyLoadElement : public Force::Custom::Implementation {
 public:
  BodyLoadElement(const RunContext* ctx, const std::vector<std::pair<MobilizedBody, double>>& bodies, double g) : ctx_(ctx), g_(g) {
    for (auto& [b, m] : bodies) bodies_.push_back({b.getMobilizedBodyIndex(), m});
  }
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector&) const override {
    const double a = ctx_->speed.accel(s.getTime());
    for (auto& [i, m] : bodies_) bodyForces[i][1] += Vec3(-m * a, 0, -m * g_);
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const RunContext* ctx_;
  double g_;
  std::vector<std::pair<MobilizedBodyIndex, double>> bodies_;
};

std::size_t contiguous(const std::vector<int>& slots) {
  DTWIN_CHECK(!slots.empty(), "empty slot list");
  for (std::size_t i = 1; i < slots.size(); ++i) DTWIN_CHECK(slots[i] == slots[0] + static_cast<int>(i), "slots not contiguous");
  return static_cast<std::size_t>(slots[0]);
}

/// A replayed step whose error norm exceeds this is split (Impl::integrate).
/// A replayed step whose error norm (RosenbrockOptions::accuracy) exceeds this is split into
/// equal parts (Impl::integrate): a safety net for parameters far from those the steps were
/// chosen at. Near them the error norms stay below it (the controller aims at about 0.7), so a
/// replay there is a smooth function of the parameters; a lower value (1) split steps at
/// neighbouring parameters and made the SSE as jagged as an adaptive one.
constexpr double kReplayRefine = 8.0;

// Knot layout (one recorded integrator state).
enum : std::size_t { HX = 0, HXD = 4, HZ = 8, HZD = 12, HZDD = 16, Q = 20, QD = 24, QDD = 28,
                     BODY = 32 /* heave, pitch, roll: value, rate, accel (3 each) */, KNOT = 41 };

double hermite(double h, double u, double y0, double m0, double y1, double m1) {
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * h * m0 + (-2 * u3 + 3 * u2) * y1 + (u3 - u2) * h * m1;
}
double hermiteD(double h, double u, double y0, double m0, double y1, double m1) {
  const double u2 = u * u;
  return ((6 * u2 - 6 * u) * y0 + (-6 * u2 + 6 * u) * y1) / h + (3 * u2 - 4 * u + 1) * m0 + (3 * u2 - 2 * u) * m1;
}

}  // namespace

// ----------------------------------------------------------------------- Impl
struct Simulator::Impl {
  std::shared_ptr<const Model> model;
  SimulationOptions opt;
  RunContext ctx;
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  MobilizedBody::Slider heave;
  MobilizedBody::Universal chassis;
  std::array<MobilizedBody, 4> wheels;
  std::array<MobilizedBody, 2> axle_slider, axle;  // solid axle only
  std::array<StrutGeometry, 4> struts;               // main suspension strut per corner
  std::array<const StrutElement*, 4> strut_elems{};
  std::array<TireCorner, 4> tires;
  std::array<double, 4> strut_preload{};
  State default_state;
  QIndex heave_q, chassis_q;
  UIndex heave_u, chassis_u;

  /// With StrutFilter effects installed, `filter_states` selects the system that integrates their
  /// auxiliary states (used for runs where such an effect is active); without, they are inert.
  bool filter_states = false;

  Impl(std::shared_ptr<const Model> m, SimulationOptions o, bool with_filter_states = false)
      : model(std::move(m)), opt(std::move(o)), filter_states(with_filter_states) {
    opt.validate();
    build();
  }

  void build() {
    const Model& M = *model;
    const VehicleData& d = M.vehicle();
    std::vector<StrutElement*> slider_elems;
    const Rotation xToZ(-Pi / 2, YAxis);  // a slider's x axis along the parent's z
    const Rotation zToX(Pi / 2, YAxis);   // a pin's z axis along the parent's x
    heave = MobilizedBody::Slider(matter.Ground(), Transform(xToZ), Body::Massless(), Transform(xToZ));
    chassis = MobilizedBody::Universal(heave, Transform(), Body::Rigid(MassProperties(d.chassis_mass, Vec3(0), Inertia(d.ixx, d.iyy, d.izz))), Transform());
    const double z_wc = -(d.cg_height - M.table().value("tire.unloaded_radius_m"));  // wheel centre below CG
    const Body::Rigid wheelBody(MassProperties(d.wheel_mass, Vec3(0), Inertia(1e-3)));
    std::vector<std::pair<MobilizedBody, double>> massive = {{chassis, d.chassis_mass}};
    for (int c = 0; c < 4; ++c) {
      const double x = isFront(c) ? d.a : -d.b;
      const double y = (cornerTrack(c) == Track::Left ? 0.5 : -0.5) * d.track;
      strut_preload[c] = M.staticStrutForce(c);
      if (M.topology() == SuspensionTopology::MacPherson) {
        wheels[c] = MobilizedBody::Slider(chassis, Transform(xToZ, Vec3(x, y, z_wc)), wheelBody, Transform(xToZ));
        struts[c] = {chassis, wheels[c], Vec3(x, y, z_wc), Vec3(0)};
      }
    }
    if (M.topology() == SuspensionTopology::SolidAxle) {
      const Body::Rigid axleBody(MassProperties(d.axle_mass, Vec3(0), Inertia(d.axle_ixx, d.axle_ixx, d.axle_ixx)));
      for (int ax = 0; ax < 2; ++ax) {
        const double x = ax == 0 ? d.a : -d.b;
        axle_slider[ax] = MobilizedBody::Slider(chassis, Transform(xToZ, Vec3(x, 0, z_wc)), Body::Massless(), Transform(xToZ));
        axle[ax] = MobilizedBody::Pin(axle_slider[ax], Transform(zToX), axleBody, Transform(zToX));
        massive.push_back({axle[ax], d.axle_mass});
        for (int side = 0; side < 2; ++side) {
          const int c = 2 * ax + side;
          const double sgn = side == 0 ? 1.0 : -1.0;
          wheels[c] = MobilizedBody::Slider(axle[ax], Transform(xToZ, Vec3(0, sgn * 0.5 * d.track, 0)), wheelBody, Transform(xToZ));
          struts[c] = {chassis, axle[ax], Vec3(x, sgn * 0.5 * d.spring_track, z_wc), Vec3(0, sgn * 0.5 * d.spring_track, 0)};
          // Wheel/axle compliant interface (paper eq. 5): no effects, preload from the data.
          StrutGeometry iface{axle[ax], wheels[c], Vec3(0, sgn * 0.5 * d.track, 0), Vec3(0)};
          auto* ie = new StrutElement(&ctx, &M, &M.interfaceLaw(), iface, contiguous(M.interfaceSlots()), M.interfacePreloadSlot(), 0.0, false);
          ie->bind_slider_ = true;  // the wheel slides on the axle along the axle's z
          slider_elems.push_back(ie);
          Force::Custom(forces, ie);
        }
      }
    }
    for (int c = 0; c < 4; ++c) {
      massive.push_back({wheels[c], d.wheel_mass});
      auto* se = new StrutElement(&ctx, &M, &M.strut(), struts[c], contiguous(M.suspensionSlots()), -1, strut_preload[c], true,
                                  filter_states, forces.getMySubsystemIndex());
      strut_elems[c] = se;
      if (M.topology() == SuspensionTopology::MacPherson) {
        se->bind_slider_ = true;  // the wheel carrier slides along the chassis z at the strut
      } else {
        const int ax = c / 2;
        se->seat_slider_ = axle_slider[ax];
        se->seat_pin_ = axle[ax];
        se->seat_y_ = struts[c].st_lower[1];
      }
      se->partner_ = &struts[c ^ 1];  // corners 2 ax + side: the other side of the axle
      se->front_ = isFront(c);
      se->tire_ = &tires[static_cast<std::size_t>(c)];
      se->wheel_ = wheels[c];
      slider_elems.push_back(se);
      Force::Custom(forces, se);
      TireCorner tc;
      tc.model = &M;
      tc.corner = c;
      tc.p0 = contiguous(M.tireSlots());
      tc.np = M.tireSlots().size();
      tc.r0 = parameterIndex(M.tire().parameters(), "unloaded_radius_m");
      for (std::size_t i = 0; i < M.effects().size(); ++i)
        if (M.effects()[i]->kind() == EffectKind::TireInput)
          tc.filters.push_back({M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
        else if (M.effects()[i]->kind() == EffectKind::TireForce)
          tc.scalers.push_back({M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
        else if (M.effects()[i]->kind() == EffectKind::TireLoad)
          tc.loads.push_back({M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0])});
      tires[c] = tc;
      Force::Custom(forces, new TireElement(&ctx, tc, wheels[c]));
    }
    for (std::size_t i = 0; i < M.effects().size(); ++i)
      if (M.effects()[i]->kind() == EffectKind::AxleCoupling)
        for (int ax = 0; ax < 2; ++ax)
          Force::Custom(forces, new AxleCouplingElement(&ctx, M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0]),
                                                        &struts[2 * ax], &struts[2 * ax + 1], ax == 0));
    for (std::size_t i = 0; i < M.effects().size(); ++i)
      if (M.effects()[i]->kind() == EffectKind::ChassisForce)
        Force::Custom(forces, new ChassisForceElement(&ctx, M.effects()[i].get(), static_cast<std::size_t>(M.effectSlots()[i][0]), heave, chassis));
    Force::Custom(forces, new BodyLoadElement(&ctx, massive, d.gravity));
    ctx.traction_per_wheel_per_accel = d.total_mass(M.topology()) / 4.0;
    system.realizeTopology();
    default_state = system.getDefaultState();
    for (auto* e : slider_elems) e->bind(default_state);
    heave_q = heave.getFirstQIndex(default_state);
    heave_u = heave.getFirstUIndex(default_state);
    chassis_q = chassis.getFirstQIndex(default_state);
    chassis_u = chassis.getFirstUIndex(default_state);
    for (int c = 0; c < 4; ++c) {
      if (M.topology() == SuspensionTopology::MacPherson) struts[c].bindSlider(default_state);
      else struts[c].bindAxleSeat(default_state, axle_slider[c / 2], axle[c / 2], struts[c].st_lower[1]);
    }
  }

  /// Static equilibrium at t = 0 for the run parameters in ctx (vehicle at rest, flat start).
  void setEquilibrium(State& s) {
    const Model& M = *model;
    const VehicleData& d = M.vehicle();
    const ParamValues tp(ctx.p + tires[0].p0, tires[0].np);
    const double R0 = M.tire().unloadedRadius(tp);
    std::array<double, 4> target{};
    for (int c = 0; c < 4; ++c) {
      const double rho = M.tire().calcStaticDeflection(M.staticTireLoad(c), tp);
      const double x_road = -(isFront(c) ? 0.0 : d.wheelbase());
      const double delay = ctx.p[ctx.delay_slot], shift = delay != 0.0 ? ctx.speed.distance(delay) - ctx.speed.distance(0.0) : 0.0;
      target[c] = ctx.p[ctx.gain_slot] * ctx.road->sample(cornerTrack(c), x_road + shift).height_m + R0 - rho;
      if (M.topology() == SuspensionTopology::SolidAxle) {
        const double* p = ctx.p;
        const double k = p[M.interfaceSlots()[0]], F0 = p[M.interfacePreloadSlot()];
        const double q = (M.staticTireLoad(c) - d.wheel_mass * d.gravity - F0) / k;
        wheels[c].setOneQ(s, 0, q);
      }
    }
    // Newton on (heave, pitch, roll) so that the FL, FR, RL hubs sit at their targets.
    auto residual = [&](const Vec3& x) {
      heave.setOneQ(s, 0, x[0]);
      chassis.setOneQ(s, 0, x[2]);  // roll
      chassis.setOneQ(s, 1, x[1]);  // pitch
      system.realize(s, Stage::Position);
      return Vec3(wheels[0].getBodyOriginLocation(s)[2] - target[0], wheels[1].getBodyOriginLocation(s)[2] - target[1],
                  wheels[2].getBodyOriginLocation(s)[2] - target[2]);
    };
    Vec3 x(d.cg_height, 0, 0);
    for (int it = 0; it < 6; ++it) {
      const Vec3 r = residual(x);
      if (r.norm() < 1e-12) break;
      Mat33 J;
      for (int j = 0; j < 3; ++j) {
        Vec3 xp = x;
        xp[j] += 1e-7;
        J(j) = (residual(xp) - r) / 1e-7;
      }
      x -= J.invert() * r;
    }
    residual(x);
    s.updU() = 0;
    system.realize(s, Stage::Velocity);
    ctx.heave0 = x[0];
    ctx.pitch0 = x[1];
    ctx.roll0 = x[2];
  }

  void record(const State& s, std::vector<std::array<double, KNOT>>& knots, std::vector<double>& times) {
    system.realize(s, Stage::Acceleration);  // a no-op after an integrator step (already realized)
    std::array<double, KNOT> k{};
    for (int c = 0; c < 4; ++c) {
      const Vec3 p = wheels[c].getBodyOriginLocation(s), v = wheels[c].getBodyOriginVelocity(s);
      const Vec3 a = wheels[c].getBodyOriginAcceleration(s);
      k[HX + c] = p[0];
      k[HXD + c] = v[0];
      k[HZ + c] = p[2];
      k[HZD + c] = v[2];
      k[HZDD + c] = a[2];
      const auto kin = struts[c].kin(s);
      k[Q + c] = kin.q;
      k[QD + c] = kin.qd;
      k[QDD + c] = struts[c].accel(s);
    }
    // Heave (slider) and pitch/roll (universal) coordinates: their q-dot is u, so read the State.
    const Vector &q = s.getQ(), &u = s.getU(), &ud = s.getUDot();
    const double vals[9] = {q[heave_q], u[heave_u], ud[heave_u],
                            q[chassis_q + 1], u[chassis_u + 1], ud[chassis_u + 1],
                            q[chassis_q], u[chassis_u], ud[chassis_u]};
    for (int i = 0; i < 9; ++i) k[BODY + i] = vals[i];
    knots.push_back(k);
    times.push_back(s.getTime());
  }

  std::unique_ptr<Integrator> makeIntegrator(const std::string& method) { return integrators().at(method, "simulation.integrator").value(system); }

  /// Time windows in which a wheel crosses an obstacle (merged, clipped).
  using Knots = std::vector<std::array<double, KNOT>>;
  using Segments = std::vector<std::pair<double, double>>;  // (end time, max step)

  /// Validates the run vector and the scenario and points the force elements at them.
  void begin(const std::vector<double>& values, const Road& road, const ScenarioSpec& sc) {
    const Model& M = *model;
    if (values.size() != M.runParameterNames().size())
      throw InputError("run parameters", "expected " + std::to_string(M.runParameterNames().size()) + " values");
    const std::string rule = M.checkRunValues(values);
    if (!rule.empty()) throw InputError("run parameters", rule);
    if (!(sc.duration_s > 0)) throw InputError("scenario " + sc.name, "duration_s must be > 0");
    ctx.p = values.data();
    ctx.road = &road;
    ctx.speed = sc.speed;
    ctx.gain_slot = static_cast<std::size_t>(M.roadGainSlot());
    ctx.delay_slot = static_cast<std::size_t>(M.roadDelaySlot());
  }

  /// The branch time of a random road with a smooth start (smooth_until_s - margin), or a
  /// negative value when the scenario has none.
  double branchTime(const ScenarioSpec& sc) const {
    if (const double t = sc.road->roughStart_s(); t > 0) return t - opt.obstacle_margin_before_s;
    return -1.0;
  }

  /// Integration segments with their step bound (integrationSegments, simulator.hpp).
  Segments segments(const Road& road, const ScenarioSpec& sc) const {
    return integrationSegments(road, sc, opt, model->vehicle().wheelbase());
  }

  /// Integrates from `s0` through segments [i0, i1) of `segs`, appending a knot per step (and one
  /// for `s0` itself when `record_start`). Never throws for a diverging run: ok = false and the
  /// message say why. On success `end` (if given) receives the final State.
  RunStats integrate(const State& s0, const Segments& segs, std::size_t i0, std::size_t i1, bool record_start, Knots& knots,
                     std::vector<double>& times, State* end, StepControl steps = {}) {
    RunStats st;
    const std::string& method = opt.integrator;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(opt.max_wall_s);
    long checks = 0;
    auto checkFinite = [&](double time) {
      for (double v : knots.back())
        if (!std::isfinite(v)) throw std::runtime_error("state became non-finite at t = " + std::to_string(time) + " s");
      if (++checks % 256 == 0 && std::chrono::steady_clock::now() > deadline)
        throw std::runtime_error("the run took longer than " + formatNumber(opt.max_wall_s) +
                                 " s of wall time (simulation.max_wall_s) at t = " + std::to_string(time) + " s");
    };
    if (method == "rosenbrock") {
      RosenbrockOptions ro;
      ro.accuracy = opt.accuracy;
      ro.max_step_s = opt.max_step_s;
      ro.max_steps = opt.max_internal_steps;
      RosenbrockIntegrator integ(system, ro);
      try {
        integ.initialize(s0);
        if (record_start) record(integ.getState(), knots, times);
        if (steps.record) *steps.record = StepPlan{};
        std::size_t k = 0;  // next step of a replayed plan
        const StepPlan* plan = steps.replay;
        if (plan) {  // skip the plan's steps before s0 (never the case for a whole run)
          while (k < plan->size() && plan->times[k] <= s0.getTime() + 1e-12) ++k;
        }
        for (std::size_t i = i0; i < i1; ++i) {
          const auto [t_end, hmax] = segs[i];
          integ.setMaximumStepSize(hmax);
          while (integ.getTime() < t_end - 1e-12) {
            if (plan) {
              if (k >= plan->size() || plan->times[k] > t_end + 1e-12)
                throw std::runtime_error("the frozen step sequence does not fit this scenario (" +
                                         (k >= plan->size() ? std::string("it ends at t = ") + formatNumber(integ.getTime()) + " s"
                                                            : "no step ends at the segment end t = " + formatNumber(t_end) + " s") +
                                         "); it was recorded on another scenario or road");
              // A planned step far too large for these parameters (its error norm above
              // kReplayRefine) is split into m equal parts, m from the error's third-order growth;
              // the rest are replayed as they are.
              const double t_k = plan->times[k];
              const double e = integ.stepToIfAccurate(t_k, plan->new_jacobian[k] != 0, kReplayRefine);
              ++k;
              if (!(e <= kReplayRefine)) {
                const int m = std::isfinite(e) ? std::clamp(static_cast<int>(std::ceil(1.25 * std::cbrt(e))), 2, 64) : 16;
                const double t0 = integ.getTime();
                for (int j = 1; j < m; ++j) {
                  integ.stepTo(t0 + (t_k - t0) * j / m, false);
                  record(integ.getState(), knots, times);
                  checkFinite(integ.getTime());
                }
                integ.stepTo(t_k, false);
              }
            } else {
              integ.step(t_end);
            }
            if (steps.record) {
              steps.record->times.push_back(integ.getTime());
              steps.record->new_jacobian.push_back(integ.lastStepNewJacobian() ? 1 : 0);
            }
            record(integ.getState(), knots, times);
            checkFinite(integ.getTime());
          }
        }
        if (end) *end = integ.getState();
      } catch (const std::exception& e) {
        st.ok = false;
        st.message = oneLine("simulation failed: " + failureInWords(e));
      }
      st.steps = integ.steps();
      st.steps_attempted = integ.attempts();
    } else {
      auto integ = makeIntegrator(method);
      integ->setAccuracy(opt.accuracy);
      integ->setReturnEveryInternalStep(true);
      integ->setInternalStepLimit(0);
      integ->setMaximumStepSize(opt.max_step_s);
      try {
        integ->initialize(s0);
        if (record_start) record(integ->getState(), knots, times);
        for (std::size_t i = i0; i < i1; ++i) {
          const auto [t_end, hmax] = segs[i];
          integ->setMaximumStepSize(hmax);
          while (integ->getTime() < t_end - 1e-12) {
            const auto status = integ->stepTo(t_end, t_end);
            if (integ->isSimulationOver() && integ->getTerminationReason() == Integrator::AnUnrecoverableErrorOccurred)
              throw std::runtime_error("integrator failed");
            if (status == Integrator::TimeHasAdvanced || status == Integrator::ReachedScheduledEvent ||
                status == Integrator::ReachedReportTime) {
              const State& s = integ->getState();
              if (times.empty() || s.getTime() > times.back()) record(s, knots, times);
            }
            if (integ->getNumStepsTaken() > opt.max_internal_steps)
              throw std::runtime_error("more than " + std::to_string(opt.max_internal_steps) + " integrator steps");
            checkFinite(integ->getTime());
          }
        }
        if (end) *end = integ->getState();
      } catch (const std::exception& e) {
        st.ok = false;
        st.message = oneLine("simulation failed: " + failureInWords(e));
      }
      st.steps = integ->getNumStepsTaken();
      st.steps_attempted = integ->getNumStepsAttempted();
    }
    return st;
  }

  /// The equilibrium start state for the run set up by begin().
  State startState() {
    State s = default_state;
    s.setTime(0);
    setEquilibrium(s);
    return s;
  }

  RunResult run(const std::vector<double>& values, const Road& road, const ScenarioSpec& sc, StepControl steps) {
    const auto t_start = std::chrono::steady_clock::now();
    begin(values, road, sc);
    if ((steps.replay || steps.record) && opt.integrator != "rosenbrock")
      throw InputError("simulation.integrator", "a frozen step sequence needs the rosenbrock integrator, not '" + opt.integrator + "'");
    RunResult res;
    Knots knots;
    std::vector<double> times;
    const State s = startState();
    const Segments segs = segments(road, sc);
    res.stats = integrate(s, segs, 0, segs.size(), true, knots, times, nullptr, steps);
    finish(knots, times, sc, res);
    res.stats.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    return res;
  }

  /// Fills knot count, simulated time and the output trace of `res` from the recorded knots.
  void finish(const Knots& knots, const std::vector<double>& times, const ScenarioSpec& sc, RunResult& res) {
    if (times.empty()) {  // the integrator could not even start: an empty trace with its channels
      for (auto& ch : channels(model->sensors())) res.trace.addChannel(ch);
      return;
    }
    res.stats.knots = static_cast<long>(knots.size());
    res.stats.sim_s = times.back();
    makeOutput(knots, times, sc, res.trace);
    if (!sc.sample_times_s.empty() && res.stats.ok) {
      DTWIN_CHECK(std::is_sorted(sc.sample_times_s.begin(), sc.sample_times_s.end()) && sc.sample_times_s.front() >= 0 &&
                      sc.sample_times_s.back() <= times.back() + 1e-9,
                  "sample_times_s must be ascending and within the run");
      writeRows(knots, times, sc, sc.sample_times_s, res.samples);
      resampleFilteredSensors(res.trace, sc.sample_times_s, res.samples);
    }
  }

  std::vector<RunResult> runBranched(const std::vector<double>& values, const std::vector<const Road*>& roads,
                                     const ScenarioSpec& sc) {
    using Clock = std::chrono::steady_clock;
    const auto t_start = Clock::now();
    if (roads.empty()) throw InputError("runBranched", "needs at least one road");
    for (std::size_t r = 0; r < roads.size(); ++r)
      if (!roads[r]) throw InputError("runBranched", "road " + std::to_string(r) + " is null");
    const double tb = branchTime(sc);
    if (!(tb > 0))
      throw InputError("scenario " + sc.name,
                       "cannot branch: the road has no smooth start (needs an iso8608 road with smooth_until_s > "
                       "obstacle_margin_before_s = " + std::to_string(opt.obstacle_margin_before_s) + " s)");
    if (!(tb < sc.duration_s))
      throw InputError("scenario " + sc.name, "cannot branch: the smooth part (to " + std::to_string(tb) +
                                                  " s) covers the whole run (duration " + std::to_string(sc.duration_s) + " s)");
    begin(values, *roads[0], sc);
    const Segments segs = segments(*roads[0], sc);
    std::size_t ib = segs.size();
    for (std::size_t i = 0; i < segs.size(); ++i)
      if (segs[i].first == tb) ib = i;
    if (ib == segs.size())
      throw InputError("scenario " + sc.name, "cannot branch: no integration segment ends at the branch time " + std::to_string(tb) +
                                                  " s (an obstacle window overlaps the smooth part's end)");
    // Every road must share the segments and the smooth part (the scenario's road, other seed).
    for (std::size_t r = 1; r < roads.size(); ++r) {
      if (segments(*roads[r], sc) != segs)
        throw InputError("runBranched", "road " + std::to_string(r) + " has other obstacle windows than road 0");
      const double x_hi = sc.speed.distance(tb) + 0.1, x_lo = sc.speed.distance(0) - model->vehicle().wheelbase() - 1.0;
      for (double x = x_lo; x <= x_hi; x += 0.05)
        for (Track t : {Track::Left, Track::Right}) {
          const RoadSample a = roads[0]->sample(t, x), b = roads[r]->sample(t, x);
          if (a.height_m != b.height_m || a.slope != b.slope)
            throw InputError("runBranched", "road " + std::to_string(r) + " differs from road 0 before the branch point (x = " +
                                                std::to_string(x) + " m): the roads must share the smooth start");
        }
    }
    // The common part, once.
    Knots knots0;
    std::vector<double> times0;
    State at_branch;
    const RunStats common = integrate(startState(), segs, 0, ib + 1, true, knots0, times0, &at_branch);
    const double common_wall = std::chrono::duration<double>(Clock::now() - t_start).count();
    const double share = common_wall / static_cast<double>(roads.size());
    std::vector<RunResult> out(roads.size());
    for (std::size_t r = 0; r < roads.size(); ++r) {
      const auto t_branch = Clock::now();
      RunResult& res = out[r];
      ctx.road = roads[r];
      Knots knots = knots0;
      std::vector<double> times = times0;
      if (common.ok) {
        State s = at_branch;
        s.invalidateAllCacheAtOrAbove(Stage::Time);  // forces are re-evaluated on this branch's road
        res.stats = integrate(s, segs, ib + 1, segs.size(), false, knots, times, nullptr);
        res.stats.steps += common.steps;
        res.stats.steps_attempted += common.steps_attempted;
      } else {
        res.stats = common;
      }
      finish(knots, times, sc, res);
      res.stats.wall_s = share + std::chrono::duration<double>(Clock::now() - t_branch).count();
    }
    return out;
  }

  void makeOutput(const std::vector<std::array<double, KNOT>>& knots, const std::vector<double>& times,
                  const ScenarioSpec& sc, Trace& tr) {
    const std::size_t n = static_cast<std::size_t>(std::floor(times.back() * opt.output_rate_hz + 1e-9)) + 1;
    std::vector<double> ts(n);
    for (std::size_t r = 0; r < n; ++r) ts[r] = std::min(static_cast<double>(r) / opt.output_rate_hz, times.back());
    writeRows(knots, times, sc, ts, tr);
    filterSensors(tr);
  }

  /// The output channels at the ascending times `ts` (within the knots' span), from the cubic
  /// Hermite interpolant of the knots: the integrator's dense output, whatever the times.
  void writeRows(const std::vector<std::array<double, KNOT>>& knots, const std::vector<double>& times,
                 const ScenarioSpec& sc, const std::vector<double>& ts, Trace& tr) {
    for (auto& ch : channels(model->sensors())) tr.addChannel(ch);
    const std::size_t n = ts.size();
    for (std::size_t i = 0; i < tr.channels().size(); ++i) tr.column(i).resize(n);
    const auto& k0 = knots.front();
    std::size_t j = 0;
    for (std::size_t r = 0; r < n; ++r) {
      const double t = ts[r];
      while (j + 2 < times.size() && times[j + 1] < t) ++j;
      const std::size_t j1 = std::min(j + 1, times.size() - 1);
      const auto& a = knots[j];
      const auto& b = knots[j1];
      const double h = times[j1] - times[j];
      const double u = h > 0 ? std::clamp((t - times[j]) / h, 0.0, 1.0) : 0.0;
      auto pos = [&](std::size_t iv, std::size_t id) { return h > 0 ? hermite(h, u, a[iv], a[id], b[iv], b[id]) : a[iv]; };
      auto acc = [&](std::size_t iv, std::size_t id) { return h > 0 ? hermiteD(h, u, a[iv], a[id], b[iv], b[id]) : a[id]; };
      std::size_t col = 0;
      tr.column(col++)[r] = t;
      tr.column(col++)[r] = sc.speed.speed(t);
      for (int c = 0; c < 4; ++c) {
        const double hx = pos(HX + c, HXD + c), hxd = a[HXD + c] + u * (b[HXD + c] - a[HXD + c]);
        const TireEval e = tires[c].eval(ctx, t, hx, hxd, pos(HZ + c, HZD + c), pos(HZD + c, HZDD + c));
        tr.column(col + c)[r] = e.fz;
        tr.column(col + 4 + c)[r] = e.rho;
        tr.column(col + 8 + c)[r] = pos(Q + c, QD + c);
        tr.column(col + 12 + c)[r] = pos(QD + c, QDD + c);
        tr.column(col + 16 + c)[r] = e.road_h;
      }
      col += 20;
      tr.column(col++)[r] = pos(BODY + 0, BODY + 1) - k0[BODY + 0];
      tr.column(col++)[r] = pos(BODY + 3, BODY + 4);
      tr.column(col++)[r] = pos(BODY + 6, BODY + 7);
      tr.column(col++)[r] = acc(BODY + 1, BODY + 2);
      tr.column(col++)[r] = acc(BODY + 4, BODY + 5);
      tr.column(col++)[r] = acc(BODY + 7, BODY + 8);
      for (std::size_t si = 0; si < model->sensors().size(); ++si) {  // before any filter (filterSensors)
        const SensorSpec& x = model->sensors()[si];
        const Model::SensorSlots& sl = model->sensorSlots()[si];
        const double offset = ctx.p[sl.offset];  // run parameters: a calibration may move them
        Motion m;
        if (x.relative()) {
          // The wheel centre's height in chassis axes, from its start: the travel (compression
          // positive) of a potentiometer parallel to the chassis z axis, wherever its body end is.
          const auto c = static_cast<std::size_t>(x.corner());
          const double cx = isFront(x.corner()) ? model->vehicle().a : -model->vehicle().b;
          const double cy = (cornerTrack(x.corner()) == Track::Left ? 0.5 : -0.5) * model->vehicle().track;
          const Motion heave{pos(BODY + 0, BODY + 1), pos(BODY + 1, BODY + 2), 0.0};
          const Motion pitch{pos(BODY + 3, BODY + 4), pos(BODY + 4, BODY + 5), 0.0};
          const Motion roll{pos(BODY + 6, BODY + 7), pos(BODY + 7, BODY + 8), 0.0};
          m = chassisAxisHeight({pos(HZ + c, HZD + c), pos(HZD + c, HZDD + c), 0.0}, heave, pitch, roll, cx, cy);
          m.q -= chassisAxisHeight({k0[HZ + c], 0, 0}, {k0[BODY + 0], 0, 0}, {k0[BODY + 3], 0, 0}, {k0[BODY + 6], 0, 0}, cx, cy).q;
          tr.column(col++)[r] = (x.quantity == SensorQuantity::Travel ? m.q : m.qd) + offset;
          continue;
        }
        if (x.corner() >= 0) {
          const std::size_t c = static_cast<std::size_t>(x.corner());
          m = {pos(HZ + c, HZD + c) - k0[HZ + c], pos(HZD + c, HZDD + c), acc(HZD + c, HZDD + c)};
        } else {
          const Motion heave{pos(BODY + 0, BODY + 1), pos(BODY + 1, BODY + 2), acc(BODY + 1, BODY + 2)};
          const Motion pitch{pos(BODY + 3, BODY + 4), pos(BODY + 4, BODY + 5), acc(BODY + 4, BODY + 5)};
          const Motion roll{pos(BODY + 6, BODY + 7), pos(BODY + 7, BODY + 8), acc(BODY + 7, BODY + 8)};
          const Motion at0{k0[BODY + 0], 0.0, 0.0};
          const std::array<double, 3> where{ctx.p[sl.x], ctx.p[sl.y], ctx.p[sl.z]};
          m = chassisPointMotion(heave, pitch, roll, where);
          m.q -= chassisPointMotion(at0, {k0[BODY + 3], 0, 0}, {k0[BODY + 6], 0, 0}, where).q;
        }
        tr.column(col++)[r] = (x.quantity == SensorQuantity::DisplacementZ ? m.q : x.quantity == SensorQuantity::VelocityZ ? m.qd : m.qdd) + offset;
      }
    }
  }

  /// The filtered sensors' columns of a grid trace (makeOutput), filtered as the logger did.
  void filterSensors(Trace& grid) {
    const auto& sensors = model->sensors();
    const std::size_t first = channels().size();
    for (std::size_t i = 0; i < sensors.size(); ++i)
      if (sensors[i].filter.order > 0) grid.column(first + i) = lowPass(grid.column(first + i), opt.output_rate_hz, sensors[i].filter);
  }

  /// A filtered sensor at extra output times: the filtered grid column read there (its filter
  /// state lives on the grid; twin/trace.hpp GridSample, the four-point cubic).
  void resampleFilteredSensors(const Trace& grid, const std::vector<double>& ts, Trace& samples) {
    const auto& sensors = model->sensors();
    const std::size_t first = channels().size();
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      if (sensors[i].filter.order == 0) continue;
      const auto& g = grid.column(first + i);
      auto& s = samples.column(first + i);
      const double last = static_cast<double>(g.size() - 1) / opt.output_rate_hz;
      for (std::size_t r = 0; r < ts.size(); ++r) s[r] = gridSample(std::min(ts[r], last), opt.output_rate_hz, g.size()).of(g);
    }
  }
};

Simulator::Simulator(std::shared_ptr<const Model> model, SimulationOptions options)
    : impl_(std::make_unique<Impl>(std::move(model), std::move(options))) {}
Simulator::~Simulator() = default;
const Model& Simulator::model() const { return *impl_->model; }
const SimulationOptions& Simulator::options() const { return impl_->opt; }
Simulator::Impl& Simulator::pick(const std::vector<double>& values) {
  if (values.size() != impl_->model->runParameterNames().size()) return *impl_;  // begin() reports it
  if (!impl_->model->builtFor(values)) {
    // A freed vehicle value (a mass, an inertia) is part of the multibody system: rebuild it.
    impl_ = std::make_unique<Impl>(impl_->model->withFreedValues(values), impl_->opt);
    impl_filter_.reset();
  }
  const Model& M = *impl_->model;
  bool active = false;
  for (std::size_t i = 0; i < M.effects().size(); ++i)
    if (M.effects()[i]->kind() == EffectKind::StrutFilter)
      active = active || M.effects()[i]->filterActive(
                             ParamValues(values.data() + M.effectSlots()[i][0], M.effects()[i]->parameters().size()));
  if (!active) return *impl_;
  if (!impl_filter_) impl_filter_ = std::make_unique<Impl>(impl_->model, impl_->opt, true);
  return *impl_filter_;
}
namespace {
/// A run that could not start because the multibody system cannot be built with the run's freed
/// values: a failed run (its SSE is infinite, as any failed run's), in plain words with the values.
RunResult unbuildableRun(const Model& model, const std::vector<double>& values, const std::vector<Channel>& channels) {
  RunResult r;
  r.stats.ok = false;
  std::string at;
  for (int s : model.freedSlots())
    at += (at.empty() ? "" : ", ") + model.runParameterNames()[static_cast<std::size_t>(s)] + " = " +
          formatNumber(values[static_cast<std::size_t>(s)]);
  r.stats.message = "the vehicle cannot be built with " + (at.empty() ? std::string("these values") : at) +
                    ": the multibody model refuses these masses or inertias";
  for (const auto& ch : channels) r.trace.addChannel(ch);
  return r;
}
}  // namespace

Simulator::Impl* Simulator::pickBuildable(const std::vector<double>& values) {
  try {
    return &pick(values);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception&) {
    return nullptr;  // the multibody library refused the rebuilt system
  }
}
RunResult Simulator::run(const std::vector<double>& values, const Road& road, const ScenarioSpec& sc, StepControl steps) {
  if (Impl* impl = pickBuildable(values)) return impl->run(values, road, sc, steps);
  return unbuildableRun(*impl_->model, values, channels(impl_->model->sensors()));
}
std::vector<RunResult> Simulator::runBranched(const std::vector<double>& values, const std::vector<const Road*>& roads,
                                              const ScenarioSpec& sc) {
  if (Impl* impl = pickBuildable(values)) return impl->runBranched(values, roads, sc);
  return std::vector<RunResult>(roads.size(), unbuildableRun(*impl_->model, values, channels(impl_->model->sensors())));
}
double Simulator::branchTime(const ScenarioSpec& sc) const { return impl_->branchTime(sc); }

std::vector<std::pair<double, double>> integrationSegments(const Road& road, const ScenarioSpec& sc, const SimulationOptions& opt,
                                                           double wheelbase) {
  // The windows in time while a wheel (front: offset 0, rear: the wheelbase) is near an obstacle.
  std::vector<Interval> w;
  for (const auto& ob : road.obstacles())
    for (double offset : {0.0, wheelbase}) {
      const double t0 = sc.speed.timeAtDistance(ob.lo + offset) - opt.obstacle_margin_before_s;
      const double t1 = sc.speed.timeAtDistance(ob.hi + offset) + opt.obstacle_margin_after_s;
      if (t1 > 0 && t0 < sc.duration_s) w.push_back({std::max(0.0, t0), std::min(sc.duration_s, t1)});
    }
  std::sort(w.begin(), w.end(), [](auto& a, auto& b) { return a.lo < b.lo; });
  std::vector<Interval> merged;
  for (auto& i : w) {
    if (!merged.empty() && i.lo <= merged.back().hi) merged.back().hi = std::max(merged.back().hi, i.hi);
    else merged.push_back(i);
  }
  std::vector<std::pair<double, double>> segs;
  double t = 0;
  for (const auto& m : merged) {
    if (m.lo > t) segs.push_back({m.lo, opt.max_step_s});
    segs.push_back({m.hi, std::min(opt.max_step_s, opt.obstacle_max_step_s)});
    t = m.hi;
  }
  if (t < sc.duration_s) segs.push_back({sc.duration_s, opt.max_step_s});
  // A rough section that starts at a known time: the integrator lands on a knot just before it,
  // so nothing before that knot depends on the rough road (every road of one theta shares the
  // smooth part bit for bit; runBranched integrates it once).
  if (const double rough = sc.road->roughStart_s(); rough > 0) {
    const double tb = rough - opt.obstacle_margin_before_s;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      const double lo = i == 0 ? 0.0 : segs[i - 1].first;
      if (tb > lo + 1e-9 && tb < segs[i].first - 1e-9) {
        segs.insert(segs.begin() + static_cast<long>(i), {tb, segs[i].second});
        break;
      }
    }
  }
  return segs;
}

}  // namespace dtwin
