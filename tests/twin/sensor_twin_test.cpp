// Sensors on the twin ([sensors.NAME]): each channel is the motion its mounting point has in the
// run, filtered as declared, read at off-grid times like any channel; bad tables name the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "calibration/calibrate.hpp"
#include "common/errors.hpp"
#include "io/study.hpp"
#include "study/generate.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;
namespace fs = std::filesystem;

namespace {

const char* kSensors = R"(
[sensors.cg]
quantity = "acceleration_z"

[sensors.cg_pos]
quantity = "displacement_z"

[sensors.seat]
position_m = [0.9, -0.4, 0.3]
quantity = "acceleration_z"
noise_sd = 0.05

[sensors.seat_lp]
position_m = [0.9, -0.4, 0.3]
quantity = "acceleration_z"
filter = { order = 2, cutoff_hz = 15.0 }

[sensors.hub_rl]
body = "wheel_rl"
quantity = "displacement_z"

[sensors.hub_rl_v]
body = "wheel_rl"
quantity = "velocity_z"

[sensors.hub_rl_a]
body = "wheel_rl"
quantity = "acceleration_z"
)";

Study sensorStudy(const std::string& name, const std::string& extra = kSensors) {
  const fs::path dir = dtwin_test::freshDir(name);
  return loadStudy(
      dtwin_test::writeDemoStudy(dir / "study.toml", "lab_repetitions = 2\n" + extra).string());
}

