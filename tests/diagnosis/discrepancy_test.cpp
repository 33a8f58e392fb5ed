// The discrepancy filter (diagnosis/discrepancy.hpp): the cross spectrum's phase is a delay's
// 2π f τ; a known FIR hidden in a residual is recovered and a residual of noise gets no filter; on
// the twin, a car with a controller the model leaves out (road_feedforward, skyhook) is predicted
// far better by physics + filter on a drive the filter was not fitted to than by the physics
// alone, never worse than the FIR baseline, and the filter's response in the body band reads as
// the controller would make it; a model that is right gets nothing.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <cmath>
#include <random>

#include "calibration/calibrate.hpp"
#include "diagnosis/baseline.hpp"
#include "diagnosis/discrepancy.hpp"
#include "diagnosis/signal.hpp"
#include "io/study.hpp"
#include "study/generate.hpp"

using namespace dtwin;
using namespace dtwin::diag;

namespace {

/// A random road input on a 0.01 s grid (4 independent wheels).
RoadInput randomRoad(unsigned seed, std::size_t n = 4001) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  RoadInput in;
  in.dt_s = 0.01;
  for (auto& v : in.u) {
    v.resize(n);
    for (auto& x : v) x = 0.01 * g(rng);
  }
  return in;
}

/// Records of `channel` at the grid's times from 0 to `until_s`, valued by `f(t)`.
template <class F>
LabData recordsOf(double until_s, F f) {
  LabData d;
  for (int k = 0; 0.01 * k <= until_s + 1e-9; ++k)
    d.records.push_back({1, 0.01 * k, "seat_mps2", f(0.01 * k)});
  return d;
}

/// The series form of one repetition: its times and the values at them.
void series(const LabData& d, const std::vector<double>& per_record, std::vector<double>& t,
            std::vector<double>& v) {
  t.clear();
  v.clear();
  for (std::size_t i = 0; i < d.records.size(); ++i)
    t.push_back(d.records[i].time_s), v.push_back(per_record[i]);
}
}  // namespace

// y(t) = x(t − τ): y lags x by τ, so arg P_xy = −2π f τ at every frequency x excites.
TEST(CrossSpectrum, TheCrossSpectrumOfADelayHasThePhaseOfTheDelay) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  const double fs = 100.0;
  const int lag = 3;  // 30 ms
  std::vector<double> x(8192), y(8192, 0.0);
  for (auto& v : x) v = g(rng);
  for (std::size_t i = lag; i < x.size(); ++i) y[i] = x[i - lag];
  const CrossSpectra cs = welchCrossSpectra(x, y, fs, 256);
  ASSERT_EQ(cs.freq_hz.size(), 129u);
  for (std::size_t k = 1; k < cs.freq_hz.size(); k += 8) {
    if (cs.freq_hz[k] > 15.0) break;  // the Hann window's leakage grows with the phase's slope
    const double expect = -2 * std::acos(-1.0) * cs.freq_hz[k] * lag / fs;
    EXPECT_NEAR(std::arg(cs.pxy[k]), expect, 0.05) << cs.freq_hz[k];
    EXPECT_NEAR(std::abs(cs.pxy[k]) / cs.pxx[k], 1.0, 0.1) << cs.freq_hz[k];
  }
  // The same scaling as welchPsd.
  const Spectrum p = welchPsd(x, fs, 256);
  for (std::size_t k = 0; k < p.value.size(); ++k)
    EXPECT_NEAR(cs.pxx[k], p.value[k], 1e-12 * (1 + p.value[k]));
}

