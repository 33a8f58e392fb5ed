#include "subsystems/time_road.hpp"

#include <algorithm>
#include <cmath>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "subsystems/sensor.hpp"  // kPi

namespace dtwin {

namespace {

struct Layout {
  const char* columns[4];  // one, two (left, right) or four (fl, fr, rl, rr) value columns
  int count;
  TimeRoadLog::Form form;
  double scale;  // to m or m/s
};
const Layout kLayouts[] = {
    {{"height_m", nullptr}, 1, TimeRoadLog::Form::Height, 1.0},
    {{"height_mm", nullptr}, 1, TimeRoadLog::Form::Height, 1e-3},
    {{"left_m", "right_m"}, 2, TimeRoadLog::Form::Height, 1.0},
    {{"left_mm", "right_mm"}, 2, TimeRoadLog::Form::Height, 1e-3},
    {{"height_cm", nullptr}, 1, TimeRoadLog::Form::Height, 1e-2},
    {{"left_cm", "right_cm"}, 2, TimeRoadLog::Form::Height, 1e-2},
    {{"velocity_mmps", nullptr}, 1, TimeRoadLog::Form::Velocity, 1e-3},
    {{"left_mmps", "right_mmps"}, 2, TimeRoadLog::Form::Velocity, 1e-3},
    {{"velocity_mps", nullptr}, 1, TimeRoadLog::Form::Velocity, 1.0},
    {{"left_mps", "right_mps"}, 2, TimeRoadLog::Form::Velocity, 1.0},
    {{"fl_m", "fr_m", "rl_m", "rr_m"}, 4, TimeRoadLog::Form::Height, 1.0},
    {{"fl_mm", "fr_mm", "rl_mm", "rr_mm"}, 4, TimeRoadLog::Form::Height, 1e-3},
    {{"fl_mps", "fr_mps", "rl_mps", "rr_mps"}, 4, TimeRoadLog::Form::Velocity, 1.0},
    {{"fl_mps2", "fr_mps2", "rl_mps2", "rr_mps2"}, 4, TimeRoadLog::Form::Acceleration, 1.0},
};
const char* kHeaders =
    "time_s,height_m | time_s,left_m,right_m | time_s,velocity_mps | time_s,left_mps,right_mps (or "
    "_mm or _cm for heights, _mmps for velocities) | each wheel's motion: "
    "time_s,fl_m,fr_m,rl_m,rr_m (or _mm), time_s,fl_mps,...,rr_mps, time_s,fl_mps2,...,rr_mps2";
}  // namespace

TimeRoadLog parseTimeRoadCsv(const std::string& text, const std::string& name) {
  CsvReader csv(text, name);
  if (!csv.next())
    throw InputError(name + ":1", std::string("empty file; expected a header ") + kHeaders);
  const auto& h = csv.fields();
  const Layout* layout = nullptr;
  for (const auto& l : kLayouts) {
    bool same = h.size() == static_cast<std::size_t>(l.count) + 1 && h[0] == "time_s";
    for (int c = 0; same && c < l.count; ++c)
      same = h[static_cast<std::size_t>(c) + 1] == l.columns[c];
    if (same) layout = &l;
  }
  if (!layout) {
    std::string got;
    for (auto f : h) got += (got.empty() ? "" : ",") + std::string(f);
    throw InputError(csv.where(),
                     "header must be " + std::string(kHeaders) + ", got '" + got + "'");
  }
  TimeRoadLog log;
  log.form = layout->form;
  log.identical_tracks = layout->count == 1;
  log.four_corners = layout->count == 4;
  log.name = name;
  const std::size_t n = static_cast<std::size_t>(layout->count) + 1;
  while (csv.next()) {
    const auto& f = csv.fields();
    if (f.size() != n)
      throw InputError(csv.where(), "expected " + std::to_string(n) + " columns, got " +
                                        std::to_string(f.size()));
    double v[5] = {0, 0, 0, 0, 0};
    for (std::size_t c = 0; c < n; ++c)
      if (!parseNumber(f[c], v[c]) || !std::isfinite(v[c]))
        throw InputError(csv.where(), std::string(c == 0 ? "time_s" : layout->columns[c - 1]) +
                                          ": '" + std::string(f[c]) + "' is not a finite number");
    if (!log.t_s.empty() && !(v[0] > log.t_s.back()))
      throw InputError(csv.where(), "time_s: must increase, got " + std::string(f[0]) + " after " +
                                        formatNumber(log.t_s.back(), 17));
    log.t_s.push_back(v[0]);
    log.left.push_back(v[1] * layout->scale);
    log.right.push_back((layout->count == 1 ? v[1] : v[2]) * layout->scale);
    if (log.four_corners) {
      log.rear_left.push_back(v[3] * layout->scale);
      log.rear_right.push_back(v[4] * layout->scale);
    }
  }
  if (log.t_s.size() < 2)
    throw InputError(name,
                     "a road log needs at least 2 rows, got " + std::to_string(log.t_s.size()));
  return log;
}

TimeRoadLog readTimeRoadCsv(const std::string& path) {
  return parseTimeRoadCsv(readTextFile(path, " (a road against time)"), path);
}

std::vector<double> zeroPhaseHighPass(const std::vector<double>& t, const std::vector<double>& u,
                                      double cutoff_hz) {
  DTWIN_CHECK(t.size() == u.size() && cutoff_hz > 0, "zeroPhaseHighPass: sizes or cut-off");
  if (u.empty()) return u;
  const double wc = 2.0 * kPi * cutoff_hz;
  std::vector<double> y(u.size());
  y[0] = u[0];
  for (std::size_t k = 1; k < u.size(); ++k)
    y[k] = y[k - 1] + (1.0 - std::exp(-wc * (t[k] - t[k - 1]))) * (u[k] - y[k - 1]);
  for (std::size_t k = u.size() - 1; k-- > 0;)
    y[k] = y[k + 1] + (1.0 - std::exp(-wc * (t[k + 1] - t[k]))) * (y[k] - y[k + 1]);
  for (std::size_t k = 0; k < u.size(); ++k) y[k] = u[k] - y[k];
  return y;
}

namespace {
/// Three-point (parabola) derivatives of samples y at times x (one-sided at the ends): exact for
/// quadratics, at any spacing.
std::vector<double> threePointSlopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> m(n, 0.0);
  if (n < 2) return m;
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0)
      m[i] = (y[1] - y[0]) / (x[1] - x[0]);
    else if (i + 1 == n)
      m[i] = (y[n - 1] - y[n - 2]) / (x[n - 1] - x[n - 2]);
    else {
      const double a = x[i] - x[i - 1], b = x[i + 1] - x[i];
      m[i] = (b * (y[i] - y[i - 1]) / a + a * (y[i + 1] - y[i]) / b) / (a + b);
    }
  }
  return m;
}

