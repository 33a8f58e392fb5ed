// What changed between two calibrations (diagnosis/changes.hpp) against closed forms: Holm's rule
// on known p-values, and, over many synthetic pairs of calibrations whose estimates scatter as
// their printed 95 % intervals say, the change's 95 % interval holds the true change about 95 % of
// the time, a car where nothing changed gets any value named in at most about 5 % of the pairs
// (family-wise), and a damper that lost 45 % is named first.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/statistics.hpp"
#include "diagnosis/changes.hpp"

using namespace dtwin;

namespace {

struct Truth {
  std::string name, unit;
  double value, lower_bound;
  double rel_sd;  ///< the calibration's sd (log scale for positive values, absolute otherwise)
};

/// A calibration folder (summary.json only) whose estimates are the truths scattered by their sd.
calib::CalibrationFolder folder(const std::string& dir, const std::vector<Truth>& truths,
                                std::mt19937_64& rng, bool integrator_ok = true) {
  calib::CalibrationFolder f;
  f.dir = dir;
  f.assembly = "M1";
  std::normal_distribution<double> n01(0, 1);
  const double z = normalQuantile(0.975);
  for (const auto& t : truths) {
    const bool log_scale = t.lower_bound >= 0;
    double x, lo, hi;
    if (log_scale) {
      const double c = std::log(t.value) + t.rel_sd * n01(rng);
      x = std::exp(c), lo = std::exp(c - z * t.rel_sd), hi = std::exp(c + z * t.rel_sd);
    } else {
      x = t.value + t.rel_sd * n01(rng), lo = x - z * t.rel_sd, hi = x + z * t.rel_sd;
    }
    f.summary["parameters"][t.name] = {{"optimum", x}, {"ci95", {lo, hi}}, {"interval", "profile"}};
    f.summary["parameter_order"].push_back(t.name);
    f.summary["units"].push_back(t.unit);
    f.summary["bounds"].push_back({t.lower_bound, 1e9});
  }
  f.summary["integrator_check"] = {{"ok", integrator_ok}};
  return f;
}

std::vector<Truth> sedan(double damping) {
  return {{"tire.stiffness", "N/m", 180000, 120000, 0.02},
          {"tire.damping", "N*s/m", 3000, 500, 0.05},
          {"suspension.stiffness", "N/m", 30000, 10000, 0.01},
          {"suspension.damping", "N*s/m", damping, 500, 0.015},
          {"sensors.seat.offset_mps2", "m/s^2", 0.02, -1, 0.004}};
}

}  // namespace

TEST(Changes, HolmStepsDownAndStopsAtTheFirstAcceptance) {
  // m = 3, level 0.05: 0.01 <= 0.05/3 rejected; 0.03 > 0.05/2 accepted, so 0.04 is accepted too.
  EXPECT_EQ(diag::holmRejections({0.01, 0.04, 0.03}, 0.05),
            (std::vector<bool>{true, false, false}));
  // 0.001 <= 0.0167, 0.02 <= 0.025, 0.04 <= 0.05: all three.
  EXPECT_EQ(diag::holmRejections({0.04, 0.001, 0.02}, 0.05), (std::vector<bool>{true, true, true}));
  EXPECT_EQ(diag::holmRejections({}, 0.05), std::vector<bool>{});
}

TEST(Changes, IntervalsHoldTheTruthAndNothingIsNamedOnAnUnchangedCar) {
  std::mt19937_64 rng(20261129);
  const int pairs = 2000;
  int held = 0, values = 0, false_alarm_pairs = 0, damper_first = 0, damper_significant = 0;
  for (int k = 0; k < pairs; ++k) {
    // An unchanged car: every change interval should hold 1 (or 0), and Holm names nothing in >= 95
    // %.
    const auto a = folder("drive1", sedan(2500), rng), b = folder("drive2", sedan(2500), rng);
    const auto r = diag::compareCalibrations(a, b);
    ASSERT_EQ(r.changes.size(), 5u);
    if (r.significantCount() > 0) ++false_alarm_pairs;
    for (const auto& c : r.changes) {
      ++values;
      const double truth = c.ratio ? 1.0 : 0.0;
      if (c.lo <= truth && truth <= c.hi) ++held;
    }
    // The same car with the dampers at 55 %: named first, significant; its interval holds 0.55.
    const auto w = folder("drive2", sedan(1375), rng);
    const auto rw = diag::compareCalibrations(a, w);
    if (rw.changes.front().name == "suspension.damping") ++damper_first;
    for (const auto& c : rw.changes)
      if (c.name == "suspension.damping" && c.significant) ++damper_significant;
  }
  // Binomial: 95 % of 10 000 values, sd 0.22 %; 5 % of 2000 pairs, sd 0.49 %.
  const double coverage = static_cast<double>(held) / values;
  std::printf(
      "change intervals holding the truth: %d of %d (%.2f %%); unchanged pairs with a value named: "
      "%d of %d\n",
      held, values, 100 * coverage, false_alarm_pairs, pairs);
  EXPECT_NEAR(coverage, 0.95, 0.01) << held << " of " << values;
  EXPECT_LE(static_cast<double>(false_alarm_pairs) / pairs, 0.05 + 0.015)
      << false_alarm_pairs << " of " << pairs;
  EXPECT_EQ(damper_first, pairs);
  EXPECT_EQ(damper_significant, pairs);
}

