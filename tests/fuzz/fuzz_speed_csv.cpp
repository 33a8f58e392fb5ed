// Fuzz harness: the speed-trace CSV reader (io/speed_trace_file.hpp parseSpeedTraceCsv), then
// the interpolant, its integral and its inverse on an accepted trace.
#include <string>

#include "io/speed_trace_file.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace dtwin::fuzz;
  const std::string text(reinterpret_cast<const char*>(data), size);
  guarded([&] {
    const auto s = dtwin::parseSpeedTraceCsv(text, "speed.csv");
    const double a = s.startTime(), b = s.endTime();
    for (double t : {a - 1.0, a, 0.0, 0.5 * (a + b), b, b + 1.0}) {
      (void)s.speed(t);
      (void)s.accel(t);
      (void)s.timeAtDistance(s.distance(t));
    }
  });
  return 0;
}