std::string errorOf(const std::string& name, const std::string& extra) {
  try {
    sensorStudy(name, extra);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

RunResult roughRun(const Study& s) {
  const auto model = s.makeModel(s.assemblies().front());
  Simulator sim(model, s.simulation);
  const ScenarioSpec& sc = s.scenario("diag_rough");
  const auto road = makeRoad(sc, model->vehicle(), s.seed);
  auto r = sim.run(model->defaultRunValues(), *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r;
}

double range(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
}

}  // namespace

// At the centre of mass the sensors read the chassis heave channels; off it, the rigid-body
// combination heave − x·pitch + y·roll (exact at level attitude; the angles here are small).
TEST(SensorTwin, ChassisSensorsAreTheMotionOfTheirPoint) {
  const Study s = sensorStudy("sensor_chassis");
  const Trace tr = roughRun(s).trace;
  EXPECT_EQ(tr.column("cg_mps2"), tr.column("chassis_heave_acc_mps2"));
  const auto &pos = tr.column("cg_pos_m"), &heave = tr.column("chassis_heave_m");
  for (std::size_t i = 0; i < pos.size(); ++i) ASSERT_NEAR(pos[i], heave[i], 1e-12) << i;
  const auto& seat = tr.column("seat_mps2");
  const auto &h = tr.column("chassis_heave_acc_mps2"), &p = tr.column("chassis_pitch_acc_radps2"),
             &r = tr.column("chassis_roll_acc_radps2");
  double worst = 0.0;
  for (std::size_t i = 0; i < seat.size(); ++i)
    worst = std::max(worst, std::abs(seat[i] - (h[i] - 0.9 * p[i] - 0.4 * r[i])));
  EXPECT_GT(range(seat), 1.0);
  EXPECT_LT(worst, 0.01 * range(seat));
  // The rigid-body terms matter: the seat is not the centre of mass.
  double differ = 0.0;
  for (std::size_t i = 0; i < seat.size(); ++i) differ = std::max(differ, std::abs(seat[i] - h[i]));
  EXPECT_GT(differ, 0.1 * range(seat));
}

// A wheel sensor's velocity and acceleration are the time derivatives of its displacement.
TEST(SensorTwin, WheelSensorsAreConsistentDerivatives) {
  const Study s = sensorStudy("sensor_wheel");
  const Trace tr = roughRun(s).trace;
  const auto &z = tr.column("hub_rl_m"), &v = tr.column("hub_rl_v_mps"),
             &a = tr.column("hub_rl_a_mps2");
  EXPECT_EQ(z.front(), 0.0);
  const double h = 1e-3;
  double worst_v = 0.0, worst_a = 0.0;
  for (std::size_t i = 1; i + 1 < z.size(); ++i) {
    worst_v = std::max(worst_v, std::abs((z[i + 1] - z[i - 1]) / (2 * h) - v[i]));
    worst_a = std::max(worst_a, std::abs((v[i + 1] - v[i - 1]) / (2 * h) - a[i]));
  }
  EXPECT_GT(range(v), 0.05);
  EXPECT_LT(worst_v, 0.02 * range(v));
  EXPECT_LT(worst_a, 0.05 * range(a));
}

// A string potentiometer on a MacPherson corner reads the strut's deflection from its start
// (compression positive), and its rate the strut's rate; filtered, the same through its filter.
TEST(SensorTwin, TravelSensorsReadTheStrutDeflection) {
  const Study s = sensorStudy("sensor_travel", R"(
[sensors.pot_fl]
body = "wheel_fl"
quantity = "travel"

[sensors.pot_rr]
body = "wheel_rr"
quantity = "travel"

[sensors.pot_rr_v]
body = "wheel_rr"
quantity = "travel_rate"

[sensors.pot_fl_lp]
body = "wheel_fl"
quantity = "travel"
filter = { order = 1, cutoff_hz = 30.0 }
)");
  const Trace tr = roughRun(s).trace;
  for (const char* c : {"fl", "rr"}) {
    const auto& pot = tr.column(std::string("pot_") + c + "_m");
    const auto& q = tr.column(std::string("susp_defl_") + c + "_m");
    EXPECT_EQ(pot.front(), 0.0);
    EXPECT_GT(range(pot), 0.005) << c;
    double worst = 0.0;
    for (std::size_t i = 0; i < pot.size(); ++i)
      worst = std::max(worst, std::abs(pot[i] - (q[i] - q.front())));
    EXPECT_LT(worst, 1e-7 * range(pot)) << c;  // the trigonometric round trip of a 0.3 m height
  }
  const auto &v = tr.column("pot_rr_v_mps"), &qd = tr.column("susp_rate_rr_mps");
  double worst_v = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) worst_v = std::max(worst_v, std::abs(v[i] - qd[i]));
  EXPECT_LT(worst_v, 1e-7 * range(v));
  EXPECT_EQ(tr.column("pot_fl_lp_m"), lowPass(tr.column("pot_fl_m"), 1000.0, {1, 30.0}));
}

// At rest on a flat road the travel stays at 0 (it counts from the start).
TEST(SensorTwin, TravelIsZeroAtRestUnderTheStaticLoad) {
  const Study s = sensorStudy("sensor_travel_rest", R"(
[sensors.pot_rl]
body = "wheel_rl"
quantity = "travel"
)");
  const auto model = s.makeModel(s.assemblies().front());
  Simulator sim(model, s.simulation);
  ScenarioSpec sc = s.scenario("diag_rough");
  sc.duration_s = 0.5;
  sc.speed.v_final_mps = 0.0;  // standing still
  sc.speed.trace.reset();
  const auto road = makeRoad(s.scenario("diag_bump"), model->vehicle(), s.seed);
  const auto r = sim.run(model->defaultRunValues(), *road, sc);
  ASSERT_TRUE(r.stats.ok) << r.stats.message;
  // A few micrometres at most (the start's equilibrium is solved for the body, the struts then
  // breathe by about 1 µm), and exactly what the strut's own deflection does.
  const auto& q = r.trace.column("susp_defl_rl_m");
  const auto& pot = r.trace.column("pot_rl_m");
  for (std::size_t i = 0; i < pot.size(); ++i) {
    ASSERT_NEAR(pot[i], 0.0, 1e-5);
    ASSERT_NEAR(pot[i], q[i] - q[0], 1e-12);
  }
}

// The filtered sensor is the unfiltered one through its filter.
TEST(SensorTwin, FilteredSensorIsTheRawSignalThroughItsFilter) {
  const Study s = sensorStudy("sensor_filter");
  const Trace tr = roughRun(s).trace;
  const auto expect = lowPass(tr.column("seat_mps2"), 1000.0, {2, 15.0});
  EXPECT_EQ(tr.column("seat_lp_mps2"), expect);
  EXPECT_LT(range(tr.column("seat_lp_mps2")), range(tr.column("seat_mps2")));
}

// Off the output grid: an unfiltered sensor is read from the dense output (the same as a 2 kHz
// grid to rounding); a filtered one from its filtered grid (the filters of the two grids differ
// by their sampling, (ωh)²/8 at most).
TEST(SensorTwin, SensorsAreReadAtOffGridTimes) {
  const Study s = sensorStudy("sensor_offgrid");
  LabData d;
  for (int k = 0; k < 300; ++k)
    for (const char* ch : {"seat_mps2", "seat_lp_mps2"})
      d.records.push_back({1, 0.5005 + 0.005 * k, ch, 0.0});
  calib::LabObjective coarse(s, s.assemblies().front(), {{"x.csv", "diag_rough", d}}, {});
  Study fine_study = s;
  fine_study.simulation.output_rate_hz = 2000.0;
  calib::LabObjective fine(fine_study, s.assemblies().front(), {{"x.csv", "diag_rough", d}}, {});
  const auto theta = dtwin_test::truthOf(s);
  const auto a = coarse.predict(theta), b = fine.predict(theta);
  ASSERT_EQ(a.size(), d.records.size());
  double worst[2] = {0, 0};
  std::vector<double> seat;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst[i % 2] = std::max(worst[i % 2], std::abs(a[i] - b[i]));
    if (i % 2 == 0) seat.push_back(b[i]);
  }
  EXPECT_LT(worst[0], 1e-9 * range(seat));
  EXPECT_LT(worst[1], 5e-3 * range(seat));
}

