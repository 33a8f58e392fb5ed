#pragma once
// The interactive comparison page (`twin compare --out DIR` writes DIR/compare.html): measured,
// predicted with its 95 % band, and residual of every channel of each data set, stacked, zoomed
// and panned together in time with one cursor read out across them; the failing windows that the
// comparison listed (the few that hold the most of the residual) shaded and tabled, largest share
// first, under each channel's count of windows in words (a row zooms to its window); the
// residual's spectrum against the noise per band when the time base allows one. Self-contained:
// uPlot (report/vendor/uplot) and the data are inlined, nothing is fetched at view time. The lines
// are decimated for display only (min and max per pixel column of what is in view); the numbers in
// the page are the comparison's, in full.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dtwin {
namespace diag {
struct DiagnosisResult;
}

/// One model's comparison on the page: its label (e.g. "base", "+ bump_stop") and its JSON
/// (diag::Comparison::toJson with its series data, as compare.json holds it).
struct PageModel {
  std::string label;
  nlohmann::json comparison;
};

/// The page for one or more models compared with the same measurements (`twin diagnose`: the
/// base, then the model with each applied effect, overlaid). The measured series and the failing
/// windows are the first model's; each model adds its predicted line and residual; the last its
/// band. `title` heads the page (the study's name and the data's file names; no absolute paths).
/// Throws InputError when the first JSON holds no series data.
std::string comparePage(const std::vector<PageModel>& models, const std::string& title);

/// The page of one comparison (`twin compare`).
std::string comparePage(const nlohmann::json& compare, const std::string& title);

/// The page of a diagnosis (`twin diagnose --out DIR` writes DIR/compare.html): the base, then
/// each applied effect (--apply) or each cause in turn, overlaid; titled "twin diagnose: `what`
/// against" and the data's file names.
std::string diagnosisPage(const diag::DiagnosisResult& r, const std::string& what,
                          const std::vector<std::string>& data);

/// The page itself, from the data its script draws: {"title", "sets": [{"name", "scenario",
/// "channels": [{"channel", "unit", "t", "y" (measured, null where none), optionally "points"
/// ([{"label", "v"}]: measured values drawn as points, aligned with t, null elsewhere: the lab's
/// repetitions), "models": [{"label", "p", "lo", "hi", "fit", "rms", "coverage"}], "windows",
/// "bands", "bands_note", optionally "windows_note"}], optionally "view": [t0, t1] (the first view)
/// and "no_gaps" (true: a long step is no gap)}], optionally "windows_of", "no_windows" (true: no
/// window table) and "whole" (the whole-record button's text)}. `note` is the sentence under the
/// title. comparePage builds this from comparisons; report/lab_page.hpp from a study's lab bands.
std::string timeSeriesPage(const nlohmann::json& data, const std::string& note);

}  // namespace dtwin
