#pragma once
// Content fingerprints written in outputs: a road file's bytes, a stream constant.
#include <cstdint>
#include <string>

namespace dtwin {

/// 64-bit FNV-1a of a byte string (portable content fingerprint).
std::uint64_t fnv1a64(const std::string& bytes);
/// "0x0123456789ABCDEF": how stream constants and content hashes are written in outputs.
std::string hexId(std::uint64_t v);

}  // namespace dtwin
