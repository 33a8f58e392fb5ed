#include "diagnosis/signal.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include <unsupported/Eigen/FFT>

#include "common/format.hpp"

namespace dtwin::diag {


namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void bad(const std::string& where, const std::string& rule) {
  throw std::invalid_argument(where + ": " + rule);
}

std::string str(double v) { return formatNumber(v); }

void requireSameSize(const char* where, size_t a, size_t b) {
  if (a != b) bad(where, "the two series must have the same length, got " + std::to_string(a) + " and " + std::to_string(b));
}

// Welch segmentation shared by welchPsd and coherence.
struct Segmentation {
  int L = 0, hop = 0, K = 0;
  std::vector<double> w;  // periodic Hann
  double U = 0;           // Σ w²
};

Segmentation segmentation(const char* where, size_t n, double fs_hz, int segment) {
  if (!(fs_hz > 0)) bad(where, "sampling frequency must be > 0 Hz, got " + str(fs_hz));
  if (n < 8) bad(where, "need at least 8 samples, got " + std::to_string(n));
  if (segment < 8) bad(where, "segment must be >= 8 samples, got " + std::to_string(segment));
  Segmentation s;
  s.L = static_cast<int>(std::min<size_t>(static_cast<size_t>(segment), n)) & ~1;
  s.hop = s.L / 2;
  s.K = 1 + static_cast<int>((n - s.L) / s.hop);
  s.w.resize(s.L);
  for (int i = 0; i < s.L; ++i) s.w[i] = 0.5 * (1.0 - std::cos(2.0 * kPi * i / s.L));
  for (double v : s.w) s.U += v * v;
  return s;
}

// The one-sided DFT bins 0..L/2 of the detrended (mean-removed), windowed segment k of x.
std::vector<std::complex<double>> segmentDft(const Segmentation& s, const std::vector<double>& x, int k,
                                             Eigen::FFT<double>& fft) {
  const size_t b = static_cast<size_t>(k) * s.hop;
  const double mean = std::accumulate(x.begin() + b, x.begin() + b + s.L, 0.0) / s.L;
  std::vector<double> seg(s.L);
  for (int i = 0; i < s.L; ++i) seg[i] = (x[b + i] - mean) * s.w[i];
  std::vector<std::complex<double>> X;
  fft.fwd(X, seg);
  X.resize(s.L / 2 + 1);  // Eigen may return the half spectrum already; keep bins 0..L/2
  return X;
}

std::vector<double> frequencies(const Segmentation& s, double fs_hz) {
  std::vector<double> f(s.L / 2 + 1);
  for (size_t k = 0; k < f.size(); ++k) f[k] = k * fs_hz / s.L;
  return f;
}

// Bin weights Δ_k of the trapezoid rule and the band-membership rule of bandIntegral/bandMean.
void checkSpectrum(const char* where, const Spectrum& s, double f_lo, double f_hi) {
  requireSameSize(where, s.freq_hz.size(), s.value.size());
  if (s.freq_hz.size() < 2) bad(where, "spectrum needs at least 2 bins, got " + std::to_string(s.freq_hz.size()));
  if (!(f_hi >= f_lo)) bad(where, "band must have f_hi >= f_lo, got [" + str(f_lo) + ", " + str(f_hi) + ")");
}
bool inBand(const Spectrum& s, size_t k, double f_lo, double f_hi) {
  const double f = s.freq_hz[k];
  return f >= f_lo && (f < f_hi || (k + 1 == s.freq_hz.size() && f_hi >= f));
}

double chiSquareQuantile(double p, double nu) {  // Wilson–Hilferty
  const double z = normalQuantile(p), c = 2.0 / (9.0 * nu);
  return nu * std::pow(std::max(0.0, 1.0 - c + z * std::sqrt(c)), 3);
}

double mean(const std::vector<double>& x) { return std::accumulate(x.begin(), x.end(), 0.0) / x.size(); }

// Least squares r ≈ a + b f; returns {b, 1 − SSR/Σr²}.
std::pair<double, double> fitAffine(const std::vector<double>& f, const std::vector<double>& r, double sum_r2) {
  const double n = static_cast<double>(r.size());
  double mf = 0, mr = 0;
  for (size_t i = 0; i < r.size(); ++i) mf += f[i], mr += r[i];
  mf /= n, mr /= n;
  double sff = 0, sfr = 0, srr = 0;
  for (size_t i = 0; i < r.size(); ++i) {
    sff += (f[i] - mf) * (f[i] - mf), sfr += (f[i] - mf) * (r[i] - mr), srr += (r[i] - mr) * (r[i] - mr);
  }
  const double b = sff > 1e-300 * std::max(1.0, mf * mf) ? sfr / sff : 0.0;
  const double ssr = std::max(0.0, srr - b * sfr);
  return {b, sum_r2 > 0 ? 1.0 - ssr / sum_r2 : 0.0};
}

void checkFitInputs(const char* where, const std::vector<double>& s, const std::vector<double>& r) {
  requireSameSize(where, s.size(), r.size());
  if (s.size() < 3) bad(where, "need at least 3 samples, got " + std::to_string(s.size()));
}

std::vector<SignatureFit> sorted(std::vector<SignatureFit> v) {
  std::stable_sort(v.begin(), v.end(),
                   [](const SignatureFit& a, const SignatureFit& b) { return a.explained_fraction > b.explained_fraction; });
  return v;
}

double sumSquares(const std::vector<double>& r) {
  double s = 0;
  for (double v : r) s += v * v;
  return s;
}

}  // namespace

