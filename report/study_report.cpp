#include "report/study_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include "calibration/summary.hpp"
#include "classification/synthesis.hpp"
#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/validate.hpp"
#include "io/measurement.hpp"
#include "io/provenance.hpp"
#include "io/study.hpp"
#include "report/lab_page.hpp"
#include "report/posterior_plots.hpp"
#include "report/svg_plot.hpp"
#include "report/ticks.hpp"
#include "twin/trace.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace dtwin::report {

std::string htmlEscape(const std::string& text) {
  std::string s;
  s.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        s += "&amp;";
        break;
      case '<':
        s += "&lt;";
        break;
      case '>':
        s += "&gt;";
        break;
      case '"':
        s += "&quot;";
        break;
      case '\'':
        s += "&#39;";
        break;
      default:
        s += c;
    }
  }
  return s;
}

namespace {

json readJson(const fs::path& p) {
  return readJsonFile(p.string(), " (is this a `twin study` folder?)");
}

json readJsonIfExists(const fs::path& p) { return fs::exists(p) ? readJson(p) : json(); }

std::string num(double v, int digits = 6) { return formatNumber(v, digits); }

std::string full(double v) { return plotNumber(v); }

std::string gq(const std::string& s) { return gnuplotQuote(s); }

/// A JSON value as short text (strings without quotes).
std::string text(const json& j) {
  if (j.is_null()) return "–";
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number_float()) return num(j.get<double>());
  return j.dump();
}

/// What the sections of the study report draw into: the plotter, the page body (sections 1–5),
/// the list of plots and the warnings shown at the top of the page.
struct ReportPage {
  GnuplotSvg gp;
  std::ostringstream body;
  json plots = json::array();
  std::vector<std::string> warnings;
  ReportPage(const std::string& gnuplot_exe, std::vector<std::string> first_warnings)
      : gp(gnuplot_exe), warnings(std::move(first_warnings)) {}
  void figure(const std::string& svg, const std::string& caption, const std::string& id = "") {
    body << (id.empty() ? std::string("<figure>\n") : "<figure id=\"" + htmlEscape(id) + "\">\n")
         << svg << "\n<figcaption>" << caption << "</figcaption>\n</figure>\n";
  }
};

/// The JSON files of a study folder the report reads (written by `twin study`).
struct StudyFiles {
  json record;   ///< study.json
  json summary;  ///< summary.json
  json csum;     ///< classification/summary.json
};

StudyFiles readStudyFiles(const fs::path& dir) {
  StudyFiles f;
  f.record = readJson(dir / "study.json");
  f.summary = readJson(dir / "summary.json");
  f.csum = readJson(dir / "classification" / "summary.json");
  return f;
}

