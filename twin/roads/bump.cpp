#include "twin/roads/bump.hpp"

#include "common/errors.hpp"
#include "common/toml_reader.hpp"
#include "twin/scenario.hpp"

namespace dtwin {

std::shared_ptr<const RoadSetting> BumpRoadSetting::parse(TableReader& rr) {
  auto b = std::make_shared<BumpRoadSetting>();
  b->height_m = rr.number("height_m", 0.2);
  b->length_m = rr.positive("length_m", 0.1);
  b->time_s = rr.number("time_s", 6.0);
  if (b->time_s < 0) throw InputError(rr.where("time_s"), "must be >= 0");
  return b;
}

nlohmann::json BumpRoadSetting::toJson() const {
  return {{"type", "bump"}, {"height_m", height_m}, {"length_m", length_m}, {"time_s", time_s}};
}

std::shared_ptr<const Road> BumpRoadSetting::make(const ScenarioSpec& s, const VehicleData&,
                                                  std::uint64_t) const {
  return std::make_shared<BumpRoad>(s.speed.distance(time_s), height_m, length_m);
}

std::vector<std::string> BumpRoadSetting::describeWindow(const ScenarioSpec& sc,
                                                         const VehicleData& v, double t0,
                                                         double t1) const {
  const double wb = v.wheelbase();
  auto overlaps = [&](double a, double b) { return t0 <= b && t1 >= a; };
  std::vector<std::string> parts;
  const double x0 = sc.speed.distance(time_s), L = length_m;
  const double f0 = sc.speed.timeAtDistance(x0), f1 = sc.speed.timeAtDistance(x0 + L);
  const double r0 = sc.speed.timeAtDistance(x0 + wb), r1 = sc.speed.timeAtDistance(x0 + wb + L);
  const double fm = 0.5 * (f0 + f1), rm = 0.5 * (r0 + r1);
  if (overlaps(f0, fm)) parts.push_back("front wheels climbing the bump");
  if (overlaps(fm, f1)) parts.push_back("front wheels leaving the bump");
  if (overlaps(f1, r0))
    parts.push_back("after the front wheels' bump (wheel hop and body response)");
  if (overlaps(r0, rm)) parts.push_back("rear wheels climbing the bump");
  if (overlaps(rm, r1)) parts.push_back("rear wheels leaving the bump");
  if (t1 > r1) parts.push_back("after the rear wheels' bump (free vibration)");
  if (t0 < f0) parts.push_back("smooth road before the bump");
  return parts;
}

void BumpRoadSetting::check(const ScenarioSpec& s, const std::string& where) const {
  if (time_s >= s.duration_s)
    throw InputError(where, "bump time_s must be before the end of the scenario");
}

}  // namespace dtwin
