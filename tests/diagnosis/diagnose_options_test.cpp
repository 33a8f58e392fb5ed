// The options of `compare` and `diagnose` (common/validate.hpp): every field out of range is an
// InputError whose where() is "<options>.<field>", checked at the library boundary before any
// simulation; the CLI shows such an error as the flag that sets the field.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "common/errors.hpp"
#include "diagnosis/compare.hpp"
#include "diagnosis/diagnose.hpp"
#include "diagnosis/diagnose_internal.hpp"
#include "io/work.hpp"

using namespace dtwin;
using namespace dtwin::diag;

namespace {
const std::string kDemo = std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml";

/// The where() and rule() of the InputError `f` throws ("" if none).
std::pair<std::string, std::string> inputError(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return {e.where(), e.rule()};
  }
  return {"", ""};
}
}  // namespace

TEST(DiagnoseOptions, DefaultsAreValidAndEveryFieldIsChecked) {
  EXPECT_NO_THROW(DiagnoseOptions().validate());
  const std::vector<std::pair<std::string, std::function<void(DiagnoseOptions&)>>> cases = {
      {"candidates", [](DiagnoseOptions& o) { o.candidates = -1; }},
      {"screen_alpha", [](DiagnoseOptions& o) { o.screen_alpha = 0.0; }},
      {"screen_alpha", [](DiagnoseOptions& o) { o.screen_alpha = 1.0; }},
      {"bic_strong", [](DiagnoseOptions& o) { o.bic_strong = -1.0; }},
      {"ambiguity_log_evidence",
       [](DiagnoseOptions& o) { o.ambiguity_log_evidence = std::nan(""); }},
      {"full_within", [](DiagnoseOptions& o) { o.full_within = -1.0; }},
      {"full_within", [](DiagnoseOptions& o) { o.full_within = std::nan(""); }},
      {"explained_min", [](DiagnoseOptions& o) { o.explained_min = 1.5; }},
      {"lack_of_fit_alpha", [](DiagnoseOptions& o) { o.lack_of_fit_alpha = -0.1; }},
      {"compare_draws", [](DiagnoseOptions& o) { o.compare_draws = 0; }},
      {"threads", [](DiagnoseOptions& o) { o.threads = -2; }},
  };
  for (const auto& [field, spoil] : cases) {
    DiagnoseOptions o;
    spoil(o);
    EXPECT_EQ(inputError([&] { o.validate(); }).first, "diagnose." + field);
  }
}

TEST(DiagnoseOptions, EffectsMustBeKnownAndNamedOnce) {
  DiagnoseOptions o;
  o.effects = {"bump_stop", "bumpstop"};
  EXPECT_NO_THROW(o.validate()) << "an effect's name is the study's to judge";
  // diagnose() judges it against the study's catalogue, before the data are read.
  const Study s = loadStudy(kDemo);
  const std::vector<calib::DataSet> fit(1);
  const auto [where, rule] = inputError([&] {
    diagnose(s, s.assemblies().front(), fit, {}, o, dtwin_test::freshDir("diag_names").string());
  });
  EXPECT_EQ(where, "diagnose.effects");
  EXPECT_EQ(rule.rfind("unknown effect 'bumpstop' (known: ", 0), 0u) << rule;
  EXPECT_NE(rule.find("did you mean 'bump_stop'?"), std::string::npos) << rule;
  o.effects = {};
  o.apply = {"strut_friction", "bump_stop", "strut_friction"};
  const auto [where2, rule2] = inputError([&] { o.validate(); });
  EXPECT_EQ(where2, "diagnose.apply");
  EXPECT_EQ(rule2, "names 'strut_friction' twice");
  // Freed values and sensor models have their own form; what the study and data hold is checked
  // by diagnose (below).
  o.apply = {"free:wheel.mass_kg", "lowpass:hub_force", "delay:hub_force_fl_N"};
  EXPECT_NO_THROW(o.validate());
  o.apply = {"highpass:hub_force"};
  const auto [where3, rule3] = inputError([&] { o.validate(); });
  EXPECT_EQ(where3, "diagnose.apply");
  EXPECT_NE(rule3.find("free:<vehicle value>"), std::string::npos) << rule3;
}

