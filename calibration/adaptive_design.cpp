#include "calibration/adaptive_design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "calibration/eigen_json.hpp"
#include "calibration/lhs.hpp"
#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::calib {
namespace {

constexpr std::uint64_t kStreamDesignRound = 0x4144'5200'0000'0004ULL;   // "ADR"
constexpr std::uint64_t kStreamDesignPilot = 0x4144'5000'0000'0005ULL;   // "ADP"
constexpr std::uint64_t kStreamResample = 0x4144'4b00'0000'0006ULL;      // "ADK"
constexpr std::uint64_t kStreamGuessCentres = 0x4144'4700'0000'0007ULL;  // "ADG"
constexpr int kPilot = 4096;
/// A ridge kernel's sd over its local Gaussian's: real SSEs rise slower than quadratically across
/// a ridge (on the demo's lab data 1.5 gave the four assemblies a final ESS of 85, 231, 51 and 102
/// against 28, 128, 81 and 102 with 1.2).
constexpr double kRidgeWiden = 1.5;
constexpr double kBendSlack = 1.5;  ///< ridgeBends: the guess's 1 % contour widened by this in sd
constexpr double kLog2Pi = 1.8378770664093454836;

/// A lower-triangular L with L Lᵀ = cov (eigenvalue floor when cov is not positive definite).
Eigen::MatrixXd choleskyOf(const Eigen::MatrixXd& cov) {
  Eigen::LLT<Eigen::MatrixXd> llt(cov);
  if (llt.info() == Eigen::Success) return llt.matrixL();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(cov);
  Eigen::VectorXd lam = es.eigenvalues();
  const double floor = std::max(lam.maxCoeff(), 1e-300) * 1e-12;
  for (Eigen::Index i = 0; i < lam.size(); ++i) lam(i) = std::max(lam(i), floor);
  const Eigen::MatrixXd fixed =
      es.eigenvectors() * lam.asDiagonal() * es.eigenvectors().transpose();
  Eigen::LLT<Eigen::MatrixXd> llt2(0.5 * (fixed + fixed.transpose()));
  DTWIN_CHECK(llt2.info() == Eigen::Success, "Cholesky factor of a floored covariance failed");
  return llt2.matrixL();
}

/// Scaled points of one round from a unit Latin hypercube u (rows); row i of a Gaussian round
/// takes kernel i mod K.
Eigen::MatrixXd mapUnit(const DesignRound& round, const Eigen::MatrixXd& u) {
  const Eigen::Index d = u.cols();
  Eigen::MatrixXd z(u.rows(), d);
  for (Eigen::Index i = 0; i < u.rows(); ++i) {
    if (round.kind == "uniform") {
      Eigen::VectorXd t(d);
      for (Eigen::Index j = 0; j < d; ++j)
        t(j) =
            round.region.t_lower(j) + u(i, j) * (round.region.t_upper(j) - round.region.t_lower(j));
      z.row(i) = round.region.at(t).transpose();
    } else {
      Eigen::VectorXd x(d);
      for (Eigen::Index j = 0; j < d; ++j)
        x(j) = normalQuantile(std::clamp(u(i, j), 1e-12, 1.0 - 1e-12));
      const long nb = round.broadCount(u.rows());
      if (i < nb)
        z.row(i) = (round.broad_mean + round.broad_chol * x).transpose();
      else {
        const Eigen::Index c = (i - nb) % round.centres.rows();
        z.row(i) = round.centres.row(c) + (round.cholOf(c) * x).transpose();
      }
    }
  }
  return z;
}

std::uint64_t derivedSeed(std::uint64_t seed, std::uint64_t stream, int round) {
  return RandomStream(seed, stream, static_cast<std::uint64_t>(round)).bits();
}

/// Importance diagnostics over the design so far.
struct Diagnostics {
  double ess = 0.0, top_share = 0.0, edge_share = 0.0;
  Eigen::VectorXd mean;
  Eigen::MatrixXd cov;
  Eigen::VectorXd weights;  ///< normalised, one per design point
  std::vector<double> mean_theta, sd_theta;
};

Diagnostics diagnose(const Eigen::MatrixXd& z, const std::vector<double>& sse,
                     const std::vector<double>& logq, int n_data, const AdaptiveDesignOptions& o,
                     const Region& outer) {
  const Eigen::Index N = z.rows(), d = z.cols();
  std::vector<double> lw(static_cast<std::size_t>(N), -std::numeric_limits<double>::infinity());
  double top = -std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < N; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (!std::isfinite(sse[i])) continue;
    lw[i] = -(o.tau_a + 0.5 * n_data) * std::log(o.tau_b + 0.5 * sse[i]) - logq[i];
    top = std::max(top, lw[i]);
  }
  Diagnostics g;
  g.mean = Eigen::VectorXd::Zero(d);
  g.cov = Eigen::MatrixXd::Zero(d, d);
  if (!std::isfinite(top)) return g;
  Eigen::VectorXd w(N);
  for (Eigen::Index k = 0; k < N; ++k)
    w(k) = std::isfinite(lw[static_cast<std::size_t>(k)])
               ? std::exp(lw[static_cast<std::size_t>(k)] - top)
               : 0.0;
  const double sw = w.sum();
  w /= sw;
  g.weights = w;
  g.ess = 1.0 / w.squaredNorm();
  g.top_share = w.maxCoeff();
  g.mean = z.transpose() * w;
  for (Eigen::Index k = 0; k < N; ++k) {
    if (w(k) == 0.0) continue;
    const Eigen::VectorXd e = z.row(k).transpose() - g.mean;
    g.cov += w(k) * e * e.transpose();
  }
  for (Eigen::Index j = 0; j < d; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const double range = outer.upper[k] - outer.lower[k];
    g.mean_theta.push_back(outer.lower[k] + g.mean(j) * range);
    g.sd_theta.push_back(std::sqrt(std::max(g.cov(j, j), 0.0)) * range);
  }
  // Edge shell of region 0, on the sides that can still grow.
  for (Eigen::Index k = 0; k < N; ++k) {
    if (w(k) == 0.0) continue;
    const Eigen::VectorXd t = outer.coordinates(z.row(k).transpose());
    bool edge = false;
    for (Eigen::Index i = 0; i < d && !edge; ++i) {
      const double shell = o.edge_fraction * (outer.t_upper(i) - outer.t_lower(i));
      edge = (outer.openLower(static_cast<int>(i)) && t(i) < outer.t_lower(i) + shell) ||
             (outer.openUpper(static_cast<int>(i)) && t(i) > outer.t_upper(i) - shell);
    }
    if (edge) g.edge_share += w(k);
  }
  return g;
}

