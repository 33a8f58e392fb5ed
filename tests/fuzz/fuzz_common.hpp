#pragma once
// Shared by the fuzz harnesses (tests/fuzz/, docs/fuzzing.md). A harness feeds arbitrary bytes to
// one reader. The reader may accept them or throw InputError; anything else is a bug that the
// fuzzer must report, so it aborts:
//   * any other exception (an "internal error" a user would see, e.g. a JSON type error),
//   * an InputError whose message is empty or spans more than one line (the one-line promise),
// and AddressSanitizer/UndefinedBehaviorSanitizer abort on memory errors and undefined behaviour.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/errors.hpp"

namespace dtwin::fuzz {

/// Runs `read`; returns normally on success or a well-formed InputError, aborts otherwise.
template <class F>
void guarded(F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.empty() || what.find('\n') != std::string::npos ||
        what.find('\r') != std::string::npos) {
      std::fprintf(stderr, "fuzz: InputError that is not one non-empty line: [%s]\n", what.c_str());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: exception other than InputError: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz: non-standard exception\n");
    std::abort();
  }
}

/// A private scratch folder for this process, made once (removed by the OS's tmp cleaning; the
/// harness rewrites the same few files on every input).
inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    std::string tmpl = (std::filesystem::temp_directory_path() / "dtwin-fuzz-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) std::abort();
    return std::filesystem::path(tmpl);
  }();
  return dir;
}

/// Writes `size` bytes to `path` (binary, truncating).
inline void writeBytes(const std::filesystem::path& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) std::abort();
}

/// The project's source folder (for data/ files a harness needs, e.g. the vehicle file).
inline std::filesystem::path sourceDir() { return DTWIN_SOURCE_DIR; }

}  // namespace dtwin::fuzz
