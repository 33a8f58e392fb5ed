#include "report/diagnosis_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/validate.hpp"
#include "io/provenance.hpp"
#include "report/diagnosis_folder.hpp"
#include "report/study_report.hpp"
#include "report/svg_plot.hpp"
#include "twin/trace.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace dtwin::report {
namespace {

using diagnosis_folder::at;
using diagnosis_folder::Comparison;
using diagnosis_folder::dbl;
using diagnosis_folder::DiagnosisInput;
using diagnosis_folder::joinEffects;
using diagnosis_folder::readDiagnosisInput;
using diagnosis_folder::Series;
using diagnosis_folder::StateMap;
using diagnosis_folder::str;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string gq(const std::string& s) { return gnuplotQuote(s); }
std::string full(double v) { return plotNumber(v); }

std::string num(double v, int digits = 4) {
  if (!std::isfinite(v)) return "–";
  return formatNumber(v, digits);
}

/// A JSON value as short text (strings without quotes, arrays joined with ", ").
std::string text(const json& j) {
  if (j.is_null()) return "–";
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number()) return num(j.get<double>());
  if (j.is_boolean()) return j.get<bool>() ? "yes" : "no";
  if (j.is_array()) {
    std::string s;
    for (const auto& e : j) s += (s.empty() ? "" : ", ") + text(e);
    return s.empty() ? "–" : s;
  }
  return j.dump();
}

std::string stepLabel(const json& step, std::size_t k) {
  return k == 0 ? std::string("base") : "+ " + joinEffects(at(step, "effects"));
}

/// "name = mean ± sd unit [lo, hi]" per parameter of a {name: {unit, mean, sd, ci95, optimum}}
/// object.
std::string paramsHtml(const json& params) {
  std::string s;
  if (!params.is_object()) return "–";
  for (auto it = params.begin(); it != params.end(); ++it) {
    const json& p = it.value();
    const json& ci = at(p, "ci95");
    if (str(at(p, "interval")) == "none") {  // a candidate calibrated to its optimum only
      s += (s.empty() ? "" : "<br>") +
           htmlEscape(it.key() + ": optimum " + num(dbl(at(p, "optimum"))) + " " +
                      str(at(p, "unit")) + " (optimum only: no interval)");
      continue;
    }
    s +=
        (s.empty() ? "" : "<br>") + htmlEscape(it.key() + " = " + num(dbl(at(p, "mean"))) + " ± " +
                                               num(dbl(at(p, "sd")), 2) + " " + str(at(p, "unit")));
    if (ci.is_array() && ci.size() == 2)
      s += htmlEscape(" [" + num(dbl(ci[0])) + ", " + num(dbl(ci[1])) + "]");
  }
  return s.empty() ? "–" : s;
}

double meanCoverage(const json& figures) {
  double sum = 0.0;
  int n = 0;
  for (const auto& s : at(figures, "series"))
    if (std::isfinite(dbl(at(s, "coverage95")))) {
      sum += dbl(at(s, "coverage95"));
      ++n;
    }
  return n ? sum / n : kNaN;
}

std::string pct(double v) { return std::isfinite(v) ? num(100.0 * v, 3) + " %" : "–"; }

/// What the parts of a diagnosis section draw into: the plotter (SVG ids "<id_prefix><n>_"), the
/// section's HTML, its plots and warnings, and its anchor.
struct SectionPage {
  GnuplotSvg gp;
  std::ostringstream b;
  json plots = json::array();
  std::vector<std::string> warnings;
  std::string anchor;
  SectionPage(const std::string& gnuplot_exe, const DiagnosisSectionOptions& options)
      : gp(gnuplot_exe, options.id_prefix), anchor(options.anchor) {}
  void figure(const std::string& svg, const std::string& caption) {
    b << "<figure>\n" << svg << "\n<figcaption>" << caption << "</figcaption>\n</figure>\n";
  }
};

