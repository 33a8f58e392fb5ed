#include "twin/roads/csv.hpp"

#include <filesystem>

#include "common/errors.hpp"
#include "common/toml_reader.hpp"
#include "twin/scenario.hpp"

namespace dtwin {

std::shared_ptr<const RoadSetting> CsvRoadSetting::parse(TableReader& rr) {
  auto rs = std::make_shared<CsvRoadSetting>();
  auto p = rr.string("path");
  if (!p) throw InputError(rr.where("path"), "is required for a csv road");
  rs->path = rr.resolvePath(*p);
  return rs;
}

std::shared_ptr<const Road> CsvRoadSetting::make(const ScenarioSpec& s, const VehicleData& v,
                                                 std::uint64_t) const {
  auto road = loadRoadCsv(path);
  const auto ext = road->extent();
  if (ext.lo > s.speed.distance(0) - v.wheelbase() || ext.hi < s.speed.distance(s.duration_s))
    throw InputError(path, "road profile covers distance_m " + std::to_string(ext.lo) + ".." +
                               std::to_string(ext.hi) + " but scenario '" + s.name + "' needs " +
                               std::to_string(s.speed.distance(0) - v.wheelbase()) + ".." +
                               std::to_string(s.speed.distance(s.duration_s)) +
                               " (front axle starts at the speed's start_m, 0 unless given; rear "
                               "axle one wheelbase behind)");
  return road;
}

}  // namespace dtwin
