#include "common/hash.hpp"

#include <cstdio>

#include "common/format.hpp"

namespace dtwin {

namespace {
std::uint64_t fnv1a64From(std::uint64_t h, const std::string& bytes) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}
}  // namespace

std::uint64_t fnv1a64(const std::string& bytes) {
  return fnv1a64From(1469598103934665603ULL, bytes);
}

std::uint64_t fnv1a64Published(const std::string& bytes) {
  return fnv1a64From(14695981039346656037ULL, bytes);
}

std::string hexId(std::uint64_t v) {
  return formatPrintf("0x%016llX", static_cast<unsigned long long>(v));
}

}  // namespace dtwin
