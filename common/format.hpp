#pragma once
// Numbers as text for messages, tables and logs (one convention for the whole project).
#include <string>

namespace dtwin {

/// `v` with `digits` significant digits, as printf's %g would write it ("inf", "-inf", "nan" for
/// the non-finite values). 17 digits round-trip a double.
std::string formatNumber(double v, int digits = 6);

}  // namespace dtwin
