#pragma once
// Running one program on several processes (MPI ranks, possibly on several machines).
//
//   mpirun -n K twin study --study data/studies/paper.toml --out /shared/study --threads T
//
// The same binary runs alone or under an MPI launcher (docs/cluster.md). The program (main)
// creates the one Distributed object and passes a pointer to it down to every call that spreads
// work, as options.processes (the process context, passed explicitly like Drake's contexts: no
// library code reaches for a process-wide instance). A null pointer, or an object without MPI
// (not started by a launcher, or the project built without MPI: DTWIN_HAVE_MPI undefined), is one
// process, rank 0 of size 1, and every function here is then a plain local call.
//
// The collective that spreads simulations:
//
//   auto results = distributedMap(processes, n, threads, [&](std::size_t i, int worker) ->
//   std::vector<double> {
//     ... simulate task i, using state private to `worker` ...
//   });
//
// Task i runs on rank i % size (inside a rank on `threads` workers through parallelFor, so worker
// ids are < distributedWorkers(n, threads)); every rank receives all n result vectors, in index
// order. Tasks draw their random numbers from streams derived from (seed, stream, index) and
// their results are stored by index, so the numbers never depend on the rank or thread count.
// An exception in a task reaches every rank: the one of the lowest failing index is rethrown
// everywhere (InputError, RunFailedError, std::logic_error and std::runtime_error keep their type
// and message on the other ranks; any other type arrives as std::runtime_error with its what()).
//
// Rules for callers (what keeps the ranks in step):
//  * every rank calls the same collectives (distributedMap, onRoot, barrier) in the same order,
//    from the main thread (MPI_THREAD_FUNNELED);
//  * only the root (rank 0) writes files and prints; a decision that depends on a file (resume)
//    is taken from what the root read (onRoot), never from each rank's own view of a shared
//    filesystem;
//  * main() creates the Distributed object, calls init() first and returns finish(rc, message): an
//  error on any rank ends the
//    whole job (MPI_Abort after a grace period) instead of leaving the others waiting forever.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/parallel.hpp"

namespace dtwin {

class Distributed {
 public:
  /// One process (rank 0 of size 1) until init() starts MPI.
  Distributed();
  ~Distributed();
  /// True when this library was built with MPI (DTWIN_HAVE_MPI).
  static bool builtWithMpi();

  /// Starts MPI (MPI_Init_thread, MPI_THREAD_FUNNELED) when the program was started by an MPI
  /// launcher (OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK in the environment) and the library
  /// was built with MPI; otherwise the process stays a single rank. DTWIN_NO_MPI=1 forces a
  /// single rank. On ranks other than 0 stdout and stderr are sent to /dev/null (only the root
  /// prints; a rank's own fatal error still reaches the terminal, see finish()). Call once, first.
  void init(int* argc, char*** argv);
  /// Ends MPI: waits until every rank got here and returns the exit code of the job (the root's,
  /// or the first non-zero one of another rank). A rank with rc != 0 whose partners do not arrive
  /// within a grace period (120 s) prints `message` with its rank and aborts the job
  /// (MPI_Abort), so that mpirun never hangs. Without MPI: returns rc.
  int finish(int rc, const std::string& message);

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }
  /// Ranks on this machine (1 without MPI).
  int localSize() const { return local_size_; }
  /// Worker threads a rank uses for `requested` (<= 0: all cores of the machine shared evenly
  /// among its ranks, at least 1; > 0: as given).
  int threadsPerRank(int requested) const;

  // ---- collectives: every rank, same order, main thread
  void barrier() const;
  /// Root's payload on every rank; if `error` is set on the root, every rank throws it.
  std::string broadcastFromRoot(const std::string& payload, const std::exception_ptr& error) const;
  /// Fills `out` (size n) with every rank's results (task i from rank i % size) after a map in
  /// which this rank computed its own entries; `local_fail` is the lowest failing task index of
  /// this rank (or -1) and `error` its exception. Throws the lowest failing task's error on
  /// every rank.
  void gatherMap(std::vector<std::vector<double>>& out, long long local_fail,
                 const std::exception_ptr& error) const;
  /// Point to point, for reductions along a tree of ranks: `values` to rank `to`, which must call
  /// receiveDoubles(from this rank). Any length (sent in pieces of at most 2^27 doubles).
  void sendDoubles(int to, const std::vector<double>& values) const;
  std::vector<double> receiveDoubles(int from) const;

  Distributed(const Distributed&) = delete;
  Distributed& operator=(const Distributed&) = delete;

 private:
  struct Comms;  // the MPI communicators (distributed.cpp)
  std::unique_ptr<Comms> comms_;
  int rank_ = 0, size_ = 1, local_size_ = 1;
  bool mpi_ = false;
  int saved_stderr_ = -1;
};

/// The rank, size, root test and worker threads of the process context `processes` (nullptr:
/// this process alone, rank 0 of size 1).
inline int processRank(const Distributed* processes) { return processes ? processes->rank() : 0; }
inline int processCount(const Distributed* processes) { return processes ? processes->size() : 1; }
inline bool isRootProcess(const Distributed* processes) { return processRank(processes) == 0; }
inline int threadsPerProcess(const Distributed* processes, int requested) {
  return processes ? processes->threadsPerRank(requested) : requested;
}

/// An exception as bytes (type, message, fields) and back: what carries a task's error to the
/// other ranks.
std::string encodeException(const std::exception_ptr& e);
[[noreturn]] void throwEncoded(const std::string& bytes);

