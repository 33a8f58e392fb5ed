#pragma once
// How an output was made: program version, command, study, assembly, every parameter value,
// road and seed, integrator settings, run statistics. Written as a JSON sidecar next to outputs.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/hash.hpp"  // fnv1a64, hexId
#include "twin/run_types.hpp"
#include "io/study.hpp"

namespace dtwin {

nlohmann::json programInfo();
std::string utcNow();


/// The sidecar of one simulation run (or of a set of runs); `road` describes the road(s)
/// (Road::describe() for one road).
nlohmann::json runRecord(const Study& study, const Model& model, const ScenarioSpec& scenario, const nlohmann::json& road,
                         std::uint64_t seed, const std::vector<double>& values, const SimulationOptions& options,
                         const RunStats& stats, const std::vector<Channel>& channels, const std::string& command);

/// "out/m1.csv" -> "out/m1.json".
std::string sidecarPath(const std::string& csv_path);
/// The scenario a data file's JSON sidecar names ("scenario": {"name": ..} as `twin generate lab`
/// writes it, or a string), "" when there is no sidecar or it names none; InputError naming the
/// sidecar when it is not valid JSON.
std::string sidecarScenario(const std::string& csv_path);

}  // namespace dtwin
