#include "twin/static_start.hpp"

#include <algorithm>
#include <cmath>

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
  const auto s0 = static_cast<std::size_t>(M.suspensionSlots().front()), t0 = static_cast<std::size_t>(M.tireSlots().front());
  const std::size_t ns = M.strut().parameters().size(), nt = M.tireSlots().size();
  // The main-strut compression whose force is the preload plus dF (Newton on the law).
  auto compression = [&](int c, double dF) {
    LawValueBuffer buf;
    const ParamValues law = Model::scaledLawValues(p, s0, ns, M.strutFactors()[static_cast<std::size_t>(c)], buf);
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
      const double rho = M.tire().calcStaticDeflection(W, Model::scaledLawValues(p, t0, nt, M.tireFactors()[static_cast<std::size_t>(c)], buf));
      const double wheel = axle ? (rho + (W - M.staticTireLoad(c)) / k_wa) / e : rho;
      r += w[c] * (wheel + compression(c, w[c] * d * e));
    }
    return r;
  };
  double d = 0.0, r = residual(0.0);
  for (int it = 0; it < 20 && std::abs(r) > 1e-13; ++it) {  // secant-Newton: the residual is nearly linear in d
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

}  // namespace dtwin