/// The heading, the verdict and summary, and the base model's figures.
void verdictPart(SectionPage& pg, const DiagnosisInput& in,
                 const DiagnosisSectionOptions& options) {
  std::ostringstream& b = pg.b;
  const std::string& A = pg.anchor;
  const json& d = in.d;
  const std::string& verdict = in.verdict;
  const std::string& effect = in.effect;
  const std::string& assembly = in.assembly;
  const std::string& diag_dir = in.diag_dir;
  b << "<section id=\"" << htmlEscape(A) << "\">\n<h2>" << htmlEscape(options.heading_prefix)
    << "Diagnosis" << (assembly.empty() ? "" : " of " + htmlEscape(assembly)) << ": <code>"
    << htmlEscape(diag_dir) << "</code></h2>\n";
  b << "<p class=\"" << (verdict == "unexplained" ? "warn" : "rec")
    << "\">Verdict: " << htmlEscape(verdict);
  if (!effect.empty()) b << " — " << htmlEscape(effect);
  b << "</p>\n";
  const json& summary = at(d, "summary");
  if (summary.is_string())
    b << "<p>" << htmlEscape(summary.get<std::string>()) << "</p>\n";
  else if (summary.is_array())
    for (const auto& s : summary) b << "<p>" << htmlEscape(text(s)) << "</p>\n";
  if (at(d, "ambiguous_with").is_array() && !at(d, "ambiguous_with").empty())
    b << "<p>Ambiguous with: " << htmlEscape(text(at(d, "ambiguous_with"))) << ".</p>\n";
  const std::string location = text(at(d, "unexplained_location"));
  if (!at(d, "unexplained_location").is_null() && text(summary).find(location) == std::string::npos)
    b << "<p>Unexplained residual: " << htmlEscape(text(at(d, "unexplained_location")))
      << ".</p>\n";
  const json& bf = at(d, "base");
  b << "<p>Base model (" << htmlEscape(str(at(bf, "label"))) << "): systematic RMS "
    << num(dbl(at(bf, "systematic_rms_noise_sd")), 3)
    << " noise sd, lack of fit z = " << num(dbl(at(bf, "lack_of_fit_z")), 3)
    << " (p = " << num(dbl(at(bf, "lack_of_fit_p")), 3) << "), log evidence "
    << num(dbl(at(bf, "log_evidence")), 6) << ".</p>\n";
}

/// The ranked (confirmed) effects with their parameter posteriors, and the screening table.
void effectTables(SectionPage& pg, const DiagnosisInput& in) {
  std::ostringstream& b = pg.b;
  const std::string& A = pg.anchor;
  const json& d = in.d;
  b << "<h3 id=\"" << htmlEscape(A) << "-ranked\">Confirmed effects (ranked)</h3>\n";
  const json& ranked = at(d, "ranked");
  if (!ranked.is_array() || ranked.empty()) {
    b << "<p>No effect was confirmed by re-calibration.</p>\n";
  } else {
    b << "<table>\n<tr><th>#</th><th>effect</th><th>ΔBIC</th><th>log evidence vs "
         "base</th><th>explained</th>"
         "<th>parameter posterior: mean ± sd [95 %]</th></tr>\n";
    int k = 0;
    for (const auto& r : ranked)
      b << "<tr><td class=\"n\">" << ++k << "</td><td>" << htmlEscape(str(at(r, "effect")))
        << "</td><td class=\"n\">" << num(dbl(at(r, "delta_bic")), 5) << "</td><td class=\"n\">"
        << num(dbl(at(r, "log_evidence_vs_base")), 5) << "</td><td class=\"n\">"
        << pct(dbl(at(r, "explained_fraction"))) << "</td><td>" << paramsHtml(at(r, "parameters"))
        << "</td></tr>\n";
    b << "</table>\n";
  }
  b << "<h3 id=\"" << htmlEscape(A) << "-screening\">Screening of every effect</h3>\n";
  const json& screening = at(d, "screening");
  if (!screening.is_array() || screening.empty()) {
    b << "<p>No effect was screened.</p>\n";
  } else {
    b << "<table>\n<tr><th>effect</th><th>score "
         "(dof)</th><th>p</th><th>gate</th><th>confirmed</th><th>why</th></tr>\n";
    for (const auto& s : screening)
      b << "<tr><td>" << htmlEscape(str(at(s, "effect"))) << "</td><td class=\"n\">"
        << num(dbl(at(s, "score")), 4) << " (" << htmlEscape(text(at(s, "score_dof")))
        << ")</td><td class=\"n\">" << num(dbl(at(s, "p_value")), 3) << "</td><td>"
        << htmlEscape(at(s, "failed").is_string() ? "failed: " + str(at(s, "failed"))
                                                  : text(at(s, "gate")))
        << "</td><td>" << htmlEscape(text(at(s, "confirmed"))) << "</td><td>"
        << htmlEscape(text(at(s, "why"))) << "</td></tr>\n";
    b << "</table>\n";
  }
}

