#pragma once
// The one progress callback of the long-running stages (calibration, diagnosis, study): the stage
// being worked on ("optimum", "calibrate M1 design", ...), and how far it is (done of total).
#include <cstddef>
#include <functional>
#include <string>

namespace dtwin {

using StageProgress = std::function<void(const std::string& stage, std::size_t done, std::size_t total)>;

}  // namespace dtwin
