#include "subsystems/effects/tire_enveloping.hpp"

namespace dtwin {

TireEnvelopingEffect::TireEnvelopingEffect() {
  specs_ = {effectParameter("length_m", "m", "averaging base length (off: 0 = point contact)", 0.0,
                            0.0, 2.0, 0.0, 0.4)};
}
RoadSample TireEnvelopingEffect::filterRoad(const Road& road, Track t, double x,
                                            ParamValues v) const {
  return v[0] > 0.0 ? road.sampleAveraged(t, x, v[0]) : road.sample(t, x);
}

}  // namespace dtwin