/// The rows of `s` whose t, measured, predicted, lo and hi are all finite, as gnuplot data.
std::string seriesData(const Series& s) {
  std::ostringstream o;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (std::isfinite(s.t[i]) && std::isfinite(s.measured[i]) && std::isfinite(s.predicted[i]) &&
        std::isfinite(s.lo[i]) && std::isfinite(s.hi[i]))
      o << full(s.t[i]) << ' ' << full(s.measured[i]) << ' ' << full(s.predicted[i]) << ' '
        << full(s.lo[i]) << ' ' << full(s.hi[i]) << '\n';
  return o.str();
}

/// One series' figure: measured mean, predicted mean and 95 % band of the base model and of the
/// "after" model, with a lower panel of the residuals (a warning instead when nothing is finite).
void seriesPlot(SectionPage& pg, const DiagnosisInput& in, const Series& s) {
  GnuplotSvg& gp = pg.gp;
  auto& warnings = pg.warnings;
  auto& plots = pg.plots;
  auto figure = [&](const std::string& svg, const std::string& caption) {
    pg.figure(svg, caption);
  };
  const Comparison& after = in.after;
  const bool has_after = in.has_after;
  const std::string& after_label = in.after_label;
  const Series* a = has_after ? after.find(s.key()) : nullptr;
  const std::string db = seriesData(s), da = a ? seriesData(*a) : "";
  if (db.empty()) {
    warnings.push_back(s.name() + ": no finite points; no plot");
    return;
  }
  if (has_after && !a) warnings.push_back(s.name() + ": not in " + after.file);
  const bool with_after = a && !da.empty();
  const std::string fb = gp.data(db), fa = with_after ? gp.data(da) : "";
  const std::string ylab = s.channel + (s.unit.empty() ? "" : " [" + s.unit + "]");
  const std::string title = s.name();
  std::ostringstream p;
  p << "set multiplot layout 2,1 title " << gq(title) << " noenhanced\n"
    << "set grid\nset key below horizontal\nset xlabel 'time [s]'\nset ylabel " << gq(ylab)
    << " noenhanced\n"
    << "set style fill transparent solid 0.25 noborder\n"
    << "plot " << fb << " using 1:4:5 with filledcurves lc rgb '#7fa7d8' title 'base 95 %', ";
  if (with_after)
    p << fa << " using 1:4:5 with filledcurves lc rgb '#7fd08f' title " << gq(after_label + " 95 %")
      << " noenhanced, ";
  p << fb << " using 1:3 with lines lw 1.5 lc rgb '#103070' title 'base predicted', ";
  if (with_after)
    p << fa << " using 1:3 with lines lw 1.5 lc rgb '#1a7a2a' title "
      << gq(after_label + " predicted") << " noenhanced, ";
  p << fb << " using 1:2 with points pt 7 ps 0.35 lc rgb '#c03020' title 'measured mean'\n"
    << "set ylabel " << gq("measured − predicted" + (s.unit.empty() ? "" : " [" + s.unit + "]"))
    << " noenhanced\n"
    << "plot " << fb
    << " using 1:($4-$3):($5-$3) with filledcurves lc rgb '#7fa7d8' title 'base 95 % band', " << fb
    << " using 1:($2-$3) with lines lc rgb '#103070' title 'base residual'";
  if (with_after)
    p << ", " << fa << " using 1:($2-$3) with lines lc rgb '#1a7a2a' title "
      << gq(after_label + " residual") << " noenhanced";
  p << "\n";
  figure(gp.plot(p.str(), 900, 600, title),
         htmlEscape(s.name() + ": base RMS " + num(s.rms) + " " + s.unit + ", NRMSE " +
                    num(s.nrmse, 3) + ", coverage " + pct(s.coverage) +
                    (a ? "; " + after_label + ": RMS " + num(a->rms) + " " + s.unit + ", NRMSE " +
                             num(a->nrmse, 3) + ", coverage " + pct(a->coverage)
                       : "") +
                    "."));
  plots.push_back({{"name", "series_" + s.scenario + "_" + s.channel},
                   {"kind", "series"},
                   {"channel", s.channel},
                   {"scenario", s.scenario},
                   {"data_set", s.data_set}});
}

