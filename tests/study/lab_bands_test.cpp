// The arithmetic of the study report's predictive bands (study/lab_bands.hpp), against closed
// forms: type-7 quantiles of small samples, quantiles of normal mixtures, and the options' rules.
// The bands of a real study folder are exercised end to end by tests/report/study_report_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "calibration/summary.hpp"
#include "common/errors.hpp"
#include "study/lab_bands.hpp"
#include "study/run.hpp"

using dtwin::quantileSorted;
using dtwin::study::normalMixtureQuantile;

// The bands use the calibration's type-7 quantile (calibration/summary.hpp).
TEST(LabBands, BandQuantilesAreType7) {
  const std::vector<double> x{1.0, 2.0, 4.0, 8.0};
  EXPECT_DOUBLE_EQ(quantileSorted(x, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantileSorted(x, 1.0), 8.0);
  EXPECT_DOUBLE_EQ(quantileSorted(x, 0.5), 3.0);            // h = 1.5: 2 + 0.5 (4 - 2)
  EXPECT_DOUBLE_EQ(quantileSorted(x, 0.25), 1.75);          // h = 0.75: 1 + 0.75 (2 - 1)
  EXPECT_THROW(quantileSorted({}, 0.5), std::logic_error);  // never asked of an empty band
  EXPECT_DOUBLE_EQ(quantileSorted({7.0}, 0.975), 7.0);
}

TEST(LabBands, MixtureOfOneNormalGivesItsQuantiles) {
  const double z975 = 1.959963984540054;  // Φ⁻¹(0.975)
  EXPECT_NEAR(normalMixtureQuantile({10.0}, {2.0}, 0.975), 10.0 + 2.0 * z975, 1e-9);
  EXPECT_NEAR(normalMixtureQuantile({10.0}, {2.0}, 0.025), 10.0 - 2.0 * z975, 1e-9);
  EXPECT_NEAR(normalMixtureQuantile({10.0}, {2.0}, 0.5), 10.0, 1e-9);
  // Equal components: the same normal.
  EXPECT_NEAR(normalMixtureQuantile({10.0, 10.0, 10.0}, {2.0, 2.0, 2.0}, 0.975), 10.0 + 2.0 * z975,
              1e-9);
}

TEST(LabBands, SymmetricMixtureHasItsMedianAtTheCentre) {
  // ½ N(−3, 1) + ½ N(3, 1): median 0; the 97.5 % quantile q solves ½ Φ(q + 3) + ½ Φ(q − 3) = 0.975.
  const double q = normalMixtureQuantile({-3.0, 3.0}, {1.0, 1.0}, 0.975);
  EXPECT_NEAR(normalMixtureQuantile({-3.0, 3.0}, {1.0, 1.0}, 0.5), 0.0, 1e-9);
  const auto Phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  EXPECT_NEAR(0.5 * Phi(q + 3.0) + 0.5 * Phi(q - 3.0), 0.975, 1e-10);
  EXPECT_GT(q, 3.0);
}

TEST(LabBands, OptionsNameTheField) {
  dtwin::study::LabBandOptions o;
  EXPECT_NO_THROW(o.validate());
  o.draws = 1;
  try {
    o.validate();
    FAIL() << "draws = 1 accepted";
  } catch (const dtwin::InputError& e) {
    EXPECT_EQ(e.where(), "lab_bands.draws");
  }
  o.draws = 2;
  o.threads = -1;
  EXPECT_THROW(o.validate(), dtwin::InputError);
}

TEST(LabBands, AFolderThatIsNotAStudyIsAnInputError) {
  EXPECT_THROW(dtwin::study::predictLabBands("/nonexistent/dtwin/study"), dtwin::InputError);
}

TEST(StudyRun, OptionsNameTheField) {
  dtwin::study::StudyRunOptions o;
  EXPECT_NO_THROW(o.validate());
  o.threads = -1;
  try {
    o.validate();
    FAIL() << "threads = -1 accepted";
  } catch (const dtwin::InputError& e) {
    EXPECT_EQ(e.where(), "study.threads");
  }
}
