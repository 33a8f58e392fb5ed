// Private to twin/ (not installed): the Simbody force elements of the vehicle (tires, struts, axle
// couplings, chassis forces, gravity with the frame's acceleration) and the per-run data they read
// (namespace dtwin::sim, with the simulator's parts: vehicle_system.hpp builds the system from
// them). Included by those parts alone, which are kept out of the unity batches (CMakeLists.txt):
// SimTK is open.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <Simbody.h>

#include "twin/simulator.hpp"

namespace dtwin {
using namespace SimTK;

// ----------------------------------------------------------------------- force elements
namespace sim {

/// Per-run data the force elements read (in the VehicleSystem; the Simulator sets it before each run).
struct RunContext {
  const double* p = nullptr;
  const Road* road = nullptr;
  SpeedProfile speed;
  double traction_per_wheel_per_accel = 0.0;  ///< M/4: traction share per unit acceleration
  /// The chassis's heave, pitch and roll coordinates at the start (StaticStart, static_start.hpp): ChassisForce
  /// effects read the motion from there.
  double heave0 = 0.0, pitch0 = 0.0, roll0 = 0.0;
  /// Run slots of the road signal's gain and delay (Model::roadGainSlot, roadDelaySlot).
  std::size_t gain_slot = 0, delay_slot = 0;
  /// The run slot of the first road-signal form (Model::roadFormSlot; roadSignalForms() order).
  std::size_t form_slot = 0;
  double wheelbase = 0.0;
  /// With the hubs' motion prescribed (VehicleSystem::prescribed_hubs): the link's static
  /// deflection at each corner at the start (StaticStart): the hub rides R0 minus it above the
  /// signal.
  std::array<double, 4> hub_rho{};
  /// Where corner `c` meets the road signal (roadSignalForms): the signal's weight there (gain
  /// included) and how far ahead [m] it reads the signal. At every form's default (0) exactly
  /// the gain and no read-ahead.
  void signalAt(int c, double& weight, double& ahead_m) const {
    weight = p[gain_slot];
    ahead_m = 0.0;
    const auto& forms = roadSignalForms();
    double w = 1.0, lag = 0.0;
    for (std::size_t f = 0; f < forms.size(); ++f) {
      const double l = p[form_slot + f];
      if (l == 0.0) continue;
      w += l * (forms[f].weight[c] - 1.0);
      lag += l * forms[f].no_lag[c];
    }
    if (w != 1.0) weight *= w;
    if (lag != 0.0) ahead_m = lag * wheelbase;
  }
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
  std::vector<Model::ScaledParameter> factors;                 // this corner's factors (Model::tireFactors)

  /// The tire law's parameters at this corner: the run vector's own without factors.
  ParamValues values(const RunContext& c, LawValueBuffer& buf) const { return Model::scaledLawValues(c.p, p0, np, factors, buf); }