/// K rows of z drawn in proportion to w by systematic resampling (one uniform offset).
Eigen::MatrixXd resampleCentres(const Eigen::MatrixXd& z, const Eigen::VectorXd& w, int k,
                                std::uint64_t seed) {
  RandomStream rng(seed, 0);
  const double u = rng.uniform();
  Eigen::MatrixXd c(k, z.cols());
  double cum = 0.0;
  Eigen::Index i = 0;
  for (int j = 0; j < k; ++j) {
    const double target = (u + j) / k;
    while (i + 1 < z.rows() && cum + w(i) <= target) cum += w(i++);
    c.row(j) = z.row(i);
  }
  return c;
}

bool settled(const Diagnostics& now, const Diagnostics& before, double settle) {
  if (before.sd_theta.empty()) return false;
  for (std::size_t j = 0; j < now.sd_theta.size(); ++j) {
    const double sd = now.sd_theta[j], sd0 = before.sd_theta[j];
    if (!(sd > 0.0 && sd0 > 0.0)) {
      if (sd != sd0) return false;
      continue;
    }
    if (std::abs(now.mean_theta[j] - before.mean_theta[j]) > settle * sd) return false;
    if (std::abs(sd / sd0 - 1.0) > settle) return false;
  }
  return true;
}

/// Ridge rows with a local Gaussian (Region::ridge_cov).
std::vector<Eigen::Index> localKernels(const Region& region) {
  std::vector<Eigen::Index> local;
  for (Eigen::Index q = 0; q < region.ridge.rows(); ++q) {
    const auto k = static_cast<std::size_t>(q);
    if (k < region.ridge_cov.size() && region.ridge_cov[k].size() > 0 &&
        k < region.ridge_sse.size())
      local.push_back(q);
  }
  return local;
}

