#pragma once
// The calls of the Python module (docs/python.md): each fills the request of one library use case
// (study/) from its keyword arguments, as the `twin` command of the same name fills it from its
// flags, runs it with the GIL released, and returns what the command writes as Python objects.
#include <memory>
#include <string>

#include "io/study.hpp"
#include "python/bridge.hpp"

namespace dtwin::python {

/// dtwin.Study: one study file, read once.
struct PyStudy {
  std::shared_ptr<const Study> study;
};

PyStudy loadStudyFile(const py::object& path);

/// study.simulate(...): the trace(s) `twin simulate --out` writes, as numpy arrays by column.
py::object simulate(const PyStudy& s, const std::string& assembly, const std::string& scenario, const py::object& set,
                    const py::object& effects, const py::object& seed, const py::object& channels, const py::object& window,
                    const py::object& integrator, const py::object& accuracy, const py::object& max_step,
                    const py::object& obstacle_step, const py::object& output_rate, const py::object& out);

/// The keyword arguments of the calibration sizes and settings (study/calibrate.hpp CalibrationOverrides).
struct CalibrationKeywords {
  py::object lhs_points, iterations, burn_in, starts, region, design, interval, steps, max_rounds, ridge_steps;
};

py::object calibrate(const PyStudy& s, const py::object& data, const py::object& assembly, const py::object& out,
                     int threads, const CalibrationKeywords& sizes, const py::object& seed, bool force, bool quiet,
                     const py::object& progress);

py::object compare(const PyStudy& s, const py::object& calibration, const py::object& data, const py::object& baseline,
                   const py::object& discrepancy, int draws, int threads, const py::object& out, bool force, bool quiet);

struct DiagnoseKeywords {
  std::string assembly = "M1";
  py::object data, holdout, effects, apply, out;
  int candidates = 6, causes = 3, propose = 3, draws = 20, threads = 0;
  double confirm_within = 2.0;
  bool all_intervals = false, force = false, quiet = false;
};

py::object diagnose(const PyStudy& s, const DiagnoseKeywords& k, const CalibrationKeywords& sizes, const py::object& progress);

/// dtwin.import_log(...): the keyword arguments of `twin import`.
struct ImportKeywords {
  std::string scenario = "drive";
  py::object log, out, map, study, time, speed, road, road_left, road_right, channel, highpass_hz, speed_lowpass_hz, separator, window, run_in;
  bool quiet = false;
};
py::object importLog(const ImportKeywords& k, const py::object& progress);

}  // namespace dtwin::python
