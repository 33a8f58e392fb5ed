#include "python/bridge.hpp"

#include <dlfcn.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <thread>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace dtwin::python {

// ------------------------------------------------------------------ exceptions
namespace {
Exceptions& exceptionSlots() {
  static Exceptions* e =
      new Exceptions();  // never destroyed: Python objects outlive no interpreter
  return *e;
}
}  // namespace

const Exceptions& exceptions() { return exceptionSlots(); }

void registerExceptions(py::module_& m) {
  Exceptions& e = exceptionSlots();
  const auto make = [&](const char* name, PyObject* base, const char* doc) {
    py::object type = py::reinterpret_steal<py::object>(
        PyErr_NewExceptionWithDoc((std::string("dtwin.") + name).c_str(), doc, base, nullptr));
    if (!type) throw py::error_already_set();
    m.add_object(name, type);
    return type;
  };
  e.input_error = make("InputError", PyExc_ValueError,
                       "Bad input (a file, a field, an argument, a value): the one line `twin` "
                       "prints after 'twin: error: '.");
  e.storage_error = make("StorageError", PyExc_OSError,
                         "A write failed because the disk (or the quota) is full.");
  e.simulation_error = make("SimulationError", PyExc_RuntimeError,
                            "A simulation failed (its step or wall-clock budget, divergence).");
}

std::string Keywords::message(const std::string& where, const std::string& rule) const {
  const auto plain = [&] { return where.empty() ? rule : where + ": " + rule; };
  if (where.rfind("--", 0) == 0) {  // a command-line flag, possibly followed by its value
    const auto space = where.find(' ');
    std::string name = where.substr(2, space == std::string::npos ? std::string::npos : space - 2);
    for (char& c : name)
      if (c == '-') c = '_';
    if (auto it = fields.find(name); it != fields.end()) name = it->second;
    if (!names.count(name)) return plain();
    return name + (space == std::string::npos ? "" : where.substr(space)) + ": " + rule;
  }
  const auto dot = where.rfind('.');
  // Only "<options>.<field>" (no path, no spaces) is an option field.
  if (dot == std::string::npos || where.find_first_of(" /:") != std::string::npos) return plain();
  std::string name = where.substr(dot + 1);
  if (auto it = fields.find(name); it != fields.end()) name = it->second;
  if (!names.count(name)) return plain();
  return name + ": " + rule;
}

// ------------------------------------------------------------------ callbacks
struct Callbacks::State {
  py::object progress;  ///< None or a callable
  bool quiet = false;
  StopToken stop = StopToken::make();
  std::mutex mutex;
  std::optional<py::error_already_set> error;  ///< what a callback or a signal handler raised
  // The default progress: a line on sys.stderr at most every kLineEvery, and one at a stage's end.
  std::string stage;
  std::chrono::steady_clock::time_point last_line{}, stage_start{};
  bool stage_printed = false;
  void keep(py::error_already_set& e) {  // with the GIL held
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error.emplace(std::move(e));
    }
    stop.request();
  }
};

namespace {
constexpr auto kLineEvery = std::chrono::seconds(10);
constexpr auto kSignalEvery = std::chrono::milliseconds(50);

void writeTo(const char* stream, const std::string& text) {
  py::module_::import("sys").attr(stream).attr("write")(text);
}
}  // namespace

Callbacks::Callbacks(py::object progress, bool quiet) : state_(std::make_shared<State>()) {
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress: must be None or a callable (stage, done, total)");
  state_->progress = std::move(progress);
  state_->quiet = quiet;
}

Callbacks::~Callbacks() {
  // The Python objects are released with the GIL held (the destructor runs in the binding).
  py::gil_scoped_acquire gil;
  state_->error.reset();
  state_->progress = py::object();
}

const StopToken& Callbacks::stop() const { return state_->stop; }

StageProgress Callbacks::progress() {
  const bool silent = state_->progress.is_none() && state_->quiet;
  return [state = state_, silent](const std::string& stage, std::size_t done, std::size_t total) {
    state->stop.throwIfRequested();
    if (silent) return;
    py::gil_scoped_acquire gil;
    try {
      if (!state->progress.is_none()) {
        state->progress(stage, done, total);
        return;
      }
      const auto now = std::chrono::steady_clock::now();
      if (stage != state->stage) {
        state->stage = stage;
        state->stage_start = now;
        state->last_line = now;
        state->stage_printed = false;
      }
      const bool closing = done >= total && state->stage_printed;
      if (!closing && now - state->last_line < kLineEvery) return;
      state->last_line = now;
      state->stage_printed = !closing;
      const double elapsed = std::chrono::duration<double>(now - state->stage_start).count();
      char line[96];
      std::snprintf(line, sizeof line, ": %zu/%zu %.0f%% (%.0f s)\n", done, total,
                    100.0 * (total ? static_cast<double>(done) / static_cast<double>(total) : 1.0),
                    elapsed);
      writeTo("stderr", stage + line);
    } catch (py::error_already_set& e) {
      state->keep(e);
      throw Stopped();
    }
  };
}

SayFn Callbacks::say() {
  if (state_->quiet) return {};
  return [state = state_](const std::string& line) {
    state->stop.throwIfRequested();
    py::gil_scoped_acquire gil;
    try {
      writeTo("stdout", line + "\n");
    } catch (py::error_already_set& e) {
      state->keep(e);
      throw Stopped();
    }
  };
}

void Callbacks::stopWithPythonError() {
  py::error_already_set e;  // takes the error indicator
  state_->keep(e);
}

void Callbacks::raiseIfCallbackRaised() {
  std::optional<py::error_already_set> e;
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    e.swap(state_->error);
  }
  if (e) throw std::move(*e);
}

