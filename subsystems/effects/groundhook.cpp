#include "subsystems/effects/groundhook.hpp"

namespace dtwin {

GroundhookEffect::GroundhookEffect() {
  specs_ = {effectParameter("damping", "N*s/m", "groundhook gain c_gh per corner (off: 0)", 0.0,
                            0.0, kUnbounded, 0.0, 8000.0)};
}

}  // namespace dtwin
