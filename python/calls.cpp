#include "python/calls.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"
#include "report/compare_page.hpp"
#include "report/diagnosis_report.hpp"
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
  CallText& add(const std::string& keyword, const std::string& value) { return add(keyword, py::str(value)); }
  std::string str() const { return text_ + ")"; }

 private:
  std::string text_;
  bool first_ = true;
};

std::string studyCall(const PyStudy& s, const std::string& method) {
  return "python: dtwin.Study(" + literal(py::str(s.study->path)) + ")." + method + "(";
}

template <class T>
std::optional<T> optionalOf(const py::object& v) {
  if (v.is_none()) return std::nullopt;
  return v.cast<T>();
}

std::optional<std::uint64_t> seedOf(const py::object& v) {
  if (v.is_none()) return std::nullopt;
  if (!py::isinstance<py::int_>(v) || v.cast<py::int_>() < py::int_(0))
    throw py::type_error("seed: must be an int in [0, 18446744073709551615] or None");
  return v.cast<std::uint64_t>();
}

/// A str "A,B" or a list of str, as strings (the comma-separated flags of `twin`).
std::vector<std::string> commaList(const py::object& v, const std::string& keyword) {
  std::vector<std::string> out;
  for (const auto& s : stringList(v, keyword))
    for (auto& part : splitOn(s, ','))
      if (!part.empty()) out.push_back(std::move(part));
  return out;
}

/// A number as text the library parses back to the same double (Python's repr is the shortest exact form).
std::string numberText(const py::handle& v) {
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::bool_>(v)) throw py::type_error("a value must be a number or a str, got a bool");
  return literal(py::float_(py::reinterpret_borrow<py::object>(v)));
}

/// set=: {"NAME": value} or ["NAME=VALUE", ...] -> the texts of `--set`.
std::vector<std::string> settingTexts(const py::object& set) {
  if (set.is_none()) return {};
  if (py::isinstance<py::dict>(set)) {
    std::vector<std::string> out;
    for (const auto& [k, v] : set.cast<py::dict>()) out.push_back(py::str(k).cast<std::string>() + "=" + numberText(v));
    return out;
  }
  return stringList(set, "set");
}

/// effects=: ["NAME[:p=v,...]", ...] or {"NAME": {"p": v} or None} -> the texts of `--effect`.
std::vector<std::string> effectTexts(const py::object& effects) {
  if (effects.is_none()) return {};
  if (!py::isinstance<py::dict>(effects)) return stringList(effects, "effects");
  std::vector<std::string> out;
  for (const auto& [k, v] : effects.cast<py::dict>()) {
    std::string text = py::str(k).cast<std::string>();
    if (!v.is_none()) {
      if (!py::isinstance<py::dict>(v)) throw py::type_error("effects: {name: {parameter: value}} or a list of 'NAME[:p=v,...]'");
      std::string settings;
      for (const auto& [p, x] : v.cast<py::dict>()) settings += (settings.empty() ? "" : ",") + py::str(p).cast<std::string>() + "=" + numberText(x);
      if (!settings.empty()) text += ":" + settings;
    }
    out.push_back(std::move(text));
  }
  return out;
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

CalibrationOverrides overridesOf(const CalibrationKeywords& k) {
  CalibrationOverrides o;
  const auto count = [](const py::object& v, long& into) {
    if (!v.is_none()) into = v.cast<long>();
  };
  const auto text = [](const py::object& v, std::string& into) {
    if (!v.is_none()) into = v.cast<std::string>();
  };
  count(k.lhs_points, o.lhs_points);
  count(k.iterations, o.iterations);
  count(k.burn_in, o.burn_in);
  count(k.starts, o.starts);
  count(k.max_rounds, o.max_rounds);
  count(k.ridge_steps, o.ridge_steps);
  text(k.region, o.region);
  text(k.design, o.design);
  text(k.interval, o.interval);
  text(k.steps, o.steps);
  return o;
}

void addSizes(CallText& call, const CalibrationKeywords& k) {
  call.add("lhs_points", k.lhs_points).add("iterations", k.iterations).add("burn_in", k.burn_in).add("starts", k.starts);
  call.add("region", k.region).add("design", k.design).add("interval", k.interval).add("steps", k.steps);
  call.add("max_rounds", k.max_rounds).add("ridge_steps", k.ridge_steps);
}

/// The names of the calibration keywords, and the option fields they set under other names.
Keywords calibrationKeywords(std::set<std::string> names) {
  for (const char* n : {"lhs_points", "iterations", "burn_in", "starts", "region", "design", "interval", "steps", "max_rounds", "ridge_steps"})
    names.insert(n);
  return {std::move(names), {{"gibbs_iterations", "iterations"}, {"gibbs_burn_in", "burn_in"}, {"optimizer_starts", "starts"}}};
}

nlohmann::json readJsonFile(const std::string& path) { return nlohmann::json::parse(readTextFile(path)); }

std::string withoutFinalNewline(std::string s) {
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s;
}

}  // namespace

