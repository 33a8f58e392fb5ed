#include "subsystems/effects/road_feedforward.hpp"

namespace dtwin {

RoadFeedforwardEffect::RoadFeedforwardEffect() {
  ParameterSpec tau = effectParameter("time_constant_s", "s", "the low-pass's time constant tau",
                                      0.02, 0.0, kUnbounded, 0.002, 0.1,
                                      /*lo_inclusive=*/false);
  tau.shape = true;
  specs_ = {
      effectParameter("gain", "N*s/m",
                      "feed-forward gain G per corner on the road's vertical velocity (off: 0)",
                      0.0, -kUnbounded, kUnbounded, -8000.0, 8000.0),
      tau};
}

}  // namespace dtwin