/// One figure of section 1: the lab data of channel `g.channel` against the assembly's predictive
/// band, drawn through the lab scenario on the dense grid, and the same relative to the median
/// prediction (the lab points against the median at their times).
void predictivePlot(ReportPage& pg, const classify::AssemblyBands& ab,
                    const classify::ChannelBand& g, const LabData& lab, const std::string& unit) {
  const auto& a = ab.assembly;
  std::ostringstream band, pts;
  double ylo = INFINITY, yhi = -INFINITY, rlo = INFINITY, rhi = -INFINITY;
  const auto span = [](double& lo, double& hi, double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  };
  // In view: from a little before the first lab time (the lab measures the response to the bump,
  // after the car has settled) to the last; the y ranges are those of what is in view.
  double t_end = 0.0, t_first = INFINITY;
  for (const auto& r : lab.records)
    if (r.channel == g.channel) {
      t_first = std::min(t_first, r.time_s);
      t_end = std::max(t_end, r.time_s);
    }
  const double x0 =
      std::max(g.times.empty() ? 0.0 : g.times.front(), t_first - 0.15 * (t_end - t_first));
  for (std::size_t i = 0; i < g.times.size(); ++i) {
    band << full(g.times[i]) << ' ' << full(g.lo[i]) << ' ' << full(g.med[i]) << ' '
         << full(g.hi[i]) << ' ' << full(g.plo[i]) << ' ' << full(g.phi[i]) << '\n';
    if (g.times[i] < x0) continue;
    span(ylo, yhi, g.plo[i]);
    span(ylo, yhi, g.phi[i]);
    span(rlo, rhi, g.plo[i] - g.med[i]);
    span(rlo, rhi, g.phi[i] - g.med[i]);
  }
  for (const auto& r : lab.records) {
    if (r.channel != g.channel) continue;
    const std::size_t i = g.at(r.time_s);  // the grid holds every lab time
    DTWIN_CHECK(i < g.times.size(),
                "lab time " + std::to_string(r.time_s) + " is not on the band's grid");
    pts << full(r.time_s) << ' ' << full(r.value) << ' ' << full(r.value - g.med[i]) << '\n';
    span(ylo, yhi, r.value);
    span(rlo, rhi, r.value - g.med[i]);
  }
  padRange(ylo, yhi, 0.05);
  padRange(rlo, rhi, 0.05);
  const std::string fb = pg.gp.data(band.str()), fp = pg.gp.data(pts.str());
  const std::string title = a.id + " (" + a.label() + "): " + g.channel;
  std::ostringstream s;
  s << "set multiplot layout 2,1 title " << gq(title) << " noenhanced\n"
    << "set grid\nset key below horizontal\nset xlabel 'time [s]'\nset ylabel "
    << gq(axisLabel(g.channel, unit)) << " noenhanced\n"
    << gnuplotTics("x", x0, t_end, 8) << gnuplotTics("y", ylo, yhi, 6)
    << "set style fill transparent solid 0.25 noborder\n"
    << "plot " << fb
    << " using 1:5:6 with filledcurves lc rgb '#7fa7d8' title 'predictive 95 % (with noise)', "
    << fb << " using 1:2:4 with filledcurves lc rgb '#1f5fbf' title 'η(θ) 95 %', " << fb
    << " using 1:3 with lines lw 1.5 lc rgb '#103070' title 'median η(θ)', " << fp
    << " using 1:2 with points pt 7 ps 0.5 lc rgb '#c03020' title 'lab data (every repetition)'\n"
    << "set ylabel " << gq(axisLabel("measured − median", unit)) << " noenhanced\n"
    << gnuplotTics("y", rlo, rhi, 5) << "plot " << fb
    << " using 1:($5-$3):($6-$3) with filledcurves lc rgb '#7fa7d8' title 'predictive 95 % (with "
       "noise)', "
    << fb << " using 1:($2-$3):($4-$3) with filledcurves lc rgb '#1f5fbf' title 'η(θ) 95 %', " << fb
    << " using 1:($3-$3) with lines lc rgb '#103070' title 'median η(θ)', " << fp
    << " using 1:3 with points pt 7 ps 0.5 lc rgb '#c03020' title 'lab data'\n";
  const std::string name = "predictive_" + a.id + "_" + g.channel;
  pg.figure(pg.gp.plot(s.str(), 900, 600, title),
            htmlEscape(a.id + ": " + std::to_string(ab.drawn - ab.failures) + " of " +
                       std::to_string(ab.drawn) + " draws simulated; the band drawn on " +
                       std::to_string(g.times.size()) +
                       " times through the lab scenario (shown from just before the first lab "
                       "time; the interactive view has it "
                       "all); noise sd 1/√τ = " +
                       num(ab.noise_sd, 4) + " " + unit + " (posterior median over the draws)."));
  pg.plots.push_back(
      {{"name", name}, {"kind", "predictive"}, {"assembly", a.id}, {"channel", g.channel}});
}

/// Section 1: the lab data against every assembly's posterior predictive bands.
void predictiveSection(ReportPage& pg, const classify::LabBands& bands,
                       const std::string& lab_link) {
  const int draws = bands.draws;
  pg.body << "<h2 id=\"lab\">1. Lab data against the posterior predictive bands</h2>\n"
          << "<p>For each assembly, " << draws
          << " evenly spaced rows of its posterior sample (rows ⌊(k + ½)·S / " << draws
          << "⌋, k = 0 … " << draws - 1
          << ") are simulated on the lab scenario and predicted through it, on a dense grid of "
             "times that holds the lab times: "
             "the lines and bands are the model's continuous response, the points what the lab "
             "measured. Dark band: 2.5–97.5 % of the predictions "
             "η(θ) (parameter uncertainty); line: their median; light band: 2.5–97.5 % of the "
             "posterior predictive "
             "distribution, the predictions plus measurement noise N(0, 1/τ) of each draw (noise "
             "sd = 1/√τ). Points: the "
             "measured values of every repetition. The lower panel shows the same relative to the "
             "median prediction.</p>\n";
  if (!lab_link.empty())
    pg.body << "<p>Interactive view (zoom, pan, one cursor across the channels): <a href=\""
            << htmlEscape(lab_link) << "\">" << htmlEscape(lab_link) << "</a>.</p>\n";
  const std::vector<Channel> known = measurableChannels(bands.study.sensors);
  for (const auto& ab : bands.assemblies)
    for (const auto& g : ab.channels)
      predictivePlot(pg, ab, g, bands.lab, channelUnit(known, g.channel));
}

