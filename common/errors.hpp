#pragma once
// Error levels (see docs/architecture.md):
//  * InputError  - something a user supplied is wrong (file, field, option, number). Thrown; the
//                  CLI prints what() on one line and exits with code 2.
//  * DTWIN_CHECK - an always-on check of an impossible internal state; throws std::logic_error.
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
    if (c >= 0x20 && c != 0x7f) out += static_cast<char>(c);
    else if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}

class InputError : public std::runtime_error {
 public:
  /// `where` names the file and the field or line ("study.toml: scenarios.lab.road.height_m"),
  /// `rule` the rule that was broken ("must be > 0, got -0.2"). Both are kept on one line
  /// (printable above): a quoted field that holds a line end cannot split the message.
  InputError(std::string where, std::string rule)
      : std::runtime_error(where.empty() ? printable(rule) : printable(where) + ": " + printable(rule)),
        where_(printable(where)), rule_(printable(rule)) {}
  const std::string& where() const { return where_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string where_;
  std::string rule_;
};

}  // namespace dtwin

#define DTWIN_CHECK(cond, msg)                                                          \
  do {                                                                                  \
    if (!(cond))                                                                        \
      throw std::logic_error(std::string("internal error: ") + (msg) + " [" #cond "] (" \
                             __FILE__ ":" + std::to_string(__LINE__) + ")");            \
  } while (0)