/// Per series: measured against predicted, before and after.
void seriesPart(SectionPage& pg, const DiagnosisInput& in) {
  std::ostringstream& b = pg.b;
  const std::string& A = pg.anchor;
  const Comparison& base = in.base;
  const bool has_after = in.has_after;
  const std::string& after_label = in.after_label;
  const std::string& after_name = in.after_name;
  b << "<h3 id=\"" << htmlEscape(A)
    << "-series\">Measured against predicted</h3>\n<p>Per series: the measured mean over "
       "the repetitions (points), the base model's predicted mean (line) and 95 % band"
    << (has_after ? ", and the same " + htmlEscape(after_label) + " (<code>comparisons/" +
                        htmlEscape(after_name) + ".json</code>)"
                  : "")
    << ". Lower panel: measured − predicted, with the base band around the base prediction.</p>\n";
  for (const auto& s : base.series) seriesPlot(pg, in, s);
}

/// The residual band-power ratios (residual / noise power, log scale) before and after, one
/// panel per series.
void bandPowerPart(SectionPage& pg, const DiagnosisInput& in) {
  pg.b << "<h3 id=\"" << htmlEscape(pg.anchor) << "-bands\">Residual band power</h3>\n";
  std::vector<const Series*> with_bands;
  for (const auto& s : in.base.series)
    if (!s.bands.empty()) with_bands.push_back(&s);
  if (with_bands.empty()) {
    pg.b << "<p>No series has band powers (too short for the Welch estimate).</p>\n";
  } else {
    double lo = 1.0, hi = 1.0;
    auto seen = [&](double r) {
      if (std::isfinite(r) && r > 0) {
        lo = std::min(lo, r);
        hi = std::max(hi, r);
      }
    };
    for (const Series* s : with_bands) {
      for (const auto& band : s->bands) seen(band.ratio);
      if (const Series* a = in.has_after ? in.after.find(s->key()) : nullptr)
        for (const auto& band : a->bands) seen(band.ratio);
    }
    const double ymin = lo / 3.0, ymax = hi * 3.0;
    const int n = static_cast<int>(with_bands.size()), cols = n > 1 ? 2 : 1,
              rows = (n + cols - 1) / cols;
    std::ostringstream p;
    p << "set multiplot layout " << rows << "," << cols << " title "
      << gq("residual power / noise power per band") << "\n"
      << "set logscale y\nset yrange [" << full(ymin) << ":" << full(ymax) << "]\nset grid ytics\n"
      << "set style fill solid 0.7 border -1\nset ylabel 'ratio'\nset key top left\n";
    for (const Series* s : with_bands) {
      const Series* a = in.has_after ? in.after.find(s->key()) : nullptr;
      std::ostringstream fb_, fa_, xt;
      for (std::size_t i = 0; i < s->bands.size(); ++i) {
        xt << (i ? ", " : "") << gq(s->bands[i].name) << " " << i + 1;
        if (std::isfinite(s->bands[i].ratio) && s->bands[i].ratio > 0)
          fb_ << i + 1 << ' ' << full(s->bands[i].ratio) << '\n';
        if (a)
          for (const auto& band : a->bands)
            if (band.name == s->bands[i].name && std::isfinite(band.ratio) && band.ratio > 0)
              fa_ << i + 1 << ' ' << full(band.ratio) << '\n';
      }
      p << "set title " << gq(s->name()) << " noenhanced\nset xtics (" << xt.str()
        << ") noenhanced\nset xrange [0.4:" << s->bands.size() + 0.6 << "]\nplot ";
      if (!fb_.str().empty())
        p << pg.gp.data(fb_.str()) << " using 1:2:($1-0.38):($1-0.02):(" << full(ymin)
          << "):2 with boxxyerror lc rgb '#4a7fc0' title 'base', ";
      if (!fa_.str().empty())
        p << pg.gp.data(fa_.str()) << " using 1:2:($1+0.02):($1+0.38):(" << full(ymin)
          << "):2 with boxxyerror lc rgb '#2a9a3a' title " << gq(in.after_label) << " noenhanced, ";
      p << "1 with lines dt 2 lw 1.5 lc rgb '#333333' title 'noise floor'\n";
    }
    pg.figure(
        pg.gp.plot(p.str(), 900, 260 * rows, "residual band power"),
        "Per series and frequency band, the power of the residual (measured − predicted mean) "
        "divided by the power the "
        "measurement noise alone would leave there (log scale; 1 = the noise floor, dashed), base" +
            (in.has_after ? " and " + htmlEscape(in.after_label) : std::string()) + ".");
    pg.plots.push_back({{"name", "band_power"}, {"kind", "band_power"}, {"panels", n}});
  }
}

