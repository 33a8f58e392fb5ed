#include "study/generate_request.hpp"

#include <cmath>
#include <utility>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/provenance.hpp"
#include "io/work.hpp"
#include "study/generate.hpp"
#include "study/request.hpp"

namespace dtwin {
namespace {

AssemblySpec chooseAssembly(const Study& study, const std::string& id) {
  if (!id.empty()) return study.assembly(id);
  const auto all = study.assemblies();
  if (all.empty()) throw InputError(study.path + ": assemblies", "the study defines no assembly");
  return all.front();  // M1: the highest fidelity by convention (docs/method.md §1)
}

std::vector<EffectSetting> parseHidden(const std::vector<std::string>& texts,
                                       const EffectCatalog& catalog) {
  std::vector<EffectSetting> out;
  out.reserve(texts.size());
  for (const auto& t : texts) out.push_back(parseEffectSetting(t, "--hidden-effect", catalog));
  return out;
}

/// NAME=VALUE texts of `flag` (a finite number after the first '=').
std::vector<std::pair<std::string, double>> parseAssignments(const std::vector<std::string>& texts,
                                                             const std::string& flag) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& t : texts) {
    const auto eq = t.find('=');
    double v = 0;
    if (eq == std::string::npos || eq == 0 || !parseNumber(t.substr(eq + 1), v) ||
        !std::isfinite(v))
      throw InputError(flag, "expects NAME=VALUE with a finite number, got '" + t + "'");
    for (const auto& [name, _] : out)
      if (name == t.substr(0, eq)) throw InputError(flag, "'" + name + "' given twice");
    out.push_back({t.substr(0, eq), v});
  }
  return out;
}

/// The lines on the hidden settings the data were made with, if any.
std::string hiddenText(const nlohmann::json& provenance, const EffectCatalog& catalog) {
  std::string s;
  if (provenance.contains("hidden_effects"))
    s += "hidden effect used to make the data: " +
         hiddenEffectsSummary(provenance["hidden_effects"], catalog) + "\n";
  if (provenance.contains("hidden_values"))
    for (const auto& [name, v] : provenance["hidden_values"].items())
      s += "hidden vehicle value used to make the data: " + name + " = " +
           formatExact(v.get<double>()) + "\n";
  if (provenance.contains("hidden_sensor"))
    for (const auto& [kind, v] : provenance["hidden_sensor"].items())
      s += "hidden sensor model applied to the data: " + kind + " " + v.dump() + "\n";
  return s;
}

std::string withoutNoise(const std::string& channel) {
  return "channel " + channel + " is not in N; it is written without noise";
}

}  // namespace

GenerateRun generateLabData(const Study& study, const GenerateRequest& request,
                            const ProgressFn& progress) {
  const AssemblySpec a = chooseAssembly(study, request.assembly);
  LabOptions opt;
  if (!request.scenario.empty()) opt.scenario = request.scenario;
  opt.hidden_effects = parseHidden(request.hidden_effects, study.effectCatalog());
  for (const auto& [name, v] : parseAssignments(request.hidden_values, "--hidden-value"))
    opt.hidden_values.push_back({name, v, "--hidden-value", "--hidden-value"});
  opt.hidden_sensor = parseAssignments(request.hidden_sensor, "--hidden-sensor");
  opt.times_mode = request.all_times ? LabTimesMode::All : LabTimesMode::Study;
  if (!request.window.empty()) {
    if (request.window.size() != 2) throw InputError("--window", "expects T0,T1 with T0 < T1");
    opt.window = std::make_pair(request.window[0], request.window[1]);
  }
  opt.rate_hz = request.rate_hz;
  opt.channels = request.channels;
  opt.processes = request.processes;
  opt.repetitions = request.repetitions;
  {
    Study sized = study;
    overrideSize(sized, "lab_repetitions", request.repetitions, "--repetitions");
    checkCommandWork(sized, {"lab"}, request.force);
  }
  if (request.seed) opt.seed = *request.seed;
  opt.command = request.command;
  LabResult r = generateLabFile(study, a, opt, request.out, progress);
  GenerateRun run;
  for (const auto& c : r.provenance["noise"]["not_applied_to"])
    run.notes.push_back(withoutNoise(c.get<std::string>()));
  std::string times;
  if (opt.times_mode == LabTimesMode::All)
    times = "times: " + r.times_rule + " (" + std::to_string(r.times_s.size()) + " times)";
  else {
    for (double t : r.times_s) times += (times.empty() ? "" : ", ") + formatExact(t);
    times =
        "times " + times + " s (" + r.provenance["lab"]["times"]["source"].get<std::string>() + ")";
  }
  run.text =
      formatPrintf("%s (%s): %ld repetitions x %zu times x %zu channel(s), %s -> %s, %s\n",
                   a.id.c_str(), a.label().c_str(), r.provenance["lab"]["repetitions"].get<long>(),
                   r.times_s.size(), r.provenance["lab"]["channels"].size(), times.c_str(),
                   request.out.c_str(), sidecarPath(request.out).c_str()) +
      hiddenText(r.provenance, study.effectCatalog());
  return run;
}

GenerateRun generateFieldData(const Study& study, const GenerateRequest& request,
                              const ProgressFn& progress) {
  const AssemblySpec a = chooseAssembly(study, request.assembly);
  FieldOptions opt;
  if (!request.scenario.empty()) opt.scenario = request.scenario;
  opt.channel = request.channel;
  applyTimeWindow(request.window, opt.t_begin_s, opt.t_end_s);
  opt.hidden_effects = parseHidden(request.hidden_effects, study.effectCatalog());
  opt.runs = request.runs;
  {
    Study sized = study;
    overrideSize(sized, "field_runs", request.runs, "--runs");
    checkCommandWork(sized, {"field"}, request.force);
  }
  opt.threads = request.threads;
  opt.processes = request.processes;
  if (request.seed) opt.seed = *request.seed;
  opt.command = request.command;
  FieldResult r = generateFieldFile(study, a, opt, request.out, progress);
  GenerateRun run;
  if (!r.provenance["noise"]["applied"].get<bool>()) run.notes.push_back(withoutNoise(opt.channel));
  run.text = formatPrintf(
                 "%s (%s): %zu runs x %zu samples of %s (%g..%g s), %d threads, %.1f s -> %s, %s\n",
                 a.id.c_str(), a.label().c_str(), r.data.rowCount(), r.data.columnCount(),
                 opt.channel.c_str(), r.data.times_s.front(), r.data.times_s.back(),
                 r.provenance["field"]["threads"].get<int>(),
                 r.provenance["stats"]["wall_s"].get<double>(), request.out.c_str(),
                 sidecarPath(request.out).c_str()) +
             hiddenText(r.provenance, study.effectCatalog());
  return run;
}

}  // namespace dtwin
