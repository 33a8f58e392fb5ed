#pragma once
// `twin report` as one call: the self-contained HTML report of a study folder (its lab bands
// simulated here, study/lab_bands.hpp) with the diagnosis folders' sections appended, or of
// diagnosis folders alone; drawn by report/.
#include <string>
#include <vector>

namespace dtwin::study {

struct ReportRequest {
  std::string study_dir;               ///< a `twin study` folder; "" for diagnosis folders alone
  std::vector<std::string> diagnoses;  ///< `twin diagnose` folders, appended in order
  std::string page;                    ///< the report.html to write
  int draws = 50;                      ///< posterior rows per assembly for the lab bands
  int threads = 0;                     ///< simulations in parallel (0: all cores)
  std::string command;                 ///< recorded in the page
};

struct ReportRun {
  std::string page;                   ///< the report written
  std::string interactive;            ///< the interactive lab view beside it ("" when none)
  int svg_count = 0;                  ///< plots drawn
  double wall_s = 0;                  ///< seconds it took
  std::vector<std::string> warnings;  ///< e.g. a study file changed after the study ran
};

/// Writes the report (InputError naming the folder or file when one is missing or malformed;
/// needs gnuplot, checked before any simulation when a study folder is given; the diagnosis
/// folders are read and checked before the study's simulations).
ReportRun writeReport(const ReportRequest& request);

}  // namespace dtwin::study
