#pragma once
// A small parallel loop for embarrassingly parallel runs (field data, designs, road libraries).
//
//   const int workers = workerCount(threads, n);
//   std::vector<std::unique_ptr<Simulator>> sims(workers);   // one per worker: a Simulator is
//   single-thread parallelFor(n, threads, [&](std::size_t i, int w) {
//     if (!sims[w]) sims[w] = std::make_unique<Simulator>(model, options);   // model:
//     shared_ptr<const Model> results[i] = sims[w]->run(...); // write by index, never append
//   });
//
// Tasks are handed out in increasing index order; results must be stored by index and random
// streams derived from the index (RandomStream(seed, stream, i)), so that the outcome never
// depends on the number of threads or on timing. If tasks throw, no new task starts, the running
// ones finish, and the exception of the LOWEST failing index is rethrown in the caller: the same
// error whatever the thread count (every index below a failing one was already handed out).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <limits>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace dtwin {

/// Workers parallelFor uses for `n` tasks: `requested` (<= 0: std::thread::hardware_concurrency(),
/// at least 1), never more than n, at least 1. Worker ids passed to the task are 0 .. result-1.
inline int workerCount(int requested, std::size_t n) {
  long t = requested > 0 ? requested : static_cast<long>(std::thread::hardware_concurrency());
  if (t < 1) t = 1;
  if (static_cast<std::size_t>(t) > n) t = static_cast<long>(std::max<std::size_t>(n, 1));
  return static_cast<int>(t);
}

/// Calls f(i, worker) for i = 0 .. n-1 on workerCount(threads, n) threads (worker 0 is the
/// calling thread). f is called concurrently from different workers, never concurrently with
/// the same worker id.
template <class F>
void parallelFor(std::size_t n, int threads, F&& f) {
  if (n == 0) return;
  const int workers = workerCount(threads, n);
  if (workers == 1) {
    for (std::size_t i = 0; i < n; ++i) f(i, 0);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex m;
  std::exception_ptr error;
  std::size_t error_index = std::numeric_limits<std::size_t>::max();
  auto work = [&](int w) {
    while (!stop.load(std::memory_order_acquire)) {
      const std::size_t i = next.fetch_add(1);
      if (i >= n) return;
      try {
        f(i, w);
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        if (i < error_index) {
          error_index = i;
          error = std::current_exception();
        }
        stop.store(true, std::memory_order_release);
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(workers - 1));
  for (int w = 1; w < workers; ++w) {
    try {
      pool.emplace_back(work, w);
    } catch (const std::system_error&) {
      break;  // cannot start more threads: the ones running (and this one) do all the work
    }
  }
  work(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace dtwin
