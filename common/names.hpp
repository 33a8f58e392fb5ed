#pragma once
// Names a user types (options, effects, fields): "did you mean" hints and the one message for an
// unknown name, so every registry reports it the same way.
#include <string>
#include <vector>

namespace dtwin {

/// Closest known name to `name` (edit distance below 4, for "did you mean" hints), or "" if none
/// is close.
std::string closestName(const std::string& name, const std::vector<std::string>& known);

/// "unknown <what> 'name' (known: a, b, c; did you mean 'b'?)".
std::string unknownNameRule(const std::string& what, const std::string& name,
                            const std::vector<std::string>& known);

}  // namespace dtwin
