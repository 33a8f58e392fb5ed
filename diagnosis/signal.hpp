#pragma once
// Signal tools for the diagnosis (docs/diagnosis.md): where, in frequency, in state and in time,
// a model fails against measurements. Everything here is pure numerics; the spectra need uniformly
// sampled records, which uniformGrid and onGrid make of a record at any increasing times; the usual
// input is a residual r(t) = measured − model.
//
// Conventions
//  * Sampling frequency fs is in Hz; time in s; frequencies in Hz.
//  * Spectra are one-sided: bins f_k = k·Δf, k = 0..M, Δf = fs/L, f_M = fs/2 (L is even).
//  * A PSD of a signal in `unit` is in unit²/Hz.
//  * Bad arguments (mismatched sizes, fs <= 0, too few samples, bins < 1, ...) throw
//    std::invalid_argument with a one-line "function: rule, got value" message.
//
// References
//  [W67]  P. D. Welch, "The use of fast Fourier transform for the estimation of power spectra",
//         IEEE Trans. Audio Electroacoust. 15(2):70–73, 1967.
//  [PW93] D. B. Percival, A. T. Walden, Spectral Analysis for Physical Applications, CUP 1993,
//         §6.17 (WOSA), eq. (292b) for the equivalent degrees of freedom.
#include <cmath>
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

#include "common/statistics.hpp"

