#include "twin/scenario.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "common/hash.hpp"

namespace dtwin {

double SpeedProfile::speed(double t) const {
  if (trace) return trace->speed(t);
  if (t <= 0) return 0.0;
  return t < ramp_s ? v_final_mps * t / ramp_s : v_final_mps;
}
double SpeedProfile::accel(double t) const {
  if (trace) return trace->accel(t);
  return (t >= 0 && t < ramp_s) ? v_final_mps / ramp_s : 0.0;
}
double SpeedProfile::distance(double t) const {
  if (trace) return start_m + trace->distance(t);
  if (t <= 0) return start_m;
  if (ramp_s <= 0) return start_m + v_final_mps * t;
  if (t < ramp_s) return start_m + 0.5 * v_final_mps / ramp_s * t * t;
  return start_m + 0.5 * v_final_mps * ramp_s + v_final_mps * (t - ramp_s);
}
double SpeedProfile::timeAtDistance(double x_road) const {
  const double x = x_road - start_m;
  if (trace) return trace->timeAtDistance(x);
  if (x <= 0) return 0.0;
  const double x_ramp = 0.5 * v_final_mps * ramp_s;
  if (ramp_s > 0 && x < x_ramp) return std::sqrt(2.0 * x * ramp_s / v_final_mps);
  return ramp_s + (x - x_ramp) / v_final_mps;
}

nlohmann::json SpeedProfile::toJson() const {
  nlohmann::json j;
  if (!trace) {
    j = {{"v_final_mps", v_final_mps}, {"ramp_s", ramp_s}};
  } else {
    std::string bytes;
    for (const auto* v : {&trace->times(), &trace->speeds()})
      bytes.append(reinterpret_cast<const char*>(v->data()), v->size() * sizeof(double));
    j = {{"csv", trace->name()},
         {"samples", trace->times().size()},
         {"content", hexId(fnv1a64(bytes))}};
  }
  if (start_m != 0.0)
    j["start_m"] = start_m;  // absent when 0: the fingerprints of every study before it stay
  return j;
}

nlohmann::json ScenarioSpec::toJson() const {
  return {{"name", name},
          {"duration_s", duration_s},
          {"speed", speed.toJson()},
          {"road", road->toJson()}};
}

std::shared_ptr<const Road> makeRoad(const ScenarioSpec& s, const VehicleData& v,
                                     std::uint64_t seed) {
  return s.road->make(s, v, seed);
}

}  // namespace dtwin
