#pragma once
// How an output was made: program version, command, study, assembly, every parameter value,
// road and seed, integrator settings, run statistics. Written as a JSON sidecar next to outputs.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/hash.hpp"  // fnv1a64, hexId
#include "io/study.hpp"
#include "twin/run_types.hpp"

namespace dtwin {

nlohmann::json programInfo();
std::string utcNow();
/// How an output was made, the same three fields in every JSON file a command writes: "program"
/// (programInfo()), "command" (the command line) and "created_utc" (utcNow()). Returns j.
nlohmann::json& stampProvenance(nlohmann::json& j, const std::string& command);

/// The sidecar of one simulation run (or of a set of runs); `road` describes the road(s)
/// (Road::describe() for one road).
nlohmann::json runRecord(const Study& study, const Model& model, const ScenarioSpec& scenario,
                         const nlohmann::json& road, std::uint64_t seed,
                         const std::vector<double>& values, const SimulationOptions& options,
                         const RunStats& stats, const std::vector<Channel>& channels,
                         const std::string& command);

/// "out/m1.csv" -> "out/m1.json".
std::string sidecarPath(const std::string& csv_path);
/// What a data file's JSON sidecar says of where it was measured: the scenario ("scenario":
/// {"name": ..} as `twin generate lab` writes it, or a string; "" when it names none) and the
/// random road's seed (road.seed). Empty without a sidecar; InputError naming the sidecar when it
/// is not valid JSON.
struct SidecarFacts {
  std::string scenario;
  std::optional<std::uint64_t> road_seed;
};
SidecarFacts readSidecarFacts(const std::string& csv_path);
/// The scenario data file `csv_path` was measured on: `given` when not empty (InputError
/// "PATH@GIVEN: its sidecar ... says it was measured on scenario 'X'" when the sidecar names
/// another), else the sidecar's, else "".
std::string dataScenario(const std::string& csv_path, const std::string& given,
                         const SidecarFacts& facts);

}  // namespace dtwin