/// Some traced floor point lies outside the Gaussian guess's own 1 % contour (Mahalanobis²
/// 2 ln 100) widened by kBendSlack in sd: the ridge bends away from the straight axes.
bool ridgeBends(const Region& region) {
  const double limit = kBendSlack * kBendSlack * 2.0 * std::log(100.0);
  for (Eigen::Index q = 0; q < region.ridge.rows(); ++q) {
    const Eigen::VectorXd t =
        region.axes.transpose() * (region.ridge.row(q).transpose() - region.guess_mean);
    double m2 = 0.0;
    for (Eigen::Index i = 0; i < t.size(); ++i)
      if (region.guess_sd(i) > 0.0) m2 += (t(i) / region.guess_sd(i)) * (t(i) / region.guess_sd(i));
    if (m2 > limit) return true;
  }
  return false;
}

/// Rows 0 .. count−1 of round.centres: the ridge floor points `local` with their own widened
/// local Gaussians (round.own_cov), allotted by systematic allotment (offset 1/2) in proportion to
/// posterior(z_q)·sqrt(det Σ_q), τ integrated out as in diagnose().
void ridgeCentres(DesignRound& round, const Region& region, const std::vector<Eigen::Index>& local,
                  int count, int n_data, const AdaptiveDesignOptions& options) {
  round.own_cov.assign(static_cast<std::size_t>(round.centres.rows()), Eigen::MatrixXd());
  std::vector<double> lw(local.size());
  for (std::size_t k = 0; k < local.size(); ++k) {
    const auto q = static_cast<std::size_t>(local[k]);
    lw[k] = -(options.tau_a + 0.5 * n_data) * std::log(options.tau_b + 0.5 * region.ridge_sse[q]) +
            choleskyOf(region.ridge_cov[q]).diagonal().array().log().sum();
  }
  const double top = *std::max_element(lw.begin(), lw.end());
  std::vector<double> cum(local.size());
  double total = 0.0;
  for (std::size_t k = 0; k < local.size(); ++k) cum[k] = (total += std::exp(lw[k] - top));
  std::size_t k = 0;
  for (int i = 0; i < count; ++i) {
    const double target = (i + 0.5) / count * total;
    while (k + 1 < local.size() && cum[k] < target) ++k;
    round.centres.row(i) = region.ridge.row(local[k]);
    round.own_cov[static_cast<std::size_t>(i)] =
        kRidgeWiden * kRidgeWiden * region.ridge_cov[static_cast<std::size_t>(local[k])];
  }
}

/// Rows 0 .. count−1 of round.centres: a stratified sample of N(m, blend), m the weighted mean
/// shrunk towards the region's guess mean with the weight nu0.
void guessCentres(DesignRound& round, const Region& region, const Diagnostics& now,
                  const Eigen::MatrixXd& blend, double nu0, int count, std::uint64_t seed) {
  const auto d = static_cast<int>(blend.rows());
  const Eigen::VectorXd m = (now.ess * now.mean + nu0 * region.guess_mean) / (now.ess + nu0);
  const std::vector<double> zero(static_cast<std::size_t>(d), 0.0),
      one(static_cast<std::size_t>(d), 1.0);
  const Eigen::MatrixXd u = latinHypercube(count, zero, one, seed);
  const Eigen::MatrixXd L = choleskyOf(blend);
  for (int i = 0; i < count; ++i) {
    Eigen::VectorXd x(d);
    for (int j = 0; j < d; ++j) x(j) = normalQuantile(std::clamp(u(i, j), 1e-12, 1.0 - 1e-12));
    round.centres.row(i) = (m + L * x).transpose();
  }
}

