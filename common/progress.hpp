#pragma once
// The one progress callback of the long-running stages (calibration, diagnosis, study): the stage
// being worked on ("optimum", "calibrate M1 design", ...), and how far it is (done of total).
#include <cstddef>
#include <functional>
#include <string>

namespace dtwin {

/// A line of text for the user (what a long call is about to do), before its work starts.
using SayFn = std::function<void(const std::string&)>;

/// Progress: `done` of `total` units finished. Called one call at a time (possibly from worker
/// threads), never concurrently.
using ProgressFn = std::function<void(std::size_t done, std::size_t total)>;

using StageProgress =
    std::function<void(const std::string& stage, std::size_t done, std::size_t total)>;

}  // namespace dtwin
