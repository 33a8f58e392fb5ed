#include "common/hash.hpp"

#include <cstdio>

#include "common/format.hpp"

namespace dtwin {

std::uint64_t fnv1a64(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

std::string hexId(std::uint64_t v) {
  return formatPrintf("0x%016llX", static_cast<unsigned long long>(v));
}

}  // namespace dtwin
