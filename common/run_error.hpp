#pragma once
// RunFailedError: a simulation that failed while generating data (study/generate.hpp). In its own
// header so that the distributed layer (common/distributed.hpp) can carry it from one MPI rank to
// every other without depending on the simulator.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace dtwin {

/// A simulation that failed (RunStats.ok false) while generating data: names the run and its seed.
class RunFailedError : public std::runtime_error {
 public:
  RunFailedError(const std::string& what, std::size_t run, std::uint64_t seed)
      : std::runtime_error(what), run_(run), seed_(seed) {}
  std::size_t run() const { return run_; }  ///< 1-based run number (0 for the lab run)
  std::uint64_t seed() const { return seed_; }

 private:
  std::size_t run_;
  std::uint64_t seed_;
};

}  // namespace dtwin
