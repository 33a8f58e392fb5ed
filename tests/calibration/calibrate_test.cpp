// The calibration of an assembly against lab data, end to end on the real twin (small sizes).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "calibration/calibrate.hpp"
#include "twin/generate.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::calib;

namespace {
const std::string kDemo = std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml";

std::vector<double> truthOf(const Study& s) {
  std::vector<double> t;
  for (const auto& c : s.calibrated) t.push_back(*c.truth);
  return t;
}
}  // namespace

// The SSE's predictions at the true parameters reproduce the noise-free lab values that
// `generate lab` computed with a full-length run (the objective stops the run early).
TEST(LabObjective, PredictionsAtTruthEqualNoiseFreeLabValues) {
  const Study study = loadStudy(kDemo);
  const auto a = study.assemblies().front();
  const LabResult lab = generateLab(study, a);
  LabObjective obj(study, a, lab.data, "lab");
  const auto eta = obj.predict(truthOf(study));
  ASSERT_EQ(eta.size(), lab.data.records.size());
  const auto& col = lab.noise_free.column("hub_force_fl_N");
  for (std::size_t i = 0; i < eta.size(); ++i) {
    const auto row = static_cast<std::size_t>(std::lround(lab.data.records[i].time_s * 1000.0));
    EXPECT_NEAR(eta[i], col[row], 1.0) << "record " << i << " t = " << lab.data.records[i].time_s;
  }
}
