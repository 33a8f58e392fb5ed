#pragma once
// A study file (TOML) names the subsystems and their options, the calibrated parameters with
// bounds, fixed values, effects, scenarios, noise, simulation options and sizes. Assemblies are
// the Cartesian product of the options (last subsystem varies fastest), optionally filtered.
// See docs/study-file.md for every field.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/study_sizes.hpp"
#include "subsystems/effect_catalog.hpp"
#include "twin/model.hpp"
#include "twin/run_types.hpp"
#include "twin/scenario.hpp"

namespace dtwin {

class TableReader;

struct CalibratedParameter {
  std::string name, unit;
  double lower = 0, upper = 0;
  std::optional<double> truth;
};

struct ParameterSetting {
  std::string name;
  double value = 0;
  std::string where;   ///< "file:line: field" for errors
  std::string source;  ///< provenance text
};

struct EffectSetting {
  std::string name;
  std::vector<ParameterSetting> values;  ///< names are "<effect>.<param>"
};

/// Optional [lab] table: which channels the lab data carry and at which times (docs/study-file.md).
struct LabSettings {
  std::vector<double> times_s;        ///< explicit times (empty: automatic)
  std::vector<std::string> channels;  ///< empty: {"hub_force_fl_N"}
  long auto_times = 5;                ///< how many automatic times
  double min_separation_s = 0.02;     ///< minimum spacing of automatic times
  std::string where;                  ///< "file:line: lab" for errors
  /// The channels to generate: `channels`, or hub_force_fl_N if none are given.
  std::vector<std::string> channelsOrDefault() const;
  nlohmann::json toJson() const;
};

/// Optional [calibration] table: how the calibration covers the posterior (docs/study-file.md,
/// docs/calibration.md). Values are checked when the study is read.
struct CalibrationSettings {
  std::string region = "joint";  ///< "joint" (the joint 1 % contour) or "paper" (one-at-a-time box)
  std::string design;            ///< "adaptive" or "lhs"; empty: adaptive for joint, lhs for paper
  long round_points = 0;         ///< points per adaptive round (0: sizes.lhs_points)
  long max_rounds = 8;           ///< adaptive rounds after the first Latin hypercube, >= 0
  double target_ess = 400.0;     ///< importance ESS at which the rounds may stop, > 0
  double margin = 1.25;          ///< joint region: extents = margin x the contour's, >= 1
  long ridge_steps = 30;         ///< joint region: steps per ridge trace (0: no traces)
  std::string interval =
      "profile";  ///< the 95 % interval summaries print as ci95: "profile" or "posterior"
  /// "frozen" (default): the integrator's steps are chosen once per stage and replayed, so the SSE
  /// is smooth in θ; "adaptive": every run chooses its own (docs/calibration.md).
  std::string steps = "frozen";
  /// "adaptive" or "lhs", the default resolved.
  std::string designOrDefault() const {
    return design.empty() ? (region == "paper" ? "lhs" : "adaptive") : design;
  }
  nlohmann::json toJson() const;
};

struct Study {
  std::string path;
  std::string name, description;
  std::uint64_t seed = 1;
  std::string vehicle_path;  ///< resolved relative to the study file
  std::vector<std::pair<std::string, std::vector<std::string>>> subsystems;
  std::vector<std::string> include;  ///< assembly ids to keep (empty: all)
  std::vector<CalibratedParameter> calibrated;
  std::vector<ParameterSetting> fixed;
  std::vector<EffectSetting> effects;
  std::vector<ScenarioSpec> scenarios;
  SimulationOptions simulation;
  double noise_variance_N2 = 18000.0;
  std::vector<SensorSpec> sensors;  ///< [sensors.NAME], by name
  /// The effects this study knows: the built-in ones and its [user_effects.NAME] definitions
  /// (effects whose force is an expression, subsystems/user_effect.hpp), by name. Shared by the
  /// study's copies and never changed once read: addUserEffects makes a new one.
  std::shared_ptr<const EffectCatalog> catalog = std::make_shared<const EffectCatalog>();
  StudySizes sizes;
  LabSettings lab;
  CalibrationSettings calibration;

  /// The effects this study knows (built-in and its own).
  const EffectCatalog& effectCatalog() const { return *catalog; }
  /// Adds user-defined effects (e.g. a diagnosis's proposal.toml) to this study's catalogue, each
  /// checked (EffectCatalog::add). Copies of the study made before keep the catalogue they had.
  void addUserEffects(const std::vector<UserEffectSpec>& specs);

  std::vector<AssemblySpec> assemblies() const;
  AssemblySpec assembly(const std::string& id) const;           ///< InputError if unknown
  const ScenarioSpec& scenario(const std::string& name) const;  ///< InputError if unknown
  /// Every parameter with its value: declarations, vehicle file, [fixed], calibrated truths,
  /// [effects], then `overrides` (e.g. --set), in that order of precedence.
  ParameterTable parameterTable(const std::vector<ParameterSetting>& overrides = {}) const;
  /// Builds the model of one assembly with extra effects installed (e.g. from --effect).
  std::shared_ptr<const Model> makeModel(const AssemblySpec& a,
                                         const std::vector<EffectSetting>& extra_effects = {},
                                         const std::vector<ParameterSetting>& overrides = {}) const;
  nlohmann::json toJson() const;
};

/// The [sensors.NAME] tables of a TOML file (a study, or an import mapping), validated: InputError
/// naming file:line: sensors.NAME.field. Their channels may not repeat the twin's own nor those of
/// `existing`.
std::vector<SensorSpec> readSensorTables(TableReader& top,
                                         const std::vector<SensorSpec>& existing = {});

/// The [user_effects.NAME] tables of a TOML file that holds nothing else (e.g. the proposal
/// `twin diagnose` writes), each checked as the study file's are (Study::addUserEffects adds
/// them to a study). InputError naming file:line and field for a bad one, for any other table,
/// or for none.
std::vector<UserEffectSpec> loadUserEffects(const std::string& path);

/// Parses and validates a study file. Every error is an InputError naming the file, the line and
/// the field, and the rule broken. A study needs at least one scenario, except a base for
/// `twin import` (`scenarios_required` false), to which the import adds the drive's.
Study loadStudy(const std::string& path, bool scenarios_required = true);

/// Parses "name=value" (CLI --set). `where` prefixes errors.
ParameterSetting parseSetting(const std::string& text, const std::string& where);
/// Parses "effect[:param=value,...]" (CLI --effect, --hidden-effect), the effect's name checked
/// against `catalog`; a library term "term:EXPR[:a=value]" (subsystems/effect.hpp kTermPrefix)
/// takes its settings after the last colon.
EffectSetting parseEffectSetting(const std::string& text, const std::string& where,
                                 const EffectCatalog& catalog);

}  // namespace dtwin