/// The marks of calibrated value `name` (its summary.json entry `entry`, nullptr for τ or when
/// there is none), and the sentence saying whether its ci95 interval holds the truth (when known).
ParameterMarks marksOf(const std::string& name, const std::string& unit, std::vector<double> v,
                       std::optional<double> truth, const json* entry,
                       std::vector<std::string>& truth_notes) {
  ParameterMarks m;
  m.name = name;
  m.unit = unit;
  m.sample = std::move(v);
  m.truth = truth;
  std::string ci_kind = "posterior";
  if (entry) {
    const json& e = *entry;
    if (e.contains("profile95"))
      m.profile = std::make_pair(e["profile95"][0].get<double>(), e["profile95"][1].get<double>());
    if (e.contains("optimum") && e["optimum"].is_number()) m.optimum = e["optimum"].get<double>();
    ci_kind = e.value("interval", std::string("posterior"));
  }
  axisRange(m);
  if (truth && !m.sample.empty()) {
    std::vector<double> sorted = m.sample;
    std::sort(sorted.begin(), sorted.end());
    const bool prof = ci_kind == "profile" && m.profile;
    const double ci_lo = prof ? m.profile->first : quantileSorted(sorted, 0.025);
    const double ci_hi = prof ? m.profile->second : quantileSorted(sorted, 0.975);
    const bool inside = *truth >= ci_lo && *truth <= ci_hi;
    truth_notes.push_back(
        name + ": the truth " + num(*truth, 6) +
        (inside ? " lies inside" : (*truth < ci_lo ? " lies BELOW" : " lies ABOVE")) +
        " the 95 % interval [" + num(ci_lo, 6) + ", " + num(ci_hi, 6) + "] (" +
        (prof ? "profile likelihood" : "posterior") + ")");
  }
  return m;
}

/// An assembly's calibration region (calibration/<id>/summary.json "region"), when it has one.
std::optional<calib::Region> regionOf(const json& cal_summary) {
  if (!cal_summary.contains("region")) return std::nullopt;
  try {
    return calib::Region::fromJson(cal_summary["region"]);
  } catch (const std::exception&) {
    return std::nullopt;  // an older or partial summary: the pair plot goes without its region
  }
}

/// The figures of section 2 for one assembly: the weighted density of every θ and of τ (one
/// panel each), then the pair plot of θ.
void posteriorFigure(ReportPage& pg, const classify::AssemblyBands& ab, const Study& study,
                     const fs::path& dir) {
  const auto& a = ab.assembly;
  const auto& post = ab.posterior;
  const json cal_summary = readJsonIfExists(dir / "calibration" / a.id / "summary.json");
  std::vector<std::string> truth_notes;
  std::vector<ParameterMarks> theta;
  for (std::size_t j = 0; j < post.names.size(); ++j) {
    const std::string& name = post.names[j];
    std::vector<double> v;
    for (const auto& row : post.theta) v.push_back(row[j]);
    std::optional<double> truth;
    std::string unit;
    for (const auto& cp : study.calibrated)
      if (cp.name == name) {
        truth = cp.truth;
        unit = cp.unit;
      }
    const bool has_entry =
        cal_summary.contains("parameters") && cal_summary["parameters"].contains(name);
    theta.push_back(marksOf(name, unit, std::move(v), truth,
                            has_entry ? &cal_summary["parameters"][name] : nullptr, truth_notes));
  }
  std::vector<std::string> ignored;
  ParameterMarks tau =
      marksOf("tau (error precision)", "1/unit²", post.tau, std::nullopt, nullptr, ignored);
  const int np = static_cast<int>(theta.size()) + 1, cols = np <= 3 ? np : 3,
            rws = (np + cols - 1) / cols;
  std::ostringstream s;
  s << "set multiplot layout " << rws << "," << cols << " title "
    << gq(a.id + " (" + a.label() + "): posterior, " + std::to_string(post.size()) + " iterations")
    << " noenhanced\n"
    << "set grid xtics\nset ylabel 'posterior density'\n";
  for (const auto& m : theta) s << densityPanel(pg.gp, m);
  s << densityPanel(pg.gp, tau);
  std::string names;
  for (std::size_t j = 0; j < post.names.size(); ++j) names += (j ? ", " : "") + post.names[j];
  std::string caption =
      a.id + ": θ = (" + names + "), τ the error precision [1/unit²]; noise sd = 1/√τ.";
  for (const auto& t : truth_notes) caption += " " + t + ".";
  pg.figure(pg.gp.plot(s.str(), 900, 300 * rws, a.id + " posterior densities"),
            htmlEscape(caption));
  pg.plots.push_back(
      {{"name", "posterior_" + a.id}, {"kind", "posterior_densities"}, {"assembly", a.id}});
  if (theta.size() < 2) return;
  const std::optional<calib::Region> region = regionOf(cal_summary);
  pg.figure(
      pairPlot(pg.gp, theta, region, a.id + " (" + a.label() + "): pairs of calibrated values"),
      htmlEscape(
          a.id +
          ": below the diagonal, each pair's posterior design points (area ∝ posterior mass)" +
          std::string(region ? ", the calibration's joint region projected (grey outline)" : "") +
          ", the optimum (black ×), the truth when known (red +) and the box of the two "
          "profile-likelihood 95 % "
          "intervals (dotted green); on the diagonal each value's density; above it the posterior "
          "correlation ρ "
          "(red when |ρ| > 0.7: a ridge along which the data cannot tell the two apart)."),
      "pairs-" + a.id);
  pg.plots.push_back({{"name", "pairs_" + a.id}, {"kind", "pair_plot"}, {"assembly", a.id}});
}

