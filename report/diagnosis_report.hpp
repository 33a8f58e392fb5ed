#pragma once
// The HTML report of a diagnosis folder (`twin report --diagnosis DIR`, docs/classification.md):
// one self-contained HTML5 page (inline CSS and inline SVG drawn by gnuplot, no script, no
// network; the style of the study report, report/svg_plot.hpp) with
//   * the verdict and summary of DIR/diagnosis.json, the ranked (confirmed) effects with their
//     parameter posteriors, and the screening table of every effect;
//   * per series, the measured mean against the base model's predicted mean and 95 % band, and
//     the "after" model's (see below), with a lower panel of the residuals;
//   * the residual band-power ratios (residual / noise power, log scale, noise floor = 1) before
//     and after, one panel per series;
//   * the force–state map with the highest explained_fraction in the base comparison, before
//     and after (bin means ± 2 se);
//   * when `steps` exist (--apply), the before/after tables and a waterfall chart of the
//     systematic RMS (in noise sd) over the steps.
// "Before" is comparisons/base.json; "after" is comparisons/<effect>.json of the named effect,
// else the first applied step's comparison, else nothing (only the base is drawn).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dtwin::report {

struct DiagnosisSectionOptions {
  std::string anchor =
      "diagnosis";  ///< id of the section heading; sub-sections get "<anchor>-<part>"
  std::string id_prefix =
      "d";  ///< SVG ids of plot n become "<id_prefix><n>_<id>" (distinct per section on a page)
  std::string heading_prefix;  ///< put before the heading text (e.g. "6. " in the study report)
  /// InputError whose where() is "diagnosis_section.<field>" (common/validate.hpp): a non-empty
  /// anchor and id_prefix.
  void validate() const;
};

/// The <section> of the diagnosis folder `diag_dir` (written by `twin diagnose --out`), for
/// embedding in a page that uses report::reportCss(). When `drawn` is given it receives
/// {"plots": [{"name", "kind", ...}], "svg_count", "verdict", "effect", "after", "warnings"}.
/// InputError (naming the file) when diagnosis.json or a needed comparisons/*.json file is
/// missing or malformed, or (naming the Debian package gnuplot-nox) when gnuplot is not on PATH,
/// checked before anything is read.
std::string diagnosisSectionHtml(const std::string& diag_dir,
                                 const DiagnosisSectionOptions& options = {},
                                 nlohmann::json* drawn = nullptr);

/// Writes the diagnosis-only page `out_html` (atomically; `command` is recorded on it) and
/// returns what it drew: the `drawn` object of diagnosisSectionHtml plus {"html", "wall_s",
/// "diagnoses": [drawn + "folder"]}. Same errors.
nlohmann::json writeDiagnosisReport(const std::string& diag_dir, const std::string& out_html,
                                    const std::string& command);

/// The same page with one section per folder (anchors "diagnosis-<k>", SVG ids "d<k>p<n>_");
/// "plots", "svg_count" and "warnings" of the result cover every section.
nlohmann::json writeDiagnosisReport(const std::vector<std::string>& diag_dirs,
                                    const std::string& out_html, const std::string& command);

}  // namespace dtwin::report
