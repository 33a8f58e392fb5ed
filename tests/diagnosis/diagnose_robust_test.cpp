// A diagnosis never dies of one candidate (docs/diagnosis.md, "When a candidate fails"):
//  * a structure option that leaves out calibrated values (tire=hub: no tire stiffness nor damping)
//    is confirmed with held-out data, and a later stage on top of it screens a candidate of the
//    values it left out (a tire's factor): that candidate is gated as absent from the model, not
//    simulated with a θ of the other size;
//  * a failure injected into one candidate (DiagnoseOptions::before_candidate_step) is reported
//    with that candidate and in diagnosis.json, and the run finishes with the others.
// On a car whose road enters at the hub and whose struts carry a skyhook controller (the demo
// sedan's study with the tire options pac2002 and hub), diagnosed from the sedan's tire model;
// small sizes (label slow: about three minutes together on 2 cores).
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <algorithm>
#include <filesystem>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "diagnosis/diagnose.hpp"
#include "io/measurement.hpp"
#include "study/diagnose.hpp"
#include "study/generate.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::diag;

namespace {

/// The demo study with the tire options pac2002 (M1) and hub (M2) on MacPherson struts.
Study hubStudy() {
  static const fs::path p = [] {
    const fs::path path =
        fs::temp_directory_path() / ("diag_robust_study_" + std::to_string(::getpid()) + ".toml");
    dtwin_test::writeDemoStudy(path, "lab_repetitions = 3\noptimizer_starts = 1\n");
    std::string t = dtwin_test::slurp(path);
    t = std::regex_replace(t, std::regex("tire = \\[[^\\]]*\\]"), "tire = [\"pac2002\", \"hub\"]");
    t = std::regex_replace(t, std::regex("suspension = \\[[^\\]]*\\]"),
                           "suspension = [\"macpherson\"]");
    dtwin_test::writeText(path, t);
    return path;
  }();
  return loadStudy(p.string());
}

/// Lab data of M2 (the hub input) with a skyhook controller on `scenario`: 4 hub forces at 200 Hz,
/// 3 repetitions, the noise and the rough road of seed study seed + first_repetition.
calib::DataSet hubData(const Study& s, const std::string& scenario, long first_repetition = 1) {
  LabOptions l;
  l.scenario = scenario;
  l.times_mode = LabTimesMode::All;
  l.rate_hz = 200.0;
  l.repetitions = 3;
  l.seed = s.seed + static_cast<std::uint64_t>(first_repetition);
  l.channels = {"hub_force_fl_N", "hub_force_fr_N", "hub_force_rl_N", "hub_force_rr_N"};
  l.hidden_effects.push_back(parseEffectSetting("skyhook:damping=3000", "test", s.effectCatalog()));
  return {scenario + ".csv", scenario, generateLab(s, s.assembly("M2"), l).data, l.seed};
}

/// Small sizes: one Latin hypercube of the paper's region, two profile points per end.
DiagnoseOptions tinyOptions(const Study& s) {
  DiagnoseOptions o;
  o.calibration = calib::CalibrationOptions::fromStudy(s);
  o.calibration.lhs_points = 20;
  o.calibration.gibbs_iterations = 800;
  o.calibration.gibbs_burn_in = 200;
  o.calibration.optimizer_starts = 1;
  o.calibration.profile.restarts = 0;
  o.calibration.profile.polish_iterations = 0;
  o.calibration.region = "paper";
  o.calibration.design.adaptive = false;
  o.calibration.profile.steps = 2;
  o.compare_draws = 5;
  o.propose_terms = 0;
  return o;
}

const Candidate* find(const std::vector<Candidate>& cands, const std::string& name) {
  for (const auto& c : cands)
    if (c.effect == name) return &c;
  return nullptr;
}

}  // namespace

// tire=hub leaves out the calibrated tire.stiffness and tire.damping: it is confirmed in full and
// compared on the held-out data with θ of its own size, and on top of it (the next stage) a
// tire's factor, which this model lacks, is gated, not screened with a θ of the other size.
TEST(DiagnoseRobust, AnOptionThatLeavesOutCalibratedValuesIsConfirmedWithAHoldoutAndBuiltOn) {
  const Study s = hubStudy();
  const std::vector<calib::DataSet> fit{hubData(s, "diag_bump"), hubData(s, "diag_rough")};
  const std::vector<calib::DataSet> hold{hubData(s, "diag_bump", 4)};
  auto o = tinyOptions(s);
  o.effects = {"tire=hub", "free:tire.stiffness@fl"};
  o.candidates = 0;  // the option alone is confirmed (beyond the budget)
  o.causes = 2;
  DiagnosisResult r;
  ASSERT_NO_THROW(r = diagnose(s, s.assembly("M1"), fit, hold, o,
                               dtwin_test::freshDir("diag_robust_hub").string()));
  const Candidate* hub = find(r.candidates, "tire=hub");
  ASSERT_NE(hub, nullptr) << r.text();
  EXPECT_TRUE(hub->failed.empty()) << hub->failed;
  ASSERT_TRUE(hub->confirmed) << r.text();
  ASSERT_TRUE(hub->fit);
  EXPECT_TRUE(hub->fit->full);
  EXPECT_EQ(hub->fit->left_out, (std::vector<std::string>{"tire.stiffness", "tire.damping"}));
  EXPECT_EQ(hub->fit->parameters, 2);  // the suspension's stiffness and damping
  ASSERT_TRUE(hub->fit->holdout) << "compared on the held-out data";
  EXPECT_TRUE(hub->holdout_change);
  // The hub input explains most of the residual, and the skyhook it lacks leaves a lack of fit:
  // the next stage is built on it.
  ASSERT_NE(r.verdict, "none") << r.text();
  ASSERT_FALSE(r.causes.empty()) << r.text();
  EXPECT_EQ(r.causes.front().name, "tire=hub") << r.text();
  ASSERT_FALSE(r.further.empty()) << r.text();
  EXPECT_EQ(r.further.front().installed, std::vector<std::string>{"tire=hub"});
  const Candidate* factor = find(r.further.front().candidates, "free:tire.stiffness@fl");
  ASSERT_NE(factor, nullptr) << r.text();
  EXPECT_TRUE(factor->failed.empty()) << factor->failed;
  EXPECT_EQ(factor->gate, "this model has no tire.stiffness@fl (tire=hub leaves it out)")
      << r.text();
  EXPECT_FALSE(factor->confirmed);
  EXPECT_TRUE(r.failures.empty()) << r.text();
}

