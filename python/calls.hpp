#pragma once
// The calls of the Python module (docs/python.md): each fills the request of one library use case
// (study/) from its arguments (python/arguments.hpp, bound and type-checked by the call's table in
// module.cpp), as the `twin` command of the same name fills it from its flags, runs it with the
// GIL released (stopped by Ctrl-C), and returns what the command writes as Python objects.
#include <memory>
#include <string>

#include "python/arguments.hpp"
#include "python/bridge.hpp"
#include "study/request.hpp"

namespace dtwin::python {

/// dtwin.Study: one study file, read once.
struct PyStudy {
  std::shared_ptr<const Study> study;
};

/// dtwin.Study(path=None).
PyStudy loadStudyFile(const Arguments& a);

/// study.simulate(...): the trace(s) `twin simulate --out` writes, as numpy arrays by column.
py::object simulate(const PyStudy& s, const Arguments& a);

/// study.calibrate(...): {id: summary.json as a dict}.
py::object calibrate(const PyStudy& s, const Arguments& a);

/// study.compare(...): compare.json as a dict.
py::object compare(const PyStudy& s, const Arguments& a);

/// study.diagnose(...): diagnosis.json as a dict.
py::object diagnose(const PyStudy& s, const Arguments& a);

/// dtwin.import_log(...): the measurements.json dict of `twin import`.
py::object importLog(const Arguments& a);

}  // namespace dtwin::python
