// The channels every run writes (twin/run_types.hpp).
#include "twin/run_types.hpp"

#include "common/format.hpp"
#include "twin/model.hpp"

namespace dtwin {

std::vector<Channel> runChannels(const std::vector<SensorSpec>& sensors) {
  std::vector<Channel> ch = runChannels();
  for (const auto& x : sensors) {
    std::string d =
        x.relative() ? sensorQuantityName(x.quantity) + " of " + x.mount +
                           " relative to the chassis (compression positive)"
                     : sensorQuantityName(x.quantity) + " of " +
                           (x.corner() >= 0 ? "the " + x.mount + " centre"
                                            : "the chassis point " + formatNumber(x.position_m[0]) +
                                                  ", " + formatNumber(x.position_m[1]) + ", " +
                                                  formatNumber(x.position_m[2]) + " m");
    if (x.filter.order > 0)
      d += ", low-pass order " + std::to_string(x.filter.order) + " at " +
           formatNumber(x.filter.cutoff_hz) + " Hz";
    ch.push_back({x.channel(), x.unit(), "sensor " + x.name + ": " + d});
  }
  return ch;
}

std::vector<Channel> runChannels() {
  std::vector<Channel> ch = {{"time_s", "s", "time"}, {"speed_mps", "m/s", "forward speed"}};
  const char* groups[5][3] = {
      {"hub_force_", "N", "tire normal force at the wheel hub"},
      {"tire_defl_", "m", "tire deflection rho_z (negative: airborne)"},
      {"susp_defl_", "m", "suspension deflection, compression positive, 0 at static ride height"},
      {"susp_rate_", "m/s", "suspension deflection rate, compression positive"},
      {"road_", "m", "road height under the wheel centre"}};
  const char* suffix[5] = {"_N", "_m", "_m", "_mps", "_m"};
  for (int g = 0; g < 5; ++g)
    for (int c = 0; c < 4; ++c)
      ch.push_back({std::string(groups[g][0]) + kCornerNames[c] + suffix[g], groups[g][1],
                    std::string(groups[g][2]) + " (" + kCornerNames[c] + ")"});
  ch.push_back({"chassis_heave_m", "m", "CG height change from static, up positive"});
  ch.push_back(
      {"chassis_pitch_rad", "rad", "pitch angle about +y (y to the left): positive nose down"});
  ch.push_back(
      {"chassis_roll_rad", "rad", "roll angle about +x (x forward): positive right side down"});
  ch.push_back({"chassis_heave_acc_mps2", "m/s^2", "heave acceleration"});
  ch.push_back({"chassis_pitch_acc_radps2", "rad/s^2", "pitch angular acceleration"});
  ch.push_back({"chassis_roll_acc_radps2", "rad/s^2", "roll angular acceleration"});
  return ch;
}

}  // namespace dtwin
