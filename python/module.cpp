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
error. Long calls release the GIL; their progress goes to `progress(stage, done, total)` or, by
default, to sys.stderr, and the lines `twin` prints to sys.stdout (quiet=True: none).)";

CalibrationKeywords sizesOf(py::object lhs_points, py::object iterations, py::object burn_in, py::object starts, py::object region,
                            py::object design, py::object interval, py::object steps, py::object max_rounds, py::object ridge_steps) {
  return {std::move(lhs_points), std::move(iterations), std::move(burn_in), std::move(starts), std::move(region),
          std::move(design), std::move(interval), std::move(steps), std::move(max_rounds), std::move(ridge_steps)};
}

}  // namespace

namespace {

/// dtwin.Study: the study file and its calls (simulate, calibrate, compare, diagnose).
void bindStudy(py::module_& m) {
  py::class_<PyStudy>(m, "Study", "A study file (TOML), read and checked once; errors raise dtwin.InputError naming file, line and field.")
      .def(py::init(&loadStudyFile), py::arg("path") = py::none(), "Reads the study file `path` (None: the default study).")
      .def_property_readonly("path", [](const PyStudy& s) { return s.study->path; })
      .def_property_readonly("name", [](const PyStudy& s) { return s.study->name; })
      .def_property_readonly("seed", [](const PyStudy& s) { return s.study->seed; })
      .def_property_readonly(
          "assemblies",
          [](const PyStudy& s) {
            py::dict out;
            for (const auto& a : s.study->assemblies()) out[py::str(a.id)] = a.label();
            return out;
          },
          "{assembly id: label}, as `twin list` names them.")
      .def_property_readonly(
          "scenarios",
          [](const PyStudy& s) {
            py::list out;
            for (const auto& sc : s.study->scenarios) out.append(sc.name);
            return out;
          },
          "The scenario names.")
      .def("to_dict", [](const PyStudy& s) { return toPython(s.study->toJson()); }, "The study as read, as the `study` record of outputs.")
      .def("__repr__", [](const PyStudy& s) { return "dtwin.Study(" + literal(py::str(s.study->path)) + ")"; })
      .def("simulate", &simulate, py::arg("assembly") = "M1", py::arg("scenario") = "lab", py::kw_only(), py::arg("set") = py::none(),
           py::arg("effects") = py::none(), py::arg("seed") = py::none(), py::arg("channels") = py::none(), py::arg("window") = py::none(),
           py::arg("integrator") = py::none(), py::arg("accuracy") = py::none(), py::arg("max_step") = py::none(),
           py::arg("obstacle_step") = py::none(), py::arg("output_rate") = py::none(), py::arg("out") = py::none(),
           R"(One run of an assembly over a scenario (`twin simulate`): {column: numpy array}, the columns
and rows `twin simulate --out` writes, the same values to the last bit. assembly="all": {id: columns}.
set: {"tire.stiffness": 2.0e5} or ["NAME=VALUE"]; effects: ["bump_stop:stiffness=5e6,gap_m=0.03"] or
{"bump_stop": {"stiffness": 5e6}}; channels: a list (time_s always); window: (T0, T1); out: also write
the CSV and its sidecar. Raises dtwin.SimulationError when the run fails.)")
      .def(
          "calibrate",
          [](const PyStudy& s, const py::object& data, const py::object& assembly, const py::object& out, int threads, py::object lhs_points,
             py::object iterations, py::object burn_in, py::object starts, py::object region, py::object design, py::object interval,
             py::object steps, py::object max_rounds, py::object ridge_steps, const py::object& seed, bool force, bool quiet,
             const py::object& progress) {
            return calibrate(s, data, assembly, out, threads,
                             sizesOf(lhs_points, iterations, burn_in, starts, region, design, interval, steps, max_rounds, ridge_steps), seed,
                             force, quiet, progress);
          },
          py::arg("data"), py::kw_only(), py::arg("assembly") = "all", py::arg("out"), py::arg("threads") = 0,
          py::arg("lhs_points") = py::none(), py::arg("iterations") = py::none(), py::arg("burn_in") = py::none(),
          py::arg("starts") = py::none(), py::arg("region") = py::none(), py::arg("design") = py::none(), py::arg("interval") = py::none(),
          py::arg("steps") = py::none(), py::arg("max_rounds") = py::none(), py::arg("ridge_steps") = py::none(), py::arg("seed") = py::none(),
          py::arg("force") = false, py::arg("quiet") = false, py::arg("progress") = py::none(),
          R"(Griddy Gibbs calibration against lab data FILE[@SCENARIO] (`twin calibrate`), each assembly into
OUT/<id>/ (a call with the same arguments resumes). Returns {id: summary}, each OUT/<id>/summary.json
as a dict. assembly: "all", "M1", "M1,M3" or a list.)")
      .def("compare", &compare, py::arg("calibration"), py::arg("data"), py::kw_only(), py::arg("baseline") = py::none(),
           py::arg("discrepancy") = py::none(), py::arg("draws") = 30, py::arg("threads") = 0, py::arg("out") = py::none(), py::arg("force") = false, py::arg("quiet") = false,
           R"(A calibration folder's model against measurement files FILE[@SCENARIO] (`twin compare`): the
compare.json dict (fit per channel, failing windows and bands, the series). baseline: the drive(s) an
FIR from the road is fitted on; discrepancy: the drive(s) a filter from the road to the model's
residual is fitted on (the hybrid's fit and the filter in words). out: also write OUT/compare.json
and OUT/compare.html.)")
      .def(
          "diagnose",
          [](const PyStudy& s, const py::object& data, const std::string& assembly, const py::object& holdout, const py::object& effects,
             const py::object& apply, int candidates, int causes, double confirm_within, bool all_intervals, int propose, int draws,
             int threads, py::object lhs_points, py::object iterations, py::object burn_in, py::object starts, py::object steps,
             const py::object& out, bool force, bool quiet, const py::object& progress) {
            DiagnoseKeywords k;
            k.assembly = assembly;
            k.data = data;
            k.holdout = holdout;
            k.effects = effects;
            k.apply = apply;
            k.out = out;
            k.candidates = candidates;
            k.causes = causes;
            k.propose = propose;
            k.draws = draws;
            k.threads = threads;
            k.confirm_within = confirm_within;
            k.all_intervals = all_intervals;
            k.force = force;
            k.quiet = quiet;
            const py::object none = py::none();
            return diagnose(s, k, sizesOf(lhs_points, iterations, burn_in, starts, none, none, none, steps, none, none), progress);
          },
          py::arg("data"), py::kw_only(), py::arg("assembly") = "M1", py::arg("holdout") = py::none(), py::arg("effects") = py::none(),
          py::arg("apply") = py::none(), py::arg("candidates") = 6, py::arg("causes") = 3, py::arg("confirm_within") = 2.0,
          py::arg("all_intervals") = false, py::arg("propose") = 3, py::arg("draws") = 20, py::arg("threads") = 0,
          py::arg("lhs_points") = py::none(), py::arg("iterations") = py::none(), py::arg("burn_in") = py::none(),
          py::arg("starts") = py::none(), py::arg("steps") = py::none(), py::arg("out") = py::none(), py::arg("force") = false,
          py::arg("quiet") = false, py::arg("progress") = py::none(),
          R"(Which effect, vehicle value or sensor model the assembly misses on measurement files
FILE[@SCENARIO] (`twin diagnose`): the diagnosis.json dict. apply: add these candidates in turn.
out: the folder (a call with the same arguments resumes), with diagnosis.json, comparisons/,
calibrations/, compare.html and report.html (needs gnuplot).)");
}

/// dtwin.import_log: a logger's file into the twin's files (`twin import`).
void bindImport(py::module_& m) {
  m.def(
      "import_log",
      [](const py::object& log, const py::object& map, const py::object& out, const py::object& study, const std::string& scenario,
         const py::object& time, const py::object& speed, const py::object& road, const py::object& road_left,
         const py::object& road_right, const py::object& channel, const py::object& highpass_hz, const py::object& speed_lowpass_hz,
         const py::object& separator, const py::object& window, const py::object& run_in, bool quiet, const py::object& progress) {
        ImportKeywords k;
        k.log = log;
        k.map = map;
        k.out = out;
        k.study = study;
        k.scenario = scenario;
        k.time = time;
        k.speed = speed;
        k.road = road;
        k.road_left = road_left;
        k.road_right = road_right;
        k.channel = channel;
        k.highpass_hz = highpass_hz;
        k.speed_lowpass_hz = speed_lowpass_hz;
        k.separator = separator;
        k.window = window;
        k.run_in = run_in;
        k.quiet = quiet;
        return importLog(k, progress);
      },
      py::arg("log"), py::kw_only(), py::arg("map") = py::none(), py::arg("out"), py::arg("study") = py::none(),
      py::arg("scenario") = "drive", py::arg("time") = py::none(), py::arg("speed") = py::none(), py::arg("road") = py::none(),
      py::arg("road_left") = py::none(), py::arg("road_right") = py::none(), py::arg("channel") = py::none(),
      py::arg("highpass_hz") = py::none(), py::arg("speed_lowpass_hz") = py::none(), py::arg("separator") = py::none(),
      py::arg("window") = py::none(), py::arg("run_in") = py::none(), py::arg("quiet") = false, py::arg("progress") = py::none(),
      R"(A logger's CSV or MF4 log into OUT/ (measurements.csv + .json, speed.csv, road.csv, study.toml), as
`twin import`: the mapping from `map` (a TOML file) or from time/speed/road/channel. Returns the
measurements.json dict; OUT/study.toml is the study that holds the drive (scenario `scenario`).)");
}

}  // namespace

PYBIND11_MODULE(dtwin, m) {
  m.doc() = kModuleDoc;
  m.attr("__version__") = dtwin::kVersion;
  m.attr("git_describe") = dtwin::kGitDescribe;
  m.attr("simbody") = dtwin::kSimbody;
  registerExceptions(m);
  m.def("default_study", &defaultStudyPath, "The path of the default study (data/studies/demo.toml), as `twin`'s --study default.");
  bindStudy(m);
  bindImport(m);
}
