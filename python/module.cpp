// The Python module `dtwin` (docs/python.md): the twin's use cases from Python, with the inputs of
// the `twin` commands as keyword arguments and their outputs as numpy arrays and dicts. Like the
// CLI it only parses, calls the library (study/) and converts.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "dtwin/version.hpp"
#include "python/bridge.hpp"
#include "python/calls.hpp"

namespace py = pybind11;
using namespace dtwin::python;

namespace {

const char* kModuleDoc = R"(The vehicle digital twin from Python (docs/python.md).

    study = dtwin.Study("data/studies/demo.toml")
    trace = study.simulate("M1", "lab")            # {column: numpy array}, as `twin simulate --out`
    fits = study.calibrate("lab.csv", assembly="M1", out="out/calib")   # as `twin calibrate`
    page = study.compare("out/calib/M1", "drive.csv")                   # as `twin compare`
    found = study.diagnose("drive.csv", assembly="M1")                  # as `twin diagnose`
    drive = dtwin.import_log("log.csv", map="map.toml", out="out/drive") # as `twin import`

Errors: dtwin.InputError (a ValueError) for bad input, with the one line `twin` prints after
'twin: error: ' (keyword arguments named instead of flags); dtwin.StorageError (an OSError) when
the disk is full; dtwin.SimulationError when a simulation fails; RuntimeError for an internal
error; TypeError for a wrong type, naming the call, the keyword and the type it expects (the types
are in each call's docstring and in dtwin.pyi). Long calls release the GIL; their progress goes to
`progress(stage, done, total)` or, by default, to sys.stderr, and the lines `twin` prints to
sys.stdout (quiet=True: none). Ctrl-C stops a call within about a second with KeyboardInterrupt,
leaving whole files only.)";

using T = ArgType;
using D = Default;

/// The calibration sizes of calibrate and diagnose (keyword-only, None: the study's).
CallSignature& sizes(CallSignature& c) {
  return c.arg("lhs_points", T::Int)
      .arg("iterations", T::Int)
      .arg("burn_in", T::Int)
      .arg("starts", T::Int);
}

/// Defines a method of dtwin.Study from its table: the table binds and checks the arguments.
template <class F>
void method(py::class_<PyStudy>& c, CallSignature sig, const std::string& summary, F&& f) {
  auto table = std::make_shared<const CallSignature>(std::move(sig));
  const std::string doc = table->doc(summary);
  c.def(
      table->name().c_str(),
      [table, f](const PyStudy& s, const py::args& args, const py::kwargs& kwargs) {
        return f(s, table->bind(args, kwargs));
      },
      doc.c_str());
}

/// dtwin.Study: the study file and its calls (simulate, calibrate, compare, diagnose).
void bindStudy(py::module_& m) {
  py::class_<PyStudy> study(m, "Study",
                            "A study file (TOML), read and checked once; errors raise "
                            "dtwin.InputError naming file, line and field.");
  auto init = std::make_shared<const CallSignature>(
      CallSignature("__init__", true, "Study").arg("path", T::Path));
  study.def(
      py::init([init](const py::args& args, const py::kwargs& kwargs) {
        return loadStudyFile(init->bind(args, kwargs));
      }),
      init->doc("Reads the study file `path` (None: the default study, dtwin.default_study()).")
          .c_str());
  study
      .def_property_readonly(
          "path", [](const PyStudy& s) { return s.study->path; }, "str: the study file.")
      .def_property_readonly(
          "name", [](const PyStudy& s) { return s.study->name; }, "str: the study's name.")
      .def_property_readonly(
          "seed", [](const PyStudy& s) { return s.study->seed; }, "int: the study's seed.")
      .def_property_readonly(
          "assemblies",
          [](const PyStudy& s) {
            py::dict out;
            for (const auto& a : s.study->assemblies()) out[py::str(a.id)] = a.label();
            return out;
          },
          "dict[str, str]: {assembly id: label}, as `twin list` names them.")
      .def_property_readonly(
          "scenarios",
          [](const PyStudy& s) {
            py::list out;
            for (const auto& sc : s.study->scenarios) out.append(sc.name);
            return out;
          },
          "list[str]: the scenario names.")
      .def(
          "to_dict", [](const PyStudy& s) { return toPython(s.study->toJson()); },
          CallSignature("to_dict", true)
              .doc("The study as read (a dict), as the `study` record of outputs.")
              .c_str())
      .def(
          "__repr__",
          [](const PyStudy& s) { return "dtwin.Study(" + literal(py::str(s.study->path)) + ")"; },
          CallSignature("__repr__", true).doc("dtwin.Study('<path>').").c_str());

  method(
      study,
      CallSignature("simulate", true)
          .arg("assembly", T::Str, D::of("M1"))
          .arg("scenario", T::Str, D::of("lab"))
          .keywordOnly()
          .arg("set", T::Settings)
          .arg("effects", T::Effects)
          .arg("seed", T::Int)
          .arg("channels", T::Names)
          .arg("window", T::Window)
          .arg("integrator", T::Str)
          .arg("accuracy", T::Float)
          .arg("max_step", T::Float)
          .arg("obstacle_step", T::Float)
          .arg("output_rate", T::Float)
          .arg("out", T::Path),
      R"(One run of an assembly over a scenario (`twin simulate`): {column: numpy array}, the columns
and rows `twin simulate --out` writes, the same values to the last bit. assembly="all": {id: columns}.
set: {"tire.stiffness": 2.0e5} or ["NAME=VALUE"]; effects: ["bump_stop:stiffness=5e6,gap_m=0.03"] or
{"bump_stop": {"stiffness": 5e6}}; channels: a list (time_s always); window: (T0, T1); out: also write
the CSV and its sidecar. Raises dtwin.SimulationError when the run fails.)",
      &simulate);