/// Section 2: the posterior densities and pair plot of every assembly.
void posteriorSection(ReportPage& pg, const classify::LabBands& bands, const fs::path& dir) {
  pg.body << "<h2 id=\"posterior\">2. Posterior of θ and τ</h2>\n<p>Griddy Gibbs draws θ only at "
             "design points, so the "
             "kept iterations of <code>calibration/&lt;id&gt;/posterior.csv</code> are a few "
             "values repeated; each panel draws "
             "their weighted density instead: every design point weighted by its share of the "
             "iterations (its posterior mass) "
             "and smoothed by a Gaussian kernel no narrower than the design's spacing (the grey "
             "rug marks the design points). "
             "Dashed lines mark the posterior's central 95 % interval (2.5 % and 97.5 % quantiles, "
             "<code>credible95</code>), "
             "dotted green lines the profile-likelihood 95 % interval (<code>profile95</code>), "
             "the dash-dotted black line the "
             "optimiser's optimum; <code>summary.json</code> prints one of the two intervals as "
             "<code>ci95</code> (the profile "
             "interval by default, docs/calibration.md). When the study knows the truth, a red "
             "line marks it, the axis is "
             "widened to show it, and the sentence under the figure says whether the ci95 interval "
             "holds it. The pair plot "
             "shows how the values trade against each other.</p>\n";
  for (const auto& ab : bands.assemblies) posteriorFigure(pg, ab, bands.study, dir);
}

/// The compared assemblies of the classification: its "assemblies", else the keys of its "wins".
std::vector<std::string> comparedIds(const json& csum) {
  std::vector<std::string> ids;
  for (const auto& id : csum.value("assemblies", json::array()))
    ids.push_back(id.get<std::string>());
  if (ids.empty()) {
    const json wins_by_id =
        csum.value("wins", json::object());  // named: items() must not outlive it
    for (const auto& [id, n] : wins_by_id.items()) ids.push_back(id);
  }
  return ids;
}

/// Section 3, first figure: the boxplot of P(M_m | record) over the field records
/// (classification/records.csv, columns prob_<id>).
void selectionBoxplot(ReportPage& pg, const fs::path& dir, const std::vector<std::string>& ids) {
  const fs::path rec_path = dir / "classification" / "records.csv";
  if (!fs::exists(rec_path))
    throw InputError(rec_path.string(), "cannot be read (is this a `twin study` folder?)");
  const std::string text = readTextFile(rec_path.string());
  CsvReader csv(text, rec_path.string());
  if (!csv.next()) throw InputError(rec_path.string(), "has no records");
  const std::vector<std::string> header(csv.fields().begin(), csv.fields().end());
  std::vector<std::size_t> col;
  for (const auto& id : ids) {
    const auto it = std::find(header.begin(), header.end(), "prob_" + id);
    if (it == header.end()) throw InputError(rec_path.string(), "has no column prob_" + id);
    col.push_back(static_cast<std::size_t>(it - header.begin()));
  }
  std::ostringstream d;
  std::size_t n_rec = 0;
  while (csv.next()) {
    const auto& cells = csv.fields();
    for (std::size_t c = 0; c < col.size(); ++c) {
      const std::string_view cell = col[c] < cells.size() ? cells[col[c]] : std::string_view();
      double v = 0;
      if (!parseNumber(cell, v) || !std::isfinite(v))
        throw InputError(csv.where(),
                         "prob_" + ids[c] + " is not a number: '" + std::string(cell) + "'");
      d << (c ? " " : "") << full(v);
    }
    d << '\n';
    ++n_rec;
  }
  if (n_rec == 0) throw InputError(rec_path.string(), "has no records");
  const std::string f = pg.gp.data(d.str());
  std::ostringstream s, xt;
  for (std::size_t i = 0; i < ids.size(); ++i) xt << (i ? ", " : "") << gq(ids[i]) << " " << i + 1;
  s << "set title " << gq("P(M | record) over " + std::to_string(n_rec) + " field records")
    << " noenhanced\n"
    << "set xtics (" << xt.str() << ") noenhanced\nset xrange [0.4:" << ids.size() + 0.6
    << "]\nset yrange [-0.05:1.05]\n"
    << "set ylabel 'posterior probability'\nset grid ytics\nset style fill solid 0.4 border -1\n"
    << "set style boxplot outliers pointtype 7\nset pointsize 0.4\nset boxwidth 0.5\nplot ";
  for (std::size_t i = 0; i < ids.size(); ++i)
    s << (i ? ", " : "") << f << " using (" << i + 1 << "):" << i + 1 << " with boxplot lc "
      << i + 1 << " notitle";
  s << "\n";
  pg.figure(pg.gp.plot(s.str(), 900, 400, "selection boxplot"),
            "Per assembly, the distribution over the field records of its posterior probability "
            "P(M<sub>m</sub> | y<sub>r</sub>) "
            "(<code>classification/records.csv</code>, columns <code>prob_&lt;id&gt;</code>): box "
            "= quartiles, line = median, "
            "whiskers 1.5 IQR, points = outliers.");
  pg.plots.push_back({{"name", "selection_boxplot"}, {"kind", "boxplot"}});
}

