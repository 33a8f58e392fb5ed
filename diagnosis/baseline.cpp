#include "diagnosis/baseline.hpp"

#include <algorithm>
#include <array>
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

RoadInput roadInput(const ScenarioSpec& sc, const VehicleData& vehicle, std::uint64_t seed,
                    double dt_s, double duration_s) {
  RoadInput in;
  in.dt_s = dt_s;
  const auto road = makeRoad(sc, vehicle, seed);
  const auto n = static_cast<std::size_t>(std::ceil(duration_s / dt_s)) + 1;
  for (auto& v : in.u) v.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = sc.speed.distance(static_cast<double>(k) * dt_s);
    for (int c = 0; c < 4; ++c)
      in.u[static_cast<std::size_t>(c)][k] =
          road->sampleAt(c, c < 2 ? x : x - vehicle.wheelbase()).height_m;
  }
  return in;
}

namespace {
/// The regressors of one time: 1, then the input at t − j Δ wheel by wheel (the height, or the
/// velocity over the tap spacing), then the model's prediction (model->u[0]) at t − j Δ, j <
/// model_taps.
void regressors(const RoadInput& in, double t, double dt, int taps, FirInput input,
                const std::vector<int>& corners, const RoadInput* model, int model_taps,
                Eigen::VectorXd& x) {
  x[0] = 1.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const int c = corners[i];
    for (int j = 0; j < taps; ++j)
      x[1 + static_cast<long>(i) * taps + j] =
          input == FirInput::Height ? in.at(c, t - j * dt)
                                    : (in.at(c, t - j * dt) - in.at(c, t - (j + 1) * dt)) / dt;
  }
  const long m0 = 1 + static_cast<long>(corners.size()) * taps;
  for (int j = 0; j < model_taps; ++j) x[m0 + j] = model->at(0, t - j * dt);
}

/// One training record: the data set, its time and value, and its fold (0: the first half of its
/// data set's time span).
struct Row {
  std::size_t set;
  double t, y;
  int fold;
};

/// The normal equations of the rows of one fold: XᵀX, Xᵀy and yᵀy.
struct Normal {
  Eigen::MatrixXd xx;
  Eigen::VectorXd xy;
  double yy = 0;
};

/// Each fold's normal equations (0: the first half of each data set's span, 1: the second).
std::array<Normal, 2> normals(const std::vector<Row>& rows,
                              const std::vector<const RoadInput*>& inputs, double dt, int taps,
                              FirInput input, const std::vector<int>& corners,
                              const std::vector<const RoadInput*>& models, int model_taps) {
  const long p = 1 + static_cast<long>(corners.size()) * taps + model_taps;
  std::array<Normal, 2> n;
  for (auto& f : n) {
    f.xx = Eigen::MatrixXd::Zero(p, p);
    f.xy = Eigen::VectorXd::Zero(p);
  }
  Eigen::VectorXd x(p);
  for (const auto& r : rows) {
    auto& f = n[static_cast<std::size_t>(r.fold)];
    regressors(*inputs[r.set], r.t, dt, taps, input, corners, model_taps ? models[r.set] : nullptr,
               model_taps, x);
    f.xx.selfadjointView<Eigen::Lower>().rankUpdate(x);
    f.xy += r.y * x;
    f.yy += r.y * r.y;
  }
  for (auto& f : n)
    f.xx.triangularView<Eigen::StrictlyUpper>() =
        f.xx.transpose().triangularView<Eigen::StrictlyUpper>();
  return n;
}

/// The ridge solution (XᵀX + λ mean(diag XᵀX) I) c = Xᵀy.
Eigen::VectorXd ridgeSolve(const Eigen::MatrixXd& xx, const Eigen::VectorXd& xy, double lambda) {
  Eigen::MatrixXd a = xx;
  a.diagonal().array() += lambda * xx.diagonal().mean();
  return a.ldlt().solve(xy);
}
}  // namespace

double FirBaseline::predict(const RoadInput& in, double t, const RoadInput* model) const {
  DTWIN_CHECK(model_taps == 0 || model,
              "FirBaseline::predict: the filter takes the model's prediction");
  Eigen::VectorXd x(static_cast<long>(coef.size()));
  regressors(in, t, dt_s, taps, input, corners, model, model_taps, x);
  return x.dot(Eigen::Map<const Eigen::VectorXd>(coef.data(), static_cast<long>(coef.size())));
}