Spectrum welchPsd(const std::vector<double>& x, double fs_hz, int segment) {
  const Segmentation s = segmentation("welchPsd", x.size(), fs_hz, segment);
  Eigen::FFT<double> fft;
  Spectrum out{frequencies(s, fs_hz), std::vector<double>(s.L / 2 + 1, 0.0)};
  for (int k = 0; k < s.K; ++k) {
    const auto X = segmentDft(s, x, k, fft);
    for (size_t j = 0; j < X.size(); ++j) out.value[j] += std::norm(X[j]);
  }
  for (size_t j = 0; j < out.value.size(); ++j) {
    const double c = (j == 0 || j + 1 == out.value.size()) ? 1.0 : 2.0;
    out.value[j] *= c / (s.K * fs_hz * s.U);
  }
  return out;
}

Spectrum coherence(const std::vector<double>& x, const std::vector<double>& y, double fs_hz, int segment) {
  requireSameSize("coherence", x.size(), y.size());
  const Segmentation s = segmentation("coherence", x.size(), fs_hz, segment);
  Eigen::FFT<double> fft;
  const size_t m = s.L / 2 + 1;
  std::vector<double> pxx(m, 0.0), pyy(m, 0.0);
  std::vector<std::complex<double>> pxy(m, 0.0);
  for (int k = 0; k < s.K; ++k) {
    const auto X = segmentDft(s, x, k, fft), Y = segmentDft(s, y, k, fft);
    for (size_t j = 0; j < m; ++j) pxx[j] += std::norm(X[j]), pyy[j] += std::norm(Y[j]), pxy[j] += std::conj(X[j]) * Y[j];
  }
  Spectrum out{frequencies(s, fs_hz), std::vector<double>(m, 0.0)};
  for (size_t j = 0; j < m; ++j) {
    const double d = pxx[j] * pyy[j];
    out.value[j] = d > 0 ? std::min(1.0, std::norm(pxy[j]) / d) : 0.0;
  }
  return out;
}

double bandIntegral(const Spectrum& s, double f_lo, double f_hi) {
  checkSpectrum("bandIntegral", s, f_lo, f_hi);
  const size_t m = s.freq_hz.size();
  const double df = s.freq_hz[1] - s.freq_hz[0];
  double sum = 0;
  for (size_t k = 0; k < m; ++k)
    if (inBand(s, k, f_lo, f_hi)) sum += s.value[k] * ((k == 0 || k + 1 == m) ? 0.5 * df : df);
  return sum;
}

double bandMean(const Spectrum& s, double f_lo, double f_hi) {
  checkSpectrum("bandMean", s, f_lo, f_hi);
  double sum = 0;
  long n = 0;
  for (size_t k = 0; k < s.freq_hz.size(); ++k)
    if (inBand(s, k, f_lo, f_hi)) sum += s.value[k], ++n;
  return n ? sum / n : kNaN;
}