/// Adaptive round r >= 1: a Gaussian mixture with kernels on the heavy points of the design so far
/// (scaled points `zs`, diagnostics `now`) and a defensive broad component.
DesignRound kernelRound(int r, const Diagnostics& now, const Eigen::MatrixXd& zs,
                        const Region& region, int n_data, const AdaptiveDesignOptions& options) {
  const int d = region.dim();
  DesignRound next;
  next.index = r;
  next.kind = "gaussian";
  // Kernels on the heavy points. Their covariance is the weighted posterior covariance shrunk
  // towards the region's guess with the weight of nu0 = 10 (d + 1) points, so a round that rests
  // on a handful of heavy points still explores around them with a sensible shape.
  const double dd = static_cast<double>(d), nu0 = 10.0 * (dd + 1.0);
  const Eigen::MatrixXd blend =
      (now.ess * now.cov + nu0 * region.guessCovariance()) / (now.ess + nu0);
  const double h = std::max(options.kernel_min, std::pow(4.0 / (dd + 2.0), 1.0 / (dd + 4.0)) *
                                                    std::pow(now.ess, -1.0 / (dd + 4.0)));
  // The centres are shrunk the same way: a share nu0 / (ESS + nu0) of them comes from what the
  // region knows, the rest is resampled from the heavy points (after a uniform round 0 whose ESS is
  // a dozen, resampling alone puts every kernel on one of a dozen points: a lumpy mixture).
  //  * A straight ridge (every traced floor point inside the Gaussian guess's own 1 % contour,
  //    with slack): a stratified sample of N(m, blend), m = (ESS·mean + nu0·guess mean)/(ESS +
  //    nu0), kernels with the common covariance.
  //  * A bent ridge (a thin curved tube, as on the demo's lab data, where no common covariance
  //    follows the posterior): the ridge floor points, each kernel with its own local Gaussian
  //    (Region::ridge_cov, widened by kRidgeWiden in sd), allotted in proportion to
  //    posterior(z_q)·sqrt(det Σ_q), so that the mixture's density along the ridge follows the
  //    posterior's.
  const int K = options.kernels;
  const int from_prior = static_cast<int>(std::lround(K * nu0 / (now.ess + nu0)));
  const std::vector<Eigen::Index> local =
      ridgeBends(region) ? localKernels(region) : std::vector<Eigen::Index>{};
  next.centres.resize(K, d);
  if (!local.empty() && from_prior > 0)
    ridgeCentres(next, region, local, from_prior, n_data, options);
  else if (from_prior > 0)
    guessCentres(next, region, now, blend, nu0, from_prior,
                 derivedSeed(options.seed, kStreamGuessCentres, r));
  if (from_prior < K)
    next.centres.bottomRows(K - from_prior) = resampleCentres(
        zs, now.weights, K - from_prior, derivedSeed(options.seed, kStreamResample, r));
  if (r == 1 && local.empty() && region.ridge.rows() > 0) {
    // The first adaptive round also puts kernels on the traced ridge floor (region.hpp), so a
    // curved ridge that round 0 sampled thinly is covered from the start.
    Eigen::MatrixXd both(next.centres.rows() + region.ridge.rows(), d);
    both << next.centres, region.ridge;
    next.centres = both;
  }
  next.cov = h * h * blend;
  next.broad_share = options.broad_share;
  next.broad_mean = now.mean;
  next.broad_cov = options.broad_scale * options.broad_scale * blend;
  // A floor keeps the kernels proper.
  for (int j = 0; j < d; ++j) {
    next.cov(j, j) = std::max(next.cov(j, j), 1e-12);
    next.broad_cov(j, j) = std::max(next.broad_cov(j, j), 1e-12);
  }
  return next;
}

}  // namespace

