// What changed over several drives of one car (diagnosis/changes_series.hpp).
#include "diagnosis/changes_series.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/statistics.hpp"
#include "io/log_import.hpp"  // parseClockTime

namespace dtwin::diag {
namespace {

const double kSeriesZ975 = normalQuantile(0.975);
constexpr double kDaysPerYear = 365.25;

std::string seriesNumber(double v) { return formatNumber(v, 4); }

std::string dateOnly(const std::string& d) {
  return d.substr(0, std::min<std::size_t>(10, d.size()));
}

/// The weighted least-squares line of y on t (weights w): its slope with its sd, its value at each
/// t, and the χ² per degree of freedom of the scatter about it.
void weightedLine(const std::vector<double>& t, const std::vector<double>& y,
                  const std::vector<double>& w, double& slope, double& sd,
                  std::vector<double>& line, double& chi2_dof) {
  double sw = 0, st = 0, sy = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    sw += w[i];
    st += w[i] * t[i];
    sy += w[i] * y[i];
  }
  const double tm = st / sw, ym = sy / sw;
  double stt = 0, sty = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    stt += w[i] * (t[i] - tm) * (t[i] - tm);
    sty += w[i] * (t[i] - tm) * (y[i] - ym);
  }
  slope = sty / stt;
  sd = 1 / std::sqrt(stt);
  double chi2 = 0;
  line.clear();
  for (std::size_t i = 0; i < t.size(); ++i) {
    line.push_back(ym + slope * (t[i] - tm));
    const double r = y[i] - line.back();
    chi2 += w[i] * r * r;
  }
  chi2_dof = chi2 / static_cast<double>(t.size() - 2);
}

std::string describeTrend(const SeriesValue& v, const SeriesReport& r) {
  std::string s = v.name;
  const std::string unit = v.unit.empty() || v.unit == "1" ? "" : " " + v.unit;
  if (v.ratio) {
    const double pct = 100 * (v.slope - 1);
    s += pct <= 0 ? " fell by " : " rose by ";
    s += seriesNumber(std::fabs(pct)) + " % a year (95 %: x " + seriesNumber(v.lo) + " to x " +
         seriesNumber(v.hi) + " a year)";
  } else {
    s += " moved by " + std::string(v.slope >= 0 ? "+" : "") + seriesNumber(v.slope) + unit +
         " a year (95 %: " + seriesNumber(v.lo) + " to " + seriesNumber(v.hi) + unit + ")";
  }
  const ValueEstimate &a = v.drives.front(), &b = v.drives.back();
  s += " over " + std::to_string(v.drives.size()) + " drives, " + dateOnly(r.dates.front()) +
       " to " + dateOnly(r.dates.back()) + ": " + seriesNumber(a.estimate) + " [" +
       seriesNumber(a.lo) + ", " + seriesNumber(a.hi) + "] -> " + seriesNumber(b.estimate) + " [" +
       seriesNumber(b.lo) + ", " + seriesNumber(b.hi) + "]" + unit;
  s += v.significant ? "; significant" : "; no significant trend";
  if (v.chi2_dof > 3)
    s += " (the drives scatter about the line " + formatPrintf("%.1f", v.chi2_dof) +
         " times as much as their intervals allow: not a straight decline)";
  if (!v.trusted) s += " (some drives' intervals are not to be trusted)";
  return s;
}

}  // namespace

bool parseDriveDate(const std::string& text, double& day) {
  std::string t = text;
  while (!t.empty() && t.back() == ' ') t.pop_back();
  while (!t.empty() && t.front() == ' ') t.erase(0, 1);
  if (t.size() == 10) t += "T00:00:00";
  ClockTime c;
  if (!parseClockTime(t, c) || !c.has_date) return false;
  day = static_cast<double>(c.day) + c.seconds / 86400.0;
  return true;
}