/// ∫ over [t[k−1], t[k]] of the polynomial through the samples t[lo .. lo+m) (m ≤ 8): the
/// Lagrange basis at 4-point Gauss–Legendre nodes, exact for degree ≤ 7.
double lagrangeIntervalIntegral(const std::vector<double>& t, const std::vector<double>& v,
                                std::size_t lo, std::size_t m, std::size_t k) {
  static constexpr double kNode[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                      0.8611363115940526};
  static constexpr double kWeight[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                        0.3478548451374538};
  const double a = t[k - 1], h = t[k] - t[k - 1];
  double sum = 0;
  for (int g = 0; g < 4; ++g) {
    const double x = a + 0.5 * h * (1.0 + kNode[g]);
    double p = 0;
    for (std::size_t i = lo; i < lo + m; ++i) {
      double basis = 1;
      for (std::size_t j = lo; j < lo + m; ++j)
        if (j != i) basis *= (x - t[j]) / (t[i] - t[j]);
      p += v[i] * basis;
    }
    sum += kWeight[g] * p;
  }
  return 0.5 * h * sum;
}
}  // namespace

std::vector<double> roadHeightFromVelocity(const std::vector<double>& t,
                                           const std::vector<double>& v, double highpass_hz) {
  // Each step is the integral of the polynomial through the eight samples around it (four on
  // each side; shifted inwards at the log's ends): eighth order. At 110 Hz it keeps 99.8 % of a
  // 20 Hz content's height and 99.2 % at 25 Hz, where the cubic Hermite interpolant with
  // three-point slopes (fourth order) kept 97.4 % and 93.8 %: a signal that enters at the hub
  // passes that band to the body, and a damper calibrated on it came out 0.5 % high. Where the
  // stencil's spacings differ by more than a factor 3 (a gap in the log) the step falls back to
  // that Hermite integral, h(t1) − h(t0) = Δt (v0 + v1)/2 + Δt² (a0 − a1)/12.
  constexpr std::size_t kStencil = 8;
  constexpr double kMaxSpacingRatio = 3.0;
  const std::size_t n = v.size();
  const std::vector<double> a = threePointSlopes(t, v);
  std::vector<double> h(n, 0.0);
  for (std::size_t k = 1; k < n; ++k) {
    const double dt = t[k] - t[k - 1];
    double step = 0.5 * (v[k] + v[k - 1]) * dt + dt * dt * (a[k - 1] - a[k]) / 12.0;
    if (n >= kStencil) {
      const std::size_t lo = std::min(k - std::min<std::size_t>(k, kStencil / 2), n - kStencil);
      double lo_dt = dt, hi_dt = dt;
      for (std::size_t i = lo + 1; i < lo + kStencil; ++i) {
        lo_dt = std::min(lo_dt, t[i] - t[i - 1]);
        hi_dt = std::max(hi_dt, t[i] - t[i - 1]);
      }
      if (hi_dt <= kMaxSpacingRatio * lo_dt) step = lagrangeIntervalIntegral(t, v, lo, kStencil, k);
    }
    h[k] = h[k - 1] + step;
  }
  return zeroPhaseHighPass(t, h, highpass_hz);
}

