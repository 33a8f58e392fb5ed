// The user-defined effects' four elements (subsystems/user_effect.hpp) in the multibody twin,
// each against a closed form or a built-in effect of the same law:
//   chassis:   a vertical force F at the mass centre, ramped in with t: the static hub forces
//              sum to M g - F, and the front pair carries F b / L less;
//   tire:      a force f on the front tires (front): the front hub force is still the static
//              load, and the law's share gives the law's static deflection at load - f;
//   strut:     a force a·u (u the speed): at constant speed every strut deflects by -a u / k;
//   axle_roll and a strut force in dq: the anti-roll bar's trace, on independent rough tracks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/study.hpp"
#include "shipped_study.hpp"
#include "subsystems/effect.hpp"
#include "subsystems/user_effect.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

/// The paper study, with this file's user-defined effects added as the tests define them.
Study& paper() {
  static Study s = dtwin_test::shippedStudy("paper");
  return s;
}

/// The first MacPherson assembly of the paper study (the closed forms below need independent
/// struts).
AssemblySpec macpherson() {
  for (const auto& a : paper().assemblies())
    if (a.option("suspension") == "macpherson") return a;
  ADD_FAILURE() << "no MacPherson assembly";
  return paper().assemblies().front();
}

/// Adds the definition to the study's catalogue (the same definition again is a no-op).
void define(const std::string& name, const std::string& element, const std::string& force,
            std::vector<UserEffectParameter> params) {
  UserEffectSpec u;
  u.name = name;
  u.element = element;
  u.force = force;
  u.parameters = std::move(params);
  u.where = "user_effect_elements_test: " + name;
  paper().addUserEffects({u});
}

RunResult run(const std::vector<EffectSetting>& effects, const ScenarioSpec& sc,
              std::uint64_t seed = 1) {
  auto model = paper().makeModel(macpherson(), effects);
  Simulator sim(model, paper().simulation);
  auto road = makeRoad(sc, model->vehicle(), seed);
  auto r = sim.run(model->defaultRunValues(), *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r;
}

EffectSetting setting(const std::string& name, const std::string& param, double value) {
  return EffectSetting{name, {{name + "." + param, value, "test", "test"}}};
}

using dtwin_test::standstill;

double last(const RunResult& r, const std::string& channel) {
  return r.trace.column(channel).back();
}

}  // namespace

TEST(UserEffectElements, AChassisForceUnloadsTheTiresByItsStaticShare) {
  define("lift", "chassis", "f0 * min(t / t0, 1)",
         {{"f0", "N", 0, -3000, 3000}, {"t0", "s", 0.5, 0.1, 2, true}});
  const double F = 1500.0;
  const auto r = run({setting("lift", "f0", F)}, standstill(5.0));
  const auto model = paper().makeModel(macpherson(), {});
  const VehicleData& d = model->vehicle();
  const double W = d.total_mass(model->topology()) * d.gravity;
  double sum = 0, front = 0;
  for (const char* c : {"fl", "fr", "rl", "rr"})
    sum += last(r, std::string("hub_force_") + c + "_N");
  for (const char* c : {"fl", "fr"}) front += last(r, std::string("hub_force_") + c + "_N");
  EXPECT_NEAR(sum, W - F, 1e-3 * W);
  EXPECT_NEAR(front, model->staticTireLoad(0) + model->staticTireLoad(1) - F * d.b / d.wheelbase(),
              1e-3 * W);
  // The chassis rises (the force lifts it): heave up.
  EXPECT_GT(last(r, "chassis_heave_m"), 1e-4);
}