TEST(Changes, RatiosForPositiveValuesDifferencesOtherwiseAndTheSentence) {
  std::mt19937_64 rng(7);
  auto truths = sedan(2500);
  for (auto& t : truths) t.rel_sd = 1e-9;  // exact estimates
  const auto a = folder("a", truths, rng);
  truths[3].value = 1375;
  truths[4].value = 0.05;
  const auto b = folder("b", truths, rng);
  const auto r = diag::compareCalibrations(a, b);
  ASSERT_EQ(r.significantCount(), 2u);
  const auto& d = r.changes[0].name == "suspension.damping" ? r.changes[0] : r.changes[1];
  EXPECT_TRUE(d.ratio);
  EXPECT_NEAR(d.change, 0.55, 1e-6);
  EXPECT_NE(d.sentence.find("suspension.damping fell to 0.55 x its first value"), std::string::npos)
      << d.sentence;
  EXPECT_NE(d.sentence.find("; significant"), std::string::npos) << d.sentence;
  const auto& o = r.changes[0].name == "suspension.damping" ? r.changes[1] : r.changes[0];
  EXPECT_EQ(o.name, "sensors.seat.offset_mps2");
  EXPECT_FALSE(o.ratio);
  EXPECT_NEAR(o.change, 0.03, 1e-6);
  for (std::size_t i = 2; i < r.changes.size(); ++i)
    EXPECT_FALSE(r.changes[i].significant) << r.changes[i].name;
  const auto j = r.toJson();
  EXPECT_EQ(j["significant"], 2);
  EXPECT_EQ(j["changes"][0]["significant"], true);
}

TEST(Changes, UntrustedIntervalsAndValuesInOneFolderOnlyAreSaid) {
  std::mt19937_64 rng(3);
  auto truths = sedan(2500);
  const auto a = folder("a", truths, rng);
  truths.pop_back();
  truths.push_back({"bump_stop.stiffness", "N/m^n", 5e6, 0, 0.1});
  const auto b = folder("b", truths, rng, false);
  const auto r = diag::compareCalibrations(a, b);
  EXPECT_EQ(r.changes.size(), 4u);
  EXPECT_EQ(r.only_first, std::vector<std::string>{"sensors.seat.offset_mps2"});
  EXPECT_EQ(r.only_second, std::vector<std::string>{"bump_stop.stiffness"});
  for (const auto& c : r.changes) {
    EXPECT_FALSE(c.trusted);
    EXPECT_NE(c.sentence.find("not to be trusted"), std::string::npos);
  }
  EXPECT_NE(r.text().find("calibrated only in the second: bump_stop.stiffness"), std::string::npos);
}

TEST(Changes, AMalformedSummaryNamesTheFieldAndALevelOutsideItsRangeIsRefused) {
  std::mt19937_64 rng(1);
  auto a = folder("cal_a", sedan(2500), rng);
  const auto b = folder("cal_b", sedan(2500), rng);
  a.summary["parameters"]["tire.damping"]["ci95"] = {1.0};
  try {
    diag::compareCalibrations(a, b);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "cal_a/summary.json: parameters.tire.damping.ci95");
  }
  EXPECT_THROW(diag::compareCalibrations(b, b, 0.7), InputError);
}

// An optimum outside its own interval (the profile search met a better fit in a flat valley): the
// interval's centre is compared, which the interval was built around, and the sentence says so.
TEST(Changes, AnOptimumOutsideItsIntervalIsReplacedByTheIntervalsCentre) {
  calib::CalibrationFolder a, b;
  a.dir = "a";
  b.dir = "b";
  a.assembly = b.assembly = "M1";
  for (auto* f : {&a, &b}) {
    f->summary["parameter_order"] = {"suspension.stiffness"};
    f->summary["units"] = {"N/m"};
    f->summary["bounds"] = {{10000, 1e9}};
  }
  a.summary["parameters"]["suspension.stiffness"] = {{"optimum", 30000.0},
                                                     {"ci95", {29600.0, 30400.0}}};
  b.summary["parameters"]["suspension.stiffness"] = {
      {"optimum", 28500.0}, {"ci95", {29600.0, 30400.0}}};  // optimum outside
  const auto r = dtwin::diag::compareCalibrations(a, b);
  ASSERT_EQ(r.changes.size(), 1u);
  const auto& c = r.changes[0];
  EXPECT_FALSE(c.first.centred);
  EXPECT_TRUE(c.second.centred);
  EXPECT_DOUBLE_EQ(c.second.estimate, std::sqrt(29600.0 * 30400.0));
  EXPECT_FALSE(c.significant);  // the optimum alone would read 0.95 x, z = -5.2
  EXPECT_NEAR(c.change, std::sqrt(29600.0 * 30400.0) / 30000.0, 1e-12);
  EXPECT_NE(c.sentence.find("the second calibration's optimum lies outside its interval"),
            std::string::npos)
      << c.sentence;
}