void DesignRound::prepare() {
  if (kind != "gaussian") return;
  chol = choleskyOf(cov);
  logdet = chol.diagonal().array().log().sum();
  own_chol.clear();
  own_logdet.clear();
  for (const auto& c : own_cov) {
    own_chol.push_back(c.size() == 0 ? Eigen::MatrixXd() : choleskyOf(c));
    own_logdet.push_back(c.size() == 0 ? 0.0 : own_chol.back().diagonal().array().log().sum());
  }
  if (broad_share > 0.0) broad_chol = choleskyOf(broad_cov);
}

long DesignRound::broadCount(long m) const {
  return broad_share > 0.0 ? std::lround(broad_share * static_cast<double>(m)) : 0;
}

void AdaptiveDesignOptions::validate() const {
  const OptionCheck check("design");
  check.atLeast("first_points", first_points, 2);
  check.atLeast("round_points", round_points, 2);
  check.atLeast("max_rounds", max_rounds, 0);
  check.positive("target_ess", target_ess);
  check.positive("settle", settle);
  check.require(kernel_min > 0.0 && kernel_min <= 2.0, "kernel_min",
                "must lie in (0, 2], got " + formatNumber(kernel_min));
  check.atLeast("kernels", kernels, 1);
  check.require(broad_share >= 0.0 && broad_share < 1.0, "broad_share",
                "must lie in [0, 1), got " + formatNumber(broad_share));
  check.require(broad_scale >= 1.0 && std::isfinite(broad_scale), "broad_scale",
                "must be a finite number >= 1, got " + formatNumber(broad_scale));
  check.require(edge_fraction > 0.0 && edge_fraction < 0.5, "edge_fraction",
                "must lie in (0, 0.5), got " + formatNumber(edge_fraction));
  check.open01("edge_share_max", edge_share_max);
  check.nonNegative("tau_a", tau_a);
  check.nonNegative("tau_b", tau_b);
}

nlohmann::json AdaptiveDesignOptions::toJson() const {
  return {{"design", adaptive ? "adaptive" : "lhs"},
          {"first_points", first_points},
          {"round_points", round_points},
          {"max_rounds", max_rounds},
          {"target_ess", target_ess},
          {"settle", settle},
          {"kernel_min", kernel_min},
          {"kernels", kernels},
          {"broad_share", broad_share},
          {"broad_scale", broad_scale},
          {"edge_fraction", edge_fraction},
          {"edge_share_max", edge_share_max}};
}

nlohmann::json DesignRound::toJson(const std::vector<std::string>& names) const {
  nlohmann::json j{{"round", index},         {"kind", kind},
                   {"drawn", drawn},         {"first_row", first},
                   {"points", count},        {"importance_ess", ess},
                   {"top_share", top_share}, {"edge_share", edge_share}};
  if (kind == "uniform")
    j["region"] = region.toJson();
  else {
    j["kernels"] = centres.rows();
    j["centres_scaled"] = nlohmann::json::array();
    for (Eigen::Index i = 0; i < centres.rows(); ++i)
      j["centres_scaled"].push_back(vectorJson(centres.row(i).transpose()));
    j["covariance_scaled"] = nlohmann::json::array();
    for (Eigen::Index i = 0; i < cov.rows(); ++i)
      j["covariance_scaled"].push_back(vectorJson(cov.row(i).transpose()));
    // Kernels with their own covariance (ridge kernels): index -> covariance, row by row.
    for (std::size_t c = 0; c < own_cov.size(); ++c)
      if (own_cov[c].size() > 0) {
        nlohmann::json m = nlohmann::json::array();
        for (Eigen::Index i = 0; i < own_cov[c].rows(); ++i)
          m.push_back(vectorJson(own_cov[c].row(i).transpose()));
        j["own_covariances_scaled"][std::to_string(c)] = m;
      }
    if (broad_share > 0.0) {
      j["broad"] = {{"share", broad_share},
                    {"mean_scaled", vectorJson(broad_mean)},
                    {"covariance_scaled", nlohmann::json::array()}};
      for (Eigen::Index i = 0; i < broad_cov.rows(); ++i)
        j["broad"]["covariance_scaled"].push_back(vectorJson(broad_cov.row(i).transpose()));
    }
  }
  for (std::size_t k = 0; k < names.size() && k < mean_theta.size(); ++k)
    j["posterior"][names[k]] = {{"mean", mean_theta[k]}, {"sd", sd_theta[k]}};
  return j;
}

