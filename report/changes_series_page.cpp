// The page of what changed over several drives (report/changes_series_page.hpp).
#include "report/changes_series_page.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/format.hpp"
#include "report/study_report.hpp"  // htmlEscape

namespace dtwin {
namespace {

using report::htmlEscape;

std::string seriesNum(double v) { return formatNumber(v, 4); }
std::string seriesPx(double v) { return formatPrintf("%.1f", v); }

/// One value's plot: each drive's estimate with its interval against the date, the trend line.
std::string trendPlot(const nlohmann::json& v, const std::vector<double>& days,
                      const std::vector<std::string>& dates) {
  const double W = 640, H = 260, L = 70, R = 20, T = 15, B = 45;
  const bool log_axis = v["kind"] == "ratio per year";
  double y0 = std::numeric_limits<double>::infinity(), y1 = -y0;
  for (const auto& d : v["drives"])
    for (double x : {d["ci95"][0].get<double>(), d["ci95"][1].get<double>()}) {
      y0 = std::min(y0, x);
      y1 = std::max(y1, x);
    }
  auto Y = [&](double x) {
    const double a = log_axis ? std::log(x) : x, lo = log_axis ? std::log(y0) : y0,
                 hi = log_axis ? std::log(y1) : y1;
    const double pad = 0.08 * (hi - lo > 0 ? hi - lo : 1.0);
    return T + (H - T - B) * (1 - (a - (lo - pad)) / (hi - lo + 2 * pad));
  };
  const double d0 = days.front(), d1 = days.back() > d0 ? days.back() : d0 + 1;
  auto X = [&](double d) { return L + (W - L - R) * (0.04 + 0.92 * (d - d0) / (d1 - d0)); };
  const bool sig = v["significant"].get<bool>();
  const std::string colour = sig ? "#c0392b" : "#2c7fb8";
  std::string s = "<svg width=\"" + seriesPx(W) + "\" height=\"" + seriesPx(H) +
                  "\" role=\"img\"><title>" + htmlEscape(v["sentence"].get<std::string>()) +
                  "</title>";
  s += "<line x1=\"" + seriesPx(L) + "\" x2=\"" + seriesPx(L) + "\" y1=\"" + seriesPx(T) +
       "\" y2=\"" + seriesPx(H - B) + "\" stroke=\"#444\"/><line x1=\"" + seriesPx(L) + "\" x2=\"" +
       seriesPx(W - R) + "\" y1=\"" + seriesPx(H - B) + "\" y2=\"" + seriesPx(H - B) +
       "\" stroke=\"#444\"/>";
  for (double f : {0.0, 0.5, 1.0}) {  // three labelled values on the y axis
    const double x = log_axis ? y0 * std::pow(y1 / y0, f) : y0 + f * (y1 - y0);
    s += "<text x=\"" + seriesPx(L - 6) + "\" y=\"" + seriesPx(Y(x) + 4) +
         "\" text-anchor=\"end\" font-size=\"11\">" + seriesNum(x) + "</text><line x1=\"" +
         seriesPx(L - 3) + "\" x2=\"" + seriesPx(W - R) + "\" y1=\"" + seriesPx(Y(x)) + "\" y2=\"" +
         seriesPx(Y(x)) + "\" stroke=\"#eee\"/>";
  }
  const auto& line = v["line"];
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
    s += "<line x1=\"" + seriesPx(X(days[i])) + "\" x2=\"" + seriesPx(X(days[i + 1])) + "\" y1=\"" +
         seriesPx(Y(line[i].get<double>())) + "\" y2=\"" + seriesPx(Y(line[i + 1].get<double>())) +
         "\" stroke=\"" + colour + "\" stroke-dasharray=\"5,3\"/>";
  for (std::size_t i = 0; i < v["drives"].size(); ++i) {
    const auto& d = v["drives"][i];
    const double x = X(days[i]);
    s += "<line x1=\"" + seriesPx(x) + "\" x2=\"" + seriesPx(x) + "\" y1=\"" +
         seriesPx(Y(d["ci95"][0].get<double>())) + "\" y2=\"" +
         seriesPx(Y(d["ci95"][1].get<double>())) +
         "\" stroke=\"#222\" stroke-width=\"2\"/><circle cx=\"" + seriesPx(x) + "\" cy=\"" +
         seriesPx(Y(d["estimate"].get<double>())) + "\" r=\"4\" fill=\"" +
         (d["trusted"].get<bool>() ? "#222" : "#b36b00") + "\"><title>" + htmlEscape(dates[i]) +
         ": " + seriesNum(d["estimate"].get<double>()) + " [" +
         seriesNum(d["ci95"][0].get<double>()) + ", " + seriesNum(d["ci95"][1].get<double>()) +
         "]</title></circle>";
    s += "<text x=\"" + seriesPx(x) + "\" y=\"" + seriesPx(H - B + 16) +
         "\" text-anchor=\"middle\" font-size=\"10\">" + htmlEscape(dates[i].substr(0, 10)) +
         "</text>";
  }
  s += "<text x=\"" + seriesPx(L + (W - L - R) / 2) + "\" y=\"" + seriesPx(H - 6) +
       "\" text-anchor=\"middle\" font-size=\"11\">the drive's date</text></svg>";
  return s;
}

}  // namespace

std::string changesSeriesPage(const nlohmann::json& j, const std::string& title) {
  std::vector<double> days;
  std::vector<std::string> dates, dirs;
  for (const auto& d : j["drives"]) {
    days.push_back(d["day"].get<double>());
    dates.push_back(d["date"].get<std::string>());
    dirs.push_back(d["calibration"].get<std::string>());
  }
  std::string plots;
  for (const auto& v : j["values"]) {
    const std::string unit = v["unit"].get<std::string>();
    plots += "<h2>" + htmlEscape(v["name"].get<std::string>()) +
             (unit.empty() || unit == "1" ? "" : " <small>[" + htmlEscape(unit) + "]</small>") +
             "</h2>\n<p class=\"" + (v["significant"].get<bool>() ? "sig" : "") + "\">" +
             htmlEscape(v["sentence"].get<std::string>()) + "</p>\n" + trendPlot(v, days, dates) +
             "\n";
  }
  std::string drives;
  for (std::size_t i = 0; i < dirs.size(); ++i)
    drives += "<li>" + htmlEscape(dates[i]) + ": <code>" + htmlEscape(dirs[i]) + "</code></li>";
  std::string pair;
  for (const auto& c : j["first_to_last"]["changes"])
    pair += "<li" + std::string(c["significant"].get<bool>() ? " class=\"sig\"" : "") + ">" +
            htmlEscape(c["sentence"].get<std::string>()) + "</li>";
  std::string notes;
  for (const auto& n : j["notes"]) notes += "<li>" + htmlEscape(n.get<std::string>()) + "</li>";
  return R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>)" +
         htmlEscape(title) + R"(</title>
<style>
body{font-family:system-ui,sans-serif;margin:1.5em;color:#222;max-width:60em}
.sig{font-weight:bold;color:#c0392b}small{color:#666}h2{margin-top:1.4em;font-size:1.1em}
</style></head><body>
<h1>)" + htmlEscape(title) +
         R"(</h1>
<p><b>)" +
         std::to_string(j["significant"].get<std::size_t>()) + " of " +
         std::to_string(j["values"].size()) +
         R"(</b> values have a significant trend over the drives. Rule: )" +
         htmlEscape(j["rule"].get<std::string>()) +
         R"(. Each point is one drive's calibration, its bar the 95 % interval; the dashed line is the trend.</p>
<h2>The drives</h2><ul>)" +
         drives + "</ul>\n" + plots + "<h2>First drive to last</h2><ul>" + pair + "</ul>\n" +
         (notes.empty() ? "" : "<h2>Notes</h2><ul>" + notes + "</ul>") + "\n</body></html>\n";
}

}  // namespace dtwin
