#include "io/fmi_description.hpp"

#include <map>
#include <set>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace dtwin {

namespace {

std::string xmlEscape(const std::string& s) {
  std::string o;
  for (const char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\'':
        o += "&apos;";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n')
          o += ' ';
        else
          o += c;
    }
  }
  return o;
}

std::string attr(const char* name, const std::string& value) {
  return std::string(" ") + name + "=\"" + xmlEscape(value) + "\"";
}

std::string number(double v) { return formatExact(v); }

}  // namespace

std::string fmi2CombinationRule(const FmiVariable& v) {
  // FMI 2.0.4, section 2.2.7: the legal (causality, variability) pairs and, for each, the allowed
  // values of initial (the first is the default).
  static const std::map<std::pair<std::string, std::string>, std::vector<std::string>> legal = {
      {{"parameter", "fixed"}, {"exact"}},
      {{"parameter", "tunable"}, {"exact"}},
      {{"calculatedParameter", "fixed"}, {"calculated", "approx"}},
      {{"calculatedParameter", "tunable"}, {"calculated", "approx"}},
      {{"input", "discrete"}, {""}},
      {{"input", "continuous"}, {""}},
      {{"output", "constant"}, {"exact"}},
      {{"output", "discrete"}, {"calculated", "exact", "approx"}},
      {{"output", "continuous"}, {"calculated", "exact", "approx"}},
      {{"local", "constant"}, {"exact"}},
      {{"local", "fixed"}, {"calculated", "approx"}},
      {{"local", "tunable"}, {"calculated", "approx"}},
      {{"local", "discrete"}, {"calculated", "exact", "approx"}},
      {{"local", "continuous"}, {"calculated", "exact", "approx"}},
      {{"independent", "continuous"}, {""}},
  };
  const auto it = legal.find({v.causality, v.variability});
  if (it == legal.end())
    return "causality '" + v.causality + "' with variability '" + v.variability +
           "' is not an FMI 2.0 combination";
  const std::string initial = v.initial.empty() ? it->second.front() : v.initial;
  bool allowed = false;
  for (const auto& a : it->second) allowed = allowed || a == initial;
  if (!allowed)
    return "initial '" + v.initial + "' is not allowed with causality '" + v.causality +
           "' and variability '" + v.variability + "'";
  // A start value is required for exact initials and inputs, forbidden for calculated ones.
  const bool needs = initial == "exact" || v.causality == "input";
  if (needs && !v.start) return "needs a start value (initial exact, or an input)";
  if (initial == "calculated" && v.start) return "may not have a start value (initial calculated)";
  return "";
}

std::string fmi2ModelDescription(const FmiModelInfo& info) {
  std::set<std::string> names, units;
  for (const auto& v : info.variables) {
    if (!names.insert(v.name).second)
      throw InputError("modelDescription.xml: " + v.name, "variable names must be unique");
    if (const std::string rule = fmi2CombinationRule(v); !rule.empty())
      throw InputError("modelDescription.xml: " + v.name, rule);
    if (!v.unit.empty()) units.insert(v.unit);
  }
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiModelDescription";
  x += attr("fmiVersion", "2.0") + attr("modelName", info.model_name) + attr("guid", info.guid) +
       attr("description", info.description) + attr("generationTool", info.generation_tool) +
       attr("generationDateAndTime", info.generation_time_utc) +
       attr("variableNamingConvention", "flat") + attr("numberOfEventIndicators", "0") + ">\n";
  const std::string state = info.can_get_and_set_state ? "true" : "false";
  x += "  <CoSimulation" + attr("modelIdentifier", info.model_identifier) +
       attr("needsExecutionTool", "false") +
       attr("canHandleVariableCommunicationStepSize", "true") +
       attr("canInterpolateInputs", "false") + attr("maxOutputDerivativeOrder", "0") +
       attr("canRunAsynchronuously", "false") +
       attr("canBeInstantiatedOnlyOncePerProcess", "false") +
       attr("canNotUseMemoryManagementFunctions", "true") + attr("canGetAndSetFMUstate", state) +
       attr("canSerializeFMUstate", "false") + attr("providesDirectionalDerivative", "false") +
       "/>\n";
  if (!units.empty()) {
    x += "  <UnitDefinitions>\n";
    for (const auto& u : units) x += "    <Unit" + attr("name", u) + "/>\n";
    x += "  </UnitDefinitions>\n";
  }
  x += "  <DefaultExperiment" + attr("startTime", "0") +
       attr("stopTime", number(info.stop_time_s)) + attr("stepSize", number(info.step_size_s)) +
       "/>\n";
  x += "  <ModelVariables>\n";
  std::vector<std::size_t> outputs, initial_unknowns;
  for (std::size_t i = 0; i < info.variables.size(); ++i) {
    const FmiVariable& v = info.variables[i];
    x += "    <ScalarVariable" + attr("name", v.name) +
         attr("valueReference", std::to_string(i + 1)) + attr("description", v.description) +
         attr("causality", v.causality) + attr("variability", v.variability);
    if (!v.initial.empty()) x += attr("initial", v.initial);
    x += ">\n      <Real";
    if (!v.unit.empty()) x += attr("unit", v.unit);
    if (v.start) x += attr("start", number(*v.start));
    x += "/>\n    </ScalarVariable>\n";
    if (v.causality == "output") outputs.push_back(i + 1);
    const std::string initial =
        v.initial.empty() && v.causality == "output" ? "calculated" : v.initial;
    if (v.causality == "output" && (initial == "calculated" || initial == "approx"))
      initial_unknowns.push_back(i + 1);
  }
  x += "  </ModelVariables>\n  <ModelStructure>\n";
  if (!outputs.empty()) {
    x += "    <Outputs>\n";
    for (auto k : outputs) x += "      <Unknown" + attr("index", std::to_string(k)) + "/>\n";
    x += "    </Outputs>\n";
  }
  if (!initial_unknowns.empty()) {
    x += "    <InitialUnknowns>\n";
    for (auto k : initial_unknowns)
      x += "      <Unknown" + attr("index", std::to_string(k)) + "/>\n";
    x += "    </InitialUnknowns>\n";
  }
  x += "  </ModelStructure>\n</fmiModelDescription>\n";
  return x;
}

}  // namespace dtwin