namespace dtwin::diag {

/// The fit percentage of system identification (MATLAB's `compare`): 100 (1 − ‖y − ŷ‖ / ‖y − mean
/// y‖), from the sum of squared errors `sse` and the values' count, sum and sum of squares; 0 when
/// the values do not vary.
inline double fitPercent(double sse, double n, double sum, double sum_sq) {
  const double spread = sum_sq - sum * sum / n;  // ‖y − mean y‖²
  return spread > 0 ? 100.0 * (1.0 - std::sqrt(sse / spread)) : 0.0;
}

/// A one-sided spectrum: value[k] at freq_hz[k], freq_hz[k] = k·Δf, k = 0..M (see welchPsd).
struct Spectrum {
  std::vector<double> freq_hz;
  std::vector<double> value;
};

/// One-sided Welch power spectral density [unit²/Hz] of x sampled at fs_hz [W67].
///
/// x is cut into K segments of L samples with 50 % overlap (hop L/2; K = 1 + ⌊(N − L)/(L/2)⌋,
/// trailing samples that do not fill a segment are ignored). L = `segment` clamped to x.size()
/// and rounded down to even. Each segment has its own mean removed, is multiplied by the periodic
/// Hann window w[n] = ½(1 − cos(2πn/L)), and transformed, X_k = Σ_n w[n] x[n] e^{−2πikn/L}. Then
///
///     P(f_k) = c_k / (K · fs · U) · Σ_segments |X_k|²,   U = Σ_n w[n]²,
///
/// with c_k = 1 at DC and Nyquist and c_k = 2 elsewhere (folding negative frequencies). With this
/// scaling the integral of P over [0, fs/2] (bandIntegral over the whole spectrum) equals the
/// variance of x (Parseval), up to estimation error and the per-segment mean removal.
/// A white noise of variance σ² has P = 2σ²/fs. Throws if fs_hz <= 0, x.size() < 8 or segment < 8.
Spectrum welchPsd(const std::vector<double>& x, double fs_hz, int segment);

/// Magnitude-squared coherence C_xy(f) = |P_xy(f)|² / (P_xx(f) P_yy(f)) ∈ [0, 1] with the Welch
/// settings of welchPsd (the cross spectrum P_xy = avg conj(X_k) Y_k). C = 1 for y a noiseless
/// linear filtering of x; for independent x and y, E[C] ≈ 1/K (the estimator's bias floor). Bins
/// where P_xx·P_yy vanishes (e.g. DC after mean removal of a constant) get C = 0.
/// Throws if the sizes differ, or as welchPsd.
Spectrum coherence(const std::vector<double>& x, const std::vector<double>& y, double fs_hz,
                   int segment);

/// The Welch auto and cross spectra of two records (frequency_response.hpp's H1 estimate and
/// coherence are made of them), with the settings and scaling of welchPsd:
/// pxx = welchPsd(x), pyy = welchPsd(y), pxy(f_k) = c_k / (K · fs · U) · Σ_segments conj(X_k) Y_k.
struct CrossSpectra {
  std::vector<double> freq_hz;
  std::vector<double> pxx, pyy;           ///< [x unit²/Hz], [y unit²/Hz]
  std::vector<std::complex<double>> pxy;  ///< [x unit · y unit/Hz]
  int segment = 0;                        ///< L, the segment length used
  int segments = 0;                       ///< K
  /// The effective number of independent averages, n_d = ν_W / 2 with ν_W the equivalent degrees
  /// of freedom of the Welch PSD (see bandAnalysis): ≈ 0.95 K for Hann at 50 % overlap (1 for K =
  /// 1).
  double averages = 0;
};

/// welchPsd of x and y and their cross spectrum, in one pass. Throws as coherence.
CrossSpectra welchCrossSpectra(const std::vector<double>& x, const std::vector<double>& y,
                               double fs_hz, int segment);
/// The phase of pxy is y's lead over x: y(t) = x(t + τ) gives arg pxy = 2π f τ, and pxy / pxx is
/// the H1 estimate of the frequency response from x to y.

/// The Welch segment length the comparison uses for n samples: the largest power of two <= n/2,
/// within [32, 512] (512 at 100 Hz: bins 0.2 Hz apart, at least 3 segments).
int welchSegmentFor(std::size_t n);

/// ∫_{f_lo}^{f_hi} S(f) df over a spectrum on the grid of welchPsd, by the trapezoid rule written
/// on the bins: Σ_{k: f_lo <= f_k < f_hi} S_k·Δ_k with Δ_k = Δf, except Δ_0 = Δ_M = Δf/2 (the DC
/// and Nyquist bins are half inside [0, fs/2]). Bands that partition [0, fs/2] thus add up to the
/// trapezoid integral over the whole spectrum. A band with f_hi >= f_M includes the last bin.
/// Returns 0 when no bin falls in the band. Throws if the spectrum has fewer than 2 bins, its
/// sizes differ, or f_hi < f_lo.
double bandIntegral(const Spectrum& s, double f_lo, double f_hi);

/// Mean of S_k over the bins with f_lo <= f_k < f_hi (same band rule as bandIntegral);
/// NaN when no bin falls in the band.
double bandMean(const Spectrum& s, double f_lo, double f_hi);

/// A named frequency band [lo_hz, hi_hz).
struct Band {
  std::string name;
  double lo_hz, hi_hz;
};

/// The standard bands of a road vehicle: "body" 0.5–2 Hz (sprung-mass heave/pitch/roll),
/// "mid" 2–8 Hz, "wheel_hop" 8–20 Hz (unsprung-mass modes), "high" 20 Hz–fs/2. Bands are clipped
/// at the Nyquist frequency fs/2; a band starting at or above fs/2 is omitted. Throws if fs_hz <=
/// 0.
std::vector<Band> vehicleBands(double fs_hz);

/// The verdict on one band of a residual.
struct BandReport {
  std::string band;
  double lo_hz, hi_hz;
  double residual_power;  ///< bandIntegral of the residual's Welch PSD [unit²]
  double noise_power;     ///< the same integral of the noise floor (white: 2σ²/fs) [unit²]
  double ratio;           ///< residual_power / noise_power
  double coherence;       ///< bandMean of the residual–input coherence; NaN without input
  bool significant;       ///< ratio > χ²_{ν,1−α}/ν (see bandAnalysis)
};

/// Band-by-band comparison of a residual with its measurement noise floor, over vehicleBands(fs).
///
/// Under H0 (residual = white noise of variance σ² = noise_variance) each Welch bin estimate is
/// P̂_k ~ P·χ²_{ν_W}/ν_W with, for the Hann window at 50 % overlap [W67; PW93 eq. 292b],
///
///     ν_W = 2K / (1 + 2 Σ_{m=1}^{K−1} (1 − m/K) ρ²(m)),   ρ(m) = Σ_n w[n] w[n + m·L/2] / Σ_n
///     w[n]²,
///
/// the correlation of the white-noise periodograms of segments m hops apart. For the periodic Hann
/// window ρ(1) = 1/6 (the sum runs over the L/2 samples two neighbouring segments share) and
/// ρ(m>1) = 0, so ν_W ≈ 1.89 K, as [PW93 eq. 292c] (FrfEstimate.QuarterCarOnARandomRoad... checks
/// n_d = ν_W/2 against the scatter of an H1 estimate). Summing the M_b bins of a band, the power
/// estimates of neighbouring Hann bins are correlated too (ρ² = 4/9 adjacent, 1/36 two apart), so a
/// band holds about M_b/1.94 independent bins; only every second bin is counted: ν = ν_W · max(1,
/// M_b/2). Flagged when
///
///     residual_power / noise_power > χ²_{ν, 1−α} / ν,
///
/// a one-sided test at level α per band (χ² quantile by the Wilson–Hilferty approximation); over
/// 8000 bands of white noise at α = 0.01 it flagged 0.99 %. The per-segment mean removal biases the
/// lowest bins down, which errs on the side of "not significant". Up to four bands are tested per
/// call: the chance that some band of a pure-noise residual is flagged is about 4α.
/// `input` (nullable, same length as residual) is e.g. the road or a body acceleration; a high
/// coherence says the missing physics is driven by that input. Throws on size mismatch,
/// fs_hz <= 0, noise_variance <= 0, alpha ∉ (0, 1), or as welchPsd.
/// `noise_acf` (optional) is the noise's autocorrelation in lags of a sample, ρ(0), ρ(1), ...
/// (gridNoiseAutocorrelation): the floor is then 2σ²/fs (ρ(0) + 2 Σ_m ρ(m) cos(2π f m/fs)) instead
/// of white; empty: white. Throws if noise_acf[0] is not > 0.
std::vector<BandReport> bandAnalysis(const std::vector<double>& residual, double fs_hz,
                                     double noise_variance, const std::vector<double>* input,
                                     int segment, double alpha = 0.01,
                                     const std::vector<double>& noise_acf = {});

/// One bin of a force-state map.
struct Bin {
  double lo, hi;  ///< smallest and largest state value in the bin
  double centre;  ///< mean state in the bin
  double mean;    ///< mean residual in the bin
  double se;  ///< standard error of that mean, s/√n with the sample deviation s (n−1); NaN if n < 2
  long count;  ///< samples in the bin
};

/// Force-state map: the residual averaged in `bins` equal-count (quantile) bins of the state.
/// Samples are sorted by state (stable) and bin b gets the sorted samples [⌊b·N/B⌋, ⌊(b+1)·N/B⌋),
/// so counts differ by at most one; tied state values may fall in two neighbouring bins.
/// Throws if sizes differ, bins < 1 or bins > N.
std::vector<Bin> binByState(const std::vector<double>& state, const std::vector<double>& residual,
                            int bins);

/// One candidate signature fitted to a force-state map.
struct SignatureFit {
  std::string feature;        ///< feature name (see fitDeflectionSignatures / fitRateSignatures)
  double coefficient;         ///< b in r ≈ a + b·feature [residual unit / feature unit]
  double explained_fraction;  ///< 1 − Σ(r − a − b·f)² / Σ r²  (about zero, not about the mean)
  double knee_at;             ///< the knee g of "knee" [state unit]; NaN for other features
};

/// Least squares r ≈ a + b·f(q) for features of a deflection-like state q [m]:
///   "knee"   max(q − g, 0)², g scanned over the 1 %, 2 %, …, 99 % quantiles of q (best g kept:
///            a bump stop or progressive spring engaging at g),
///   "cubic"  q³ (a symmetric progressive stiffness),
///   "linear" q (a stiffness error).
/// Returned sorted by explained_fraction, best first. A feature that is constant over the data
/// gets b = 0 (only the intercept). Throws if sizes differ or there are fewer than 3 samples.
std::vector<SignatureFit> fitDeflectionSignatures(const std::vector<double>& q,
                                                  const std::vector<double>& r);

/// Least squares r ≈ a + b·f(v) for features of a rate-like state v [m/s], v > 0 in compression:
///   "step"              tanh(v/v_s), v_s = 0.05·std(v) (Coulomb friction, a smoothed sign(v)),
///   "rebound_slope"     v·[v < 0] (a rebound damping error),
///   "compression_slope" v·[v > 0] (a compression damping error),
///   "linear"            v (a symmetric damping error).
/// Sorted by explained_fraction, best first; knee_at is NaN. Throws as fitDeflectionSignatures.
std::vector<SignatureFit> fitRateSignatures(const std::vector<double>& v,
                                            const std::vector<double>& r);

/// A time window where the standardised residual is large.
struct Window {
  double t_begin, t_end;  ///< times of the first and last sample of the window [s]
  double peak_z;          ///< max |z| in the window
  double share;  ///< Σ_{window} z² / Σ_{record} z² (every sample between t_begin and t_end)
};

/// Windows in time where |z| exceeds `threshold`: maximal runs of consecutive samples with
/// |z| > threshold; consecutive runs are merged when the gap t(first of next) − t(last of
/// previous) < merge_gap_s (the merged window includes the samples between), and windows with
/// t_end − t_begin < min_length_s are then dropped. Chronological order. t must be strictly
/// increasing. Throws if sizes differ, t is not increasing, or threshold, merge_gap_s or
/// min_length_s is negative.
std::vector<Window> exceedanceWindows(const std::vector<double>& t, const std::vector<double>& z,
                                      double threshold, double merge_gap_s, double min_length_s);

/// How many windows a record has and how much of it they hold (see rankWindows).
struct WindowSummary {
  std::size_t found = 0;    ///< windows at the requested merge gap (exceedanceWindows)
  std::size_t merged = 0;   ///< windows once neighbours are merged (= found when they are few)
  std::size_t listed = 0;   ///< the largest merged windows, the ones listed
  double merge_gap_s = 0;   ///< the merge gap of the merged windows (the requested one when few)
  double time_share = 0;    ///< share of the record's samples inside the found windows
  double merged_share = 0;  ///< Σ share of the merged windows
  double listed_share = 0;  ///< Σ share of the listed windows
};

/// The windows of a record, ranked.
struct WindowRanking {
  std::vector<Window> found;   ///< exceedanceWindows at the requested merge gap, chronological
  std::vector<Window> ranked;  ///< merged, largest share first (ties: earlier first); the first
                               ///< summary.listed are listed
  WindowSummary summary;
};

/// How rankWindows merges and lists.
struct WindowRankOptions {
  std::size_t max_merged = 200;  ///< merge neighbours while more windows than this remain
  std::size_t max_listed = 20;   ///< list at most this many
  double listed_share =
      0.8;  ///< list the fewest windows holding this share of the merged windows' share
};

/// The windows of exceedanceWindows ranked by their share of the residual, merged and cut to the
/// few that matter when there are many:
///  * found ≤ max_listed: every window is listed, largest share first (nothing merged);
///  * found > max_merged: neighbours are merged with the merge gap doubled (from merge_gap_s, or
///    the median step when that is 0) until at most max_merged windows remain; a merge never makes
///    a window longer than L = 2 (t.back() − t.front()) / max_merged, so a record that fails
///    throughout keeps windows of a few L at most, not one window over the whole record, and the
///    doubling stops once the gap exceeds L. A merged window's share and peak are over every
///    sample from its first to its last (as in exceedanceWindows);
///  * then the windows are sorted by share, largest first, and the fewest of the largest holding
///    `listed_share` of the merged windows' share are listed, at most max_listed.
/// time_share counts the samples from the first to the last of each found window over all samples.
/// Throws as exceedanceWindows, and if max_merged or max_listed is 0 or listed_share ∉ (0, 1].
WindowRanking rankWindows(const std::vector<double>& t, const std::vector<double>& z,
                          double threshold, double merge_gap_s, double min_length_s,
                          const WindowRankOptions& options = {});

/// A uniform time base for the spectrum of a record sampled at strictly increasing times t
/// (docs/measurements.md, "Sample times"):
///  * **gaps**: a step longer than the median step m by more than max(m/2, 8 MAD), MAD the median
///    absolute deviation of the steps from m. On a regular clock (MAD ≈ 0) that is 1.5 m; on a
///    jittering clock the jitter alone hardly ever reaches it (MAD is 0.18 of the largest step
///    deviation for stamps jittered uniformly and independently), so jitter does not cut the
///    record into pieces. The spectrum is that of the longest stretch [begin, end) between gaps
///    (the whole record when there is none);
///  * **steady rate**: the stretch is cut into blocks of max(64, n/16) steps; the rate is steady
///    when every block's mean step is within max(5 %, 4 σ/√B) of the stretch's mean step dt (σ =
///    1.4826 MAD, B the block's steps): jitter averages out over a block, a change of rate does
///    not;
///  * **uniform**: every step within 1e-6 of dt: the samples are used as they are;
///  * **resampled**: otherwise, onto the grid t[begin] + k·dt, k = 0 .. end − begin − 1, by linear
///    interpolation between the measured times (onGrid).
struct UniformGrid {
  std::size_t begin = 0, end = 0;         ///< the stretch of t used, [begin, end)
  std::size_t gaps = 0;                   ///< steps of the whole record counted as gaps
  double gap_step_s = 0;                  ///< a step longer than this is a gap
  double dt = 0;                          ///< the grid's step: the stretch's mean step [s]
  double jitter = 0;                      ///< max |step − dt| / dt within the stretch
  bool steady = true;                     ///< false: the rate changes within the stretch (no grid)
  double rate_lo_hz = 0, rate_hi_hz = 0;  ///< the slowest and fastest block of the stretch [Hz]
  bool resampled = false;                 ///< the grid is interpolated (index, weight below)
  std::vector<std::size_t>
      index;                   ///< resampled: grid time k lies in [t[index[k]], t[index[k] + 1]]
  std::vector<double> weight;  ///< resampled: its place u ∈ [0, 1] there
  std::size_t size() const { return end - begin; }
};

/// The uniform grid of times t (see UniformGrid). Throws if t has fewer than 2 times or is not
/// strictly increasing.
UniformGrid uniformGrid(const std::vector<double>& t);

/// The values x (one per time of the record the grid was made from) on the grid: x[begin, end)
/// when the times are uniform, else (1 − u) x[i] + u x[i + 1] at each grid time. Linear
/// interpolation is a filter: a sinusoid of frequency f keeps on average sinc²(f·dt) =
/// [sin(π f dt)/(π f dt)]² of its amplitude when the grid times fall evenly across the steps
/// (docs/diagnosis.md). Throws if x does not have one value per time.
std::vector<double> onGrid(const UniformGrid& grid, const std::vector<double>& x);

/// The autocorrelation ρ(0), ρ(1), ... (lags in grid steps, up to the last nonzero one) of white
/// noise of unit variance carried onto the grid by onGrid: {1} when the times are uniform. Its
/// spectrum, 2/fs (ρ(0) + 2 Σ_m ρ(m) cos(2π f m/fs)), is the noise floor of a resampled residual
/// (bandAnalysis's noise_acf).
std::vector<double> gridNoiseAutocorrelation(const UniformGrid& grid);

}  // namespace dtwin::diag
