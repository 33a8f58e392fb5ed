// Fuzz harness: the OpenCRG reader (subsystems/crg.hpp parseCrg), then heights of an accepted
// surface inside and outside its grid and the two-track road made from it.
#include <cmath>

#include "subsystems/crg.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace dtwin::fuzz;
  const std::string text(reinterpret_cast<const char*>(data), size);
  guarded([&] {
    const dtwin::CrgSurface s = dtwin::parseCrg(text, "road.crg");
    const double u_hi = s.u0_m + s.du_m * static_cast<double>(s.rows - 1);
    const double v_lo = s.v_m.front(), v_hi = s.v_m.back();
    for (double u : {s.u0_m - 1.0, s.u0_m, 0.5 * (s.u0_m + u_hi), u_hi, u_hi + 1.0})
      for (double v : {v_lo - 1.0, v_lo, 0.5 * (v_lo + v_hi), v_hi, v_hi + 1.0})
        (void)s.height(u, v);
    const auto road = dtwin::makeCrgRoad(s, v_hi, v_lo, s.u0_m, {});
    const dtwin::Interval e = road->extent();
    for (double x : {e.lo, 0.5 * (e.lo + e.hi), e.hi})
      for (auto t : {dtwin::Track::Left, dtwin::Track::Right}) (void)road->sample(t, x);
  });
  return 0;
}
