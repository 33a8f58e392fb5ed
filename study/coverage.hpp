#pragma once
// Coverage of the calibration's 95 % intervals, measured (docs/calibration.md, "Coverage").
//
// An interval printed as 95 % must hold the truth about 95 % of the time. For each assembly, its
// own lab data are generated at the study's true parameters (twin generate lab --assembly ID)
// with N noise seeds s = first_seed .. first_seed + N − 1, each data set is calibrated exactly as
// `twin calibrate` would (the study's sizes and [calibration] settings, the study's design seed),
// and per calibrated parameter the benchmark counts the seeds whose 95 % interval holds the truth.
// It also compares the posterior's width with how far the estimates move from seed to seed:
//  - the sd of the posterior means across seeds (for a regular, data-dominated posterior the mean
//    posterior sd is about this; far below 1 means overconfident). Where the data leave a ridge
//    open up to a bound, the posterior mean sits mid-ridge in every seed and moves little, so this
//    ratio overstates the width;
//  - the sd of the optimiser's θ̂ across seeds (the estimate the data alone make), and
//  - RMSE / mean sd: the root mean square of (posterior mean − truth) over the mean posterior sd,
//    about 1 when the sd is an honest error bar of the mean.
//
// \par Uncertainty of the figure itself
// A coverage of k out of m pairs is a binomial proportion; with m = 80 and a true 95 %, its sd
// is 2.4 points. The table prints the 95 % Wilson interval of each proportion.
//
// \par Files (in `out_dir`, resumable: a killed run rerun with the same command continues)
//   <id>/lab_<seed>.csv (+ .json sidecar)   the generated lab data
//   <id>/seed_<seed>/                       the calibration folder (docs/calibration.md)
//   coverage.json, coverage.md              the table, with how it was made
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/calibrate.hpp"
#include "io/study.hpp"
#include "study/calibrate.hpp"

namespace dtwin::calib {

struct CoverageOptions {
  int seeds = 20;                       ///< N noise seeds, >= 2
  std::uint64_t first_seed = 1001;      ///< noise seed of the first data set
  std::vector<std::string> assemblies;  ///< empty: every assembly of the study
  CalibrationOptions
      calibration;      ///< as `twin calibrate` would use (CalibrationOptions::fromStudy)
  std::string out_dir;  ///< required
  std::string command;  ///< recorded in coverage.json
  /// Throws InputError whose where() is "coverage.<field>" (common/validate.hpp), then validates
  /// `calibration`. runCoverage calls it.
  void validate() const;
};

/// One parameter of one assembly over the seeds.
struct CoverageRow {
  std::string assembly, parameter;
  double truth = 0.0;
  std::string interval;        ///< which interval ci95 is ("profile" or "posterior")
  int seeds = 0, covered = 0;  ///< seeds whose ci95 holds the truth
  int covered_profile = 0, covered_posterior = 0;  ///< the same for each interval
  double wilson_low = 0.0, wilson_high = 0.0;      ///< 95 % Wilson interval of covered / seeds
  double mean_width = 0.0;                         ///< mean width of ci95
  double mean_width_profile = 0.0, mean_width_posterior = 0.0;
  double mean_sd = 0.0;       ///< mean posterior sd
  double sd_of_means = 0.0;   ///< sd of the posterior means across seeds
  double rmse = 0.0;          ///< root mean square of (posterior mean − truth)
  double sd_of_optima = 0.0;  ///< sd of the optimiser's θ̂ across seeds
  double sd_ratio() const { return sd_of_means > 0 ? mean_sd / sd_of_means : 0.0; }
  double optimum_ratio() const { return sd_of_optima > 0 ? mean_sd / sd_of_optima : 0.0; }
  double rmse_ratio() const { return mean_sd > 0 ? rmse / mean_sd : 0.0; }
};

struct CoverageResult {
  std::vector<CoverageRow> rows;
  /// Per assembly: covered (parameter, seed) pairs and all pairs.
  std::vector<std::pair<std::string, std::pair<int, int>>> totals;
  double median_calibration_wall_s = 0.0;
  double wall_s = 0.0;
  nlohmann::json toJson() const;
  /// The table in Markdown (docs/calibration.md quotes it).
  std::string markdown() const;
};

/// Progress: assembly, seed, index of the data set (0-based), data sets in all, stage, done, total.
using CoverageProgress =
    std::function<void(const std::string& assembly, std::uint64_t seed, int index, int count,
                       const std::string& stage, std::size_t done, std::size_t total)>;

/// Runs the benchmark (see the top of this file); writes coverage.json and coverage.md atomically
/// at the end.
CoverageResult runCoverage(const Study& study, const CoverageOptions& options,
                           const CoverageProgress& progress = {});

/// `twin coverage`'s options from a front end's settings, checked before anything runs: the
/// assembly ids, out_dir a folder or absent (InputError naming --out), the work of `seeds`
/// calibrations of each assembly at the study's sizes with `overrides` within the limits unless
/// `force`; then `calibration` the study's options (fromStudy; the given threads and processes
/// kept) with `overrides` over them, and the whole validated.
CoverageOptions coverageOptions(const Study& study, CoverageOptions options,
                                const CalibrationOverrides& overrides, bool force);

/// The line `twin coverage` prints before it starts: the assemblies, the seeds, the region and
/// the design, and the folder.
std::string coveragePlan(const Study& study, const CoverageOptions& options);

/// The lines `twin coverage` prints at the end: the table, the calibrations' wall times and the
/// files written in `out_dir`.
std::string coverageText(const CoverageResult& result, const std::string& out_dir);

/// 95 % Wilson score interval of k successes in m trials.
std::pair<double, double> wilsonInterval(int k, int m);

}  // namespace dtwin::calib
