// The run's speed memo (twin/road_contact.hpp): every corner's force element asks the speed
// profile at the same times, so the memo keeps the last two times of each quantity. It must give
// SpeedProfile's numbers bit for bit in any order of asking, and forget them when the run's
// profile changes.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "twin/road_contact.hpp"

using dtwin::SpeedProfile;
using dtwin::SpeedTrace;
using dtwin::sim::SpeedMemo;

TEST(SpeedMemo, GivesTheProfilesNumbersBitForBitInAnyOrder) {
  std::vector<double> t, v;
  for (int i = 0; i <= 200; ++i) {
    t.push_back(0.05 * i);
    v.push_back(15.0 + 3.0 * std::sin(0.7 * i) + 0.01 * i);
  }
  SpeedProfile traced;
  traced.trace = std::make_shared<const SpeedTrace>(t, v, "memo");
  traced.start_m = 12.5;
  SpeedProfile ramp;  // the default straight line
  ramp.v_final_mps = 20.0;
  ramp.ramp_s = 4.0;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pick(-0.5, 10.5);
  for (const SpeedProfile* p : {&traced, &ramp}) {
    SpeedMemo m;
    m = *p;
    // Times asked again and again (the four corners at t, the delayed signal at t + d), mixed
    // with new ones, in a random order.
    std::vector<double> times;
    for (int i = 0; i < 300; ++i) times.push_back(pick(rng));
    for (int i = 0; i < 3000; ++i) {
      const double s = times[static_cast<std::size_t>(rng() % (i % 7 == 0 ? times.size() : 3))];
      switch (rng() % 3) {
        case 0:
          ASSERT_EQ(m.speed(s), p->speed(s)) << s;
          break;
        case 1:
          ASSERT_EQ(m.accel(s), p->accel(s)) << s;
          break;
        default:
          ASSERT_EQ(m.distance(s), p->distance(s)) << s;
          break;
      }
    }
  }
  // A new profile for the next run: nothing of the last one's is kept.
  SpeedMemo m;
  m = traced;
  const double d = m.distance(3.3), s = m.speed(3.3), a = m.accel(3.3);
  m = ramp;
  EXPECT_EQ(m.distance(3.3), ramp.distance(3.3));
  EXPECT_EQ(m.speed(3.3), ramp.speed(3.3));
  EXPECT_EQ(m.accel(3.3), ramp.accel(3.3));
  EXPECT_NE(m.distance(3.3), d);
  EXPECT_NE(m.speed(3.3), s);
  EXPECT_NE(m.accel(3.3), a);
}
