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

#include "classification/synthesis.hpp"
#include "io/measurement.hpp"
#include "io/study.hpp"

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

/// One channel's band on the dense grid through the lab scenario.
struct ChannelBand {
  std::string channel;
  std::vector<double> times;  ///< the grid, ascending: holds every lab time of the channel exactly
  std::vector<double> lo, med, hi;  ///< 2.5 / 50 / 97.5 % of η(θ)
  std::vector<double> plo, phi;     ///< 2.5 / 97.5 % of the posterior predictive (with noise)
  /// The row of time `t` (a lab time of the channel: the grid holds it exactly); times.size()
  /// when the grid does not hold it.
  std::size_t at(double t) const;
};

/// One assembly's posterior and its bands.
struct AssemblyBands {
  AssemblySpec assembly;
  calib::PosteriorSample posterior;  ///< calibration/<id>/posterior.csv
  std::size_t drawn = 0;             ///< rows simulated
  std::size_t failures = 0;          ///< of which failed to simulate
  double noise_sd = 0.0;  ///< median of 1/√τ over the rows that simulated (0 when none)
  /// Per lab channel, the band on a dense grid through the lab scenario (the grid's times and the
  /// lab times, merged): the continuous response the report draws, and the band at each lab
  /// time (ChannelBand::at). Empty when every row failed.
  std::vector<ChannelBand> channels;
};

/// What a study folder holds for its report, with the predictive bands computed.
struct LabBands {
  std::string study_path;  ///< the study file named by study.json
  Study study;
  std::string lab_path;  ///< summary.json's lab path if it exists, else OUT/lab/lab.csv
  LabData lab;
  int draws = 0;
  std::vector<AssemblyBands>
      assemblies;  ///< the study's assemblies that have a posterior.csv, in study order
  std::vector<std::string> warnings;  ///< e.g. the study file changed after the study ran
};

/// Reads `study_dir` (study.json, summary.json, the study file it names, the lab data, every
/// calibration/<id>/posterior.csv) and simulates the bands. InputError naming the file when one is
/// missing or malformed, when no assembly has a posterior, or when a posterior's columns are not
/// the study's calibrated parameters. A row whose simulation fails counts as a failure.
LabBands predictLabBands(const std::string& study_dir, const LabBandOptions& options = {});

/// Quantile p of the equal-weight mixture of N(mean_k, sd_k²) (bisection on its CDF).
double normalMixtureQuantile(const std::vector<double>& mean, const std::vector<double>& sd,
                             double p);

}  // namespace dtwin::study