// A residual that is a known FIR of the road's velocity plus noise: the filter is chosen, predicts
// a drive it was not fitted to as the formula says, and its response against a physics prediction
// that is another FIR of the road is the ratio of the two.
TEST(Discrepancy, AKnownFilterInTheResidualIsFoundAndPredicts) {
  FirBaseline truth;
  truth.channel = "seat_mps2";
  truth.dt_s = 0.02;
  truth.taps = 10;
  truth.input = FirInput::Velocity;
  truth.coef.assign(1 + 4 * 10, 0.0);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  for (std::size_t i = 1; i < truth.coef.size(); ++i)
    truth.coef[i] = 0.02 * g(rng) / (1 + 0.2 * static_cast<double>((i - 1) % 10));
  FirBaseline model = truth;  // the physics: another FIR of the road
  for (std::size_t i = 1; i < model.coef.size(); ++i)
    model.coef[i] = 3 * truth.coef[i] + 0.01 * g(rng);
  const auto drive = [&](unsigned seed, RoadInput& in, LabData& d, std::vector<double>& physics) {
    in = randomRoad(seed);
    std::mt19937_64 noise(seed + 100);
    d = recordsOf(38.0, [&](double t) {
      return model.predict(in, t) + truth.predict(in, t) + 0.002 * g(noise);
    });
    physics.clear();
    for (const auto& r : d.records) physics.push_back(model.predict(in, r.time_s));
  };
  RoadInput in_a, in_b;
  LabData a, b;
  std::vector<double> pa, pb;
  drive(21, in_a, a, pa);
  drive(22, in_b, b, pb);
  const DiscrepancyFilter f = fitDiscrepancy("seat_mps2", {{&a, &pa, &in_a}});
  ASSERT_FALSE(f.fir.none()) << f.describe();
  EXPECT_EQ(f.fir.input, FirInput::Velocity);
  EXPECT_GE(f.fir.taps, 10) << f.describe();
  EXPECT_LT(f.cv_sse_chosen, 0.1 * f.cv_sse_none);
  std::vector<double> t, p;
  series(b, pb, t, p);
  const SeriesDiscrepancy s = scoreDiscrepancy(f, t, p, b, in_b);
  // y − ŷ − d is the noise alone (and the filter's error): the fit is 100 (1 − σ / sd(y)).
  double sum = 0, sq = 0;
  for (const auto& r : b.records) sum += r.value, sq += r.value * r.value;
  const double n = static_cast<double>(b.records.size()),
               sd = std::sqrt(sq / n - (sum / n) * (sum / n));
  EXPECT_NEAR(s.hybrid_fit_percent, 100 * (1 - 0.002 / sd), 1.0);
  EXPECT_LT(s.physics_fit_percent, s.hybrid_fit_percent - 10);
  EXPECT_GT(s.share, 0.1);
  EXPECT_FALSE(f.bands.empty());
  EXPECT_FALSE(f.summary.empty());
  EXPECT_EQ(f.freq_hz.size(), f.gain.size());
}

// A residual of white noise: nothing predicts it better than nothing, and the hybrid is the
// physics.
TEST(Discrepancy, AResidualOfNoiseGetsNoFilter) {
  const RoadInput in_a = randomRoad(31), in_b = randomRoad(32);
  std::mt19937_64 rng(33);
  std::normal_distribution<double> g(0.0, 1.0);
  const auto physicsAt = [](const RoadInput& in, double t) {
    return 50 * (in.at(0, t) - in.at(0, t - 0.02));
  };
  const LabData a = recordsOf(38.0, [&](double t) { return physicsAt(in_a, t) + 0.05 * g(rng); });
  const LabData b = recordsOf(38.0, [&](double t) { return physicsAt(in_b, t) + 0.05 * g(rng); });
  std::vector<double> pa, pb;
  for (const auto& r : a.records) pa.push_back(physicsAt(in_a, r.time_s));
  for (const auto& r : b.records) pb.push_back(physicsAt(in_b, r.time_s));
  const DiscrepancyFilter f = fitDiscrepancy("seat_mps2", {{&a, &pa, &in_a}});
  std::vector<double> t, p;
  series(b, pb, t, p);
  const SeriesDiscrepancy s = scoreDiscrepancy(f, t, p, b, in_b);
  EXPECT_TRUE(f.fir.none() || s.share < 0.05) << f.describe() << " share " << s.share;
  EXPECT_NEAR(s.hybrid_fit_percent, s.physics_fit_percent, 0.5);
  if (f.fir.none()) {
    EXPECT_EQ(s.hybrid_fit_percent, s.physics_fit_percent);
    EXPECT_NE(f.summary.find("no filter"), std::string::npos);
  }
}

