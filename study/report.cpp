// `twin report` as one call (study/report.hpp).
#include "study/report.hpp"

#include "common/errors.hpp"
#include "report/diagnosis_report.hpp"
#include "report/study_report.hpp"
#include "report/svg_plot.hpp"
#include "study/lab_bands.hpp"

namespace dtwin::study {

namespace {
void takeWarnings(const nlohmann::json& j, std::vector<std::string>& into) {
  for (const auto& w : j["warnings"]) into.push_back(w.get<std::string>());
}
}  // namespace

ReportRun writeReport(const ReportRequest& request) {
  if (request.study_dir.empty() && request.diagnoses.empty())
    throw InputError("twin report",
                     "give a study folder (--study-dir DIR), --diagnosis DIR, or both");
  ReportRun run;
  run.page = request.page;
  if (request.study_dir.empty()) {  // diagnosis-only page
    const auto r = report::writeDiagnosisReport(request.diagnoses, request.page, request.command);
    takeWarnings(r, run.warnings);
    run.svg_count = r["svg_count"].get<int>();
    run.wall_s = r["wall_s"].get<double>();
    return run;
  }
  report::requireGnuplot("`twin report`");  // before any simulation
  report::ReportOptions o;
  std::vector<std::string> diag_warnings;
  for (std::size_t k = 0; k < request.diagnoses.size();
       ++k) {  // read (and checked) before the study's simulations
    report::DiagnosisSectionOptions so;
    so.anchor = "diagnosis-" + std::to_string(k + 1);
    so.id_prefix = "d" + std::to_string(k + 1) + "p";
    so.heading_prefix = std::to_string(6 + k) + ". ";
    nlohmann::json drawn;
    report::ReportSection s;
    s.html = report::diagnosisSectionHtml(request.diagnoses[k], so, &drawn);
    s.id = so.anchor;
    s.title = "Diagnosis: " + request.diagnoses[k];
    s.svg_count = drawn["svg_count"].get<int>();
    takeWarnings(drawn, diag_warnings);
    o.appendix.push_back(std::move(s));
  }
  LabBandOptions bo;
  bo.draws = request.draws;
  bo.threads = request.threads;
  const LabBands bands = predictLabBands(request.study_dir, bo);
  const auto r =
      report::writeStudyReport(bands, request.study_dir, request.page, request.command, o);
  takeWarnings(r, run.warnings);
  run.warnings.insert(run.warnings.end(), diag_warnings.begin(), diag_warnings.end());
  run.svg_count = r["svg_count"].get<int>();
  run.wall_s = r["wall_s"].get<double>();
  if (r["interactive"].is_string()) run.interactive = r["interactive"].get<std::string>();
  return run;
}

}  // namespace dtwin::study
