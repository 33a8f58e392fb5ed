// Fuzz harness: `twin import` (io/log_import.hpp) on an MF4 log, read through the vendored mdflib
// (io/mdf_log.hpp) after the import's own check of the file's block structure. The input is the
// whole file; the mapping is the demonstration drive's. An accepted log is written and its study
// read back, as the command does. The seeds (tests/fuzz/seeds/mf4_import) are the drive's first
// 200 rows written by tests/io/write_mf4.py: `head -201 data/drives/stop_and_go.csv > seed.csv`,
// then `write_mf4.py seed.csv plain.mf4 --units ...` and `... transposed_split.mf4 --data
// transposed --split GPS_Speed --units ...` with the units GPS_Speed=km/h,Road_L=mm,Road_R=mm,
// AccZ_Seat=g,Cabin_Temp=degC.
#include <filesystem>
#include <string>

#include "tests/fuzz/fuzz_common.hpp"
#include "io/log_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace dtwin::fuzz;
  static const dtwin::ImportMapping mapping =
      dtwin::readImportMapping((sourceDir() / "data" / "drives" / "stop_and_go_map.toml").string());
  static const std::string study = (sourceDir() / "data" / "studies" / "demo.toml").string();
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::filesystem::path out = scratch() / "drive";
  std::filesystem::remove_all(out);
  guarded([&] {
    const auto r = dtwin::importLog(bytes, "log.mf4", mapping, study, "drive");
    dtwin::writeImport(r, out.string());
  });
  return 0;
}
