#pragma once
// Road type "iso8608": an ISO 8608 random road (makeIsoRoad, docs/method.md §2), flat until the
// front axle reaches it at smooth_until_s, one profile per seed.
#include "twin/road_setting.hpp"

namespace dtwin {

class IsoRoadSetting final : public RoadSetting {
 public:
  char iso_class = 'D';
  double smooth_until_s =
      0.0;  ///< the front axle reaches the rough section at this time (0: rough from the start)
  double n_min = 0.011, n_max = 2.83;  ///< band [cycles/m]
  double dx_m = 0.01, taper_m = 1.0;
  IsoRoadSpec::Coherence coherence = IsoRoadSpec::Coherence::Independent;

  /// Fields: class, smooth_until_s, band_cycles_per_m, dx_m, taper_m, tracks.
  static std::shared_ptr<const RoadSetting> parse(TableReader& table);
  std::string type() const override { return "iso8608"; }
  nlohmann::json toJson() const override;
  std::shared_ptr<const Road> make(const ScenarioSpec& s, const VehicleData& v,
                                   std::uint64_t seed) const override;
  std::vector<std::string> describeWindow(const ScenarioSpec& s, const VehicleData& v, double t0,
                                          double t1) const override;
  double featureTime_s() const override { return smooth_until_s > 0.0 ? smooth_until_s : 0.0; }
  double roughStart_s() const override { return smooth_until_s > 0.0 ? smooth_until_s : -1.0; }
  bool random() const override { return true; }
  void check(const ScenarioSpec& s, const std::string& where) const override;
};

}  // namespace dtwin