// Bad [sensors] tables: one line naming the file, the line and the field.
TEST(SensorTwin, BadSensorTablesNameTheField) {
  struct Case {
    const char* toml;
    const char* expect;
  };
  const Case cases[] = {
      {"[sensors.a]\nbody = \"roof\"\nquantity = \"acceleration_z\"\n", "sensors.a.body"},
      {"[sensors.a]\nposition_m = [1, 2]\nquantity = \"acceleration_z\"\n",
       "sensors.a.position_m: must be [x, y, z]"},
      {"[sensors.a]\n", "sensors.a.quantity: is required"},
      {"[sensors.a]\nquantity = \"acceleration_x\"\n", "sensors.a.quantity"},
      {"[sensors.a]\nquantity = \"acceleration_z\"\nfilter = { order = 3, cutoff_hz = 10 }\n",
       "sensors.a.filter.order"},
      {"[sensors.a]\nquantity = \"acceleration_z\"\nfilter = { order = 1 }\n",
       "sensors.a.filter.cutoff_hz"},
      {"[sensors.a]\nquantity = \"acceleration_z\"\nfilter = { order = 1, cutoff_hz = 5, cut = 3 "
       "}\n",
       "sensors.a.filter.cut"},
      {"[sensors.a]\nquantity = \"acceleration_z\"\nnoise_sd = -1\n", "sensors.a.noise_sd"},
      {"[sensors.a]\nquantity = \"acceleration_z\"\nmount = \"chassis\"\n", "sensors.a.mount"},
      {"[sensors.A]\nquantity = \"acceleration_z\"\n", "sensors.A: sensor name 'A'"},
      {"[sensors.b]\nbody = \"wheel_fl\"\nposition_m = [0.1, 0, 0]\nquantity = \"velocity_z\"\n",
       "sensors.b.position_m"},
      {"[sensors.chassis_heave]\nquantity = \"displacement_z\"\n",
       "is already a channel of the twin"},
      {"[sensors]\na = 3\n", "sensors.a: must be a table"},
  };
  int i = 0;
  for (const auto& c : cases) {
    const std::string e = errorOf("sensor_bad_" + std::to_string(i++), c.toml);
    EXPECT_NE(e.find(c.expect), std::string::npos) << c.toml << " -> " << e;
    EXPECT_NE(e.find("study.toml:"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

// A sensor channel is a channel like any other: measurements may name it (the lab reader checks
// names against the study's sensors), and it carries its unit.
TEST(SensorTwin, MeasurementsMayNameSensorChannels) {
  const Study s = sensorStudy("sensor_names");
  const auto known = measurableChannels(s.sensors);
  EXPECT_TRUE(checkChannelName("seat_mps2", known).empty());
  EXPECT_FALSE(checkChannelName("seat_mps2").empty());  // not a channel of a study without sensors
  const auto chans = Simulator::channels(s.sensors);
  ASSERT_EQ(chans.size(), Simulator::channels().size() + 7);
  const auto it = std::find_if(chans.begin(), chans.end(),
                               [](const Channel& c) { return c.name == "hub_rl_a_mps2"; });
  ASSERT_NE(it, chans.end());
  EXPECT_EQ(it->unit, "m/s^2");
  EXPECT_NE(it->description.find("wheel_rl"), std::string::npos) << it->description;
}

// Synthetic lab data can be made on a sensor channel (the generator validates against the
// study's channels, sensors included).
TEST(SensorTwin, LabDataCanBeGeneratedOnASensorChannel) {
  const Study s = sensorStudy("sensor_generate");
  LabOptions o;
  o.scenario = "diag_rough";
  o.times_mode = LabTimesMode::All;
  o.window = std::make_pair(0.5, 1.0);
  o.rate_hz = 100.0;
  o.repetitions = 2;
  o.channels = {"seat_mps2"};
  const LabResult r = generateLab(s, s.assemblies().front(), o);
  ASSERT_EQ(r.data.records.size(), 2u * 51u);
  EXPECT_EQ(r.data.records.front().channel, "seat_mps2");
  EXPECT_NO_THROW(labCsvText(r.data, measurableChannels(s.sensors)));
}

// A sensor's position and offset are run parameters (sensors.NAME.x_m, .y_m, .z_m,
// .offset): a calibration that frees them predicts, at a value, what a study with the sensor
// mounted there predicts, bit for bit, and an offset adds itself to every sample.
TEST(SensorTwin, ASensorsPositionAndOffsetAreRunParameters) {
  const char* kAt = R"(
[sensors.seat]
position_m = [0.9, -0.4, 0.3]
quantity = "acceleration_z"
)";
  const Study s = sensorStudy("sensor_param_a", std::string(kAt) + R"(
[[calibrated]]
name = "sensors.seat.x_m"
lower = -1.0
upper = 1.5

[[calibrated]]
name = "sensors.seat.offset"
unit = "m/s^2"
lower = -1.0
upper = 1.0
)");
  const Study moved = sensorStudy("sensor_param_b", R"(
[sensors.seat]
position_m = [1.2, -0.4, 0.3]
quantity = "acceleration_z"
)");
  LabData data;
  for (int k = 0; k <= 300; ++k) data.records.push_back({1, 0.01 * k, "seat_mps2", 0.0});
  const std::vector<calib::DataSet> sets{{"d", "diag_bump", data}};
  const calib::LabObjective with(s, s.assemblies().front(), sets, {});
  const calib::LabObjective base(moved, moved.assemblies().front(), sets, {});
  ASSERT_EQ(with.names().size(), 6u);
  auto th = dtwin_test::truthOf(moved);
  const auto expect = base.predict(th);
  th.push_back(1.2);
  th.push_back(0.0);
  EXPECT_EQ(with.predict(th), expect);
  th.back() = 0.25;
  const auto shifted = with.predict(th);
  for (std::size_t i = 0; i < expect.size(); ++i)
    EXPECT_NEAR(shifted[i], expect[i] + 0.25, 1e-12) << i;
  // In [fixed] too, and a position beyond 10 m is refused when the study is read.
  const Study fixed =
      sensorStudy("sensor_param_c", std::string(kAt) + "\n[fixed]\n\"sensors.seat.x_m\" = 1.2\n");
  const calib::LabObjective f(fixed, fixed.assemblies().front(), sets, {});
  EXPECT_EQ(f.predict(dtwin_test::truthOf(fixed)), expect);
  EXPECT_NE(errorOf("sensor_param_d", std::string(kAt) + "\n[fixed]\n\"sensors.seat.x_m\" = 12.0\n")
                .find("sensors.seat.x_m"),
            std::string::npos);
}
