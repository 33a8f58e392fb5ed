// What changed between two calibrations of one car (diagnosis/changes.hpp).
#include "diagnosis/changes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/statistics.hpp"

namespace dtwin::diag {
namespace {

const double kZ975 = normalQuantile(0.975);

std::string summaryPath(const calib::CalibrationFolder& f) { return f.dir + "/summary.json"; }

/// The unit of `name` in summary.json (parameter_order and units side by side), "" if absent.
std::string unitOf(const calib::CalibrationFolder& f, const std::string& name) {
  const auto& s = f.summary;
  if (!s.contains("parameter_order") || !s.contains("units")) return "";
  const auto& order = s["parameter_order"];
  for (std::size_t i = 0; i < order.size() && i < s["units"].size(); ++i)
    if (order[i].is_string() && order[i].get<std::string>() == name && s["units"][i].is_string())
      return s["units"][i].get<std::string>();
  return "";
}

/// The lower bound of `name`'s calibration range, or NaN when summary.json does not record it.
double lowerBound(const calib::CalibrationFolder& f, const std::string& name) {
  const auto& s = f.summary;
  if (!s.contains("parameter_order") || !s.contains("bounds")) return std::nan("");
  const auto& order = s["parameter_order"];
  for (std::size_t i = 0; i < order.size() && i < s["bounds"].size(); ++i)
    if (order[i].is_string() && order[i].get<std::string>() == name && s["bounds"][i].is_array() &&
        !s["bounds"][i].empty() && s["bounds"][i][0].is_number())
      return s["bounds"][i][0].get<double>();
  return std::nan("");
}

std::string number(double v) { return formatNumber(v, 4); }

std::string describe(const ValueChange& c) {
  std::string s = c.name;
  const std::string unit = c.unit.empty() || c.unit == "1" ? "" : " " + c.unit;
  if (c.ratio) {
    s += c.change >= 1 ? " rose to " : " fell to ";
    s += number(c.change) + " x its first value (95 %: " + number(c.lo) + " to " + number(c.hi) +
         ")";
  } else {
    s += " moved by " + std::string(c.change >= 0 ? "+" : "") + number(c.change) + unit +
         " (95 %: " + number(c.lo) + " to " + number(c.hi) + unit + ")";
  }
  s += ": " + number(c.first.estimate) + " -> " + number(c.second.estimate) + unit;
  s += c.significant ? "; significant" : "; no significant change";
  if (!c.trusted) {
    std::string why = !c.first.trusted ? "first: " + c.first.note : "";
    if (!c.second.trusted)
      why += (why.empty() ? "" : "; ") + std::string("second: ") + c.second.note;
    s += " (intervals not to be trusted: " + why + ")";
  }
  if (c.first.centred || c.second.centred)
    s += c.first.centred && c.second.centred
             ? " (both optima lie outside their intervals: the profile search met better fits; the "
               "intervals' centres are compared)"
             : std::string(" (the ") + (c.first.centred ? "first" : "second") +
                   " calibration's optimum lies outside its interval: the profile search met a "
                   "better fit; the interval's centre is compared)";
  return s;
}

}  // namespace

std::vector<std::string> parameterNames(const calib::CalibrationFolder& f) {
  std::vector<std::string> names;
  const auto& s = f.summary;
  if (s.contains("parameter_order") && s["parameter_order"].is_array()) {
    for (const auto& n : s["parameter_order"])
      if (n.is_string()) names.push_back(n.get<std::string>());
  } else if (s.contains("parameters") && s["parameters"].is_object()) {
    for (const auto& [k, v] : s["parameters"].items()) names.push_back(k);
  }
  return names;
}

ValueEstimate valueEstimate(const calib::CalibrationFolder& folder, const std::string& name) {
  const std::string where = summaryPath(folder) + ": parameters." + name;
  const auto& s = folder.summary;
  if (!s.contains("parameters") || !s["parameters"].is_object() || !s["parameters"].contains(name))
    throw InputError(where, "missing: the calibration has no such value");
  const auto& p = s["parameters"][name];
  if (!p.is_object() || !p.contains("optimum") || !p["optimum"].is_number())
    throw InputError(where + ".optimum", "must be a number");
  if (!p.contains("ci95") || !p["ci95"].is_array() || p["ci95"].size() != 2 ||
      !p["ci95"][0].is_number() || !p["ci95"][1].is_number())
    throw InputError(where + ".ci95", "must be two numbers [lower, upper]");
  ValueEstimate e;
  e.optimum = p["optimum"].get<double>();
  e.lo = p["ci95"][0].get<double>();
  e.hi = p["ci95"][1].get<double>();
  if (!std::isfinite(e.optimum) || !std::isfinite(e.lo) || !std::isfinite(e.hi))
    throw InputError(where, "optimum and ci95 must be finite numbers");
  if (e.lo > e.hi) throw InputError(where + ".ci95", "lower end above the upper end");
  e.interval = p.value("interval", s.value("interval", std::string("profile")));
  e.estimate = e.optimum;
  if (e.optimum < e.lo || e.optimum > e.hi) {
    e.centred = true;
    e.estimate = e.lo > 0 ? std::sqrt(e.lo * e.hi) : 0.5 * (e.lo + e.hi);
  }
  if (s.contains("integrator_check") && s["integrator_check"].is_object() &&
      s["integrator_check"].contains("ok") && s["integrator_check"]["ok"].is_boolean() &&
      !s["integrator_check"]["ok"].get<bool>()) {
    e.trusted = false;
    e.note = "the integrator limits the calibration's intervals";
  }
  for (const auto& b : folder.bound_findings)
    if (b.name == name) {
      e.trusted = false;
      e.note += (e.note.empty() ? "" : "; ") + std::string(b.side == "none"
                                                               ? "the data do not determine it"
                                                               : "on its " + b.side + " bound");
    }
  return e;
}

std::vector<bool> holmRejections(const std::vector<double>& p, double level) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<bool> reject(p.size(), false);
  const std::size_t m = p.size();
  for (std::size_t k = 0; k < m; ++k) {
    if (!(p[order[k]] <= level / static_cast<double>(m - k)))
      break;  // step down: stop at the first acceptance
    reject[order[k]] = true;
  }
  return reject;
}

