#pragma once
// Road type "bump": a one-cosine bump across both tracks (BumpRoad), placed where the front axle
// is at time_s.
#include "twin/road_setting.hpp"

namespace dtwin {

class BumpRoadSetting final : public RoadSetting {
 public:
  double height_m = 0.2;  ///< may be negative (a pothole)
  double length_m = 0.1;  ///< > 0
  double time_s = 6.0;    ///< when the front axle reaches the bump, >= 0 and before the end

  /// Fields: height_m, length_m, time_s.
  static std::shared_ptr<const RoadSetting> parse(TableReader& table);
  std::string type() const override { return "bump"; }
  nlohmann::json toJson() const override;
  std::shared_ptr<const Road> make(const ScenarioSpec& s, const VehicleData& v,
                                   std::uint64_t seed) const override;
  std::vector<std::string> describeWindow(const ScenarioSpec& s, const VehicleData& v, double t0,
                                          double t1) const override;
  double featureTime_s() const override { return time_s; }
  bool obstacle() const override { return true; }
  void check(const ScenarioSpec& s, const std::string& where) const override;
};

}  // namespace dtwin
