#pragma once
// Road type "crg": a road surface from an ASAM OpenCRG file (subsystems/crg.hpp), the two wheel
// tracks at lateral offsets v along the file's reference line u.
#include <optional>

#include "subsystems/crg.hpp"
#include "twin/road_setting.hpp"

namespace dtwin {

class CrgRoadSetting final : public RoadSetting {
 public:
  std::string path;  ///< absolute, or relative to the working directory (the study file's folder is
                     ///< applied on parse)
  std::optional<double> left_v_m, right_v_m;  ///< the tracks' v; default +/- half the track width
  std::optional<double> u_start_m;            ///< u of the front axle at time 0; default: first u
  std::shared_ptr<const CrgSurface> surface;  ///< read once, on parse

  /// Fields: path (relative to the study file's folder), left_v_m, right_v_m, u_start_m.
  static std::shared_ptr<const RoadSetting> parse(TableReader& table);
  std::string type() const override { return "crg"; }
  bool measured() const override { return true; }
  nlohmann::json toJson() const override;
  /// Throws InputError when the front axle would leave the file's u range during the run.
  std::shared_ptr<const Road> make(const ScenarioSpec& s, const VehicleData& v,
                                   std::uint64_t seed) const override;
  std::vector<std::string> describeWindow(const ScenarioSpec& s, const VehicleData& v, double t0,
                                          double t1) const override;

 private:
  double uStart() const { return u_start_m.value_or(surface->u0_m); }
  /// u under the front axle at time t.
  double frontU(const ScenarioSpec& s, double t) const;
};

}  // namespace dtwin
