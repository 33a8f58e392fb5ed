#include "report/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/format.hpp"

namespace dtwin::report {

double niceStep(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi <= lo || target < 1) return 0.0;
  const double raw = (hi - lo) / target;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * p >= raw * (1.0 - 1e-9)) return m * p;
  return 10.0 * p;
}

std::vector<double> niceTicks(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) return {};
  if (lo == hi) return {lo};
  const double step = niceStep(lo, hi, target);
  std::vector<double> t;
  const double eps = 1e-6 * step;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps; k += 1.0) {
    const double v = k * step;
    t.push_back(std::abs(v) < eps ? 0.0 : v);
  }
  return t;
}

std::string tickLabel(double v, double step, double magnitude) {
  if (!std::isfinite(v)) return v > 0 ? "inf" : (v < 0 ? "-inf" : "nan");
  step = std::abs(step);
  if (step > 0 && std::abs(v) < 1e-9 * step) v = 0.0;
  const double mag = std::max({std::abs(v), step, std::abs(magnitude)});
  if (v == 0.0) return "0";
  if (mag < 1e-3) {
    // Digits after the point of the mantissa: enough to tell ticks `step` apart.
    const int e = static_cast<int>(std::floor(std::log10(std::abs(v))));
    const int d =
        step > 0 ? std::clamp(e - static_cast<int>(std::floor(std::log10(step) + 1e-9)), 0, 6) : 3;
    std::string s = formatPrintf("%.*e", d, v);
    // "2.0e-05" -> "2e-05": drop a mantissa's trailing zeros and point.
    const auto epos = s.find('e');
    std::string mant = s.substr(0, epos), ex = s.substr(epos);
    if (mant.find('.') != std::string::npos) {
      while (mant.back() == '0') mant.pop_back();
      if (mant.back() == '.') mant.pop_back();
    }
    return mant + ex;
  }
  double scale = 1.0;
  std::string suffix;
  if (mag >= 1e4) {
    static const struct {
      double s;
      const char* p;
    } kSi[] = {{1e12, "T"}, {1e9, "G"}, {1e6, "M"}, {1e3, "k"}};
    for (const auto& si : kSi)
      if (mag >= si.s) {
        scale = si.s;
        suffix = si.p;
        break;
      }
  }
  const double s = step > 0 ? step / scale : 1.0;
  // Decimals: the step's own (2.5 needs one, 0.25 two), at most 9.
  int decimals = 0;
  while (decimals < 9 &&
         std::abs(s * std::pow(10.0, decimals) - std::round(s * std::pow(10.0, decimals))) >
             1e-6 * s * std::pow(10.0, decimals))
    ++decimals;
  std::string out = formatPrintf("%.*f", decimals, v / scale);
  if (out.find_first_not_of("-0.") == std::string::npos) out = "0";
  return out + suffix;
}

void padRange(double& lo, double& hi, double fraction) {
  const double span = hi - lo;
  if (span > 0) {
    lo -= fraction * span;
    hi += fraction * span;
  } else {
    const double m = std::max(std::abs(lo), std::abs(hi));
    const double d = m > 0 ? fraction * m : fraction;
    lo -= d;
    hi += d;
  }
}

std::string gnuplotTics(const std::string& axis, double lo, double hi, int target, bool labelled) {
  if (!(hi > lo)) {
    const double m = std::max(std::abs(lo), std::abs(hi));
    const double d = m > 0 ? 1e-3 * m : 1.0;
    lo -= d;
    hi += d;
  }
  const double step = niceStep(lo, hi, target);
  const std::vector<double> ticks = niceTicks(lo, hi, target);
  double magnitude = 0.0;  // one suffix for the whole axis: the largest tick's
  for (double t : ticks) magnitude = std::max(magnitude, std::abs(t));
  std::ostringstream s;
  s << "set " << axis << "range [" << formatPrintf("%.17g", lo) << ":" << formatPrintf("%.17g", hi)
    << "]\nset " << axis << "tics (";
  bool first = true;
  for (double t : ticks) {
    s << (first ? "" : ", ") << '"' << (labelled ? tickLabel(t, step, magnitude) : std::string())
      << "\" " << formatPrintf("%.17g", t);
    first = false;
  }
  s << ")\n";
  return s.str();
}

std::string axisLabel(const std::string& name, const std::string& unit) {
  if (unit.empty() || unit == "1") return name;
  return name + " [" + unit + "]";
}

}  // namespace dtwin::report
