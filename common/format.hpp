#pragma once
// Numbers as text for messages, tables and logs (one convention for the whole project).
#include <string>
#include <string_view>

namespace dtwin {

/// `v` with `digits` significant digits, as printf's %g would write it ("inf", "-inf", "nan" for
/// the non-finite values). 17 digits round-trip a double.
std::string formatNumber(double v, int digits = 6);

/// Shortest decimal text that reads back as exactly `v` (std::to_chars); "inf", "-inf", "nan".
std::string formatExact(double v);
/// `v` with `decimals` digits after the point, as printf's "%.*f".
std::string formatFixed(double v, int decimals);
/// `v` through a printf format for one double ("%.3g", "%+.2f"); a format with a '*' takes
/// `width_or_precision` first ("%.*f"). At most 127 characters.
std::string formatPrintf(const char* format, double v, int width_or_precision = -1);

/// Parses the whole of `s` as a double, whatever the process's locale (std::from_chars; a leading
/// '+', inf and nan accepted). False when `s` is empty or has anything around the number (trim
/// spaces first). The one number parser of the project: text from users' files and flags.
bool parseNumber(std::string_view s, double& v);

/// `text` on one line: every run of white space (line ends included) becomes one space, and the
/// ends are trimmed. Messages from other libraries (Simbody's span several lines) go through it.
std::string oneLine(const std::string& text);

}  // namespace dtwin
