#pragma once
// The modelDescription.xml of an FMI 2.0 co-simulation FMU (FMI 2.0.4 standard, chapters 2.2 and
// 4.3): the model's identity, the co-simulation capabilities, the units, the default experiment,
// the scalar variables and the model structure. Only Real variables (all the twin's are).
#include <optional>
#include <string>
#include <vector>

namespace dtwin {

struct FmiVariable {
  std::string name;
  std::string causality;    ///< "parameter", "input", "output"
  std::string variability;  ///< "fixed", "tunable", "continuous", ...
  std::string initial;      ///< "", "exact", "calculated" ("" writes none)
  std::optional<double> start;
  std::string unit;  ///< "" writes none
  std::string description;
};

struct FmiModelInfo {
  std::string model_name, model_identifier, guid, description;
  std::string generation_tool, generation_time_utc;  ///< ISO 8601, e.g. 2026-12-08T01:02:03Z
  double step_size_s = 1e-3;                         ///< DefaultExperiment
  double stop_time_s = 10.0;
  bool can_get_and_set_state = false;
  /// valueReference = index + 1, in this order.
  std::vector<FmiVariable> variables;
};

/// The XML text. InputError naming the variable when a name repeats or a
/// causality/variability/initial combination is not one FMI 2.0 allows (its table 2.2.7).
std::string fmi2ModelDescription(const FmiModelInfo& info);

/// "" when FMI 2.0 allows this causality, variability and initial (empty: the default) together
/// for a Real variable with or without a start value; else the rule broken.
std::string fmi2CombinationRule(const FmiVariable& v);

}  // namespace dtwin
