#pragma once
// The posterior predictive through the lab scenario of a study folder (written by `twin study`):
// for each calibrated assembly, `draws` evenly spaced rows of calibration/<id>/posterior.csv (rows
// ⌊(k + ½)·S / draws⌋, k = 0 … draws − 1) are simulated on the study's lab scenario and predicted
// on a dense grid of times that holds every lab time; the band is the 2.5 / 50 / 97.5 % quantiles
// of the predictions η(θ) and, with the measurement noise N(0, 1/τ) of each draw, the 2.5 / 97.5 %
// quantiles of the posterior predictive (an equal-weight normal mixture). This is the one
// simulation the study report needs; it lives here so that report/ only draws
// (report/study_report.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "classification/lab_bands.hpp"

namespace dtwin::study {

struct LabBandOptions {
  int draws = 50;   ///< posterior rows per assembly (>= 2)
  int threads = 0;  ///< simulations in parallel (0: all cores; never changes the numbers)
  /// Evenly spaced times from 0 to the last lab time, and as many from the first lab time to the
  /// last, at which the response is predicted besides the lab times (AssemblyBands::channels;
  /// >= 2). The same runs give both: no extra simulation.
  int grid_points = 400;
  /// InputError whose where() is "lab_bands.<field>" (common/validate.hpp) when out of range.
  void validate() const;
};

// The result types live below report/ (classification/lab_bands.hpp), which draws them.
using classify::AssemblyBands;
using classify::ChannelBand;
using classify::LabBands;
using classify::normalMixtureQuantile;

/// Reads `study_dir` (study.json, summary.json, the study file it names, the lab data, every
/// calibration/<id>/posterior.csv) and simulates the bands. InputError naming the file when one is
/// missing or malformed, when no assembly has a posterior, or when a posterior's columns are not
/// the study's calibrated parameters. A row whose simulation fails counts as a failure.
LabBands predictLabBands(const std::string& study_dir, const LabBandOptions& options = {});

}  // namespace dtwin::study