/// The force–state map whose best signature explains the largest fraction in the base
/// comparison, before and after (bin means ± 2 se).
void stateMapPart(SectionPage& pg, const DiagnosisInput& in) {
  pg.b << "<h3 id=\"" << htmlEscape(pg.anchor) << "-map\">Force–state map</h3>\n";
  const StateMap* best = nullptr;
  for (const auto& m : in.base.maps)
    if (std::isfinite(m.explained) && !m.bins.empty() && (!best || m.explained > best->explained))
      best = &m;
  if (!best) {
    pg.b << "<p>The base comparison has no force–state map with a fitted signature.</p>\n";
  } else {
    const StateMap* am = in.has_after ? in.after.findMap(best->channel, best->state) : nullptr;
    std::string unit;
    for (const auto& s : in.base.series)
      if (s.channel == best->channel) unit = s.unit;
    auto binData = [&](const StateMap& m) {
      std::ostringstream o;
      for (const auto& bin : m.bins)
        if (std::isfinite(bin.centre) && std::isfinite(bin.mean))
          o << full(bin.centre) << ' ' << full(bin.mean) << ' '
            << full(std::isfinite(bin.se) ? 2 * bin.se : 0.0) << '\n';
      return o.str();
    };
    const std::string title = best->channel + " residual against " + best->state;
    std::ostringstream p;
    p << "set title "
      << gq(title + " (best base signature: " + best->feature + ", explains " +
            pct(best->explained) + ")")
      << " noenhanced\nset grid\nset key below horizontal\nset xlabel " << gq(best->state)
      << " noenhanced\nset ylabel " << gq("mean residual" + (unit.empty() ? "" : " [" + unit + "]"))
      << " noenhanced\nset xzeroaxis lt -1\n";
    if (best->feature == "knee" && std::isfinite(best->knee_at))
      p << "set arrow from " << full(best->knee_at) << ", graph 0 to " << full(best->knee_at)
        << ", graph 1 nohead dt 2 lc rgb '#c03020'\nset label " << gq("knee " + num(best->knee_at))
        << " at " << full(best->knee_at) << ", graph 0.95 offset 0.5,0 tc rgb '#c03020'\n";
    const std::string bd = binData(*best), ad = am ? binData(*am) : "";
    const std::string fb = pg.gp.data(bd);
    p << "plot " << fb
      << " using 1:2:3 with yerrorbars pt 7 ps 0.6 lc rgb '#103070' title 'base ± 2 se', " << fb
      << " using 1:2 with lines lc rgb '#103070' notitle";
    if (!ad.empty()) {
      const std::string fa = pg.gp.data(ad);
      p << ", " << fa << " using 1:2:3 with yerrorbars pt 5 ps 0.6 lc rgb '#1a7a2a' title "
        << gq(in.after_label + " ± 2 se") << " noenhanced, " << fa
        << " using 1:2 with lines lc rgb '#1a7a2a' notitle";
    }
    p << "\n";
    pg.figure(pg.gp.plot(p.str(), 900, 450, title),
              "The residual of " + htmlEscape(best->channel) + " averaged in equal-count bins of " +
                  htmlEscape(best->state) +
                  " (± 2 standard errors): the map of the base comparison whose best signature "
                  "explains the largest fraction (" +
                  htmlEscape(best->feature) + ", " + pct(best->explained) + ")" +
                  (am ? ", and the same map " + htmlEscape(in.after_label) : std::string()) + ".");
    pg.plots.push_back({{"name", "state_map"},
                        {"kind", "state_map"},
                        {"channel", best->channel},
                        {"state", best->state},
                        {"feature", best->feature},
                        {"explained_fraction", best->explained}});
  }
}

