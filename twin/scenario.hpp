#pragma once
// Scenarios: a speed profile, a road (one of the road types of twin/road_setting.hpp), a duration.
// The vehicle stays in place and the road moves under it; road coordinate x = s(t) + (x_hub - a),
// so the front axle starts at x = 0.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subsystems/road.hpp"
#include "subsystems/speed_trace.hpp"
#include "twin/model.hpp"
#include "twin/road_setting.hpp"

namespace dtwin {

/// The vehicle's speed. By default a straight line: 0 -> v_final linearly in ramp_s, then constant
/// (paper: 0 -> 20 mph in 5 s). When `trace` is set, a measured speed trace instead
/// (subsystems/speed_trace.hpp: monotone cubic between the samples, distance its exact integral),
/// and v_final_mps and ramp_s are not used.
struct SpeedProfile {
  double v_final_mps = 8.9408;
  double ramp_s = 5.0;
  std::shared_ptr<const SpeedTrace> trace;  ///< shared, never modified after reading
  /// The distance the front axle has travelled before t = 0 (a window cut from a drive on a road
  /// measured against distance: the window keeps its place on the road). distance(0) = start_m.
  double start_m = 0.0;
  double speed(double t) const;
  double accel(double t) const;
  double distance(double t) const;
  double timeAtDistance(
      double x) const;  ///< inverse of distance (0 at or before start_m); +inf if never reached
  /// {"v_final_mps", "ramp_s"}, or for a trace {"csv", "samples", "content"} (a hash of the
  /// samples, so fingerprints change with the file's numbers).
  nlohmann::json toJson() const;
};

struct ScenarioSpec {
  std::string name;
  double duration_s = 15.0;
  SpeedProfile speed;
  /// The road type and its fields (twin/road_setting.hpp); shared, never modified after reading.
  std::shared_ptr<const RoadSetting> road = flatRoadSetting();
  /// Extra output times a caller asks of a run (ascending, within duration_s): the times of
  /// measurements off the output grid. Not part of the study file, nor of toJson().
  std::vector<double> sample_times_s;
  /// false: the run writes only the rows at sample_times_s (RunResult::samples) and leaves the
  /// output grid empty (RunResult::trace has the channels and no rows), unless a sensor is
  /// filtered (its filter runs on the grid). For callers that read measured times only: on a long
  /// drive the grid's rows cost more than the rows the data ask for. A grid time asked as a
  /// sample time (r / output_rate_hz) gives its grid row's numbers bit for bit. Not part of
  /// toJson().
  bool grid_output = true;
  nlohmann::json toJson() const;
};

/// Builds the road of a scenario for a vehicle; `seed` is used by random roads only.
/// Throws InputError when a CSV road does not cover the distance the wheels travel.
std::shared_ptr<const Road> makeRoad(const ScenarioSpec& s, const VehicleData& v,
                                     std::uint64_t seed);

}  // namespace dtwin
