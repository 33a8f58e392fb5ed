#include "study/bench.hpp"

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "io/log_import.hpp"
#include "io/mdf_log.hpp"
#include "subsystems/user_effect.hpp"
#include "twin/simulator.hpp"

namespace dtwin {
namespace {
double peak(const Trace& t) {
  const auto& c = t.column("hub_force_fl_N");
  return *std::max_element(c.begin(), c.end());
}
}  // namespace

BenchRow benchAssembly(const Study& study, const AssemblySpec& a, const ScenarioSpec& sc, int runs,
                       bool reference) {
  DTWIN_CHECK(runs >= 1, "runs >= 1");
  auto model = study.makeModel(a);
  auto road = makeRoad(sc, model->vehicle(), study.seed);
  Simulator sim(model, study.simulation);
  const auto values = model->defaultRunValues();
  BenchRow row;
  row.assembly = a.id;
  row.label = a.label();
  row.scenario = sc.name;
  RunResult r = sim.run(values, *road, sc);  // warm-up
  std::vector<double> walls;
  for (int i = 0; i < runs; ++i) {
    r = sim.run(values, *road, sc);
    walls.push_back(r.stats.wall_s);
    row.ok = row.ok && r.stats.ok;
  }
  std::sort(walls.begin(), walls.end());
  row.median_wall_s = walls.size() % 2
                          ? walls[walls.size() / 2]
                          : 0.5 * (walls[walls.size() / 2 - 1] + walls[walls.size() / 2]);
  row.min_wall_s = walls.front();
  row.max_wall_s = walls.back();
  row.simulated_s = r.stats.sim_s;
  row.real_time_factor = row.simulated_s / row.median_wall_s;
  row.steps = r.stats.steps;
  row.peak_fl_N = peak(r.trace);
  if (reference) {
    SimulationOptions tight = study.simulation;
    tight.accuracy = 1e-8;
    tight.max_step_s = 1e-3;
    tight.obstacle_max_step_s = 2.5e-5;
    Simulator ref(model, tight);
    row.reference_peak_fl_N = peak(ref.run(values, *road, sc).trace);
  }
  return row;
}

BenchImport benchImport(const std::string& study_path, long rows, int runs) {
  DTWIN_CHECK(rows >= 2 && runs >= 1, "benchImport: rows >= 2, runs >= 1");
  std::string log = "time,speed_kmh,road_l_mm,road_r_mm,seat_g,hub_g,counter,note\n";
  log.reserve(static_cast<std::size_t>(rows) * 64);
  char line[256];
  std::uint64_t state = 12345;
  MdfWriteGroup mf4{"bench",
                    "time",
                    "s",
                    {},
                    {{"speed_kmh", "km/h", {}, {}},
                     {"road_l_mm", "mm", {}, {}},
                     {"road_r_mm", "mm", {}, {}},
                     {"seat_g", "g", {}, {}},
                     {"hub_g", "deg/s^2", {}, {}}}};  // hub_g: as the mapping reads it
  for (long k = 0; k < rows; ++k) {
    state = state * 6364136223846793005ULL +
            1442695040888963407ULL;  // a fixed LCG: the same log every time
    const double jitter = (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5) * 0.004;
    const double t = 0.01 * static_cast<double>(k) + jitter;
    const double x[] = {40 + 20 * std::sin(t / 30), 3 * std::sin(1.1 * t), 3 * std::cos(1.3 * t),
                        1 + 0.05 * std::sin(7 * t), 0.3 * std::sin(11 * t)};
    std::snprintf(line, sizeof line, "%.4f,%.2f,%.3f,%.3f,%.5f,%.5f,%ld,ok\n", t, x[0], x[1], x[2],
                  x[3], x[4], k);
    log += line;
    mf4.time.push_back(t);
    for (std::size_t c = 0; c < 5; ++c) mf4.channels[c].values.push_back(x[c]);
  }
  ImportMapping m;
  m.source = "bench";
  m.time = {"time", "s", 0, 1, "time", ""};
  m.speed = ImportColumn{"speed_kmh", "km/h", 0, 1, "speed", ""};
  m.road_left = ImportColumn{"road_l_mm", "mm", 0, 1, "road_left", ""};
  m.road_right = ImportColumn{"road_r_mm", "mm", 0, 1, "road_right", ""};
  m.channels.push_back({{"seat_g", "g", 1, 1, "seat", ""}, "chassis_heave_acc_mps2"});
  m.channels.push_back({{"hub_g", "g", 0, 1, "hub", ""}, "chassis_pitch_acc_radps2"});
  m.channels.back().source.unit = "deg/s^2";  // any channel will do: the reading is what is timed
  BenchImport b;
  b.rows = rows;
  b.bytes = static_cast<double>(log.size());
  std::vector<double> walls;
  const auto tmp =
      std::filesystem::temp_directory_path() / ("dtwin_bench_import_" + std::to_string(::getpid()));
  for (int r = 0; r < runs; ++r) {
    std::filesystem::remove_all(tmp);
    const auto t0 = std::chrono::steady_clock::now();
    const ImportResult res = importLog(log, "bench.csv", m, study_path, "drive");
    writeImport(res, tmp.string());
    walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::filesystem::remove_all(tmp);
  std::sort(walls.begin(), walls.end());
  b.median_s = walls[walls.size() / 2];
  b.min_s = walls.front();
  b.max_s = walls.back();
  // The same log as MF4, written by mdflib into a temporary folder, read from there as a file.
  const auto mdir =
      std::filesystem::temp_directory_path() / ("dtwin_bench_mf4_" + std::to_string(::getpid()));
  std::filesystem::create_directories(mdir);
  for (bool compress : {false, true}) {
    const std::string path = (mdir / (compress ? "bench_dz.mf4" : "bench.mf4")).string();
    writeMdfLog(path, {mf4}, compress);
    walls.clear();
    for (int r = 0; r < runs; ++r) {
      std::filesystem::remove_all(tmp);
      const auto t0 = std::chrono::steady_clock::now();
      const std::string bytes = readTextFile(path);
      const ImportResult res = importLog(bytes, path, m, study_path, "drive");
      writeImport(res, tmp.string());
      walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::filesystem::remove_all(tmp);
    std::sort(walls.begin(), walls.end());
    const double size = static_cast<double>(std::filesystem::file_size(path));
    (compress ? b.mf4z_bytes : b.mf4_bytes) = size;
    (compress ? b.mf4z_median_s : b.mf4_median_s) = walls[walls.size() / 2];
    (compress ? b.mf4z_min_s : b.mf4_min_s) = walls.front();
    (compress ? b.mf4z_max_s : b.mf4_max_s) = walls.back();
  }
  std::filesystem::remove_all(mdir);
  return b;
}

BenchUserEffect benchUserEffect(const Study& study, const std::string& scenario, long evaluations,
                                int runs) {
  UserEffectSpec spec;
  spec.name = "user_damper_asymmetry";
  spec.element = "strut";
  spec.force = "v < 0 ? (ratio - 1) * c * v : 0";
  spec.parameters = {{"ratio", "1", 1.0, 0.5, 3.0}};
  spec.where = "twin bench";
  const auto user = makeUserEffect(spec);
  const auto builtin = makeEffect("damper_asymmetry", "twin bench");
  const std::vector<double> p = {2.2};
  StrutState s;
  s.base_stiffness = 3e4;
  s.base_damping = 2500;
  BenchUserEffect r;
  r.evaluations = evaluations;
  std::vector<double> rates(
      4096);  // both signs, never the same twice in a row; read, not computed, in the timed loop
  for (std::size_t i = 0; i < rates.size(); ++i)
    rates[i] = std::sin(1e-3 * static_cast<double>(i * 7919 % 6283));
  auto time = [&](const Effect& e, double& sink) {
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < evaluations; ++i) {
      s.rate_mps = rates[static_cast<std::size_t>(i) & 4095];
      sink += e.calcStrutForce(s, p);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() * 1e9 /
           static_cast<double>(evaluations);
  };
  std::vector<double> tb, tu;
  double sink_b = 0, sink_u = 0;
  for (int k = 0; k < runs; ++k) {
    tb.push_back(time(*builtin, sink_b));
    tu.push_back(time(*user, sink_u));
  }
  std::sort(tb.begin(), tb.end());
  std::sort(tu.begin(), tu.end());
  r.builtin_ns = tb[tb.size() / 2];
  r.user_ns = tu[tu.size() / 2];
  for (double v = -2.0; v <= 2.0; v += 1e-3) {
    s.rate_mps = v;
    r.max_abs_difference = std::max(
        r.max_abs_difference, std::abs(user->calcStrutForce(s, p) - builtin->calcStrutForce(s, p)));
  }
  if (sink_b != sink_u)
    r.max_abs_difference = std::max(r.max_abs_difference,
                                    std::abs(sink_b - sink_u) / static_cast<double>(evaluations));
  // Inside the twin: whole runs with each effect, the user one added to a copy of the study.
  Study with = study;
  with.addUserEffects({spec});
  const ScenarioSpec& sc = with.scenario(scenario);
  r.scenario = scenario;
  const AssemblySpec a = with.assemblies().front();
  auto runOnce = [&](const std::string& name, RunResult* keep) {
    auto model = with.makeModel(
        a, {EffectSetting{name, {{name + ".ratio", 2.2, "twin bench", "twin bench"}}}});
    Simulator sim(model, with.simulation);
    auto road = makeRoad(sc, model->vehicle(), with.seed);
    const auto t0 = std::chrono::steady_clock::now();
    RunResult res = sim.run(model->defaultRunValues(), *road, sc);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!res.stats.ok)
      throw std::runtime_error("twin bench: the run with " + name +
                               " failed: " + res.stats.message);
    if (keep) *keep = std::move(res);
    return wall;
  };
  RunResult rb, ru;
  runOnce("damper_asymmetry", &rb);  // warm-up, and the traces compared
  runOnce(spec.name, &ru);
  r.steps = rb.stats.steps;
  r.identical_traces = rb.trace.channels().size() == ru.trace.channels().size();
  for (std::size_t c = 0; r.identical_traces && c < rb.trace.channels().size(); ++c)
    r.identical_traces = rb.trace.column(c) == ru.trace.column(c);
  std::vector<double> wb, wu;
  for (int k = 0; k < runs; ++k) {
    wb.push_back(runOnce("damper_asymmetry", nullptr));
    wu.push_back(runOnce(spec.name, nullptr));
  }
  std::sort(wb.begin(), wb.end());
  std::sort(wu.begin(), wu.end());
  r.builtin_run_s = wb[wb.size() / 2];
  r.user_run_s = wu[wu.size() / 2];
  return r;
}

namespace {
double handMedian(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t k = v.size() / 2;
  return v.size() % 2 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

/// max |simbody - hand| of the front-left hub force over the common grid, and where.
std::pair<double, double> handMaxDiff(const Trace& simbody, const HandOdeRun& hand) {
  const auto& ts = simbody.column("time_s");
  const auto& fs = simbody.column("hub_force_fl_N");
  DTWIN_CHECK(ts.size() == hand.time_s.size(),
              "benchHandOde: the two output grids differ in length");
  double worst = 0, at = 0;
  for (std::size_t i = 0; i < ts.size(); ++i)
    if (const double d = std::abs(fs[i] - hand.hub_force_N[0][i]); d > worst) {
      worst = d;
      at = ts[i];
    }
  return {worst, at};
}
}  // namespace

HandOdeBench benchHandOde(const Study& study, const AssemblySpec& a, const ScenarioSpec& sc,
                          int runs) {
  if (runs < 1) throw InputError("twin bench --hand-ode", "--runs must be >= 1");
  const auto model = study.makeModel(a);
  const auto road = makeRoad(sc, model->vehicle(), study.seed);
  const auto values = model->defaultRunValues();
  const HandOde probe(*model, values, *road,
                      sc.speed);  // InputError for an assembly it does not model
  HandOdeBench b;
  b.assembly = a.id;
  b.label = a.label();
  b.scenario = sc.name;
  b.runs = runs;
  b.accuracy = study.simulation.accuracy;
  Simulator sim(model, study.simulation);
  SimulationOptions quiet = study.simulation;
  quiet.output_rate_hz =
      0.1;  // two output rows: what is left is the equilibrium and the integration
  Simulator sim_quiet(model, quiet);
  // Warm-up, counts and agreement (the Simbody run records its steps to count its Jacobians).
  StepPlan plan;
  const RunResult ref = sim.run(values, *road, sc, StepControl{nullptr, &plan});
  if (!ref.stats.ok)
    throw std::runtime_error("twin bench --hand-ode: the Simbody run failed: " + ref.stats.message);
  sim_quiet.run(values, *road, sc);
  const HandOdeRun hand = runHandOde(*model, values, *road, sc, study.simulation);
  b.simbody_steps = ref.stats.steps;
  b.simbody_attempts = ref.stats.steps_attempted;
  b.simbody_jacobians =
      static_cast<long>(std::count(plan.new_jacobian.begin(), plan.new_jacobian.end(), 1));
  b.simbody_evaluations = 1 + 4 * b.simbody_steps + 3 * (b.simbody_attempts - b.simbody_steps) +
                          HandOde::kStates * b.simbody_jacobians;
  b.hand_steps = hand.steps;
  b.hand_attempts = hand.attempts;
  b.hand_evaluations = hand.evaluations;
  b.hand_jacobians = hand.jacobians;
  const auto& fl = ref.trace.column("hub_force_fl_N");
  b.peak_fl_N = *std::max_element(fl.begin(), fl.end());
  std::tie(b.max_diff_fl_N, b.max_diff_time_s) = handMaxDiff(ref.trace, hand);
  // Timed runs, alternating so that a change of the machine's load hits both alike.
  std::vector<double> ws, wq, wh, whq;
  for (int k = 0; k < runs; ++k) {
    ws.push_back(sim.run(values, *road, sc).stats.wall_s);
    wq.push_back(sim_quiet.run(values, *road, sc).stats.wall_s);
    wh.push_back(runHandOde(*model, values, *road, sc, study.simulation).wall_s);
    whq.push_back(runHandOde(*model, values, *road, sc, quiet).wall_s);
  }
  b.simbody_median_s = handMedian(ws);
  b.simbody_min_s = *std::min_element(ws.begin(), ws.end());
  b.simbody_max_s = *std::max_element(ws.begin(), ws.end());
  b.simbody_integration_s = handMedian(wq);
  b.hand_median_s = handMedian(wh);
  b.hand_min_s = *std::min_element(wh.begin(), wh.end());
  b.hand_max_s = *std::max_element(wh.begin(), wh.end());
  b.hand_integration_s = handMedian(whq);
  // One right-hand side alone, at the state the run starts from, in a loop.
  {
    const Eigen::VectorXd y = probe.equilibrium();
    Eigen::VectorXd yd(HandOde::kStates);
    const int reps = 20000;
    double sink = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < reps; ++i) {
      probe.rhs(6.0 + 1e-6 * i, y, yd);
      sink += yd[7];
    }
    b.hand_rhs_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps;
    if (!std::isfinite(sink))
      throw std::runtime_error("twin bench --hand-ode: non-finite right-hand side");
  }
  // Both at tight tolerance (untimed): the difference of the models themselves.
  SimulationOptions tight = study.simulation;
  tight.accuracy = 1e-8;
  tight.max_step_s = 1e-3;
  tight.obstacle_max_step_s = 2.5e-5;
  const RunResult ref_tight = Simulator(model, tight).run(values, *road, sc);
  b.tight_max_diff_fl_N =
      handMaxDiff(ref_tight.trace, runHandOde(*model, values, *road, sc, tight)).first;
  return b;
}

}  // namespace dtwin