PyStudy loadStudyFile(const py::object& path) {
  const std::string p = path.is_none() ? defaultStudyPath() : pathText(path, "path");
  PyStudy s;
  runReleased([&] { s.study = std::make_shared<const Study>(loadStudy(p)); }, Keywords{{"path"}, {}});
  return s;
}

// ------------------------------------------------------------------ simulate
py::object simulate(const PyStudy& s, const std::string& assembly, const std::string& scenario, const py::object& set,
                    const py::object& effects, const py::object& seed, const py::object& channels, const py::object& window,
                    const py::object& integrator, const py::object& accuracy, const py::object& max_step,
                    const py::object& obstacle_step, const py::object& output_rate, const py::object& out) {
  const Study& study = *s.study;
  const std::vector<std::string> sets = settingTexts(set), effect_texts = effectTexts(effects);
  SimulateRequest req;
  req.assembly = assembly;
  req.scenario = scenario;
  req.out = out.is_none() ? std::string() : pathText(out, "out");
  req.channels = commaList(channels, "channels");
  std::optional<std::pair<double, double>> win;
  if (!window.is_none()) {
    const auto w = window.cast<std::vector<double>>();
    if (w.size() != 2) throw py::type_error("window: expects (T0, T1)");
    win = std::make_pair(w[0], w[1]);
  }
  req.seed = seedOf(seed);
  req.simulation = study.simulation;
  if (!integrator.is_none()) req.simulation.integrator = integrator.cast<std::string>();
  req.simulation.accuracy = optionalOf<double>(accuracy).value_or(req.simulation.accuracy);
  req.simulation.max_step_s = optionalOf<double>(max_step).value_or(req.simulation.max_step_s);
  req.simulation.obstacle_max_step_s = optionalOf<double>(obstacle_step).value_or(req.simulation.obstacle_max_step_s);
  req.simulation.output_rate_hz = optionalOf<double>(output_rate).value_or(req.simulation.output_rate_hz);
  req.keep_values = true;
  CallText call(studyCall(s, "simulate"));
  call.add("assembly", assembly).add("scenario", scenario).add("set", set).add("effects", effects).add("seed", seed);
  call.add("channels", channels).add("window", window).add("integrator", integrator).add("accuracy", accuracy);
  call.add("max_step", max_step).add("obstacle_step", obstacle_step).add("output_rate", output_rate).add("out", out);
  req.command = call.str();

  const Keywords keywords{{"assembly", "scenario", "set", "effects", "seed", "channels", "window", "integrator", "accuracy", "max_step",
                           "obstacle_step", "output_rate", "out"},
                          {{"effect", "effects"}, {"max_step_s", "max_step"}, {"obstacle_max_step_s", "obstacle_step"}, {"output_rate_hz", "output_rate"}}};
  std::vector<SimulateRun> runs;
  runReleased(
      [&] {
        for (const auto& t : sets) req.sets.push_back(parseSetting(t, "--set"));
        for (const auto& e : effect_texts) req.effects.push_back(parseEffectSetting(e, "--effect", study.effectCatalog()));
        req.window = win;
        runs = simulateScenario(study, req);
      },
      keywords);
  std::string failed;
  for (const auto& r : runs) {
    for (const auto& note : r.off_effects)
      if (PyErr_WarnEx(PyExc_UserWarning, ("dtwin: " + note).c_str(), 1) != 0) throw py::error_already_set();
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
py::object calibrate(const PyStudy& s, const py::object& data_arg, const py::object& assembly, const py::object& out_arg, int threads,
                     const CalibrationKeywords& sizes, const py::object& seed, bool force, bool quiet, const py::object& progress) {
  const Study& study = *s.study;
  const std::string data = pathText(data_arg, "data"), out = pathText(out_arg, "out");
  const CalibrationOverrides overrides = overridesOf(sizes);
  std::vector<std::string> assemblies;
  for (auto& id : commaList(assembly, "assembly"))
    if (id != "all") assemblies.push_back(std::move(id));
  const auto seed_value = seedOf(seed);
  CallText call(studyCall(s, "calibrate"));
  call.add("data", data).add("assembly", assembly).add("out", out);
  addSizes(call, sizes);
  call.add("seed", seed);
  Callbacks callbacks(progress, quiet);
  const StageProgress stage_progress = callbacks.progress();
  const SayFn say = callbacks.say();
  std::vector<std::string> done;
  runReleased(
      [&] {
        CalibrateRequest req;
        std::tie(req.data, req.scenario) = calibrationData(data, "--data");
        req.assemblies = assemblies;
        req.out = out;
        req.command = call.str();
        calib::CalibrationOptions& opt = req.options;
        opt = calib::CalibrationOptions::fromStudy(study);
        opt.threads = threads;
        opt.processes = nullptr;  // this process alone
        if (seed_value) opt.seed = *seed_value;
        overrides.applyTo(opt);
        req.validate(study);
        checkCalibrateWork(study, req, overrides, force);
        const auto progress_of = [&](const AssemblySpec& a) -> StageProgress {
          if (!stage_progress) return {};
          return [&, id = a.id](const std::string& stage, std::size_t d, std::size_t t) { stage_progress(id + " " + stage, d, t); };
        };
        calibrateAssemblies(study, req, say, progress_of, [&](const CalibrateRun& run) {
          if (say) say(withoutFinalNewline(run.text()));
          done.push_back(run.assembly.id);
        });
      },
      calibrationKeywords({"data", "assembly", "out", "threads", "seed", "force"}), &callbacks);
  py::dict result;
  for (const auto& id : done) result[py::str(id)] = toPython(readJsonFile((fs::path(out) / id / "summary.json").string()));
  return std::move(result);
}

// ------------------------------------------------------------------ compare
py::object compare(const PyStudy& s, const py::object& calibration_arg, const py::object& data, const py::object& baseline,
                   const py::object& discrepancy, int draws,
                   int threads, const py::object& out, bool force, bool quiet) {
  const Study& study = *s.study;
  const std::string calibration = pathText(calibration_arg, "calibration");
  CompareRequest req;
  req.calibration = calibration;
  req.data = stringList(data, "data");
  req.baseline = stringList(baseline, "baseline");
  req.discrepancy = stringList(discrepancy, "discrepancy");
  req.out = out.is_none() ? std::string() : pathText(out, "out");
  req.draws = draws;
  req.threads = threads;
  req.processes = nullptr;
  req.force = force;
  CallText call(studyCall(s, "compare"));
  call.add("calibration", calibration).add("data", data).add("baseline", baseline).add("discrepancy", discrepancy).add("draws", py::int_(draws)).add("out", out);
  req.command = call.str();
  Callbacks callbacks(py::none(), quiet);
  const SayFn say = callbacks.say();
  CompareRun run;
  runReleased(
      [&] {
        run = compareMeasurements(study, req, say);
        if (say) say(withoutFinalNewline(run.text()));
        if (!run.written.empty()) {
          if (say) say("wrote " + run.written);
          const std::string page = (fs::path(run.written).parent_path() / "compare.html").string();
          writeFileAtomic(page, comparePage(run, study.name, req.data));
          if (say) say("wrote " + page);
        }
      },
      Keywords{{"calibration", "data", "baseline", "discrepancy", "draws", "threads", "out", "force"}, {}}, &callbacks);
  return toPython(run.json);
}

// ------------------------------------------------------------------ diagnose
py::object diagnose(const PyStudy& s, const DiagnoseKeywords& k, const CalibrationKeywords& sizes, const py::object& progress) {
  const Study& study = *s.study;
  const CalibrationOverrides overrides = overridesOf(sizes);
  DiagnoseRequest req;
  req.assembly = k.assembly;
  req.data = stringList(k.data, "data");
  req.holdout = stringList(k.holdout, "holdout");
  req.out = k.out.is_none() ? std::string() : pathText(k.out, "out");
  req.force = k.force;
  diag::DiagnoseOptions& o = req.options;
  o.candidates = k.candidates;
  o.confirm_within = k.confirm_within;
  o.causes = k.causes;
  if (k.all_intervals) o.full_within = std::numeric_limits<double>::infinity();
  o.propose_terms = k.propose;
  o.compare_draws = k.draws;
  o.effects = commaList(k.effects, "effects");
  o.apply = commaList(k.apply, "apply");
  o.threads = k.threads;
  o.processes = nullptr;  // this process alone
  CallText call(studyCall(s, "diagnose"));
  call.add("data", k.data).add("assembly", k.assembly).add("holdout", k.holdout).add("effects", k.effects).add("apply", k.apply);
  call.add("candidates", py::int_(k.candidates)).add("causes", py::int_(k.causes)).add("propose", py::int_(k.propose));
  addSizes(call, sizes);
  call.add("out", k.out);
  o.command = call.str();
  Callbacks callbacks(progress, k.quiet);
  const StageProgress stage_progress = callbacks.progress();
  const SayFn say = callbacks.say();
  DiagnoseRun run;
  Keywords keywords = calibrationKeywords({"data", "assembly", "holdout", "effects", "apply", "candidates", "causes", "confirm_within",
                                           "all_intervals", "propose", "draws", "threads", "out", "force"});
  keywords.fields["compare_draws"] = "draws";
  keywords.fields["fit"] = "data";
  keywords.fields["propose_terms"] = "propose";
  runReleased(
      [&] {
        o.calibration = calib::CalibrationOptions::fromStudy(study);
        overrides.applyTo(o.calibration);
        run = diagnoseMeasurements(study, req, say, stage_progress);
        if (say) say(withoutFinalNewline(run.result.text()));
        if (run.written.empty()) return;
        if (say) say("wrote " + run.written);
        // The pages `twin diagnose` writes beside diagnosis.json (report.html needs gnuplot).
        try {
          const std::string page = (fs::path(req.out) / "compare.html").string();
          writeFileAtomic(page, diagnosisPage(run.result, study.name + ", " + req.assembly, req.data));
          if (say) say("wrote " + page);
        } catch (const InputError& e) {
          if (say) say(std::string("note: no interactive page (") + e.what() + ")");
        }
        try {
          const std::string html = (fs::path(req.out) / "report.html").string();
          report::writeDiagnosisReport(req.out, html, o.command);
          if (say) say("wrote " + html);
        } catch (const InputError& e) {
          if (say) say(std::string("note: no HTML report (") + e.what() + ")");
        }
      },
      keywords, &callbacks);
  return toPython(run.json);
}

// ------------------------------------------------------------------ import
py::object importLog(const ImportKeywords& k, const py::object& progress) {
  ImportRequest req;
  req.log = pathText(k.log, "log");
  req.out = pathText(k.out, "out");
  req.scenario = k.scenario;
  req.study = k.study.is_none() ? defaultStudyPath() : pathText(k.study, "study");
  const auto text = [](const py::object& v) { return v.is_none() ? std::string() : py::str(v).cast<std::string>(); };
  req.map = k.map.is_none() ? std::string() : pathText(k.map, "map");
  req.time = text(k.time);
  req.speed = text(k.speed);
  req.road = text(k.road);
  req.road_left = text(k.road_left);
  req.road_right = text(k.road_right);
  req.separator = text(k.separator);
  req.channels = stringList(k.channel, "channel");
  req.highpass_hz = optionalOf<double>(k.highpass_hz).value_or(0.0);
  req.speed_lowpass_hz = optionalOf<double>(k.speed_lowpass_hz).value_or(0.0);
  if (!k.window.is_none()) req.window = k.window.cast<std::vector<double>>();
  req.run_in = optionalOf<double>(k.run_in).value_or(-1.0);
  CallText call("python: dtwin.import_log(");
  call.add("log", k.log).add("map", k.map).add("out", k.out).add("study", k.study).add("scenario", k.scenario);
  call.add("time", k.time).add("speed", k.speed).add("road", k.road).add("road_left", k.road_left).add("road_right", k.road_right);
  call.add("channel", k.channel).add("highpass_hz", k.highpass_hz).add("speed_lowpass_hz", k.speed_lowpass_hz);
  call.add("separator", k.separator).add("window", k.window).add("run_in", k.run_in);
  req.command = call.str();
  Callbacks callbacks(progress, k.quiet);
  const StageProgress stage_progress = callbacks.progress();
  const SayFn say = callbacks.say();
  ImportResult r;
  runReleased(
      [&] {
        StageProgress bytes;
        if (stage_progress) bytes = [&](const std::string&, std::size_t d, std::size_t t) { stage_progress("import " + req.log, d, t); };
        r = importDrive(req, bytes);
        if (say)
          say("imported " + std::to_string(r.rows) + " rows (" + formatNumber(r.duration_s, 6) + " s of driving, " +
              std::to_string(r.data.records.size()) + " records) into " + req.out + "/ (study.toml, scenario '" + r.scenario + "')");
      },
      Keywords{{"log", "map", "out", "study", "scenario", "time", "speed", "road", "road_left", "road_right", "channel", "highpass_hz",
                "speed_lowpass_hz", "separator", "window", "run_in"},
               {}},
      &callbacks);
  return toPython(r.sidecar);
}

}  // namespace dtwin::python
