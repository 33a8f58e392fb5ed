#pragma once
// Signal tools for the diagnosis (docs/diagnosis.md): where, in frequency, in state and in time,
// a model fails against measurements. Everything here is pure numerics on uniformly sampled
// records; the usual input is a residual r(t) = measured − model on a uniform time grid.
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
Spectrum coherence(const std::vector<double>& x, const std::vector<double>& y, double fs_hz, int segment);

/// ∫_{f_lo}^{f_hi} S(f) df over a spectrum on the grid of welchPsd, by the trapezoid rule written
/// on the bins: Σ_{k: f_lo <= f_k < f_hi} S_k·Δ_k with Δ_k = Δf, except Δ_0 = Δ_M = Δf/2 (the DC and
/// Nyquist bins are half inside [0, fs/2]). Bands that partition [0, fs/2] thus add up to the
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
/// at the Nyquist frequency fs/2; a band starting at or above fs/2 is omitted. Throws if fs_hz <= 0.
std::vector<Band> vehicleBands(double fs_hz);

/// The verdict on one band of a residual.
struct BandReport {
  std::string band;
  double lo_hz, hi_hz;
  double residual_power;  ///< bandIntegral of the residual's Welch PSD [unit²]
  double noise_power;     ///< the same integral of the white noise floor 2σ²/fs [unit²]
  double ratio;           ///< residual_power / noise_power
  double coherence;       ///< bandMean of the residual–input coherence; NaN without input
  bool significant;       ///< ratio > χ²_{ν,1−α}/ν (see bandAnalysis)
};

/// Band-by-band comparison of a residual with its measurement noise floor, over vehicleBands(fs).
///
/// Under H0 (residual = white noise of variance σ² = noise_variance) each Welch bin estimate is
/// P̂_k ~ P·χ²_{ν_W}/ν_W with, for the Hann window at 50 % overlap [W67; PW93 eq. 292b],
///
///     ν_W = 2K / (1 + 2 Σ_{m=1}^{K−1} (1 − m/K) ρ²(m)),   ρ(m) = Σ_n w[n] w[n + m·L/2] / Σ_n w[n]²,
///
/// the correlation of the white-noise periodograms of segments m hops apart. For the periodic Hann
/// window ρ(1) = 1/3 and ρ(m>1) = 0, so ν_W ≈ 1.64 K (fewer than the 1.89 K of [PW93 eq. 292c],
/// which uses ρ² = 1/36). Summing the M_b bins of a band, the power estimates of neighbouring Hann
/// bins are correlated too (ρ² = 4/9 adjacent, 1/36 two apart), so a band holds about M_b/1.94
/// independent bins; only every second bin is counted: ν = ν_W · max(1, M_b/2). Flagged when
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
std::vector<BandReport> bandAnalysis(const std::vector<double>& residual, double fs_hz, double noise_variance,
                                     const std::vector<double>* input, int segment, double alpha = 0.01);

/// One bin of a force-state map.
struct Bin {
  double lo, hi;   ///< smallest and largest state value in the bin
  double centre;   ///< mean state in the bin
  double mean;     ///< mean residual in the bin
  double se;       ///< standard error of that mean, s/√n with the sample deviation s (n−1); NaN if n < 2
  long count;      ///< samples in the bin
};

/// Force-state map: the residual averaged in `bins` equal-count (quantile) bins of the state.
/// Samples are sorted by state (stable) and bin b gets the sorted samples [⌊b·N/B⌋, ⌊(b+1)·N/B⌋),
/// so counts differ by at most one; tied state values may fall in two neighbouring bins.
/// Throws if sizes differ, bins < 1 or bins > N.
std::vector<Bin> binByState(const std::vector<double>& state, const std::vector<double>& residual, int bins);

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
std::vector<SignatureFit> fitDeflectionSignatures(const std::vector<double>& q, const std::vector<double>& r);

/// Least squares r ≈ a + b·f(v) for features of a rate-like state v [m/s], v > 0 in compression:
///   "step"              tanh(v/v_s), v_s = 0.05·std(v) (Coulomb friction, a smoothed sign(v)),
///   "rebound_slope"     v·[v < 0] (a rebound damping error),
///   "compression_slope" v·[v > 0] (a compression damping error),
///   "linear"            v (a symmetric damping error).
/// Sorted by explained_fraction, best first; knee_at is NaN. Throws as fitDeflectionSignatures.
std::vector<SignatureFit> fitRateSignatures(const std::vector<double>& v, const std::vector<double>& r);

/// A time window where the standardised residual is large.
struct Window {
  double t_begin, t_end;  ///< times of the first and last sample of the window [s]
  double peak_z;          ///< max |z| in the window
  double share;           ///< Σ_{window} z² / Σ_{record} z² (every sample between t_begin and t_end)
};

/// Windows in time where |z| exceeds `threshold`: maximal runs of consecutive samples with
/// |z| > threshold; consecutive runs are merged when the gap t(first of next) − t(last of
/// previous) < merge_gap_s (the merged window includes the samples between), and windows with
/// t_end − t_begin < min_length_s are then dropped. Chronological order. t must be strictly
/// increasing. Throws if sizes differ, t is not increasing, or threshold, merge_gap_s or
/// min_length_s is negative.
std::vector<Window> exceedanceWindows(const std::vector<double>& t, const std::vector<double>& z, double threshold,
                                      double merge_gap_s, double min_length_s);

}  // namespace dtwin::diag
