// Full-vehicle checks of the effects: at its off values every registered effect leaves the trace
// the base model's bit for bit; switched on, the effects added for the diagnosis
// (progressive_spring, speed_dependent_tire_stiffness, anti_roll_bar, top_mount_compliance) change
// it in the physically determined direction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/study.hpp"
#include "shipped_study.hpp"
#include "subsystems/effect.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

const Study& paper() { return dtwin_test::shippedStudy("paper"); }

double maxOf(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }
double maxAbsDiff(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}
double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

using dtwin_test::standstill;

/// Runs assembly `id` with `effects` (empty: the base model) on `sc` / road seed `seed`.
RunResult runWith(const std::string& id, const std::vector<EffectSetting>& effects,
                  const ScenarioSpec& sc, std::uint64_t seed = 1) {
  auto model = paper().makeModel(paper().assembly(id), effects);
  Simulator sim(model, paper().simulation);
  auto road = makeRoad(sc, model->vehicle(), seed);
  auto r = sim.run(model->defaultRunValues(), *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r;
}

/// left - right suspension deflection of the front axle.
std::vector<double> frontRollDeflection(const RunResult& r) {
  const auto& l = r.trace.column("susp_defl_fl_m");
  const auto& rr = r.trace.column("susp_defl_fr_m");
  std::vector<double> d(l.size());
  for (std::size_t i = 0; i < l.size(); ++i) d[i] = l[i] - rr[i];
  return d;
}

}  // namespace

// Every registered effect (subsystems/effect.hpp effectRegistry), so a new effect is checked here
// without an edit.
TEST(NewEffects, AtTheirOffValuesTheBumpTraceIsTheBaseModelsBitForBit) {
  const auto& sc = paper().scenario("lab");
  for (const std::string id : {"M1", "M2"}) {
    const auto base = runWith(id, {}, sc);
    for (const auto& name : effectNames()) {
      SCOPED_TRACE(id + " " + name);
      const auto off = runWith(id, {EffectSetting{name, {}}}, sc);
      ASSERT_EQ(off.trace.channels().size(), base.trace.channels().size());
      for (std::size_t c = 0; c < base.trace.channels().size(); ++c)
        EXPECT_EQ(off.trace.column(c), base.trace.column(c))
            << "channel " << base.trace.channels()[c].name;
      EXPECT_EQ(off.stats.steps, base.stats.steps);
    }
  }
}

TEST(NewEffects, ProgressiveSpringRaisesThePeakSpringForceAndLimitsTravel) {
  const auto& sc = paper().scenario("lab");
  const double k3 = 5.0e6;
  const auto base = runWith("M1", {}, sc);
  const auto on = runWith(
      "M1",
      {EffectSetting{"progressive_spring", {{"progressive_spring.stiffness3", k3, "", "test"}}}},
      sc);
  auto model = paper().makeModel(paper().assembly("M1"));
  const double k = model->table().value("suspension.stiffness");
  // The elastic strut force k q + k3 q^3 (the total's peak is the damper's, at the bump's first
  // millisecond, where q is still small).
  auto peakSpringForce = [&](const RunResult& r, double k3v) {
    double peak = 0;
    for (double q : r.trace.column("susp_defl_fl_m"))
      peak = std::max(peak, k * q + k3v * q * q * q);
    return peak;
  };
  EXPECT_GT(peakSpringForce(on, k3), 1.1 * peakSpringForce(base, 0.0))
      << "a progressive spring raises the peak spring force";
  EXPECT_LT(maxOf(on.trace.column("susp_defl_fl_m")), maxOf(base.trace.column("susp_defl_fl_m")))
      << "and limits the compression travel";
  const double peak0 = maxOf(base.trace.column("hub_force_fl_N"));
  EXPECT_GT(maxAbsDiff(on.trace.column("hub_force_fl_N"), base.trace.column("hub_force_fl_N")),
            0.02 * peak0);
}

