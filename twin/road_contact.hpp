// Private to twin/ (not installed): the per-run data the simulator's force elements read
// (RunContext) and the road signal where each wheel meets it (TireCorner: the tire law's inputs,
// or a prescribed hub's path). Included by twin/force_elements.hpp; SimTK is open.
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

namespace sim {
/// The run's speed profile with its last values kept: at one time every corner asks the same
/// distance, speed and acceleration (and the delayed signal's, at t + delay), and the recorder asks
/// them again; each is computed once. Per run, like RunContext (no locks); the numbers are
/// SpeedProfile's bit for bit.
class SpeedMemo {
 public:
  SpeedMemo& operator=(const SpeedProfile& p) {
    profile_ = p;
    memo_ = {};
    return *this;
  }
  double speed(double t) const { return at(kSpeed, t); }
  double accel(double t) const { return at(kAccel, t); }
  double distance(double t) const { return at(kDistance, t); }
  const SpeedProfile& profile() const { return profile_; }

 private:
  enum Kind { kSpeed = 0, kAccel = 1, kDistance = 2 };
  struct Kept {  // the last two times asked and their values
    std::array<double, 2> t{}, v{};
    int filled = 0, next = 0;
  };
  double at(Kind kind, double t) const {
    Kept& k = memo_[kind];
    for (int i = 0; i < k.filled; ++i)
      if (k.t[static_cast<std::size_t>(i)] == t) return k.v[static_cast<std::size_t>(i)];
    const double v = kind == kSpeed   ? profile_.speed(t)
                     : kind == kAccel ? profile_.accel(t)
                                      : profile_.distance(t);
    const auto slot = static_cast<std::size_t>(k.next);
    k.t[slot] = t;
    k.v[slot] = v;
    k.next ^= 1;
    k.filled = std::min(k.filled + 1, 2);
    return v;
  }
  SpeedProfile profile_;
  mutable std::array<Kept, 3> memo_{};
};

/// Per-run data the force elements read (in the VehicleSystem; the Simulator sets it before each
/// run).
struct RunContext {
  const double* p = nullptr;
  const Road* road = nullptr;
  SpeedMemo speed;
  double traction_per_wheel_per_accel = 0.0;  ///< M/4: traction share per unit acceleration
  /// The chassis's heave, pitch and roll coordinates at the start (StaticStart, static_start.hpp):
  /// ChassisForce effects read the motion from there.
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
  /// An actuator force in each main strut (Corner order; strut sign: positive pushes the body up
  /// and the wheel down), set from outside the twin between steps (a co-simulation's controller,
  /// twin/stepped_run.hpp). Zero in every other run.
  std::array<double, 4> actuator_N{};
  /// Where corner `c` meets the road signal (roadSignalForms): the signal's weight there (gain
  /// included) and how far ahead [m] it reads the signal. At every form's default (0) exactly
  /// the gain and no read-ahead. On a four-corner road (Road::eachWheelOwn) a rear wheel's column
  /// is its own motion at its own time already: no form reads it ahead.
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
    if (lag != 0.0 && !road->eachWheelOwn()) ahead_m = lag * wheelbase;
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
  std::vector<Model::ScaledParameter> factors;  // this corner's factors (Model::tireFactors)

  /// The tire law's parameters at this corner: the run vector's own without factors.
  ParamValues values(const RunContext& c, LawValueBuffer& buf) const {
    return Model::scaledLawValues(c.p, p0, np, factors, buf);
  }

  /// Where the road signal is read for a wheel at road distance x_road (the delay's read-ahead,
  /// see eval) and the forward speed of that point along the signal (hub_xd: the hub's own).
  static void signalPoint(const RunContext& c, double t, double x_road, double hub_xd, double& x,
                          double& contact_speed) {
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
    signalPoint(c, t, c.speed.distance(t) + hub_x - model->vehicle().a + ahead, hub_xd, x,
                contact_speed);
    return weight * c.road->sampleAt(corner, x).slope * contact_speed;
  }
  /// The road the wheel meets at road distance x_road (tire-input effects and the signal's gain
  /// applied), the speed at which the wheel travels along it, and the road before the tire-input
  /// effects (road_h, gain applied).
  RoadSample signalUnder(const RunContext& c, double t, double x_road, double hub_xd,
                         double& contact_speed, double& road_h) const {
    const Track tr = cornerTrack(corner);
    // The road signal's delay d relative to the measured channels (positive: logged late) and its
    // gain g: the wheel meets g h(x + s(t + d) - s(t)), read ahead by the distance travelled in d
    // (docs/model.md, "The road signal's gain and delay"). At d = 0 and g = 1 exactly the road.
    double gain = 1.0, ahead = 0.0;
    c.signalAt(corner, gain, ahead);
    double x = 0.0;
    signalPoint(c, t, x_road + ahead, hub_xd, x, contact_speed);
    RoadSample rs = c.road->sampleAt(corner, x);
    road_h = rs.height_m;  // the road under the wheel, before tire-input effects
    if (!filters.empty()) {
      // A tire-input effect reads a track: given this corner's view of the road, it reads the
      // wheel's own profile on a four-corner road (on any other the track's, as before).
      const CornerView view(*c.road, corner);
      for (auto& [eff, s] : filters)
        rs = eff->filterRoad(view, tr, x, ParamValues(c.p + s, eff->parameters().size()));
    }
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
    const RoadSample rs = signalUnder(c, t, c.speed.distance(t) + hub_x - model->vehicle().a,
                                      hub_xd, contact_speed, road_h);
    return {rs.height_m + R0 - c.hub_rho[static_cast<std::size_t>(corner)],
            rs.slope * contact_speed};
  }
  /// The prescribed hub's vertical acceleration: the rate's central difference over +-10 us (the
  /// road's interpolant has no second derivative of its own; it jumps at the signal's nodes).
  /// For the recorded outputs only: no force reads it.
  double hubAccel(const RunContext& c, double t, double hub_x, double hub_xd) const {
    constexpr double dt = 1e-5;
    return (hubPath(c, t + dt, hub_x + hub_xd * dt, hub_xd).zd -
            hubPath(c, t - dt, hub_x - hub_xd * dt, hub_xd).zd) /
           (2 * dt);
  }
  TireEval eval(const RunContext& c, double t, double hub_x, double hub_xd, double hub_z,
                double hub_zd) const {
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
    for (auto& [eff, s] : scalers)
      e.fz *= eff->tireForceFactor(ts, ParamValues(c.p + s, eff->parameters().size()));
    if (!loads.empty() && e.rho > 0) {  // added at a wheel in contact; the tire cannot pull
      ts.normal_force_N = e.fz;
      double add = 0.0;
      for (auto& [eff, s] : loads)
        add += eff->calcTireLoad(ts, ParamValues(c.p + s, eff->parameters().size()));
      e.fz = std::max(0.0, e.fz + add);
    }
    return e;
  }
};

}  // namespace sim

}  // namespace dtwin
