#include "python/calls.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <optional>
#include <utility>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"
#include "study/calibrate.hpp"
#include "study/diagnose.hpp"
#include "study/import_drive.hpp"
#include "study/simulate.hpp"

namespace fs = std::filesystem;

namespace dtwin::python {
namespace {

/// The command recorded in every output: the call with its given keyword arguments.
class CallText {
 public:
  explicit CallText(std::string head) : text_(std::move(head)) {}
  CallText& add(const std::string& keyword, const py::handle& value) {
    if (value.is_none()) return *this;
    if (!py::isinstance<py::str>(value) && py::hasattr(value, "__fspath__"))
      return add(keyword, pathText(value, keyword));  // a pathlib.Path as its text
    text_ += std::string(first_ ? "" : ", ") + keyword + "=" + literal(value);
    first_ = false;
    return *this;
  }
  CallText& add(const std::string& keyword, const std::string& value) {
    return add(keyword, py::str(value));
  }
  std::string str() const { return text_ + ")"; }

 private:
  std::string text_;
  bool first_ = true;
};

std::string studyCall(const PyStudy& s, const std::string& method) {
  return "python: dtwin.Study(" + literal(py::str(s.study->path)) + ")." + method + "(";
}

py::dict columnsOf(const Trace& t) {
  py::dict out;
  for (std::size_t i = 0; i < t.channels().size(); ++i) {
    const std::vector<double>& c = t.column(i);
    py::array_t<double> a(static_cast<py::ssize_t>(c.size()));
    std::copy(c.begin(), c.end(), a.mutable_data());
    out[py::str(t.channels()[i].name)] = std::move(a);
  }
  return out;
}

/// The calibration sizes and settings of a call (study/calibrate.hpp CalibrationOverrides).
CalibrationOverrides overridesOf(const Arguments& a, bool settings) {
  CalibrationOverrides o;
  o.lhs_points = a.optionalInteger("lhs_points").value_or(-1);
  o.iterations = a.optionalInteger("iterations").value_or(-1);
  o.burn_in = a.optionalInteger("burn_in").value_or(-1);
  o.starts = a.optionalInteger("starts").value_or(-1);
  o.steps = a.str("steps");
  if (!settings) return o;  // diagnose: the sizes alone
  o.max_rounds = a.optionalInteger("max_rounds").value_or(-1);
  o.ridge_steps = a.optionalInteger("ridge_steps").value_or(-1);
  o.region = a.str("region");
  o.design = a.str("design");
  o.interval = a.str("interval");
  return o;
}

/// The call's given arguments among `names`, recorded as its command.
void addAll(CallText& call, const Arguments& a, std::initializer_list<const char*> names) {
  for (const char* n : names) call.add(n, a[n]);
}

/// The study a stoppable call runs on: `study` with the call's stop in its simulation options.
Study withStop(const Study& study, const StopToken& stop) {
  Study s = study;
  s.simulation.stop = stop;
  return s;
}

/// The call's keywords, with the option fields the calibration keywords set under other names.
Keywords calibrationKeywords(const Arguments& a) {
  return a.keywords({{"gibbs_iterations", "iterations"},
                     {"gibbs_burn_in", "burn_in"},
                     {"optimizer_starts", "starts"}});
}

nlohmann::json readJsonFile(const std::string& path) {
  return nlohmann::json::parse(readTextFile(path));
}

std::string withoutFinalNewline(std::string s) {
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}

}  // namespace

PyStudy loadStudyFile(const Arguments& a) {
  const std::string p = a.isNone("path") ? defaultStudyPath() : a.path("path");
  PyStudy s;
  runReleased([&] { s.study = std::make_shared<const Study>(loadStudy(p)); }, a.keywords());
  return s;
}

// ------------------------------------------------------------------ simulate
py::object simulate(const PyStudy& s, const Arguments& a) {
  const Study& study = *s.study;
  const std::vector<std::string> sets = a.settings("set"), effect_texts = a.effects("effects");
  const std::string assembly = a.str("assembly");
  SimulateRequest req;
  req.assembly = assembly;
  req.scenario = a.str("scenario");
  req.out = a.path("out");
  req.channels = a.names("channels");
  std::optional<std::pair<double, double>> win;
  if (const auto w = a.window("window"); !w.empty()) win = std::make_pair(w[0], w[1]);
  req.seed = a.seed("seed");
  req.simulation = study.simulation;
  if (!a.isNone("integrator")) req.simulation.integrator = a.str("integrator");
  req.simulation.accuracy = a.optionalReal("accuracy").value_or(req.simulation.accuracy);
  req.simulation.max_step_s = a.optionalReal("max_step").value_or(req.simulation.max_step_s);
  req.simulation.obstacle_max_step_s =
      a.optionalReal("obstacle_step").value_or(req.simulation.obstacle_max_step_s);
  req.simulation.output_rate_hz =
      a.optionalReal("output_rate").value_or(req.simulation.output_rate_hz);
  req.keep_values = true;
  CallText call(studyCall(s, "simulate"));
  addAll(call, a,
         {"assembly", "scenario", "set", "effects", "seed", "channels", "window", "integrator",
          "accuracy", "max_step", "obstacle_step", "output_rate", "out"});
  req.command = call.str();

  const Keywords keywords = a.keywords({{"effect", "effects"},
                                        {"max_step_s", "max_step"},
                                        {"obstacle_max_step_s", "obstacle_step"},
                                        {"output_rate_hz", "output_rate"}});
  Callbacks callbacks(py::none(), true);
  req.simulation.stop = callbacks.stop();
  std::vector<SimulateRun> runs;
  runReleased(
      [&] {
        for (const auto& t : sets) req.sets.push_back(parseSetting(t, "--set"));
        for (const auto& e : effect_texts)
          req.effects.push_back(parseEffectSetting(e, "--effect", study.effectCatalog()));
        req.window = win;
        runs = simulateScenario(study, req);
      },
      keywords, &callbacks);
  std::string failed;
  for (const auto& r : runs) {
    for (const auto& note : r.off_effects)
      if (PyErr_WarnEx(PyExc_UserWarning, ("dtwin: " + note).c_str(), 1) != 0)
        throw py::error_already_set();
    if (!r.ok) failed += (failed.empty() ? "" : "; ") + r.assembly + ": " + r.message;
  }
  if (!failed.empty()) {
    PyErr_SetString(exceptions().simulation_error.ptr(), oneLine(failed).c_str());
    throw py::error_already_set();
  }
  if (assembly != "all") return columnsOf(runs.front().values);
  py::dict out_all;
  for (const auto& r : runs) out_all[py::str(r.assembly)] = columnsOf(r.values);
  return std::move(out_all);
}

// ------------------------------------------------------------------ calibrate
py::object calibrate(const PyStudy& s, const Arguments& a) {
  CalibrateSettings settings;
  settings.data = a.path("data");
  settings.out = a.path("out");
  settings.overrides = overridesOf(a, true);
  for (auto& id : a.names("assembly"))
    if (id != "all") settings.assemblies.push_back(std::move(id));
  settings.seed = a.seed("seed");
  settings.threads = a.smallInteger("threads");
  settings.processes = nullptr;  // this process alone
  settings.force = a.flag("force");
  CallText call(studyCall(s, "calibrate"));
  call.add("data", settings.data).add("assembly", a["assembly"]).add("out", settings.out);
  addAll(call, a,
         {"lhs_points", "iterations", "burn_in", "starts", "region", "design", "interval", "steps",
          "max_rounds", "ridge_steps", "seed"});
  settings.command = call.str();
  Callbacks callbacks(a["progress"], a.flag("quiet"));
  const StageProgress stage_progress = callbacks.progress();
  const SayFn say = callbacks.say();
  std::vector<std::string> done;
  runReleased(
      [&] {
        const Study study = withStop(*s.study, callbacks.stop());
        const CalibrateRequest req = calibrateRequest(study, settings);
        const auto progress_of = [&](const AssemblySpec& as) -> StageProgress {
          return [&, id = as.id](const std::string& stage, std::size_t d, std::size_t t) {
            stage_progress(id + " " + stage, d, t);
          };
        };
        calibrateAssemblies(study, req, say, progress_of, [&](const CalibrateRun& run) {
          if (say) say(withoutFinalNewline(run.text()));
          done.push_back(run.assembly.id);
        });
      },
      calibrationKeywords(a), &callbacks);
  py::dict result;
  for (const auto& id : done)
    result[py::str(id)] =
        toPython(readJsonFile((fs::path(settings.out) / id / "summary.json").string()));
  return std::move(result);
}

// ------------------------------------------------------------------ compare
py::object compare(const PyStudy& s, const Arguments& a) {
  const std::string calibration = a.path("calibration");
  CompareRequest req;
  req.calibration = calibration;
  req.data = a.paths("data");
  req.baseline = a.paths("baseline");
  req.discrepancy = a.paths("discrepancy");
  req.out = a.path("out");
  req.draws = a.smallInteger("draws");
  req.threads = a.smallInteger("threads");
  req.processes = nullptr;
  req.force = a.flag("force");
  CallText call(studyCall(s, "compare"));
  call.add("calibration", calibration);
  addAll(call, a, {"data", "baseline", "discrepancy", "draws", "out"});
  req.command = call.str();
  Callbacks callbacks(py::none(), a.flag("quiet"));
  const SayFn say = callbacks.say();
  CompareRun run;
  runReleased(
      [&] {
        const Study study = withStop(*s.study, callbacks.stop());
        run = compareMeasurements(study, req, say);
        if (say) say(withoutFinalNewline(run.text()));
        if (!run.written.empty() && say) say("wrote " + run.written);
        if (say)
          for (const auto& line : run.pages) say(line);
      },
      a.keywords(), &callbacks);
  return toPython(run.json);
}

// ------------------------------------------------------------------ diagnose
py::object diagnose(const PyStudy& s, const Arguments& a) {
  const CalibrationOverrides overrides = overridesOf(a, false);
  DiagnoseRequest req;
  req.assembly = a.str("assembly");
  req.data = a.paths("data");
  req.holdout = a.paths("holdout");
  req.out = a.path("out");
  req.force = a.flag("force");
  diag::DiagnoseOptions& o = req.options;
  o.candidates = a.smallInteger("candidates");
  o.confirm_within = a.real("confirm_within");
  o.causes = a.smallInteger("causes");
  if (a.flag("all_intervals")) o.full_within = std::numeric_limits<double>::infinity();
  o.propose_terms = a.smallInteger("propose");
  o.compare_draws = a.smallInteger("draws");
  o.effects = a.names("effects");
  o.apply = a.names("apply");
  o.threads = a.smallInteger("threads");
  o.processes = nullptr;  // this process alone
  CallText call(studyCall(s, "diagnose"));
  addAll(call, a,
         {"data", "assembly", "holdout", "effects", "apply", "candidates", "causes", "propose",
          "lhs_points", "iterations", "burn_in", "starts", "steps", "out"});
  o.command = call.str();
  Callbacks callbacks(a["progress"], a.flag("quiet"));
  const StageProgress stage_progress = callbacks.progress();
  const SayFn say = callbacks.say();
  DiagnoseRun run;
  Keywords keywords = calibrationKeywords(a);
  keywords.fields["compare_draws"] = "draws";
  keywords.fields["fit"] = "data";
  keywords.fields["propose_terms"] = "propose";
  runReleased(
      [&] {
        const Study study = withStop(*s.study, callbacks.stop());
        o.calibration = calib::CalibrationOptions::fromStudy(study);
        overrides.applyTo(o.calibration);
        run = diagnoseMeasurements(study, req, say, stage_progress);
        if (say) say(withoutFinalNewline(run.result.text()));
        if (run.written.empty()) return;
        if (say) say("wrote " + run.written);
        if (say)
          for (const auto& line : run.pages) say(line);
      },
      keywords, &callbacks);
  return toPython(run.json);
}

// ------------------------------------------------------------------ import
py::object importLog(const Arguments& a) {
  ImportRequest req;
  req.log = a.path("log");
  req.out = a.path("out");
  req.scenario = a.str("scenario");
  req.study = a.isNone("study") ? defaultStudyPath() : a.path("study");
  req.map = a.path("map");
  req.time = a.str("time");
  req.speed = a.str("speed");
  req.road = a.str("road");
  req.road_left = a.str("road_left");
  req.road_right = a.str("road_right");
  req.road_wheels = {a.str("road_fl"), a.str("road_fr"), a.str("road_rl"), a.str("road_rr")};
  req.separator = a.str("separator");
  req.channels = a.strings("channel");
  req.highpass_hz = a.optionalReal("highpass_hz").value_or(0.0);
  req.speed_lowpass_hz = a.optionalReal("speed_lowpass_hz").value_or(0.0);
  req.window = a.window("window");
  req.run_in = a.optionalReal("run_in").value_or(-1.0);
  CallText call("python: dtwin.import_log(");
  addAll(call, a,
         {"log",     "map",     "out",       "study",       "scenario",         "time",
          "speed",   "road",    "road_left", "road_right",  "road_fl",          "road_fr",
          "road_rl", "road_rr", "channel",   "highpass_hz", "speed_lowpass_hz", "separator",
          "window",  "run_in"});
  req.command = call.str();
  Callbacks callbacks(a["progress"], a.flag("quiet"));
  const StageProgress stage_progress = callbacks.progress();
  const SayFn say = callbacks.say();
  ImportResult r;
  runReleased(
      [&] {
        const StageProgress bytes = [&](const std::string&, std::size_t d, std::size_t t) {
          stage_progress("import " + req.log, d, t);
        };
        r = importDrive(req, bytes);
        if (say)
          say("imported " + std::to_string(r.rows) + " rows (" + formatNumber(r.duration_s, 6) +
              " s of driving, " + std::to_string(r.data.records.size()) + " records) into " +
              req.out + "/ (study.toml, scenario '" + r.scenario + "')");
      },
      a.keywords(), &callbacks);
  return toPython(r.sidecar);
}

}  // namespace dtwin::python
