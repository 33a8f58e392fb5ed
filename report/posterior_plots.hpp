#pragma once
// The posterior figures of the study report (report/study_report.cpp, section 2): the weighted
// density of each calibrated value, and the pair plot of every two with the joint region, the
// optimum, the truth when known and the profile intervals. Griddy Gibbs draws θ only at design
// points, so the raw sample is a few spikes; the density smooths the design points' posterior
// masses with a Gaussian kernel no narrower than the design's spacing.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "calibration/region.hpp"
#include "report/svg_plot.hpp"

namespace dtwin::report {

/// A Gaussian kernel density of a sample on a grid.
struct Density {
  std::vector<double> x, f;  ///< grid and density (integrates to 1 over the real line)
  double bandwidth = 0.0;
  /// Distinct sample values and their share of the sample (the design points' posterior masses).
  std::vector<double> atoms, mass;
};

/// The density of `v` on `points` evenly spaced values of [lo, hi]: the atoms (distinct values)
/// weighted by their counts, bandwidth h = max(0.9 min(sd, IQR/1.34) n^(−1/5), the median gap
/// between neighbouring atoms, (hi − lo)/200) with n the number of atoms (the sample repeats
/// design points; its size is no measure of information). Empty `v` gives an empty density.
Density weightedDensity(const std::vector<double>& v, double lo, double hi, int points = 200);

/// The outline (counter-clockwise, closed: the last vertex repeats the first) of the projection
/// of region `r` on the plane of parameters (i, j), in physical units. The region is a
/// parallelepiped, so its projection is a zonogon: its vertices come from the generators sorted by
/// angle.
std::vector<std::array<double, 2>> projectedRegion(const calib::Region& r, int i, int j);

/// What the posterior figures mark for one calibrated value.
struct ParameterMarks {
  std::string name, unit;
  std::vector<double> sample;  ///< the posterior sample (one value per row)
  std::optional<double> truth, optimum;
  std::optional<std::pair<double, double>> profile;  ///< the profile-likelihood 95 % interval
  double lo = 0, hi = 0;                             ///< the axis range (set by axisRange)
};

/// Sets m.lo, m.hi to the sample's range with the marks and `extra` values inside, padded by 4 %.
void axisRange(ParameterMarks& m, const std::vector<double>& extra = {});

/// The gnuplot commands of one density panel: the weighted density, the posterior's central 95 %
/// (dashed), the profile interval (dotted green), the optimum (dash-dot black) and the truth (red),
/// x ticks human and labelled "name [unit]" (unlabelled ticks when !labelled), no y ticks.
std::string densityPanel(GnuplotSvg& gp, const ParameterMarks& m, bool labelled = true,
                         int target_ticks = 4);

/// The pair plot of `params` (d >= 2): density panels on the diagonal, below it every pair's
/// posterior design points (area ∝ posterior mass), the region's projection, the profile box, the
/// optimum and the truth; above it the posterior correlation. Returns the <svg>.
std::string pairPlot(GnuplotSvg& gp, const std::vector<ParameterMarks>& params,
                     const std::optional<calib::Region>& region, const std::string& title);

/// Posterior correlation of two equally long samples (0 when either is constant).
double sampleCorrelation(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace dtwin::report