// An internal error injected into one candidate's comparison: that candidate is reported as
// failed with its reason (the verdict's table, diagnosis.json), every other candidate is
// screened and confirmed, the verdict is made without it, and diagnosis.json and the finished
// calibration folders are written.
TEST(DiagnoseRobust, ACandidateThatThrowsIsReportedAndTheRunGoesOn) {
  const Study s = hubStudy();
  const std::string dir = dtwin_test::freshDir("diag_robust_inject").string();
  const std::vector<calib::DataSet> sets{hubData(s, "diag_bump"), hubData(s, "diag_bump", 4)};
  for (std::size_t k = 0; k < sets.size(); ++k)
    dtwin_test::writeText(dir + "/data" + std::to_string(k) + ".csv",
                          labCsvText(sets[k].data, measurableChannels(s.sensors)));
  DiagnoseRequest request;
  request.assembly = "M1";
  request.data = {dir + "/data0.csv@diag_bump"};
  request.holdout = {dir + "/data1.csv@diag_bump"};
  request.out = dir + "/out";
  request.options = tinyOptions(s);
  request.options.effects = {"tire=hub", "skyhook"};
  request.options.candidates = 1;
  request.options.causes = 1;
  std::vector<std::string> steps;  // every step the seam saw, in order
  request.options.before_candidate_step = [&](const std::string& model, const std::string& step) {
    steps.push_back(model + " " + step);
    if (model == "tire=hub" && step == "compare")
      throw std::logic_error(
          "internal error: injected [false] (tests/diagnosis/diagnose_robust_test.cpp:1)");
  };
  DiagnoseRun run;
  ASSERT_NO_THROW(run = diagnoseMeasurements(s, request));
  const DiagnosisResult& r = run.result;
  EXPECT_NE(std::find(steps.begin(), steps.end(), "skyhook screen"), steps.end());
  EXPECT_NE(std::find(steps.begin(), steps.end(), "tire=hub optimum"), steps.end());
  const Candidate* hub = find(r.candidates, "tire=hub");
  ASSERT_NE(hub, nullptr) << r.text();
  EXPECT_EQ(hub->failed,
            "its confirming calibration failed: internal error: injected [false] "
            "(tests/diagnosis/diagnose_robust_test.cpp:1)")
      << r.text();
  EXPECT_FALSE(hub->confirmed);
  EXPECT_FALSE(hub->fit);
  EXPECT_NE(r.text().find("tire=hub: failed, left out of the verdict: its confirming calibration "
                          "failed: internal error: injected"),
            std::string::npos)
      << r.text();
  // The other candidate went through its screening (and, within the budget, its confirmation).
  const Candidate* sky = find(r.candidates, "skyhook");
  ASSERT_NE(sky, nullptr);
  EXPECT_TRUE(sky->failed.empty()) << sky->failed;
  EXPECT_GT(sky->score, 0.0);
  for (const auto& k : r.causes) EXPECT_NE(k.name, "tire=hub") << r.text();
  // diagnosis.json lists it with its reason, and the calibrations that finished are kept.
  ASSERT_EQ(run.written, request.out + "/diagnosis.json");
  const auto j = nlohmann::json::parse(dtwin_test::slurp(run.written));
  ASSERT_EQ(j.at("failed").size(), 1u) << j.at("failed").dump();
  EXPECT_EQ(j.at("failed")[0].at("candidate"), "tire=hub");
  EXPECT_EQ(j.at("failed")[0].at("reason"), hub->failed);
  bool listed = false;
  for (const auto& c : j.at("screening"))
    if (c.at("effect") == "tire=hub") listed = c.value("failed", "") == hub->failed;
  EXPECT_TRUE(listed) << j.at("screening").dump();
  EXPECT_TRUE(fs::exists(request.out + "/calibrations/base/summary.json"));
  EXPECT_TRUE(fs::exists(request.out + "/calibrations/tire=hub/optimum.json"))
      << "the optimum it reached is kept";
  EXPECT_TRUE(fs::exists(request.out + "/comparisons/base.json"));
}
