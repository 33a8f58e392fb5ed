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

/// How one call names its inputs in errors: the library names option fields ("calibration.gibbs_burn_in")
/// and some command-line flags ("--data"); a call shows them as its keyword arguments.
struct Keywords {
  std::set<std::string> names;                ///< the call's keyword arguments
  std::map<std::string, std::string> fields;  ///< option field -> keyword, where they differ
  /// The one-line message of an InputError as this call's user should read it.
  std::string message(const std::string& where, const std::string& rule) const;
};

/// Raised inside a library call when a Python callback raised (its Python error is kept by the
/// Callbacks object that threw it and raised again once the call returns).
struct CallbackRaised : std::runtime_error {
  CallbackRaised() : std::runtime_error("a Python callback raised an exception") {}
};

/// The progress callback and the printed lines of one long call. Built with the GIL held; the
/// functions it hands out may be called from any thread while the GIL is released: each takes
/// the GIL for its Python work. A Python exception in a callback (KeyboardInterrupt included,
/// seen by the progress calls made on the main thread) stops the call and is raised when it returns.
class Callbacks {
 public:
  /// `progress`: None (lines on sys.stderr unless `quiet`) or a callable (stage, done, total).
  Callbacks(py::object progress, bool quiet);
  ~Callbacks();
  StageProgress progress();
  /// A line on sys.stdout (the lines `twin` prints), unless quiet.
  SayFn say();
  /// Raises the kept Python error, if a callback raised.
  void raiseIfCallbackRaised();

 private:
  struct State;
  std::shared_ptr<State> state_;
};

/// Runs `work` with the GIL released and turns the library's errors into the module's
/// exceptions (InputError -> dtwin.InputError with `keywords`' message, StorageError ->
/// dtwin.StorageError, anything else -> RuntimeError "internal error: ..."), the `twin`
/// program's classes. `callbacks` (may be null) re-raise a callback's own exception.
void runReleased(const std::function<void()>& work, const Keywords& keywords, Callbacks* callbacks = nullptr);

/// A JSON value as Python objects (dict, list, str, int, float, bool, None); a number that is
/// not finite becomes None, as in the files the library writes.
py::object toPython(const nlohmann::json& j);

/// A path given as a str or an os.PathLike (pathlib.Path); TypeError naming `keyword` otherwise.
std::string pathText(const py::handle& value, const std::string& keyword);
/// A str or path, or a list/tuple of them, as strings (None: empty).
std::vector<std::string> stringList(const py::object& value, const std::string& keyword);
/// `value` written as a Python literal, for the command recorded in outputs.
std::string literal(const py::handle& value);

/// The default study: data/studies/demo.toml in the source tree, else the install prefix.
std::string defaultStudyPath();

}  // namespace dtwin::python