// ------------------------------------------------------------------ errors
namespace {
[[noreturn]] void raiseAs(const py::object& type, const std::string& message) {
  PyErr_SetString(type.ptr(), message.c_str());
  throw py::error_already_set();
}

/// Runs `work` on a thread of its own; the calling thread (GIL released) wakes every kSignalEvery
/// to run Python's signal handlers with the GIL held. Returns what `work` threw.
std::exception_ptr runWatched(const std::function<void()>& work, Callbacks& callbacks) {
  // Python runs signal handlers on the main thread only: elsewhere there is nothing to watch.
  const py::module_ threading = py::module_::import("threading");
  const bool watch = threading.attr("current_thread")().is(threading.attr("main_thread")());
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::exception_ptr failure;
  py::gil_scoped_release release;
  std::thread worker([&] {
    try {
      work();
    } catch (...) {
      failure = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(m);
    done = true;
    cv.notify_one();
  });
  std::unique_lock<std::mutex> lock(m);
  while (!cv.wait_for(lock, kSignalEvery, [&] { return done; })) {
    if (!watch || callbacks.stop().requested()) continue;  // stopping: wait for the work to end
    lock.unlock();
    {
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) callbacks.stopWithPythonError();
    }
    lock.lock();
  }
  lock.unlock();
  worker.join();
  return failure;
}
}  // namespace

void runReleased(const std::function<void()>& work, const Keywords& keywords,
                 Callbacks* callbacks) {
  // The library's exceptions leave the released section before they are translated: Python's
  // error state is set with the GIL held.
  std::exception_ptr failure;
  if (callbacks) {
    failure = runWatched(work, *callbacks);
  } else {
    py::gil_scoped_release release;
    try {
      work();
    } catch (...) {
      failure = std::current_exception();
    }
  }
  if (callbacks)
    callbacks->raiseIfCallbackRaised();  // a callback's or a signal handler's exception comes first
  if (!failure) return;
  try {
    std::rethrow_exception(failure);
  } catch (const InputError& e) {
    raiseAs(exceptions().input_error, oneLine(keywords.message(e.where(), e.rule())));
  } catch (const StorageError& e) {
    raiseAs(exceptions().storage_error,
            oneLine(std::string(e.what()) + "; free space and call again"));
  } catch (py::error_already_set&) {
    throw;
  } catch (const std::exception& e) {
    raiseAs(py::reinterpret_borrow<py::object>(PyExc_RuntimeError),
            oneLine(internalErrorText(e.what())));
  } catch (const Stopped&) {
    raiseAs(py::reinterpret_borrow<py::object>(PyExc_RuntimeError),
            "internal error: the call stopped with no exception to raise");
  }
}

// ------------------------------------------------------------------ conversions
py::object toPython(const nlohmann::json& j) {
  using T = nlohmann::json::value_t;
  switch (j.type()) {
    case T::null:
    case T::discarded:
      return py::none();
    case T::boolean:
      return py::bool_(j.get<bool>());
    case T::number_integer:
      return py::int_(j.get<std::int64_t>());
    case T::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case T::number_float: {
      const double x = j.get<double>();
      return std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none());
    }
    case T::string:
      return py::str(j.get_ref<const std::string&>());
    case T::array: {
      py::list out(j.size());
      std::size_t i = 0;
      for (const auto& v : j) out[i++] = toPython(v);
      return std::move(out);
    }
    case T::object: {
      py::dict out;
      for (auto it = j.begin(); it != j.end(); ++it) out[py::str(it.key())] = toPython(it.value());
      return std::move(out);
    }
    case T::binary: {
      const auto& b = j.get_binary();
      return py::bytes(reinterpret_cast<const char*>(b.data()), b.size());
    }
  }
  return py::none();
}

std::string pathText(const py::handle& value, const std::string& keyword) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) {
    const py::object p = py::module_::import("os").attr("fspath")(value);
    if (py::isinstance<py::str>(p)) return p.cast<std::string>();
  }
  throw py::type_error(keyword + ": expects a str or a path, got " +
                       py::str(py::type::handle_of(value)).cast<std::string>());
}

std::vector<std::string> stringList(const py::object& value, const std::string& keyword) {
  std::vector<std::string> out;
  if (value.is_none()) return out;
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"))
    return {pathText(value, keyword)};
  for (const auto& v : value)
    out.push_back(pathText(v, keyword));  // a sequence (checked by the call's arguments)
  return out;
}

std::string literal(const py::handle& value) { return py::repr(value).cast<std::string>(); }

std::string defaultStudyPath() {
  // The module's own folder: <prefix>/lib/python3.X/dist-packages/ after `cmake --install`
  // (data in <prefix>/share/dtwin/data), or the package folder dtwin/ of the wheel (data beside
  // it).
  std::vector<std::string> dirs{DTWIN_SOURCE_DATA_DIR};
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&defaultStudyPath), &info) != 0 && info.dli_fname != nullptr) {
    std::error_code ec;
    const std::filesystem::path here = std::filesystem::canonical(info.dli_fname, ec).parent_path();
    if (!ec) {
      dirs.push_back((here / "data").string());
      dirs.push_back(
          (here.parent_path().parent_path().parent_path() / "share" / "dtwin" / "data").string());
    }
  }
  dirs.push_back(DTWIN_INSTALL_DATA_DIR);
  for (const std::string& dir : dirs) {
    const std::filesystem::path p = std::filesystem::path(dir) / "studies" / "demo.toml";
    if (std::filesystem::exists(p)) return p.string();
  }
  return "data/studies/demo.toml";
}

}  // namespace dtwin::python
