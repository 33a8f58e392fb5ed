#pragma once
// `twin compare` and `twin diagnose` as one library call each: the measurements read, the work
// checked against its limits, the model compared or diagnosed, and every output file written
// atomically on the root rank with how it was made (program, command, study, data, options).
// The CLI parses its flags into these requests, calls, and prints; the HTML report (report/) is
// drawn from the files written here.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"
#include "common/json.hpp"
#include "diagnosis/compare.hpp"
#include "diagnosis/diagnose.hpp"
#include "io/study.hpp"

namespace dtwin {

struct CompareRequest {
  std::string calibration;        ///< a calibration folder (summary.json + posterior.csv)
  std::vector<std::string> data;  ///< measurement files FILE[@SCENARIO]
  /// Measurement files (the calibration drive) the FIR baseline is fitted on, per channel; each
  /// compared series then also gets the baseline's fit percentage (diagnosis/baseline.hpp).
  std::vector<std::string> baseline;
  /// Measurement files (the calibration drive) a filter from the road to the model's residual is
  /// fitted on, per channel; each compared series then also gets the hybrid's (model + filter) fit
  /// percentage and the filter in words (diagnosis/discrepancy.hpp). Without `baseline`, the FIR
  /// baseline is fitted on these files too.
  std::vector<std::string> discrepancy;
  std::string out;  ///< folder for compare.json; "" writes nothing
  int draws = 30;   ///< posterior rows (evenly spaced) for the predictive band
  int threads = 0;  ///< worker threads (0: all cores)
  const Distributed* processes =
      nullptr;  ///< the process context (common/distributed.hpp); nullptr: this process alone
  bool force = false;   ///< run even above the work limits (io/work.hpp)
  std::string command;  ///< recorded in compare.json
};

struct CompareRun {
  AssemblySpec assembly;
  diag::Comparison comparison;
  std::string written;  ///< the compare.json written ("" without --out)
  nlohmann::json json;  ///< what compare.json holds (built with or without --out)
  std::map<std::string, std::string>
      baseline;  ///< per channel: the FIR baseline, described (--baseline)
  /// What was written beside compare.json, a line each, to print as it stands: "wrote
  /// OUT/compare.html (...)" (the interactive page); empty without an out folder.
  std::vector<std::string> pages;
  /// The table, the windows and bands where the model fails, the state maps and the notes, as
  /// `twin compare` prints them: per series the windows' counts in words and the largest windows,
  /// largest share first (at most 8; compare.html lists every listed one, compare.json every one).
  std::string text() const;
};

/// Compares the calibrated model of `request.calibration` with `request.data` (InputError for a
/// bad request or a file that cannot be read; the work is checked before anything runs); with an
/// out folder writes compare.json and compare.html (titled without absolute paths).
CompareRun compareMeasurements(const Study& study, const CompareRequest& request,
                               const SayFn& say = {});

struct DiagnoseRequest {
  std::string assembly = "M1";
  std::vector<std::string> data;     ///< measurement files FILE[@SCENARIO] to fit
  std::vector<std::string> holdout;  ///< held out: not fitted, their error reported
  /// The options; `options.apply` may hold .toml files (a diagnosis's proposal.toml): their
  /// [user_effects] join the study's catalogue and are applied in their order.
  diag::DiagnoseOptions options;
  std::string
      out;  ///< the folder (resumable); "" runs in a temporary folder and writes no result files
  bool force = false;  ///< run even above the work limits (io/work.hpp)
};

struct DiagnoseRun {
  diag::DiagnosisResult result;
  diag::DiagnoseOptions options;  ///< as run (the .toml items of apply replaced by their effects)
  std::string written;            ///< the diagnosis.json written ("" without an out folder)
  nlohmann::json json;  ///< what diagnosis.json holds (built with or without an out folder)
  /// The pages beside diagnosis.json, a line each, to print as it stands: "wrote OUT/compare.html
  /// (...)" and "wrote OUT/report.html", or "note: no ... (why)" when one could not be drawn
  /// (report.html needs gnuplot); empty without an out folder and on processes other than the
  /// first.
  std::vector<std::string> pages;
};

/// Diagnoses `request.assembly` of `study` on the measurements (docs/diagnosis.md): the work is
/// checked first, then diagnose() runs with calibrations under OUT/calibrations, and
/// OUT/diagnosis.json, OUT/proposal.toml (when the sparse regression proposes terms),
/// OUT/comparisons/*.json (base, every confirmed candidate, every applied step) and the pages
/// OUT/compare.html (the models overlaid) and OUT/report.html (needs gnuplot) are written.
DiagnoseRun diagnoseMeasurements(const Study& study, const DiagnoseRequest& request,
                                 const SayFn& say = {},
                                 const diag::DiagnoseProgress& progress = {});

}  // namespace dtwin
