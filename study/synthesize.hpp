#pragma once
// `twin synthesize` as one call: synthetic field data of calibrated assemblies (posterior draws on
// library roads, plus noise), accumulated as streaming moments (classification/synthesis.hpp),
// one folder per assembly, and the index synthesize.json beside them.
//
//   SynthesizeRequest r;
//   r.calibration = "out/calib"; r.out = "out/synth"; r.options.draws = 400;
//   auto runs = synthesizeAssemblies(study, r, progress, on_done);
#include <functional>
#include <string>
#include <vector>

#include "classification/synthesis.hpp"
#include "common/progress.hpp"
#include "io/study.hpp"

namespace dtwin {

struct SynthesizeRequest {
  std::string calibration;       ///< folder written by `twin calibrate` (reads <id>/posterior.csv)
  std::string assembly = "all";  ///< an assembly id or "all"
  std::string out;  ///< each assembly writes OUT/<id>/; OUT/synthesize.json indexes them
  classify::SynthesisOptions options;  ///< command and processes included
  bool force = false;                  ///< run even above the work limits (io/work.hpp)
};

/// One synthesized assembly.
struct SynthesizeRun {
  AssemblySpec assembly;
  std::string dir;  ///< OUT/<id>
  classify::SynthesisResult result;
  /// The lines `twin synthesize` prints: sizes, failures (the first five), cost, where it went.
  std::string text() const;
};

/// Checks the request (the calibration folder exists, OUT is a folder or absent, the estimated work
/// within the limits unless `force`, every posterior.csv readable: all before any simulation), then
/// synthesizes each assembly in the study's order and writes OUT/synthesize.json on the root.
/// `progress(stage, done, total)` with stage "<id> synthesize"; `done` is called after each
/// assembly. InputError for a bad request or file.
std::vector<SynthesizeRun> synthesizeAssemblies(
    const Study& study, const SynthesizeRequest& request, const StageProgress& progress = {},
    const std::function<void(const SynthesizeRun&)>& done = {});

}  // namespace dtwin
