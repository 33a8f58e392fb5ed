#pragma once
// The page of what changed between two calibrations of one car (`twin changes --out DIR` writes
// DIR/changes.html): one row per value both calibrations hold, significant changes first, each
// with both calibrations' estimates and 95 % intervals, the change with its 95 % interval drawn
// against "no change", z and the verdict in words. Columns sort on a click; a row's bar shows its
// numbers on hover. Self-contained: nothing is fetched at view time.
#include <string>

#include <nlohmann/json.hpp>

namespace dtwin {

/// The page from a change list's JSON (diag::ChangeReport::toJson); `title` heads the page.
std::string changesPage(const nlohmann::json& changes, const std::string& title);

}  // namespace dtwin