/// Section 3, second figure: the records won by each assembly.
void winsPlot(ReportPage& pg, const std::vector<std::string>& ids, const json& wins) {
  std::ostringstream d, xt;
  long total = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const long w = wins.value(ids[i], 0L);
    total += w;
    d << i + 1 << ' ' << w << '\n';
    xt << (i ? ", " : "") << gq(ids[i]) << " " << i + 1;
  }
  const std::string f = pg.gp.data(d.str());
  std::ostringstream s;
  s << "set title " << gq("records won (" + std::to_string(total) + " records)") << " noenhanced\n"
    << "set xtics (" << xt.str() << ") noenhanced\nset xrange [0.4:" << ids.size() + 0.6
    << "]\nset yrange [0:" << std::max<long>(1, total) * 1.12
    << "]\nset ylabel 'records won'\nset grid ytics\nset style fill solid 0.6 border -1\n"
    << "set boxwidth 0.5\nplot " << f << " using 1:2 with boxes lc rgb '#4a7fc0' notitle, " << f
    << " using 1:2:(sprintf('%d', $2)) with labels offset 0,0.8 notitle\n";
  pg.figure(pg.gp.plot(s.str(), 900, 350, "win counts"),
            "Records won by each assembly (largest posterior probability; "
            "<code>summary.json</code> <code>wins</code>).");
  pg.plots.push_back({{"name", "wins"}, {"kind", "wins"}});
}

/// Section 4, figure: total log likelihood against cost, the recommended assembly marked (a
/// warning instead when the classification has no such figures).
void evidencePlot(ReportPage& pg, const std::vector<std::string>& ids, const json& L,
                  const json& cost, const std::string& recommended) {
  std::ostringstream d, r;
  int n = 0;
  double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
  for (const auto& id : ids) {
    if (!L.contains(id) || !cost.contains(id)) continue;
    ++n;
    const double x = cost[id].get<double>(), y = L[id].get<double>();
    (id == recommended ? r : d) << full(x) << ' ' << full(y) << " \"" << id << "\"\n";
    xlo = std::min(xlo, x);
    xhi = std::max(xhi, x);
    ylo = std::min(ylo, y);
    yhi = std::max(yhi, y);
  }
  if (n == 0) {
    pg.warnings.push_back(
        "classification/summary.json has no total_log_likelihood/cost_s_per_s: no evidence plot");
    return;
  }
  if (d.str().empty()) d << r.str();
  if (r.str().empty()) r << d.str();
  const std::string fd = pg.gp.data(d.str()), fr = pg.gp.data(r.str());
  std::ostringstream s;
  s << "set title 'evidence against cost'\nset xlabel 'cost [wall s per simulated s]'\nset ylabel "
       "'total log likelihood L_m'\n"
    << "set grid\nset key bottom right\n";
  padRange(xlo, xhi, 0.15);
  padRange(ylo, yhi, 0.15);
  s << gnuplotTics("x", xlo, xhi, 6) << gnuplotTics("y", ylo, yhi, 6) << "plot " << fd
    << " using 1:2 with points pt 7 ps 1.2 lc rgb '#4a7fc0' title 'assemblies', " << fr
    << " using 1:2 with points pt 5 ps 1.6 lc rgb '#2a9a3a' title "
    << gq("recommended: " + recommended) << " noenhanced, " << fd
    << " using 1:2:3 with labels offset 1.5,0.8 noenhanced notitle, " << fr
    << " using 1:2:3 with labels offset 1.5,0.8 noenhanced notitle\n";
  pg.figure(
      pg.gp.plot(s.str(), 900, 450, "evidence against cost"),
      "Joint log likelihood L<sub>m</sub> = Σ<sub>r</sub> ln N(y<sub>r</sub>; μ<sub>m</sub>, "
      "Σ<sub>m</sub>) of the field "
      "records against the median wall time per simulated second of each assembly's synthesis runs "
      "(<code>classification/summary.json</code>).");
  pg.plots.push_back({{"name", "evidence_cost"}, {"kind", "evidence_cost"}});
}

