// CalibrationRun's stages 4 to 7: the profile intervals (with the residuals' time correlation), the
// Griddy Gibbs sampler, the integrator check and the summary.
#include "calibration/calibrate_internal.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>

#include "calibration/folder.hpp"
#include "common/checksum.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/parallel.hpp"
#include "io/provenance.hpp"

namespace dtwin::calib {

namespace {

std::vector<double> packProfileEnd(const ProfileEnd& e) {
  return Packer()
      .put(e.theta)
      .put(e.sse)
      .put(e.at_bound ? 1.0 : 0.0)
      .put(e.evaluations)
      .put(e.steps_taken)
      .put(e.jacobians)
      .put(e.outside_points)
      .take();
}
ProfileEnd unpackProfileEnd(const std::vector<double>& v) {
  Unpacker u(v);
  ProfileEnd e;
  e.theta = u.vec();
  e.sse = u.num();
  e.at_bound = u.num() != 0.0;
  e.evaluations = static_cast<int>(u.integer());
  e.steps_taken = static_cast<int>(u.integer());
  e.jacobians = static_cast<int>(u.integer());
  e.outside_points = static_cast<int>(u.integer());
  return e;
}

}  // namespace

// ------------------------------------------------------------------ CalibrationRun: profile ..
// summary
/// Every evaluated point the profile starts from: the design, the optimum, the ridge floor
/// (rows of `pts`, physical units) and their SSEs `f`.
void CalibrationRun::evaluatedPoints(Eigen::MatrixXd& pts, std::vector<double>& f) const {
  const std::size_t d = d_;
  const long extra = 1 + res_.region.ridge.rows();
  pts.resize(res_.design.rows() + extra, static_cast<long>(d));
  f = res_.sse;
  pts.topRows(res_.design.rows()) = res_.design;
  for (std::size_t k = 0; k < d; ++k)
    pts(res_.design.rows(), static_cast<long>(k)) = res_.optimum.theta[k];
  f.push_back(res_.optimum.sse);
  for (Eigen::Index q = 0; q < res_.region.ridge.rows(); ++q) {
    const auto th = res_.region.toPhysical(res_.region.ridge.row(q).transpose());
    for (std::size_t k = 0; k < d; ++k)
      pts(res_.design.rows() + 1 + q, static_cast<long>(k)) = th[k];
    f.push_back(res_.region.ridge_sse[static_cast<std::size_t>(q)]);
  }
}

/// The optimiser's start ends other than the optimum, with their SSEs on the steps the later stages
/// replay, appended to the evaluated points: a second basin that the data cannot tell from the
/// optimum's lies inside the threshold, and the profile's intervals must span it (the design,
/// drawn around the optimum, never sees it).
void CalibrationRun::appendStartEnds(Eigen::MatrixXd& pts, std::vector<double>& f) const {
  std::vector<std::vector<double>> ends;
  for (const auto& st : res_.optimum.starts)
    if (st.theta.size() == d_ && std::isfinite(st.sse) && st.theta != res_.optimum.theta)
      ends.push_back(st.theta);
  if (ends.empty()) return;
  const auto out = distributedMap(
      options_.processes, ends.size(), options_.threads,
      [&](std::size_t i, int) { return std::vector<double>{objective_->sse(ends[i])}; },
      [&](std::size_t done, std::size_t total) { report("profile: optimiser ends", done, total); });
  const Eigen::Index r0 = pts.rows();
  pts.conservativeResize(r0 + static_cast<Eigen::Index>(ends.size()), Eigen::NoChange);
  for (std::size_t i = 0; i < ends.size(); ++i) {
    for (std::size_t k = 0; k < d_; ++k)
      pts(r0 + static_cast<Eigen::Index>(i), static_cast<long>(k)) = ends[i][k];
    f.push_back(out[i][0]);
  }
}

/// The warning for the other basins profile() found (profile.json "other_basins").
void CalibrationRun::warnOtherBasins(const nlohmann::json& basins) {
  if (!basins.is_array() || basins.empty()) return;
  std::string where;
  for (std::size_t k = 0; k < d_ && k < basins[0].at("theta").size(); ++k)
    where += (k ? ", " : "") + res_.names[k] + " = " +
             formatNumber(basins[0].at("theta")[k].get<double>(), 4);
  res_.warnings.push_back(
      std::to_string(basins.size()) +
      " optimiser start(s) ended in another basin that the data cannot reject (e.g. " + where +
      "): the 95 % profile intervals span it and the optimum's basin; the posterior and the design "
      "see only the optimum's");
}

CorrelationAdjustment CalibrationRun::timeCorrelation() {
  const LabObjective& objective = *objective_;
  const std::vector<int> blocks =
      timeBlocks(objective.times(), objective.dataSetOf(), objective.repetitions());
  if (blocks.empty() || blocks.front() < 0) return {};
  // The weighted residuals' Jacobian at the optimum: forward differences in scaled units, each
  // step towards the inside of the bounds (κ does not depend on the parameters' scales).
  const std::vector<double>& theta = res_.optimum.theta;
  const double h = objective.stepsFrozen() ? kPolishStepFrozen : kPolishStep;
  const auto scaled_step = [&](std::size_t j) {  // h, or −h where +h would leave the bounds
    return theta[j] + h * (objective.upper()[j] - objective.lower()[j]) <= objective.upper()[j]
               ? h
               : -h;
  };
  const auto runs = distributedMap(
      options_.processes, d_ + 1, options_.threads,
      [&](std::size_t k, int) {
        std::vector<double> th = theta;
        if (k > 0)
          th[k - 1] += scaled_step(k - 1) * (objective.upper()[k - 1] - objective.lower()[k - 1]);
        return objective.residuals(th);
      },
      [&](std::size_t done, std::size_t total) {
        report("profile: residual correlation", done, total);
      });
  const auto n = static_cast<Eigen::Index>(runs[0].size());
  if (n != n_) return {};
  const Eigen::Map<const Eigen::VectorXd> r0(runs[0].data(), n);
  Eigen::MatrixXd J(n, static_cast<Eigen::Index>(d_));
  for (std::size_t j = 0; j < d_; ++j) {
    if (static_cast<Eigen::Index>(runs[j + 1].size()) != n) return {};
    J.col(static_cast<Eigen::Index>(j)) =
        (Eigen::Map<const Eigen::VectorXd>(runs[j + 1].data(), n) - r0) / scaled_step(j);
  }
  const double s2 = res_.optimum.sse /
                    static_cast<double>(n_ > static_cast<int>(d_) ? n_ - static_cast<int>(d_) : n_);
  return blockAdjustment(J, r0, blocks, s2, options_.profile.level);
}

/// Stage 4, profile (profile.json): the profile-likelihood intervals, from every evaluated point
/// (the design, the ridge floor, the optimum), each end pushed out by profile steps.
void CalibrationRun::profile() {
  const auto t0 = Clock::now();
  res_.interval = options_.interval;
  const fs::path profile_path = file("profile.json");
  nlohmann::json basins;
  if (auto j = readStage(options_.processes, profile_path, fingerprint_); !j.is_null()) {
    res_.profile = ProfileIntervals::fromJson(j.at("profile"));
    basins = j.value("other_basins", nlohmann::json::array());
  } else {
    Eigen::MatrixXd pts;
    std::vector<double> f;
    evaluatedPoints(pts, f);
    const Eigen::Index first_end = pts.rows();
    appendStartEnds(pts, f);
    const LabObjective& objective = *objective_;
    const ProfilePlan plan = planProfile(pts, f, n_, objective.lower(), objective.upper(),
                                         options_.profile, timeCorrelation());
    // An optimiser start that ended in another basin the data cannot reject (inside the threshold,
    // a parameter more than a tenth of its range from the optimum): the intervals span both.
    basins = nlohmann::json::array();
    for (Eigen::Index q = first_end; q < pts.rows(); ++q) {
      if (!(f[static_cast<std::size_t>(q)] <=
            *std::max_element(plan.thresholds.begin(), plan.thresholds.end())))
        continue;
      bool far = false;
      for (std::size_t k = 0; k < d_; ++k)
        far = far || std::abs(pts(q, static_cast<long>(k)) - res_.optimum.theta[k]) >
                         0.1 * (objective.upper()[k] - objective.lower()[k]);
      if (far) {
        std::vector<double> th(d_);
        for (std::size_t k = 0; k < d_; ++k) th[k] = pts(q, static_cast<long>(k));
        basins.push_back(
            {{"theta", jsonNumbers(th)}, {"sse", jsonNumber(f[static_cast<std::size_t>(q)])}});
      }
    }
    // A smooth SSE (frozen steps): forward differences are enough for the profile points'
    // Jacobians.
    ProfileOptions po = options_.profile;
    po.forward_differences = objective.stepsFrozen();
    const auto packed = distributedMap(
        options_.processes, 2 * d_, options_.threads,
        [&](std::size_t i, int) {
          return packProfileEnd(refineProfileEnd(
              [&](const std::vector<double>& th) { return objective.residuals(th); }, plan,
              static_cast<int>(i), po));
        },
        [&](std::size_t done, std::size_t total) { report("profile", done, total); });
    std::vector<ProfileEnd> ends;
    ends.reserve(packed.size());
    for (const auto& v : packed) ends.push_back(unpackProfileEnd(v));
    res_.profile = collectProfile(plan, ends, options_.profile);
    rootWrites(options_.processes, [&] {
      writeFileAtomic(profile_path.string(),
                      sealJson({{"fingerprint", fingerprint_},
                                {"profile", res_.profile.toJson()},
                                {"differences", po.forward_differences ? "forward" : "central"},
                                {"other_basins", basins}})
                              .dump(2) +
                          "\n");
    });
  }
  warnOtherBasins(basins);
  // A point the later stages evaluated (the ridge floor, the design, another start's end) below
  // the optimiser's optimum: the intervals are drawn about it (its SSE is sse_best), so it is the
  // calibration's optimum from here on (the integrator check, the summary, the comparisons).
  if (res_.profile.best_point.size() == d_ && res_.profile.sse_best < res_.optimum.sse) {
    res_.warnings.push_back(
        "an evaluated point has a lower SSE (" + formatNumber(res_.profile.sse_best, 6) +
        ") than the optimiser's optimum (" + formatNumber(res_.optimum.sse, 6) +
        "): it is the optimum from the profile on (optimum.json keeps the optimiser's)");
    res_.optimum.theta = res_.profile.best_point;
    res_.optimum.sse = res_.profile.sse_best;
  }
  res_.stage_wall_s.push_back({"profile", secondsSince(t0)});
}

/// posterior.csv: θ, τ and the design index of every kept Gibbs iteration.
void CalibrationRun::writePosterior() {
  std::vector<std::vector<double>> rows;
  std::vector<long> index;
  for (std::size_t t = 0; t < res_.chains.index.size(); ++t) {
    const int k = res_.chains.index[t];
    std::vector<double> row(d_);
    for (std::size_t c = 0; c < d_; ++c) row[c] = res_.design(k, static_cast<long>(c));
    rows.push_back(std::move(row));
    index.push_back(k);
  }
  const std::string text = posteriorCsv(res_.names, rows, res_.chains.tau, index);
  posterior_checksum_ =
      contentChecksum(text);  // summary.json records it: a reader refuses a changed file
  rootWrites(options_.processes, [&] { writeFileAtomic(file("posterior.csv").string(), text); });
}

/// Stage 5, sampler (posterior.csv): the two-block Griddy Gibbs with the design weights and the
/// posterior summaries. Cheap and deterministic from the seed: never persisted half-way, always
/// rerun.
void CalibrationRun::sampler() {
  const auto t0 = Clock::now();
  report("gibbs", 0, 1);
  res_.chains = runGriddyGibbs(res_.sse, n_, options_.gibbsOptions(), res_.rounds.log_weight);
  res_.posterior = summarisePosterior(res_.design, res_.chains, res_.names);
  report("gibbs", 1, 1);
  writePosterior();
  res_.stage_wall_s.push_back({"gibbs", secondsSince(t0)});
}

/// Stage 6, the integrator check (IntegratorCheck): two simulations at the optimum, one at a tenth
/// of the accuracy the steps were chosen at; with frozen steps, the probes of probeBias along
/// every axis as well. Deterministic: never persisted, always rerun.
void CalibrationRun::integratorCheck() {
  const auto t0 = Clock::now();
  const double threshold = res_.profile.threshold - res_.profile.sse_best;
  const std::vector<double>& theta = res_.optimum.theta;
  if (!std::isfinite(res_.optimum.sse) || theta.size() != d_) return;
  const double accuracy =
      objective_->stepsFrozen() ? objective_->stepsFrozenAccuracy() : study_.simulation.accuracy;
  report("integrator check", 0, 1);
  LabObjective fine = fineObjective(accuracy);
  const std::vector<double> eta = objective_->predict(theta), eta_fine = fine.predict(theta);
  report("integrator check", 1, 1);
  if (eta.empty() || eta_fine.empty()) return;  // a failed run: no check (ok, zero figures)
  res_.integrator = assessIntegrator(eta, eta_fine, objective_->measured(), objective_->weights(),
                                     accuracy, threshold);
  if (objective_->stepsFrozen() && fine.freezeSteps(theta)) {
    // Probe steps: a tenth of each profile half-width, in [1e-4, 1e-2] of the bounds' range.
    std::vector<double> h(d_);
    for (std::size_t k = 0; k < d_; ++k) {
      const double range = objective_->upper()[k] - objective_->lower()[k];
      const double half = k < res_.profile.lower.size() &&
                                  std::isfinite(res_.profile.upper[k] - res_.profile.lower[k])
                              ? 0.5 * (res_.profile.upper[k] - res_.profile.lower[k]) / range
                              : 1e-1;
      h[k] = std::clamp(half / 10, 1e-4, 1e-2);
    }
    if (const auto taken = steps_log_.is_array() && !steps_log_.empty()
                               ? takeOverProbe(steps_log_.back(), theta, h, accuracy,
                                               objective_->lower(), objective_->upper())
                               : std::nullopt) {
      applyProbes(res_.integrator, taken->roughness, taken->optimum_shift, taken->shift_floor);
      res_.integrator.probes = "step choice";
    } else {
      const BiasProbe p = probeBias(fine, theta, h, true, "integrator check: probes");
      if (p.ok) applyProbes(res_.integrator, p.roughness, p.shift, p.shift_floor);
    }
  }
  res_.stage_wall_s.push_back({"integrator check", secondsSince(t0)});
}

/// The objective of the study with adaptive steps at `accuracy` / 10: the integrator check's
/// reference.
LabObjective CalibrationRun::fineObjective(double accuracy) const {
  Study tight = study_;
  tight.simulation.accuracy = accuracy / 10;
  return LabObjective(tight, assembly_, data_, setup_);
}

/// The integrator's bias at θ on frozen steps (IntegratorCheck): along each parameter's axis k,
/// frozen-step runs of the objective at offsets −2..2 (`five`) or −1, +1 times h_k (scaled units;
/// the points moved inside the bounds) and runs of `fine` (steps frozen at a tenth of the accuracy)
/// at −1 and +1. The roughness is the largest departure of an axis's five SSEs from their
/// quadratic (NaN with three points); the residuals' Jacobian and the gradient of SSE − SSE_fine
/// come from the runs at ±1 by central differences, and give the shift (integratorOptimumShift).
CalibrationRun::BiasProbe CalibrationRun::probeBias(const LabObjective& fine,
                                                    const std::vector<double>& theta,
                                                    const std::vector<double>& h, bool five,
                                                    const std::string& stage) const {
  const std::size_t d = d_;
  const auto& lo = objective_->lower();
  const auto& up = objective_->upper();
  const int reach = five ? 2 : 1;
  std::vector<int> offsets;
  for (int o = -reach; o <= reach; ++o)
    if (o != 0 || five) offsets.push_back(o);
  const std::size_t frozen = offsets.size(), per = frozen + 2;  // then -1 and +1 on `fine`
  std::vector<double> centre(d);
  for (std::size_t k = 0; k < d; ++k)
    centre[k] = std::clamp((theta[k] - lo[k]) / (up[k] - lo[k]), reach * h[k], 1 - reach * h[k]);
  auto point = [&](std::size_t k, int offset) {
    std::vector<double> th(d);
    for (std::size_t j = 0; j < d; ++j)
      th[j] = lo[j] + (j == k ? centre[j] + offset * h[j] : centre[j]) * (up[j] - lo[j]);
    return th;
  };
  const auto out = distributedMap(
      options_.processes, per * d, options_.threads,
      [&](std::size_t t, int) -> std::vector<double> {
        const std::size_t k = t / per, which = t % per;
        if (which < frozen) return objective_->residuals(point(k, offsets[which]));
        return {fine.sse(point(k, which == frozen ? -1 : 1))};
      },
      [&](std::size_t done, std::size_t total) { report(stage, done, total); });
  BiasProbe p;
  Eigen::MatrixXd J(n_, static_cast<long>(d));
  Eigen::VectorXd g(static_cast<long>(d)), g_floor = Eigen::VectorXd::Zero(static_cast<long>(d));
  p.roughness = five ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < d; ++k) {
    std::vector<double> x, f;
    const Eigen::VectorXd* rm = nullptr;
    const Eigen::VectorXd* rp = nullptr;
    std::vector<Eigen::VectorXd> r(frozen);
    for (std::size_t o = 0; o < frozen; ++o) {
      const auto& v = out[k * per + o];
      if (v.size() != static_cast<std::size_t>(n_))
        return p;  // a failed run: no figures (p.ok false)
      r[o] = Eigen::Map<const Eigen::VectorXd>(v.data(), n_);
      x.push_back(offsets[o]);
      f.push_back(r[o].squaredNorm());
      if (offsets[o] == -1) rm = &r[o];
      if (offsets[o] == 1) rp = &r[o];
    }
    const double fine_minus = out[k * per + frozen][0], fine_plus = out[k * per + frozen + 1][0];
    if (!std::isfinite(fine_minus) || !std::isfinite(fine_plus)) return p;
    if (five) {
      const double r_k = quadraticRoughness(x, f);
      p.roughness = std::max(p.roughness, r_k);
      g_floor[static_cast<long>(k)] = r_k / h[k];
    }
    J.col(static_cast<long>(k)) = (*rp - *rm) / (2 * h[k]);
    g[static_cast<long>(k)] =
        ((rp->squaredNorm() - rm->squaredNorm()) - (fine_plus - fine_minus)) / (2 * h[k]);
  }
  p.shift = integratorOptimumShift(J, g);
  p.shift_floor = integratorOptimumShift(J, g_floor);
  p.ok = true;
  return p;
}

