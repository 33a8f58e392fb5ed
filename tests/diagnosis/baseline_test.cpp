// The FIR baseline (diagnosis/baseline.hpp): least squares recovers a known FIR exactly from its
// own output, scores it 100 %, and the road input puts the rear wheels one wheelbase behind.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/errors.hpp"
#include "diagnosis/baseline.hpp"
#include "io/study.hpp"

using namespace dtwin;
using namespace dtwin::diag;

namespace {
/// A random road input on a 0.01 s grid, and records y = b + Σ h u(t − jΔ) of a known FIR.
struct Known {
  RoadInput in;
  LabData data;
  FirBaseline truth;
  Known(int taps, double noise_sd, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    in.dt_s = 0.01;
    for (auto& v : in.u) {
      v.resize(3001);
      for (auto& x : v) x = 0.01 * g(rng);
    }
    truth.channel = "seat_mps2";
    truth.dt_s = 0.02;
    truth.taps = taps;
    truth.coef.resize(1 + 4 * static_cast<std::size_t>(taps));
    for (auto& c : truth.coef) c = g(rng);
    for (int k = 0; k <= 2900; ++k) {
      const double t = 0.01 * k;
      data.records.push_back({1, t, "seat_mps2", truth.predict(in, t) + noise_sd * g(rng)});
    }
  }
};
}  // namespace

TEST(FirBaseline, RecoversAKnownFirFromItsOutput) {
  const Known k(10, 0.0, 7);
  const FirBaseline b = fitFirBaseline("seat_mps2", {&k.data}, {&k.in}, 0.02, 10);
  ASSERT_EQ(b.coef.size(), k.truth.coef.size());
  for (std::size_t i = 0; i < b.coef.size(); ++i)
    EXPECT_NEAR(b.coef[i], k.truth.coef[i], 1e-6 * (1 + std::abs(k.truth.coef[i]))) << i;
  EXPECT_NEAR(firFitPercent(b, k.data, k.in), 100.0,
              1e-4);  // the ridge and the normal equations: 2.5e-7 of the signal
  EXPECT_EQ(b.training_records, 2901);
  EXPECT_NE(b.describe().find("10 taps each at 0.02 s"), std::string::npos) << b.describe();
}

TEST(FirBaseline, NoiseLowersTheFitAsTheFormulaSays) {
  const Known k(10, 0.05, 8);
  const FirBaseline b = fitFirBaseline("seat_mps2", {&k.data}, {&k.in}, 0.02, 10);
  // On data it was not fitted to (another noise draw of the same system) the fit is
  // 100 (1 − σ / sd(y)), within the sampling error of 2900 records.
  Known other(10, 0.05, 8);
  std::mt19937_64 rng(99);
  std::normal_distribution<double> g(0.0, 1.0);
  double sum = 0, sq = 0;
  for (auto& r : other.data.records) {
    r.value = k.truth.predict(k.in, r.time_s) + 0.05 * g(rng);
    sum += r.value;
    sq += r.value * r.value;
  }
  const double n = static_cast<double>(other.data.records.size());
  const double sd = std::sqrt(sq / n - (sum / n) * (sum / n));
  EXPECT_NEAR(firFitPercent(b, other.data, k.in), 100.0 * (1.0 - 0.05 / sd), 1.0);
}

TEST(FirBaseline, TooFewRecordsForItsCoefficientsIsAnInputError) {
  Known k(10, 0.0, 9);
  k.data.records.resize(20);
  EXPECT_THROW(fitFirBaseline("seat_mps2", {&k.data}, {&k.in}, 0.02, 10), InputError);
}