std::string FirBaseline::describe() const {
  if (none())
    return "no filter: predicting nothing beat every FIR form in a two-fold cross-validation on " +
           std::to_string(training_records) + " records";
  const bool front = corners.size() <= 2 &&
                     std::all_of(corners.begin(), corners.end(), [](int c) { return c < 2; });
  const std::string wheels =
      front ? (corners.size() == 1 ? "the front wheels (one signal)" : "the 2 front wheels")
            : (corners.size() == 4 ? "the 4 wheels"
                                   : std::to_string(corners.size()) + " distinct wheel signals");
  return std::string("FIR from the road's ") +
         (input == FirInput::Height ? "height" : "vertical velocity") + " under " + wheels + ", " +
         std::to_string(taps) + " taps each at " + formatNumber(dt_s) + " s, least squares on " +
         std::to_string(training_records) + " records, ridge " + formatNumber(ridge) +
         (cv_sse.empty()
              ? ""
              : " (input, wheels and ridge chosen by two-fold cross-validation on them)");
}

FirBaseline fitFir(const std::string& channel, const std::vector<const LabData*>& train,
                   const std::vector<const RoadInput*>& inputs, double dt_s,
                   const FirSearch& search, const std::vector<const RoadInput*>& models) {
  DTWIN_CHECK(train.size() == inputs.size() && dt_s > 0 && !search.taps.empty() &&
                  !search.inputs.empty() && !search.ridges.empty() && !search.model_taps.empty(),
              "fitFir: arguments");
  for (const int taps : search.taps) DTWIN_CHECK(taps > 0, "fitFir: taps must be positive");
  const int most_model = *std::max_element(search.model_taps.begin(), search.model_taps.end());
  DTWIN_CHECK(*std::min_element(search.model_taps.begin(), search.model_taps.end()) >= 0 &&
                  (most_model == 0 || models.size() == train.size()),
              "fitFir: the model's predictions");
  FirBaseline b;
  b.channel = channel;
  b.dt_s = dt_s;
  std::vector<Row> rows;
  for (std::size_t s = 0; s < train.size(); ++s) {
    double t0 = std::numeric_limits<double>::infinity(), t1 = -t0;
    for (const auto& r : train[s]->records)
      if (r.channel == channel) t0 = std::min(t0, r.time_s), t1 = std::max(t1, r.time_s);
    for (const auto& r : train[s]->records)
      if (r.channel == channel)
        rows.push_back({s, r.time_s, r.value, r.time_s < 0.5 * (t0 + t1) ? 0 : 1});
  }
  b.training_records = static_cast<long>(rows.size());
  // Wheels whose road repeats an earlier wheel's in every training input enter once.
  std::vector<int> distinct;
  for (int c = 0; c < 4; ++c) {
    bool repeat = false;
    for (int e : distinct) {
      bool same = true;
      for (const auto* in : inputs)
        same = same && in->u[static_cast<std::size_t>(c)] == in->u[static_cast<std::size_t>(e)];
      repeat = repeat || same;
    }
    if (!repeat) distinct.push_back(c);
  }
  std::vector<int> front;
  for (int c : distinct)
    if (c < 2) front.push_back(c);
  const int fewest = *std::min_element(search.taps.begin(), search.taps.end());
  const int most = *std::max_element(search.taps.begin(), search.taps.end());
  const long p_min = 1 + static_cast<long>(distinct.size()) * fewest;
  if (b.training_records < p_min)
    throw InputError("baseline " + channel,
                     "the calibration data hold " + std::to_string(b.training_records) +
                         " records of " + channel + ", fewer than the FIR's " +
                         std::to_string(p_min) + " coefficients");
  std::vector<std::vector<int>> sets{distinct};
  if (search.front_only && !front.empty() && front.size() < distinct.size()) sets.push_back(front);
  const std::size_t candidates = sets.size() * search.inputs.size() * search.taps.size() *
                                     search.model_taps.size() * search.ridges.size() +
                                 (search.allow_none ? 1 : 0);
  // Each form (wheels, input, taps, ridge) scored by two-fold cross-validation: each half of the
  // training data predicted by the FIR fitted on the other half; the sums of squares from the
  // held half's normal equations, yᵀy − 2 cᵀXᵀy + cᵀXᵀX c. The normal equations are made once per
  // wheels and input at the most taps; a form with fewer taps takes its rows and columns.
  long in_fold[2] = {0, 0};
  for (const auto& r : rows) ++in_fold[r.fold];
  double best = std::numeric_limits<double>::infinity();
  bool chosen_none = false;
  if (candidates > 1 && search.allow_none) {
    double yy[2] = {0, 0};
    for (const auto& r : rows) yy[r.fold] += r.y * r.y;
    best = yy[0] + yy[1];
    b.cv_sse.push_back(best);
    chosen_none = true;
  }
  // Without a score, the fallback: nothing (allow_none), else the first input at the fewest taps
  // from every distinct wheel.
  b.input = search.inputs.front();
  b.corners = distinct;
  b.taps = fewest;
  b.model_taps = search.model_taps.front();
  b.ridge = *std::min_element(search.ridges.begin(), search.ridges.end());
  const auto sub = [](const Normal& n, const std::vector<long>& idx) {
    Normal o;
    const long p = static_cast<long>(idx.size());
    o.xx.resize(p, p);
    o.xy.resize(p);
    o.yy = n.yy;
    for (long i = 0; i < p; ++i) {
      o.xy[i] = n.xy[idx[static_cast<std::size_t>(i)]];
      for (long j = 0; j < p; ++j)
        o.xx(i, j) = n.xx(idx[static_cast<std::size_t>(i)], idx[static_cast<std::size_t>(j)]);
    }
    return o;
  };
  Eigen::VectorXd c;
  for (const auto& set : sets)
    for (const FirInput form : search.inputs) {
      const auto full = normals(rows, inputs, dt_s, most, form, set, models, most_model);
      for (const int taps : search.taps)
        for (const int mt : search.model_taps) {
          std::vector<long> idx{0};
          for (std::size_t i = 0; i < set.size(); ++i)
            for (int j = 0; j < taps; ++j) idx.push_back(1 + static_cast<long>(i) * most + j);
          for (int j = 0; j < mt; ++j) idx.push_back(1 + static_cast<long>(set.size()) * most + j);
          const bool all = taps == most && mt == most_model;
          const std::array<Normal, 2> n =
              all ? full : std::array<Normal, 2>{sub(full[0], idx), sub(full[1], idx)};
          const long p = static_cast<long>(idx.size());
          if (candidates > 1 && in_fold[0] >= p && in_fold[1] >= p)
            for (const double lambda : search.ridges) {
              double sse = 0;
              for (std::size_t f = 0; f < 2; ++f) {
                const Eigen::VectorXd cf = ridgeSolve(n[1 - f].xx, n[1 - f].xy, lambda);
                sse += n[f].yy - 2 * cf.dot(n[f].xy) + cf.dot(n[f].xx * cf);
              }
              b.cv_sse.push_back(sse);
              if (sse < best)
                best = sse, b.input = form, b.corners = set, b.taps = taps, b.model_taps = mt,
                b.ridge = lambda, chosen_none = false;
            }
          if (!chosen_none && b.input == form && b.corners == set && b.taps == taps &&
              b.model_taps == mt && b.training_records >= p)
            c = ridgeSolve(n[0].xx + n[1].xx, n[0].xy + n[1].xy, b.ridge);
        }
    }
  if (chosen_none || (search.allow_none && b.cv_sse.size() <= 1)) {
    b.taps = 0;
    b.model_taps = 0;
    b.corners.clear();
    b.coef = {0.0};
    return b;
  }
  b.coef.assign(c.data(), c.data() + c.size());
  return b;
}

FirBaseline fitFirBaseline(const std::string& channel, const std::vector<const LabData*>& train,
                           const std::vector<const RoadInput*>& inputs, double dt_s, int taps,
                           std::optional<FirInput> input) {
  DTWIN_CHECK(taps > 0, "fitFirBaseline: arguments");
  FirSearch search;
  search.taps = {taps};
  if (input) {  // that input from every distinct wheel, the smallest ridge: nothing to choose
    search.inputs = {*input};
    search.front_only = false;
    search.ridges = {1e-9};
  }
  return fitFir(channel, train, inputs, dt_s, search);
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
