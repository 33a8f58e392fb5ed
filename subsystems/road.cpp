#include "subsystems/road.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include <unsupported/Eigen/FFT>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/json.hpp"
#include "common/statistics.hpp"
#include "subsystems/random.hpp"

namespace dtwin {
namespace {
constexpr double kHuge = 1e12;
}

RoadSample Road::sampleAveraged(Track t, double x, double L) const {
  const double a = x - 0.5 * L, b = x + 0.5 * L;
  return {(integral(t, b) - integral(t, a)) / L,
          (sample(t, b).height_m - sample(t, a).height_m) / L};
}

Interval FlatRoad::extent() const { return {-kHuge, kHuge}; }

// ------------------------------------------------------------------ bump
BumpRoad::BumpRoad(double start_x_m, double height_m, double length_m)
    : x0_(start_x_m), H_(height_m), L_(length_m) {
  DTWIN_CHECK(length_m > 0.0, "bump length must be positive");
}

RoadSample BumpRoad::sample(Track, double x) const {
  if (x <= x0_ || x >= x0_ + L_) return {};
  const double w = 2.0 * kPi / L_;
  return {0.5 * H_ * (1.0 - std::cos(w * (x - x0_))), 0.5 * H_ * w * std::sin(w * (x - x0_))};
}

double BumpRoad::integral(Track, double x) const {
  if (x <= x0_) return 0.0;
  if (x >= x0_ + L_) return 0.5 * H_ * L_;
  const double w = 2.0 * kPi / L_;
  return 0.5 * H_ * ((x - x0_) - std::sin(w * (x - x0_)) / w);
}

Interval BumpRoad::extent() const { return {-kHuge, kHuge}; }

nlohmann::json BumpRoad::describe() const {
  return {{"type", "bump"},
          {"shape", "one-cosine"},
          {"start_x_m", x0_},
          {"height_m", H_},
          {"length_m", L_}};
}

// ------------------------------------------------------------------ grid
GridRoad::GridRoad(double x0_m, double dx_m, std::vector<double> left_m,
                   std::vector<double> right_m, nlohmann::json description,
                   std::vector<double> left_slope, std::vector<double> right_slope)
    : x0_(x0_m), dx_(dx_m), description_(std::move(description)) {
  DTWIN_CHECK(dx_m > 0.0, "grid spacing must be positive");
  DTWIN_CHECK(left_m.size() == right_m.size() && left_m.size() >= 2,
              "grid road needs >= 2 equal-length tracks");
  DTWIN_CHECK(left_slope.size() == right_slope.size() &&
                  (left_slope.empty() || left_slope.size() == left_m.size()),
              "grid road slopes: none, or one per node of each track");
  h_[0] = std::move(left_m);
  h_[1] = std::move(right_m);
  m_[0] = std::move(left_slope);
  m_[1] = std::move(right_slope);
  for (int t = 0; t < 2; ++t) {
    const auto& h = h_[t];
    const std::size_t n = h.size();
    auto& m = m_[t];
    if (m.empty()) {
      m.resize(n);
      m[0] = (h[1] - h[0]) / dx_;
      m[n - 1] = (h[n - 1] - h[n - 2]) / dx_;
      for (std::size_t i = 1; i + 1 < n; ++i) m[i] = (h[i + 1] - h[i - 1]) / (2.0 * dx_);
    }
    auto& P = prefix_[t];
    P.resize(n);
    P[0] = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i)
      P[i + 1] = P[i] + dx_ * 0.5 * (h[i] + h[i + 1]) + dx_ * dx_ * (m[i] - m[i + 1]) / 12.0;
  }
}

RoadSample GridRoad::sample(Track t, double x) const {
  const auto& h = h_[static_cast<int>(t)];
  const auto& m = m_[static_cast<int>(t)];
  const double s = (x - x0_) / dx_;
  const std::size_t n = h.size();
  // Held flat outside the grid; on its first and last node the interpolant's own slope (a run
  // that ends on the last node of a logged road reads the log's slope there, not the hold's 0).
  if (s < 0.0) return {h.front(), 0.0};
  if (s > static_cast<double>(n - 1)) return {h.back(), 0.0};
  const std::size_t i = std::min(static_cast<std::size_t>(s), n - 2);
  const double u = s - static_cast<double>(i), u2 = u * u, u3 = u2 * u;
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
               h11 = u3 - u2;
  const double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = -6 * u2 + 6 * u,
               d11 = 3 * u2 - 2 * u;
  return {h00 * h[i] + h10 * dx_ * m[i] + h01 * h[i + 1] + h11 * dx_ * m[i + 1],
          (d00 * h[i] + d01 * h[i + 1]) / dx_ + d10 * m[i] + d11 * m[i + 1]};
}

