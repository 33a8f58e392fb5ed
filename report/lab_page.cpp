#include "report/lab_page.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/errors.hpp"
#include "report/compare_page.hpp"

namespace dtwin::report {

namespace {

/// The unit of channel `name` among the study's measurable channels ("" when unknown).
std::string unitOf(const Study& study, const std::string& name) {
  for (const auto& c : measurableChannels(study.sensors))
    if (c.name == name) return c.unit;
  return "";
}

/// One channel of the page: the grid of `grid` (the first assembly's dense band of it), the
/// repetitions as points, and every assembly's median and band.
nlohmann::json channelData(const study::LabBands& bands, const study::ChannelBand& grid) {
  const std::size_t n = grid.times.size();
  std::map<double, std::size_t> at;
  for (std::size_t i = 0; i < n; ++i) at.emplace(grid.times[i], i);
  std::map<long, std::vector<nlohmann::json>> reps;
  for (const auto& r : bands.lab.records) {
    if (r.channel != grid.channel) continue;
    auto& v = reps[r.repetition];
    if (v.empty()) v.assign(n, nlohmann::json());
    const auto it = at.find(r.time_s);
    if (it != at.end()) v[it->second] = r.value;
  }
  nlohmann::json c{{"channel", grid.channel},
                   {"unit", unitOf(bands.study, grid.channel)},
                   {"t", grid.times},
                   {"y", nlohmann::json::array()},
                   {"points", nlohmann::json::array()},
                   {"models", nlohmann::json::array()},
                   {"windows", nlohmann::json::array()},
                   {"bands", nlohmann::json::array()},
                   {"bands_note", "the lab scenario's points are too few and uneven for a spectrum"}};
  for (auto& [rep, v] : reps) c["points"].push_back({{"label", "repetition " + std::to_string(rep)}, {"v", v}});
  for (const auto& ab : bands.assemblies) {
    const study::ChannelBand* d = nullptr;
    for (const auto& b : ab.dense)
      if (b.channel == grid.channel && b.times == grid.times) d = &b;
    if (!d) continue;
    double ss = 0.0;
    long count = 0, inside = 0;
    for (const auto& r : bands.lab.records) {
      if (r.channel != grid.channel || !at.count(r.time_s)) continue;
      const std::size_t i = at.at(r.time_s);
      ss += (r.value - d->med[i]) * (r.value - d->med[i]);
      ++count;
      inside += r.value >= d->plo[i] && r.value <= d->phi[i] ? 1 : 0;
    }
    c["models"].push_back({{"label", ab.assembly.id + " (" + ab.assembly.label() + ")"},
                           {"p", d->med},
                           {"lo", d->plo},
                           {"hi", d->phi},
                           {"fit", nullptr},
                           {"rms", count ? std::sqrt(ss / static_cast<double>(count)) : 0.0},
                           {"coverage", count ? static_cast<double>(inside) / static_cast<double>(count) : 0.0}});
  }
  return c;
}

}  // namespace

nlohmann::json labPageData(const study::LabBands& bands, const std::string& title) {
  const study::AssemblyBands* first = nullptr;
  for (const auto& ab : bands.assemblies)
    if (!ab.dense.empty() && !first) first = &ab;
  if (!first) throw InputError("lab page", "no assembly has a predictive band (every posterior draw failed to simulate)");
  nlohmann::json set{{"name", "lab data"}, {"scenario", "lab"}, {"channels", nlohmann::json::array()}};
  for (const auto& grid : first->dense) set["channels"].push_back(channelData(bands, grid));
  // The first view: from a little before the first lab time to the last (the static report's).
  double t0 = INFINITY, t1 = -INFINITY;
  for (const auto& r : bands.lab.records) {
    t0 = std::min(t0, r.time_s);
    t1 = std::max(t1, r.time_s);
  }
  if (t1 > t0) set["view"] = {std::max(0.0, t0 - 0.15 * (t1 - t0)), t1};
  return {{"title", title}, {"sets", nlohmann::json::array({set})}, {"no_windows", true}, {"whole", "whole scenario"}};
}

std::string labPage(const study::LabBands& bands, const std::string& title) {
  return timeSeriesPage(labPageData(bands, title),
                        "Each assembly's median prediction through the lab scenario (one colour each; " +
                            std::to_string(bands.draws) +
                            " posterior draws), the last one's posterior predictive 95 % band, the lab's repetitions as points, and "
                            "under each channel the points' residuals against each median. Drag across a plot to zoom; "
                            "double-click for the whole scenario.");
}

}  // namespace dtwin::report
