#include "twin/bench.hpp"

#include <algorithm>

#include "common/errors.hpp"

namespace dtwin {
namespace {
double peak(const Trace& t) {
  const auto& c = t.column("hub_force_fl_N");
  return *std::max_element(c.begin(), c.end());
}
}  // namespace

BenchRow benchAssembly(const Study& study, const AssemblySpec& a, const ScenarioSpec& sc, int runs, bool reference) {
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
  row.median_wall_s = walls.size() % 2 ? walls[walls.size() / 2] : 0.5 * (walls[walls.size() / 2 - 1] + walls[walls.size() / 2]);
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

}  // namespace dtwin
