#pragma once
// What the Python module's bindings share (docs/python.md): the module's exception types, the
// translation of the library's errors into them, JSON into Python objects, and the progress and
// message sinks of long calls. Like cli/, python/ only parses, calls the library and converts.
#include <pybind11/pybind11.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/json.hpp"
#include "common/progress.hpp"
#include "common/stop.hpp"

namespace dtwin::python {

namespace py = pybind11;

/// The exception types of the module, created once at import (registerExceptions).
struct Exceptions {
  py::object input_error;       ///< dtwin.InputError(ValueError): bad input, `twin`'s exit code 2
  py::object storage_error;     ///< dtwin.StorageError(OSError): the disk filled
  py::object simulation_error;  ///< dtwin.SimulationError(RuntimeError): a run failed
};
const Exceptions& exceptions();
void registerExceptions(py::module_& m);

/// How one call names its inputs in errors: the library names option fields
/// ("calibration.gibbs_burn_in") and some command-line flags ("--data"); a call shows them as its
/// keyword arguments.
struct Keywords {
  std::set<std::string> names;                ///< the call's keyword arguments
  std::map<std::string, std::string> fields;  ///< option field -> keyword, where they differ
  /// The one-line message of an InputError as this call's user should read it.
  std::string message(const std::string& where, const std::string& rule) const;
};

/// The progress callback, the printed lines and the stop of one long call. Built with the GIL
/// held; the functions it hands out may be called from any thread while the GIL is released: each
/// takes the GIL for its Python work. A Python exception in a callback, or one raised by a signal
/// handler while the call runs (Ctrl-C: KeyboardInterrupt), requests the stop (stop()): the work
/// throws Stopped at its next progress report or integrator step, and the exception is raised when
/// the call returns.
class Callbacks {
 public:
  /// `progress`: None (lines on sys.stderr unless `quiet`) or a callable (stage, done, total).
  Callbacks(py::object progress, bool quiet);
  ~Callbacks();
  /// Never empty: even a quiet call reports to it, as it checks the stop.
  StageProgress progress();
  /// A line on sys.stdout (the lines `twin` prints), unless quiet.
  SayFn say();
  /// The call's stop: pass it to the simulation options of the work (SimulationOptions::stop).
  const StopToken& stop() const;
  /// With the GIL held: keeps the Python error now set (PyErr_Occurred) and requests the stop.
  void stopWithPythonError();
  /// Raises the kept Python error, if a callback or a signal handler raised.
  void raiseIfCallbackRaised();

 private:
  struct State;
  std::shared_ptr<State> state_;
};

/// Runs `work` with the GIL released and turns the library's errors into the module's
/// exceptions (InputError -> dtwin.InputError with `keywords`' message, StorageError ->
/// dtwin.StorageError, anything else -> RuntimeError "internal error: ..."), the `twin`
/// program's classes. With `callbacks`, `work` runs on a thread of its own while the calling
/// thread runs Python's signal handlers every 50 ms (PyErr_CheckSignals: on the main thread, Ctrl-C
/// raises KeyboardInterrupt there): an exception they raise stops the work through
/// callbacks->stop(), and it, or a callback's own exception, is raised once the work has ended.
void runReleased(const std::function<void()>& work, const Keywords& keywords,
                 Callbacks* callbacks = nullptr);

/// A JSON value as Python objects (dict, list, str, int, float, bool, None); a number that is
/// not finite becomes None, as in the files the library writes.
py::object toPython(const nlohmann::json& j);

/// A path given as a str or an os.PathLike (pathlib.Path); TypeError naming `keyword` otherwise.
std::string pathText(const py::handle& value, const std::string& keyword);
/// A str or path, or a list/tuple of them, as strings (None: empty).
std::vector<std::string> stringList(const py::object& value, const std::string& keyword);
/// `value` written as a Python literal, for the command recorded in outputs.
std::string literal(const py::handle& value);

/// The default study: data/studies/demo.toml in the source tree, else beside the module (the
/// wheel's dtwin/data, an install prefix's share/dtwin/data), else the configured install prefix.
std::string defaultStudyPath();

}  // namespace dtwin::python
