#pragma once
// The frequency response from an input u to an output y estimated from records, with its random
// error, and a measured response against a model's (`twin compare`, docs/diagnosis.md, "The
// frequency response"). Pure numerics on vectors, like signal.hpp, whose Welch spectra
// (welchCrossSpectra) and uniform grid (uniformGrid, onGrid) it uses.
//
// Conventions: as signal.hpp (one-sided bins f_k = k·fs/L, k = 0..L/2; Hann, 50 % overlap, the
// per-segment mean removed). Magnitudes in y unit per u unit; phases in degrees, wrapped into
// (−180°, 180°] (not unwrapped: an unwrapped phase carries every slip of a noisy bin into all the
// bins above it).
//
// References
//  [BP10] J. S. Bendat, A. G. Piersol, Random Data: Analysis and Measurement Procedures, 4th ed.,
//         Wiley 2010: §9.1.4 (H1 = G_uy/G_uu), §9.2.3 (coherence), Table 9.6 and eqs. (9.65),
//         (9.73), (9.90) (random errors of γ², |H| and φ), eq. (9.26)/§9.2.3 (the null distribution
//         of γ², P(γ̂² > c) = (1 − c)^{n_d − 1}).
#include <complex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "diagnosis/signal.hpp"

namespace dtwin::diag {

/// The H1 estimate of the frequency response from u to y, per bin.
struct FrequencyResponse {
  std::vector<double> freq_hz;
  std::vector<std::complex<double>> h;  ///< H1(f) = G_uy(f) / G_uu(f); 0 where G_uu = 0
  std::vector<double> magnitude;        ///< |H1| [y unit / u unit]
  std::vector<double> phase_deg;        ///< arg H1 in (−180°, 180°]
  std::vector<double> coherence;  ///< γ² = |G_uy|² / (G_uu G_yy) ∈ [0, 1]; 0 where G_uu G_yy = 0
  /// The normalised random error of |H1| [BP10 eq. 9.73]: ε = sqrt(1 − γ²) / (|γ| sqrt(2 n_d)), the
  /// standard deviation of |Ĥ| over |H| (and of each part of Ĥ − H over |H|); +inf where γ² = 0.
  std::vector<double> magnitude_error;
  /// The standard deviation of the phase [BP10 eq. 9.90]: ε in radians, written in degrees, at most
  /// 180°/√3 (a phase spread evenly over the circle).
  std::vector<double> phase_sd_deg;
  int segment = 0, segments = 0;  ///< L and K of the Welch estimate
  double averages = 0;  ///< n_d, the effective number of independent averages (CrossSpectra)
};

/// H1 from u to y sampled together at fs_hz, Welch segments of `segment` samples
/// (welchCrossSpectra). Throws std::invalid_argument as welchCrossSpectra (sizes differ, fs <= 0,
/// fewer than 8 samples, segment < 8).
FrequencyResponse frequencyResponse(const std::vector<double>& u, const std::vector<double>& y,
                                    double fs_hz, int segment);

/// Measured against predicted over one band.
struct ResponseBand {
  std::string band;
  double lo_hz = 0, hi_hz = 0;
  int bins = 0;                     ///< bins in [lo, hi) with both responses nonzero
  double gain_ratio = 1;            ///< exp of the weighted mean of ln(|Ĥ_m| / |Ĥ_p|)
  double gain_ratio_error = 0;      ///< its standard deviation on the log scale (≈ relative sd)
  double phase_difference_deg = 0;  ///< the weighted mean of arg(Ĥ_m / Ĥ_p), in (−180°, 180°]
  double phase_difference_sd_deg = 0;
  double coherence_measured = 0, coherence_predicted = 0;  ///< band means of γ²
  double chi2 = 0;       ///< |mean ln(Ĥ_m/Ĥ_p)|² / sd², against χ²₂
  bool differs = false;  ///< chi2 > χ²₂ at the level (−2 ln(1 − level))
};

/// Measured against predicted, both from the same input.
struct ResponseComparison {
  FrequencyResponse measured, predicted;
  /// The residual r = measured − predicted against the input: Ĥ_m − Ĥ_p is exactly r's H1, and its
  /// coherence γ_r² says how much of r the input explains. Under "the two responses agree" (the
  /// residual holds no part linear in the input) P(γ̂_r² > c) = (1 − c)^{n_d − 1} [BP10]: a bin
  /// differs when γ̂_r² > c_level = 1 − (1 − level)^{1/(n_d − 1)}.
  std::vector<double> residual_coherence;
  double coherence_threshold = 1;   ///< c_level; 1 (nothing differs) when n_d <= 1
  std::vector<bool> differs;        ///< per bin; about 1 − level of the bins differ by chance
  std::vector<ResponseBand> bands;  ///< over vehicleBands(fs)
  double level = 0.95;
};

/// frequencyResponse of `measured` and of `predicted` from u, the per-bin test and the per-band
/// summary. Each bin's ln(Ĥ_m/Ĥ_p) has, under agreement, the standard deviation s_k = σ_k / |Ĥ_p|
/// in each of its parts (log gain, phase in radians), σ_k² = G_rr (1 − γ_r²) / (2 n_d G_uu) the
/// variance of each part of r's H1. A band averages ln(Ĥ_m/Ĥ_p) over its bins with weights 1/s_k²;
/// neighbouring Hann bins are correlated, so the band holds about max(1, M/2) independent bins of
/// its M and its variance is min(M, 2) / Σ 1/s_k². Throws std::invalid_argument as
/// frequencyResponse, or when the sizes differ or level ∉ (0, 1).
ResponseComparison compareResponses(const std::vector<double>& u,
                                    const std::vector<double>& measured,
                                    const std::vector<double>& predicted, double fs_hz, int segment,
                                    double level = 0.95);

/// The frequency response of one compared series: from the road under the channel's wheel to the
/// measured and the predicted values, on the uniform grid of the series' times (uniformGrid: the
/// longest stretch between gaps, resampled when the clock jitters), at 95 %.
struct SeriesResponse {
  std::string input;      ///< the input's channel, e.g. "road_fl_m"; "" when there is none
  bool computed = false;  ///< false: `note` says why not
  double fs_hz = 0;
  ResponseComparison response;
  std::string note;  ///< why there is none, or what the grid was made of ("" when plain)
  /// {"input", "note"} when not computed; else also the estimate's settings and bands, and with
  /// `with_bins` the bins: f_hz, measured and predicted (magnitude, phase_deg, coherence,
  /// magnitude_error, phase_sd_deg), residual_coherence and differs (6 significant digits).
  nlohmann::json toJson(bool with_bins = true) const;
};

/// The SeriesResponse of values measured and predicted at times t (ascending, distinct) with the
/// input `road` at the same times (empty: none). Needs 64 times on the grid; the Welch segment is
/// welchSegmentFor(grid size). Throws std::invalid_argument when the sizes differ.
SeriesResponse seriesResponse(const std::vector<double>& t, const std::vector<double>& road,
                              const std::string& input, const std::vector<double>& measured,
                              const std::vector<double>& predicted);

}  // namespace dtwin::diag
