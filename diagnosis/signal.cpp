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
  if (a != b)
    bad(where, "the two series must have the same length, got " + std::to_string(a) + " and " +
                   std::to_string(b));
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

// Welch equivalent degrees of freedom (PW93 eq. 292b) with the window's own overlap correlation.
double welchDof(const Segmentation& seg) {
  double rho = 0;
  for (int i = 0; i + seg.hop < seg.L; ++i) rho += seg.w[i] * seg.w[i + seg.hop];
  rho /= seg.U;
  return 2.0 * seg.K / (1.0 + 2.0 * (1.0 - 1.0 / seg.K) * rho * rho);
}

// The one-sided DFT bins 0..L/2 of the detrended (mean-removed), windowed segment k of x.
std::vector<std::complex<double>> segmentDft(const Segmentation& s, const std::vector<double>& x,
                                             int k, Eigen::FFT<double>& fft) {
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
  if (s.freq_hz.size() < 2)
    bad(where, "spectrum needs at least 2 bins, got " + std::to_string(s.freq_hz.size()));
  if (!(f_hi >= f_lo))
    bad(where, "band must have f_hi >= f_lo, got [" + str(f_lo) + ", " + str(f_hi) + ")");
}
bool inBand(const Spectrum& s, size_t k, double f_lo, double f_hi) {
  const double f = s.freq_hz[k];
  return f >= f_lo && (f < f_hi || (k + 1 == s.freq_hz.size() && f_hi >= f));
}

double chiSquareQuantile(double p, double nu) {  // Wilson–Hilferty
  const double z = normalQuantile(p), c = 2.0 / (9.0 * nu);
  return nu * std::pow(std::max(0.0, 1.0 - c + z * std::sqrt(c)), 3);
}

double mean(const std::vector<double>& x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / x.size();
}

