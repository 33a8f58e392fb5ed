// Private to twin/ (not installed): the Simbody force elements of the vehicle (tires, struts, axle
// couplings, a prescribed hub's reactions, chassis forces, gravity with the frame's acceleration);
// the per-run data they read are twin/road_contact.hpp's (namespace dtwin::sim, with the
// simulator's parts: vehicle_system.hpp builds the system from them). Included by those parts
// alone, which are kept out of the unity batches (CMakeLists.txt): SimTK is open.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <Simbody.h>

#include "twin/road_contact.hpp"
#include "twin/simulator.hpp"

namespace dtwin {
using namespace SimTK;

// ----------------------------------------------------------------------- force elements
namespace sim {

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
    /// A prescribed hub's (prescribedKin): the station's x, its velocity's x and z, the hub's
    /// vertical rate. Unset otherwise.
    double px = 0, pvx = 0, pvz = 0, hub_zd = 0;
  };
  /// A solid axle's spring seat: the axle hangs on a Slider (heave along the chassis z) and a
  /// Pin (roll about the chassis x) with the seat at lateral offset `seat_y` on the axle. The seat
  /// moves along the chassis z by q_h + y sin(phi): read q, u from the State. The force is applied
  /// as the generalized forces of that pair (virtual work of a force along the chassis z).
  bool is_axle_seat = false;
  QIndex qh{}, qr{};
  UIndex uh{}, ur{};
  double seat_y = 0;
  /// The hub's motion prescribed (VehicleSystem::prescribed_hubs): `lower` is empty and the hub
  /// sits on upper's z axis through st_upper, at the height of the road signal under it
  /// (TireCorner::hubPath). The compression is the distance along that axis from st_upper to the
  /// hub's height: q = (z_hub - z_P) / z_z, P the station and z the axis in Ground.
  bool is_prescribed = false;
  const RunContext* ctx = nullptr;
  const TireCorner* tire = nullptr;
  /// Where a prescribed hub is (Position stage): the station P, the axis z, the hub's path, q.
  struct HubAt {
    Vec3 p;
    UnitVec3 z;
    TireCorner::HubPath path;
    double q = 0;
  };
  /// `hub_xd`: the station's forward velocity where known (the Velocity stage); the position
  /// alone (the static start) reads the signal at the hub's own speed along the road.
  HubAt hubAt(const State& s, double hub_xd = 0.0) const {
    HubAt h;
    h.p = upper.findStationLocationInGround(s, st_upper);
    h.z = upper.getBodyRotation(s).z();
    h.path = tire->hubPath(*ctx, s.getTime(), h.p[0], hub_xd);
    h.q = (h.path.z - h.p[2]) / h.z[2];
    return h;
  }
  Kin prescribedKin(const State& s, Vec3* station_velocity = nullptr,
                    TireCorner::HubPath* path = nullptr) const {
    const Vec3 v = upper.findStationVelocityInGround(s, st_upper);
    const HubAt h = hubAt(s, v[0]);
    const Vec3 zdot = upper.getBodyAngularVelocity(s) % Vec3(h.z);
    if (station_velocity) *station_velocity = v;
    if (path) *path = h.path;
    return {h.q, (h.path.zd - v[2] - h.q * zdot[2]) / h.z[2], h.p[0], v[0], v[2], h.path.zd};
  }
  Kin kin(const State& s) const {
    if (is_slider) return {s.getQ()[qi], s.getU()[ui]};
    if (is_prescribed) return prescribedKin(s);
    if (is_axle_seat) {
      const double phi = s.getQ()[qr];
      return {s.getQ()[qh] + seat_y * std::sin(phi),
              s.getU()[uh] + seat_y * std::cos(phi) * s.getU()[ur]};
    }
    const Vec3 pu = upper.findStationLocationInGround(s, st_upper),
               pl = lower.findStationLocationInGround(s, st_lower);
    const Vec3 vu = upper.findStationVelocityInGround(s, st_upper),
               vl = lower.findStationVelocityInGround(s, st_lower);
    const UnitVec3 z = upper.getBodyRotation(s).z();
    const Vec3 w = upper.getBodyAngularVelocity(s);
    const Vec3 d = pl - pu;
    return {~d * Vec3(z), ~(vl - vu) * Vec3(z) + ~d * (w % Vec3(z))};
  }
  double accel(const State& s) const {
    if (is_slider) return s.getUDot()[ui];
    if (is_prescribed) {  // q z_z = z_hub - z_P, differentiated twice (z the body's axis in Ground)
      Vec3 v;
      TireCorner::HubPath path;
      const Kin k = prescribedKin(s, &v, &path);
      const Vec3 z(upper.getBodyRotation(s).z()), w = upper.getBodyAngularVelocity(s);
      const Vec3 zdot = w % z, zddot = upper.getBodyAngularAcceleration(s) % z + w % zdot;
      const double hdd = tire->hubAccel(*ctx, s.getTime(),
                                        upper.findStationLocationInGround(s, st_upper)[0], v[0]);
      const double pdd = upper.findStationAccelerationInGround(s, st_upper)[2];
      return (hdd - pdd - 2 * k.qd * zdot[2] - k.q * zddot[2]) / z[2];
    }
    if (is_axle_seat) {
      const double phi = s.getQ()[qr], w = s.getU()[ur];
      return s.getUDot()[uh] + seat_y * (std::cos(phi) * s.getUDot()[ur] - std::sin(phi) * w * w);
    }
    const Vec3 au = upper.findStationAccelerationInGround(s, st_upper),
               al = lower.findStationAccelerationInGround(s, st_lower);
    return ~(al - au) * Vec3(upper.getBodyRotation(s).z());
  }
  /// Applies the strut force F (positive pushes the ends apart along upper's z). `k`: the strut's
  /// kinematics at `s` where the caller has them (a prescribed hub's compression places the force).
  void apply(const State& s, double F, Vector_<SpatialVec>& bodyForces, Vector& mobilityForces,
             const Kin* k = nullptr) const {
    if (is_slider) {
      mobilityForces[ui] -= F;  // compression positive: the force pushes the slider back down
      return;
    }
    if (is_prescribed) {
      // On the body alone: the road moves the hub. The wheel carrier slides along the body's z
      // and the road holds the hub by a vertical force, so what the body receives from this
      // corner is vertical, F / z_z at the hub: the strut's push along z plus the slide's
      // reaction to the push's tilt (HubReactionElement adds the fore-aft reactions).
      const double q = k ? k->q : hubAt(s).q;
      upper.applyForceToBodyPoint(s, st_upper + Vec3(0, 0, q),
                                  Vec3(0, 0, F / upper.getBodyRotation(s).z()[2]), bodyForces);
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
  void bindAxleSeat(const State& s, const MobilizedBody& slider, const MobilizedBody& pin,
                    double y) {
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

// The Simbody force elements. Only the system builder (vehicle_system.cpp) instantiates them, and
// they keep internal linkage there: the compiler sees every use of their code in that one file.
namespace {

class TireElement : public Force::Custom::Implementation {
 public:
  TireElement(const RunContext* ctx, TireCorner tc, MobilizedBody wheel)
      : ctx_(ctx), tc_(std::move(tc)), wheel_(wheel) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&,
                 Vector&) const override {
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

class StrutElement : public Force::Custom::Implementation {
 public:
  /// `filter_states`: allocate one auxiliary state (a Z of `sub`) per installed StrutFilter effect.
  StrutElement(const RunContext* ctx, const Model* m, const StrutLaw* law, StrutGeometry g,
               std::size_t p0, int preload_slot, double preload, bool with_effects,
               bool filter_states = false, SubsystemIndex sub = SubsystemIndex())
      : ctx_(ctx),
        m_(m),
        law_(law),
        g_(g),
        p0_(p0),
        preload_slot_(preload_slot),
        preload_(preload),
        effects_(with_effects),
        sub_(sub) {
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
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&,
                 Vector& mobilityForces) const override {
    StrutGeometry::Kin k;
    const double F = totalForce(s, &k);
    g_.apply(s, F, bodyForces, mobilityForces, &k);
  }
  /// The strut's force with every effect, the StrutFilter ones included (compression positive);
  /// `kin` receives the strut's kinematics.
  double totalForce(const State& s, StrutGeometry::Kin* kin = nullptr) const {
    const auto k = g_.kin(s);
    if (kin) *kin = k;
    const StrutState ss = strutState(s, k);
    double F = force(ss);
    if (!filter_effects_.empty()) {
      const Vector& z = s.getZ(sub_);
      for (std::size_t j = 0; j < filter_effects_.size(); ++j) {
        const std::size_t i = filter_effects_[j];
        F += m_->effects()[i]->calcFilteredStrutForce(ss, z[zi_[j]], effectValues(i));
      }
    }
    return F;
  }
  void realizeTopology(State& s) const override {
    zi_.clear();
    for (std::size_t j = 0; j < filter_effects_.size(); ++j)
      zi_.push_back(s.allocateZ(sub_, Vector(1, 0.0)));
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
  /// A main strut's corner (0-3): the effects installed at another corner only leave it alone.
  /// Call before the system's topology is realized (it keeps the StrutFilter states of its own).
  void placeAt(int corner) {
    corner_ = corner;
    filter_effects_.erase(
        std::remove_if(filter_effects_.begin(), filter_effects_.end(),
                       [&](std::size_t i) { return !m_->effectActsAt(i, corner); }),
        filter_effects_.end());
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
    LawValueBuffer buf;
    const ParamValues law = lawValues(buf);
    ss.base_stiffness = law[0];
    ss.base_damping = law[1];
    if (context_ && partner_) {
      const auto o = partner_->kin(s);
      ss.other_deflection_m = o.q;
      ss.other_rate_mps = o.qd;
      ss.time_s = s.getTime();
      ss.speed_mps = ctx_->speed.speed(ss.time_s);
      ss.front = front_;
      if (motion_ && g_.is_prescribed) {  // k is the prescribed hub's (kin)
        ss.body_velocity_mps = k.pvz;
        ss.wheel_velocity_mps = k.hub_zd;
        ss.road_velocity_mps = tire_->roadRate(*ctx_, ss.time_s, k.px, k.pvx);
      } else if (motion_) {
        ss.body_velocity_mps = g_.upper.findStationVelocityInGround(s, g_.st_upper)[2];
        ss.wheel_velocity_mps = g_.lower.findStationVelocityInGround(s, g_.st_lower)[2];
        ss.road_velocity_mps = tire_->roadRate(*ctx_, ss.time_s, wheel_.getBodyOriginLocation(s)[0],
                                               wheel_.getBodyOriginVelocity(s)[0]);
      }
    }
    return ss;
  }
  /// The strut law's parameters at this corner (its factors applied; the run vector's own without).
  ParamValues lawValues(LawValueBuffer& buf) const {
    return Model::scaledLawValues(ctx_->p, p0_, law_->parameters().size(), factors_, buf);
  }
  /// A main strut's factors (Model::strutFactors); none on the solid axle's wheel interfaces.
  std::vector<Model::ScaledParameter> factors_;
  ParamValues effectValues(std::size_t i) const {
    return ParamValues(ctx_->p + m_->effectSlots()[i][0], m_->effects()[i]->parameters().size());
  }
  /// Strut force without the StrutFilter effects (they need the State's auxiliary variables).
  double force(const StrutState& ss) const {
    const double* p = ctx_->p;
    LawValueBuffer buf;
    double F = law_->calcForce(ss, lawValues(buf));
    if (corner_ >= 0) F += ctx_->actuator_N[static_cast<std::size_t>(corner_)];
    if (effects_) {
      const auto& effs = m_->effects();
      for (std::size_t i = 0; i < effs.size(); ++i)
        if (effs[i]->kind() == EffectKind::Strut && m_->effectActsAt(i, corner_))
          F += effs[i]->calcStrutForce(
              ss, ParamValues(p + m_->effectSlots()[i][0], effs[i]->parameters().size()));
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
  int corner_ = -1;       ///< a main strut's corner (placeAt); -1 on interface elements
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
  AxleCouplingElement(const RunContext* ctx, const Effect* eff, std::size_t slot,
                      const StrutGeometry* left, const StrutGeometry* right, bool front)
      : ctx_(ctx), eff_(eff), slot_(slot), left_(left), right_(right), front_(front) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&,
                 Vector& mobilityForces) const override {
    StrutGeometry::Kin l, r;
    const double F = pairForce(s, &l, &r);
    if (F == 0.0) return;
    left_->apply(s, F, bodyForces, mobilityForces, &l);
    right_->apply(s, -F, bodyForces, mobilityForces, &r);
  }
  /// The force on the left strut (the right one takes its opposite), compression positive; `left`
  /// and `right` receive the struts' kinematics.
  double pairForce(const State& s, StrutGeometry::Kin* left = nullptr,
                   StrutGeometry::Kin* right = nullptr) const {
    const auto l = left_->kin(s), r = right_->kin(s);
    if (left) *left = l;
    if (right) *right = r;
    AxleState a;
    a.q_left = l.q;
    a.q_right = r.q;
    a.v_left = l.qd;
    a.v_right = r.qd;
    a.front = front_;
    a.time_s = s.getTime();
    a.speed_mps = ctx_->speed.speed(a.time_s);
    return eff_->calcAxleForce(a, ParamValues(ctx_->p + slot_, eff_->parameters().size()));
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const RunContext* ctx_;
  const Effect* eff_;
  std::size_t slot_;
  const StrutGeometry *left_, *right_;  // the system's struts (bound after realizeTopology)
  bool front_;
};

/// A prescribed hub's reactions on the body besides its strut (VehicleSystem::prescribed_hubs):
/// what a wheel carrier sliding on the body passes to it across the slide. The fore-aft force on
/// the wheel, H = traction - m_w a(t) (the wheel's d'Alembert load of the accelerating frame), at
/// the hub; the traction's moment, acting R0 - rho below the hub; and, as the slide does not carry
/// H's part along the tilted strut axis, the road's vertical -H z_x / z_z that holds the hub
/// against it. The wheel's weight and vertical inertia go to the road, which moves the hub.
class HubReactionElement : public Force::Custom::Implementation {
 public:
  HubReactionElement(const RunContext* ctx, const StrutGeometry* g, double wheel_mass)
      : ctx_(ctx), g_(g), m_w_(wheel_mass) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&,
                 Vector&) const override {
    const double a = ctx_->speed.accel(s.getTime());
    const double fx = ctx_->traction_per_wheel_per_accel * a;
    const StrutGeometry::HubAt h = g_->hubAt(s);
    const double H = fx - m_w_ * a;
    g_->upper.applyForceToBodyPoint(s, g_->st_upper + Vec3(0, 0, h.q),
                                    Vec3(H, 0, -H * h.z[0] / h.z[2]), bodyForces);
    LawValueBuffer buf;
    const double R0 = g_->tire->values(*ctx_, buf)[g_->tire->r0];
    g_->upper.applyBodyTorque(
        s, Vec3(0, -(R0 - ctx_->hub_rho[static_cast<std::size_t>(g_->tire->corner)]) * fx, 0),
        bodyForces);
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const RunContext* ctx_;
  const StrutGeometry* g_;
  double m_w_;
};

/// A ChassisForce effect: a vertical force on the chassis at its mass centre (its body origin),
/// from the heave, pitch and roll coordinates relative to the start. Installed only when such an
/// effect is.
class ChassisForceElement : public Force::Custom::Implementation {
 public:
  /// `heave`: the chassis's vertical Slider; `chassis`: its Universal (q0 roll, q1 pitch).
  ChassisForceElement(const RunContext* ctx, const Effect* eff, std::size_t slot,
                      MobilizedBody heave, MobilizedBody chassis)
      : ctx_(ctx), eff_(eff), slot_(slot), heave_(heave), chassis_(chassis) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&,
                 Vector&) const override {
    ChassisState c;
    c.heave_m = heave_.getOneQ(s, 0) - ctx_->heave0;
    c.heave_rate_mps = heave_.getOneU(s, 0);
    c.pitch_rad = chassis_.getOneQ(s, 1) - ctx_->pitch0;
    c.roll_rad = chassis_.getOneQ(s, 0) - ctx_->roll0;
    c.time_s = s.getTime();
    c.speed_mps = ctx_->speed.speed(c.time_s);
    const double F =
        eff_->calcChassisForce(c, ParamValues(ctx_->p + slot_, eff_->parameters().size()));
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
  BodyLoadElement(const RunContext* ctx,
                  const std::vector<std::pair<MobilizedBody, double>>& bodies, double g)
      : ctx_(ctx), g_(g) {
    for (auto& [b, m] : bodies) bodies_.push_back({b.getMobilizedBodyIndex(), m});
  }
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&,
                 Vector&) const override {
    const double a = ctx_->speed.accel(s.getTime());
    for (auto& [i, m] : bodies_) bodyForces[i][1] += Vec3(-m * a, 0, -m * g_);
  }
  Real calcPotentialEnergy(const State&) const override { return 0; }

 private:
  const RunContext* ctx_;
  double g_;
  std::vector<std::pair<MobilizedBodyIndex, double>> bodies_;
};
}  // namespace

}  // namespace sim

}  // namespace dtwin