SeriesReport compareSeries(std::vector<DatedCalibration> drives, double level,
                           const std::string& where) {
  if (!(level > 0 && level < 0.5))
    throw InputError("changes.level", "must lie in (0, 0.5), got " + formatNumber(level));
  if (drives.size() < 3)
    throw InputError(where,
                     "a series needs at least three calibrations (two: --before and "
                     "--after), got " +
                         std::to_string(drives.size()));
  std::stable_sort(
      drives.begin(), drives.end(),
      [](const DatedCalibration& a, const DatedCalibration& b) { return a.day < b.day; });
  SeriesReport r;
  r.level = level;
  r.assembly = drives.front().folder.assembly;
  for (std::size_t i = 0; i < drives.size(); ++i) {
    if (i > 0 && drives[i].day == drives[i - 1].day)
      throw InputError(where, "two calibrations have the same date " + drives[i].date + " (" +
                                  drives[i - 1].folder.dir + ", " + drives[i].folder.dir +
                                  "): each drive needs its own date");
    r.dirs.push_back(drives[i].folder.dir);
    r.dates.push_back(drives[i].date);
    r.days.push_back(drives[i].day);
    if (drives[i].folder.assembly != r.assembly)
      r.notes.push_back("the calibrations are of different assemblies (" + r.assembly + ", " +
                        drives[i].folder.assembly + "): values of the same name are compared");
  }
  // The values every drive calibrated.
  std::vector<std::string> names = parameterNames(drives.front().folder);
  for (std::size_t i = 1; i < drives.size(); ++i) {
    const auto other = parameterNames(drives[i].folder);
    for (const auto& n : names)
      if (std::find(other.begin(), other.end(), n) == other.end())
        r.notes.push_back(n + " is not calibrated in " + drives[i].folder.dir + ": left out");
    names.erase(std::remove_if(names.begin(), names.end(),
                               [&](const std::string& n) {
                                 return std::find(other.begin(), other.end(), n) == other.end();
                               }),
                names.end());
  }
  r.first_to_last = compareCalibrations(drives.front().folder, drives.back().folder, level);
  std::vector<double> t_years;
  for (double d : r.days) t_years.push_back((d - r.days.front()) / kDaysPerYear);
  std::vector<double> p;
  for (const auto& n : names) {
    SeriesValue v;
    v.name = n;
    v.ratio = true;
    for (const auto& d : drives) {
      v.drives.push_back(valueEstimate(d.folder, n));
      const ValueEstimate& e = v.drives.back();
      v.ratio = v.ratio && e.lo > 0 && e.estimate > 0;
      v.trusted = v.trusted && e.trusted;
    }
    for (const auto& c : r.first_to_last.changes)
      if (c.name == n) v.unit = c.unit;
    std::vector<double> y, w;
    for (auto& e : v.drives) {
      if (e.centred && !v.ratio) e.estimate = 0.5 * (e.lo + e.hi);
      auto scale = [&](double x) { return v.ratio ? std::log(x) : x; };
      const double sd = (scale(e.hi) - scale(e.lo)) / (2 * kSeriesZ975);
      y.push_back(scale(e.estimate));
      w.push_back(sd > 0 ? 1 / (sd * sd) : 0.0);
    }
    if (std::any_of(w.begin(), w.end(), [](double x) { return x == 0.0; })) {
      r.notes.push_back(n + ": an interval of zero width; its trend is not judged");
      continue;
    }
    double slope = 0, sd = 0;
    weightedLine(t_years, y, w, slope, sd, v.line, v.chi2_dof);
    if (v.ratio)
      for (double& x : v.line) x = std::exp(x);
    v.z = slope / sd;
    v.p = 2 * normalCdf(-std::fabs(v.z));
    v.slope = v.ratio ? std::exp(slope) : slope;
    v.lo = v.ratio ? std::exp(slope - kSeriesZ975 * sd) : slope - kSeriesZ975 * sd;
    v.hi = v.ratio ? std::exp(slope + kSeriesZ975 * sd) : slope + kSeriesZ975 * sd;
    p.push_back(v.p);
    r.values.push_back(std::move(v));
  }
  const auto reject = holmRejections(p, level);
  for (std::size_t i = 0; i < r.values.size(); ++i) r.values[i].significant = reject[i];
  std::stable_sort(r.values.begin(), r.values.end(),
                   [](const SeriesValue& a, const SeriesValue& b) {
                     if (a.significant != b.significant) return a.significant;
                     return std::fabs(a.z) > std::fabs(b.z);
                   });
  for (auto& v : r.values) v.sentence = describeTrend(v, r);
  return r;
}

