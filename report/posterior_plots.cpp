#include "report/posterior_plots.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include "calibration/summary.hpp"
#include "common/format.hpp"
#include "report/ticks.hpp"

namespace dtwin::report {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// gnuplot's arrow from (x, graph 0) to (x, graph 1).
std::string vline(double x, const std::string& style) {
  return "set arrow from " + plotNumber(x) + ", graph 0 to " + plotNumber(x) + ", graph 1 nohead " +
         style + "\n";
}

}  // namespace

Density weightedDensity(const std::vector<double>& v, double lo, double hi, int points) {
  Density d;
  if (v.empty() || points < 2 || !(hi > lo)) return d;
  std::map<double, long> count;
  for (double x : v) ++count[x];
  const double n = static_cast<double>(v.size());
  for (const auto& [x, c] : count) {
    d.atoms.push_back(x);
    d.mass.push_back(static_cast<double>(c) / n);
  }
  // Spread of the weighted atoms: sd and IQR.
  double mean = 0.0;
  for (std::size_t k = 0; k < d.atoms.size(); ++k) mean += d.mass[k] * d.atoms[k];
  double var = 0.0;
  for (std::size_t k = 0; k < d.atoms.size(); ++k)
    var += d.mass[k] * (d.atoms[k] - mean) * (d.atoms[k] - mean);
  std::vector<double> sorted = v;
  std::sort(sorted.begin(), sorted.end());
  const double iqr = quantileSorted(sorted, 0.75) - quantileSorted(sorted, 0.25);
  const double spread = iqr > 0 ? std::min(std::sqrt(var), iqr / 1.34) : std::sqrt(var);
  const double m = static_cast<double>(d.atoms.size());
  double gap = 0.0;
  if (d.atoms.size() > 1) {
    std::vector<double> gaps;
    for (std::size_t k = 1; k < d.atoms.size(); ++k) gaps.push_back(d.atoms[k] - d.atoms[k - 1]);
    std::sort(gaps.begin(), gaps.end());
    gap = quantileSorted(gaps, 0.5);
  }
  d.bandwidth = std::max({0.9 * spread * std::pow(m, -0.2), gap, (hi - lo) / 200.0});
  const double h = d.bandwidth, norm = 1.0 / (h * std::sqrt(2.0 * kPi));
  for (int i = 0; i < points; ++i) {
    const double x = lo + (hi - lo) * i / (points - 1);
    double f = 0.0;
    for (std::size_t k = 0; k < d.atoms.size(); ++k) {
      const double u = (x - d.atoms[k]) / h;
      if (std::abs(u) < 9.0) f += d.mass[k] * std::exp(-0.5 * u * u);
    }
    d.x.push_back(x);
    d.f.push_back(f * norm);
  }
  return d;
}

std::vector<std::array<double, 2>> projectedRegion(const calib::Region& r, int i, int j) {
  const int d = r.dim();
  const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
  const double wi = r.upper[si] - r.lower[si], wj = r.upper[sj] - r.lower[sj];
  // Centre of the parallelepiped and its half-edge generators, projected (scaled units).
  const Eigen::VectorXd mid = r.at(0.5 * (r.t_lower + r.t_upper));
  std::array<double, 2> c{mid(i), mid(j)};
  std::vector<std::array<double, 2>> g;
  for (int k = 0; k < d; ++k) {
    const double half = 0.5 * (r.t_upper(k) - r.t_lower(k));
    std::array<double, 2> v{r.axes(i, k) * half, r.axes(j, k) * half};
    if (std::hypot(v[0], v[1]) == 0.0) continue;
    if (v[1] < 0 || (v[1] == 0 && v[0] < 0)) v = {-v[0], -v[1]};  // angle in [0, π)
    g.push_back(v);
  }
  std::sort(g.begin(), g.end(), [](const auto& a, const auto& b) {
    return std::atan2(a[1], a[0]) < std::atan2(b[1], b[0]);
  });
  // Start at the lowest vertex c − Σ g (every generator points up), walk +2g in angle order,
  // then −2g: a convex polygon, counter-clockwise.
  std::array<double, 2> p = c;
  for (const auto& v : g) p = {p[0] - v[0], p[1] - v[1]};
  std::vector<std::array<double, 2>> poly{p};
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& v : g) {
      const double s = pass == 0 ? 2.0 : -2.0;
      p = {p[0] + s * v[0], p[1] + s * v[1]};
      poly.push_back(p);
    }
  if (g.empty()) poly.push_back(p);
  for (auto& q : poly) q = {r.lower[si] + q[0] * wi, r.lower[sj] + q[1] * wj};
  return poly;
}