/// Upper bound (exclusive) of the worker ids distributedMap passes to its task.
inline int distributedWorkers(const Distributed* processes, std::size_t n, int threads) {
  return workerCount(threadsPerProcess(processes, threads), n);
}

/// See the top of this file. `progress(done, n)` (optional) is called one call at a time as this
/// rank's tasks finish (done estimated from this rank's share under MPI), and with (n, n) at the
/// end.
template <class F>
std::vector<std::vector<double>> distributedMap(
    const Distributed* processes, std::size_t n, int threads, F f,
    const std::function<void(std::size_t, std::size_t)>& progress = nullptr) {
  const std::size_t size = static_cast<std::size_t>(processCount(processes)),
                    rank = static_cast<std::size_t>(processRank(processes));
  std::vector<std::vector<double>> out(n);
  std::mutex m;
  std::size_t done = 0;
  auto tick = [&]() {
    if (!progress) return;
    std::lock_guard<std::mutex> lock(m);
    ++done;
    progress(std::min(n, done * size), n);
  };
  if (processes == nullptr || size == 1) {
    parallelFor(n, threadsPerProcess(processes, threads), [&](std::size_t i, int w) {
      out[i] = f(i, w);
      tick();
    });
    return out;
  }
  const std::size_t local_n = n > rank ? (n - rank + size - 1) / size : 0;
  long long local_fail = -1;
  std::exception_ptr error;
  try {
    parallelFor(local_n, processes->threadsPerRank(threads), [&](std::size_t k, int w) {
      const std::size_t i = rank + k * size;
      try {
        out[i] = f(i, w);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        if (local_fail < 0 || static_cast<long long>(i) < local_fail)
          local_fail = static_cast<long long>(i);
        throw;
      }
      tick();
    });
  } catch (...) {
    error = std::current_exception();  // parallelFor rethrows the lowest failing index's
  }
  processes->gatherMap(out, local_fail, error);
  if (progress) progress(n, n);
  return out;
}

/// Runs f() (returning a std::string) on the root only and returns its result on every rank; an
/// exception f throws is rethrown on every rank. The way to base a decision on a file: the root
/// reads it, every rank gets the same bytes.
template <class F>
std::string onRoot(const Distributed* processes, F f) {
  if (processes == nullptr || processes->size() == 1) return f();
  std::string payload;
  std::exception_ptr error;
  if (processes->isRoot()) {
    try {
      payload = f();
    } catch (...) {
      error = std::current_exception();
    }
  }
  return processes->broadcastFromRoot(payload, error);
}

/// Runs `write` on the root only (the only rank that writes files); its error reaches every rank.
template <class F>
void rootWrites(const Distributed* processes, F write) {
  onRoot(processes, [&]() -> std::string {
    write();
    return std::string();
  });
}

/// A file's bytes as the root reads them (InputError if it cannot be read), on every rank: files
/// the root wrote in this run are never read from another rank's view of a shared filesystem.
std::string rootFileBytes(const Distributed* processes, const std::string& path);

/// Packing of mixed values into the doubles distributedMap carries (integers up to 2^53 exactly,
/// strings byte by byte).
class Packer {
 public:
  Packer& put(double v) {
    v_.push_back(v);
    return *this;
  }
  Packer& put(const std::vector<double>& v) {
    v_.push_back(static_cast<double>(v.size()));
    v_.insert(v_.end(), v.begin(), v.end());
    return *this;
  }
  Packer& put(const std::string& s) {
    v_.push_back(static_cast<double>(s.size()));
    for (unsigned char c : s) v_.push_back(c);
    return *this;
  }
  std::vector<double> take() { return std::move(v_); }

 private:
  std::vector<double> v_;
};

class Unpacker {
 public:
  explicit Unpacker(const std::vector<double>& v) : v_(v) {}
  double num() { return at(); }
  long long integer() { return static_cast<long long>(at()); }
  std::vector<double> vec() {
    const std::size_t k = static_cast<std::size_t>(at());
    check(k);
    std::vector<double> r(v_.begin() + static_cast<long>(pos_),
                          v_.begin() + static_cast<long>(pos_ + k));
    pos_ += k;
    return r;
  }
  std::string str() {
    const std::size_t k = static_cast<std::size_t>(at());
    check(k);
    std::string s(k, '\0');
    for (std::size_t j = 0; j < k; ++j)
      s[j] = static_cast<char>(static_cast<unsigned char>(v_[pos_ + j]));
    pos_ += k;
    return s;
  }

 private:
  double at() {
    check(1);
    return v_[pos_++];
  }
  void check(std::size_t k) const {
    if (pos_ + k > v_.size())
      throw std::logic_error("internal error: Unpacker read past the end of a packed result");
  }
  const std::vector<double>& v_;
  std::size_t pos_ = 0;
};

/// Doubles as raw bytes in a std::string and back (for onRoot payloads).
inline std::string doublesToBytes(const std::vector<double>& v) {
  std::string s(v.size() * sizeof(double), '\0');
  if (!v.empty()) std::memcpy(&s[0], v.data(), s.size());
  return s;
}
inline std::vector<double> bytesToDoubles(const std::string& s) {
  std::vector<double> v(s.size() / sizeof(double));
  if (!v.empty()) std::memcpy(v.data(), s.data(), v.size() * sizeof(double));
  return v;
}

}  // namespace dtwin
