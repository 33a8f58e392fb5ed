// Fuzz harness: the lab CSV reader (io/measurement.hpp parseLabCsv), then what readers of lab
// data do with an accepted file (channels, repetitions, times).
#include <string>

#include "io/measurement.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dtwin::fuzz::guarded([&] {
    const dtwin::LabData lab = dtwin::parseLabCsv(text, "fuzz_lab.csv");
    for (const auto& c : lab.channels()) (void)lab.times(c);
    (void)lab.repetitions();
    (void)dtwin::labCsvText(lab);  // an accepted file must write back
  });
  return 0;
}
