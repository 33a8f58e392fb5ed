#pragma once
// The whole method end to end (docs/method.md §1-5): lab data, field data, calibration of every
// assembly, synthetic field data from every posterior, classification of the field records, and
// the cost-aware recommendation. Every stage persists its results in the study folder as it
// goes (each stage is itself resumable), so a killed study rerun with the same command continues
// where it stopped and ends with identical results.
//
// Folder layout (docs/architecture.md, "One study through the layers"):
//   OUT/lab/lab.csv (+ .json)          stage "lab"        (or the user's --lab file)
//   OUT/field/field.csv (+ .json)      stage "field"      (or the user's --field file)
//   OUT/calibration/<id>/...           stage "calibrate"  (calibration/calibrate.hpp)
//   OUT/synthetic/<id>/...             stage "synthesize" (classification/synthesis.hpp)
//   OUT/classification/...             stage "classify"   (classification/classify_field.hpp)
//   OUT/study.json                     the fingerprint of the study and the stage record
//   OUT/summary.json                   wins, recommended, stages (wall seconds), sentence, paths
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/distributed.hpp"
#include "common/progress.hpp"
#include "io/study.hpp"

namespace dtwin::study {

struct StudyRunOptions {
  int threads = 0;  ///< 0: all cores (never changes the numbers)
  const Distributed* processes =
      nullptr;  ///< the process context (common/distributed.hpp); nullptr: this process alone
  std::string lab_file;    ///< use these lab data instead of generating them
  std::string field_file;  ///< use these field records instead of generating them
  std::string command;     ///< recorded in every output
  /// InputError whose where() is "study.<field>" (common/validate.hpp): threads >= 0.
  void validate() const;
};

/// Progress: stage ("lab", "field", "calibrate M1 optimum", ...), done, total.
using StudyProgress = StageProgress;  // common/progress.hpp
/// One line of news per finished stage (for the CLI to print).
using StudyLog = std::function<void(const std::string& line)>;

/// Runs (or resumes) the study into `out_dir`; returns the content of OUT/summary.json.
nlohmann::json runStudy(const Study& study, const StudyRunOptions& options,
                        const std::string& out_dir, const StudyProgress& progress = {},
                        const StudyLog& log = {});

/// The work of `twin study` on `study` checked against the limits (io/work.hpp): the calibration
/// and the synthesis, and the lab and field data unless `options` give their files. InputError
/// naming the study file above them, unless `force`.
void checkStudyWork(const Study& study, const StudyRunOptions& options, bool force);

/// The lines `twin study` prints at the end: the wins, the recommendation, each stage's wall time
/// and where the summary is.
std::string summaryText(const nlohmann::json& summary, const std::string& out_dir);

}  // namespace dtwin::study
