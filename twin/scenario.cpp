#include "twin/scenario.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace dtwin {

double SpeedProfile::speed(double t) const {
  if (t <= 0) return 0.0;
  return t < ramp_s ? v_final_mps * t / ramp_s : v_final_mps;
}
double SpeedProfile::accel(double t) const { return (t >= 0 && t < ramp_s) ? v_final_mps / ramp_s : 0.0; }
double SpeedProfile::distance(double t) const {
  if (t <= 0) return 0.0;
  if (ramp_s <= 0) return v_final_mps * t;
  if (t < ramp_s) return 0.5 * v_final_mps / ramp_s * t * t;
  return 0.5 * v_final_mps * ramp_s + v_final_mps * (t - ramp_s);
}
double SpeedProfile::timeAtDistance(double x) const {
  if (x <= 0) return 0.0;
  const double x_ramp = 0.5 * v_final_mps * ramp_s;
  if (ramp_s > 0 && x < x_ramp) return std::sqrt(2.0 * x * ramp_s / v_final_mps);
  return ramp_s + (x - x_ramp) / v_final_mps;
}

nlohmann::json ScenarioSpec::toJson() const {
  nlohmann::json r;
  switch (road.type) {
    case RoadSpec::Type::Flat: r = {{"type", "flat"}}; break;
    case RoadSpec::Type::Bump:
      r = {{"type", "bump"}, {"height_m", road.bump_height_m}, {"length_m", road.bump_length_m}, {"time_s", road.bump_time_s}};
      break;
    case RoadSpec::Type::Iso:
      r = {{"type", "iso8608"}, {"class", std::string(1, road.iso_class)}, {"smooth_until_s", road.smooth_until_s},
           {"band_cycles_per_m", {road.n_min, road.n_max}}, {"dx_m", road.dx_m}, {"taper_m", road.taper_m},
           {"tracks", road.coherence == IsoRoadSpec::Coherence::Identical ? "identical" : "independent"}};
      break;
    case RoadSpec::Type::Csv: r = {{"type", "csv"}, {"path", road.csv_path}}; break;
  }
  return {{"name", name}, {"duration_s", duration_s},
          {"speed", {{"v_final_mps", speed.v_final_mps}, {"ramp_s", speed.ramp_s}}}, {"road", r}};
}

std::shared_ptr<const Road> makeRoad(const ScenarioSpec& s, const VehicleData& v, std::uint64_t seed) {
  const double x_end = s.speed.distance(s.duration_s) + 5.0;  // front axle, plus margin
  const double x_begin = -v.wheelbase() - 5.0;                // rear axle at t = 0, minus margin
  switch (s.road.type) {
    case RoadSpec::Type::Flat: return std::make_shared<FlatRoad>();
    case RoadSpec::Type::Bump:
      return std::make_shared<BumpRoad>(s.speed.distance(s.road.bump_time_s), s.road.bump_height_m, s.road.bump_length_m);
    case RoadSpec::Type::Iso: {
      IsoRoadSpec iso;
      iso.road_class = s.road.iso_class;
      iso.n_min = s.road.n_min;
      iso.n_max = s.road.n_max;
      iso.dx_m = s.road.dx_m;
      iso.x_begin_m = x_begin;
      iso.length_m = x_end - x_begin;
      iso.smooth_until_m = s.road.smooth_until_s > 0 ? s.speed.distance(s.road.smooth_until_s) : -1e300;
      iso.taper_m = s.road.taper_m;
      iso.coherence = s.road.coherence;
      iso.seed = seed;
      return makeIsoRoad(iso);
    }
    case RoadSpec::Type::Csv: {
      auto road = loadRoadCsv(s.road.csv_path);
      const auto ext = road->extent();
      if (ext.lo > -v.wheelbase() || ext.hi < s.speed.distance(s.duration_s))
        throw InputError(s.road.csv_path, "road profile covers distance_m " + std::to_string(ext.lo) + ".." +
                                              std::to_string(ext.hi) + " but scenario '" + s.name + "' needs " +
                                              std::to_string(-v.wheelbase()) + ".." +
                                              std::to_string(s.speed.distance(s.duration_s)) +
                                              " (front axle starts at 0, rear axle at -wheelbase)");
      return road;
    }
  }
  DTWIN_CHECK(false, "road type");
  return nullptr;
}

}  // namespace dtwin
