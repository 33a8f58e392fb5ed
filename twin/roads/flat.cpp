#include "twin/roads/flat.hpp"

namespace dtwin {

std::shared_ptr<const RoadSetting> FlatRoadSetting::parse(TableReader&) {
  return std::make_shared<const FlatRoadSetting>();
}

std::shared_ptr<const Road> FlatRoadSetting::make(const ScenarioSpec&, const VehicleData&,
                                                  std::uint64_t) const {
  return std::make_shared<FlatRoad>();
}

}  // namespace dtwin
