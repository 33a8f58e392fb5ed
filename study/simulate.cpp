#include "study/simulate.hpp"

#include <algorithm>
#include <filesystem>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/validate.hpp"
#include "io/provenance.hpp"

namespace fs = std::filesystem;

namespace dtwin {

void SimulateRequest::validate(const Study& study) const {
  const OptionCheck check("simulate");
  (void)study.scenario(scenario);
  simulation.validate();
  if (window) check.require(window->first < window->second, "window", "expects T0,T1 with T0 < T1");
  const auto known = Simulator::channels(study.sensors);
  for (const auto& c : channels)
    check.require(
        std::any_of(known.begin(), known.end(), [&](const Channel& k) { return k.name == c; }),
        "channels", "unknown channel '" + c + "' (see `twin list --channels`)");
  if (assembly == "all") {
    check.require(!fs::path(out).has_extension(), "out",
                  "with --assembly all, --out must be a folder, got '" + out + "'");
  } else {
    (void)study.assembly(assembly);
    check.require(out.empty() || fs::path(out).extension() == ".csv", "out",
                  "must name a .csv file, got '" + out + "'");
  }
}

namespace {

double peakOf(const Trace& t, const std::string& ch) {
  const auto& c = t.column(ch);
  return *std::max_element(c.begin(), c.end());
}

/// The effects of `model` whose parameters are all at their off values, with a hint.
std::vector<std::string> offEffects(const Model& model) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < model.assembly().effects.size(); ++i) {
    bool off = true;
    for (std::size_t k = 0; k < model.effects()[i]->parameters().size(); ++k) {
      const auto& n =
          model.runParameterNames()[static_cast<std::size_t>(model.effectSlots()[i][k])];
      off = off && model.table().value(n) == model.table().at(n).spec.default_value;
    }
    if (off)
      out.push_back(
          "effect " + model.assembly().effects[i] +
          " is installed at its off values; set its parameters to switch it on, e.g. --effect " +
          model.assembly().effects[i] + ":" + model.effects()[i]->parameters()[0].name + "=...");
  }
  return out;
}

}  // namespace

std::vector<SimulateRun> simulateScenario(const Study& study, const SimulateRequest& request,
                                          const std::function<void(const SimulateRun&)>& on_run) {
  request.validate(study);
  const ScenarioSpec& sc = study.scenario(request.scenario);
  const bool all = request.assembly == "all";
  const std::vector<AssemblySpec> targets =
      all ? study.assemblies() : std::vector<AssemblySpec>{study.assembly(request.assembly)};
  std::vector<std::string> channels = request.channels;
  if (!channels.empty() && std::find(channels.begin(), channels.end(), "time_s") == channels.end())
    channels.insert(channels.begin(), "time_s");
  const std::uint64_t seed = request.seed.value_or(study.seed);
  const double t_lo = request.window ? request.window->first : -1e300,
               t_hi = request.window ? request.window->second : 1e300;

  nlohmann::json summary = {{"study", study.path}, {"scenario", sc.name}, {"seed", seed}};
  stampProvenance(summary, request.command);
  std::vector<SimulateRun> runs;
  for (const auto& a : targets) {
    const auto model = study.makeModel(a, request.effects, request.sets);
    SimulateRun run;
    run.assembly = a.id;
    run.label = model->assembly().label();
    run.off_effects = offEffects(*model);
    auto road = makeRoad(sc, model->vehicle(), seed);
    Simulator sim(model, request.simulation);
    const auto values = model->defaultRunValues();
    const RunResult r = sim.run(values, *road, sc);
    const std::string csv =
        all ? (fs::path(request.out) / (a.id + "_" + sc.name + ".csv")).string() : request.out;
    run.ok = r.stats.ok;
    run.message = r.stats.message;
    run.steps = r.stats.steps;
    run.wall_s = r.stats.wall_s;
    run.peak_hub_force_fl_N = peakOf(r.trace, "hub_force_fl_N");
    run.static_hub_force_fl_N = r.trace.column("hub_force_fl_N").front();
    if (r.stats.ok && (request.keep_values || request.out.empty()))
      run.values = r.trace.select(channels, t_lo, t_hi);
    if (r.stats.ok && !request.out.empty()) {
      writeFileAtomic(csv, r.trace.toCsv(channels, t_lo, t_hi));
      const auto rec =
          runRecord(study, *model, sc, road->describe(), seed, values, request.simulation, r.stats,
                    Simulator::channels(study.sensors), request.command);
      writeFileAtomic(sidecarPath(csv), rec.dump(2) + "\n");
      run.trace = csv;
    }
    summary["runs"].push_back(
        {{"assembly", run.assembly},
         {"label", run.label},
         {"ok", run.ok},
         {"message", run.message},
         {"peak_hub_force_fl_N", run.peak_hub_force_fl_N},
         {"static_hub_force_fl_N", run.static_hub_force_fl_N},
         {"integrator_steps", run.steps},
         {"wall_s", run.wall_s},
         {"trace", run.trace.empty() ? nlohmann::json() : nlohmann::json(csv)}});
    if (on_run) on_run(run);
    runs.push_back(std::move(run));
  }
  if (all && !request.out.empty())
    writeFileAtomic((fs::path(request.out) / "summary.json").string(), summary.dump(2) + "\n");
  return runs;
}

}  // namespace dtwin