TEST(CompareOptions, DefaultsAreValidAndEveryFieldIsChecked) {
  EXPECT_NO_THROW(CompareOptions().validate());
  const std::vector<std::pair<std::string, std::function<void(CompareOptions&)>>> cases = {
      {"threads", [](CompareOptions& o) { o.threads = -1; }},
      {"window_threshold", [](CompareOptions& o) { o.window_threshold = -4.0; }},
      {"window_merge_s", [](CompareOptions& o) { o.window_merge_s = std::nan(""); }},
      {"window_min_s", [](CompareOptions& o) { o.window_min_s = -1e-3; }},
      {"state_bins", [](CompareOptions& o) { o.state_bins = 0; }},
      {"fitted_parameters", [](CompareOptions& o) { o.fitted_parameters = -1; }},
      {"window_max_merged", [](CompareOptions& o) { o.window_max_merged = 0; }},
      {"window_max_listed", [](CompareOptions& o) { o.window_max_listed = -3; }},
      {"window_listed_share", [](CompareOptions& o) { o.window_listed_share = 0.0; }},
  };
  for (const auto& [field, spoil] : cases) {
    CompareOptions o;
    spoil(o);
    EXPECT_EQ(inputError([&] { o.validate(); }).first, "compare." + field);
  }
}

// Bad input is refused before any simulation, naming the field.
TEST(Diagnose, RefusesNoDataAndAnInstalledEffectByField) {
  Study s = loadStudy(kDemo);
  const AssemblySpec a = s.assemblies().front();
  const std::string out = dtwin_test::freshDir("diag_options").string();
  EXPECT_EQ(inputError([&] { diagnose(s, a, {}, {}, DiagnoseOptions(), out); }).first,
            "diagnose.fit");
  s.effects.push_back(EffectSetting{"bump_stop", {}});
  const std::vector<calib::DataSet> fit(1);  // never read: the catalogue is checked first
  DiagnoseOptions o;
  o.effects = {"bump_stop"};
  const auto [where, rule] = inputError([&] { diagnose(s, a, fit, {}, o, out); });
  EXPECT_EQ(where, "diagnose.effects");
  EXPECT_EQ(rule,
            "'bump_stop' is already installed in assembly " + a.id + " or the study's [effects]");
  o.effects = {};
  o.apply = {"bump_stop"};
  EXPECT_EQ(inputError([&] { diagnose(s, a, fit, {}, o, out); }).first, "diagnose.apply");
}

namespace {
/// `twin diagnose --data <diag_bump lab data> <args>` in a fresh folder `name`, which must exit
/// with code 2; returns its standard error.
std::string failingDiagnose(const std::string& name, const std::string& args) {
  const std::string dir = dtwin_test::freshDir(name).string();
  const std::string twin = DTWIN_TWIN_EXE;
  const std::string data = dir + "/bump.csv";
  EXPECT_EQ(std::system((twin +
                         " generate lab --scenario diag_bump --times all --rate 50 --repetitions 2 "
                         "--channels hub_force_fl_N"
                         " --out " +
                         data + " --quiet")
                            .c_str()),
            0);
  const std::string err = dir + "/err.txt";
  const int st =
      std::system((twin + " diagnose --data " + data + " " + args + " --quiet 2> " + err).c_str());
  EXPECT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 2);
  return dtwin_test::slurp(err);
}
}  // namespace