TEST(UserEffectElements, AFrontTireForceLeavesTheLoadAndShiftsTheLawsShare) {
  define("front_tire_push", "tire", "f * front", {{"f", "N", 0, -2000, 2000}});
  const double f = 500.0;
  const auto base = run({}, standstill(4.0));
  const auto r = run({setting("front_tire_push", "f", f)}, standstill(4.0));
  const auto model = paper().makeModel(macpherson(), {});
  const auto values = model->defaultRunValues();
  const ParamValues tp(values.data() + model->tireSlots()[0], model->tireSlots().size());
  for (int c : {0, 2}) {
    const std::string name = c == 0 ? "fl" : "rl";
    SCOPED_TRACE(name);
    const double load = model->staticTireLoad(c);
    EXPECT_NEAR(last(r, "hub_force_" + name + "_N"), load, 1e-3 * load);
    // The law carries load - f at the front (the rear tires carry no extra force): the change of
    // deflection from the base run (which settles alike) is the law's static one.
    const double change = c == 0 ? model->tire().calcStaticDeflection(load - f, tp) -
                                       model->tire().calcStaticDeflection(load, tp)
                                 : 0.0;
    const double got = last(r, "tire_defl_" + name + "_m") - last(base, "tire_defl_" + name + "_m");
    EXPECT_NEAR(got, change,
                2e-3 * std::abs(model->tire().calcStaticDeflection(load - f, tp) -
                                model->tire().calcStaticDeflection(load, tp)));
  }
}

TEST(UserEffectElements, ASpeedDependentStrutForceDeflectsEveryStrutByItsStaticShare) {
  define("speed_push", "strut", "a * u", {{"a", "N*s/m", 0, 0, 500}});
  ScenarioSpec sc;
  sc.name = "cruise";
  sc.duration_s = 6.0;
  sc.speed.v_final_mps = 10.0;
  sc.speed.ramp_s = 1.0;
  const double a = 80.0;
  const auto base = run({}, sc);
  const auto r = run({setting("speed_push", "a", a)}, sc);
  const auto model = paper().makeModel(macpherson(), {});
  const double k = model->defaultRunValues()[static_cast<std::size_t>(model->suspensionSlots()[0])];
  ASSERT_EQ(model->strut().name(), "linear");
  for (const char* c : {"fl", "fr", "rl", "rr"}) {
    const std::string ch = std::string("susp_defl_") + c + "_m";
    EXPECT_NEAR(last(r, ch) - last(base, ch), -a * 10.0 / k, 2e-3 * a * 10.0 / k) << c;
  }
}

TEST(UserEffectElements, AxleRollAndAStrutForceInDqAreTheAntiRollBar) {
  define("roll_bar_expr", "axle_roll", "(kf * front + kr * (1 - front)) * dq",
         {{"kf", "N/m", 0, 0, 4e4}, {"kr", "N/m", 0, 0, 4e4}});
  define("roll_bar_strut", "strut", "(kf * front + kr * (1 - front)) * dq",
         {{"kf", "N/m", 0, 0, 4e4}, {"kr", "N/m", 0, 0, 4e4}});
  ScenarioSpec sc = paper().scenario("field");
  sc.duration_s = 9.0;
  const double kf = 20000, kr = 10000;
  const auto builtin =
      run({EffectSetting{"anti_roll_bar",
                         {{"anti_roll_bar.stiffness_front_N_per_m", kf, "t", "t"},
                          {"anti_roll_bar.stiffness_rear_N_per_m", kr, "t", "t"}}}},
          sc);
  const auto base = run({}, sc);
  for (const char* name : {"roll_bar_expr", "roll_bar_strut"}) {
    SCOPED_TRACE(name);
    const std::string n(name);
    const auto r =
        run({EffectSetting{n, {{n + ".kf", kf, "t", "t"}, {n + ".kr", kr, "t", "t"}}}}, sc);
    for (const char* c : {"fl", "fr", "rl", "rr"}) {
      const auto& x = r.trace.column(std::string("hub_force_") + c + "_N");
      const auto& y = builtin.trace.column(std::string("hub_force_") + c + "_N");
      const auto& b = base.trace.column(std::string("hub_force_") + c + "_N");
      ASSERT_EQ(x.size(), y.size());
      double diff = 0, effect = 0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        diff = std::max(diff, std::abs(x[i] - y[i]));
        effect = std::max(effect, std::abs(y[i] - b[i]));
      }
      EXPECT_GT(effect, 50.0) << c << ": the bar must matter on these tracks";
      EXPECT_LT(diff, 1e-3 * effect) << c;
    }
  }
}