std::shared_ptr<const GridRoad> roadFromTimeLog(const TimeRoadLog& log,
                                                const std::function<double(double)>& distance,
                                                const TimeRoadOptions& o,
                                                nlohmann::json description) {
  DTWIN_CHECK(o.dx_m > 0 && o.highpass_hz > 0, "roadFromTimeLog: options");
  if (log.form == TimeRoadLog::Form::Acceleration) {
    // Integrated once to a velocity (the same quadrature and drift removal), then read as one.
    TimeRoadLog v = log;
    v.form = TimeRoadLog::Form::Velocity;
    v.left = roadHeightFromVelocity(log.t_s, log.left, o.highpass_hz);
    v.right =
        log.identical_tracks ? v.left : roadHeightFromVelocity(log.t_s, log.right, o.highpass_hz);
    return roadFromTimeLog(v, distance, o, std::move(description));
  }
  std::vector<double> left = log.left, right = log.right;
  const bool velocity = log.form == TimeRoadLog::Form::Velocity;
  std::vector<double> rate_l,
      rate_r;  // a velocity log's own dh/dt (its drift removed as the heights' is)
  if (velocity) {
    left = roadHeightFromVelocity(log.t_s, log.left, o.highpass_hz);
    right = log.identical_tracks ? left : roadHeightFromVelocity(log.t_s, log.right, o.highpass_hz);
    rate_l = zeroPhaseHighPass(log.t_s, log.left, o.highpass_hz);
    rate_r = log.identical_tracks ? rate_l : zeroPhaseHighPass(log.t_s, log.right, o.highpass_hz);
  }
  // Heights a road can have: a wrong unit (mm read as m, a velocity's bias integrated without
  // its drift removed) is refused here, not met as a failed simulation.
  for (const auto* h : {&left, &right})
    for (std::size_t k = 0; k < h->size(); ++k)
      if (!(std::abs((*h)[k]) <= 10.0))
        throw InputError(log.name,
                         std::string("the road height at time_s = ") + formatNumber(log.t_s[k]) +
                             " is " + formatNumber((*h)[k]) +
                             " m, beyond the 10 m a road can rise or fall here: check the unit" +
                             (log.form == TimeRoadLog::Form::Velocity ? " and highpass_hz" : ""));
  std::vector<double> x, hl, hr, kept;
  for (std::size_t k = 0; k < log.t_s.size(); ++k) {
    const double d = distance(log.t_s[k]);
    if (!x.empty() && !(d > x.back() + 1e-6)) continue;
    x.push_back(d);
    hl.push_back(left[k]);
    hr.push_back(right[k]);
    kept.push_back(static_cast<double>(k));
  }
  if (x.size() < 2)
    throw InputError(
        log.name,
        "the vehicle moves past fewer than two of its samples: no profile against distance");
  const double x_lo = std::min(o.x_from_m, x.front()), x_hi = x.back() + std::max(0.0, o.x_past_m);
  const double points = (x_hi - x_lo) / o.dx_m + 1;
  if (!(points <= 1e7))
    throw InputError(log.name, "the profile would need " + formatNumber(points, 3) +
                                   " grid points of dx_m = " + formatNumber(o.dx_m) +
                                   " m (at most 1e7): raise dx_m");
  // Slopes at the kept samples: a velocity log's own, dh/dx = (dh/dt) / (dx/dt), where the
  // vehicle moves at more than 0.5 m/s (at 100 Hz the profile then holds a 10 Hz content of the
  // signal to 0.6 %, a 20 Hz one to 4 %); else, and for a height log, three-point (parabola)
  // slopes.
  auto slopes = [&](const std::vector<double>& h, const std::vector<double>& rate) {
    std::vector<double> m = threePointSlopes(x, h);
    if (rate.empty()) return m;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double t = log.t_s[static_cast<std::size_t>(kept[i])], dt = 1e-3;
      const double speed = (distance(t + dt) - distance(t - dt)) / (2 * dt);
      if (speed > 0.5) m[i] = rate[static_cast<std::size_t>(kept[i])] / speed;
    }
    return m;
  };
  const auto ml = slopes(hl, rate_l), mr = slopes(hr, rate_r);
  const auto n = static_cast<std::size_t>(std::ceil((x_hi - x_lo) / o.dx_m)) + 1;
  // A velocity log's grid keeps the interpolant's own slopes at its nodes (the velocity between
  // samples), where central differences of the grid's heights would lose 0.1 % of the body's
  // response at 8-20 Hz on a 2 cm grid; a height log's grid takes its heights' differences.
  const bool own_slopes = !rate_l.empty();
  std::vector<double> gl(n), gr(n), sl(own_slopes ? n : 0), sr(own_slopes ? n : 0);
  std::size_t j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = x_lo + static_cast<double>(i) * o.dx_m;
    if (xi <= x.front()) {
      gl[i] = hl.front();
      gr[i] = hr.front();
      continue;
    }
    if (xi >= x.back()) {  // run on along the last slope (TimeRoadOptions::x_past_m)
      gl[i] = hl.back() + ml.back() * (xi - x.back());
      gr[i] = hr.back() + mr.back() * (xi - x.back());
      if (own_slopes) {
        sl[i] = ml.back();
        sr[i] = mr.back();
      }
      continue;
    }
    while (x[j + 1] < xi) ++j;
    const double hseg = x[j + 1] - x[j], u = (xi - x[j]) / hseg;
    const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u),
                 h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
    gl[i] = h00 * hl[j] + h10 * hseg * ml[j] + h01 * hl[j + 1] + h11 * hseg * ml[j + 1];
    gr[i] = h00 * hr[j] + h10 * hseg * mr[j] + h01 * hr[j + 1] + h11 * hseg * mr[j + 1];
    if (own_slopes) {
      const double d00 = 6 * u * (u - 1), d10 = (1 - u) * (1 - 3 * u), d11 = u * (3 * u - 2);
      sl[i] = d00 * (hl[j] - hl[j + 1]) / hseg + d10 * ml[j] + d11 * ml[j + 1];
      sr[i] = d00 * (hr[j] - hr[j + 1]) / hseg + d10 * mr[j] + d11 * mr[j + 1];
    }
  }
  return std::make_shared<GridRoad>(x_lo, o.dx_m, std::move(gl), std::move(gr),
                                    std::move(description), std::move(sl), std::move(sr));
}

std::shared_ptr<const CornerRoad> cornerRoadFromTimeLog(
    const TimeRoadLog& log, const std::function<double(double)>& distance, double wheelbase_m,
    const TimeRoadOptions& o, nlohmann::json description) {
  DTWIN_CHECK(log.four_corners && log.rear_left.size() == log.t_s.size() &&
                  log.rear_right.size() == log.t_s.size(),
              "cornerRoadFromTimeLog: a four-corner log");
  TimeRoadLog front = log, rear = log;
  front.four_corners = rear.four_corners = false;
  front.rear_left.clear();
  front.rear_right.clear();
  rear.left = log.rear_left;
  rear.right = log.rear_right;
  rear.rear_left.clear();
  rear.rear_right.clear();
  auto f = roadFromTimeLog(front, distance, o, description);
  // The rear wheels' profile on the distance their contact points have: a rear wheel at time t is
  // at distance(t) - wheelbase_m and reads its sample of time t there.
  auto r = roadFromTimeLog(
      rear, [&distance, wheelbase_m](double t) { return distance(t) - wheelbase_m; }, o,
      description);
  return std::make_shared<CornerRoad>(std::move(f), std::move(r), std::move(description));
}

}  // namespace dtwin
