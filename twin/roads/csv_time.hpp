#pragma once
// Road type "csv_time": a road logged against time (height, or vertical road velocity, under the
// front axle; or each wheel's own vertical motion), mapped to distance through the scenario's
// speed (subsystems/time_road.hpp).
#include "subsystems/time_road.hpp"
#include "twin/road_setting.hpp"

namespace dtwin {

class CsvTimeRoadSetting final : public RoadSetting {
 public:
  std::string path;          ///< resolved against the study file's folder
  double highpass_hz = 0.1;  ///< drift removal of a velocity or acceleration log (only there)
  double dx_m = 0.02;        ///< spacing of the distance grid
  std::shared_ptr<const TimeRoadLog> log;  ///< read and checked when the study is read

  /// Fields: path (required), dx_m in [1e-3, 1] m (default 0.02), highpass_hz in [1e-3, 10] Hz
  /// (default 0.1; a velocity or acceleration file only). A four-corner file makes a CornerRoad.
  static std::shared_ptr<const RoadSetting> parse(TableReader& table);
  std::string type() const override { return "csv_time"; }
  bool measured() const override { return true; }
  nlohmann::json toJson() const override;
  std::shared_ptr<const Road> make(const ScenarioSpec& s, const VehicleData& v,
                                   std::uint64_t seed) const override;
  std::vector<std::string> describeWindow(const ScenarioSpec&, const VehicleData&, double,
                                          double) const override {
    return {"measured road (logged against time)"};
  }
  /// The log must cover the scenario: its times from <= 0 to >= duration_s.
  void check(const ScenarioSpec& s, const std::string& where) const override;
};

}  // namespace dtwin