ChangeReport compareCalibrations(const calib::CalibrationFolder& first,
                                 const calib::CalibrationFolder& second, double level) {
  if (!(level > 0 && level < 0.5))
    throw InputError("changes.level", "must lie in (0, 0.5), got " + formatNumber(level));
  ChangeReport r;
  r.first_dir = first.dir;
  r.second_dir = second.dir;
  r.assembly = first.assembly;
  r.level = level;
  if (first.assembly != second.assembly)
    r.notes.push_back("the calibrations are of different assemblies (" + first.assembly + ", " +
                      second.assembly + "): values of the same name are compared");
  const auto names1 = parameterNames(first), names2 = parameterNames(second);
  for (const auto& n : names1)
    if (std::find(names2.begin(), names2.end(), n) == names2.end()) r.only_first.push_back(n);
  for (const auto& n : names2)
    if (std::find(names1.begin(), names1.end(), n) == names1.end()) r.only_second.push_back(n);
  std::vector<double> p;
  for (const auto& n : names1) {
    if (std::find(names2.begin(), names2.end(), n) == names2.end()) continue;
    ValueChange c;
    c.name = n;
    c.unit = unitOf(first, n);
    c.first = valueEstimate(first, n);
    c.second = valueEstimate(second, n);
    c.trusted = c.first.trusted && c.second.trusted;
    const double b1 = lowerBound(first, n), b2 = lowerBound(second, n);
    c.ratio = c.first.lo > 0 && c.second.lo > 0 && c.first.optimum > 0 && c.second.optimum > 0 &&
              !(b1 < 0) && !(b2 < 0);
    // A centred estimate of a value compared by difference: the arithmetic centre.
    for (ValueEstimate* e : {&c.first, &c.second})
      if (e->centred && !c.ratio) e->estimate = 0.5 * (e->lo + e->hi);
    auto centre = [&](double x) { return c.ratio ? std::log(x) : x; };
    const double s1 = (centre(c.first.hi) - centre(c.first.lo)) / (2 * kZ975);
    const double s2 = (centre(c.second.hi) - centre(c.second.lo)) / (2 * kZ975);
    const double d = centre(c.second.estimate) - centre(c.first.estimate);
    const double s = std::sqrt(s1 * s1 + s2 * s2);
    if (s > 0) {
      c.z = d / s;
      c.p = 2 * normalCdf(-std::fabs(c.z));
    } else {  // both intervals of zero width: nothing to judge a change by
      c.z = 0;
      c.p = 1;
      r.notes.push_back(n + ": both intervals have zero width; its change is not judged");
    }
    c.change = c.ratio ? std::exp(d) : d;
    c.lo = c.ratio ? std::exp(d - kZ975 * s) : d - kZ975 * s;
    c.hi = c.ratio ? std::exp(d + kZ975 * s) : d + kZ975 * s;
    p.push_back(c.p);
    r.changes.push_back(std::move(c));
  }
  const auto reject = holmRejections(p, level);
  for (std::size_t i = 0; i < r.changes.size(); ++i) r.changes[i].significant = reject[i];
  std::stable_sort(r.changes.begin(), r.changes.end(),
                   [](const ValueChange& a, const ValueChange& b) {
                     if (a.significant != b.significant) return a.significant;
                     return std::fabs(a.z) > std::fabs(b.z);
                   });
  for (auto& c : r.changes) {
    c.sentence = describe(c);
    if (!c.trusted && c.significant)
      r.notes.push_back(c.name + ": a significant change whose intervals are not to be trusted");
  }
  return r;
}