/// Section 4: the recommendation, the evidence-against-cost figure, and the table of evidence,
/// cost and wins per assembly with the rule.
void evidenceSection(ReportPage& pg, const classify::LabBands& bands,
                     const std::vector<std::string>& ids, const json& csum, const json& wins,
                     const std::string& recommended, const std::string& sentence) {
  const json L = csum.value("total_log_likelihood", json::object()),
             cost = csum.value("cost_s_per_s", json::object());
  pg.body << "<h2 id=\"evidence\">4. Evidence against cost</h2>\n<p class=\"rec\">"
          << htmlEscape(sentence) << "</p>\n";
  double best = -INFINITY;
  for (const auto& id : ids)
    if (L.contains(id)) best = std::max(best, L[id].get<double>());
  evidencePlot(pg, ids, L, cost, recommended);
  const json two = csum.contains("recommendation")
                       ? csum["recommendation"].value("two_ln_b_vs_best", json::object())
                       : json::object();
  std::ostringstream& body = pg.body;
  body << "<table>\n<tr><th>assembly</th><th>label</th><th>total log likelihood</th><th>2 "
          "(L<sub>best</sub> − L<sub>m</sub>)</th>"
          "<th>cost [s/s]</th><th>records won</th><th>recommended</th></tr>\n";
  for (const auto& id : ids) {
    std::string label;
    for (const auto& ab : bands.assemblies)
      if (ab.assembly.id == id) label = ab.assembly.label();
    body << "<tr><td>" << htmlEscape(id) << "</td><td>" << htmlEscape(label)
         << "</td><td class=\"n\">" << (L.contains(id) ? num(L[id].get<double>(), 10) : "–")
         << "</td><td class=\"n\">"
         << (two.contains(id) ? num(two[id].get<double>())
                              : (L.contains(id) ? num(2 * (best - L[id].get<double>())) : "–"))
         << "</td><td class=\"n\">" << (cost.contains(id) ? num(cost[id].get<double>(), 4) : "–")
         << "</td><td class=\"n\">" << wins.value(id, 0L) << "</td><td>"
         << (id == recommended ? "yes" : "") << "</td></tr>\n";
  }
  body << "</table>\n";
  if (csum.contains("recommendation"))
    body << "<p>Rule: " << htmlEscape(csum["recommendation"].value("rule", "")) << " (threshold "
         << htmlEscape(text(csum["recommendation"].value("threshold_two_ln_b", json())))
         << ").</p>\n";
}

/// Section 5, second table: per assembly, the sizes and seeds of its calibration and synthesis.
void perAssemblyProvenance(std::ostringstream& body, const classify::LabBands& bands,
                           const fs::path& dir) {
  body
      << "</table>\n<h3>Per assembly (from the calibration and synthesis summaries)</h3>\n<table>\n"
         "<tr><th>assembly</th><th>calibration seed</th><th>optimizer starts</th><th>LHS "
         "points</th><th>Gibbs iterations</th>"
         "<th>burn-in</th><th>lab values n</th><th>SSE<sub>min</sub></th><th>synthesis "
         "seed</th><th>draws × roads</th>"
         "<th>road library</th><th>vectors</th><th>failures</th></tr>\n";
  for (const auto& ab : bands.assemblies) {
    const auto& a = ab.assembly;
    const json cs = readJsonIfExists(dir / "calibration" / a.id / "summary.json");
    const json ss = readJsonIfExists(dir / "synthetic" / a.id / "synthesis.json");
    const json co = cs.value("options", json::object());
    auto cell = [&](const json& j) {
      body << "<td class=\"n\">" << htmlEscape(text(j)) << "</td>";
    };
    body << "<tr><td>" << htmlEscape(a.id) << "</td>";
    cell(co.value("seed", json()));
    cell(co.value("optimizer_starts", json()));
    cell(co.value("lhs_points", json()));
    cell(co.value("gibbs_iterations", json()));
    cell(co.value("gibbs_burn_in", json()));
    cell(cs.value("n_data", json()));
    cell(cs.value("sse_min", json()));
    cell(ss.value("seed", json()));
    body << "<td class=\"n\">"
         << htmlEscape(text(ss.value("draws", json())) + " × " +
                       text(ss.value("roads_per_draw", json())))
         << "</td>";
    cell(ss.value("road_library", json()));
    cell(ss.value("vectors", json()));
    cell(ss.value("failures", json()));
    body << "</tr>\n";
  }
  body << "</table>\n";
}

