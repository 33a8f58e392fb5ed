#pragma once
// Road type "csv": a measured profile, distance_m,left_m,right_m (loadRoadCsv).
#include "twin/road_setting.hpp"

namespace dtwin {

class CsvRoadSetting final : public RoadSetting {
 public:
  std::string path;  ///< absolute, or relative to the working directory (the study file's folder is
                     ///< applied on parse)

  /// Field: path (relative to the study file's folder).
  static std::shared_ptr<const RoadSetting> parse(TableReader& table);
  std::string type() const override { return "csv"; }
  bool measured() const override { return true; }
  nlohmann::json toJson() const override { return {{"type", "csv"}, {"path", path}}; }
  std::shared_ptr<const Road> make(const ScenarioSpec& s, const VehicleData& v,
                                   std::uint64_t seed) const override;
  std::vector<std::string> describeWindow(const ScenarioSpec& s, const VehicleData& v, double t0,
                                          double t1) const override {
    return {"measured road profile"};
  }
};

}  // namespace dtwin
