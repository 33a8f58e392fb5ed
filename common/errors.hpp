#pragma once
// Error levels (see docs/architecture.md):
//  * InputError  - something a user supplied is wrong (file, field, option, number). Thrown; the
//                  CLI prints what() on one line and exits with code 2.
//  * StorageError - a write failed because the storage is full (the disk, the quota or the file
//                  size limit): neither the user's input nor a bug. The CLI prints it on one line
//                  with what to do (free space, rerun) and exits with code 1.
//  * DTWIN_CHECK - an always-on check of an impossible internal state; throws std::logic_error.
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace dtwin {

/// `text` with every control byte (line ends, tabs, NUL, DEL) written as an escape (\r, \n, \t,
/// \x00): a message that quotes a user's bytes stays on one line. Other bytes (UTF-8) are kept.
inline std::string printable(const std::string& text) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (unsigned char c : text) {
    if (c >= 0x20 && c != 0x7f)
      out += static_cast<char>(c);
    else if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (c == '\t')
      out += "\\t";
    else
      out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}

class InputError : public std::runtime_error {
 public:
  /// `where` names the file and the field or line ("study.toml: scenarios.lab.road.height_m"),
  /// `rule` the rule that was broken ("must be > 0, got -0.2"). Both are kept on one line
  /// (printable above): a quoted field that holds a line end cannot split the message.
  InputError(const std::string& where, const std::string& rule)
      : std::runtime_error(where.empty() ? printable(rule)
                                         : printable(where) + ": " + printable(rule)),
        where_(printable(where)),
        rule_(printable(rule)) {}
  const std::string& where() const { return where_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string where_;
  std::string rule_;
};

/// A write to `path` failed with ENOSPC, EDQUOT or EFBIG (isStorageFull): what() is
/// "<path>: cannot write: the disk is full (No space left on device)" (the quota, the file size
/// limit for the other two).
class StorageError : public std::runtime_error {
 public:
  StorageError(const std::string& path, int error_number)
      : std::runtime_error(printable(path) + ": cannot write: " + reason(error_number)),
        path_(printable(path)),
        errno_(error_number) {}
  const std::string& path() const { return path_; }
  int errorNumber() const { return errno_; }

  /// True for the errno values of a full storage: ENOSPC, EDQUOT, EFBIG.
  static bool isStorageFull(int error_number) {
    return error_number == ENOSPC || error_number == EDQUOT || error_number == EFBIG;
  }
  /// "the disk is full (No space left on device)", and the like for EDQUOT and EFBIG.
  static std::string reason(int error_number) {
    const char* what = error_number == EDQUOT  ? "the disk quota is used up"
                       : error_number == EFBIG ? "the file size limit is reached"
                                               : "the disk is full";
    return std::string(what) + " (" + std::strerror(error_number) + ")";
  }

 private:
  std::string path_;
  int errno_;
};

/// The one line shown for an exception that is neither bad input nor a full disk (a bug):
/// "internal error: <what>", the prefix once (DTWIN_CHECK's message carries it already).
inline std::string internalErrorText(const std::string& what) {
  static const std::string prefix = "internal error: ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what : prefix + what;
}

}  // namespace dtwin

#define DTWIN_CHECK(cond, msg)                                                                \
  do {                                                                                        \
    if (!(cond))                                                                              \
      throw std::logic_error(std::string("internal error: ") + (msg) +                        \
                             " [" #cond "] (" __FILE__ ":" + std::to_string(__LINE__) + ")"); \
  } while (0)
