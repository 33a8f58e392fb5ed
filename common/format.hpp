#pragma once
// Numbers as text for messages, tables and logs (one convention for the whole project).
#include <string>
#include <string_view>
#include <vector>

namespace dtwin {

/// `v` with `digits` significant digits, as printf's %g would write it ("inf", "-inf", "nan" for
/// the non-finite values). 17 digits round-trip a double.
std::string formatNumber(double v, int digits = 6);

/// Shortest decimal text that reads back as exactly `v` (std::to_chars); "inf", "-inf", "nan".
std::string formatExact(double v);
/// `v` with `decimals` digits after the point, as printf's "%.*f".
std::string formatFixed(double v, int decimals);
/// printf into a std::string, of any length ("%.3g", "%-28s %10.4g\n"): the one way a line of a
/// table or report is formatted. The compiler checks the arguments against the format.
std::string formatPrintf(const char* format, ...) __attribute__((format(printf, 1, 2)));

/// Parses the whole of `s` as a double, whatever the process's locale (std::from_chars; a leading
/// '+', inf and nan accepted). False when `s` is empty or has anything around the number (trim
/// spaces first). The one number parser of the project: text from users' files and flags.
bool parseNumber(std::string_view s, double& v);

/// The parts of `text` between the separators `sep`, empty ones included ("a,,b" gives a, "", b;
/// "a," gives a, ""; "" gives one empty part): a list from a flag or a field, never silently
/// shortened. Callers trim or refuse empty parts as their rule says.
std::vector<std::string> splitOn(std::string_view text, char sep);

/// `text` on one line: every run of white space (line ends included) becomes one space, and the
/// ends are trimmed. Messages from other libraries (Simbody's span several lines) go through it.
std::string oneLine(const std::string& text);

}  // namespace dtwin