void axisRange(ParameterMarks& m, const std::vector<double>& extra) {
  double lo = INFINITY, hi = -INFINITY;
  auto take = [&](double x) {
    if (!std::isfinite(x)) return;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  };
  for (double x : m.sample) take(x);
  for (double x : extra) take(x);
  if (m.truth) take(*m.truth);
  if (m.optimum) take(*m.optimum);
  if (m.profile) {
    take(m.profile->first);
    take(m.profile->second);
  }
  if (!(lo <= hi)) lo = hi = 0.0;
  padRange(lo, hi, 0.04);
  m.lo = lo;
  m.hi = hi;
}

std::string densityPanel(GnuplotSvg& gp, const ParameterMarks& m, bool labelled, int target_ticks) {
  const Density dn = weightedDensity(m.sample, m.lo, m.hi);
  std::ostringstream data, rug;
  double fmax = 0.0;
  for (std::size_t k = 0; k < dn.x.size(); ++k) {
    data << plotNumber(dn.x[k]) << ' ' << plotNumber(dn.f[k]) << '\n';
    fmax = std::max(fmax, dn.f[k]);
  }
  for (double a : dn.atoms) rug << plotNumber(a) << ' ' << plotNumber(0.05 * fmax) << '\n';
  std::ostringstream s;
  s << "unset arrow\nunset label\n"
    << gnuplotTics("x", m.lo, m.hi, target_ticks, labelled) << "unset ytics\n"
    << "set yrange [0:" << plotNumber(fmax > 0 ? 1.08 * fmax : 1.0) << "]\n";
  if (!m.sample.empty()) {
    std::vector<double> sorted = m.sample;
    std::sort(sorted.begin(), sorted.end());
    for (double q : {quantileSorted(sorted, 0.025), quantileSorted(sorted, 0.975)})
      s << vline(q, "lw 1 dt 2 lc rgb '#222222'");
  }
  if (m.profile)
    for (double q : {m.profile->first, m.profile->second})
      s << vline(q, "lw 2 dt 3 lc rgb '#2a8a3a'");
  if (m.optimum) s << vline(*m.optimum, "lw 1.5 dt 4 lc rgb '#000000'");
  if (m.truth) s << vline(*m.truth, "lw 2 lc rgb '#c03020'");
  s << "set xlabel " << (labelled ? gnuplotQuote(axisLabel(m.name, m.unit)) : std::string("''"))
    << " noenhanced\n";
  if (dn.x.empty()) {
    s << "plot 1/0 notitle\n";
    return s.str();
  }
  s << "plot " << gp.data(data.str())
    << " using 1:2 with filledcurves y1=0 lc rgb '#4a7fc0' fs solid 0.35 notitle, '' using 1:2 "
    << "with lines lw 1.5 lc rgb '#1f4f90' notitle, " << gp.data(rug.str())
    << " using 1:2 with impulses lc rgb '#555555' notitle\n";
  return s.str();
}

