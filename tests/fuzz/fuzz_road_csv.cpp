// Fuzz harness: the measured-road CSV reader (subsystems/road.hpp loadRoadCsv), then a few
// height queries on an accepted road.
#include "subsystems/road.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace dtwin::fuzz;
  static const auto path = scratch() / "road.csv";
  writeBytes(path, data, size);
  guarded([&] {
    const auto road = dtwin::loadRoadCsv(path.string());
    const dtwin::Interval e = road->extent();
    for (double x : {e.lo - 1.0, e.lo, 0.5 * (e.lo + e.hi), e.hi, e.hi + 1.0})
      for (auto t : {dtwin::Track::Left, dtwin::Track::Right}) {
        (void)road->sample(t, x);
        (void)road->sampleAveraged(t, x, 0.2);
      }
  });
  return 0;
}
