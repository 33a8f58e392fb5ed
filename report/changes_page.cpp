// The page of what changed between two calibrations (report/changes_page.hpp).
#include "report/changes_page.hpp"

#include <algorithm>
#include <cmath>

#include "common/format.hpp"
#include "report/study_report.hpp"  // htmlEscape

namespace dtwin {
namespace {

using report::htmlEscape;

std::string num(double v) { return formatNumber(v, 4); }

/// An interval bar on [x0, x1] (log axis for ratios), a mark at "no change" and the estimate.
std::string changeBar(const nlohmann::json& c, double x0, double x1, bool log_axis) {
  const double w = 220, h = 18;
  auto X = [&](double v) {
    const double a = log_axis ? std::log(std::max(v, 1e-300)) : v,
                 lo = log_axis ? std::log(x0) : x0, hi = log_axis ? std::log(x1) : x1;
    return std::clamp((a - lo) / (hi - lo), 0.0, 1.0) * w;
  };
  const double lo = c["ci95"][0].get<double>(), hi = c["ci95"][1].get<double>(),
               v = c["change"].get<double>();
  const double none = log_axis ? 1.0 : 0.0;
  const bool sig = c["significant"].get<bool>();
  const std::string colour = sig ? "#c0392b" : "#2c7fb8";
  std::string s = "<svg width=\"" + num(w) + "\" height=\"" + num(h) + "\" role=\"img\"><title>" +
                  htmlEscape(c["sentence"].get<std::string>()) + "</title>";
  s += "<line x1=\"" + num(X(none)) + "\" x2=\"" + num(X(none)) + "\" y1=\"0\" y2=\"" + num(h) +
       "\" stroke=\"#888\" stroke-dasharray=\"3,2\"/>";
  s += "<line x1=\"" + num(X(lo)) + "\" x2=\"" + num(X(hi)) + "\" y1=\"9\" y2=\"9\" stroke=\"" +
       colour + "\" stroke-width=\"3\"/>";
  s += "<circle cx=\"" + num(X(v)) + "\" cy=\"9\" r=\"4\" fill=\"" + colour + "\"/></svg>";
  return s;
}

}  // namespace

std::string changesPage(const nlohmann::json& j, const std::string& title) {
  // One axis for every ratio (log, symmetric about 1) and one per difference (symmetric about 0).
  double rmax = 1.25;
  for (const auto& c : j["changes"])
    if (c["kind"] == "ratio")
      for (double v : {c["ci95"][0].get<double>(), c["ci95"][1].get<double>()})
        if (v > 0) rmax = std::max(rmax, std::max(v, 1 / v));
  rmax = std::min(rmax * 1.1, 100.0);
  std::string rows;
  for (const auto& c : j["changes"]) {
    const bool ratio = c["kind"] == "ratio";
    double dmax = 0;
    if (!ratio)
      dmax = std::max({std::fabs(c["ci95"][0].get<double>()), std::fabs(c["ci95"][1].get<double>()),
                       1e-300}) *
             1.1;
    const std::string unit = c["unit"].get<std::string>();
    auto est = [&](const nlohmann::json& e) {
      const bool centred = e.value("optimum_outside_interval", false);
      return num(e.value("estimate", e["optimum"].get<double>())) +
             (centred ? " <span class=\"warn\" title=\"the optimum (" +
                            num(e["optimum"].get<double>()) +
                            ") lies outside its interval: the profile search met a better fit; the "
                            "interval's centre is compared\">c</span>"
                      : std::string()) +
             " <small>[" + num(e["ci95"][0].get<double>()) + ", " +
             num(e["ci95"][1].get<double>()) + "]</small>" +
             (e["trusted"].get<bool>()
                  ? ""
                  : " <span class=\"warn\" title=\"" + htmlEscape(e["note"].get<std::string>()) +
                        "\">!</span>");
    };
    const bool sig = c["significant"].get<bool>();
    rows += "<tr class=\"" + std::string(sig ? "sig" : "") + "\" data-z=\"" +
            num(std::fabs(c["z"].get<double>())) + "\"><td>" +
            htmlEscape(c["name"].get<std::string>()) + "</td><td>" + htmlEscape(unit) +
            "</td><td>" + est(c["first"]) + "</td><td>" + est(c["second"]) + "</td><td>" +
            (ratio ? "&times; " : "&plusmn; ") + num(c["change"].get<double>()) + " <small>[" +
            num(c["ci95"][0].get<double>()) + ", " + num(c["ci95"][1].get<double>()) +
            "]</small></td><td>" +
            changeBar(c, ratio ? 1 / rmax : -dmax, ratio ? rmax : dmax, ratio) + "</td><td>" +
            formatPrintf("%.2f", c["z"].get<double>()) + "</td><td>" +
            (sig ? "changed" : "unchanged") + "</td></tr>\n";
  }
  std::string only;
  for (const char* k : {"only_first", "only_second"})
    if (j.contains(k) && !j[k].empty()) {
      only += std::string("<p>Calibrated only in the ") +
              (std::string(k) == "only_first" ? "first" : "second") + ": ";
      for (const auto& n : j[k]) only += "<code>" + htmlEscape(n.get<std::string>()) + "</code> ";
      only += "</p>\n";
    }
  std::string notes;
  for (const auto& n : j["notes"]) notes += "<li>" + htmlEscape(n.get<std::string>()) + "</li>";
  const std::size_t k = j["significant"].get<std::size_t>();
  std::string html =
      R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>)" +
      htmlEscape(title) + R"(</title>
<style>
body{font-family:system-ui,sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse}th,td{padding:4px 8px;border-bottom:1px solid #ddd;text-align:left;vertical-align:middle}
th{cursor:pointer;background:#f4f4f4}th:hover{background:#e8e8e8}
tr.sig td:first-child{font-weight:bold;color:#c0392b}.warn{color:#b36b00;font-weight:bold}small{color:#666}
</style></head><body>
<h1>)" +
      htmlEscape(title) + R"(</h1>
<p><b>)" +
      std::to_string(k) + " of " + std::to_string(j["changes"].size()) +
      R"(</b> values changed significantly between the two calibrations.</p>
<p>First: <code>)" +
      htmlEscape(j["first"].get<std::string>()) + "</code>; second: <code>" +
      htmlEscape(j["second"].get<std::string>()) + R"(</code>. Rule: )" +
      htmlEscape(j["rule"].get<std::string>()) +
      R"(. A positive value's change is a ratio (drawn on a log axis; the dashed line is no change), any other value's a difference.</p>
<table id="t"><thead><tr><th>value</th><th>unit</th><th>first [95 %]</th><th>second [95 %]</th><th>change [95 %]</th><th>interval</th><th data-num="1">z</th><th>verdict</th></tr></thead>
<tbody>
)" + rows +
      R"(</tbody></table>
)" + only +
      (notes.empty() ? "" : "<h2>Notes</h2><ul>" + notes + "</ul>") +
      R"(
<script>
document.querySelectorAll('#t th').forEach(function(th,i){th.addEventListener('click',function(){
 var tb=document.querySelector('#t tbody'),rows=Array.from(tb.rows),asc=th.dataset.asc!=='1';th.dataset.asc=asc?'1':'0';
 rows.sort(function(a,b){var x=a.cells[i].textContent,y=b.cells[i].textContent;
  if(th.dataset.num){x=Math.abs(parseFloat(x));y=Math.abs(parseFloat(y));return asc?x-y:y-x;}
  return asc?x.localeCompare(y):y.localeCompare(x);});
 rows.forEach(function(r){tb.appendChild(r);});});});
</script>
</body></html>
)";
  return html;
}

}  // namespace dtwin