nlohmann::json AdaptiveDesign::toJson(const std::vector<std::string>& names) const {
  nlohmann::json j{{"points", points.rows()},
                   {"importance_ess", ess},
                   {"top_share", top_share},
                   {"stop_reason", stop_reason},
                   {"warnings", warnings}};
  j["rounds"] = nlohmann::json::array();
  for (const auto& r : rounds) j["rounds"].push_back(r.toJson(names));
  return j;
}

double logMixtureDensity(const std::vector<DesignRound>& rounds, const Eigen::VectorXd& z) {
  const double d = static_cast<double>(z.size());
  std::vector<double> terms;
  for (const auto& r : rounds) {
    if (r.drawn <= 0) continue;
    if (r.kind == "uniform") {
      if (r.region.contains(z))
        terms.push_back(std::log(static_cast<double>(r.drawn)) - r.region.logVolume());
    } else {
      // Each component weighted by the number of points it took (exactly as drawRound assigns).
      const long nb = r.broadCount(r.drawn), rest = r.drawn - nb, K = r.centres.rows();
      if (nb > 0) {
        const Eigen::VectorXd x =
            r.broad_chol.triangularView<Eigen::Lower>().solve(z - r.broad_mean);
        terms.push_back(std::log(static_cast<double>(nb)) - 0.5 * d * kLog2Pi -
                        r.broad_chol.diagonal().array().log().sum() - 0.5 * x.squaredNorm());
      }
      for (long c = 0; c < K; ++c) {
        const long count = rest / K + (c < rest % K ? 1 : 0);
        if (count == 0) continue;
        const Eigen::VectorXd x =
            r.cholOf(c).triangularView<Eigen::Lower>().solve(z - r.centres.row(c).transpose());
        terms.push_back(std::log(static_cast<double>(count)) - 0.5 * d * kLog2Pi - r.logdetOf(c) -
                        0.5 * x.squaredNorm());
      }
    }
  }
  if (terms.empty()) return -std::numeric_limits<double>::infinity();
  const double m = *std::max_element(terms.begin(), terms.end());
  double s = 0.0;
  for (double t : terms) s += std::exp(t - m);
  return m + std::log(s);
}

namespace {
/// How many of the kPilot pilot points (no simulation) of `round` lie inside the bounds.
int pilotInside(const DesignRound& round, std::uint64_t seed) {
  const int d =
      round.kind == "uniform" ? round.region.dim() : static_cast<int>(round.centres.cols());
  const std::vector<double> zero(static_cast<std::size_t>(d), 0.0),
      one(static_cast<std::size_t>(d), 1.0);
  const Eigen::MatrixXd pilot = mapUnit(
      round, latinHypercube(kPilot, zero, one, derivedSeed(seed, kStreamDesignPilot, round.index)));
  int in = 0;
  for (Eigen::Index i = 0; i < pilot.rows(); ++i)
    in += insideUnitCube(pilot.row(i).transpose()) ? 1 : 0;
  return in;
}
double pilotInsideShare(const DesignRound& round, std::uint64_t seed) {
  return static_cast<double>(pilotInside(round, seed)) / kPilot;
}
}  // namespace