  /// Where the road signal is read for a wheel at road distance x_road (the delay's read-ahead,
  /// see eval) and the forward speed of that point along the signal (hub_xd: the hub's own).
  static void signalPoint(const RunContext& c, double t, double x_road, double hub_xd, double& x, double& contact_speed) {
    const double delay = c.p[c.delay_slot];
    x = x_road;  // the form's read-ahead is in x_road already (eval, roadRate)
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
    double x = 0.0, contact_speed = 0.0, weight = 1.0, ahead = 0.0;
    c.signalAt(corner, weight, ahead);
    signalPoint(c, t, c.speed.distance(t) + hub_x - model->vehicle().a + ahead, hub_xd, x, contact_speed);
    return weight * c.road->sample(cornerTrack(corner), x).slope * contact_speed;
  }
  /// The road the wheel meets at road distance x_road (tire-input effects and the signal's gain
  /// applied), the speed at which the wheel travels along it, and the road before the tire-input
  /// effects (road_h, gain applied).
  RoadSample signalUnder(const RunContext& c, double t, double x_road, double hub_xd, double& contact_speed, double& road_h) const {
    const Track tr = cornerTrack(corner);
    // The road signal's delay d relative to the measured channels (positive: logged late) and its
    // gain g: the wheel meets g h(x + s(t + d) - s(t)), read ahead by the distance travelled in d
    // (docs/model.md, "The road signal's gain and delay"). At d = 0 and g = 1 exactly the road.
    double gain = 1.0, ahead = 0.0;
    c.signalAt(corner, gain, ahead);
    double x = 0.0;
    signalPoint(c, t, x_road + ahead, hub_xd, x, contact_speed);
    RoadSample rs = c.road->sample(tr, x);
    road_h = rs.height_m;  // the road under the wheel, before tire-input effects
    for (auto& [eff, s] : filters) rs = eff->filterRoad(*c.road, tr, x, ParamValues(c.p + s, eff->parameters().size()));
    if (gain != 1.0) {
      rs.height_m *= gain;
      rs.slope *= gain;
      road_h *= gain;
    }
    return rs;
  }
  /// A prescribed hub's height and vertical rate (VehicleSystem::prescribed_hubs): the road the
  /// wheel meets (signalUnder) plus R0 less the link's static deflection (RunContext::hub_rho),
  /// for a hub at x (hub_x, hub_xd as in eval).
  struct HubPath {
    double z = 0, zd = 0;
  };
  HubPath hubPath(const RunContext& c, double t, double hub_x, double hub_xd) const {
    LawValueBuffer buf;
    const double R0 = values(c, buf)[r0];
    double contact_speed = 0.0, road_h = 0.0;
    const RoadSample rs = signalUnder(c, t, c.speed.distance(t) + hub_x - model->vehicle().a, hub_xd, contact_speed, road_h);
    return {rs.height_m + R0 - c.hub_rho[static_cast<std::size_t>(corner)], rs.slope * contact_speed};
  }
  /// The prescribed hub's vertical acceleration: the rate's central difference over +-10 us (the
  /// road's interpolant has no second derivative of its own; it jumps at the signal's nodes).
  /// For the recorded outputs only: no force reads it.
  double hubAccel(const RunContext& c, double t, double hub_x, double hub_xd) const {
    constexpr double dt = 1e-5;
    return (hubPath(c, t + dt, hub_x + hub_xd * dt, hub_xd).zd - hubPath(c, t - dt, hub_x - hub_xd * dt, hub_xd).zd) / (2 * dt);
  }
  TireEval eval(const RunContext& c, double t, double hub_x, double hub_xd, double hub_z, double hub_zd) const {
    TireEval e;
    LawValueBuffer buf;
    const ParamValues p = values(c, buf);
    const double v = c.speed.speed(t);
    e.x_road = c.speed.distance(t) + hub_x - model->vehicle().a;
    double contact_speed = 0.0;
    const RoadSample rs = signalUnder(c, t, e.x_road, hub_xd, contact_speed, e.road_h);
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
  Kin prescribedKin(const State& s, Vec3* station_velocity = nullptr, TireCorner::HubPath* path = nullptr) const {
    const Vec3 v = upper.findStationVelocityInGround(s, st_upper);
    const HubAt h = hubAt(s, v[0]);
    const Vec3 zdot = upper.getBodyAngularVelocity(s) % Vec3(h.z);
    if (station_velocity) *station_velocity = v;
    if (path) *path = h.path;
    return {h.q, (h.path.zd - v[2] - h.q * zdot[2]) / h.z[2]};
  }
  Kin kin(const State& s) const {
    if (is_slider) return {s.getQ()[qi], s.getU()[ui]};
    if (is_prescribed) return prescribedKin(s);
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
    if (is_prescribed) {  // q z_z = z_hub - z_P, differentiated twice (z the body's axis in Ground)
      Vec3 v;
      TireCorner::HubPath path;
      const Kin k = prescribedKin(s, &v, &path);
      const Vec3 z(upper.getBodyRotation(s).z()), w = upper.getBodyAngularVelocity(s);
      const Vec3 zdot = w % z, zddot = upper.getBodyAngularAcceleration(s) % z + w % zdot;
      const double hdd = tire->hubAccel(*ctx, s.getTime(), upper.findStationLocationInGround(s, st_upper)[0], v[0]);
      const double pdd = upper.findStationAccelerationInGround(s, st_upper)[2];
      return (hdd - pdd - 2 * k.qd * zdot[2] - k.q * zddot[2]) / z[2];
    }
    if (is_axle_seat) {
      const double phi = s.getQ()[qr], w = s.getU()[ur];
      return s.getUDot()[uh] + seat_y * (std::cos(phi) * s.getUDot()[ur] - std::sin(phi) * w * w);
    }
    const Vec3 au = upper.findStationAccelerationInGround(s, st_upper), al = lower.findStationAccelerationInGround(s, st_lower);
    return ~(al - au) * Vec3(upper.getBodyRotation(s).z());
  }
  /// Applies the strut force F (positive pushes the ends apart along upper's z). `k`: the strut's
  /// kinematics at `s` where the caller has them (a prescribed hub's compression places the force).
  void apply(const State& s, double F, Vector_<SpatialVec>& bodyForces, Vector& mobilityForces, const Kin* k = nullptr) const {
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
      upper.applyForceToBodyPoint(s, st_upper + Vec3(0, 0, q), Vec3(0, 0, F / upper.getBodyRotation(s).z()[2]), bodyForces);
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

// The Simbody force elements. Only the system builder (vehicle_system.cpp) instantiates them, and
// they keep internal linkage there: the compiler sees every use of their code in that one file.
namespace {

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
  /// A main strut's corner (0-3): the effects installed at another corner only leave it alone.
  /// Call before the system's topology is realized (it keeps the StrutFilter states of its own).
  void placeAt(int corner) {
    corner_ = corner;
    filter_effects_.erase(std::remove_if(filter_effects_.begin(), filter_effects_.end(),
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
      if (motion_ && g_.is_prescribed) {
        Vec3 v;
        TireCorner::HubPath path;
        g_.prescribedKin(s, &v, &path);
        ss.body_velocity_mps = v[2];
        ss.wheel_velocity_mps = path.zd;
        ss.road_velocity_mps = tire_->roadRate(*ctx_, ss.time_s, g_.upper.findStationLocationInGround(s, g_.st_upper)[0], v[0]);
      } else if (motion_) {
        ss.body_velocity_mps = g_.upper.findStationVelocityInGround(s, g_.st_upper)[2];
        ss.wheel_velocity_mps = g_.lower.findStationVelocityInGround(s, g_.st_lower)[2];
        ss.road_velocity_mps =
            tire_->roadRate(*ctx_, ss.time_s, wheel_.getBodyOriginLocation(s)[0], wheel_.getBodyOriginVelocity(s)[0]);
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
    if (effects_) {
      const auto& effs = m_->effects();
      for (std::size_t i = 0; i < effs.size(); ++i)
        if (effs[i]->kind() == EffectKind::Strut && m_->effectActsAt(i, corner_))
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
  AxleCouplingElement(const RunContext* ctx, const Effect* eff, std::size_t slot, const StrutGeometry* left,
                      const StrutGeometry* right, bool front)
      : ctx_(ctx), eff_(eff), slot_(slot), left_(left), right_(right), front_(front) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector& mobilityForces) const override {
    StrutGeometry::Kin l, r;
    const double F = pairForce(s, &l, &r);
    if (F == 0.0) return;
    left_->apply(s, F, bodyForces, mobilityForces, &l);
    right_->apply(s, -F, bodyForces, mobilityForces, &r);
  }
  /// The force on the left strut (the right one takes its opposite), compression positive; `left`
  /// and `right` receive the struts' kinematics.
  double pairForce(const State& s, StrutGeometry::Kin* left = nullptr, StrutGeometry::Kin* right = nullptr) const {
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
  HubReactionElement(const RunContext* ctx, const StrutGeometry* g, double wheel_mass) : ctx_(ctx), g_(g), m_w_(wheel_mass) {}
  void calcForce(const State& s, Vector_<SpatialVec>& bodyForces, Vector_<Vec3>&, Vector&) const override {
    const double a = ctx_->speed.accel(s.getTime());
    const double fx = ctx_->traction_per_wheel_per_accel * a;
    const StrutGeometry::HubAt h = g_->hubAt(s);
    const double H = fx - m_w_ * a;
    g_->upper.applyForceToBodyPoint(s, g_->st_upper + Vec3(0, 0, h.q), Vec3(H, 0, -H * h.z[0] / h.z[2]), bodyForces);
    LawValueBuffer buf;
    const double R0 = g_->tire->values(*ctx_, buf)[g_->tire->r0];
    g_->upper.applyBodyTorque(s, Vec3(0, -(R0 - ctx_->hub_rho[static_cast<std::size_t>(g_->tire->corner)]) * fx, 0), bodyForces);
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
}  // namespace

}  // namespace sim

}  // namespace dtwin
