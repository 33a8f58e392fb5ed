#include "twin/static_start.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "twin/vehicle_system.hpp"

namespace dtwin {

bool tireFactorsActive(const Model& model, const double* p) {
  for (const auto& f : model.tireFactors())
    for (const auto& x : f)
      if (p[x.slot] != 1.0) return true;
  return false;
}

WarpedStart warpedStart(const Model& M, const double* p) {
  const VehicleData& v = M.vehicle();
  static constexpr double w[4] = {1.0, -1.0, -1.0, 1.0};
  const bool axle = M.topology() == SuspensionTopology::SolidAxle;
  const double e = axle ? v.track / v.spring_track : 1.0;
  const auto s0 = static_cast<std::size_t>(M.suspensionSlots().front()),
             t0 = static_cast<std::size_t>(M.tireSlots().front());
  const std::size_t ns = M.strut().parameters().size(), nt = M.tireSlots().size();
  // The main-strut compression whose force is the preload plus dF (Newton on the law).
  auto compression = [&](int c, double dF) {
    LawValueBuffer buf;
    const ParamValues law =
        Model::scaledLawValues(p, s0, ns, M.strutFactors()[static_cast<std::size_t>(c)], buf);
    const double preload = M.staticStrutForce(c);
    auto excess = [&](double q) {
      StrutState ss;
      ss.deflection_m = q;
      ss.preload_N = preload;
      return M.strut().calcForce(ss, law) - preload - dF;
    };
    double q = 0.0;
    for (int it = 0; it < 30; ++it) {
      const double r = excess(q);
      if (std::abs(r) < 1e-9) break;
      const double h = 1e-6, slope = (excess(q + h) - excess(q - h)) / (2 * h);
      if (!(slope > 0)) break;
      q -= r / slope;
    }
    return q;
  };
  // Sum over the corners of w_c times the drop of the strut's chassis point: the tire's
  // deflection, on a solid axle with the interface's compression and scaled by spring_track /
  // track (the axle's roll carries the wheels' differences to the seats), plus the strut's.
  const double k_wa = axle ? p[M.interfaceSlots()[0]] : 0.0;
  auto residual = [&](double d) {
    double r = 0.0;
    for (int c = 0; c < 4; ++c) {
      LawValueBuffer buf;
      const double W = std::max(0.0, M.staticTireLoad(c) + w[c] * d);
      const double rho = M.tire().calcStaticDeflection(
          W, Model::scaledLawValues(p, t0, nt, M.tireFactors()[static_cast<std::size_t>(c)], buf));
      const double wheel = axle ? (rho + (W - M.staticTireLoad(c)) / k_wa) / e : rho;
      r += w[c] * (wheel + compression(c, w[c] * d * e));
    }
    return r;
  };
  double d = 0.0, r = residual(0.0);
  for (int it = 0; it < 20 && std::abs(r) > 1e-13;
       ++it) {  // secant-Newton: the residual is nearly linear in d
    const double h = 1.0, slope = (residual(d + h) - r) / h;
    if (!(slope > 0)) break;
    d -= r / slope;
    r = residual(d);
  }
  WarpedStart out;
  for (int c = 0; c < 4; ++c) {
    out.tire_load_N[static_cast<std::size_t>(c)] = std::max(0.0, M.staticTireLoad(c) + w[c] * d);
    out.strut_compression_m[static_cast<std::size_t>(c)] = compression(c, w[c] * d * e);
  }
  return out;
}

namespace sim {

State StaticStart::state() {
  State s = sys_.default_state;
  s.setTime(0);
  setEquilibrium(s);
  return s;
}

void StaticStart::setEquilibrium(State& s) {
  const Model& M = sys_.model;
  RunContext& ctx = sys_.ctx;
  const VehicleData& d = M.vehicle();
  const ParamValues tp(ctx.p + sys_.tires[0].p0, sys_.tires[0].np);
  const double R0 = M.tire().unloadedRadius(tp);
  std::array<double, 4> target{};
  // The corners' tire loads: the static ones, warped when the tires differ (warpedStart).
  std::array<double, 4> load{}, strut_q{};
  for (int c = 0; c < 4; ++c) load[c] = M.staticTireLoad(c);
  if (tireFactorsActive(M, ctx.p)) {
    const WarpedStart warp = warpedStart(M, ctx.p);
    load = warp.tire_load_N;
    strut_q = warp.strut_compression_m;
    if (sys_.prescribed_hubs) {
      // the hubs' compressions are the Newton's targets below
    } else if (M.topology() == SuspensionTopology::MacPherson) {
      for (int c = 0; c < 4; ++c) sys_.wheels[c].setOneQ(s, 0, strut_q[c]);
    } else {  // a seat moves by q_h + y sin(phi), y = +-spring_track / 2 (left +)
      for (int ax = 0; ax < 2; ++ax) {
        const double ql = strut_q[2 * ax], qr = strut_q[2 * ax + 1];
        sys_.axle_slider[ax].setOneQ(s, 0, 0.5 * (ql + qr));
        sys_.axle[ax].setOneQ(s, 0, std::asin(std::clamp((ql - qr) / d.spring_track, -1.0, 1.0)));
      }
    }
  }
  for (int c = 0; c < 4; ++c) {
    // The corner's own tire values (its factors applied; tp itself without).
    LawValueBuffer buf;
    const double rho = M.tire().calcStaticDeflection(load[c], sys_.tires[c].values(ctx, buf));
    ctx.hub_rho[static_cast<std::size_t>(c)] = rho;
    const double x_road = -(isFront(c) ? 0.0 : d.wheelbase());
    const double delay = ctx.p[ctx.delay_slot],
                 shift = delay != 0.0 ? ctx.speed.distance(delay) - ctx.speed.distance(0.0) : 0.0;
    double weight = 1.0, ahead = 0.0;
    ctx.signalAt(c, weight, ahead);
    target[c] = weight * ctx.road->sampleAt(c, x_road + ahead + shift).height_m + R0 - rho;
    if (M.topology() == SuspensionTopology::SolidAxle) {
      const double* p = ctx.p;
      const double k = p[M.interfaceSlots()[0]], F0 = p[M.interfacePreloadSlot()];
      const double q = (load[c] - d.wheel_mass * d.gravity - F0) / k;
      sys_.wheels[c].setOneQ(s, 0, q);
    }
  }
  // Newton on (heave, pitch, roll) so that the FL, FR, RL hubs sit at their targets (prescribed
  // hubs: their struts at their compressions, the hubs on the signal).
  auto residual = [&](const Vec3& x) {
    sys_.heave.setOneQ(s, 0, x[0]);
    sys_.chassis.setOneQ(s, 0, x[2]);  // roll
    sys_.chassis.setOneQ(s, 1, x[1]);  // pitch
    sys_.system.realize(s, Stage::Position);
    if (sys_.prescribed_hubs)
      return Vec3(sys_.struts[0].hubAt(s).q - strut_q[0], sys_.struts[1].hubAt(s).q - strut_q[1],
                  sys_.struts[2].hubAt(s).q - strut_q[2]);
    return Vec3(sys_.wheels[0].getBodyOriginLocation(s)[2] - target[0],
                sys_.wheels[1].getBodyOriginLocation(s)[2] - target[1],
                sys_.wheels[2].getBodyOriginLocation(s)[2] - target[2]);
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
  sys_.system.realize(s, Stage::Velocity);
  ctx.heave0 = x[0];
  ctx.pitch0 = x[1];
  ctx.roll0 = x[2];
}

}  // namespace sim

}  // namespace dtwin
