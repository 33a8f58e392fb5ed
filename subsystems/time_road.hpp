#pragma once
// A road measured against time, as loggers record it (docs/measurements.md, "Roads against
// time"): the road height under the front axle, or the vertical road velocity, at the logger's
// sample times. Mapped to distance through the distance the vehicle travelled, it becomes a
// profile like any other; the rear axle then meets it one wheelbase later by construction.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "subsystems/road.hpp"

namespace dtwin {

struct TimeRoadLog {
  enum class Form { Height, Velocity };
  Form form = Form::Height;
  std::vector<double> t_s;  ///< strictly increasing, finite
  std::vector<double> left,
      right;  ///< m (height) or m/s (velocity); equal when the file has one track
  bool identical_tracks = false;  ///< the file gave one column for both tracks
  std::string name;               ///< the file
};

/// Parses a time road CSV. Header: `time_s`, then one of `height_m`/`height_mm` (both tracks
/// the same), `left_m,right_m`/`left_mm,right_mm`, `velocity_mps`, `left_mps,right_mps`. Rows:
/// finite numbers, time strictly increasing, at least 2. The usual CSV leniency (common/csv.hpp).
/// Errors: InputError naming name:line and the column.
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
/// the drift removed by zeroPhaseHighPass at `highpass_hz`.
std::vector<double> roadHeightFromVelocity(const std::vector<double>& t,
                                           const std::vector<double>& v, double highpass_hz);

struct TimeRoadOptions {
  double dx_m = 0.02;        ///< spacing of the distance grid
  double highpass_hz = 0.1;  ///< drift removal of a velocity log
  double x_from_m = -5.0;    ///< the grid starts here (the rear axle's start, with a margin)
};

/// The profile against distance: each sample at the distance the front axle had travelled at its
/// time (`distance(t)`, non-decreasing). Samples taken while the vehicle stood still (less than
/// 1e-6 m on from the last kept one) are dropped: the road under a standing wheel does not change.
/// The kept samples are joined by the cubic Hermite interpolant and sampled on the uniform grid of
/// dx_m. Its slopes: a velocity log's own velocity over the speed (dx/dt from `distance`) where the
/// vehicle moves faster than 0.5 m/s, else three-point slopes (exact for quadratics). Before the
/// first kept distance the first height is held, after the last the last. Throws
/// InputError(log.name, rule) when a height (after integration) is beyond ±10 m, fewer than two
/// samples are at distinct distances, or the grid would exceed 1e7 points.
std::shared_ptr<const GridRoad> roadFromTimeLog(const TimeRoadLog& log,
                                                const std::function<double(double)>& distance,
                                                const TimeRoadOptions& options,
                                                nlohmann::json description);

}  // namespace dtwin