Eigen::MatrixXd drawRound(const DesignRound& round, int inside, std::uint64_t seed, long& drawn) {
  DTWIN_CHECK(inside >= 1, "a round needs at least one point");
  const int d =
      round.kind == "uniform" ? round.region.dim() : static_cast<int>(round.centres.cols());
  const std::vector<double> zero(static_cast<std::size_t>(d), 0.0),
      one(static_cast<std::size_t>(d), 1.0);
  // Inside fraction from a pilot sample (no simulation).
  const int in = pilotInside(round, seed);
  const long cap = 64L * inside;
  long m = in > 0 ? static_cast<long>(std::ceil(static_cast<double>(inside) * kPilot / in)) : cap;
  m = std::clamp(m, static_cast<long>(inside), cap);
  const std::uint64_t s =
      round.index == 0 ? seed : derivedSeed(seed, kStreamDesignRound, round.index);
  const Eigen::MatrixXd z = mapUnit(round, latinHypercube(static_cast<int>(m), zero, one, s));
  drawn = m;
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < z.rows(); ++i)
    if (insideUnitCube(z.row(i).transpose())) keep.push_back(i);
  Eigen::MatrixXd in_z(static_cast<Eigen::Index>(keep.size()), d);
  for (std::size_t r = 0; r < keep.size(); ++r)
    in_z.row(static_cast<Eigen::Index>(r)) = z.row(keep[r]);
  return in_z;
}

