#pragma once
// The interactive view of a study's lab section (`twin report` writes it beside the static page,
// as <report stem>_lab.html): per lab channel, each assembly's median prediction through the lab
// scenario with the last one's posterior predictive 95 % band, the measured repetitions as points,
// and the points' residuals against each median, zoomed and panned together with one cursor
// (report/compare_page.hpp draws it).
#include <string>

#include <nlohmann/json.hpp>

#include "classification/lab_bands.hpp"

namespace dtwin::report {

/// What the page draws (the data of timeSeriesPage, report/compare_page.hpp): one set, the lab
/// scenario; per channel the dense grid's times with every lab record at its time (a repetition
/// after the first a nanosecond-scale step later), one point series of the records (null off the
/// lab times), and per assembly with a band its median ("p"), predictive band ("lo", "hi"), the
/// RMS of the lab points about the median and the share of them inside the band ("coverage").
/// InputError when no assembly has a band (every draw failed).
nlohmann::json labPageData(const classify::LabBands& bands, const std::string& title);

/// The page (self-contained HTML).
std::string labPage(const classify::LabBands& bands, const std::string& title);

}  // namespace dtwin::report
