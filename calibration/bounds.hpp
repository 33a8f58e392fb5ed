#pragma once
// Values on their bounds are findings (docs/calibration.md, "Values on their bounds"). A
// calibrated value whose optimum sits on a bound of its range, or whose posterior piles up against
// one, is not an estimate: the data want a value the range does not allow, or the model's
// structure differs from the car's. Likewise a value whose 95 % interval spans nearly its whole
// range is not determined by the data. Each finding says which, in words, with the physical limit
// the range could be widened to (twin/model.hpp physicalLimit). Pure: no simulation.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

namespace dtwin::calib {

struct BoundFinding {
  std::string name, unit;
  /// "lower" or "upper": the bound the value sits on; "none" for a value the data do not
  /// determine (its interval spans most of its range, no bound preferred).
  std::string side;
  double bound = 0.0;             ///< the calibration's bound on that side
  double optimum = 0.0;           ///< the optimiser's value
  bool optimum_on_bound = false;  ///< within kOnBound of the range from the bound
  /// The posterior's mass within kNearBound of the range from the bound (NaN: no posterior yet).
  double posterior_share = std::numeric_limits<double>::quiet_NaN();
  /// The printed 95 % interval reaches the bound (NaN-free only when an interval exists).
  bool interval_reaches = false;
  /// The printed 95 % interval's width over the range (NaN: no interval yet).
  double interval_span = std::numeric_limits<double>::quiet_NaN();
  /// The physical limit beyond this bound (NaN: none known) and where it comes from.
  double limit = std::numeric_limits<double>::quiet_NaN();
  std::string limit_basis;
  /// The bound is at (or beyond) the physical limit already: widening cannot help.
  bool at_limit() const;
  /// The finding in words: "tire.damping is at its upper bound 7000 N*s/m: the data want more;
  /// widen the range (a road vehicle's value may reach 20000 N*s/m: ...) or the structure differs".
  std::string sentence() const;
  nlohmann::json toJson() const;
  static BoundFinding fromJson(const nlohmann::json& j);

  /// An optimum this close to a bound (fraction of the range) sits on it.
  static constexpr double kOnBound = 1e-3;
  /// The posterior's share within this fraction of the range from a bound ...
  static constexpr double kNearBound = 0.02;
  /// ... above which the posterior piles up against it.
  static constexpr double kPileUp = 0.5;
  /// An interval spanning more than this fraction of the range: the data do not determine the
  /// value.
  static constexpr double kUndetermined = 0.9;
};

/// What findBounds reads. The optional parts are empty before the stages that make them.
struct BoundInputs {
  std::vector<std::string> names, units;
  std::vector<double> lower, upper;  ///< the calibration's bounds
  std::vector<double> optimum;
  std::vector<double> interval_lo, interval_hi;  ///< the printed 95 % intervals (empty: none yet)
  /// The posterior draws: design rows (N x d) and the draws' row indices (empty: none yet).
  const Eigen::MatrixXd* design = nullptr;
  std::vector<int> draws;
  /// Per value: its physical limit (lower, upper; NaN when none) and their basis.
  std::vector<double> limit_lower, limit_upper;
  std::vector<std::string> limit_basis;
};

/// The values on their bounds (optimum on a bound, or at least kPileUp of the posterior within
/// kNearBound of it), then the values the data do not determine (interval wider than
/// kUndetermined of the range), in parameter order within each.
std::vector<BoundFinding> findBounds(const BoundInputs& in);

/// One line per finding, each "FINDING: " + sentence (empty when none).
std::string boundFindingsText(const std::vector<BoundFinding>& findings, const std::string& indent);

}  // namespace dtwin::calib
