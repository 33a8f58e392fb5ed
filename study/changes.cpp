// `twin changes` as one call (study/changes.hpp).
#include "study/changes.hpp"

#include <filesystem>

#include "calibration/folder.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "io/provenance.hpp"
#include "report/changes_page.hpp"

namespace dtwin {

diag::ChangeReport detectChanges(const ChangesRequest& request) {
  if (request.before.empty())
    throw InputError("changes.before", "give the first drive's calibration folder");
  if (request.after.empty())
    throw InputError("changes.after", "give the second drive's calibration folder");
  if (!request.out.empty() && std::filesystem::exists(request.out) &&
      !std::filesystem::is_directory(request.out))
    throw InputError("changes.out", "'" + request.out + "' exists and is not a folder");
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