double GridRoad::integral(Track t, double x) const {
  const int k = static_cast<int>(t);
  const auto& h = h_[k];
  const auto& m = m_[k];
  const auto& P = prefix_[k];
  const std::size_t n = h.size();
  const double s = (x - x0_) / dx_;
  if (s <= 0.0) return h.front() * (x - x0_);
  if (s >= static_cast<double>(n - 1)) return P.back() + h.back() * (x - (x0_ + dx_ * (n - 1)));
  const std::size_t i = static_cast<std::size_t>(s);
  const double u = s - static_cast<double>(i), u2 = u * u, u3 = u2 * u, u4 = u3 * u;
  const double I00 = u - u3 + 0.5 * u4, I10 = 0.5 * u2 - 2.0 * u3 / 3.0 + 0.25 * u4;
  const double I01 = u3 - 0.5 * u4, I11 = -u3 / 3.0 + 0.25 * u4;
  return P[i] + dx_ * (h[i] * I00 + dx_ * m[i] * I10 + h[i + 1] * I01 + dx_ * m[i + 1] * I11);
}

Interval GridRoad::extent() const {
  return {x0_, x0_ + dx_ * static_cast<double>(h_[0].size() - 1)};
}

// ------------------------------------------------------------------ four corners
CornerRoad::CornerRoad(std::shared_ptr<const Road> front, std::shared_ptr<const Road> rear,
                       nlohmann::json description)
    : front_(std::move(front)), rear_(std::move(rear)), description_(std::move(description)) {
  DTWIN_CHECK(front_ && rear_, "CornerRoad: a front and a rear road");
}

Interval CornerRoad::extent() const {
  const Interval f = front_->extent(), r = rear_->extent();
  return {std::min(f.lo, r.lo), std::max(f.hi, r.hi)};
}

std::vector<Interval> CornerRoad::obstacles() const {
  std::vector<Interval> o = front_->obstacles();
  for (const Interval& i : rear_->obstacles()) o.push_back(i);
  return o;
}

// ------------------------------------------------------------------ ISO 8608
double isoClassGd0(char c) {
  if (c < 'A' || c > 'H')
    throw InputError("", std::string("ISO 8608 class must be A..H, got '") + c + "'");
  return 16e-6 * std::pow(4.0, c - 'A');
}

double isoRmsHeight(char c, double n_min, double n_max) {
  const double n0 = 0.1;
  return std::sqrt(isoClassGd0(c) * n0 * n0 * (1.0 / n_min - 1.0 / n_max));
}