double sampleCorrelation(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  if (n < 2) return 0.0;
  const double ma =
      std::accumulate(a.begin(), a.begin() + static_cast<long>(n), 0.0) / static_cast<double>(n);
  const double mb =
      std::accumulate(b.begin(), b.begin() + static_cast<long>(n), 0.0) / static_cast<double>(n);
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t k = 0; k < n; ++k) {
    sab += (a[k] - ma) * (b[k] - mb);
    saa += (a[k] - ma) * (a[k] - ma);
    sbb += (b[k] - mb) * (b[k] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

namespace {

/// One panel below the diagonal: parameter `x` across, `y` up.
std::string pairPanel(GnuplotSvg& gp, const ParameterMarks& x, const ParameterMarks& y, int ix,
                      int iy, const std::optional<calib::Region>& region, bool xlab, bool ylab) {
  std::map<std::pair<double, double>, long> mass;
  const std::size_t n = std::min(x.sample.size(), y.sample.size());
  for (std::size_t k = 0; k < n; ++k) ++mass[{x.sample[k], y.sample[k]}];
  long most = 1;
  for (const auto& [p, c] : mass) most = std::max(most, c);
  std::ostringstream pts;
  for (const auto& [p, c] : mass)
    pts << plotNumber(p.first) << ' ' << plotNumber(p.second) << ' '
        << plotNumber(0.25 + 1.6 * std::sqrt(double(c) / most)) << '\n';
  std::ostringstream s;
  s << "unset arrow\nunset label\nunset object\n"
    << gnuplotTics("x", x.lo, x.hi, 4, xlab) << gnuplotTics("y", y.lo, y.hi, 4, ylab)
    << "set xlabel " << (xlab ? gnuplotQuote(axisLabel(x.name, x.unit)) : std::string("''"))
    << " noenhanced\n"
    << "set ylabel " << (ylab ? gnuplotQuote(axisLabel(y.name, y.unit)) : std::string("''"))
    << " noenhanced\n";
  if (x.profile && y.profile)
    s << "set object 1 rect from " << plotNumber(x.profile->first) << ","
      << plotNumber(y.profile->first) << " to " << plotNumber(x.profile->second) << ","
      << plotNumber(y.profile->second) << " fs empty border lc rgb '#2a8a3a' dt 3 lw 1.5\n";
  std::string plot = "plot " + gp.data(pts.str()) +
                     " using 1:2:3 with points pt 7 ps variable lc rgb '#4a7fc0' notitle";
  if (region) {
    std::ostringstream poly;
    for (const auto& v : projectedRegion(*region, ix, iy))
      poly << plotNumber(v[0]) << ' ' << plotNumber(v[1]) << '\n';
    plot += ", " + gp.data(poly.str()) + " using 1:2 with lines lw 1 lc rgb '#777777' notitle";
  }
  if (x.optimum && y.optimum) {
    std::ostringstream o;
    o << plotNumber(*x.optimum) << ' ' << plotNumber(*y.optimum) << '\n';
    plot += ", " + gp.data(o.str()) +
            " using 1:2 with points pt 2 ps 1.4 lw 2 lc rgb '#000000' notitle";
  }
  if (x.truth && y.truth) {
    std::ostringstream t;
    t << plotNumber(*x.truth) << ' ' << plotNumber(*y.truth) << '\n';
    plot += ", " + gp.data(t.str()) +
            " using 1:2 with points pt 3 ps 1.6 lw 2 lc rgb '#c03020' notitle";
  }
  s << plot << "\n";
  return s.str();
}

}  // namespace

std::string pairPlot(GnuplotSvg& gp, const std::vector<ParameterMarks>& params,
                     const std::optional<calib::Region>& region, const std::string& title) {
  const int d = static_cast<int>(params.size());
  const int size = std::clamp(150 * d, 500, 1400);
  std::ostringstream s;
  // Both ends of a region edge may lie outside a panel: `clip two` still draws the part inside.
  s << "set multiplot layout " << d << "," << d
    << " margins 0.13,0.98,0.1,0.94 spacing 0.012,0.012 title " << gnuplotQuote(title)
    << " noenhanced\nset key off\nset grid\nset clip two\nset style fill transparent solid 0.35 "
       "noborder\n"
    << "set xlabel font ',8'\nset ylabel font ',8' offset 1,0\nset tics font ',8'\n";
  for (int r = 0; r < d; ++r)
    for (int c = 0; c < d; ++c) {
      const bool bottom = r == d - 1, left = c == 0;
      const auto& pr = params[static_cast<std::size_t>(r)];
      const auto& pc = params[static_cast<std::size_t>(c)];
      if (r == c) {
        s << "set ylabel " << (left ? gnuplotQuote(axisLabel(pr.name, pr.unit)) : std::string("''"))
          << " noenhanced\n"
          << densityPanel(gp, pr, bottom, 4);
      } else if (r > c) {
        s << pairPanel(gp, pc, pr, c, r, region, bottom, left);
      } else {
        // Above the diagonal: the posterior correlation of the two.
        const double rho = sampleCorrelation(pc.sample, pr.sample);
        s << "unset arrow\nunset label\nunset object\nunset xtics\nunset ytics\nunset "
             "xlabel\nunset ylabel\nunset grid\n"
          << "set xrange [0:1]\nset yrange [0:1]\nset border 0\nset label 1 "
          << gnuplotQuote("ρ = " + formatPrintf("%.2f", rho))
          << " at 0.5,0.5 center font ',11' textcolor rgb '"
          << (std::abs(rho) > 0.7 ? "#b03020" : "#333333") << "'\n"
          << "plot 1/0 notitle\nset border 31\nset grid\n";
      }
    }
  s << "unset multiplot\n";
  return gp.plot(s.str(), size, size, title);
}

}  // namespace dtwin::report
