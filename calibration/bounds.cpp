#include "calibration/bounds.hpp"

#include <cmath>
#include <limits>

#include "common/format.hpp"
#include "common/json.hpp"

namespace dtwin::calib {
namespace {

std::string num(double v) { return formatNumber(v); }

/// " N*s/m" or "" for a dimensionless value.
std::string withUnit(const std::string& unit) {
  return unit.empty() || unit == "1" ? "" : " " + unit;
}

}  // namespace

bool BoundFinding::at_limit() const {
  if (!std::isfinite(limit)) return false;
  return side == "upper" ? bound >= limit : side == "lower" ? bound <= limit : false;
}

std::string BoundFinding::sentence() const {
  const std::string u = withUnit(unit);
  if (side == "none")
    return name + ": its 95 % interval spans " + formatPrintf("%.0f", 100.0 * interval_span) +
           " % of its range: these data do not determine it (fix it at a known value, or add data "
           "that move it)";
  std::string s = name + " is at its " + side + " bound " + num(bound) + u;
  std::string why;
  if (optimum_on_bound) why = "the optimum is " + num(optimum);
  if (std::isfinite(posterior_share))
    why += (why.empty() ? "" : ", ") + formatPrintf("%.0f", 100.0 * posterior_share) +
           " % of the posterior lies within " + formatPrintf("%.0f", 100.0 * kNearBound) +
           " % of the range from it";
  if (!why.empty()) s += " (" + why + ")";
  s += side == "upper" ? ": the data want more" : ": the data want less";
  if (at_limit()) {
    s += ", and that bound is the physical limit of a road vehicle's value (" + limit_basis +
         "): the structure differs (twin diagnose weighs other structures)";
  } else if (std::isfinite(limit)) {
    s += "; widen the range (a road vehicle's value may reach " + num(limit) + u + ": " +
         limit_basis + ") or the structure differs (twin diagnose weighs both)";
  } else {
    s += "; widen the range or the structure differs (no physical limit is known for this value)";
  }
  return s;
}

nlohmann::json BoundFinding::toJson() const {
  nlohmann::json j{{"name", name},
                   {"unit", unit},
                   {"side", side},
                   {"bound", bound},
                   {"optimum", optimum},
                   {"optimum_on_bound", optimum_on_bound},
                   {"posterior_share", jsonNumber(posterior_share)},
                   {"interval_reaches", interval_reaches},
                   {"interval_span", jsonNumber(interval_span)},
                   {"limit", jsonNumber(limit)},
                   {"limit_basis", limit_basis},
                   {"at_limit", at_limit()},
                   {"sentence", sentence()}};
  return j;
}

BoundFinding BoundFinding::fromJson(const nlohmann::json& j) {
  const auto number = [&](const char* k) {
    const auto& v = j.at(k);
    return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
  };
  BoundFinding f;
  f.name = j.at("name").get<std::string>();
  f.unit = j.value("unit", "");
  f.side = j.at("side").get<std::string>();
  f.bound = number("bound");
  f.optimum = number("optimum");
  f.optimum_on_bound = j.value("optimum_on_bound", false);
  f.posterior_share = number("posterior_share");
  f.interval_reaches = j.value("interval_reaches", false);
  f.interval_span = number("interval_span");
  f.limit = number("limit");
  f.limit_basis = j.value("limit_basis", "");
  return f;
}

std::vector<BoundFinding> findBounds(const BoundInputs& in) {
  const std::size_t d = in.names.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<BoundFinding> on, undetermined;
  for (std::size_t k = 0; k < d; ++k) {
    const double lo = in.lower[k], hi = in.upper[k], range = hi - lo;
    if (!(range > 0) || k >= in.optimum.size()) continue;
    const double x = in.optimum[k];
    const bool has_interval = k < in.interval_lo.size() && k < in.interval_hi.size() &&
                              std::isfinite(in.interval_lo[k]) && std::isfinite(in.interval_hi[k]);
    for (const char* side : {"lower", "upper"}) {
      const bool upper = std::string(side) == "upper";
      const double b = upper ? hi : lo;
      BoundFinding f;
      f.name = in.names[k];
      f.unit = k < in.units.size() ? in.units[k] : "";
      f.side = side;
      f.bound = b;
      f.optimum = x;
      f.optimum_on_bound = std::abs(x - b) <= BoundFinding::kOnBound * range;
      if (in.design && !in.draws.empty()) {
        long near = 0;
        for (int r : in.draws)
          if (std::abs((*in.design)(r, static_cast<long>(k)) - b) <=
              BoundFinding::kNearBound * range)
            ++near;
        f.posterior_share = static_cast<double>(near) / static_cast<double>(in.draws.size());
      }
      if (has_interval) {
        f.interval_reaches = std::abs((upper ? in.interval_hi[k] : in.interval_lo[k]) - b) <=
                             BoundFinding::kOnBound * range;
        f.interval_span = (in.interval_hi[k] - in.interval_lo[k]) / range;
      }
      f.limit = k < in.limit_lower.size() ? (upper ? in.limit_upper[k] : in.limit_lower[k]) : nan;
      f.limit_basis = k < in.limit_basis.size() ? in.limit_basis[k] : "";
      const bool piles_up =
          std::isfinite(f.posterior_share) && f.posterior_share >= BoundFinding::kPileUp;
      if (f.optimum_on_bound || piles_up) {
        on.push_back(f);
        break;  // one side per value
      }
    }
    if (!on.empty() && on.back().name == in.names[k]) continue;
    if (has_interval &&
        (in.interval_hi[k] - in.interval_lo[k]) > BoundFinding::kUndetermined * range) {
      BoundFinding f;
      f.name = in.names[k];
      f.unit = k < in.units.size() ? in.units[k] : "";
      f.side = "none";
      f.optimum = x;
      f.interval_span = (in.interval_hi[k] - in.interval_lo[k]) / range;
      undetermined.push_back(f);
    }
  }
  on.insert(on.end(), undetermined.begin(), undetermined.end());
  return on;
}

std::string boundFindingsText(const std::vector<BoundFinding>& findings,
                              const std::string& indent) {
  std::string s;
  for (const auto& f : findings) s += indent + "FINDING: " + f.sentence() + "\n";
  return s;
}

}  // namespace dtwin::calib
