#pragma once
// A road measured against time, as loggers record it (docs/measurements.md, "Roads against
// time"): the road height under the front axle, or the vertical road velocity, at the logger's
// sample times. Mapped to distance through the distance the vehicle travelled, it becomes a
// profile like any other; the rear axle then meets it one wheelbase later by construction. A
// four-corner log gives each wheel's own vertical motion (height, velocity or acceleration, as a
// wheel-carrier accelerometer records it): each wheel follows its own column at its own time.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subsystems/road.hpp"

namespace dtwin {

struct TimeRoadLog {
  /// Acceleration: a four-corner log's only.
  enum class Form { Height, Velocity, Acceleration };
  Form form = Form::Height;
  std::vector<double> t_s;  ///< strictly increasing, finite
  /// m (height), m/s (velocity) or m/s² (acceleration); equal when the file has one track. On a
  /// four-corner log the front wheels'.
  std::vector<double> left, right;
  std::vector<double> rear_left, rear_right;  ///< a four-corner log's rear wheels' (else empty)
  bool identical_tracks = false;              ///< the file gave one column for both tracks
  bool four_corners = false;                  ///< one column per wheel (fl, fr, rl, rr)
  std::string name;                           ///< the file
};

/// Parses a time road CSV. Header: `time_s`, then one of `height_m`/`height_mm` (both tracks
/// the same), `left_m,right_m`/`left_mm,right_mm`, `velocity_mps`, `left_mps,right_mps`, or a
/// four-corner layout `fl_m,fr_m,rl_m,rr_m` (or `_mm`), `fl_mps,...` (vertical velocity),
/// `fl_mps2,...` (vertical acceleration). Rows: finite numbers, time strictly increasing, at least
/// 2. The usual CSV leniency (common/csv.hpp). Errors: InputError naming name:line and the column.
TimeRoadLog parseTimeRoadCsv(const std::string& text, const std::string& name);
TimeRoadLog readTimeRoadCsv(const std::string& path);

/// u minus its forward-backward first-order low-pass at `cutoff_hz` (each pass exact for u held
/// between the times, which may be non-uniform): a zero-phase high-pass whose gain at frequency f
/// is (f/fc)² / (1 + (f/fc)²) (|1 − |H_lp|²|, H_lp = 1/(1 + j f/fc)): 0.5 at fc, 0.99 at 10 fc.
std::vector<double> zeroPhaseHighPass(const std::vector<double>& t, const std::vector<double>& u,
                                      double cutoff_hz);

/// Heights from vertical road velocities: each step the exact integral of the polynomial through
/// the eight samples around it (eighth order, at any spacing), or of the cubic Hermite interpolant
/// with three-point slopes where the stencil's spacings differ by more than a factor 3 (a gap);
/// the drift removed by zeroPhaseHighPass at `highpass_hz`. The same integral makes a velocity of
/// an acceleration (a four-corner acceleration log is integrated twice by it).
std::vector<double> roadHeightFromVelocity(const std::vector<double>& t,
                                           const std::vector<double>& v, double highpass_hz);

struct TimeRoadOptions {
  double dx_m = 0.02;  ///< spacing of the distance grid
  double highpass_hz =
      0.1;  ///< drift removal of a velocity log (each integration of an acceleration)
  double x_from_m = -5.0;  ///< the grid starts here (the rear axle's start, with a margin)
  /// The grid runs on this far past the last sample, along its last slope: a wheel whose hub
  /// sits a little ahead of its static place (the suspension's kinematics) meets the log's last
  /// sample before the run ends, and would otherwise read the hold's zero slope there.
  double x_past_m = 0.5;
};

/// The profile against distance: each sample at the distance the front axle had travelled at its
/// time (`distance(t)`, non-decreasing). Samples taken while the vehicle stood still (less than
/// 1e-6 m on from the last kept one) are dropped: the road under a standing wheel does not change.
/// The kept samples are joined by the cubic Hermite interpolant and sampled on the uniform grid of
/// dx_m. Its slopes: a velocity log's own velocity over the speed (dx/dt from `distance`) where the
/// vehicle moves faster than 0.5 m/s, else three-point slopes (exact for quadratics). Before the
/// first kept distance the first height is held; after the last the profile runs on along its
/// last slope for options.x_past_m, and is held from there. Throws
/// InputError(log.name, rule) when a height (after integration) is beyond ±10 m, fewer than two
/// samples are at distinct distances, or the grid would exceed 1e7 points. An acceleration log is
/// integrated to a velocity first (roadHeightFromVelocity) and then read as one. Of a four-corner
/// log the front wheels' columns (cornerRoadFromTimeLog reads all four).
std::shared_ptr<const GridRoad> roadFromTimeLog(const TimeRoadLog& log,
                                                const std::function<double(double)>& distance,
                                                const TimeRoadOptions& options,
                                                nlohmann::json description);

/// The four-corner road of a four-corner log (log.four_corners): the front wheels' columns laid
/// out on `distance` (roadFromTimeLog), the rear wheels' on distance(t) − wheelbase_m, so that a
/// rear wheel at time t (at road distance distance(t) − wheelbase_m) reads its own sample of time
/// t: no wheelbase lag. Throws as roadFromTimeLog does.
std::shared_ptr<const CornerRoad> cornerRoadFromTimeLog(
    const TimeRoadLog& log, const std::function<double(double)>& distance, double wheelbase_m,
    const TimeRoadOptions& options, nlohmann::json description);

}  // namespace dtwin
