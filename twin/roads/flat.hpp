#pragma once
// Road type "flat": no profile at all.
#include "twin/road_setting.hpp"

namespace dtwin {

class FlatRoadSetting final : public RoadSetting {
 public:
  static std::shared_ptr<const RoadSetting> parse(TableReader& table);
  std::string type() const override { return "flat"; }
  nlohmann::json toJson() const override { return {{"type", "flat"}}; }
  std::shared_ptr<const Road> make(const ScenarioSpec& s, const VehicleData& v,
                                   std::uint64_t seed) const override;
  std::vector<std::string> describeWindow(const ScenarioSpec& s, const VehicleData& v, double t0,
                                          double t1) const override {
    return {"flat road"};
  }
};

}  // namespace dtwin