std::vector<Band> vehicleBands(double fs_hz) {
  if (!(fs_hz > 0)) bad("vehicleBands", "sampling frequency must be > 0 Hz, got " + str(fs_hz));
  const double ny = fs_hz / 2;
  std::vector<Band> out;
  for (const Band& b : {Band{"body", 0.5, 2.0}, Band{"mid", 2.0, 8.0}, Band{"wheel_hop", 8.0, 20.0}, Band{"high", 20.0, ny}})
    if (b.lo_hz < ny) out.push_back({b.name, b.lo_hz, std::min(b.hi_hz, ny)});
  return out;
}

std::vector<BandReport> bandAnalysis(const std::vector<double>& residual, double fs_hz, double noise_variance,
                                     const std::vector<double>* input, int segment, double alpha) {
  if (input) requireSameSize("bandAnalysis", residual.size(), input->size());
  if (!(noise_variance > 0)) bad("bandAnalysis", "noise variance must be > 0, got " + str(noise_variance));
  if (!(alpha > 0 && alpha < 1)) bad("bandAnalysis", "alpha must be in (0, 1), got " + str(alpha));
  const Segmentation seg = segmentation("bandAnalysis", residual.size(), fs_hz, segment);
  const Spectrum psd = welchPsd(residual, fs_hz, segment);
  Spectrum floor{psd.freq_hz, std::vector<double>(psd.freq_hz.size(), 2.0 * noise_variance / fs_hz)};
  Spectrum coh;
  if (input) coh = coherence(residual, *input, fs_hz, segment);
  // Welch equivalent degrees of freedom (PW93 eq. 292b) with the window's own overlap correlation.
  double rho = 0;
  for (int i = 0; i + seg.hop < seg.L; ++i) rho += seg.w[i] * seg.w[i + seg.hop];
  rho /= seg.U;
  const double nu_w = 2.0 * seg.K / (1.0 + 2.0 * (1.0 - 1.0 / seg.K) * rho * rho);
  std::vector<BandReport> out;
  for (const Band& b : vehicleBands(fs_hz)) {
    long bins = 0;
    for (size_t k = 0; k < psd.freq_hz.size(); ++k) bins += inBand(psd, k, b.lo_hz, b.hi_hz);
    if (bins == 0) continue;  // band narrower than one bin of this segment length
    BandReport r{b.name, b.lo_hz, b.hi_hz, bandIntegral(psd, b.lo_hz, b.hi_hz), bandIntegral(floor, b.lo_hz, b.hi_hz),
                 0, input ? bandMean(coh, b.lo_hz, b.hi_hz) : kNaN, false};
    r.ratio = r.residual_power / r.noise_power;
    const double nu = nu_w * std::max(1.0, bins / 2.0);
    r.significant = r.ratio > chiSquareQuantile(1.0 - alpha, nu) / nu;
    out.push_back(r);
  }
  return out;
}

std::vector<Bin> binByState(const std::vector<double>& state, const std::vector<double>& residual, int bins) {
  requireSameSize("binByState", state.size(), residual.size());
  const size_t n = state.size();
  if (bins < 1) bad("binByState", "bins must be >= 1, got " + std::to_string(bins));
  if (static_cast<size_t>(bins) > n)
    bad("binByState", "bins must not exceed the sample count " + std::to_string(n) + ", got " + std::to_string(bins));
  std::vector<size_t> idx(n);
  std::iota(idx.begin(), idx.end(), size_t{0});
  std::stable_sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return state[a] < state[b]; });
  std::vector<Bin> out;
  for (int b = 0; b < bins; ++b) {
    const size_t i0 = b * n / bins, i1 = (b + 1) * n / bins;
    Bin bin{state[idx[i0]], state[idx[i1 - 1]], 0, 0, kNaN, static_cast<long>(i1 - i0)};
    for (size_t i = i0; i < i1; ++i) bin.centre += state[idx[i]], bin.mean += residual[idx[i]];
    bin.centre /= bin.count, bin.mean /= bin.count;
    if (bin.count > 1) {
      double ss = 0;
      for (size_t i = i0; i < i1; ++i) ss += (residual[idx[i]] - bin.mean) * (residual[idx[i]] - bin.mean);
      bin.se = std::sqrt(ss / (bin.count - 1) / bin.count);
    }
    out.push_back(bin);
  }
  return out;
}

