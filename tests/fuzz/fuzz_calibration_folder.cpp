// Fuzz harness: the calibration-folder reader (calibration/folder.hpp readCalibrationFolder and
// calibratedAssembly). The input is summary.json, a NUL byte, then posterior.csv; an input with
// no NUL is summary.json alone (and the folder has no posterior.csv).
#include <algorithm>
#include <filesystem>

#include "calibration/folder.hpp"
#include "io/study.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fs = std::filesystem;
  using namespace dtwin::fuzz;
  static const dtwin::Study study =
      dtwin::loadStudy((sourceDir() / "data/studies/demo.toml").string());
  static const fs::path dir = [] {
    fs::create_directories(scratch() / "calib");
    return scratch() / "calib";
  }();
  const uint8_t* nul = std::find(data, data + size, uint8_t{0});
  writeBytes(dir / "summary.json", data, static_cast<size_t>(nul - data));
  fs::remove(dir / "posterior.csv");
  if (nul != data + size)
    writeBytes(dir / "posterior.csv", nul + 1, static_cast<size_t>(data + size - nul - 1));
  guarded([&] {
    const auto folder = dtwin::calib::readCalibrationFolder(dir.string());
    (void)dtwin::calib::calibratedAssembly(study, folder);
  });
  return 0;
}
