#pragma once
// What changed between two calibrations of one car (two drives, months apart): for every value
// both calibrated, the change from the first to the second with its 95 % interval, built from both
// calibrations' own 95 % intervals, and whether it is significant when all values are judged
// together (Holm's step-down rule at a family-wise 5 %: on a car where nothing changed, at most
// 5 % of comparisons name any value). Largest evidence first, one sentence each.
//
// Each calibration's interval [lo, hi] around its optimum x is read as a normal estimate with
// sd = (hi - lo) / (2 z_0.975): on the log scale for a positive value (a stiffness, a damping, a
// factor: the change is a ratio), on the linear scale otherwise (a position, an offset: the change
// is a difference). The two estimates are independent (two drives, two noise records), so the
// change has sd = sqrt(sd1² + sd2²) and z = change / sd. The estimate is the optimum, unless it
// lies outside its own interval (the profile search met a better fit than the optimiser's, in a
// flat valley): then the interval's centre (geometric for a positive value), which the interval
// was built around, and the change says so.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/folder.hpp"

namespace dtwin::diag {

/// One value as one calibration gives it.
struct ValueEstimate {
  double optimum = 0, lo = 0, hi = 0;  ///< the optimum and the printed 95 % interval
  /// The point estimate compared: the optimum, or the interval's centre when the optimum lies
  /// outside the interval (centred true).
  double estimate = 0;
  bool centred = false;
  std::string interval;  ///< "profile" | "posterior" (summary.json "interval")
  bool trusted =
      true;  ///< false: the integrator check flagged the calibration, or the value sits on a bound
  std::string note;  ///< why not trusted
};

struct ValueChange {
  std::string name, unit;
  ValueEstimate first, second;
  bool ratio = false;     ///< a positive value: the change is second / first (else second - first)
  double change = 0;      ///< the ratio or the difference
  double lo = 0, hi = 0;  ///< its 95 % interval (one value at a time)
  double z = 0, p = 1;    ///< the standardized change and its two-sided p-value
  bool significant = false;  ///< by Holm's rule over every compared value at `level`
  bool trusted = true;       ///< both estimates trusted
  std::string sentence;  ///< "suspension.damping fell to 0.55 x its first value (95 %: 0.50-0.61):
                         ///< 2481 -> 1365 N*s/m; significant"
};

struct ChangeReport {
  std::string first_dir, second_dir, assembly;
  double level = 0.05;  ///< family-wise error rate of the significance rule
  std::vector<ValueChange>
      changes;  ///< every value both calibrated: significant first, then by |z|
  std::vector<std::string> only_first, only_second;  ///< values calibrated in one folder only
  std::vector<std::string> notes;  ///< e.g. the assemblies differ; an interval not to be trusted
  std::size_t significantCount() const;
  nlohmann::json toJson() const;
  /// The lines `twin changes` prints: the significant changes, then the rest, then the notes.
  std::string text() const;
};

/// The values a calibration folder holds, in its summary.json's parameter_order (or the keys of
/// its "parameters" when that order is absent).
std::vector<std::string> parameterNames(const calib::CalibrationFolder& f);

/// The estimate of `name` in a calibration's summary.json (InputError naming summary.json and the
/// field when the parameter's optimum or ci95 is missing or not finite, or lo > hi).
ValueEstimate valueEstimate(const calib::CalibrationFolder& folder, const std::string& name);

/// The change list from `first` to `second`. `level` in (0, 0.5).
ChangeReport compareCalibrations(const calib::CalibrationFolder& first,
                                 const calib::CalibrationFolder& second, double level = 0.05);

/// Holm's step-down rule: which of the p-values are rejected at family-wise level `level`.
std::vector<bool> holmRejections(const std::vector<double>& p, double level);

}  // namespace dtwin::diag
