// Fuzz harness: the road-against-time CSV reader (subsystems/time_road.hpp parseTimeRoadCsv, on
// common/csv.hpp's CsvReader), then the drift removal and the mapping to distance of an
// accepted log at 10 m/s.
#include <string>

#include "subsystems/time_road.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace dtwin::fuzz;
  const std::string text(reinterpret_cast<const char*>(data), size);
  guarded([&] {
    const auto log = dtwin::parseTimeRoadCsv(text, "road.csv");
    dtwin::TimeRoadOptions o;
    o.dx_m = 0.05;
    // Bounded grids only: a fuzzed time span of 1e300 s is refused inside (at most 1e7 points).
    const auto road = dtwin::roadFromTimeLog(log, [](double t) { return 10.0 * t; }, o, {});
    (void)road->sample(dtwin::Track::Left, 0.5 * (road->extent().lo + road->extent().hi));
  });
  return 0;
}
