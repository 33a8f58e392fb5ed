// Fuzz harness: the field CSV reader (io/measurement.hpp parseFieldCsv).
#include <string>

#include "io/measurement.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dtwin::fuzz::guarded([&] { (void)dtwin::parseFieldCsv(text, "fuzz_field.csv"); });
  return 0;
}
