// `twin changes` as one call (study/changes.hpp).
#include "study/changes.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "calibration/folder.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "io/provenance.hpp"
#include "report/changes_page.hpp"
#include "report/changes_series_page.hpp"

namespace dtwin {
namespace {

/// The drive date of calibration folder `f`: its data file's sidecar (summary.json's data.path,
/// less any "@SCENARIO", with ".json" for its extension), source.start_utc.
std::string dateFromData(const calib::CalibrationFolder& f) {
  const std::string where = f.dir + "/summary.json: data.path";
  const auto& s = f.summary;
  if (!s.contains("data") || !s["data"].is_object() || !s["data"].contains("path") ||
      !s["data"]["path"].is_string())
    throw InputError(where, "missing: give the drives' dates (--dates)");
  std::string path = s["data"]["path"].get<std::string>();
  path = path.substr(0, path.find(','));
  path = path.substr(0, path.find('@'));
  const std::string sidecar = std::filesystem::path(path).replace_extension(".json").string();
  std::ifstream in(sidecar);
  if (!in)
    throw InputError(where, "its data's sidecar " + sidecar +
                                " cannot be read: give the drives' dates (--dates)");
  std::stringstream text;
  text << in.rdbuf();
  const auto j = nlohmann::json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.contains("source") || !j["source"].is_object() ||
      !j["source"].contains("start_utc") || !j["source"]["start_utc"].is_string())
    throw InputError(sidecar + ": source.start_utc",
                     "missing (the log's time column held no dates): give the drives' dates "
                     "(--dates)");
  return j["source"]["start_utc"].get<std::string>();
}

void checkOut(const std::string& out) {
  if (!out.empty() && std::filesystem::exists(out) && !std::filesystem::is_directory(out))
    throw InputError("changes.out", "'" + out + "' exists and is not a folder");
}

}  // namespace

diag::SeriesReport detectChangesOverDrives(const ChangesRequest& request) {
  if (!request.before.empty() || !request.after.empty())
    throw InputError("changes.calibrations",
                     "give either two calibrations (before and after) or a series of three or "
                     "more (calibrations), not both");
  if (request.calibrations.size() < 3)
    throw InputError("changes.calibrations",
                     "a series needs at least three calibration folders, got " +
                         std::to_string(request.calibrations.size()) +
                         " (two drives: before and after)");
  if (!request.dates.empty() && request.dates.size() != request.calibrations.size())
    throw InputError("changes.dates", "gives " + std::to_string(request.dates.size()) +
                                          " dates for " +
                                          std::to_string(request.calibrations.size()) +
                                          " calibrations: one date each, in their order");
  checkOut(request.out);
  std::vector<diag::DatedCalibration> drives;
  for (std::size_t i = 0; i < request.calibrations.size(); ++i) {
    diag::DatedCalibration d;
    d.folder = calib::readCalibrationFolder(request.calibrations[i]);
    d.date = request.dates.empty() ? dateFromData(d.folder) : request.dates[i];
    if (!diag::parseDriveDate(d.date, d.day))
      throw InputError(
          request.dates.empty() ? d.folder.dir + "/summary.json: data.path" : "changes.dates",
          "'" + d.date + "' is not a date YYYY-MM-DD (optionally with a time)");
    drives.push_back(std::move(d));
  }
  diag::SeriesReport r =
      diag::compareSeries(std::move(drives), request.level, "changes.calibrations");
  if (!request.out.empty()) {
    nlohmann::json j = r.toJson();
    stampProvenance(j, request.command);
    writeFileAtomic((std::filesystem::path(request.out) / "changes.json").string(),
                    j.dump(2) + "\n");
    const std::string title = "What changed over " + std::to_string(r.dirs.size()) + " drives, " +
                              r.dates.front().substr(0, 10) + " to " +
                              r.dates.back().substr(0, 10) + " (" + r.assembly + ")";
    writeFileAtomic((std::filesystem::path(request.out) / "changes.html").string(),
                    changesSeriesPage(r.toJson(), title));
  }
  return r;
}

diag::ChangeReport detectChanges(const ChangesRequest& request) {
  if (request.before.empty())
    throw InputError("changes.before", "give the first drive's calibration folder");
  if (request.after.empty())
    throw InputError("changes.after", "give the second drive's calibration folder");
  checkOut(request.out);
  const calib::CalibrationFolder first = calib::readCalibrationFolder(request.before);
  const calib::CalibrationFolder second = calib::readCalibrationFolder(request.after);
  diag::ChangeReport r = diag::compareCalibrations(first, second, request.level);
  if (!request.out.empty()) {
    nlohmann::json j = r.toJson();
    stampProvenance(j, request.command);
    writeFileAtomic((std::filesystem::path(request.out) / "changes.json").string(),
                    j.dump(2) + "\n");
    // The page, titled by the folders' last two names (drive_may/M1), which tell the drives
    // apart.
    auto shortName = [](const std::string& dir) {
      const std::filesystem::path p = std::filesystem::path(dir).lexically_normal();
      const std::filesystem::path leaf = p.filename().empty() ? p.parent_path() : p;
      return (leaf.parent_path().filename() / leaf.filename()).string();
    };
    const std::string title = "What changed: " + shortName(request.before) + " -> " +
                              shortName(request.after) + " (" + r.assembly + ")";
    writeFileAtomic((std::filesystem::path(request.out) / "changes.html").string(),
                    changesPage(r.toJson(), title));
  }
  return r;
}

}  // namespace dtwin
