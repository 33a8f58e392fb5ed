#pragma once
// Portable, explicit random streams (no global state). std::mt19937_64 is specified exactly by
// the standard; the distributions are not, so the transforms here are our own and documented.
#include <cmath>
#include <cstdint>
#include <random>

#include "common/statistics.hpp"

namespace dtwin {

/// SplitMix64 finaliser: a well-mixed 64-bit hash used to derive independent stream seeds.
inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

/// The stream for task `index` of purpose `stream` under `seed`: depends on (seed, stream,
/// index) only, never on execution order.
class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t stream, std::uint64_t index = 0)
      : engine_(splitmix64(splitmix64(splitmix64(seed) ^ stream) ^ index)) {}
  /// Uniform on [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Standard normal by Box-Muller (portable, unlike std::normal_distribution).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u1;
    do u1 = uniform();
    while (u1 <= 0.0);
    const double u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2.0 * kPi * u2);
    has_spare_ = true;
    return r * std::cos(2.0 * kPi * u2);
  }
  std::uint64_t bits() { return engine_(); }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace dtwin