std::size_t ChangeReport::significantCount() const {
  return static_cast<std::size_t>(std::count_if(
      changes.begin(), changes.end(), [](const ValueChange& c) { return c.significant; }));
}

nlohmann::json ChangeReport::toJson() const {
  nlohmann::json j;
  j["first"] = first_dir;
  j["second"] = second_dir;
  j["assembly"] = assembly;
  j["level"] = level;
  j["rule"] =
      "Holm's step-down rule over every value both calibrations hold, family-wise " +
      formatNumber(100 * level) +
      " %; each value's 95 % intervals read as normal estimates (log scale for positive values)";
  j["significant"] = significantCount();
  j["changes"] = nlohmann::json::array();
  for (const auto& c : changes) {
    auto est = [](const ValueEstimate& e) {
      return nlohmann::json{
          {"optimum", e.optimum}, {"estimate", e.estimate}, {"optimum_outside_interval", e.centred},
          {"ci95", {e.lo, e.hi}}, {"interval", e.interval}, {"trusted", e.trusted},
          {"note", e.note}};
    };
    j["changes"].push_back({{"name", c.name},
                            {"unit", c.unit},
                            {"kind", c.ratio ? "ratio" : "difference"},
                            {"first", est(c.first)},
                            {"second", est(c.second)},
                            {"change", c.change},
                            {"ci95", {c.lo, c.hi}},
                            {"z", c.z},
                            {"p", c.p},
                            {"significant", c.significant},
                            {"trusted", c.trusted},
                            {"sentence", c.sentence}});
  }
  j["only_first"] = only_first;
  j["only_second"] = only_second;
  j["notes"] = notes;
  return j;
}

std::string ChangeReport::text() const {
  std::string s;
  const std::size_t k = significantCount();
  s += std::to_string(k) + " of " + std::to_string(changes.size()) +
       " values changed significantly (Holm, family-wise " + formatNumber(100 * level) + " %)" +
       (k ? ":" : "") + "\n";
  for (const auto& c : changes)
    if (c.significant) s += "  " + c.sentence + "\n";
  if (k < changes.size()) s += "unchanged within their intervals:\n";
  for (const auto& c : changes)
    if (!c.significant) s += "  " + c.sentence + "\n";
  if (!only_first.empty()) {
    s += "calibrated only in the first:";
    for (const auto& n : only_first) s += " " + n;
    s += "\n";
  }
  if (!only_second.empty()) {
    s += "calibrated only in the second:";
    for (const auto& n : only_second) s += " " + n;
    s += "\n";
  }
  for (const auto& n : notes) s += "note: " + n + "\n";
  return s;
}

}  // namespace dtwin::diag
