#include "twin/recorder.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/errors.hpp"

namespace dtwin::sim {
using namespace knot;

namespace {

double hermite(double h, double u, double y0, double m0, double y1, double m1) {
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * h * m0 + (-2 * u3 + 3 * u2) * y1 +
         (u3 - u2) * h * m1;
}
double hermiteD(double h, double u, double y0, double m0, double y1, double m1) {
  const double u2 = u * u;
  return ((6 * u2 - 6 * u) * y0 + (-6 * u2 + 6 * u) * y1) / h + (3 * u2 - 4 * u + 1) * m0 +
         (3 * u2 - 2 * u) * m1;
}

}  // namespace

void Recorder::finish(const Knots& knots, const std::vector<double>& times, const ScenarioSpec& sc,
                      RunResult& res) const {
  if (times.empty()) {  // the integrator could not even start: an empty trace with its channels
    for (auto& ch : runChannels(sys_.model.sensors())) res.trace.addChannel(ch);
    return;
  }
  res.stats.knots = static_cast<long>(knots.size());
  res.stats.sim_s = times.back();
  if (!sc.grid_output && !sc.sample_times_s.empty() &&
      !filteredSensors()) {  // the samples alone (ScenarioSpec::grid_output)
    for (auto& ch : runChannels(sys_.model.sensors())) res.trace.addChannel(ch);
    if (res.stats.ok) {
      DTWIN_CHECK(std::is_sorted(sc.sample_times_s.begin(), sc.sample_times_s.end()) &&
                      sc.sample_times_s.front() >= 0 &&
                      sc.sample_times_s.back() <= times.back() + 1e-9,
                  "sample_times_s must be ascending and within the run");
      writeRows(knots, times, sc, sc.sample_times_s, res.samples);
    }
    return;
  }
  makeOutput(knots, times, sc, res.trace);
  if (!sc.sample_times_s.empty() && res.stats.ok) {
    DTWIN_CHECK(std::is_sorted(sc.sample_times_s.begin(), sc.sample_times_s.end()) &&
                    sc.sample_times_s.front() >= 0 &&
                    sc.sample_times_s.back() <= times.back() + 1e-9,
                "sample_times_s must be ascending and within the run");
    writeRows(knots, times, sc, sc.sample_times_s, res.samples);
    resampleFilteredSensors(res.trace, sc.sample_times_s, res.samples);
  }
}

void Recorder::makeOutput(const Knots& knots, const std::vector<double>& times,
                          const ScenarioSpec& sc, Trace& tr) const {
  const std::size_t n =
      static_cast<std::size_t>(std::floor(times.back() * opt_.output_rate_hz + 1e-9)) + 1;
  std::vector<double> ts(n);
  for (std::size_t r = 0; r < n; ++r)
    ts[r] = std::min(static_cast<double>(r) / opt_.output_rate_hz, times.back());
  writeRows(knots, times, sc, ts, tr);
  filterSensors(tr);
}

void Recorder::writeRows(const Knots& knots, const std::vector<double>& times,
                         const ScenarioSpec& sc, const std::vector<double>& ts, Trace& tr) const {
  const Model& model = sys_.model;
  const RunContext& ctx = sys_.ctx;
  const auto& tires = sys_.tires;
  for (auto& ch : runChannels(model.sensors())) tr.addChannel(ch);
  const std::size_t n = ts.size();
  for (std::size_t i = 0; i < tr.channels().size(); ++i) tr.column(i).resize(n);
  const auto& k0 = knots.front();
  // Prescribed hubs: the State at each output time, rebuilt from the body's interpolated
  // coordinates and auxiliary states; the hubs are read off the signal there, exactly, where the
  // knots (the body's steps) are too far apart to carry the signal's detail.
  const bool prescribed = sys_.prescribed_hubs;
  State st;
  if (prescribed) st = sys_.default_state;
  std::size_t j = 0;
  for (std::size_t r = 0; r < n; ++r) {
    const double t = ts[r];
    while (j + 2 < times.size() && times[j + 1] < t) ++j;
    const std::size_t j1 = std::min(j + 1, times.size() - 1);
    const auto& a = knots[j];
    const auto& b = knots[j1];
    const double h = times[j1] - times[j];
    const double u = h > 0 ? std::clamp((t - times[j]) / h, 0.0, 1.0) : 0.0;
    auto pos = [&](std::size_t iv, std::size_t id) {
      return h > 0 ? hermite(h, u, a[iv], a[id], b[iv], b[id]) : a[iv];
    };
    auto acc = [&](std::size_t iv, std::size_t id) {
      return h > 0 ? hermiteD(h, u, a[iv], a[id], b[iv], b[id]) : a[id];
    };
    std::size_t col = 0;
    tr.column(col++)[r] = t;
    tr.column(col++)[r] = sc.speed.speed(t);
    // Each hub's height, rate and acceleration, and its strut's compression and rate.
    std::array<double, 4> hz{}, hzd{}, hzdd{}, sq{}, sqd{}, fz{};
    if (prescribed) rebuildState(st, t, a, b, h, u);
    // Heave, pitch and roll accelerations: the interpolant's (wheel bodies) or the State's.
    const std::array<double, 3> body_acc =
        prescribed
            ? std::array<double, 3>{st.getUDot()[sys_.heave_u], st.getUDot()[sys_.chassis_u + 1],
                                    st.getUDot()[sys_.chassis_u]}
            : std::array<double, 3>{acc(BODY + 1, BODY + 2), acc(BODY + 4, BODY + 5),
                                    acc(BODY + 7, BODY + 8)};
    for (int c = 0; c < 4; ++c) {
      double hx = 0.0, hxd = 0.0;
      if (prescribed) {
        const StrutGeometry& g = sys_.struts[c];
        Vec3 v;
        TireCorner::HubPath path;
        const auto k = g.prescribedKin(st, &v, &path);
        hx = g.upper.findStationLocationInGround(st, g.st_upper)[0];
        hxd = v[0];
        hz[c] = path.z;
        hzd[c] = path.zd;
        hzdd[c] = tires[c].hubAccel(ctx, t, hx, hxd);
        sq[c] = k.q;
        sqd[c] = k.qd;
        fz[c] = sys_.prescribedHubForce(st, c, hzdd[c]);
      } else {
        hx = pos(HX + c, HXD + c);
        hxd = a[HXD + c] + u * (b[HXD + c] - a[HXD + c]);
        hz[c] = pos(HZ + c, HZD + c);
        hzd[c] = pos(HZD + c, HZDD + c);
        hzdd[c] = acc(HZD + c, HZDD + c);
        sq[c] = pos(Q + c, QD + c);
        sqd[c] = pos(QD + c, QDD + c);
      }
      const TireEval e = tires[c].eval(ctx, t, hx, hxd, hz[c], hzd[c]);
      tr.column(col + c)[r] = prescribed ? fz[c] : e.fz;
      tr.column(col + 4 + c)[r] = e.rho;
      tr.column(col + 8 + c)[r] = sq[c];
      tr.column(col + 12 + c)[r] = sqd[c];
      tr.column(col + 16 + c)[r] = e.road_h;
    }
    col += 20;
    tr.column(col++)[r] = pos(BODY + 0, BODY + 1) - k0[BODY + 0];
    tr.column(col++)[r] = pos(BODY + 3, BODY + 4);
    tr.column(col++)[r] = pos(BODY + 6, BODY + 7);
    tr.column(col++)[r] = body_acc[0];
    tr.column(col++)[r] = body_acc[1];
    tr.column(col++)[r] = body_acc[2];
    for (std::size_t si = 0; si < model.sensors().size();
         ++si) {  // before any filter (filterSensors)
      const SensorSpec& x = model.sensors()[si];
      const Model::SensorSlots& sl = model.sensorSlots()[si];
      const double offset = ctx.p[sl.offset];  // run parameters: a calibration may move them
      Motion m;
      if (x.relative()) {
        // The wheel centre's height in chassis axes, from its start: the travel (compression
        // positive) of a potentiometer parallel to the chassis z axis, wherever its body end is.
        const auto c = static_cast<std::size_t>(x.corner());
        const double cx = isFront(x.corner()) ? model.vehicle().a : -model.vehicle().b;
        const double cy =
            (cornerTrack(x.corner()) == Track::Left ? 0.5 : -0.5) * model.vehicle().track;
        const Motion heave{pos(BODY + 0, BODY + 1), pos(BODY + 1, BODY + 2), 0.0};
        const Motion pitch{pos(BODY + 3, BODY + 4), pos(BODY + 4, BODY + 5), 0.0};
        const Motion roll{pos(BODY + 6, BODY + 7), pos(BODY + 7, BODY + 8), 0.0};
        m = chassisAxisHeight({hz[c], hzd[c], 0.0}, heave, pitch, roll, cx, cy);
        m.q -= chassisAxisHeight({k0[HZ + c], 0, 0}, {k0[BODY + 0], 0, 0}, {k0[BODY + 3], 0, 0},
                                 {k0[BODY + 6], 0, 0}, cx, cy)
                   .q;
        tr.column(col++)[r] = (x.quantity == SensorQuantity::Travel ? m.q : m.qd) + offset;
        continue;
      }
      if (x.corner() >= 0) {
        const std::size_t c = static_cast<std::size_t>(x.corner());
        m = {hz[c] - k0[HZ + c], hzd[c], hzdd[c]};
      } else {
        const Motion heave{pos(BODY + 0, BODY + 1), pos(BODY + 1, BODY + 2), body_acc[0]};
        const Motion pitch{pos(BODY + 3, BODY + 4), pos(BODY + 4, BODY + 5), body_acc[1]};
        const Motion roll{pos(BODY + 6, BODY + 7), pos(BODY + 7, BODY + 8), body_acc[2]};
        const Motion at0{k0[BODY + 0], 0.0, 0.0};
        const std::array<double, 3> where{ctx.p[sl.x], ctx.p[sl.y], ctx.p[sl.z]};
        m = chassisPointMotion(heave, pitch, roll, where);
        m.q -= chassisPointMotion(at0, {k0[BODY + 3], 0, 0}, {k0[BODY + 6], 0, 0}, where).q;
      }
      tr.column(col++)[r] = (x.quantity == SensorQuantity::DisplacementZ ? m.q
                             : x.quantity == SensorQuantity::VelocityZ   ? m.qd
                                                                         : m.qdd) +
                            offset;
    }
  }
}

void Recorder::rebuildState(State& st, double t, const Knot& a, const Knot& b, double h,
                            double u) const {
  auto pos = [&](std::size_t iv, std::size_t id) {
    return h > 0 ? hermite(h, u, a[iv], a[id], b[iv], b[id]) : a[iv];
  };
  st.setTime(t);
  Vector &Qv = st.updQ(), &Uv = st.updU();
  Qv[sys_.heave_q] = pos(BODY + 0, BODY + 1);
  Uv[sys_.heave_u] = pos(BODY + 1, BODY + 2);
  Qv[sys_.chassis_q + 1] = pos(BODY + 3, BODY + 4);
  Uv[sys_.chassis_u + 1] = pos(BODY + 4, BODY + 5);
  Qv[sys_.chassis_q] = pos(BODY + 6, BODY + 7);
  Uv[sys_.chassis_u] = pos(BODY + 7, BODY + 8);
  Vector& Zv = st.updZ();
  for (int i = 0; i < Zv.size(); ++i) {
    const std::size_t iz = ZS + static_cast<std::size_t>(i);
    Zv[i] = a[iz] + u * (b[iz] - a[iz]);
  }
  // The body's accelerations from the forces at the rebuilt State: the struts' damping passes
  // the signal's rate to the body, whose detail the body's steps do not resolve.
  sys_.system.realize(st, Stage::Acceleration);
}

bool Recorder::filteredSensors() const {
  return std::any_of(sys_.model.sensors().begin(), sys_.model.sensors().end(),
                     [](const SensorSpec& x) { return x.filter.order > 0; });
}

void Recorder::filterSensors(Trace& grid) const {
  const auto& sensors = sys_.model.sensors();
  const std::size_t first = runChannels().size();
  for (std::size_t i = 0; i < sensors.size(); ++i)
    if (sensors[i].filter.order > 0)
      grid.column(first + i) =
          lowPass(grid.column(first + i), opt_.output_rate_hz, sensors[i].filter);
}

void Recorder::resampleFilteredSensors(const Trace& grid, const std::vector<double>& ts,
                                       Trace& samples) const {
  const auto& sensors = sys_.model.sensors();
  const std::size_t first = runChannels().size();
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    if (sensors[i].filter.order == 0) continue;
    const auto& g = grid.column(first + i);
    auto& s = samples.column(first + i);
    const double last = static_cast<double>(g.size() - 1) / opt_.output_rate_hz;
    for (std::size_t r = 0; r < ts.size(); ++r)
      s[r] = gridSample(std::min(ts[r], last), opt_.output_rate_hz, g.size()).of(g);
  }
}

}  // namespace dtwin::sim
