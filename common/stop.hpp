#pragma once
// Stopping a long call from outside it (the Python module's Ctrl-C, docs/python.md). The caller
// holds a StopToken and requests the stop; the work checks the token where it can stop cleanly
// (every integrator step of a run, every progress report) and throws Stopped, which unwinds to the
// caller. Every output is written whole (writeFileAtomic) or not at all and the resumable stages
// keep their state as after a killed process, so a stopped call leaves no partial file and a new
// call with the same arguments resumes. A default-constructed token is never stopped.
#include <atomic>
#include <memory>

namespace dtwin {

/// Thrown when a stop was requested. Deliberately not a std::exception: the handlers that keep one
/// failed item from failing the whole work (a run, a candidate, a posterior draw) catch
/// std::exception and let it through; catch (...) handlers rethrow it.
struct Stopped {};

class StopToken {
 public:
  /// A token whose stop can be requested (shared by its copies).
  static StopToken make() {
    StopToken t;
    t.flag_ = std::make_shared<std::atomic<bool>>(false);
    return t;
  }
  void request() const {
    if (flag_) flag_->store(true, std::memory_order_relaxed);
  }
  bool requested() const { return flag_ && flag_->load(std::memory_order_relaxed); }
  void throwIfRequested() const {
    if (requested()) throw Stopped();
  }

 private:
  std::shared_ptr<std::atomic<bool>> flag_;
};

}  // namespace dtwin