AdaptiveDesign runAdaptiveDesign(const Region& region, int n_data,
                                 const AdaptiveDesignOptions& options,
                                 const DesignEvaluator& evaluate) {
  options.validate();
  DTWIN_CHECK(n_data >= 1, "an adaptive design needs n >= 1");
  const int d = region.dim();
  AdaptiveDesign out;
  out.points.resize(0, d);
  Eigen::MatrixXd zs(0, d);
  Diagnostics before;

  auto runRound = [&](DesignRound round, int inside) -> Diagnostics {
    round.prepare();
    round.first = static_cast<int>(out.points.rows());
    const Eigen::MatrixXd z = drawRound(round, inside, options.seed, round.drawn);
    if (round.index == 0 && z.rows() == 0)
      throw std::runtime_error(
          "the calibration region lies outside the parameter bounds: none of " +
          std::to_string(round.drawn) +
          " points drawn in it is inside them (box.json shows the region)");
    Eigen::MatrixXd theta(z.rows(), d);
    for (Eigen::Index i = 0; i < z.rows(); ++i) {
      const auto th = region.toPhysical(z.row(i).transpose());
      for (int j = 0; j < d; ++j) theta(i, j) = th[static_cast<std::size_t>(j)];
    }
    round.count = static_cast<int>(theta.rows());
    std::vector<double> s = round.count > 0 ? evaluate(theta, round.first) : std::vector<double>{};
    DTWIN_CHECK(static_cast<Eigen::Index>(s.size()) == theta.rows(),
                "the design evaluator returned the wrong number of SSEs");
    const Eigen::Index n0 = out.points.rows();
    out.points.conservativeResize(n0 + theta.rows(), d);
    out.points.bottomRows(theta.rows()) = theta;
    zs.conservativeResize(n0 + z.rows(), d);
    zs.bottomRows(z.rows()) = z;
    out.sse.insert(out.sse.end(), s.begin(), s.end());
    out.rounds.push_back(round);
    std::vector<double> logq(static_cast<std::size_t>(zs.rows()));
    for (Eigen::Index k = 0; k < zs.rows(); ++k)
      logq[static_cast<std::size_t>(k)] = logMixtureDensity(out.rounds, zs.row(k).transpose());
    Diagnostics g = diagnose(zs, out.sse, logq, n_data, options, region);
    auto& last = out.rounds.back();
    last.ess = g.ess;
    last.top_share = g.top_share;
    last.edge_share = g.edge_share;
    last.mean_theta = g.mean_theta;
    last.sd_theta = g.sd_theta;
    return g;
  };

  DesignRound r0;
  r0.index = 0;
  r0.kind = "uniform";
  r0.region = region;
  {
    // A region mostly outside the bounds (an optimum on a bound, with a tilted axis whose clipped
    // sweep took the bounds' whole reach) draws from its part inside them instead: the same
    // P ∩ [0, 1]^d, a smaller box around it (region.hpp narrowedToCube). Regions inside the
    // bounds for the most part are drawn from as they are.
    r0.prepare();
    const double inside = pilotInsideShare(r0, options.seed);
    if (inside < 1.0 / 16.0) {
      r0.region = narrowedToCube(region);
      r0.prepare();
      out.warnings.push_back("the calibration region lay mostly outside the parameter bounds (" +
                             formatNumber(100.0 * inside, 3) +
                             " % of it inside): the first round drew from its part inside them (" +
                             formatNumber(100.0 * pilotInsideShare(r0, options.seed), 3) +
                             " % of the narrowed region)");
    }
  }
  Diagnostics now = runRound(r0, options.first_points);
  out.stop_reason = options.adaptive ? "" : "one Latin hypercube (design = \"lhs\")";
  for (int r = 1; options.adaptive && r <= options.max_rounds; ++r) {
    if (!std::isfinite(now.ess) || now.ess <= 0.0) {
      out.stop_reason = "no design point has a finite SSE";
      break;
    }
    before = now;
    now = runRound(kernelRound(r, now, zs, region, n_data, options), options.round_points);
    if (now.ess >= options.target_ess && settled(now, before, options.settle)) {
      out.stop_reason = "settled after round " + std::to_string(r) + ": importance ESS " +
                        formatNumber(now.ess, 4) + " >= " + formatNumber(options.target_ess, 4) +
                        ", means and sds changed by less than " + formatNumber(options.settle, 4) +
                        " sd";
      break;
    }
    if (r == options.max_rounds)
      out.stop_reason = "all " + std::to_string(options.max_rounds) + " adaptive rounds used";
  }
  if (options.adaptive && options.max_rounds == 0) out.stop_reason = "max_rounds = 0: round 0 only";
  out.ess = now.ess;
  out.top_share = now.top_share;
  // Design weights ω_k = −log q(z_k), largest 0.
  out.log_weight.resize(out.sse.size());
  double mx = -std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < zs.rows(); ++k) {
    out.log_weight[static_cast<std::size_t>(k)] =
        -logMixtureDensity(out.rounds, zs.row(k).transpose());
    mx = std::max(mx, out.log_weight[static_cast<std::size_t>(k)]);
  }
  for (auto& w : out.log_weight) w -= mx;
  if (out.ess < 100.0)
    out.warnings.push_back(
        "the design resolves the posterior with only " + formatNumber(out.ess, 4) +
        " effective points (importance ESS < 100): the intervals are rough; raise lhs_points, "
        "[calibration] round_points or max_rounds");
  const bool kernel_rounds = std::any_of(out.rounds.begin(), out.rounds.end(),
                                         [](const DesignRound& r) { return r.kind == "gaussian"; });
  if (!kernel_rounds && now.edge_share > options.edge_share_max)
    out.warnings.push_back("the posterior still puts " + formatNumber(100.0 * now.edge_share, 4) +
                           " % of its weight near the region's edge: the region may cut it off");
  if (options.adaptive && out.stop_reason.rfind("settled", 0) != 0 && out.ess >= 100.0)
    out.warnings.push_back("the adaptive design did not settle (" + out.stop_reason +
                           "): the intervals may still move with more rounds");
  return out;
}

}  // namespace dtwin::calib