TEST(NewEffects, SpeedDependentTireStiffnessRaisesTheBumpPeakAndIsAbsentAtRest) {
  const EffectSetting on{"speed_dependent_tire_stiffness",
                         {{"speed_dependent_tire_stiffness.c_v", 0.01, "", "test"}}};
  const auto& sc = paper().scenario("lab");
  const auto base = runWith("M1", {}, sc);
  const auto r = runWith("M1", {on}, sc);
  const double peak0 = maxOf(base.trace.column("hub_force_fl_N")),
               peak1 = maxOf(r.trace.column("hub_force_fl_N"));
  EXPECT_GT(peak1, peak0 * 1.01) << "a stiffer tire at speed raises the bump peak";
  EXPECT_GT(maxAbsDiff(r.trace.column("hub_force_fl_N"), base.trace.column("hub_force_fl_N")),
            0.02 * peak0);
  // At rest the factor is exactly 1: the standstill trace is the base model's.
  const auto rest0 = runWith("M1", {}, standstill(2.0));
  const auto rest1 = runWith("M1", {on}, standstill(2.0));
  EXPECT_EQ(rest1.trace.column("hub_force_fl_N"), rest0.trace.column("hub_force_fl_N"));
}

TEST(NewEffects, AntiRollBarIsInertOnASymmetricBumpAndCouplesIndependentTracks) {
  const EffectSetting arb{"anti_roll_bar",
                          {{"anti_roll_bar.stiffness_front_N_per_m", 30000.0, "", "test"},
                           {"anti_roll_bar.stiffness_rear_N_per_m", 20000.0, "", "test"}}};
  for (const std::string id : {"M1", "M2"}) {
    SCOPED_TRACE(id);
    // The bump spans both tracks: left and right deflect alike and the bar does nothing.
    const auto& lab = paper().scenario("lab");
    const auto base = runWith(id, {}, lab);
    const auto on = runWith(id, {arb}, lab);
    const double peak0 = maxOf(base.trace.column("hub_force_fl_N"));
    EXPECT_LT(maxAbsDiff(on.trace.column("hub_force_fl_N"), base.trace.column("hub_force_fl_N")),
              1e-6 * peak0);
    // Independent class-D tracks: the bar reduces the left/right deflection difference and
    // changes the front-left hub force.
    const auto& field = paper().scenario("field");
    const auto fb = runWith(id, {}, field, 7);
    const auto fo = runWith(id, {arb}, field, 7);
    const double roll0 = rms(frontRollDeflection(fb)), roll1 = rms(frontRollDeflection(fo));
    EXPECT_GT(roll0, 0.0);
    EXPECT_LT(roll1, 0.95 * roll0) << "the bar resists left/right deflection differences";
    EXPECT_GT(maxAbsDiff(fo.trace.column("hub_force_fl_N"), fb.trace.column("hub_force_fl_N")),
              0.02 * maxOf(fb.trace.column("hub_force_fl_N")));
  }
}

TEST(NewEffects, TopMountComplianceChangesTheHubForceAndTendsToTheRigidMount) {
  const auto& sc = paper().scenario("lab");
  for (const std::string id : {"M1", "M2"}) {
    SCOPED_TRACE(id);
    const auto base = runWith(id, {}, sc);
    const double peak0 = maxOf(base.trace.column("hub_force_fl_N"));
    auto with = [&](double C) {
      return runWith(id,
                     {EffectSetting{"top_mount_compliance",
                                    {{"top_mount_compliance.compliance_m_per_N", C, "", "test"}}}},
                     sc);
    };
    // A typical soft mount (k_mount = 2e5 N/m, tau = 12.5 ms): a visible change.
    const auto on = with(5e-6);
    EXPECT_GT(maxAbsDiff(on.trace.column("hub_force_fl_N"), base.trace.column("hub_force_fl_N")),
              0.02 * peak0);
    // A nearly rigid mount (tau = 25 us): the auxiliary state follows c q' closely and the trace
    // approaches the base model's (this checks the state is really integrated).
    const auto stiff = with(1e-8);
    const double d =
        maxAbsDiff(stiff.trace.column("hub_force_fl_N"), base.trace.column("hub_force_fl_N"));
    EXPECT_GT(d, 0.0);
    EXPECT_LT(d, 0.01 * peak0);
  }
}
