#pragma once
// Checksums of the resumable files (the stages' JSON, the design journal's lines, posterior.csv):
// a file changed on disk after it was written (bytes overwritten in the middle, a digit changed)
// is told from one written whole, and set aside instead of trusted.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace dtwin {

/// 32-bit FNV-1a of `text` as 8 lower-case hex digits: the checksum of one line of a journal.
std::string lineChecksum(const std::string& text);

/// The key of the checksum a sealed JSON object carries.
inline constexpr const char* kChecksumKey = "checksum";
/// `j` (an object) with "checksum": "fnv1a64:<16 hex digits>" of the compact dump of `j` without
/// it. The dump of the parsed file gives the same text (nlohmann_json writes numbers that read
/// back to the same double and keeps the keys sorted), so the check does not depend on spacing.
nlohmann::json sealJson(nlohmann::json j);
/// What the checksum of a JSON object read back says.
enum class Seal {
  absent,  ///< no "checksum" (a file written before checksums were recorded): trusted as before
  holds,   ///< the content is the one that was written
  broken   ///< the content changed after it was written
};
Seal checkSeal(const nlohmann::json& j);

/// "fnv1a64:<16 hex digits>" of a file's bytes: posterior.csv's checksum in summary.json.
std::string contentChecksum(const std::string& bytes);

/// A damaged resumable file: renames `path` to `path`.corrupt (replacing an older one) and prints
/// one line on stderr, "twin: note: <path>: <what>: the stage is redone, not trusted (set aside as
/// <path>.corrupt)". Returns the new name. Root only (the only rank that writes and prints).
std::string setAsideCorrupt(const std::string& path, const std::string& what);

}  // namespace dtwin