  CallSignature calibrate_sig("calibrate", true);
  calibrate_sig.arg("data", T::Path, D::required())
      .keywordOnly()
      .arg("assembly", T::Names, D::of("all"))
      .arg("out", T::Path, D::required())
      .arg("threads", T::Int, D::of(0));
  sizes(calibrate_sig)
      .arg("region", T::Str)
      .arg("design", T::Str)
      .arg("interval", T::Str)
      .arg("steps", T::Str)
      .arg("max_rounds", T::Int)
      .arg("ridge_steps", T::Int)
      .arg("seed", T::Int)
      .arg("force", T::Bool, D::of(false))
      .arg("quiet", T::Bool, D::of(false))
      .arg("progress", T::Progress);
  method(
      study, std::move(calibrate_sig),
      R"(Griddy Gibbs calibration against lab data FILE[@SCENARIO] (`twin calibrate`), each assembly into
OUT/<id>/ (a call with the same arguments resumes). Returns {id: summary}, each OUT/<id>/summary.json
as a dict. assembly: "all", "M1", "M1,M3" or a list. Ctrl-C stops it (KeyboardInterrupt).)",
      &calibrate);

  method(
      study,
      CallSignature("compare", true)
          .arg("calibration", T::Path, D::required())
          .arg("data", T::Paths, D::required())
          .keywordOnly()
          .arg("baseline", T::Paths)
          .arg("discrepancy", T::Paths)
          .arg("draws", T::Int, D::of(30))
          .arg("threads", T::Int, D::of(0))
          .arg("out", T::Path)
          .arg("force", T::Bool, D::of(false))
          .arg("quiet", T::Bool, D::of(false)),
      R"(A calibration folder's model against measurement files FILE[@SCENARIO] (`twin compare`): the
compare.json dict (fit per channel, failing windows and bands, the series). baseline: the drive(s) an
FIR from the road is fitted on; discrepancy: the drive(s) a filter from the road to the model's
residual is fitted on (the hybrid's fit and the filter in words). out: also write OUT/compare.json
and OUT/compare.html.)",
      &compare);

  CallSignature diagnose_sig("diagnose", true);
  diagnose_sig.arg("data", T::Paths, D::required())
      .keywordOnly()
      .arg("assembly", T::Str, D::of("M1"))
      .arg("holdout", T::Paths)
      .arg("effects", T::Names)
      .arg("apply", T::Names)
      .arg("candidates", T::Int, D::of(6))
      .arg("causes", T::Int, D::of(3))
      .arg("confirm_within", T::Float, D::of(2.0))
      .arg("all_intervals", T::Bool, D::of(false))
      .arg("propose", T::Int, D::of(3))
      .arg("draws", T::Int, D::of(20))
      .arg("threads", T::Int, D::of(0));
  sizes(diagnose_sig)
      .arg("steps", T::Str)
      .arg("out", T::Path)
      .arg("force", T::Bool, D::of(false))
      .arg("quiet", T::Bool, D::of(false))
      .arg("progress", T::Progress);
  method(study, std::move(diagnose_sig),
         R"(Which effect, vehicle value or sensor model the assembly misses on measurement files
FILE[@SCENARIO] (`twin diagnose`): the diagnosis.json dict. apply: add these candidates in turn.
out: the folder (a call with the same arguments resumes), with diagnosis.json, comparisons/,
calibrations/, compare.html and report.html (needs gnuplot). Ctrl-C stops it (KeyboardInterrupt).)",
         &diagnose);
}

