#include "twin/roads/csv_time.hpp"

#include <filesystem>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/hash.hpp"
#include "common/toml_reader.hpp"
#include "twin/model.hpp"
#include "twin/scenario.hpp"

namespace dtwin {

std::shared_ptr<const RoadSetting> CsvTimeRoadSetting::parse(TableReader& rr) {
  auto rs = std::make_shared<CsvTimeRoadSetting>();
  auto p = rr.string("path");
  if (!p) throw InputError(rr.where("path"), "is required for a csv_time road");
  rs->path = rr.resolvePath(*p);
  rs->dx_m = rr.number("dx_m", rs->dx_m);
  if (!(rs->dx_m >= 1e-3 && rs->dx_m <= 1.0))
    throw InputError(rr.where("dx_m"), "must lie in [1e-3, 1] m, got " + formatNumber(rs->dx_m));
  rs->log = std::make_shared<const TimeRoadLog>(readTimeRoadCsv(rs->path));
  if (rr.has("highpass_hz")) {
    if (rs->log->form == TimeRoadLog::Form::Height)
      throw InputError(
          rr.where("highpass_hz"),
          "applies to a road-velocity or acceleration log only (" + rs->path + " gives heights)");
    rs->highpass_hz = *rr.number("highpass_hz");
    if (!(rs->highpass_hz >= 1e-3 && rs->highpass_hz <= 10.0))
      throw InputError(rr.where("highpass_hz"),
                       "must lie in [1e-3, 10] Hz, got " + formatNumber(rs->highpass_hz));
  }
  return rs;
}

nlohmann::json CsvTimeRoadSetting::toJson() const {
  std::string bytes;
  for (const auto* v : {&log->t_s, &log->left, &log->right, &log->rear_left, &log->rear_right})
    bytes.append(reinterpret_cast<const char*>(v->data()), v->size() * sizeof(double));
  const char* form = log->form == TimeRoadLog::Form::Height     ? "height"
                     : log->form == TimeRoadLog::Form::Velocity ? "velocity"
                                                                : "acceleration";
  nlohmann::json j = {{"type", "csv_time"},
                      {"path", path},
                      {"form", form},
                      {"tracks", log->four_corners       ? "four corners"
                                 : log->identical_tracks ? "identical"
                                                         : "left and right"},
                      {"rows", log->t_s.size()},
                      {"content", hexId(fnv1a64(bytes))},
                      {"dx_m", dx_m}};
  if (log->form != TimeRoadLog::Form::Height) j["highpass_hz"] = highpass_hz;
  return j;
}

void CsvTimeRoadSetting::check(const ScenarioSpec& s, const std::string& where) const {
  if (log->t_s.front() > 0 || log->t_s.back() < s.duration_s)
    throw InputError(where, "the road log " + path + " covers " + formatNumber(log->t_s.front()) +
                                " .. " + formatNumber(log->t_s.back()) +
                                " s, but the scenario runs 0 .. " + formatNumber(s.duration_s) +
                                " s");
}

std::shared_ptr<const Road> CsvTimeRoadSetting::make(const ScenarioSpec& s, const VehicleData& v,
                                                     std::uint64_t) const {
  TimeRoadOptions o;
  o.dx_m = dx_m;
  o.highpass_hz = highpass_hz;
  o.x_from_m = -v.wheelbase() - 1.0;
  const auto distance = [&s](double t) { return s.speed.distance(t); };
  if (log->four_corners) return cornerRoadFromTimeLog(*log, distance, v.wheelbase(), o, toJson());
  return roadFromTimeLog(*log, distance, o, toJson());
}

}  // namespace dtwin
