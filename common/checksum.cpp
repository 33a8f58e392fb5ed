#include "common/checksum.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/hash.hpp"

namespace dtwin {

std::string lineChecksum(const std::string& text) {
  std::uint32_t h = 2166136261u;
  for (unsigned char c : text) {
    h ^= c;
    h *= 16777619u;
  }
  return formatPrintf("%08x", static_cast<unsigned>(h));
}

std::string contentChecksum(const std::string& bytes) {
  return formatPrintf("fnv1a64:%016llx", static_cast<unsigned long long>(fnv1a64Published(bytes)));
}

nlohmann::json sealJson(nlohmann::json j) {
  DTWIN_CHECK(j.is_object(), "only a JSON object carries a checksum");
  j.erase(kChecksumKey);
  const std::string sum = contentChecksum(j.dump());
  j[kChecksumKey] = sum;
  return j;
}

Seal checkSeal(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains(kChecksumKey)) return Seal::absent;
  const auto& sum = j.at(kChecksumKey);
  if (!sum.is_string()) return Seal::broken;
  nlohmann::json rest = j;
  rest.erase(kChecksumKey);
  return sum.get<std::string>() == contentChecksum(rest.dump()) ? Seal::holds : Seal::broken;
}

std::string setAsideCorrupt(const std::string& path, const std::string& what) {
  std::string aside = path + ".corrupt";
  std::error_code ec;
  std::filesystem::rename(path, aside, ec);
  if (ec) {  // cannot rename: at least never read it again
    std::filesystem::remove(path, ec);
    std::fprintf(stderr, "twin: note: %s: %s: the stage is redone, not trusted (removed)\n",
                 printable(path).c_str(), printable(what).c_str());
    return std::string();
  }
  std::fprintf(stderr, "twin: note: %s: %s: the stage is redone, not trusted (set aside as %s)\n",
               printable(path).c_str(), printable(what).c_str(), printable(aside).c_str());
  std::fflush(stderr);
  return aside;
}

}  // namespace dtwin
