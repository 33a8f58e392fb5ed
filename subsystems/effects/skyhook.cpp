#include "subsystems/effects/skyhook.hpp"

namespace dtwin {

SkyhookEffect::SkyhookEffect() {
  specs_ = {effectParameter("damping", "N*s/m", "skyhook gain c_sky per corner (off: 0)", 0.0, 0.0,
                            kUnbounded, 0.0, 8000.0)};
}

}  // namespace dtwin
