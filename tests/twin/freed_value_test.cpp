// Freed vehicle values (AssemblySpec::freed, twin diagnose's "free:" candidates): a fixed value of
// the vehicle file made a run parameter. A run at the file's value is the base model's run bit for
// bit; a run at another value is the run of a model built with that value, bit for bit, whatever
// the Simulator ran before; the static hub forces carry the whole weight with the freed mass.
#include <gtest/gtest.h>

#include <string>

#include "calibration/calibrate.hpp"
#include "common/errors.hpp"
#include "io/study.hpp"
#include "io/vehicle_file.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;
namespace fs = std::filesystem;

namespace {

Study demo() {
  return loadStudy(
      dtwin_test::writeDemoStudy(dtwin_test::freshDir("freed") / "study.toml", "").string());
}

Trace runOf(Simulator& sim, const std::vector<double>& values, const Study& s) {
  const auto& sc = s.scenario("diag_bump");
  const auto road = makeRoad(sc, sim.model().vehicle(), s.seed);
  auto r = sim.run(values, *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r.trace;
}

void expectSame(const Trace& a, const Trace& b) {
  ASSERT_EQ(a.rows(), b.rows());
  for (const char* ch : {"hub_force_fl_N", "hub_force_rr_N", "susp_defl_fl_m", "chassis_heave_m"})
    for (std::size_t i = 0; i < a.rows(); ++i)
      ASSERT_EQ(a.column(ch)[i], b.column(ch)[i]) << ch << " row " << i;
}

}  // namespace

TEST(FreedValue, RunsAreThoseOfAModelBuiltWithTheValue) {
  const Study s = demo();
  AssemblySpec a = s.assemblies().front();
  const auto base = s.makeModel(a);
  a.freed = {"wheel.mass_kg"};
  const auto freed = s.makeModel(a);
  const int slot = freed->slot("wheel.mass_kg");
  ASSERT_GE(slot, 0);
  EXPECT_EQ(freed->runParameterNames().size(), base->runParameterNames().size() + 1);
  Simulator sim_base(base, s.simulation), sim(freed, s.simulation);
  auto values = freed->defaultRunValues();
  const double file = values[static_cast<std::size_t>(slot)];
  EXPECT_DOUBLE_EQ(file, 29.46);
  const Trace at_file = runOf(sim, values, s);
  expectSame(at_file, runOf(sim_base, base->defaultRunValues(), s));

  values[static_cast<std::size_t>(slot)] = 1.2 * file;
  const Trace heavier = runOf(sim, values, s);
  const auto built =
      s.makeModel(s.assemblies().front(), {}, {{"wheel.mass_kg", 1.2 * file, "test", "test"}});
  Simulator sim_built(built, s.simulation);
  expectSame(heavier, runOf(sim_built, built->defaultRunValues(), s));
  EXPECT_NE(heavier.column("hub_force_fl_N")[0], at_file.column("hub_force_fl_N")[0]);

  // Static equilibrium: the four hub forces carry the chassis and the four (heavier) wheels.
  const auto& v = built->vehicle();
  double sum = 0;
  for (const char* c : {"fl", "fr", "rl", "rr"})
    sum += heavier.column(std::string("hub_force_") + c + "_N")[0];
  EXPECT_NEAR(sum, (v.chassis_mass + 4 * 1.2 * file) * v.gravity, 1e-6 * sum);

  // Back to the file's value: the same numbers as the first run (the system is rebuilt again).
  values[static_cast<std::size_t>(slot)] = file;
  expectSame(runOf(sim, values, s), at_file);
}

TEST(FreedValue, LabObjectiveCalibratesAFreedValue) {
  const Study s = demo();
  calib::CalibrationSetup setup;
  setup.freed = {"wheel.mass_kg"};
  CalibratedParameter c;
  c.name = "wheel.mass_kg";
  c.unit = "kg";
  c.lower = 15;
  c.upper = 45;
  setup.extra_calibrated = {c};
  LabData data;
  data.records.push_back({1, 1.0, "hub_force_fl_N", 3000.0});
  const calib::LabObjective obj(s, s.assemblies().front(), {{"d", "diag_bump", data}}, setup);
  ASSERT_EQ(obj.names().back(), "wheel.mass_kg");
  std::vector<double> th;
  for (const auto& p : s.calibrated) th.push_back(*p.truth);
  th.push_back(29.46);
  const double a = obj.predict(th)[0];
  th.back() = 40.0;
  EXPECT_GT(std::abs(obj.predict(th)[0] - a), 1.0);
  // The setup round-trips through summary.json (a calibration folder resumes with it).
  const auto back = calib::CalibrationSetup::fromJson(setup.toJson());
  EXPECT_EQ(back.freed, setup.freed);
  EXPECT_EQ(back.toJson(), setup.toJson());
}

TEST(FreedValue, OnlyFreeableValuesOfTheAssemblyCanBeFreed) {
  const Study s = demo();
  AssemblySpec a = s.assemblies().front();  // MacPherson
  a.freed = {"wheel.mas_kg"};
  try {
    s.makeModel(a);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wheel.mass_kg"), std::string::npos) << e.what();
  }
  a.freed = {"solid_axle.mass_kg"};
  EXPECT_THROW(s.makeModel(a), InputError);
  a.freed = {"wheel.mass_kg", "wheel.mass_kg"};
  EXPECT_THROW(s.makeModel(a), InputError);
}

// Yaw is not a degree of freedom: a freed pitch inertia over its whole ±50 % prior range builds and
// runs, the yaw inertia following it into the triangle inequality (docs/model.md), and the file's
// own values are kept where they already satisfy it.
TEST(FreedValue, APitchInertiaOverItsWholeRangeCarriesTheYawInertiaIntoTheTriangle) {
  EXPECT_EQ(yawInertiaInTriangle(500, 2100, 2300), 2300);  // inside: unchanged
  EXPECT_EQ(yawInertiaInTriangle(500, 3150, 2300), 2650);  // Izz >= Iyy - Ixx
  EXPECT_EQ(yawInertiaInTriangle(500, 1050, 2300), 1550);  // Izz <= Ixx + Iyy
  EXPECT_EQ(yawInertiaInTriangle(2000, 500, 100), 1500);   // Izz >= Ixx - Iyy

  const Study s = demo();
  AssemblySpec a = s.assemblies().front();
  a.freed = {"chassis.pitch_inertia_kgm2"};
  const auto freed = s.makeModel(a);
  EXPECT_EQ(freed->vehicle().izz, 2300);  // the file's 500 / 2100 / 2300 satisfy the inequality
  Simulator sim(freed, s.simulation);
  auto values = freed->defaultRunValues();
  const auto slot = static_cast<std::size_t>(freed->slot("chassis.pitch_inertia_kgm2"));
  const Trace at_file = runOf(sim, values, s);
  for (const double iyy : {1.5 * 2100, 0.5 * 2100}) {
    SCOPED_TRACE(iyy);
    values[slot] = iyy;
    const Trace t = runOf(sim, values, s);  // Simbody refused 3150 with Ixx 500, Izz 2300 before
    ASSERT_GT(t.rows(), 0u);
    EXPECT_NE(t.column("chassis_pitch_rad")[t.rows() / 2],
              at_file.column("chassis_pitch_rad")[t.rows() / 2]);
    EXPECT_EQ(freed->withFreedValues(values)->vehicle().izz, yawInertiaInTriangle(500, iyy, 2300));
  }
}

TEST(FreedValue, InertiasThatNoRigidBodyHasAreRefusedWhereTheyAreWritten) {
  const auto dir = dtwin_test::freshDir("inertia_triangle");
  // In the vehicle file: the file is named.
  std::string vehicle =
      dtwin_test::slurp(fs::path(DTWIN_SOURCE_DIR) / "data" / "vehicle" / "midsize_sedan.toml");
  const std::string from = "yaw_inertia_kgm2 = { value = 2300.0";
  ASSERT_NE(vehicle.find(from), std::string::npos);
  vehicle.replace(vehicle.find(from), from.size(), "yaw_inertia_kgm2 = { value = 3000.0");
  dtwin_test::writeText(dir / "vehicle.toml", vehicle);
  ParameterTable t = declareVehicleParameters(EffectCatalog());
  try {
    loadVehicleFile(t, (dir / "vehicle.toml").string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind((dir / "vehicle.toml").string() +
                          ": the chassis inertias roll 500, pitch 2100 and yaw 3000",
                      0),
              0u)
        << m;
    EXPECT_NE(m.find("triangle inequality"), std::string::npos) << m;
  }
  // In the study's [fixed]: the study and the table are named.
  const auto study = dtwin_test::writeDemoStudy(
      dir / "study.toml", "\n[fixed]\n\"chassis.roll_inertia_kgm2\" = 100.0\n");
  try {
    (void)loadStudy(study.string()).parameterTable();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("study.toml: fixed: the chassis inertias roll 100"),
              std::string::npos)
        << e.what();
  }
}