namespace {
/// Integral of Gd(n0) (n/n0)^-w over [a, b].
double gdIntegral(double gd0, double w, double a, double b) {
  const double n0 = 0.1;
  if (b <= a) return 0.0;
  if (std::abs(w - 1.0) < 1e-12) return gd0 * n0 * std::log(b / a);
  return gd0 * std::pow(n0, w) * (std::pow(b, 1.0 - w) - std::pow(a, 1.0 - w)) / (1.0 - w);
}

std::vector<double> isoTrack(const IsoRoadSpec& s, std::size_t N, std::uint64_t stream_id) {
  const double period = static_cast<double>(N) * s.dx_m, dn = 1.0 / period,
               gd0 = isoClassGd0(s.road_class);
  RandomStream rng(s.seed, 0x150'8608ULL, stream_id);
  std::vector<std::complex<double>> spec(N, 0.0);
  for (std::size_t k = 1; k < N / 2; ++k) {
    const double phase =
        2.0 * kPi * rng.uniform();  // drawn for every bin: band changes keep phases
    const double a = std::max(s.n_min, (k - 0.5) * dn), b = std::min(s.n_max, (k + 0.5) * dn);
    const double var = gdIntegral(gd0, s.waviness, a, b);
    if (var <= 0.0) continue;
    const double amp = std::sqrt(2.0 * var);
    spec[k] = static_cast<double>(N) * amp * std::polar(1.0, phase);
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> z;
  fft.inv(z, spec);
  std::vector<double> out(N);
  for (std::size_t j = 0; j < N; ++j) out[j] = z[j].real();
  return out;
}
}  // namespace

std::shared_ptr<const GridRoad> makeIsoRoad(const IsoRoadSpec& s) {
  if (!(s.n_min > 0 && s.n_max > s.n_min))
    throw InputError("", "ISO road band needs 0 < n_min < n_max");
  if (!(s.dx_m > 0 && s.n_max < 0.25 / s.dx_m))
    throw InputError("",
                     "ISO road grid spacing must resolve n_max with >= 4 points per wavelength");
  if (!(s.length_m > 0)) throw InputError("", "ISO road length must be > 0");
  // Period P = N dx >= max(length, 4 / n_min), so that several bins lie below the band's low end.
  const double need = std::max(s.length_m, 4.0 / s.n_min);
  const std::size_t n_pts = static_cast<std::size_t>(std::ceil(s.length_m / s.dx_m)) + 1;
  std::size_t N = 1024;
  while (static_cast<double>(N) * s.dx_m < need || N < n_pts) N *= 2;
  std::vector<double> left = isoTrack(s, N, 0);
  std::vector<double> right =
      s.coherence == IsoRoadSpec::Coherence::Identical ? left : isoTrack(s, N, 1);
  left.resize(std::min(N, n_pts));
  right.resize(left.size());
  for (std::size_t j = 0; j < left.size(); ++j) {
    const double x = s.x_begin_m + s.dx_m * static_cast<double>(j);
    double w = 1.0;
    if (x < s.smooth_until_m)
      w = 0.0;
    else if (x < s.smooth_until_m + s.taper_m)
      w = 0.5 * (1.0 - std::cos(kPi * (x - s.smooth_until_m) / s.taper_m));
    left[j] *= w;
    right[j] *= w;
  }
  nlohmann::json d = {
      {"type", "iso8608"},
      {"class", std::string(1, s.road_class)},
      {"gd_n0_m3", isoClassGd0(s.road_class)},
      {"n0_cycles_per_m", 0.1},
      {"waviness", s.waviness},
      {"band_cycles_per_m", {s.n_min, s.n_max}},
      {"dx_m", s.dx_m},
      {"x_begin_m", s.x_begin_m},
      {"length_m", s.length_m},
      {"period_m", static_cast<double>(N) * s.dx_m},
      {"tracks", s.coherence == IsoRoadSpec::Coherence::Identical ? "identical" : "independent"},
      {"seed", s.seed}};
  if (s.smooth_until_m > -1e299) {
    d["smooth_until_m"] = s.smooth_until_m;
    d["taper_m"] = s.taper_m;
  }
  return std::make_shared<GridRoad>(s.x_begin_m, s.dx_m, std::move(left), std::move(right),
                                    std::move(d));
}

// ------------------------------------------------------------------ CSV
std::shared_ptr<const GridRoad> loadRoadCsv(const std::string& path) {
  const std::string text = readTextFile(path, " (a road profile)");
  CsvReader csv(text, path);
  // The heights in m, mm or cm (the same unit on both tracks).
  static const std::pair<const char*, double> kUnits[] = {{"m", 1.0}, {"mm", 1e-3}, {"cm", 1e-2}};
  const char* kHeader = "'distance_m,left_m,right_m' (or left_mm,right_mm or left_cm,right_cm)";
  if (!csv.next())
    throw InputError(path + ":1", std::string("empty file; expected header ") + kHeader);
  double scale = 0;
  if (const auto& h = csv.fields(); h.size() == 3 && h[0] == "distance_m")
    for (const auto& [unit, factor] : kUnits)
      if (h[1] == std::string("left_") + unit && h[2] == std::string("right_") + unit)
        scale = factor;
  if (scale == 0) {
    std::string got;
    for (auto f : csv.fields()) got += (got.empty() ? "" : ",") + std::string(f);
    throw InputError(csv.where(), std::string("header must be ") + kHeader + ", got '" + got + "'");
  }
  std::vector<double> x, l, r;
  std::vector<long> lines;
  while (csv.next()) {
    const auto& f = csv.fields();
    if (f.size() > 3) throw InputError(csv.where(), "expected 3 columns, got more");
    if (f.size() < 3)
      throw InputError(csv.where(), "expected 3 columns, got " + std::to_string(f.size()));
    double v[3];
    for (std::size_t c = 0; c < 3; ++c)
      if (!parseNumber(f[c], v[c]) || !std::isfinite(v[c]))
        throw InputError(csv.where(), "value '" + std::string(f[c]) + "' is not a finite number");
    if (!x.empty() && !(v[0] > x.back()))
      throw InputError(csv.where(), "distance_m must increase strictly");
    x.push_back(v[0]);
    l.push_back(v[1] * scale);
    r.push_back(v[2] * scale);
    lines.push_back(csv.line());
  }
  if (x.size() < 2) throw InputError(path, "a road profile needs at least 2 rows");
  // Uniform spacing: every step must equal the first one (the first irregular line is named).
  const double step = x[1] - x[0];
  for (std::size_t i = 2; i < x.size(); ++i)
    if (std::abs((x[i] - x[i - 1]) - step) > 1e-6 * std::max(1.0, step) + 1e-9 * std::abs(x[i]))
      throw InputError(path + ":" + std::to_string(lines[i]),
                       "distance_m must be uniformly spaced (step " +
                           std::to_string(x[i] - x[i - 1]) + " m differs from the first step " +
                           std::to_string(step) + " m)");
  const double dx = (x.back() - x.front()) / static_cast<double>(x.size() - 1);
  nlohmann::json d = {{"type", "csv"}, {"path", path}, {"rows", x.size()}, {"dx_m", dx}};
  return std::make_shared<GridRoad>(x.front(), dx, std::move(l), std::move(r), std::move(d));
}

}  // namespace dtwin
