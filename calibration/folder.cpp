#include "calibration/folder.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "io/provenance.hpp"
#include "twin/trace.hpp"

namespace fs = std::filesystem;

namespace dtwin::calib {

CalibrationFolder readCalibrationFolder(const std::string& dir) {
  const fs::path d(dir);
  if (!fs::is_directory(d))
    throw InputError(dir,
                     "is not a folder (give one written by `twin calibrate` or `twin diagnose`)");
  CalibrationFolder f;
  f.dir = dir;
  const fs::path summary_path = d / "summary.json";
  if (!fs::exists(summary_path) && fs::exists(d / "optimum.json"))
    throw InputError(dir,
                     "holds only an optimum (a `twin diagnose` candidate that could not be the "
                     "verdict stops there); "
                     "rerun that diagnosis with --all-intervals to calibrate it in full");
  if (!fs::exists(summary_path))
    throw InputError(
        dir, "has no summary.json (give a folder written by `twin calibrate` or `twin diagnose`)");
  const std::string where = summary_path.string();
  try {
    f.summary = nlohmann::json::parse(readTextFile(where));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, std::string("is not valid JSON: ") + jsonErrorInWords(e));
  }
  if (!f.summary.is_object()) throw InputError(where, "must hold a JSON object");
  if (!f.summary.contains("assembly")) throw InputError(where + ": assembly", "is missing");
  if (!f.summary["assembly"].is_string() || f.summary["assembly"].get<std::string>().empty())
    throw InputError(where + ": assembly", "must be a non-empty string (an assembly id), got " +
                                               f.summary["assembly"].dump());
  f.assembly = f.summary["assembly"].get<std::string>();
  if (f.summary.contains("setup")) {
    try {
      f.setup = CalibrationSetup::fromJson(f.summary["setup"]);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw InputError(where + ": setup", std::string("is malformed: ") + jsonErrorInWords(e));
    }
  }
  if (f.summary.contains("bound_findings")) {
    try {
      for (const auto& b : f.summary["bound_findings"])
        f.bound_findings.push_back(BoundFinding::fromJson(b));
    } catch (const std::exception& e) {
      throw InputError(where + ": bound_findings",
                       std::string("is malformed: ") + jsonErrorInWords(e));
    }
  }
  f.posterior = readPosteriorCsv((d / "posterior.csv").string());
  return f;
}

AssemblySpec calibratedAssembly(const Study& study, const CalibrationFolder& folder) {
  std::string known;
  for (const auto& a : study.assemblies()) {
    if (a.id == folder.assembly) return a;
    known += (known.empty() ? "" : ", ") + a.id;
  }
  throw InputError((fs::path(folder.dir) / "summary.json").string() + ": assembly",
                   "'" + folder.assembly + "' is not an assembly of the study " + study.path +
                       " (it defines: " + known + ")");
}

}  // namespace dtwin::calib
