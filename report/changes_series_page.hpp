#pragma once
// The page of what changed over several drives of one car (`twin changes --calibration ...` with
// more than two, DIR/changes.html): one plot per value, each drive's estimate and 95 % interval
// against the drive's date (a log axis for a positive value), the trend line through them, and the
// trend in words; then the table of the first and last drives' change. Self-contained: plain
// inline SVG, nothing fetched at view time.
#include <string>

#include <nlohmann/json.hpp>

namespace dtwin {

/// The page from a series' JSON (diag::SeriesReport::toJson); `title` heads the page.
std::string changesSeriesPage(const nlohmann::json& series, const std::string& title);

}  // namespace dtwin