/// dtwin.import_log: a logger's file into the twin's files (`twin import`).
void bindImport(py::module_& m) {
  auto table = std::make_shared<const CallSignature>(CallSignature("import_log", false)
                                                         .arg("log", T::Path, D::required())
                                                         .keywordOnly()
                                                         .arg("map", T::Path)
                                                         .arg("out", T::Path, D::required())
                                                         .arg("study", T::Path)
                                                         .arg("scenario", T::Str, D::of("drive"))
                                                         .arg("time", T::Str)
                                                         .arg("speed", T::Str)
                                                         .arg("road", T::Str)
                                                         .arg("road_left", T::Str)
                                                         .arg("road_right", T::Str)
                                                         .arg("road_fl", T::Str)
                                                         .arg("road_fr", T::Str)
                                                         .arg("road_rl", T::Str)
                                                         .arg("road_rr", T::Str)
                                                         .arg("channel", T::Names)
                                                         .arg("highpass_hz", T::Float)
                                                         .arg("speed_lowpass_hz", T::Float)
                                                         .arg("separator", T::Str)
                                                         .arg("window", T::Window)
                                                         .arg("run_in", T::Float)
                                                         .arg("quiet", T::Bool, D::of(false))
                                                         .arg("progress", T::Progress));
  m.def(
      "import_log",
      [table](const py::args& args, const py::kwargs& kwargs) {
        return importLog(table->bind(args, kwargs));
      },
      table
          ->doc(
              R"(A logger's CSV or MF4 log into OUT/ (measurements.csv + .json, speed.csv, road.csv, study.toml), as
`twin import`: the mapping from `map` (a TOML file) or from time/speed/road (or road_left/road_right,
or each wheel's own motion road_fl/road_fr/road_rl/road_rr, all four)/channel. Returns the
measurements.json dict; OUT/study.toml is the study that holds the drive (scenario `scenario`).)")
          .c_str());
}

}  // namespace

PYBIND11_MODULE(dtwin, m) {
  m.doc() = kModuleDoc;
  m.attr("__version__") = dtwin::kVersion;
  m.attr("git_describe") = dtwin::kGitDescribe;
  m.attr("simbody") = dtwin::kSimbody;
  // Each call's docstring starts with its text signature (CallSignature::doc), which
  // inspect.signature and help() read; pybind11's own signature line would hide it.
  py::options options;
  options.disable_function_signatures();
  registerExceptions(m);
  m.def("default_study", &defaultStudyPath,
        CallSignature("default_study", false)
            .doc("The path of the default study (data/studies/demo.toml), as `twin`'s --study "
                 "default.")
            .c_str());
  bindStudy(m);
  bindImport(m);
}