std::size_t SeriesReport::significantCount() const {
  return static_cast<std::size_t>(std::count_if(
      values.begin(), values.end(), [](const SeriesValue& v) { return v.significant; }));
}

nlohmann::json SeriesReport::toJson() const {
  nlohmann::json j;
  j["assembly"] = assembly;
  j["level"] = level;
  j["rule"] =
      "each value's weighted least-squares line against the drive's date (log scale for a "
      "positive value), Holm's step-down rule over every value's trend, family-wise " +
      formatNumber(100 * level) + " %";
  j["drives"] = nlohmann::json::array();
  for (std::size_t i = 0; i < dirs.size(); ++i)
    j["drives"].push_back({{"calibration", dirs[i]}, {"date", dates[i]}, {"day", days[i]}});
  j["significant"] = significantCount();
  j["values"] = nlohmann::json::array();
  for (const auto& v : values) {
    nlohmann::json d = nlohmann::json::array();
    for (const auto& e : v.drives)
      d.push_back({{"optimum", e.optimum},
                   {"estimate", e.estimate},
                   {"optimum_outside_interval", e.centred},
                   {"ci95", {e.lo, e.hi}},
                   {"trusted", e.trusted},
                   {"note", e.note}});
    j["values"].push_back({{"name", v.name},
                           {"unit", v.unit},
                           {"kind", v.ratio ? "ratio per year" : "difference per year"},
                           {"drives", d},
                           {"line", v.line},
                           {"trend", v.slope},
                           {"trend_ci95", {v.lo, v.hi}},
                           {"z", v.z},
                           {"p", v.p},
                           {"chi2_per_dof", v.chi2_dof},
                           {"significant", v.significant},
                           {"trusted", v.trusted},
                           {"sentence", v.sentence}});
  }
  j["first_to_last"] = first_to_last.toJson();
  j["notes"] = notes;
  return j;
}

std::string SeriesReport::text() const {
  std::string s = std::to_string(dirs.size()) + " drives, " + dateOnly(dates.front()) + " to " +
                  dateOnly(dates.back()) + ":";
  for (std::size_t i = 0; i < dirs.size(); ++i) s += (i ? ", " : " ") + dateOnly(dates[i]);
  s += "\n";
  const std::size_t k = significantCount();
  s += std::to_string(k) + " of " + std::to_string(values.size()) +
       " values have a significant trend (Holm, family-wise " + formatNumber(100 * level) + " %)" +
       (k ? ":" : "") + "\n";
  for (const auto& v : values)
    if (v.significant) s += "  " + v.sentence + "\n";
  if (k < values.size()) s += "no significant trend:\n";
  for (const auto& v : values)
    if (!v.significant) s += "  " + v.sentence + "\n";
  s += "drive by drive (estimate [95 %]):\n";
  for (const auto& v : values) {
    s += "  " + v.name + ":";
    for (std::size_t i = 0; i < v.drives.size(); ++i)
      s += (i ? ";" : "") + std::string(" ") + dateOnly(dates[i]) + " " +
           seriesNumber(v.drives[i].estimate) + " [" + seriesNumber(v.drives[i].lo) + ", " +
           seriesNumber(v.drives[i].hi) + "]";
    s += "\n";
  }
  s += "first drive to last:\n";
  std::string pair = first_to_last.text();
  for (std::size_t a = 0; a < pair.size();) {
    const std::size_t b = pair.find('\n', a);
    s += "  " + pair.substr(a, b - a) + "\n";
    if (b == std::string::npos) break;
    a = b + 1;
  }
  for (const auto& n : notes) s += "note: " + n + "\n";
  return s;
}

}  // namespace dtwin::diag