/// Stage 7, summary (summary.json): the result (CalibrationResult::toJson) with how it was made:
/// program, command, study, data sets, setup and options.
void CalibrationRun::summary() {
  res_.stage_wall_s.push_back({"total", secondsSince(t_all_)});
  res_.median_run_wall_s = objective_->medianWallSeconds();
  findBoundFindings();

  nlohmann::json j = res_.toJson();
  stampProvenance(j, options_.command);
  j["study"] = study_.path;
  j["scenario"] = data_.front().scenario;
  std::size_t records = 0;
  for (const auto& ds : data_) records += ds.data.records.size();
  j["data"] = {{"path", options_.data_path}, {"records", records}, {"fnv1a64", fingerprint_extra_}};
  j["data_sets"] = nlohmann::json::array();
  for (const auto& ds : data_)
    j["data_sets"].push_back({{"name", ds.name},
                              {"scenario", ds.scenario},
                              {"records", ds.data.records.size()},
                              {"road_seed", ds.road_seed ? nlohmann::json(*ds.road_seed)
                                                         : nlohmann::json(study_.seed)}});
  j["setup"] = setup_.toJson();
  j["options"] = options_.toJson();
  j["threads"] = options_.threads;
  if (!posterior_checksum_.empty()) j["posterior_checksum"] = posterior_checksum_;
  rootWrites(options_.processes,
             [&] { writeFileAtomic(file("summary.json").string(), j.dump(2) + "\n"); });
}

}  // namespace dtwin::calib