/// The before/after tables of the applied steps: per model, then per series.
void stepTables(SectionPage& pg, const json& steps) {
  std::ostringstream& b = pg.b;
  const std::string& A = pg.anchor;
  b << "<h3 id=\"" << htmlEscape(A)
    << "-steps\">Before and after (effects added in turn)</h3>\n<table>\n"
       "<tr><th>model</th><th>systematic RMS [noise sd]</th><th>lack of fit z</th><th>mean "
       "coverage 95 %</th>"
       "<th>log evidence</th><th>Δ log evidence vs base</th><th>effect parameters</th></tr>\n";
  const double le0 = dbl(at(steps[0], "log_evidence"));
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const json& st = steps[k];
    b << "<tr><td>" << htmlEscape(stepLabel(st, k)) << "</td><td class=\"n\">"
      << num(dbl(at(st, "systematic_rms_noise_sd")), 4) << "</td><td class=\"n\">"
      << num(dbl(at(st, "lack_of_fit_z")), 3) << "</td><td class=\"n\">" << pct(meanCoverage(st))
      << "</td><td class=\"n\">" << num(dbl(at(st, "log_evidence")), 6) << "</td><td class=\"n\">"
      << num(dbl(at(st, "log_evidence")) - le0, 5) << "</td><td>"
      << paramsHtml(at(st, "effect_parameters")) << "</td></tr>\n";
  }
  b << "</table>\n<p>Per series: RMS [unit] (NRMSE), coverage of the 95 % "
       "band.</p>\n<table>\n<tr><th>series</th>";
  for (std::size_t k = 0; k < steps.size(); ++k)
    b << "<th>" << htmlEscape(stepLabel(steps[k], k)) << "</th>";
  b << "</tr>\n";
  const json& s0 = at(steps[0], "series");
  for (std::size_t i = 0; s0.is_array() && i < s0.size(); ++i) {
    const json& e0 = s0[i];
    b << "<tr><td>" << htmlEscape(str(at(e0, "scenario")) + " " + str(at(e0, "channel")))
      << "</td>";
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const json* e = nullptr;
      for (const auto& x : at(steps[k], "series"))
        if (str(at(x, "data_set")) == str(at(e0, "data_set")) &&
            str(at(x, "scenario")) == str(at(e0, "scenario")) &&
            str(at(x, "channel")) == str(at(e0, "channel")))
          e = &x;
      if (e)
        b << "<td class=\"n\">" << num(dbl(at(*e, "rms"))) << " (" << num(dbl(at(*e, "nrmse")), 3)
          << "), " << pct(dbl(at(*e, "coverage95"))) << "</td>";
      else
        b << "<td>–</td>";
    }
    b << "</tr>\n";
  }
  b << "</table>\n";
}

