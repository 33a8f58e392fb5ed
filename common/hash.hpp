#pragma once
// Content fingerprints written in outputs: a road file's bytes, a stream constant.
#include <cstdint>
#include <string>

namespace dtwin {

/// 64-bit FNV-1a of a byte string (portable content fingerprint). Its offset basis is a digit
/// short of the published one; kept, because every fingerprint already written uses it.
std::uint64_t fnv1a64(const std::string& bytes);
/// 64-bit FNV-1a with the published offset basis 14695981039346656037 (the files' checksums).
std::uint64_t fnv1a64Published(const std::string& bytes);
/// "0x0123456789ABCDEF": how stream constants and content hashes are written in outputs.
std::string hexId(std::uint64_t v);

}  // namespace dtwin