// The CG's longitudinal position at a fixed wheelbase (free:chassis.cg_x_m): a and b move together,
// so the static axle loads follow in closed form while the axles, and so the road under them, stay.
TEST(FreedValue, TheCgMovesForwardAtAFixedWheelbaseAndTheStaticLoadsFollow) {
  const Study s = demo();
  AssemblySpec a = s.assemblies().front();
  a.freed = {"chassis.cg_x_m"};
  const auto freed = s.makeModel(a);
  const auto base = s.makeModel(s.assemblies().front());
  Simulator sim(freed, s.simulation), sim_base(base, s.simulation);
  auto values = freed->defaultRunValues();
  const auto slot = static_cast<std::size_t>(freed->slot("chassis.cg_x_m"));
  EXPECT_EQ(values[slot], 0.0);
  expectSame(runOf(sim, values, s),
             runOf(sim_base, base->defaultRunValues(), s));  // 0: the file's CG, bit for bit

  values[slot] = 0.08;
  const auto moved = freed->withFreedValues(values);
  const VehicleData& v = moved->vehicle();
  const VehicleData& v0 = base->vehicle();
  EXPECT_DOUBLE_EQ(v.a, v0.a - 0.08);
  EXPECT_DOUBLE_EQ(v.b, v0.b + 0.08);
  EXPECT_DOUBLE_EQ(v.wheelbase(), v0.wheelbase());
  const Trace t = runOf(sim, values, s);
  // Static front axle load: the sprung weight's share b / L plus the two front wheels.
  const double front = t.column("hub_force_fl_N")[0] + t.column("hub_force_fr_N")[0];
  const double expected = v.gravity * (v.chassis_mass * v.b / v.wheelbase() + 2 * v.wheel_mass);
  EXPECT_NEAR(front, expected, 1e-6 * expected);
  const double front0 = v0.gravity * (v0.chassis_mass * v0.b / v0.wheelbase() + 2 * v0.wheel_mass);
  EXPECT_GT(front - front0, 0.9 * v.gravity * v.chassis_mass * 0.08 / v.wheelbase());

  // Outside the wheelbase: refused, naming the value and the rule.
  values[slot] = 2.0;
  try {
    (void)freed->withFreedValues(values);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("puts the CG outside the wheelbase"), std::string::npos)
        << e.what();
  }
}

