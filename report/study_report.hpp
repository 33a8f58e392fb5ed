#pragma once
// The HTML report of a study folder (`twin report`, docs/classification.md): one self-contained
// HTML5 page (inline CSS and inline SVG only: no external file, no script, no network) with
//   1. the lab data against each assembly's posterior predictive band, drawn through the lab
//      scenario on a dense grid of times (computed beforehand by study::predictLabBands,
//      study/lab_bands.hpp: the report itself runs no simulation);
//   2. the weighted posterior density of every θ and of τ per assembly, and the pair plot of θ
//      with the joint region, optimum, truth and profile intervals (report/posterior_plots.hpp);
//   3. the field-record selection boxplot (P(M_m | record) over the records,
//      classification/records.csv) and the win counts (summary.json);
//   4. evidence (total log likelihood) against cost, with the recommendation;
//   5. provenance: program, commands, paths, times, seeds and sizes;
// then any ReportOptions::appendix sections (`twin report --diagnosis DIR`). Beside it, the
// interactive view of section 1 (<stem>_lab.html: uPlot, zoom and one cursor; report/lab_page.hpp),
// linked from the page; the page itself stays static for print.
// Axes carry units and human ticks (report/ticks.hpp); the title is the study's name and every
// path is relative to the page's folder. Plots are drawn by gnuplot (Debian package gnuplot-nox)
// run as a subprocess with the svg terminal; its output is inlined (ids made unique per plot;
// report/svg_plot.hpp). Without gnuplot on PATH the call throws InputError naming the package,
// before any work is done (callers that compute the bands first check requireGnuplot() before, as
// `twin report` does).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "classification/lab_bands.hpp"

namespace dtwin::report {

/// A section appended to the page after the provenance and listed in its contents (e.g. a
/// diagnosis, report/diagnosis_report.hpp); `html` is inserted as is (its SVG ids must not
/// clash with the report's own "p<n>_" ids).
struct ReportSection {
  std::string id;     ///< anchor of the section's heading (for the contents)
  std::string title;  ///< entry in the contents
  std::string html;   ///< the section
  int svg_count = 0;  ///< its plots (added to the returned svg_count)
};

struct ReportOptions {
  std::vector<ReportSection>
      appendix;  ///< extra sections after the provenance (none: the page as before)
  /// InputError whose where() is "report.<field>" (common/validate.hpp): every appendix section
  /// has an id and svg_count >= 0.
  void validate() const;
};

/// Draws the study folder `study_dir` (written by `twin study`) with its predictive `bands`
/// (study::predictLabBands of the same folder), writes `out_html` atomically and returns what
/// was drawn: {"html", "interactive" (the lab section's interactive view written beside it,
/// <stem>_lab.html, report/lab_page.hpp; null when no assembly has a band), "plots": [{"name",
/// "kind", "assembly"}...], "svg_count",
/// "assemblies", "draws", "prediction_failures", "noise_sd", "warnings", "wall_s"}.
/// InputError when a needed file is missing or malformed, or when gnuplot is not installed.
nlohmann::json writeStudyReport(const classify::LabBands& bands, const std::string& study_dir,
                                const std::string& out_html, const std::string& command,
                                const ReportOptions& options = {});

/// `text` with & < > " ' replaced by character references (HTML text and attribute values).
std::string htmlEscape(const std::string& text);

}  // namespace dtwin::report
