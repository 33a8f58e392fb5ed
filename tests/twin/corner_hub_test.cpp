// Each hub driven by its own logged motion (a four-corner csv_time road with tire = hub) against
// the forms the twin already has: a log whose front-left column alone moves gives the run of the
// single-column log read at the front-left wheel alone (road.fl_only = 1); a log whose rear
// columns are the front ones a wheelbase later gives the run of the two-track log. Compared on
// the body's accelerations, a body accelerometer and the four hub forces, over the whole run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <regex>
#include <string>
#include <vector>

#include "io/study.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;
namespace fs = std::filesystem;

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kDt = 0.005;  // the log's sample interval [s]
constexpr int kLag = 100;      // the wheelbase's lag in samples (the speed is chosen so)
constexpr int kRows = 801;     // 4 s

/// A track's height at sample k: sines from 1 to 11 Hz, 0 before 0.6 s and faded in over 0.5 s.
double track(int side, int k) {
  const double t = k * kDt;
  if (t <= 0.6) return 0.0;
  const double u = std::min(1.0, (t - 0.6) / 0.5), fade = u * u * (3 - 2 * u);
  return 4e-3 * fade *
         (std::sin(kTwoPi * 1.3 * t + side) + 0.5 * std::sin(kTwoPi * 4.7 * t + 0.3 + side) +
          0.2 * std::sin(kTwoPi * 11.0 * t));
}

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

/// A log of `header` whose row k holds cols(k) (each value written exactly).
void writeLog(const fs::path& p, const std::string& header,
              const std::function<std::vector<double>(int)>& cols) {
  std::string s = header + "\n";
  for (int k = 0; k < kRows; ++k) {
    s += num(k * kDt);
    for (double v : cols(k)) s += "," + num(v);
    s += "\n";
  }
  dtwin_test::writeText(p, s);
}

/// The demo study with the hub input on MacPherson struts, a body accelerometer over the front
/// left, and one scenario per log at `speed` (csv_time roads).
Study hubStudy(const fs::path& dir, double speed, const std::vector<std::string>& logs) {
  const auto path = dtwin_test::writeDemoStudy(dir / "study.toml", "lab_repetitions = 2\n");
  std::string s = dtwin_test::slurp(path);
  s = std::regex_replace(s, std::regex("tire = \\[[^\\]]*\\]"), "tire = [\"hub\"]");
  s = std::regex_replace(s, std::regex("suspension = \\[[^\\]]*\\]"),
                         "suspension = [\"macpherson\"]");
  for (const auto& name : logs)
    s += "\n[scenarios." + name + "]\nduration_s = 3.5\nspeed = { v_final_mps = " + num(speed) +
         ", ramp_s = 0.0 }\nroad = { type = \"csv_time\", path = \"" + name + ".csv\" }\n";
  s += "\n[sensors.seat]\nquantity = \"acceleration_z\"\nposition_m = [1.2, 0.6, 0.3]\n";
  dtwin_test::writeText(path, s);
  return loadStudy(path.string());
}

/// The largest difference of the compared channels between two runs, each relative to the
/// channel's largest magnitude (its dynamic part for the hub forces: less their static value).
double worstDifference(const Trace& a, const Trace& b) {
  double worst = 0;
  for (const char* ch :
       {"chassis_heave_acc_mps2", "chassis_pitch_acc_radps2", "chassis_roll_acc_radps2",
        "seat_mps2", "hub_force_fl_N", "hub_force_fr_N", "hub_force_rl_N", "hub_force_rr_N"}) {
    const auto &x = a.column(ch), &y = b.column(ch);
    EXPECT_EQ(x.size(), y.size()) << ch;
    double scale = 0, diff = 0;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
      scale = std::max(scale, std::abs(x[i] - x[0]));
      diff = std::max(diff, std::abs(x[i] - y[i]));
    }
    std::printf("  %-26s largest change %.4g, largest difference %.3g\n", ch, scale, diff);
    EXPECT_GT(scale, 0.0) << ch;
    worst = std::max(worst, diff / scale);
  }
  return worst;
}

struct Runs {
  std::shared_ptr<const Model> model;
  std::unique_ptr<Simulator> sim;
  const Study* study;
  RunResult run(const std::string& scenario, std::vector<double> values) const {
    const ScenarioSpec& sc = study->scenario(scenario);
    const auto road = makeRoad(sc, model->vehicle(), 0);
    RunResult r = sim->run(values, *road, sc);
    EXPECT_TRUE(r.stats.ok) << scenario << ": " << r.stats.message;
    return r;
  }
};

Runs prepare(const Study& st) {
  Runs r;
  r.study = &st;
  r.model = st.makeModel(st.assemblies().front(), {});
  SimulationOptions o = st.simulation;
  o.accuracy = 1e-7;
  r.sim = std::make_unique<Simulator>(r.model, o);
  return r;
}

