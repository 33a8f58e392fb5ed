#include "report/lab_page.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "report/compare_page.hpp"

namespace dtwin::report {

namespace {

/// One channel of the page: the grid of `grid` (the first assembly's band of it) with every
/// lab record at its time (a repetition after the first a nanosecond-scale step later, so that
/// one series holds them all), the records as points, and every assembly's median and band.
nlohmann::json channelData(const classify::LabBands& bands, const classify::ChannelBand& grid) {
  std::map<double, std::vector<double>>
      at_time;  // lab time -> the values of its repetitions, in file order
  long repetitions = 0;
  for (const auto& r : bands.lab.records)
    if (r.channel == grid.channel) {
      at_time[r.time_s].push_back(r.value);
      repetitions = std::max(repetitions, r.repetition);
    }
  std::vector<double> t;
  std::vector<std::size_t> src;  // per entry: its grid row
  nlohmann::json v = nlohmann::json::array();
  for (std::size_t i = 0; i < grid.times.size(); ++i) {
    const auto it = at_time.find(grid.times[i]);
    if (it == at_time.end()) {
      t.push_back(grid.times[i]);
      src.push_back(i);
      v.push_back(nullptr);
      continue;
    }
    const double step = 1e-9 * std::max(1.0, std::abs(grid.times[i]));
    for (std::size_t k = 0; k < it->second.size(); ++k) {
      t.push_back(grid.times[i] + static_cast<double>(k) * step);
      src.push_back(i);
      v.push_back(it->second[k]);
    }
  }
  nlohmann::json c{
      {"channel", grid.channel},
      {"unit", channelUnit(measurableChannels(bands.study.sensors), grid.channel)},
      {"t", t},
      {"y", nlohmann::json::array()},
      {"points",
       nlohmann::json::array(
           {{{"label", "lab data (" + std::to_string(repetitions) + " repetitions)"}, {"v", v}}})},
      {"models", nlohmann::json::array()},
      {"windows", nlohmann::json::array()},
      {"bands", nlohmann::json::array()},
      {"bands_note", "the lab scenario's points are too few and uneven for a spectrum"}};
  for (const auto& ab : bands.assemblies) {
    const classify::ChannelBand* d = nullptr;
    for (const auto& b : ab.channels)
      if (b.channel == grid.channel && b.times == grid.times) d = &b;
    if (!d) continue;
    nlohmann::json p = nlohmann::json::array(), lo = nlohmann::json::array(),
                   hi = nlohmann::json::array();
    double ss = 0.0;
    long count = 0, inside = 0;
    for (std::size_t j = 0; j < t.size(); ++j) {
      const std::size_t i = src[j];
      p.push_back(d->med[i]);
      lo.push_back(d->plo[i]);
      hi.push_back(d->phi[i]);
      if (v[j].is_null()) continue;
      const double y = v[j].get<double>();
      ss += (y - d->med[i]) * (y - d->med[i]);
      ++count;
      inside += y >= d->plo[i] && y <= d->phi[i] ? 1 : 0;
    }
    c["models"].push_back(
        {{"label", ab.assembly.id + " (" + ab.assembly.label() + ")"},
         {"p", p},
         {"lo", lo},
         {"hi", hi},
         {"fit", nullptr},
         {"rms", count ? std::sqrt(ss / static_cast<double>(count)) : 0.0},
         {"coverage", count ? static_cast<double>(inside) / static_cast<double>(count) : 0.0}});
  }
  return c;
}

}  // namespace

nlohmann::json labPageData(const classify::LabBands& bands, const std::string& title) {
  const classify::AssemblyBands* first = nullptr;
  for (const auto& ab : bands.assemblies)
    if (!ab.channels.empty() && !first) first = &ab;
  if (!first)
    throw InputError("lab page",
                     "no assembly has a predictive band (every posterior draw failed to simulate)");
  // The grid is finer where the lab measured: its coarser steps are no gaps.
  nlohmann::json set{{"name", "lab data"},
                     {"scenario", "lab"},
                     {"channels", nlohmann::json::array()},
                     {"no_gaps", true}};
  for (const auto& grid : first->channels) set["channels"].push_back(channelData(bands, grid));
  // The first view: from a little before the first lab time to the last (the static report's).
  double t0 = INFINITY, t1 = -INFINITY;
  for (const auto& r : bands.lab.records) {
    t0 = std::min(t0, r.time_s);
    t1 = std::max(t1, r.time_s);
  }
  if (t1 > t0) set["view"] = {std::max(0.0, t0 - 0.15 * (t1 - t0)), t1};
  return {{"title", title},
          {"sets", nlohmann::json::array({set})},
          {"no_windows", true},
          {"whole", "whole scenario"}};
}

std::string labPage(const classify::LabBands& bands, const std::string& title) {
  return timeSeriesPage(
      labPageData(bands, title),
      "Each assembly's median prediction through the lab scenario (one colour each; " +
          std::to_string(bands.draws) +
          " posterior draws), the last one's posterior predictive 95 % band, the lab's repetitions "
          "as points, and "
          "under each channel the points' residuals against each median. Drag across a plot to "
          "zoom; "
          "double-click for the whole scenario.");
}

}  // namespace dtwin::report
