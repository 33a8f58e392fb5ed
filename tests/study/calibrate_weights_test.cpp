// `twin calibrate` against data with several channels: each weighed by 1/σ², σ from the sensor's
// noise_sd (one repetition) or the repetitions; a channel with no noise is a one-line error; one
// channel, or forces alone, stay unweighted (the sampler's τ takes their noise), as before.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include "common/errors.hpp"
#include "study/calibrate.hpp"

using namespace dtwin;

namespace {
Study twoSensorStudy(const std::string& name) {
  const auto dir = dtwin_test::freshDir(name);
  return loadStudy(
      dtwin_test::writeDemoStudy(
          dir / "study.toml",
          "lab_repetitions = 2\n[sensors.seat]\nquantity = \"acceleration_z\"\n"
          "noise_sd = 0.03\n[sensors.pot]\nbody = \"wheel_fl\"\nquantity = \"travel\"\n"
          "noise_sd = 5e-5\n[sensors.bare]\nquantity = \"acceleration_z\"\n")
          .string());
}

LabData records(const std::vector<std::string>& channels) {
  LabData d;
  for (int k = 0; k < 10; ++k)
    for (const auto& c : channels) d.records.push_back({1, 0.1 * k, c, 0.001 * k});
  return d;
}
}  // namespace

TEST(CalibrateWeights, ChannelsOfDifferentUnitsAreWeighedByTheirNoise) {
  const Study s = twoSensorStudy("calw_units");
  const auto w = channelWeights(s, {"drive.csv", "diag_rough", records({"seat_mps2", "pot_m"})});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_DOUBLE_EQ(w.at("seat_mps2"), 1.0 / (0.03 * 0.03));
  EXPECT_DOUBLE_EQ(w.at("pot_m"), 1.0 / (5e-5 * 5e-5));
  // A force channel with one repetition, beside another unit, takes the study's [noise] variance.
  const auto f =
      channelWeights(s, {"drive.csv", "diag_rough", records({"seat_mps2", "hub_force_fl_N"})});
  EXPECT_DOUBLE_EQ(f.at("hub_force_fl_N"), 1.0 / s.noise_variance_N2);
}

TEST(CalibrateWeights, OneChannelOrForcesAloneStayUnweighted) {
  const Study s = twoSensorStudy("calw_one");
  EXPECT_TRUE(channelWeights(s, {"lab.csv", "diag_rough", records({"seat_mps2"})}).empty());
  // Hub forces alone share the study's one [noise] variance: unweighted, as the lab calibration
  // was.
  EXPECT_TRUE(
      channelWeights(s, {"lab.csv", "lab", records({"hub_force_fl_N", "hub_force_fr_N"})}).empty());
}

TEST(CalibrateWeights, AChannelWithNoNoiseIsAOneLineErrorNamingIt) {
  const Study s = twoSensorStudy("calw_bare");
  try {
    (void)channelWeights(s, {"drive.csv", "diag_rough", records({"seat_mps2", "bare_mps2"})});
    FAIL() << "a channel without noise_sd was weighed";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("drive.csv"), std::string::npos) << m;
    EXPECT_NE(m.find("bare_mps2"), std::string::npos) << m;
    EXPECT_NE(m.find("noise_sd"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}
