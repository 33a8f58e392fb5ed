#pragma once
// The road types of a scenario (the study file's [scenarios.NAME.road] table). Each type is one
// class in twin/roads/ that reads its own fields, records itself, says what a time window of a
// run crosses, and makes the Road (subsystems/road.hpp). twin/road_setting.cpp registers each
// type once; the list of type names, the "unknown type" message and `twin list` come from there
// (docs/extending.md).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/registry.hpp"
#include "subsystems/road.hpp"

namespace dtwin {

struct ScenarioSpec;
struct VehicleData;
class TableReader;

/// The road of one scenario as the study file gives it. Immutable once read: copies of a
/// ScenarioSpec share it, and parallel runs read it without locks.
class RoadSetting {
 public:
  virtual ~RoadSetting() = default;
  /// The study-file name of the type ("bump").
  virtual std::string type() const = 0;
  /// The "road" object of ScenarioSpec::toJson (study.json, sidecars).
  virtual nlohmann::json toJson() const = 0;
  /// The road under a vehicle during a scenario; `seed` is used by random roads only. Throws
  /// InputError when the road cannot serve the scenario (a CSV profile too short).
  virtual std::shared_ptr<const Road> make(const ScenarioSpec& s, const VehicleData& v,
                                           std::uint64_t seed) const = 0;
  /// What the time window [t0, t1] of a run crosses, in words ("front wheels climbing the bump").
  virtual std::vector<std::string> describeWindow(const ScenarioSpec& s, const VehicleData& v,
                                                  double t0, double t1) const = 0;
  /// When the front axle reaches the road's main feature (a bump, the rough section); 0 if none.
  virtual double featureTime_s() const { return 0.0; }
  /// A random road with a smooth lead-in: when its rough section starts (> 0), else < 0. Runs on
  /// different seeds share the smooth part (branched runs, twin/simulator.hpp).
  virtual double roughStart_s() const { return -1.0; }
  /// Drawn from a seed (synthetic field data need such a road).
  virtual bool random() const { return false; }
  /// A short obstacle (the `twin bench` bump case).
  virtual bool obstacle() const { return false; }
  /// A measured signal (a logged or surveyed road): it may be another quantity than the road under
  /// a tire (the hub's own motion), or carry a gain or a delay, which a diagnosis then weighs.
  virtual bool measured() const { return false; }
  /// Checks that need the scenario (a bump before the end of the run); `where` names the table.
  virtual void check(const ScenarioSpec& s, const std::string& where) const {}
};

/// One registered road type: its study-file name, a sentence for `twin list`, and how it reads
/// its table (every field it knows, except `type`).
/// What the road registry holds of a type: the parser of its fields.
using RoadParser = std::shared_ptr<const RoadSetting> (*)(TableReader& table);
using RoadType = RegistryEntry<RoadParser>;

/// Every road type, in the order `twin list` shows them.
const Registry<RoadParser>& roadTypes();
std::vector<std::string> roadTypeNames();
/// Reads the `road` table of a scenario table: its `type`, then the type's own fields. Unknown
/// fields and types are InputErrors naming file:line and field.
std::shared_ptr<const RoadSetting> parseRoadSetting(TableReader& scenario_table);
/// The flat road (the default of a ScenarioSpec).
std::shared_ptr<const RoadSetting> flatRoadSetting();

}  // namespace dtwin
