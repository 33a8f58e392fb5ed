#include "io/provenance.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/json.hpp"
#include "dtwin/version.hpp"

namespace dtwin {

nlohmann::json programInfo() {
  return {{"name", "twin"}, {"version", kVersion}, {"git", kGitDescribe}, {"simbody", kSimbody}};
}

std::string utcNow() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

nlohmann::json& stampProvenance(nlohmann::json& j, const std::string& command) {
  j["program"] = programInfo();
  j["command"] = command;
  j["created_utc"] = utcNow();
  return j;
}

nlohmann::json runRecord(const Study& study, const Model& model, const ScenarioSpec& scenario,
                         const nlohmann::json& road, std::uint64_t seed,
                         const std::vector<double>& values, const SimulationOptions& options,
                         const RunStats& stats, const std::vector<Channel>& channels,
                         const std::string& command) {
  nlohmann::json j;
  stampProvenance(j, command);
  j["study"] = {{"path", study.path}, {"name", study.name}, {"vehicle", study.vehicle_path}};
  j["assembly"] = {{"id", model.assembly().id},
                   {"label", model.assembly().label()},
                   {"effects", model.assembly().effects}};
  for (auto& [s, o] : model.assembly().options) j["assembly"]["options"][s] = o;
  j["scenario"] = scenario.toJson();
  j["road"] = road;
  j["seed"] = seed;
  nlohmann::json rp = nlohmann::json::object();
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto& e = model.table().at(model.runParameterNames()[i]);
    rp[model.runParameterNames()[i]] = {
        {"value", values[i]}, {"unit", e.spec.unit}, {"source", e.source}};
  }
  j["run_parameters"] = rp;
  j["all_parameters"] = model.table().toJson();
  j["simulation"] = options.toJson();
  j["contact_model"] =
      "single-point contact under the wheel centre" +
      std::string(std::find(model.assembly().effects.begin(), model.assembly().effects.end(),
                            "tire_enveloping") != model.assembly().effects.end()
                      ? " with a moving-average effective road (tire_enveloping)"
                      : "");
  j["stats"] = {{"ok", stats.ok},
                {"message", stats.message},
                {"integrator_steps", stats.steps},
                {"steps_attempted", stats.steps_attempted},
                {"recorded_states", stats.knots},
                {"simulated_s", stats.sim_s},
                {"wall_s", stats.wall_s}};
  for (const auto& c : channels)
    j["channels"].push_back({{"name", c.name}, {"unit", c.unit}, {"description", c.description}});
  return j;
}

std::string sidecarPath(const std::string& csv_path) {
  std::filesystem::path p(csv_path);
  p.replace_extension(".json");
  return p.string();
}

SidecarFacts readSidecarFacts(const std::string& csv_path) {
  SidecarFacts facts;
  const std::string side = sidecarPath(csv_path);
  if (!std::filesystem::exists(side)) return facts;
  try {
    const auto j = nlohmann::json::parse(readTextFile(side));
    if (j.contains("scenario") && j["scenario"].is_object() && j["scenario"].contains("name") &&
        j["scenario"]["name"].is_string())
      facts.scenario = j["scenario"]["name"].get<std::string>();
    else if (j.contains("scenario") && j["scenario"].is_string())
      facts.scenario = j["scenario"].get<std::string>();
    if (j.contains("road") && j["road"].is_object() && j["road"].contains("seed") &&
        j["road"]["seed"].is_number_unsigned())
      facts.road_seed = j["road"]["seed"].get<std::uint64_t>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(side, std::string("is not valid JSON: ") + jsonErrorInWords(e));
  }
  return facts;
}

std::string dataScenario(const std::string& csv_path, const std::string& given,
                         const SidecarFacts& facts) {
  if (given.empty()) return facts.scenario;
  if (!facts.scenario.empty() && given != facts.scenario)
    throw InputError(csv_path + "@" + given, "its sidecar " + sidecarPath(csv_path) +
                                                 " says it was measured on scenario '" +
                                                 facts.scenario + "'");
  return given;
}

}  // namespace dtwin