TEST(Discrepancy, OptionsOutOfRangeAreInputErrors) {
  DiscrepancyOptions o;
  o.taps = {};
  EXPECT_THROW(o.validate(), InputError);
  o.taps = {0};
  EXPECT_THROW(o.validate(), InputError);
  o.taps = {10};
  o.dt_s = -1;
  EXPECT_THROW(o.validate(), InputError);
}

// ------------------------------------------------------------------ the twin
namespace {
/// The demo study with a body accelerometer and a rough road of 12 s at 15 m/s (both tracks
/// rough, independent).
Study twinStudy() {
  const auto dir = dtwin_test::freshDir("discrepancy_study");
  const auto path = dtwin_test::writeDemoStudy(
      dir / "study.toml",
      "lab_repetitions = 1\n\n"
      "[sensors.seat]\nposition_m = [0.4, -0.35, 0.25]\nquantity = \"acceleration_z\"\n\n"
      "[scenarios.rough_long]\nduration_s = 12.0\nspeed = { v_final_mps = 15.0, ramp_s = 0.0 }\n"
      "road = { type = \"iso8608\", class = \"C\", smooth_until_s = 0.5, band_cycles_per_m = "
      "[0.011, 2.83], dx_m = 0.01, tracks = \"independent\" }\n");
  return loadStudy(path.string());
}

/// One drive of the car with `hidden` switched on (an accelerometer with 0.03 m/s² of noise, 100
/// Hz, the road made with `seed`), and the prediction of the model without it at the study's
/// truth.
struct TwinDrive {
  LabData data;
  RoadInput road;
  std::vector<double> physics;  ///< per record
  std::vector<double> t, p;     ///< the series: times and the physics there
};

TwinDrive twinDrive(const Study& s, const std::string& hidden, std::uint64_t seed) {
  LabOptions o;
  o.scenario = "rough_long";
  o.times_mode = LabTimesMode::All;
  o.window = std::make_pair(1.0, 12.0);
  o.rate_hz = 100.0;
  o.repetitions = 1;
  o.seed = seed;
  o.channels = {"seat_mps2"};
  if (!hidden.empty())
    o.hidden_effects.push_back(parseEffectSetting(hidden, "test", s.effectCatalog()));
  TwinDrive d;
  d.data = generateLab(s, s.assemblies().front(), o).data;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 0.03);
  for (auto& r : d.data.records) r.value += g(rng);
  const calib::DataSet ds{"drive.csv", "rough_long", d.data, seed};
  const calib::LabObjective obj(s, s.assemblies().front(), {ds}, {});
  d.physics = obj.predict(dtwin_test::truthOf(s));
  EXPECT_EQ(d.physics.size(), d.data.records.size());
  d.road = roadInput(s.scenario("rough_long"), obj.model().vehicle(), seed, 0.001, 12.0);
  series(d.data, d.physics, d.t, d.p);
  return d;
}

/// Physics, hybrid and FIR baseline on drive B, the filter and the baseline fitted on drive A.
struct Scores {
  DiscrepancyFilter filter;
  SeriesDiscrepancy hybrid;
  double baseline = 0;
};

Scores score(const TwinDrive& a, const TwinDrive& b) {
  Scores s;
  s.filter = fitDiscrepancy("seat_mps2", {{&a.data, &a.physics, &a.road}});
  s.hybrid = scoreDiscrepancy(s.filter, b.t, b.p, b.data, b.road);
  s.baseline = firFitPercent(fitFirBaseline("seat_mps2", {&a.data}, {&a.road}), b.data, b.road);
  return s;
}

const DiscrepancyBand& bodyBand(const DiscrepancyFilter& f) {
  for (const auto& b : f.bands)
    if (b.band == "body") return b;
  throw std::runtime_error("no body band");
}
}  // namespace