/// `p` relative to the folder `base` (the page's folder): the page names no absolute path, and
/// the links still hold when the folder is moved or copied whole.
std::string relativeTo(const fs::path& p, const fs::path& base) {
  std::error_code ec;
  const fs::path rel = fs::relative(fs::absolute(p), fs::absolute(base), ec);
  return ec || rel.empty() ? p.filename().string() : rel.lexically_normal().string();
}

/// Section 5: program, commands, paths (relative to the page's folder), times, seeds and sizes.
void provenanceSection(ReportPage& pg, const classify::LabBands& bands, const fs::path& dir,
                       const StudyFiles& files, const std::string& command,
                       const fs::path& page_dir) {
  const json& record = files.record;
  const json& summary = files.summary;
  const json& csum = files.csum;
  std::ostringstream& body = pg.body;
  body << "<h2 id=\"provenance\">5. Provenance</h2>\n<table>\n";
  auto row = [&](const std::string& k, const std::string& v) {
    body << "<tr><th>" << htmlEscape(k) << "</th><td>" << htmlEscape(v) << "</td></tr>\n";
  };
  const json prog = record.value("program", summary.value("program", json::object()));
  row("program", prog.value("name", std::string("twin")) + " " +
                     prog.value("version", std::string()) + " (" +
                     prog.value("git", std::string()) + ")");
  const json now_prog = programInfo();
  row("report made by", now_prog.value("name", std::string("twin")) + " " +
                            now_prog.value("version", std::string()) + " (" +
                            now_prog.value("git", std::string()) + "), " + utcNow());
  row("study command", record.value("command", std::string()));
  if (summary.value("command", std::string()) != record.value("command", std::string()))
    row("last study command", summary.value("command", std::string()));
  row("report command", command);
  row("study file", relativeTo(bands.study_path, page_dir));
  row("study folder", relativeTo(dir, page_dir));
  row("lab data", relativeTo(bands.lab_path, page_dir) + " (" +
                      std::to_string(bands.lab.records.size()) + " records)");
  row("study created (UTC)", record.value("created_utc", std::string()));
  row("summary written (UTC)", summary.value("created_utc", std::string()));
  row("seed", std::to_string(bands.study.seed));
  {
    std::string sz;
    for (const auto& [k, v] : bands.study.sizes.asMap())
      sz += (sz.empty() ? "" : ", ") + k + " = " + std::to_string(v);
    row("study sizes", sz);
  }
  row("field records classified", text(summary.value("records", json())));
  if (csum.contains("covariance"))
    row("covariance",
        csum["covariance"].value("method", "") + ": " + csum["covariance"].value("reason", ""));
  if (summary.contains("stages")) {
    std::string st;
    for (auto& [k, v] : summary["stages"].items())
      st += (st.empty() ? "" : ", ") + k + " " + num(v.get<double>(), 4) + " s";
    row("stage wall time (last invocation)", st);
  }
  perAssemblyProvenance(body, bands, dir);
}

/// The whole page: head and style, title, study line, recommendation, warnings, contents, the
/// sections 1–5 and the appendix.
std::string pageHtml(const classify::LabBands& bands, const fs::path& dir,
                     const std::string& sentence, const ReportPage& pg,
                     const ReportOptions& options) {
  const std::string title = "twin study report: " +
                            (bands.study.name.empty() ? dir.filename().string() : bands.study.name);
  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>"
       << htmlEscape(title) << "</title>\n<style>\n"
       << reportCss() << "\n</style>\n</head>\n<body>\n<h1>" << htmlEscape(title) << "</h1>\n"
       << "<p>Study <code>" << htmlEscape(bands.study.name)
       << "</code>: " << htmlEscape(bands.study.description) << ". Assemblies: ";
  for (std::size_t m = 0; m < bands.assemblies.size(); ++m)
    page << (m ? ", " : "")
         << htmlEscape(bands.assemblies[m].assembly.id + " (" +
                       bands.assemblies[m].assembly.label() + ")");
  page << ".</p>\n<p class=\"rec\">" << htmlEscape(sentence) << "</p>\n";
  if (!pg.warnings.empty()) {
    page << "<div class=\"warn\"><p>Warnings:</p>\n<ul>\n";
    for (const auto& w : pg.warnings) page << "<li>" << htmlEscape(w) << "</li>\n";
    page << "</ul></div>\n";
  }
  page << "<nav><ol><li><a href=\"#lab\">Lab data and predictive bands</a></li><li><a "
          "href=\"#posterior\">Posterior "
          "densities and pairs</a></li><li><a href=\"#selection\">Field-record "
          "selection</a></li><li><a href=\"#evidence\">Evidence "
          "against cost</a></li><li><a href=\"#provenance\">Provenance</a></li>";
  for (const auto& a : options.appendix)
    page << "<li><a href=\"#" << htmlEscape(a.id) << "\">" << htmlEscape(a.title) << "</a></li>";
  page << "</ol></nav>\n" << pg.body.str();
  for (const auto& a : options.appendix) page << a.html;
  page << "</body>\n</html>\n";
  return page.str();
}

}  // namespace