// The road input: at constant speed the rear wheels meet the front wheels' road one wheelbase
// (L / v seconds) later.
TEST(FirBaseline, TheRearWheelsFollowTheFrontOnesByAWheelbase) {
  const Study s = loadStudy(std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml");
  const ScenarioSpec& sc = s.scenario("diag_rough");
  const auto model = s.makeModel(s.assemblies().front());
  const RoadInput in = roadInput(sc, model->vehicle(), s.seed, 0.001, sc.duration_s);
  const double v = sc.speed.speed(sc.duration_s), lag = model->vehicle().wheelbase() / v;
  ASSERT_GT(v, 1.0);
  double most = 0;
  for (double t = sc.speed.ramp_s + lag + 0.1; t < sc.duration_s - 0.1; t += 0.0137) {
    EXPECT_NEAR(in.at(2, t), in.at(0, t - lag), 2e-5) << t;
    most = std::max(most, std::abs(in.at(0, t)));
  }
  EXPECT_GT(most, 1e-3);  // a rough road
}

// The input form by cross-validation on the training data: a channel that follows the road's
// velocity over a road that drifts (a random walk: its height wanders far from where it started)
// gets the velocity form, and the height form's zero-frequency gain would carry the drift into its
// prediction of another drive; a channel that follows the height gets the height form.
TEST(FirBaseline, TheInputFormIsChosenByCrossValidationOnTheTrainingData) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  const auto walk = [&](double start) {
    RoadInput in;
    in.dt_s = 0.01;
    for (auto& v : in.u) {
      v.resize(3001);
      double h = start;
      for (auto& x : v) x = (h += 0.002 * g(rng));
    }
    return in;
  };
  FirBaseline truth;
  truth.channel = "seat_mps2";
  truth.dt_s = 0.02;
  truth.taps = 8;
  truth.input = FirInput::Velocity;
  truth.coef.assign(1 + 4 * 8, 0.0);
  for (std::size_t i = 1; i < truth.coef.size(); ++i) truth.coef[i] = 0.02 * g(rng);
  const auto recordsOf = [&](const RoadInput& in) {
    LabData d;
    for (int k = 0; k <= 2900; ++k)
      d.records.push_back({1, 0.01 * k, "seat_mps2", truth.predict(in, 0.01 * k) + 0.01 * g(rng)});
    return d;
  };
  const RoadInput train = walk(0.0), test = walk(0.5);  // another drive, its signal 0.5 m off
  const LabData train_data = recordsOf(train), test_data = recordsOf(test);
  const FirBaseline chosen = fitFirBaseline("seat_mps2", {&train_data}, {&train}, 0.02, 8);
  // 2 input forms x 5 ridges, from the 4 wheels and from the 2 front ones.
  ASSERT_EQ(chosen.cv_sse.size(), 20u);
  EXPECT_EQ(chosen.input, FirInput::Velocity);
  EXPECT_NE(chosen.describe().find("vertical velocity"), std::string::npos) << chosen.describe();
  const FirBaseline height =
      fitFirBaseline("seat_mps2", {&train_data}, {&train}, 0.02, 8, FirInput::Height);
  EXPECT_TRUE(height.cv_sse.empty());
  EXPECT_GT(firFitPercent(chosen, test_data, test), firFitPercent(height, test_data, test));
  // A channel that follows the height: the height form.
  truth.input = FirInput::Height;
  const LabData h_data = recordsOf(train);
  EXPECT_EQ(fitFirBaseline("seat_mps2", {&h_data}, {&train}, 0.02, 8).input, FirInput::Height);
}

// One signal for both tracks (a logged road): the right wheels repeat the left ones and enter
// once; the FIR from the 2 distinct signals (left front, left rear) recovers the system.
TEST(FirBaseline, WheelsThatRepeatAnotherEnterOnce) {
  Known k(10, 0.0, 12);
  k.in.u[1] = k.in.u[0];
  k.in.u[3] = k.in.u[2];
  FirBaseline truth = k.truth;
  truth.corners = {0, 2};
  truth.coef.resize(1 + 2 * 10);
  for (auto& r : k.data.records) r.value = truth.predict(k.in, r.time_s);
  const FirBaseline b = fitFirBaseline("seat_mps2", {&k.data}, {&k.in}, 0.02, 10);
  EXPECT_EQ(b.corners, (std::vector<int>{0, 2}));
  EXPECT_EQ(b.input, FirInput::Height);
  EXPECT_NEAR(firFitPercent(b, k.data, k.in), 100.0, 1e-3);
  EXPECT_NE(b.describe().find("2 distinct wheel signals"), std::string::npos) << b.describe();
}