// A feed-forward actuator (G = +2500 N s/m on the road's vertical velocity) the model leaves out.
// At low frequency it adds G s / k to the road's path to the body (hub input: R = 1 + iωG/k), so
// the car responds earlier than the model there.
TEST(DiscrepancyTwin, AHiddenFeedForwardIsPredictedAndReadsEarlier) {
  const Study s = twinStudy();
  const TwinDrive a = twinDrive(s, "road_feedforward:gain=2500", 101),
                  b = twinDrive(s, "road_feedforward:gain=2500", 102);
  const Scores sc = score(a, b);
  ASSERT_FALSE(sc.filter.fir.none()) << sc.filter.describe();
  EXPECT_GT(sc.hybrid.hybrid_fit_percent, sc.hybrid.physics_fit_percent + 5) << sc.filter.summary;
  EXPECT_GE(sc.hybrid.hybrid_fit_percent, sc.baseline);
  const DiscrepancyBand& body = bodyBand(sc.filter);
  EXPECT_TRUE(body.read);
  EXPECT_GT(body.phase_deg, 3.0) << body.words;
  EXPECT_NE(body.words.find("earlier"), std::string::npos) << body.words;
  std::printf(
      "feed-forward: physics %.1f %%, hybrid %.1f %%, FIR %.1f %%, share %.2f\n  %s\n  %s\n",
      sc.hybrid.physics_fit_percent, sc.hybrid.hybrid_fit_percent, sc.baseline, sc.hybrid.share,
      sc.filter.describe().c_str(), sc.filter.summary.c_str());
}

// A skyhook (c_sky = 2500 N s/m) the model leaves out: the body's resonance damped against the
// sky, so less of the road reaches the body in the body band (|R| < 1).
TEST(DiscrepancyTwin, AHiddenSkyhookIsPredictedAndReadsLessGain) {
  const Study s = twinStudy();
  const TwinDrive a = twinDrive(s, "skyhook:damping=2500", 201),
                  b = twinDrive(s, "skyhook:damping=2500", 202);
  const Scores sc = score(a, b);
  ASSERT_FALSE(sc.filter.fir.none()) << sc.filter.describe();
  EXPECT_GT(sc.hybrid.hybrid_fit_percent, sc.hybrid.physics_fit_percent + 5) << sc.filter.summary;
  EXPECT_GE(sc.hybrid.hybrid_fit_percent, sc.baseline);
  const DiscrepancyBand& body = bodyBand(sc.filter);
  EXPECT_TRUE(body.read);
  EXPECT_LT(body.gain, 0.9) << body.words;
  std::printf("skyhook: physics %.1f %%, hybrid %.1f %%, FIR %.1f %%, share %.2f\n  %s\n  %s\n",
              sc.hybrid.physics_fit_percent, sc.hybrid.hybrid_fit_percent, sc.baseline,
              sc.hybrid.share, sc.filter.describe().c_str(), sc.filter.summary.c_str());
}

// The model is right (no hidden controller): the filter is nothing, the hybrid the physics within
// noise.
TEST(DiscrepancyTwin, WhenThePhysicsIsRightTheFilterIsNothing) {
  const Study s = twinStudy();
  const TwinDrive a = twinDrive(s, "", 301), b = twinDrive(s, "", 302);
  const Scores sc = score(a, b);
  EXPECT_TRUE(sc.filter.fir.none() || sc.hybrid.share < 0.05)
      << sc.filter.describe() << " share " << sc.hybrid.share;
  EXPECT_NEAR(sc.hybrid.hybrid_fit_percent, sc.hybrid.physics_fit_percent, 0.5);
  EXPECT_GT(sc.hybrid.physics_fit_percent, sc.baseline);
  std::printf("null: physics %.1f %%, hybrid %.1f %%, FIR %.1f %%, share %.3f\n  %s\n",
              sc.hybrid.physics_fit_percent, sc.hybrid.hybrid_fit_percent, sc.baseline,
              sc.hybrid.share, sc.filter.describe().c_str());
}

