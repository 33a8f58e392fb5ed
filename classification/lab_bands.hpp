#pragma once
// The posterior predictive bands of a study's lab scenario, per calibrated assembly: what
// study::predictLabBands (study/lab_bands.hpp) computes and report/ draws (the study report, the
// lab page). Result types only, with the mixture quantile they are made of.
#include <cstddef>
#include <string>
#include <vector>

#include "classification/synthesis.hpp"
#include "io/measurement.hpp"
#include "io/study.hpp"

namespace dtwin::classify {

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

/// Quantile p of the equal-weight mixture of N(mean_k, sd_k²) (bisection on its CDF).
double normalMixtureQuantile(const std::vector<double>& mean, const std::vector<double>& sd,
                             double p);

}  // namespace dtwin::classify