// A candidate the study or the data do not have is refused before any calibration, naming the flag
// and what is known.
TEST(Diagnose, TheCliRefusesAFreedValueOrChannelGroupItDoesNotHave) {
  std::string text = failingDiagnose("diag_options_free", "--apply free:wheel.mas_kg");
  EXPECT_NE(text.find("twin: error: --apply: unknown fixed value that can be freed in assembly M1 "
                      "'wheel.mas_kg'"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("wheel.mass_kg"), std::string::npos) << text;
  text = failingDiagnose("diag_options_group", "--effects lowpass:seat");
  EXPECT_NE(text.find("--effects: unknown channel group of the fitted data 'seat'"),
            std::string::npos)
      << text;
}

// The CLI shows the field as its flag.
TEST(Diagnose, TheCliNamesTheFlagOfABadField) {
  const std::string text = failingDiagnose("diag_options_cli", "--effects warp_drive");
  EXPECT_NE(text.find("twin: error: --effects: unknown effect 'warp_drive' (known: bump_stop, "),
            std::string::npos)
      << text;
}

namespace {
/// A data set of `reps` repetitions of one channel, sampled at `rate` Hz up to `span` s.
calib::DataSet flatSet(double span, double rate, long reps) {
  calib::DataSet s;
  s.name = "flat";
  s.scenario = "diag_bump";
  for (long r = 1; r <= reps; ++r)
    for (double t = 0; t <= span + 1e-9; t += 1.0 / rate)
      s.data.records.push_back({r, t, "hub_force_fl_N", 0.0});
  return s;
}
}  // namespace

// The work estimates (io/work.hpp) of compare and diagnose follow the sizes that drive them:
// draws × data span for compare; calibrations × (design + optimiser + profile) × span for diagnose.
TEST(DiagnoseWork, EstimatesScaleWithTheSizesThatDriveThem) {
  const auto set = flatSet(2.0, 10.0, 3);
  const StageWork c = estimateCompareWork({set, set}, 30);
  EXPECT_DOUBLE_EQ(c.simulations, 2 * 31.0);
  EXPECT_NEAR(c.simulated_s, 2 * 31.0 * 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(c.memory_bytes, 8.0 * 2 * 31 * static_cast<double>(set.data.records.size()));

  const Study s = loadStudy(kDemo);
  const AssemblySpec a = s.assemblies().front();
  DiagnoseOptions o;
  o.calibration = calib::CalibrationOptions::fromStudy(s);
  auto total = [](const std::vector<StageWork>& w) {
    double t = 0;
    for (const auto& x : w) t += x.simulated_s;
    return t;
  };
  auto stage = [](const std::vector<StageWork>& w, const std::string& name) {
    for (const auto& x : w)
      if (x.stage == name) return x;
    ADD_FAILURE() << "no stage " << name;
    return StageWork{};
  };
  const auto w = estimateDiagnoseWork(s, a, {set}, {}, o);
  ASSERT_EQ(w.size(), 6u);
  EXPECT_GT(stage(w, "diagnose screening").simulations, 0.0);
  // The demo's diagnosis runs without --force; twice the data span, twice the work.
  EXPECT_LT(total(w), WorkLimits().simulated_s);
  EXPECT_NEAR(total(estimateDiagnoseWork(s, a, {flatSet(4.0, 10.0, 3)}, {}, o)), 2 * total(w),
              1e-6 * total(w));
  // Further causes: one more screening and confirmation per cause after the first.
  EXPECT_GT(stage(w, "diagnose further causes").simulations,
            stage(w, "diagnose screening").simulations);
  auto one = o;
  one.causes = 1;
  EXPECT_EQ(
      stage(estimateDiagnoseWork(s, a, {set}, {}, one), "diagnose further causes").simulations,
      0.0);
  // No candidates, no confirmations; each applied effect one more calibration.
  o.candidates = 0;
  EXPECT_EQ(stage(estimateDiagnoseWork(s, a, {set}, {}, o), "diagnose confirm").simulations, 0.0);
  o.apply = {"bump_stop", "strut_friction"};
  EXPECT_GT(stage(estimateDiagnoseWork(s, a, {set}, {}, o), "diagnose apply").simulations,
            stage(w, "diagnose base").simulations / 2);
  // Ten million design points: refused, naming the data and --force.
  o.calibration.lhs_points = 10000000;
  const auto [where, rule] =
      inputError([&] { checkWork(estimateDiagnoseWork(s, a, {set}, {}, o), "--data", false); });
  EXPECT_EQ(where, "--data");
  EXPECT_NE(rule.find("estimated work"), std::string::npos) << rule;
  EXPECT_NE(rule.find("--force"), std::string::npos) << rule;
  EXPECT_NO_THROW(checkWork(estimateDiagnoseWork(s, a, {set}, {}, o), "--data", true));
}

// The CLI refuses such a diagnosis before it starts, in one line, writing nothing.
TEST(DiagnoseWork, TheCliRefusesUnboundedWorkBeforeItStarts) {
  const std::string out = (dtwin_test::freshDir("diag_work_out") / "out").string();
  const std::string text = failingDiagnose("diag_work_cli", "--lhs-points 9000000 --out " + out);
  EXPECT_EQ(text.rfind("twin: error: --data: estimated work ", 0), 0u) << text;
  EXPECT_NE(text.find("pass --force"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A confirmed candidate whose design did not resolve the posterior (importance ESS 1) prints its
// optimum and the profile interval, never a mean ± sd drawn from one design point.
TEST(DiagnoseText, AnUnresolvedPosteriorPrintsTheOptimumNotAMeanAndSd) {
  DiagnosisResult r;
  r.assembly = "M1";
  r.verdict = "none";
  Candidate c;
  c.effect = "lowpass:hub_force";
  c.confirmed = true;
  c.why = "ΔBIC +9.3";
  Figures f;
  f.folder = "out/calibrations/lowpass:hub_force";
  f.integrator.ok = true;
  EffectParameter p;
  p.name = "lowpass:hub_force.time_constant_s";
  p.unit = "s";
  p.mean = 1.005e-4;
  p.sd = 2.6e-18;
  p.optimum = 4.723e-5;
  p.q025 = 0;
  p.q975 = 1.969e-4;
  f.effect_parameters = {p};
  f.importance_ess = 1.0;
  c.fit = f;
  r.candidates = {c};
  std::string t = r.text();
  EXPECT_NE(
      t.find("time_constant_s: optimum 4.723e-05 s  (95 % profile likelihood [0, 0.0001969])"),
      std::string::npos)
      << t;
  EXPECT_NE(t.find("the posterior is not resolved: importance ESS 1.0 < 10"), std::string::npos)
      << t;
  EXPECT_EQ(t.find("2.6e-18"), std::string::npos) << t;  // the meaningless sd is not printed
  r.candidates[0].fit->importance_ess = 250.0;
  t = r.text();
  EXPECT_NE(t.find("time_constant_s = 0.0001005 ± 2.6e-18 s"), std::string::npos) << t;
  EXPECT_EQ(t.find("not resolved"), std::string::npos) << t;
}

namespace {
/// A screened candidate of `kind` with screening score `score` (an option is not screened: p = 1).
dtwin::diag::Candidate screenedCandidate(const std::string& name, const std::string& kind,
                                         double score) {
  dtwin::diag::Candidate c;
  c.effect = name;
  c.kind = kind;
  c.score = score;
  c.p_value = kind == "option" ? 1.0 : 0.0;
  return c;
}
}  // namespace

// The confirmation budget: within the factor of the best score, the best of each kind first, so
// that two mirror images of one cause do not take the slots of a cause of another kind; then the
// others by score; then the best of each kind beyond the factor; options beyond the budget.
TEST(DiagnoseConfirm, TheBudgetGoesToEachKindsBestFirst) {
  using dtwin::diag::Candidate;
  auto cand = screenedCandidate;
  const std::vector<Candidate> cands = {
      cand("free:road.fl_only", "input", 7.0e5), cand("free:road.fr_only", "input", 6.95e5),
      cand("place:seat", "place", 6.9e5),        cand("free:tire.stiffness@fl", "parameter", 5.2e5),
      cand("gain:seat", "sensor", 1.0e5),        cand("tire=hub", "option", 0.0)};
  dtwin::diag::DiagnoseOptions o;
  o.confirm_within = 2.0;
  auto names = [&](const std::vector<std::size_t>& idx) {
    std::vector<std::string> out;
    for (auto i : idx) out.push_back(cands[i].effect);
    return out;
  };
  o.candidates = 2;
  EXPECT_EQ(names(dtwin::diag::chooseConfirmations(cands, o)),
            (std::vector<std::string>{"free:road.fl_only", "place:seat", "tire=hub"}));
  o.candidates = 4;
  EXPECT_EQ(names(dtwin::diag::chooseConfirmations(cands, o)),
            (std::vector<std::string>{"free:road.fl_only", "place:seat", "free:tire.stiffness@fl",
                                      "free:road.fr_only", "tire=hub"}));
  o.candidates = 6;  // every one within the factor, then the sensor model as its kind's best
  EXPECT_EQ(names(dtwin::diag::chooseConfirmations(cands, o)),
            (std::vector<std::string>{"free:road.fl_only", "place:seat", "free:tire.stiffness@fl",
                                      "free:road.fr_only", "gain:seat", "tire=hub"}));
}

// A later round of the budget: the candidates a round before took, and those promising no more
// than the drop a confirmed one achieved, are left out; the factor still counts from the best
// score of all; no candidate beyond the factor and no option is added again.
TEST(DiagnoseConfirm, ALaterRoundTakesTheNextWithinTheFactor) {
  using dtwin::diag::Candidate;
  auto cand = screenedCandidate;
  // Scores as on a car whose controller moves the sensor's fitted place: the sensor model and the
  // widened range screen best, the controllers just behind.
  const std::vector<Candidate> cands = {
      cand("lowpass:seat", "sensor", 1505), cand("widen:chassis.pitch_inertia_kgm2", "range", 1299),
      cand("groundhook", "effect", 1206),   cand("lowpass2:seat", "sensor", 1151),
      cand("skyhook", "effect", 1123),      cand("free:chassis.mass_kg", "parameter", 736),
      cand("tire=hub", "option", 0.0)};
  dtwin::diag::DiagnoseOptions o;
  o.candidates = 2;
  auto names = [&](const std::vector<std::size_t>& idx) {
    std::vector<std::string> out;
    for (auto i : idx) out.push_back(cands[i].effect);
    return out;
  };
  EXPECT_EQ(
      names(dtwin::diag::chooseConfirmations(cands, o)),
      (std::vector<std::string>{"lowpass:seat", "widen:chassis.pitch_inertia_kgm2", "tire=hub"}));
  EXPECT_EQ(names(dtwin::diag::chooseConfirmations(cands, o, {0, 1, 6})),
            (std::vector<std::string>{"groundhook", "lowpass2:seat"}));
  EXPECT_EQ(names(dtwin::diag::chooseConfirmations(cands, o, {0, 1, 2, 3, 6})),
            (std::vector<std::string>{"skyhook"}));
  // Every one within the factor taken: the parameter beyond it (736 < 1505 / 2) is not.
  EXPECT_TRUE(dtwin::diag::chooseConfirmations(cands, o, {0, 1, 2, 3, 4, 6}).empty());
}
