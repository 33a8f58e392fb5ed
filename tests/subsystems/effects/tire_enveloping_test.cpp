// The `tire_enveloping` effect's closed form (subsystems/effects/tire_enveloping.hpp); the contract
// every effect keeps is checked over the registry in tests/subsystems/effect_test.cpp.
#include "subsystems/effects/tire_enveloping.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "../effect_fixture.hpp"
#include "subsystems/road.hpp"

namespace dtwin {
namespace {

using dtwin_test::kTracks;
using dtwin_test::valuesWith;

TEST(TireEnveloping, AveragesTheBumpOverTheContactLength) {
  auto e = makeEffect("tire_enveloping", "t");
  const double x0 = 5.0, H = 0.2, L = 0.1, window = 0.3;
  BumpRoad bump(x0, H, L);
  const auto v = valuesWith(*e, {{"length_m", window}});
  const double plateau = 0.5 * H * L / window;  // whole bump area / window length
  double peak = 0.0;
  for (Track t : kTracks) {
    for (double x = x0 - 0.3; x <= x0 + L + 0.3; x += 0.001) {
      const RoadSample s = e->filterRoad(bump, t, x, v);
      peak = std::max(peak, s.height_m);
      EXPECT_GE(s.height_m, -1e-17);
      EXPECT_LE(s.height_m, plateau * (1 + 1e-12));
      // Slope is the derivative of the averaged height.
      const double h = 1e-6;
      const double fd =
          (e->filterRoad(bump, t, x + h, v).height_m - e->filterRoad(bump, t, x - h, v).height_m) /
          (2 * h);
      EXPECT_NEAR(s.slope, fd, 1e-6) << "x " << x;
    }
    // While the window covers the whole bump ([x - 0.15, x + 0.15] contains [x0, x0 + L]):
    for (double x : {x0 - 0.05 + 1e-6, x0, x0 + 0.05, x0 + 0.1, x0 + 0.15 - 1e-6}) {
      EXPECT_NEAR(e->filterRoad(bump, t, x, v).height_m, plateau, 1e-15) << "x " << x;
      EXPECT_NEAR(e->filterRoad(bump, t, x, v).slope, 0.0, 1e-15) << "x " << x;
    }
    // Far from the bump: flat.
    EXPECT_EQ(e->filterRoad(bump, t, x0 - 1.0, v).height_m, 0.0);
    EXPECT_EQ(e->filterRoad(bump, t, x0 + 1.0, v).height_m, 0.0);
    // Partly covered: the window [x - 0.15, x + 0.15] holds the bump's first half.
    const double xa = x0 + 0.05 - 0.15;
    EXPECT_NEAR(e->filterRoad(bump, t, xa, v).height_m, 0.25 * H * L / window, 1e-15);
  }
  EXPECT_NEAR(peak, plateau, 1e-12);
  EXPECT_LT(peak, H);  // far lower than the point-contact peak
  EXPECT_NEAR(peak / H, L / (2 * window), 1e-12);
}

TEST(TireEnveloping, ShortWindowTendsToPointContact) {
  auto e = makeEffect("tire_enveloping", "t");
  BumpRoad bump(5.0, 0.2, 0.1);
  const auto v = valuesWith(*e, {{"length_m", 1e-4}});
  for (double x = 5.001; x < 5.1; x += 0.0071) {
    EXPECT_NEAR(e->filterRoad(bump, Track::Left, x, v).height_m,
                bump.sample(Track::Left, x).height_m, 1e-5);
    EXPECT_NEAR(e->filterRoad(bump, Track::Left, x, v).slope, bump.sample(Track::Left, x).slope,
                1e-3);
  }
}

}  // namespace
}  // namespace dtwin