// A vehicle value can be calibrated like a law value ([[calibrated]]): every model of
// the study frees it, and the objective at a value predicts what a study with that value fixed
// predicts, bit for bit. Bounds that would move the CG off the wheelbase are refused when read.
TEST(FreedValue, AVehicleValueInCalibratedIsCalibratedLikeALawValue) {
  const fs::path dir = dtwin_test::freshDir("freed_calibrated");
  const Study s = loadStudy(
      dtwin_test::writeDemoStudy(dir / "a.toml",
                                 "\n[[calibrated]]\nname = \"chassis.mass_kg\"\nunit = \"kg\"\n"
                                 "lower = 1100\nupper = 1700\ntruth = 1400\n")
          .string());
  ASSERT_EQ(s.calibrated.back().name, "chassis.mass_kg");
  const Study fixed = loadStudy(
      dtwin_test::writeDemoStudy(dir / "b.toml", "\n[fixed]\n\"chassis.mass_kg\" = 1530\n")
          .string());
  LabData data;
  for (int k = 200; k <= 2800; k += 20)
    data.records.push_back({1, k / 1000.0, "hub_force_fl_N", 0.0});
  const std::vector<calib::DataSet> sets{{"d", "diag_bump", data}};
  const calib::LabObjective with(s, s.assemblies().front(), sets, {});
  const calib::LabObjective base(fixed, fixed.assemblies().front(), sets, {});
  ASSERT_EQ(with.names().back(), "chassis.mass_kg");
  auto th = dtwin_test::truthOf(fixed);
  const auto expect = base.predict(th);
  th.push_back(1530);
  EXPECT_EQ(with.predict(th), expect);
  th.back() = 1400;
  EXPECT_NE(with.predict(th), expect);

  try {
    loadStudy(dtwin_test::writeDemoStudy(
                  dir / "c.toml",
                  "\n[[calibrated]]\nname = \"chassis.cg_x_m\"\nlower = -0.2\nupper = 1.6\n")
                  .string());
    FAIL() << "a CG range beyond the front axle was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("calibrated[4]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("between the axles"), std::string::npos) << e.what();
  }
}