std::vector<SignatureFit> fitDeflectionSignatures(const std::vector<double>& q, const std::vector<double>& r) {
  checkFitInputs("fitDeflectionSignatures", q, r);
  const double srr = sumSquares(r);
  const size_t n = q.size();
  std::vector<double> sq = q, f(n);
  std::sort(sq.begin(), sq.end());
  SignatureFit knee{"knee", 0, -std::numeric_limits<double>::infinity(), kNaN};
  for (int p = 1; p <= 99; ++p) {
    const double g = sq[std::min(n - 1, static_cast<size_t>(p / 100.0 * (n - 1) + 0.5))];
    for (size_t i = 0; i < n; ++i) f[i] = std::pow(std::max(q[i] - g, 0.0), 2);
    const auto [b, e] = fitAffine(f, r, srr);
    if (e > knee.explained_fraction) knee = {"knee", b, e, g};
  }
  std::vector<SignatureFit> out{knee};
  for (size_t i = 0; i < n; ++i) f[i] = q[i] * q[i] * q[i];
  auto [bc, ec] = fitAffine(f, r, srr);
  out.push_back({"cubic", bc, ec, kNaN});
  auto [bl, el] = fitAffine(q, r, srr);
  out.push_back({"linear", bl, el, kNaN});
  return sorted(out);
}

std::vector<SignatureFit> fitRateSignatures(const std::vector<double>& v, const std::vector<double>& r) {
  checkFitInputs("fitRateSignatures", v, r);
  const double srr = sumSquares(r), mv = mean(v);
  const size_t n = v.size();
  double var = 0;
  for (double x : v) var += (x - mv) * (x - mv);
  const double vs = 0.05 * std::sqrt(var / (n - 1));
  std::vector<double> f(n);
  std::vector<SignatureFit> out;
  auto add = [&](const char* name, auto feature) {
    for (size_t i = 0; i < n; ++i) f[i] = feature(v[i]);
    const auto [b, e] = fitAffine(f, r, srr);
    out.push_back({name, b, e, kNaN});
  };
  add("step", [&](double x) { return vs > 0 ? std::tanh(x / vs) : (x > 0) - (x < 0); });
  add("rebound_slope", [](double x) { return x < 0 ? x : 0.0; });
  add("compression_slope", [](double x) { return x > 0 ? x : 0.0; });
  add("linear", [](double x) { return x; });
  return sorted(out);
}

std::vector<Window> exceedanceWindows(const std::vector<double>& t, const std::vector<double>& z, double threshold,
                                      double merge_gap_s, double min_length_s) {
  const char* where = "exceedanceWindows";
  requireSameSize(where, t.size(), z.size());
  if (!(threshold >= 0)) bad(where, "threshold must be >= 0, got " + str(threshold));
  if (!(merge_gap_s >= 0)) bad(where, "merge gap must be >= 0 s, got " + str(merge_gap_s));
  if (!(min_length_s >= 0)) bad(where, "minimum length must be >= 0 s, got " + str(min_length_s));
  for (size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1])) bad(where, "time must be strictly increasing, got t[" + std::to_string(i) + "] = " + str(t[i]));
  std::vector<std::pair<size_t, size_t>> runs;  // [first, last] sample of each run, merged
  for (size_t i = 0; i < z.size(); ++i) {
    if (!(std::abs(z[i]) > threshold)) continue;
    size_t j = i;
    while (j + 1 < z.size() && std::abs(z[j + 1]) > threshold) ++j;
    if (!runs.empty() && t[i] - t[runs.back().second] < merge_gap_s)
      runs.back().second = j;
    else
      runs.emplace_back(i, j);
    i = j;
  }
  const double total = sumSquares(z);
  std::vector<Window> out;
  for (const auto& [a, b] : runs) {
    if (t[b] - t[a] < min_length_s) continue;
    Window w{t[a], t[b], 0, 0};
    for (size_t i = a; i <= b; ++i) w.peak_z = std::max(w.peak_z, std::abs(z[i])), w.share += z[i] * z[i];
    w.share = total > 0 ? w.share / total : 0;
    out.push_back(w);
  }
  return out;
}

}  // namespace dtwin::diag
