// Fuzz harness: the study file reader (io/study.hpp loadStudy). The input is the study TOML,
// written as studies/fuzz.toml beside a copy of the project's vehicle folder, so that a study
// naming "../vehicle/midsize_sedan.toml" (as data/studies/*.toml do) finds it.
#include <filesystem>

#include "io/study.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fs = std::filesystem;
  using namespace dtwin::fuzz;
  static const fs::path study = [] {
    fs::create_directories(scratch() / "studies");
    fs::create_directories(scratch() / "vehicle");
    fs::copy_file(sourceDir() / "data/vehicle/midsize_sedan.toml",
                  scratch() / "vehicle/midsize_sedan.toml", fs::copy_options::overwrite_existing);
    return scratch() / "studies/fuzz.toml";
  }();
  writeBytes(study, data, size);
  guarded([&] {
    const dtwin::Study s = dtwin::loadStudy(study.string());
    // What every command does next with a loaded study: the parameter table and each assembly.
    (void)s.parameterTable();
    for (const auto& a : s.assemblies()) (void)s.assembly(a.id);
  });
  return 0;
}