// Least squares r ≈ a + b f; returns {b, 1 − SSR/Σr²}.
std::pair<double, double> fitAffine(const std::vector<double>& f, const std::vector<double>& r,
                                    double sum_r2) {
  const double n = static_cast<double>(r.size());
  double mf = 0, mr = 0;
  for (size_t i = 0; i < r.size(); ++i) mf += f[i], mr += r[i];
  mf /= n, mr /= n;
  double sff = 0, sfr = 0, srr = 0;
  for (size_t i = 0; i < r.size(); ++i) {
    sff += (f[i] - mf) * (f[i] - mf), sfr += (f[i] - mf) * (r[i] - mr),
        srr += (r[i] - mr) * (r[i] - mr);
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
  std::stable_sort(v.begin(), v.end(), [](const SignatureFit& a, const SignatureFit& b) {
    return a.explained_fraction > b.explained_fraction;
  });
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

CrossSpectra welchCrossSpectra(const std::vector<double>& x, const std::vector<double>& y,
                               double fs_hz, int segment) {
  requireSameSize("welchCrossSpectra", x.size(), y.size());
  const Segmentation s = segmentation("welchCrossSpectra", x.size(), fs_hz, segment);
  Eigen::FFT<double> fft;
  const size_t m = s.L / 2 + 1;
  CrossSpectra out{frequencies(s, fs_hz),
                   std::vector<double>(m, 0.0),
                   std::vector<double>(m, 0.0),
                   std::vector<std::complex<double>>(m, 0.0),
                   s.L,
                   s.K,
                   welchDof(s) / 2.0};
  for (int k = 0; k < s.K; ++k) {
    const auto X = segmentDft(s, x, k, fft), Y = segmentDft(s, y, k, fft);
    for (size_t j = 0; j < m; ++j)
      out.pxx[j] += std::norm(X[j]), out.pyy[j] += std::norm(Y[j]),
          out.pxy[j] += std::conj(X[j]) * Y[j];
  }
  for (size_t j = 0; j < m; ++j) {
    const double c = (j == 0 || j + 1 == m ? 1.0 : 2.0) / (s.K * fs_hz * s.U);
    out.pxx[j] *= c, out.pyy[j] *= c, out.pxy[j] *= c;
  }
  return out;
}

int welchSegmentFor(std::size_t n) {
  int s = 32;
  while (2 * static_cast<std::size_t>(s) <= n / 2 && s < 512) s *= 2;
  return s;
}

Spectrum coherence(const std::vector<double>& x, const std::vector<double>& y, double fs_hz,
                   int segment) {
  requireSameSize("coherence", x.size(), y.size());
  segmentation("coherence", x.size(), fs_hz,
               segment);  // the argument checks, named for this function
  const CrossSpectra c = welchCrossSpectra(x, y, fs_hz, segment);
  Spectrum out{c.freq_hz, std::vector<double>(c.freq_hz.size(), 0.0)};
  for (size_t j = 0; j < out.value.size(); ++j) {
    const double d = c.pxx[j] * c.pyy[j];
    out.value[j] = d > 0 ? std::min(1.0, std::norm(c.pxy[j]) / d) : 0.0;
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
  for (const Band& b : {Band{"body", 0.5, 2.0}, Band{"mid", 2.0, 8.0}, Band{"wheel_hop", 8.0, 20.0},
                        Band{"high", 20.0, ny}})
    if (b.lo_hz < ny) out.push_back({b.name, b.lo_hz, std::min(b.hi_hz, ny)});
  return out;
}

std::vector<BandReport> bandAnalysis(const std::vector<double>& residual, double fs_hz,
                                     double noise_variance, const std::vector<double>* input,
                                     int segment, double alpha,
                                     const std::vector<double>& noise_acf) {
  if (input) requireSameSize("bandAnalysis", residual.size(), input->size());
  if (!(noise_variance > 0))
    bad("bandAnalysis", "noise variance must be > 0, got " + str(noise_variance));
  if (!(alpha > 0 && alpha < 1)) bad("bandAnalysis", "alpha must be in (0, 1), got " + str(alpha));
  const Segmentation seg = segmentation("bandAnalysis", residual.size(), fs_hz, segment);
  if (!noise_acf.empty() && !(noise_acf[0] > 0))
    bad("bandAnalysis", "the noise autocorrelation at lag 0 must be > 0, got " + str(noise_acf[0]));
  const Spectrum psd = welchPsd(residual, fs_hz, segment);
  Spectrum floor{psd.freq_hz,
                 std::vector<double>(psd.freq_hz.size(), 2.0 * noise_variance / fs_hz)};
  if (!noise_acf.empty())
    for (std::size_t k = 0; k < floor.value.size(); ++k) {
      double shape = noise_acf[0];
      for (std::size_t m = 1; m < noise_acf.size(); ++m)
        shape += 2.0 * noise_acf[m] * std::cos(2.0 * kPi * psd.freq_hz[k] * m / fs_hz);
      floor.value[k] *= std::max(0.0, shape);
    }
  Spectrum coh;
  if (input) coh = coherence(residual, *input, fs_hz, segment);
  const double nu_w = welchDof(seg);
  std::vector<BandReport> out;
  for (const Band& b : vehicleBands(fs_hz)) {
    long bins = 0;
    for (size_t k = 0; k < psd.freq_hz.size(); ++k) bins += inBand(psd, k, b.lo_hz, b.hi_hz);
    if (bins == 0) continue;  // band narrower than one bin of this segment length
    BandReport r{b.name,
                 b.lo_hz,
                 b.hi_hz,
                 bandIntegral(psd, b.lo_hz, b.hi_hz),
                 bandIntegral(floor, b.lo_hz, b.hi_hz),
                 0,
                 input ? bandMean(coh, b.lo_hz, b.hi_hz) : kNaN,
                 false};
    r.ratio = r.residual_power / r.noise_power;
    const double nu = nu_w * std::max(1.0, bins / 2.0);
    r.significant = r.ratio > chiSquareQuantile(1.0 - alpha, nu) / nu;
    out.push_back(r);
  }
  return out;
}

std::vector<Bin> binByState(const std::vector<double>& state, const std::vector<double>& residual,
                            int bins) {
  requireSameSize("binByState", state.size(), residual.size());
  const size_t n = state.size();
  if (bins < 1) bad("binByState", "bins must be >= 1, got " + std::to_string(bins));
  if (static_cast<size_t>(bins) > n)
    bad("binByState", "bins must not exceed the sample count " + std::to_string(n) + ", got " +
                          std::to_string(bins));
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
      for (size_t i = i0; i < i1; ++i)
        ss += (residual[idx[i]] - bin.mean) * (residual[idx[i]] - bin.mean);
      bin.se = std::sqrt(ss / (bin.count - 1) / bin.count);
    }
    out.push_back(bin);
  }
  return out;
}

std::vector<SignatureFit> fitDeflectionSignatures(const std::vector<double>& q,
                                                  const std::vector<double>& r) {
  checkFitInputs("fitDeflectionSignatures", q, r);
  const double srr = sumSquares(r);
  const size_t n = q.size();
  std::vector<double> sq = q, f(n);
  std::sort(sq.begin(), sq.end());
  SignatureFit knee{"knee", 0, -std::numeric_limits<double>::infinity(), kNaN};
  for (int p = 1; p <= 99; ++p) {
    // NOLINTNEXTLINE(bugprone-incorrect-roundings): >= 0, rounded half up, as the results were
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

std::vector<SignatureFit> fitRateSignatures(const std::vector<double>& v,
                                            const std::vector<double>& r) {
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

namespace {

using Run = std::pair<std::size_t, std::size_t>;  // [first, last] sample of a window

void checkWindowInputs(const char* where, const std::vector<double>& t,
                       const std::vector<double>& z, double threshold, double merge_gap_s,
                       double min_length_s) {
  requireSameSize(where, t.size(), z.size());
  if (!(threshold >= 0)) bad(where, "threshold must be >= 0, got " + str(threshold));
  if (!(merge_gap_s >= 0)) bad(where, "merge gap must be >= 0 s, got " + str(merge_gap_s));
  if (!(min_length_s >= 0)) bad(where, "minimum length must be >= 0 s, got " + str(min_length_s));
  for (size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      bad(where,
          "time must be strictly increasing, got t[" + std::to_string(i) + "] = " + str(t[i]));
}

// The runs of exceedanceWindows: maximal runs of |z| > threshold merged across gaps < merge_gap_s,
// the short ones dropped.
std::vector<Run> exceedanceRuns(const std::vector<double>& t, const std::vector<double>& z,
                                double threshold, double merge_gap_s, double min_length_s) {
  std::vector<Run> runs;
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
  std::vector<Run> kept;
  for (const auto& r : runs)
    if (t[r.second] - t[r.first] >= min_length_s) kept.push_back(r);
  return kept;
}

Window windowOf(const std::vector<double>& t, const std::vector<double>& z, const Run& r,
                double total) {
  Window w{t[r.first], t[r.second], 0, 0};
  for (size_t i = r.first; i <= r.second; ++i) {
    if (!std::isfinite(z[i])) continue;
    w.peak_z = std::max(w.peak_z, std::abs(z[i]));
    w.share += z[i] * z[i];
  }
  w.share = total > 0 ? w.share / total : 0;
  return w;
}

double finiteSumSquares(const std::vector<double>& z) {
  double s = 0;
  for (double v : z)
    if (std::isfinite(v)) s += v * v;
  return s;
}

// The runs merged across gaps < gap_s, never into a window longer than max_length_s.
std::vector<Run> mergeRuns(const std::vector<double>& t, const std::vector<Run>& runs, double gap_s,
                           double max_length_s) {
  std::vector<Run> out;
  for (const auto& r : runs) {
    if (!out.empty() && t[r.first] - t[out.back().second] < gap_s &&
        t[r.second] - t[out.back().first] <= max_length_s)
      out.back().second = r.second;
    else
      out.push_back(r);
  }
  return out;
}

double medianOf(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

std::vector<double> stepsOf(const std::vector<double>& t, size_t b, size_t e) {
  std::vector<double> s;
  s.reserve(e - b);
  for (size_t i = b + 1; i < e; ++i) s.push_back(t[i] - t[i - 1]);
  return s;
}

}  // namespace

std::vector<Window> exceedanceWindows(const std::vector<double>& t, const std::vector<double>& z,
                                      double threshold, double merge_gap_s, double min_length_s) {
  checkWindowInputs("exceedanceWindows", t, z, threshold, merge_gap_s, min_length_s);
  const double total = sumSquares(z);
  std::vector<Window> out;
  for (const auto& r : exceedanceRuns(t, z, threshold, merge_gap_s, min_length_s)) {
    Window w{t[r.first], t[r.second], 0, 0};
    for (size_t i = r.first; i <= r.second; ++i)
      w.peak_z = std::max(w.peak_z, std::abs(z[i])), w.share += z[i] * z[i];
    w.share = total > 0 ? w.share / total : 0;
    out.push_back(w);
  }
  return out;
}

WindowRanking rankWindows(const std::vector<double>& t, const std::vector<double>& z,
                          double threshold, double merge_gap_s, double min_length_s,
                          const WindowRankOptions& o) {
  const char* where = "rankWindows";
  checkWindowInputs(where, t, z, threshold, merge_gap_s, min_length_s);
  if (o.max_merged < 1) bad(where, "max_merged must be >= 1, got 0");
  if (o.max_listed < 1) bad(where, "max_listed must be >= 1, got 0");
  if (!(o.listed_share > 0 && o.listed_share <= 1))
    bad(where, "listed share must lie in (0, 1], got " + str(o.listed_share));
  WindowRanking out;
  const double total = finiteSumSquares(z);
  const std::vector<Run> runs = exceedanceRuns(t, z, threshold, merge_gap_s, min_length_s);
  std::size_t inside = 0;
  for (const auto& r : runs) {
    out.found.push_back(windowOf(t, z, r, total));
    inside += r.second - r.first + 1;
  }
  WindowSummary& s = out.summary;
  s.found = runs.size();
  s.time_share = t.empty() ? 0.0 : static_cast<double>(inside) / static_cast<double>(t.size());
  s.merge_gap_s = merge_gap_s;
  std::vector<Run> merged = runs;
  if (runs.size() > o.max_merged && t.size() > 1) {
    const double max_length = 2.0 * (t.back() - t.front()) / static_cast<double>(o.max_merged);
    double gap = merge_gap_s > 0 ? merge_gap_s : medianOf(stepsOf(t, 0, t.size()));
    while (merged.size() > o.max_merged && gap <= max_length) {
      gap *= 2.0;
      merged = mergeRuns(t, runs, gap, max_length);
      s.merge_gap_s = gap;
    }
  }
  for (const auto& r : merged) out.ranked.push_back(windowOf(t, z, r, total));
  std::stable_sort(out.ranked.begin(), out.ranked.end(),
                   [](const Window& a, const Window& b) { return a.share > b.share; });
  s.merged = out.ranked.size();
  for (const auto& w : out.ranked) s.merged_share += w.share;
  if (s.merged <= o.max_listed) {
    s.listed = s.merged;
  } else {
    double held = 0;
    while (s.listed < o.max_listed && held < o.listed_share * s.merged_share)
      held += out.ranked[s.listed++].share;
  }
  for (std::size_t k = 0; k < s.listed; ++k) s.listed_share += out.ranked[k].share;
  return out;
}

UniformGrid uniformGrid(const std::vector<double>& t) {
  const char* where = "uniformGrid";
  if (t.size() < 2) bad(where, "need at least 2 times, got " + std::to_string(t.size()));
  for (size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      bad(where,
          "time must be strictly increasing, got t[" + std::to_string(i) + "] = " + str(t[i]));
  UniformGrid g;
  // Gaps: steps beyond what the clock's jitter gives.
  const std::vector<double> steps = stepsOf(t, 0, t.size());
  const double m = medianOf(steps);
  std::vector<double> dev(steps.size());
  for (size_t i = 0; i < steps.size(); ++i) dev[i] = std::abs(steps[i] - m);
  const double mad = medianOf(dev);
  g.gap_step_s = m + std::max(0.5 * m, 8.0 * mad);
  g.begin = 0, g.end = 1;
  for (size_t b = 0, i = 1; i <= t.size(); ++i)
    if (i == t.size() || steps[i - 1] > g.gap_step_s) {
      if (i < t.size()) ++g.gaps;
      if (i - b > g.end - g.begin) g.begin = b, g.end = i;
      b = i;
    }
  const size_t n = g.size();
  if (n < 2) return g;
  g.dt = (t[g.end - 1] - t[g.begin]) / static_cast<double>(n - 1);
  for (size_t i = g.begin + 1; i < g.end; ++i)
    g.jitter = std::max(g.jitter, std::abs(t[i] - t[i - 1] - g.dt) / g.dt);
  // A steady rate: every block's mean step near dt.
  const size_t nsteps = n - 1, block = std::max<size_t>(64, nsteps / 16);
  std::vector<double> sd = stepsOf(t, g.begin, g.end);
  const double ms = medianOf(sd);
  for (double& v : sd) v = std::abs(v - ms);
  const double sigma = 1.4826 * medianOf(sd);
  g.rate_lo_hz = g.rate_hi_hz = 1.0 / g.dt;
  const size_t blocks = std::max<size_t>(1, nsteps / block);
  for (size_t k = 0; k < blocks; ++k) {
    const size_t a = g.begin + k * block,
                 b = k + 1 == blocks ? g.end - 1 : a + block;  // steps a..b (times a..b)
    const double steps_in = static_cast<double>(b - a), mean_step = (t[b] - t[a]) / steps_in;
    g.rate_lo_hz = std::min(g.rate_lo_hz, 1.0 / mean_step);
    g.rate_hi_hz = std::max(g.rate_hi_hz, 1.0 / mean_step);
    if (std::abs(mean_step - g.dt) > std::max(0.05 * g.dt, 4.0 * sigma / std::sqrt(steps_in)))
      g.steady = false;
  }
  if (g.jitter <= 1e-6 || !g.steady) return g;
  // Resampled: each grid time's bracket and place in it.
  g.resampled = true;
  g.index.resize(n);
  g.weight.resize(n);
  size_t i = g.begin;
  for (size_t k = 0; k < n; ++k) {
    const double tau = k + 1 == n ? t[g.end - 1] : t[g.begin] + static_cast<double>(k) * g.dt;
    while (i + 2 < g.end && t[i + 1] < tau) ++i;
    g.index[k] = i;
    g.weight[k] = std::clamp((tau - t[i]) / (t[i + 1] - t[i]), 0.0, 1.0);
  }
  return g;
}

std::vector<double> onGrid(const UniformGrid& g, const std::vector<double>& x) {
  if (x.size() < g.end)
    bad("onGrid", "need one value per time of the record, got " + std::to_string(x.size()) +
                      " for a stretch ending at " + std::to_string(g.end));
  if (!g.resampled)
    return std::vector<double>(x.begin() + static_cast<long>(g.begin),
                               x.begin() + static_cast<long>(g.end));
  std::vector<double> y(g.index.size());
  for (size_t k = 0; k < y.size(); ++k) {
    const double u = g.weight[k];
    y[k] = (1.0 - u) * x[g.index[k]] + u * x[g.index[k] + 1];
  }
  return y;
}

std::vector<double> gridNoiseAutocorrelation(const UniformGrid& g) {
  if (!g.resampled) return {1.0};
  // y_k = (1 − u_k) n_{i_k} + u_k n_{i_k + 1}: grid times k and k + m share the noise of a sample
  // when their brackets overlap, i_{k+m} − i_k ∈ {0, 1}.
  const size_t n = g.index.size();
  std::vector<double> acf;
  for (size_t m = 0; m < n; ++m) {
    double sum = 0;
    bool any = false;
    for (size_t k = 0; k + m < n; ++k) {
      const size_t d = g.index[k + m] - g.index[k];
      const double u = g.weight[k], v = g.weight[k + m];
      if (d == 0)
        sum += (1 - u) * (1 - v) + u * v, any = true;
      else if (d == 1)
        sum += u * (1 - v), any = true;
    }
    if (!any) break;
    acf.push_back(sum / static_cast<double>(n - m));
  }
  return acf;
}

}  // namespace dtwin::diag
