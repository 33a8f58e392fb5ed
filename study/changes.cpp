// `twin changes` as one call (study/changes.hpp).
#include "study/changes.hpp"

#include <filesystem>

#include "calibration/folder.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "io/provenance.hpp"

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
  }
  return r;
}

}  // namespace dtwin
