#include "diagnosis/baseline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "diagnosis/signal.hpp"
#include "subsystems/road.hpp"

namespace dtwin::diag {

double RoadInput::at(int corner, double t) const {
  const auto& v = u[static_cast<std::size_t>(corner)];
  if (v.empty()) return 0.0;
  const double s = t / dt_s;
  if (s <= 0) return v.front();
  const auto k = static_cast<std::size_t>(s);
  if (k + 1 >= v.size()) return v.back();
  const double w = s - static_cast<double>(k);
  return (1 - w) * v[k] + w * v[k + 1];
}

RoadInput roadInput(const ScenarioSpec& sc, const VehicleData& vehicle, std::uint64_t seed, double dt_s, double duration_s) {
  RoadInput in;
  in.dt_s = dt_s;
  const auto road = makeRoad(sc, vehicle, seed);
  const auto n = static_cast<std::size_t>(std::ceil(duration_s / dt_s)) + 1;
  for (auto& v : in.u) v.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = sc.speed.distance(static_cast<double>(k) * dt_s);
    for (int c = 0; c < 4; ++c) {
      const Track track = c % 2 == 0 ? Track::Left : Track::Right;
      in.u[static_cast<std::size_t>(c)][k] = road->sample(track, c < 2 ? x : x - vehicle.wheelbase()).height_m;
    }
  }
  return in;
}

namespace {
/// The regressors of one time: 1, then u_c(t − j Δ) wheel by wheel.
void regressors(const RoadInput& in, double t, double dt, int taps, Eigen::VectorXd& x) {
  x[0] = 1.0;
  for (int c = 0; c < 4; ++c)
    for (int j = 0; j < taps; ++j) x[1 + c * taps + j] = in.at(c, t - j * dt);
}
}  // namespace

double FirBaseline::predict(const RoadInput& in, double t) const {
  Eigen::VectorXd x(static_cast<long>(coef.size()));
  regressors(in, t, dt_s, taps, x);
  return x.dot(Eigen::Map<const Eigen::VectorXd>(coef.data(), static_cast<long>(coef.size())));
}

std::string FirBaseline::describe() const {
  return "FIR from the road under the 4 wheels, " + std::to_string(taps) + " taps each at " + formatNumber(dt_s) +
         " s, least squares on " + std::to_string(training_records) + " records";
}

FirBaseline fitFirBaseline(const std::string& channel, const std::vector<const LabData*>& train, const std::vector<const RoadInput*>& inputs,
                           double dt_s, int taps) {
  DTWIN_CHECK(train.size() == inputs.size() && dt_s > 0 && taps > 0, "fitFirBaseline: arguments");
  FirBaseline b;
  b.channel = channel;
  b.dt_s = dt_s;
  b.taps = taps;
  const long p = 1 + 4L * taps;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(p), x(p);
  for (std::size_t s = 0; s < train.size(); ++s)
    for (const auto& r : train[s]->records) {
      if (r.channel != channel) continue;
      regressors(*inputs[s], r.time_s, dt_s, taps, x);
      A.selfadjointView<Eigen::Lower>().rankUpdate(x);
      rhs += r.value * x;
      ++b.training_records;
    }
  if (b.training_records < p)
    throw InputError("baseline " + channel, "the calibration data hold " + std::to_string(b.training_records) + " records of " + channel +
                                                ", fewer than the FIR's " + std::to_string(p) + " coefficients");
  A.triangularView<Eigen::StrictlyUpper>() = A.transpose().triangularView<Eigen::StrictlyUpper>();
  A.diagonal().array() += 1e-9 * A.diagonal().mean();
  const Eigen::VectorXd c = A.ldlt().solve(rhs);
  b.coef.assign(c.data(), c.data() + c.size());
  return b;
}

double firFitPercent(const FirBaseline& baseline, const LabData& data, const RoadInput& input) {
  double ss = 0, sum = 0, sq = 0, n = 0;
  for (const auto& r : data.records) {
    if (r.channel != baseline.channel) continue;
    const double e = r.value - baseline.predict(input, r.time_s);
    ss += e * e;
    sum += r.value;
    sq += r.value * r.value;
    n += 1;
  }
  if (n == 0) return std::numeric_limits<double>::quiet_NaN();
  return fitPercent(ss, n, sum, sq);
}

}  // namespace dtwin::diag
