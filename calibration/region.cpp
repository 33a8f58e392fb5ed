#include "calibration/region.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>

#include "calibration/eigen_json.hpp"
#include "calibration/subspace_lm.hpp"
#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::calib {

// ------------------------------------------------------------------ Region
bool insideUnitCube(const Eigen::VectorXd& z) {
  for (Eigen::Index j = 0; j < z.size(); ++j)
    if (!(z(j) >= 0.0 && z(j) <= 1.0)) return false;
  return true;
}

Region narrowedToCube(const Region& r) {
  Region out = r;
  const Eigen::Index d = r.centre.size();
  Eigen::VectorXd& lo = out.t_lower;
  Eigen::VectorXd& hi = out.t_upper;
  for (int pass = 0; pass < 50; ++pass) {
    double moved = 0.0;
    for (Eigen::Index j = 0; j < d; ++j) {
      // z_j = c_j + sum_i A(j, i) t_i must lie in [0, 1].
      double sum_min = 0.0, sum_max = 0.0;
      for (Eigen::Index i = 0; i < d; ++i) {
        const double a = r.axes(j, i);
        sum_min += std::min(a * lo(i), a * hi(i));
        sum_max += std::max(a * lo(i), a * hi(i));
      }
      for (Eigen::Index i = 0; i < d; ++i) {
        const double a = r.axes(j, i);
        if (std::abs(a) < 1e-12) continue;
        const double rest_min = sum_min - std::min(a * lo(i), a * hi(i));
        const double rest_max = sum_max - std::max(a * lo(i), a * hi(i));
        // a t_i in [-c_j - rest_max, 1 - c_j - rest_min]
        double t0 = (-r.centre(j) - rest_max) / a, t1 = (1.0 - r.centre(j) - rest_min) / a;
        if (a < 0) std::swap(t0, t1);
        const double new_lo = std::min(std::max(lo(i), t0), 0.0),
                     new_hi = std::max(std::min(hi(i), t1), 0.0);
        moved = std::max({moved, new_lo - lo(i), hi(i) - new_hi});
        // Keep the running sums in step with the narrowed interval.
        sum_min += std::min(a * new_lo, a * new_hi) - std::min(a * lo(i), a * hi(i));
        sum_max += std::max(a * new_lo, a * new_hi) - std::max(a * lo(i), a * hi(i));
        lo(i) = new_lo;
        hi(i) = new_hi;
      }
    }
    if (moved <= 1e-12) break;
  }
  return out;
}

double Region::logVolume() const {
  double v = 0.0;
  for (Eigen::Index i = 0; i < t_lower.size(); ++i) v += std::log(t_upper(i) - t_lower(i));
  return v;
}

Eigen::VectorXd Region::toScaled(const std::vector<double>& theta) const {
  Eigen::VectorXd z(dim());
  for (int j = 0; j < dim(); ++j)
    z(j) = (theta[static_cast<std::size_t>(j)] - lower[static_cast<std::size_t>(j)]) /
           (upper[static_cast<std::size_t>(j)] - lower[static_cast<std::size_t>(j)]);
  return z;
}

std::vector<double> Region::toPhysical(const Eigen::VectorXd& z) const {
  std::vector<double> th(static_cast<std::size_t>(dim()));
  for (int j = 0; j < dim(); ++j) {
    const auto k = static_cast<std::size_t>(j);
    const double zj = std::clamp(z(j), 0.0, 1.0);
    th[k] = zj >= 1.0 ? upper[k] : lower[k] + zj * (upper[k] - lower[k]);
  }
  return th;
}

bool Region::contains(const Eigen::VectorXd& z) const {
  const Eigen::VectorXd t = coordinates(z);
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    const double tol = 1e-12 * (t_upper(i) - t_lower(i));
    if (t(i) < t_lower(i) - tol || t(i) > t_upper(i) + tol) return false;
  }
  return true;
}

void Region::boundingBox(std::vector<double>& lo, std::vector<double>& hi) const {
  const int d = dim();
  Eigen::VectorXd zlo(d), zhi(d);
  for (int j = 0; j < d; ++j) {
    double a = centre(j), b = centre(j);
    for (int i = 0; i < d; ++i) {
      const double x = axes(j, i) * t_lower(i), y = axes(j, i) * t_upper(i);
      a += std::min(x, y);
      b += std::max(x, y);
    }
    zlo(j) = std::clamp(a, 0.0, 1.0);
    zhi(j) = std::clamp(b, 0.0, 1.0);
  }
  lo = toPhysical(zlo);
  hi = toPhysical(zhi);
}