/// The waterfall chart of the systematic RMS (in noise sd) over the steps (a warning instead when
/// a step has none).
void waterfallPlot(SectionPage& pg, const json& steps) {
  GnuplotSvg& gp = pg.gp;
  auto& warnings = pg.warnings;
  auto& plots = pg.plots;
  auto figure = [&](const std::string& svg, const std::string& caption) {
    pg.figure(svg, caption);
  };
  std::vector<double> v;
  std::vector<std::string> labels;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    v.push_back(dbl(at(steps[k], "systematic_rms_noise_sd")));
    labels.push_back(stepLabel(steps[k], k));
  }
  if (std::any_of(v.begin(), v.end(), [](double x) { return !std::isfinite(x); })) {
    warnings.push_back(
        "a step of diagnosis.json has no finite systematic_rms_noise_sd: no waterfall chart");
  } else {
    std::ostringstream whole, down, up, lab, xt;
    const std::size_t K = v.size();
    whole << 1 << ' ' << full(v[0]) << ' ' << 0 << ' ' << full(v[0]) << '\n';
    for (std::size_t k = 1; k < K; ++k)
      (v[k] <= v[k - 1] ? down : up)
          << k + 1 << ' ' << full(v[k]) << ' ' << full(std::min(v[k], v[k - 1])) << ' '
          << full(std::max(v[k], v[k - 1])) << '\n';
    whole << K + 1 << ' ' << full(v[K - 1]) << ' ' << 0 << ' ' << full(v[K - 1]) << '\n';
    for (std::size_t k = 0; k < K; ++k) {
      xt << (k ? ", " : "") << gq(labels[k]) << ' ' << k + 1;
      lab << k + 1 << ' ' << full(v[k]) << " \"" << num(v[k], 3) << "\"\n";
    }
    lab << K + 1 << ' ' << full(v[K - 1]) << " \"" << num(v[K - 1], 3) << "\"\n";
    xt << ", 'after' " << K + 1;
    const double top = std::max(1.0, *std::max_element(v.begin(), v.end())) * 1.15;
    std::ostringstream p;
    p << "set title 'systematic RMS over the steps' noenhanced\nset xtics (" << xt.str()
      << ") noenhanced\nset xrange [0.4:" << K + 1.6 << "]\nset yrange [0:" << full(top)
      << "]\nset ylabel 'systematic RMS [noise sd]'\nset grid ytics\n"
      << "set style fill solid 0.7 border -1\nset key top right\nplot " << gp.data(whole.str())
      << " using 1:2:($1-0.3):($1+0.3):3:4 with boxxyerror lc rgb '#4a7fc0' title 'level', ";
    if (!down.str().empty())
      p << gp.data(down.str())
        << " using 1:2:($1-0.3):($1+0.3):3:4 with boxxyerror lc rgb '#2a9a3a' title 'decrease', ";
    if (!up.str().empty())
      p << gp.data(up.str())
        << " using 1:2:($1-0.3):($1+0.3):3:4 with boxxyerror lc rgb '#c03020' title 'increase', ";
    p << gp.data(lab.str())
      << " using 1:2:3 with labels offset 0,0.8 notitle, 1 with lines dt 2 lw 1.5 lc rgb '#333333' "
         "title "
      << "'1 noise sd'\n";
    figure(gp.plot(p.str(), 900, 400, "systematic RMS waterfall"),
           "Systematic RMS of the residual (the part beyond the measurement noise, in noise sd, "
           "over all series) of the base "
           "model and after each effect added in turn (<code>diagnosis.json</code> "
           "<code>steps</code>): a green bar is a "
           "decrease, a red one an increase.");
    plots.push_back({{"name", "waterfall"}, {"kind", "waterfall"}, {"steps", K}});
  }
}

/// The source table (folder, program, command, times, study, data) and the section's warnings;
/// closes the section.
void sourcePart(SectionPage& pg, const DiagnosisInput& in) {
  std::ostringstream& b = pg.b;
  const std::string& A = pg.anchor;
  const json& d = in.d;
  const fs::path& dir = in.dir;
  const bool has_after = in.has_after;
  const Comparison& after = in.after;
  auto& warnings = pg.warnings;
  b << "<h3 id=\"" << htmlEscape(A) << "-source\">Source</h3>\n<table>\n";
  auto row = [&](const std::string& k, const std::string& v) {
    b << "<tr><th>" << htmlEscape(k) << "</th><td>" << htmlEscape(v) << "</td></tr>\n";
  };
  row("diagnosis folder", fs::absolute(dir).lexically_normal().string());
  const json& prog = at(d, "program");
  if (prog.is_object())
    row("program",
        str(at(prog, "name")) + " " + str(at(prog, "version")) + " (" + str(at(prog, "git")) + ")");
  row("command", text(at(d, "command")));
  row("created (UTC)", text(at(d, "created_utc")));
  row("study", text(at(d, "study")));
  row("data", text(at(d, "data")));
  row("after comparison", has_after ? after.file : "–");
  b << "</table>\n";
  for (const auto& w : pg.gp.warnings()) warnings.push_back(w);
  if (!warnings.empty()) {
    b << "<div class=\"warn\"><p>Diagnosis report warnings:</p>\n<ul>\n";
    for (const auto& w : warnings) b << "<li>" << htmlEscape(w) << "</li>\n";
    b << "</ul></div>\n";
  }
  b << "</section>\n";
}

}  // namespace

void DiagnosisSectionOptions::validate() const {
  const OptionCheck check("diagnosis_section");
  check.nonEmpty("anchor", anchor);
  check.nonEmpty("id_prefix", id_prefix);
}

