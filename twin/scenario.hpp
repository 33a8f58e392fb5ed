#pragma once
// Scenarios: a speed profile, a road, a duration. The vehicle stays in place and the road moves
// under it; road coordinate x = s(t) + (x_hub - a), so the front axle starts at x = 0.
#include <cstdint>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "subsystems/road.hpp"
#include "twin/model.hpp"

namespace dtwin {

/// Straight line: 0 -> v_final linearly in t_ramp, then constant (paper: 0 -> 20 mph in 5 s).
struct SpeedProfile {
  double v_final_mps = 8.9408;
  double ramp_s = 5.0;
  double speed(double t) const;
  double accel(double t) const;
  double distance(double t) const;
  double timeAtDistance(double x) const;  ///< inverse of distance (x >= 0)
};

struct RoadSpec {
  enum class Type { Flat, Bump, Iso, Csv } type = Type::Flat;
  // bump
  double bump_height_m = 0.2, bump_length_m = 0.1, bump_time_s = 6.0;
  // iso
  char iso_class = 'D';
  double smooth_until_s = 6.0;  ///< front axle reaches the rough section at this time
  double n_min = 0.011, n_max = 2.83, dx_m = 0.01, taper_m = 1.0;
  IsoRoadSpec::Coherence coherence = IsoRoadSpec::Coherence::Independent;
  // csv
  std::string csv_path;
};

struct ScenarioSpec {
  std::string name;
  double duration_s = 15.0;
  SpeedProfile speed;
  RoadSpec road;
  nlohmann::json toJson() const;
};

/// Builds the road of a scenario for a vehicle; `seed` is used by random roads only.
/// Throws InputError when a CSV road does not cover the distance the wheels travel.
std::shared_ptr<const Road> makeRoad(const ScenarioSpec& s, const VehicleData& v, std::uint64_t seed);

}  // namespace dtwin
