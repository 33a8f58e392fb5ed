#pragma once
// How an output was made: program version, command, study, assembly, every parameter value,
// road and seed, integrator settings, run statistics. Written as a JSON sidecar next to outputs.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "twin/simulator.hpp"
#include "twin/study.hpp"

namespace dtwin {

nlohmann::json programInfo();
std::string utcNow();

/// 64-bit FNV-1a of a byte string (portable content fingerprint).
std::uint64_t fnv1a64(const std::string& bytes);
/// "0x0123456789ABCDEF": how stream constants and content hashes are written in outputs.
std::string hexId(std::uint64_t v);

/// The sidecar of one simulation run (or of a set of runs); `road` describes the road(s)
/// (Road::describe() for one road).
nlohmann::json runRecord(const Study& study, const Model& model, const ScenarioSpec& scenario, const nlohmann::json& road,
                         std::uint64_t seed, const std::vector<double>& values, const SimulationOptions& options,
                         const RunStats& stats, const std::vector<Channel>& channels, const std::string& command);

/// "out/m1.csv" -> "out/m1.json".
std::string sidecarPath(const std::string& csv_path);

}  // namespace dtwin