// twin compare --discrepancy end to end on the imported demonstration drive, compared at the
// truth without its hidden effect (a calibration folder of one row): the filter fitted on the
// drive itself gives each series a discrepancy object whose in-sample fit is never below the
// physics' (least squares with a ridge never raises the residual it fits), with the FIR baseline
// beside it; a file that does not exist and a drive on a flat road are one-line errors, exit 2.
TEST(DiscrepancyCli, CompareFitsTheFilterAndRefusesBadDrives) {
  namespace fs = std::filesystem;
  const fs::path dir = dtwin_test::freshDir("discrepancy_cli");
  const std::string drive = std::string(DTWIN_SOURCE_DIR) + "/data/drives/";
  auto r = dtwin_test::runTwin("import --log " + drive + "stop_and_go.csv --map " + drive +
                                   "stop_and_go_map.toml --quiet --out " + (dir / "drive").string(),
                               dir);
  ASSERT_EQ(r.code, 0) << r.err;
  fs::create_directories(dir / "cal");
  dtwin_test::writeText(dir / "cal" / "summary.json", R"({"assembly": "M1"})");
  dtwin_test::writeText(
      dir / "cal" / "posterior.csv",
      "tire.stiffness,tire.damping,suspension.stiffness,suspension.damping,tau,design_index\n"
      "180000,3000,30000,2500,1,0\n");
  // A study with a flat road too, and the drive's records on it (no sidecar naming its scenario).
  const std::string study = (dir / "drive" / "study.toml").string();
  dtwin_test::writeText(dir / "drive" / "flat.toml",
                        dtwin_test::slurp(study) +
                            "\n[scenarios.flat]\nduration_s = 60.0\nspeed = { v_final_mps = 10.0, "
                            "ramp_s = 0.0 }\nroad = { type = \"flat\" }\n");
  fs::copy_file(dir / "drive" / "measurements.csv", dir / "flat.csv");
  const std::string data = (dir / "drive" / "measurements.csv").string();
  const std::string base = "compare --study " + study + " --calibration " + (dir / "cal").string() +
                           " --data " + data + " --draws 1 --quiet";
  r = dtwin_test::runTwin(base + " --discrepancy " + (dir / "none.csv").string(), dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("none.csv"), std::string::npos) << r.err;
  r = dtwin_test::runTwin("compare --study " + (dir / "drive" / "flat.toml").string() +
                              " --calibration " + (dir / "cal").string() + " --data " + data +
                              " --draws 1 --quiet --discrepancy " + (dir / "flat.csv").string() +
                              "@flat",
                          dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("no road signal"), std::string::npos) << r.err;
  r = dtwin_test::runTwin(base + " --discrepancy " + data + " --out " + (dir / "out").string(),
                          dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(dtwin_test::slurp(dir / "out" / "compare.json"));
  EXPECT_EQ(j.at("discrepancy").at("data").size(), 1u);
  EXPECT_EQ(j.at("baseline").at("data"), j.at("discrepancy").at("data"))
      << "--discrepancy implies the baseline on its drive";
  ASSERT_FALSE(j.at("series").empty());
  for (const auto& s : j.at("series")) {
    const auto& d = s.at("discrepancy");
    EXPECT_NEAR(d.at("physics_fit_percent").get<double>(), s.at("fit_percent").get<double>(), 1e-9);
    EXPECT_GE(d.at("hybrid_fit_percent").get<double>(),
              d.at("physics_fit_percent").get<double>() - 1e-6)
        << d.dump();
    EXPECT_TRUE(d.at("baseline_fit_percent").is_number()) << d.dump();
    EXPECT_EQ(d.at("hybrid_predicted").size(), s.at("t").size());
    EXPECT_FALSE(d.at("summary").get<std::string>().empty());
  }
  EXPECT_NE(dtwin_test::slurp(dir / "out" / "compare.html").find("what the physics misses"),
            std::string::npos);
}