void ReportOptions::validate() const {
  const OptionCheck check("report");
  for (std::size_t k = 0; k < appendix.size(); ++k) {
    const std::string section = "section " + std::to_string(k + 1);
    check.require(!appendix[k].id.empty(), "appendix",
                  section + ": id (the anchor of its heading) must not be empty");
    check.require(
        appendix[k].svg_count >= 0, "appendix",
        section + ": svg_count must be >= 0, got " + std::to_string(appendix[k].svg_count));
  }
}

// The stages: the study folder's files → sections 1 (predictive bands), 2 (posteriors),
// 3 (selection), 4 (evidence against cost), 5 (provenance) → the page with the appendix,
// written atomically → what was drawn.
json writeStudyReport(const classify::LabBands& bands, const std::string& study_dir,
                      const std::string& out_html, const std::string& command,
                      const ReportOptions& options) {
  const auto t_start = std::chrono::steady_clock::now();
  options.validate();
  const std::string gnuplot_exe = requireGnuplot("`twin report`");
  const fs::path dir(study_dir);
  if (!fs::is_directory(dir)) throw InputError(study_dir, "is not a folder");
  const StudyFiles files = readStudyFiles(dir);
  const json& summary = files.summary;
  const json& csum = files.csum;
  const std::string recommended =
      summary.value("recommended", csum.value("recommended", std::string()));
  const std::string sentence = summary.value("recommendation_sentence",
                                             csum.value("recommendation_sentence", std::string()));
  const json wins = summary.value("wins", csum.value("wins", json::object()));

  ReportPage pg(gnuplot_exe, bands.warnings);
  // The interactive view of section 1, beside the page (linked from it).
  const fs::path out_path(out_html);
  const fs::path lab_html = out_path.parent_path() / (out_path.stem().string() + "_lab.html");
  std::string lab_link;
  try {
    writeFileAtomic(
        lab_html.string(),
        labPage(bands, "twin lab view: " + (bands.study.name.empty() ? dir.filename().string()
                                                                     : bands.study.name)));
    lab_link = lab_html.filename().string();
  } catch (const InputError& e) {
    pg.warnings.push_back(std::string("no interactive lab view: ") + e.what());
  }
  predictiveSection(pg, bands, lab_link);
  posteriorSection(pg, bands, dir);
  const std::vector<std::string> ids = comparedIds(csum);
  pg.body << "<h2 id=\"selection\">3. Field-record selection</h2>\n";
  selectionBoxplot(pg, dir, ids);
  winsPlot(pg, ids, wins);
  evidenceSection(pg, bands, ids, csum, wins, recommended, sentence);
  provenanceSection(pg, bands, dir, files, command, fs::path(out_html).parent_path());
  for (const auto& w : pg.gp.warnings()) pg.warnings.push_back(w);
  writeFileAtomic(out_html, pageHtml(bands, dir, sentence, pg, options));

  json failures = json::object(), noise_sd = json::object(), assemblies_json = json::array();
  for (const auto& ab : bands.assemblies) {
    failures[ab.assembly.id] = ab.failures;
    if (!ab.channels.empty()) noise_sd[ab.assembly.id] = ab.noise_sd;
    assemblies_json.push_back(ab.assembly.id);
  }
  int appendix_svgs = 0;
  for (const auto& a : options.appendix) appendix_svgs += a.svg_count;
  return {{"html", out_html},
          {"interactive", lab_link.empty() ? json() : json(lab_html.string())},
          {"plots", pg.plots},
          {"svg_count", pg.gp.count() + appendix_svgs},
          {"assemblies", assemblies_json},
          {"draws", bands.draws},
          {"prediction_failures", failures},
          {"noise_sd", noise_sd},
          {"warnings", pg.warnings},
          {"wall_s",
           std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count()}};
}

}  // namespace dtwin::report