// The parts in page order: verdict → effect tables → series → band power → force–state map →
// steps (tables and waterfall) → source and warnings.
std::string diagnosisSectionHtml(const std::string& diag_dir,
                                 const DiagnosisSectionOptions& options, json* drawn) {
  options.validate();
  const std::string gnuplot_exe = requireGnuplot("the diagnosis report");
  const DiagnosisInput in = readDiagnosisInput(diag_dir);
  SectionPage pg(gnuplot_exe, options);
  verdictPart(pg, in, options);
  effectTables(pg, in);
  seriesPart(pg, in);
  bandPowerPart(pg, in);
  stateMapPart(pg, in);
  if (in.has_steps) {
    stepTables(pg, in.steps());
    waterfallPlot(pg, in.steps());
  }
  sourcePart(pg, in);
  if (drawn)
    *drawn = {{"plots", pg.plots},
              {"svg_count", pg.gp.count()},
              {"verdict", in.verdict},
              {"effect", in.effect},
              {"after", in.has_after ? json(in.after.file) : json()},
              {"warnings", pg.warnings}};
  return pg.b.str();
}

json writeDiagnosisReport(const std::vector<std::string>& diag_dirs, const std::string& out_html,
                          const std::string& command) {
  const auto t_start = std::chrono::steady_clock::now();
  requireGnuplot("the diagnosis report");
  if (diag_dirs.empty())
    throw InputError("diagnosis_report.diag_dirs", "needs at least one diagnosis folder");
  std::vector<std::string> sections;
  json all = json::array(), plots = json::array(), warnings = json::array();
  int svg_count = 0;
  std::ostringstream nav;
  for (std::size_t k = 0; k < diag_dirs.size(); ++k) {
    DiagnosisSectionOptions o;
    if (diag_dirs.size() > 1) {
      o.anchor = "diagnosis-" + std::to_string(k + 1);
      o.id_prefix = "d" + std::to_string(k + 1) + "p";
      o.heading_prefix = std::to_string(k + 1) + ". ";
    }
    json drawn;
    sections.push_back(diagnosisSectionHtml(diag_dirs[k], o, &drawn));
    const std::string& sec = sections.back();
    const std::string& A = o.anchor;
    if (diag_dirs.size() > 1)
      nav << "<li><a href=\"#" << htmlEscape(A) << "\">" << htmlEscape(diag_dirs[k]) << "</a><ol>";
    for (const auto& [part, name] :
         std::vector<std::pair<std::string, std::string>>{{"-ranked", "Confirmed effects"},
                                                          {"-screening", "Screening"},
                                                          {"-series", "Measured against predicted"},
                                                          {"-bands", "Residual band power"},
                                                          {"-map", "Force–state map"},
                                                          {"-steps", "Before and after"},
                                                          {"-source", "Source"}})
      if (sec.find("id=\"" + A + part + "\"") != std::string::npos)
        nav << "<li><a href=\"#" << htmlEscape(A + part) << "\">" << htmlEscape(name)
            << "</a></li>";
    if (diag_dirs.size() > 1) nav << "</ol></li>";
    svg_count += drawn["svg_count"].get<int>();
    for (const auto& p : drawn["plots"]) plots.push_back(p);
    for (const auto& w : drawn["warnings"]) warnings.push_back(w);
    drawn["folder"] = diag_dirs[k];
    all.push_back(drawn);
  }
  const std::string title =
      diag_dirs.size() == 1
          ? "twin diagnosis report: " + fs::absolute(diag_dirs[0]).lexically_normal().string()
          : "twin diagnosis report: " + std::to_string(diag_dirs.size()) + " diagnoses";
  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>"
       << htmlEscape(title) << "</title>\n<style>\n"
       << reportCss() << "\n</style>\n</head>\n<body>\n<h1>" << htmlEscape(title) << "</h1>\n"
       << "<nav><ol>" << nav.str() << "</ol></nav>\n";
  for (const auto& sec : sections) page << sec;
  const json prog = programInfo();
  page << "<p>Report command: <code>" << htmlEscape(command) << "</code>; made by "
       << htmlEscape(str(at(prog, "name")) + " " + str(at(prog, "version")) + " (" +
                     str(at(prog, "git")) + ")")
       << ", " << htmlEscape(utcNow()) << ".</p>\n</body>\n</html>\n";
  writeFileAtomic(out_html, page.str());
  json r = all.size() == 1 ? all[0] : json::object();
  r["diagnoses"] = all;
  r["plots"] = plots;
  r["svg_count"] = svg_count;
  r["warnings"] = warnings;
  r["html"] = out_html;
  r["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return r;
}

json writeDiagnosisReport(const std::string& diag_dir, const std::string& out_html,
                          const std::string& command) {
  return writeDiagnosisReport(std::vector<std::string>{diag_dir}, out_html, command);
}

}  // namespace dtwin::report
