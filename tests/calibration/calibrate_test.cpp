// The calibration of an assembly against lab data, end to end on the real twin (small sizes).
#include <gtest/gtest.h>

#include <cstdio>

#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "calibration/calibrate.hpp"
#include "common/errors.hpp"
#include "study/generate.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::calib;

namespace {
const std::string kDemo = std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml";

using dtwin_test::truthOf;
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

namespace {
using dtwin_test::slurp;

CalibrationOptions smallOptions(int threads) {
  CalibrationOptions o;
  o.threads = threads;
  o.optimizer_starts = 2;
  o.optimizer.maxeval = 40;
  o.box.max_evaluations = 12;
  o.lhs_points = 12;
  o.design.round_points = 10;
  o.design.max_rounds = 2;
  o.joint.ridge_steps = 4;
  o.gibbs_iterations = 600;
  o.gibbs_burn_in = 100;
  o.seed = 7;
  return o;
}

struct Fixture {
  Study study = loadStudy(kDemo);
  AssemblySpec assembly = study.assembly("M3");  // Fiala + MacPherson: the cheapest assembly
  LabData data = generateLab(study, study.assemblies().front()).data;
};
}  // namespace

// The same calibration with 1 and 2 threads gives byte-identical posterior and design files.
TEST(Calibrate, ThreadCountDoesNotChangeResults) {
  Fixture f;
  const fs::path dir = fs::temp_directory_path() / "dtwin_calibrate_threads";
  fs::remove_all(dir);
  const auto r1 = calibrateAssembly(f.study, f.assembly, f.data, "lab", smallOptions(1),
                                    (dir / "t1").string(), "x");
  const auto r2 = calibrateAssembly(f.study, f.assembly, f.data, "lab", smallOptions(2),
                                    (dir / "t2").string(), "x");
  for (const char* file :
       {"posterior.csv", "design.csv", "optimum.json", "box.json", "profile.json"})
    EXPECT_EQ(slurp(dir / "t1" / file), slurp(dir / "t2" / file)) << file;
  EXPECT_FALSE(slurp(dir / "t1" / "posterior.csv").empty());
  EXPECT_EQ(r1.posterior.parameters[0].mean, r2.posterior.parameters[0].mean);
  // The region holds the optimum; a design point better than the optimum is reported.
  const double best_design = *std::min_element(r1.sse.begin(), r1.sse.end());
  EXPECT_EQ(r1.toJson()["design"]["better_than_optimum"].get<bool>(), best_design < r1.optimum.sse);
  // The optimum is the best point the calibration evaluated (the optimiser's, or a later stage's
  // below it), and lies inside every profile interval drawn about it.
  EXPECT_LE(r1.optimum.sse, best_design);
  EXPECT_LE(r1.optimum.sse, r1.profile.sse_best);
  for (std::size_t k = 0; k < r1.names.size(); ++k) {
    EXPECT_LE(r1.profile.lower[k], r1.optimum.theta[k]) << r1.names[k];
    EXPECT_GE(r1.profile.upper[k], r1.optimum.theta[k]) << r1.names[k];
  }
  EXPECT_EQ(r1.region.kind, "joint");
  EXPECT_TRUE(r1.region.contains(r1.region.toScaled(r1.optimum.theta)));
  EXPECT_EQ(r1.rounds.rounds.size(),
            3u);  // round 0 and two adaptive rounds (they never settle at these sizes)
  std::vector<double> lo, hi;
  r1.region.boundingBox(lo, hi);
  for (std::size_t k = 0; k < r1.names.size(); ++k) {
    EXPECT_LE(lo[k], r1.optimum.theta[k]);
    EXPECT_GE(hi[k], r1.optimum.theta[k]);
  }
  // summary.json records the region with its axes and the rounds.
  const auto j = nlohmann::json::parse(slurp(dir / "t1" / "summary.json"));
  EXPECT_EQ(j["region"]["kind"], "joint");
  EXPECT_EQ(j["region"]["axes"].size(), r1.names.size());
  EXPECT_EQ(j["design"]["rounds"].size(), 3u);
  // Both 95 % intervals; ci95 is the profile interval (the default), which holds the best
  // evaluated design point.
  EXPECT_EQ(j["interval"], "profile");
  const auto best = std::min_element(r1.sse.begin(), r1.sse.end()) - r1.sse.begin();
  for (std::size_t k = 0; k < r1.names.size(); ++k) {
    const auto& e = j["parameters"][r1.names[k]];
    EXPECT_EQ(e["interval"], "profile");
    EXPECT_EQ(e["ci95"], e["profile95"]);
    EXPECT_EQ(e["credible95"][0].get<double>(), r1.posterior.parameters[k].q025);
    if (r1.sse[static_cast<std::size_t>(best)] <= j["profile"]["threshold"].get<double>()) {
      EXPECT_LE(e["profile95"][0].get<double>(), r1.design(best, static_cast<long>(k)));
      EXPECT_GE(e["profile95"][1].get<double>(), r1.design(best, static_cast<long>(k)));
    }
    EXPECT_EQ(e["truth_in_ci95"], e["truth_in_profile95"]);
  }
  // The profile's threshold rests on the best SSE evaluated anywhere (the optimum, or a design
  // point that beat it: this test's optimiser is cut short at 40 evaluations).
  EXPECT_LE(j["profile"]["sse_best"].get<double>(),
            std::min(j["sse_min"].get<double>(), best_design));
  EXPECT_GT(j["profile"]["threshold"].get<double>(), j["profile"]["sse_best"].get<double>());
  // Along a traced ridge the region reaches margin x the profile's crossing (or the bounds' reach).
  const auto box = nlohmann::json::parse(slurp(dir / "t1" / "box.json"));
  ASSERT_TRUE(box["gauss_newton"].contains("ridges"));
  for (const auto& tr : box["gauss_newton"]["ridges"]) {
    const int i = tr["axis"].get<int>(), s = tr["direction"].get<int>();
    if (!tr["closed"].get<bool>()) continue;
    const double want = std::min(1.25 * tr["crossing"].get<double>(),
                                 s > 0 ? r1.region.reach_upper(i) : r1.region.reach_lower(i));
    EXPECT_GT(tr["crossing"].get<double>(), 0.0);
    EXPECT_GE(s > 0 ? r1.region.t_upper(i) : -r1.region.t_lower(i), want * (1 - 1e-12))
        << "ridge axis " << i << " direction " << s;
  }
  fs::remove_all(dir);
}

// Frozen steps (the default; docs/calibration.md, "A smooth objective"): the starts are
// Levenberg–Marquardt runs, the optimum is polished on its own steps, the accuracy is chosen and
// recorded, and the integrator check measures the roughness and the optimum shift. With adaptive
// steps none of that happens.
TEST(Calibrate, FrozenStepsMakeTheObjectiveSmoothAndTheCheckSaysSo) {
  Fixture f;
  f.assembly = f.study.assembly("M1");
  const fs::path dir = fs::temp_directory_path() / "dtwin_calibrate_frozen";
  fs::remove_all(dir);
  CalibrationOptions o = smallOptions(2);
  ASSERT_EQ(o.steps, "frozen");
  const auto r =
      calibrateAssembly(f.study, f.assembly, f.data, "lab", o, (dir / "frozen").string(), "x");
  const auto opt = nlohmann::json::parse(slurp(dir / "frozen" / "optimum.json"));
  ASSERT_TRUE(opt["steps"]["frozen"].get<bool>());
  EXPECT_EQ(opt["steps"]["frozen_at"].size(), r.names.size());
  ASSERT_FALSE(opt["steps"]["accuracy_choice"].empty());
  EXPECT_GT(opt["steps"]["accuracy_choice"][0]["threshold"].get<double>(), 0.0);
  EXPECT_LE(opt["steps"]["accuracy"].get<double>(), f.study.simulation.accuracy);
  const auto& starts = opt["optimum"]["starts"];
  EXPECT_EQ(starts[0]["status"], "LM");
  EXPECT_EQ(starts[starts.size() - 1]["status"], "LM_POLISH_FROZEN_STEPS");
  EXPECT_EQ(opt["optimum"]["best_start"].get<int>(), static_cast<int>(starts.size()) - 1);
  const auto& c = r.integrator;
  EXPECT_EQ(c.steps, "frozen");
  ASSERT_GT(c.threshold, 0.0);
  // The bump makes wheels touch down and lift off, where the tire force jumps or kinks: the SSE
  // keeps small jumps even with frozen steps (docs/calibration.md), which the check measures.
  EXPECT_LT(c.roughness, c.threshold) << "roughness " << c.roughness;
  EXPECT_GT(c.roughness, 0.0);
  EXPECT_DOUBLE_EQ(c.jitter, c.optimum_shift > 4 * c.shift_floor
                                 ? std::max(c.roughness, c.optimum_shift)
                                 : c.roughness);
  EXPECT_EQ(c.ok, c.jitter < 0.5 * c.threshold);
  // The check takes over the step choice's last probe only when it was made at this optimum and
  // accuracy; its figures are then that probe's.
  // (Here a design point beat the polished optimum, so the check probes on its own.)
  const auto& last = opt["steps"]["accuracy_choice"].back();
  ASSERT_TRUE(last.contains("at"));
  const bool moved = last["at"].get<std::vector<double>>() != r.optimum.theta;
  EXPECT_EQ(c.probes, moved ? "own" : c.probes);
  if (c.probes == "step choice") {
    EXPECT_EQ(last["roughness"].get<double>(), c.roughness);
    EXPECT_EQ(last["optimum_shift"].get<double>(), c.optimum_shift);
  }
  std::printf(
      "[ figures  ] M1 lab, frozen steps: roughness %.3g, optimum shift %.3g (floor %.3g), "
      "threshold %.3g, accuracy %.3g, probes %s\n",
      c.roughness, c.optimum_shift, c.shift_floor, c.threshold, c.accuracy, c.probes.c_str());

  o.steps = "adaptive";
  const auto a =
      calibrateAssembly(f.study, f.assembly, f.data, "lab", o, (dir / "adaptive").string(), "x");
  const auto opt_a = nlohmann::json::parse(slurp(dir / "adaptive" / "optimum.json"));
  EXPECT_FALSE(opt_a["steps"]["frozen"].get<bool>());
  EXPECT_NE(opt_a["optimum"]["starts"][0]["status"], "LM");
  EXPECT_EQ(a.integrator.steps, "adaptive");
  std::printf("[ figures  ] adaptive steps: jitter %.3g, threshold %.3g\n", a.integrator.jitter,
              a.integrator.threshold);
  fs::remove_all(dir);
}

// The integrator check takes over the step choice's last probe only when it would measure the
// same: the same accuracy, a kept try, the same optimum (within a hundredth of a probe step) and
// probe steps within a factor 1.5.
TEST(Calibrate, TheIntegratorCheckTakesOverTheStepChoicesProbeOnlyWhenItWouldRepeatIt) {
  const std::vector<double> lo{0, 100}, up{10, 300}, theta{4, 200}, h{1e-3, 2e-3};
  const nlohmann::json last{
      {"accuracy", 5e-5},  {"at", {4.0, 200.0}},   {"probe_step", {1e-3, 2.2e-3}},
      {"roughness", 0.25}, {"optimum_shift", 1.5}, {"shift_floor", 0.125}};
  const auto taken = takeOverProbe(last, theta, h, 5e-5, lo, up);
  ASSERT_TRUE(taken.has_value());
  EXPECT_EQ(taken->roughness, 0.25);
  EXPECT_EQ(taken->optimum_shift, 1.5);
  EXPECT_EQ(taken->shift_floor, 0.125);
  auto with = [&](const std::vector<double>& th, const std::vector<double>& hh, double acc) {
    return takeOverProbe(last, th, hh, acc, lo, up).has_value();
  };
  EXPECT_TRUE(with({4 + 0.9e-4, 200}, h, 5e-5));    // moved 0.9 % of its probe step
  EXPECT_FALSE(with({4 + 1.1e-4, 200}, h, 5e-5));   // 1.1 %
  EXPECT_FALSE(with(theta, h, 4e-5));               // another accuracy
  EXPECT_TRUE(with(theta, {0.7e-3, 2e-3}, 5e-5));   // the try's step 1.43 times the check's
  EXPECT_FALSE(with(theta, {0.6e-3, 2e-3}, 5e-5));  // 1.67 times
  EXPECT_TRUE(with(theta, {1e-3, 3.2e-3}, 5e-5));   // 0.69 times
  EXPECT_FALSE(with(theta, {1e-3, 3.4e-3}, 5e-5));  // 0.65 times
  nlohmann::json dropped = last;
  dropped["kept"] = false;  // a tighter accuracy that did not halve the shift: undone
  EXPECT_FALSE(takeOverProbe(dropped, theta, h, 5e-5, lo, up).has_value());
  nlohmann::json old = last;
  old.erase("at");  // written before the tries recorded where they probed
  EXPECT_FALSE(takeOverProbe(old, theta, h, 5e-5, lo, up).has_value());
}

// A calibration interrupted during the design stage resumes from its journal and ends with the
// same files as an uninterrupted one; a resume against different inputs is refused.
TEST(Calibrate, InterruptedDesignResumesToIdenticalResults) {
  Fixture f;
  const fs::path dir = fs::temp_directory_path() / "dtwin_calibrate_resume";
  fs::remove_all(dir);
  calibrateAssembly(f.study, f.assembly, f.data, "lab", smallOptions(2), (dir / "whole").string(),
                    "x");
  struct Stop {};
  int seen = 0;
  auto interrupt = [&](const std::string& stage, std::size_t done, std::size_t) {
    if (stage == "design round 1" && done >= 5 && ++seen > 0) throw Stop{};
  };
  EXPECT_THROW(calibrateAssembly(f.study, f.assembly, f.data, "lab", smallOptions(2),
                                 (dir / "cut").string(), "x", interrupt),
               Stop);
  const auto journal = slurp(dir / "cut" / "design_journal.csv");
  EXPECT_FALSE(fs::exists(dir / "cut" / "posterior.csv"));
  const auto r = calibrateAssembly(f.study, f.assembly, f.data, "lab", smallOptions(2),
                                   (dir / "cut").string(), "x");
  EXPECT_GE(r.resumed_points, r.rounds.rounds[0].count + 5);  // all of round 0 and part of round 1
  EXPECT_LT(r.resumed_points, r.design.rows());
  for (const char* file :
       {"posterior.csv", "design.csv", "optimum.json", "box.json", "profile.json"})
    EXPECT_EQ(slurp(dir / "whole" / file), slurp(dir / "cut" / file)) << file;
  // Different data: refused with a clear message, nothing overwritten.
  try {
    calibrateAssembly(f.study, f.assembly, f.data, "lab", smallOptions(2), (dir / "cut").string(),
                      "other data");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different calibration"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// region = "paper" is the paper's procedure: the one-at-a-time box, one Latin hypercube, equal
// design weights.
TEST(Calibrate, PaperRegionIsTheOneAtATimeBox) {
  Fixture f;
  const fs::path dir = fs::temp_directory_path() / "dtwin_calibrate_paper";
  fs::remove_all(dir);
  CalibrationOptions o = smallOptions(2);
  o.region = "paper";
  o.design.adaptive = false;
  const auto r = calibrateAssembly(f.study, f.assembly, f.data, "lab", o, dir.string(), "x");
  EXPECT_EQ(r.region.kind, "paper");
  EXPECT_TRUE(r.region.axes.isIdentity());
  EXPECT_EQ(r.box.sweeps.size(), 2 * r.names.size());
  ASSERT_EQ(r.rounds.rounds.size(), 1u);
  EXPECT_EQ(r.design.rows(), o.lhs_points);
  for (double w : r.rounds.log_weight) EXPECT_EQ(w, 0.0);
  for (Eigen::Index k = 0; k < r.design.rows(); ++k)
    for (std::size_t j = 0; j < r.names.size(); ++j) {
      EXPECT_GE(r.design(k, static_cast<long>(j)),
                r.box.lower[j] - 1e-9 * std::abs(r.box.lower[j]));
      EXPECT_LE(r.design(k, static_cast<long>(j)),
                r.box.upper[j] + 1e-9 * std::abs(r.box.upper[j]));
    }
  const auto j = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(j["options"]["region"], "paper");
  EXPECT_TRUE(j.contains("box"));
  fs::remove_all(dir);
}

// The defaults are typed once (calibration/common.hpp): CalibrationOptions and GibbsOptions agree.
TEST(CalibrationOptions, DefaultsComeFromOnePlace) {
  const CalibrationOptions o;
  const GibbsOptions g = o.gibbsOptions();
  EXPECT_EQ(o.lhs_points, kDefaultLhsPoints);
  EXPECT_EQ(o.optimizer_starts, kDefaultOptimizerStarts);
  EXPECT_EQ(g.iterations, GibbsOptions{}.iterations);
  EXPECT_EQ(g.burn_in, GibbsOptions{}.burn_in);
  EXPECT_EQ(g.a, GibbsOptions{}.a);
  EXPECT_EQ(g.b, GibbsOptions{}.b);
  EXPECT_EQ(o.designOptions().tau_a, AdaptiveDesignOptions{}.tau_a);
  EXPECT_NO_THROW(o.validate());
}

// Bad values are refused naming "<options>.<field>" (common/validate.hpp), nested options included.
TEST(CalibrationOptions, BadValuesNameTheField) {
  auto whereOf = [](const CalibrationOptions& o) {
    try {
      o.validate();
    } catch (const InputError& e) {
      return e.where();
    }
    return std::string("(accepted)");
  };
  const std::vector<std::pair<std::function<void(CalibrationOptions&)>, std::string>> cases = {
      {[](CalibrationOptions& o) { o.threads = -1; }, "calibration.threads"},
      {[](CalibrationOptions& o) { o.optimizer_starts = 0; }, "calibration.optimizer_starts"},
      {[](CalibrationOptions& o) { o.lhs_points = 1; }, "calibration.lhs_points"},
      {[](CalibrationOptions& o) { o.gibbs_iterations = 0; }, "calibration.gibbs_iterations"},
      {[](CalibrationOptions& o) { o.gibbs_burn_in = -1; }, "calibration.gibbs_burn_in"},
      {[](CalibrationOptions& o) { o.gibbs_burn_in = o.gibbs_iterations; },
       "calibration.gibbs_burn_in"},
      {[](CalibrationOptions& o) { o.tau_prior_a = -1; }, "calibration.tau_prior_a"},
      {[](CalibrationOptions& o) { o.tau_prior_b = std::numeric_limits<double>::infinity(); },
       "calibration.tau_prior_b"},
      {[](CalibrationOptions& o) { o.region = "box"; }, "calibration.region"},
      {[](CalibrationOptions& o) { o.interval = "hpd"; }, "calibration.interval"},
      {[](CalibrationOptions& o) { o.polish_step = 0.6; }, "calibration.polish_step"},
      {[](CalibrationOptions& o) { o.steps = "fixed"; }, "calibration.steps"},
      {[](CalibrationOptions& o) { o.optimizer.maxeval = 0; }, "optimizer.maxeval"},
      {[](CalibrationOptions& o) { o.box.growth = 1.0; }, "feasible_box.growth"},
      {[](CalibrationOptions& o) { o.joint.ridge_steps = -1; }, "joint_region.ridge_steps"},
      {[](CalibrationOptions& o) { o.design.max_rounds = -1; }, "design.max_rounds"},
  };
  for (const auto& [spoil, where] : cases) {
    CalibrationOptions o;
    spoil(o);
    EXPECT_EQ(whereOf(o), where);
  }
  CalibrationOptions o;
  o.gibbs_iterations = 100;
  o.gibbs_burn_in = 0;  // no burn-in is allowed
  o.polish_step = 0.01;
  EXPECT_EQ(whereOf(o), "(accepted)");
}

// Lab data that do not fit the scenario are refused with the record named; a time off the
// output grid is accepted (it reads the output interpolated there).
TEST(LabObjective, RejectsTimesOutsideTheScenarioAndAcceptsOffGridTimes) {
  Fixture f;
  LabData d = f.data;
  d.records[3].time_s = 99.0;
  try {
    LabObjective obj(f.study, f.assembly, d, "lab");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("record 4"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("outside scenario"), std::string::npos) << e.what();
  }
  d = f.data;
  d.records[0].time_s = 6.0005;
  EXPECT_NO_THROW(LabObjective(f.study, f.assembly, d, "lab"));
}

// predict() runs without the output grid (ScenarioSpec::grid_output): every record, on the grid or
// off it, is a sample time of the run. Its predictions are the grid path's numbers bit for bit: a
// run with the grid read through read(), grid rows and off-grid samples mixed.
TEST(LabObjective, PredictionsWithoutTheGridAreTheGridsNumbers) {
  Fixture f;
  LabData d;
  const std::vector<std::string> names = {"hub_force_fl_N", "chassis_heave_acc_mps2",
                                          "susp_defl_rr_m"};
  for (int k = 0; k < 300; ++k)
    for (const auto& ch : names)
      d.records.push_back({1, k % 2 ? 5.8 + 0.001 * k : 5.8005 + 0.0025 * k, ch, 0.0});
  LabObjective obj(f.study, f.assembly, d, "lab");
  const auto theta = truthOf(f.study);
  const auto eta = obj.predict(theta);
  const auto runs = obj.runs(theta);
  ASSERT_EQ(eta.size(), d.records.size());
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_GT(runs[0].trace.rows(), 0u);  // runs() keeps the grid
  const auto channels = Simulator::channels(obj.model().sensors());
  for (std::size_t i = 0; i < eta.size(); ++i) {
    const auto it = std::find_if(channels.begin(), channels.end(),
                                 [&](const Channel& c) { return c.name == d.records[i].channel; });
    ASSERT_NE(it, channels.end());
    EXPECT_EQ(eta[i], obj.read(runs[0], i, static_cast<std::size_t>(it - channels.begin())))
        << "record " << i;
  }
}

// Times off the 1 kHz output grid are extra output times of the run, read from the same dense
// output as the grid: the same values as a 2 kHz run (on whose grid they lie) gives, to rounding.
// The integration does not depend on the output rate.
TEST(LabObjective, OffGridTimesMatchAFinerOutputGrid) {
  Fixture f;
  LabData d;
  for (int k = 0; k < 400; ++k)
    for (const char* ch : {"hub_force_fl_N", "chassis_heave_acc_mps2", "susp_defl_rr_m"})
      d.records.push_back(
          {1, 5.8005 + 0.0025 * k, ch, 0.0});  // odd multiples of 0.5 ms: off the 1 kHz grid
  LabObjective coarse(f.study, f.assembly, d, "lab");
  Study fine_study = f.study;
  fine_study.simulation.output_rate_hz = 2000.0;
  LabObjective fine(fine_study, f.assembly, d, "lab");
  const auto a = coarse.predict(truthOf(f.study)), b = fine.predict(truthOf(f.study));
  ASSERT_EQ(a.size(), d.records.size());
  ASSERT_EQ(b.size(), d.records.size());
  double worst[3] = {0, 0, 0}, range_lo[3] = {1e300, 1e300, 1e300},
         range_hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst[i % 3] = std::max(worst[i % 3], std::abs(a[i] - b[i]));
    range_lo[i % 3] = std::min(range_lo[i % 3], b[i]);
    range_hi[i % 3] = std::max(range_hi[i % 3], b[i]);
  }
  for (int c = 0; c < 3; ++c) {
    const double range = range_hi[c] - range_lo[c];
    EXPECT_GT(range, 0.0) << c;
    EXPECT_LT(worst[c], 1e-9 * range)
        << "channel " << c << ": worst " << worst[c] << " of range " << range;
  }
}