double wheelbaseOf(const fs::path& dir) {
  const Study st = hubStudy(dir, 10.0, {});
  return st.makeModel(st.assemblies().front(), {})->vehicle().wheelbase();
}

/// The run values of `r`'s model with the road-signal form `name` at share 1.
std::vector<double> withForm(const Runs& r, const std::string& name) {
  std::vector<double> v = r.model->defaultRunValues();
  std::size_t form = 0;
  while (form < roadSignalForms().size() && roadSignalForms()[form].name != name) ++form;
  EXPECT_LT(form, roadSignalForms().size()) << name;
  if (form < roadSignalForms().size())
    v[static_cast<std::size_t>(r.model->roadFormSlot()) + form] = 1.0;
  return v;
}

}  // namespace

TEST(CornerHub, TheFrontLeftColumnAloneIsTheFrontLeftForm) {
  const fs::path dir = dtwin_test::freshDir("corner_hub_fl");
  writeLog(dir / "four.csv", "time_s,fl_m,fr_m,rl_m,rr_m", [](int k) {
    return std::vector<double>{track(0, k), 0.0, 0.0, 0.0};
  });
  writeLog(dir / "one.csv", "time_s,height_m",
           [](int k) { return std::vector<double>{track(0, k)}; });
  const Study st = hubStudy(dir, 10.0, {"four", "one"});
  EXPECT_EQ(st.scenario("four").road->toJson()["tracks"], "four corners");
  const Runs r = prepare(st);
  ASSERT_TRUE(r.model->tire().followsSignal());
  const std::vector<double> fl_only = withForm(r, "road.fl_only");
  const RunResult four = r.run("four", r.model->defaultRunValues());
  const RunResult one = r.run("one", fl_only);
  const double worst = worstDifference(four.trace, one.trace);
  std::printf("front-left column against road.fl_only: worst %.3g\n", worst);
  EXPECT_LT(worst, 1e-6);  // the same numbers here (0)
}

TEST(CornerHub, RearColumnsAWheelbaseLateAreTheTwoTrackLog) {
  const fs::path dir = dtwin_test::freshDir("corner_hub_lag");
  // The speed at which the rear axle meets the front's road kLag samples later.
  const double speed = wheelbaseOf(dir) / (kLag * kDt);
  writeLog(dir / "two.csv", "time_s,left_m,right_m", [](int k) {
    return std::vector<double>{track(0, k), track(1, k)};
  });
  writeLog(dir / "four.csv", "time_s,fl_m,fr_m,rl_m,rr_m", [](int k) {
    const int j = k - kLag;  // before the log's start the road is flat (track() is 0 there)
    return std::vector<double>{track(0, k), track(1, k), j >= 0 ? track(0, j) : 0.0,
                               j >= 0 ? track(1, j) : 0.0};
  });
  const Study st = hubStudy(dir, speed, {"two", "four"});
  const Runs r = prepare(st);
  const RunResult two = r.run("two", r.model->defaultRunValues());
  const RunResult four = r.run("four", r.model->defaultRunValues());
  const double worst = worstDifference(four.trace, two.trace);
  std::printf("rear columns a wheelbase late against the two-track log: worst %.3g\n", worst);
  // The two roads' rear nodes agree to the rounding of their distances; the integrator's steps
  // then part by its tolerance (3e-5 of each channel's change at accuracy 1e-7).
  EXPECT_LT(worst, 2e-4);
}

// On a four-corner road a rear column is its wheel's own motion at its own time: road.rl_only = 1
// keeps the rear-left column where it is (no wheelbase's read-ahead, which the form needs on a
// road under the front axle) and drops the other three.
TEST(CornerHub, TheRearLeftFormKeepsTheRearLeftColumnAtItsOwnTime) {
  const fs::path dir = dtwin_test::freshDir("corner_hub_rl");
  writeLog(dir / "four.csv", "time_s,fl_m,fr_m,rl_m,rr_m", [](int k) {
    return std::vector<double>{track(0, k), track(1, k), track(2, k), track(3, k)};
  });
  writeLog(dir / "rl.csv", "time_s,fl_m,fr_m,rl_m,rr_m", [](int k) {
    return std::vector<double>{0.0, 0.0, track(2, k), 0.0};
  });
  const Study st = hubStudy(dir, 10.0, {"four", "rl"});
  const Runs r = prepare(st);
  const RunResult four = r.run("four", withForm(r, "road.rl_only"));
  const RunResult rl = r.run("rl", r.model->defaultRunValues());
  const double worst = worstDifference(four.trace, rl.trace);
  std::printf("road.rl_only on four columns against the rear-left column alone: worst %.3g\n",
              worst);
  EXPECT_LT(worst, 1e-6);
  // The same form on the right rear's column is another run (the check can fail).
  const RunResult rr = r.run("four", withForm(r, "road.rr_only"));
  EXPECT_GT(worstDifference(rr.trace, rl.trace), 1e-2);
}