nlohmann::json Region::toJson() const {
  nlohmann::json j{{"kind", kind},
                   {"coordinates",
                    "scaled z_j = (theta_j - lower_j)/(upper_j - lower_j); region = {centre + axes "
                    "t : t_lower <= t <= t_upper}"},
                   {"bounds_lower", lower},
                   {"bounds_upper", upper},
                   {"centre", vectorJson(centre)},
                   {"t_lower", vectorJson(t_lower)},
                   {"t_upper", vectorJson(t_upper)},
                   {"reach_lower", vectorJson(reach_lower)},
                   {"reach_upper", vectorJson(reach_upper)},
                   {"guess_mean", vectorJson(guess_mean)},
                   {"guess_sd", vectorJson(guess_sd)},
                   {"threshold", threshold},
                   {"sse_min", sse_min},
                   {"evaluations", evaluations},
                   {"log_volume", logVolume()},
                   {"messages", messages}};
  j["axes"] = nlohmann::json::array();  // column i = axis i
  for (Eigen::Index i = 0; i < axes.cols(); ++i) j["axes"].push_back(vectorJson(axes.col(i)));
  j["ridge"] = nlohmann::json::array();  // traced floor points inside the contour, scaled
  for (Eigen::Index i = 0; i < ridge.rows(); ++i)
    j["ridge"].push_back(vectorJson(ridge.row(i).transpose()));
  j["ridge_sse"] = ridge_sse;
  j["ridge_cov"] = nlohmann::json::array();  // per ridge row: the local Gaussian's covariance, row
                                             // by row (null: unknown)
  for (const auto& c : ridge_cov) {
    nlohmann::json m = c.size() == 0 ? nlohmann::json() : nlohmann::json::array();
    for (Eigen::Index i = 0; i < c.rows(); ++i) m.push_back(vectorJson(c.row(i).transpose()));
    j["ridge_cov"].push_back(m);
  }
  std::vector<double> lo, hi;
  boundingBox(lo, hi);
  j["bounding_box_lower"] = lo;
  j["bounding_box_upper"] = hi;
  return j;
}

Region Region::fromJson(const nlohmann::json& j) {
  Region r;
  r.kind = j.at("kind").get<std::string>();
  r.lower = j.at("bounds_lower").get<std::vector<double>>();
  r.upper = j.at("bounds_upper").get<std::vector<double>>();
  r.centre = vectorFromJson(j.at("centre"));
  r.t_lower = vectorFromJson(j.at("t_lower"));
  r.t_upper = vectorFromJson(j.at("t_upper"));
  r.reach_lower = vectorFromJson(j.at("reach_lower"));
  r.reach_upper = vectorFromJson(j.at("reach_upper"));
  r.guess_mean = vectorFromJson(j.at("guess_mean"));
  r.guess_sd = vectorFromJson(j.at("guess_sd"));
  r.threshold = j.at("threshold").get<double>();
  r.sse_min = j.at("sse_min").get<double>();
  r.evaluations = j.at("evaluations").get<int>();
  r.messages = j.at("messages").get<std::vector<std::string>>();
  const auto& ax = j.at("axes");
  const auto d = static_cast<Eigen::Index>(ax.size());
  r.axes.resize(d, d);
  for (Eigen::Index i = 0; i < d; ++i)
    r.axes.col(i) = vectorFromJson(ax[static_cast<std::size_t>(i)]);
  const auto& rg = j.at("ridge");
  r.ridge.resize(static_cast<Eigen::Index>(rg.size()), d);
  for (std::size_t i = 0; i < rg.size(); ++i)
    r.ridge.row(static_cast<Eigen::Index>(i)) = vectorFromJson(rg[i]).transpose();
  r.ridge_sse = j.at("ridge_sse").get<std::vector<double>>();
  if (j.contains("ridge_cov"))
    for (const auto& m : j.at("ridge_cov")) {
      Eigen::MatrixXd c;
      if (!m.is_null()) {
        c.resize(d, d);
        for (Eigen::Index i = 0; i < d; ++i)
          c.row(i) = vectorFromJson(m[static_cast<std::size_t>(i)]).transpose();
      }
      r.ridge_cov.push_back(c);
    }
  return r;
}

std::string Region::briefReport() const {
  std::ostringstream os;
  std::vector<double> lo, hi;
  boundingBox(lo, hi);
  os << kind << " region (SSE <= " << formatNumber(threshold) << "), bounding box ";
  for (std::size_t j = 0; j < lo.size(); ++j)
    os << (j ? ", " : "") << "[" << formatNumber(lo[j]) << ", " << formatNumber(hi[j]) << "]";
  os << " (" << evaluations << " evaluations)";
  for (const auto& m : messages) os << "\n  note: " << m;
  return os.str();
}

Region regionFromBox(const FeasibleBox& box, const BoxProblem& problem) {
  Region r;
  r.kind = "paper";
  r.lower = problem.lower;
  r.upper = problem.upper;
  const int d = r.dim();
  r.axes = Eigen::MatrixXd::Identity(d, d);
  r.centre = r.toScaled(problem.theta_hat);
  const Eigen::VectorXd zlo = r.toScaled(box.lower), zhi = r.toScaled(box.upper);
  r.t_lower = zlo - r.centre;
  r.t_upper = zhi - r.centre;
  r.reach_lower = r.centre;
  r.reach_upper = Eigen::VectorXd::Ones(d) - r.centre;
  r.guess_mean = r.centre + 0.5 * (r.t_lower + r.t_upper);
  r.guess_sd = (r.t_upper - r.t_lower) / (2.0 * std::sqrt(2.0 * std::log(100.0)));
  r.ridge.resize(0, d);
  r.threshold = box.threshold;
  r.sse_min = problem.sse_min;
  r.evaluations = box.evaluations;
  for (const auto& s : box.sweeps)
    if (!s.message.empty()) r.messages.push_back(s.message);
  return r;
}

}  // namespace dtwin::calib
