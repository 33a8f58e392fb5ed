// `twin import`'s road columns (io/log_import.hpp): the road under the axles (one column or left
// and right) or each wheel's own motion (road_fl, road_fr, road_rl, road_rr), their units, and
// road.csv in the layout the csv_time road reads (subsystems/time_road.hpp).
#include <cmath>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/import_units.hpp"

namespace dtwin {

void resolveRoadUnits(const ImportMapping& m, ImportUnits& u) {
  if (m.road) u.road_cols = {&*m.road};
  if (m.road_left) u.road_cols = {&*m.road_left, &*m.road_right};
  const bool wheels = m.road_wheels[0].has_value();
  if (wheels)
    for (const auto& c : m.road_wheels) u.road_cols.push_back(&*c);
  for (const auto* c : u.road_cols) {
    // A velocity unit makes a velocity, an acceleration unit (the wheels' only) an acceleration;
    // any other must be a height (unitFactor names what fits).
    std::string si = "m";
    for (const auto& k : kUnits)
      if (c->unit == k.name &&
          (std::string(k.si) == "m/s" || (wheels && std::string(k.si) == "m/s^2")))
        si = k.si;
    u.road.push_back(unitFactor(c->unit, si, c->unitWhere()));
    const bool velocity = si == "m/s", acceleration = si == "m/s^2";
    if (c != u.road_cols.front() &&
        (velocity != u.road_velocity || acceleration != u.road_acceleration))
      throw InputError(c->where, wheels ? "the four wheels' columns must all be heights (m, mm), "
                                          "all velocities (m/s, mm/s) or all accelerations "
                                          "(m/s^2, g)"
                                        : "both tracks must be heights (m, mm) or both road "
                                          "velocities (m/s, mm/s)");
    u.road_velocity = velocity;
    u.road_acceleration = acceleration;
  }
  if (m.highpass_given && !u.road_velocity && !u.road_acceleration)
    throw InputError(m.source == "command line" ? std::string("--highpass-hz")
                                                : m.source + ": import.highpass_hz",
                     "applies to a road velocity (m/s, mm/s) or a wheel's acceleration only; the "
                     "road here is " +
                         (u.road_cols.empty() ? std::string("not mapped") : "a height"));
}

std::string roadCsvText(const ImportUnits& u, const std::vector<double>& t,
                        const std::vector<std::vector<double>>& road) {
  if (u.road_cols.empty()) return "";
  const bool two = u.road_cols.size() == 2, four = u.road_cols.size() == 4;
  std::string r = four ? (u.road_acceleration ? "time_s,fl_mps2,fr_mps2,rl_mps2,rr_mps2\n"
                          : u.road_velocity   ? "time_s,fl_mps,fr_mps,rl_mps,rr_mps\n"
                                              : "time_s,fl_m,fr_m,rl_m,rr_m\n")
                  : u.road_velocity
                      ? (two ? "time_s,left_mps,right_mps\n" : "time_s,velocity_mps\n")
                      : (two ? "time_s,left_m,right_m\n" : "time_s,height_m\n");
  for (std::size_t i = 0; i < t.size(); ++i) {
    r += formatExact(t[i]);
    for (const auto& col : road) r += "," + formatExact(col[i]);
    r += "\n";
  }
  return r;
}

nlohmann::json roadSidecar(const ImportMapping& m, const ImportUnits& u) {
  if (u.road_cols.empty()) return nullptr;
  const bool four = u.road_cols.size() == 4;
  nlohmann::json rj = {{"form", u.road_acceleration ? "acceleration"
                                : u.road_velocity   ? "velocity"
                                                    : "height"},
                       {"tracks", four                      ? "four corners"
                                  : u.road_cols.size() == 2 ? "left and right"
                                                            : "identical"}};
  rj["columns"] = nlohmann::json::array();
  for (const auto* c : u.road_cols) {
    nlohmann::json col = {{"column", c->column}, {"unit", c->unit}};
    if (four) {
      col["offset"] = c->offset;
      col["scale"] = c->scale;
    }
    rj["columns"].push_back(col);
  }
  if (u.road_velocity || u.road_acceleration) rj["highpass_hz"] = m.highpass_hz;
  return rj;
}

void checkWheelAccelerations(const ImportUnits& u, const std::vector<std::vector<double>>& road) {
  if (!u.road_acceleration) return;
  constexpr double kG = 9.80665;
  for (std::size_t k = 0; k < road.size() && k < u.road_cols.size(); ++k) {
    if (road[k].empty()) continue;
    double mean = 0;
    for (double a : road[k]) mean += a;
    mean /= static_cast<double>(road[k].size());
    if (std::abs(mean) > 0.5 * kG)
      throw InputError(u.road_cols[k]->where,
                       "column '" + u.road_cols[k]->column + "' reads " + formatNumber(mean, 4) +
                           " m/s^2 on average: a wheel's accelerometer reads gravity too; remove "
                           "it with the column's offset (in the column's unit: 1 for a column in "
                           "g that reads +1 g at rest, -1 for one that reads -1 g)");
  }
}

}  // namespace dtwin
