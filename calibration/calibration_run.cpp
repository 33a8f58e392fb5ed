// CalibrationRun's stages 0 to 3 (objective, optimum, region, design) and the stage files' helpers:
// readStage, the MPI packing of the optimiser's starts and the region's sweeps and traces.
#include "calibration/calibrate_internal.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "calibration/lhs.hpp"
#include "common/checksum.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/parallel.hpp"

namespace dtwin::calib {

// ------------------------------------------------------------------ persistence helpers
nlohmann::json readStage(const Distributed* processes, const fs::path& p,
                         const std::string& fingerprint) {
  // The root reads and checks the file; a damaged one is set aside and every rank redoes the stage.
  const std::string text = onRoot(processes, [&]() -> std::string {
    if (!fs::exists(p)) return std::string();
    std::ifstream in(p, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(os.str());
    } catch (const std::exception&) {  // written atomically: damaged on disk, or not ours
      setAsideCorrupt(p.string(), "is not valid JSON");
      return std::string();
    }
    if (checkSeal(j) == Seal::broken) {
      setAsideCorrupt(p.string(), "fails its checksum");
      return std::string();
    }
    return "F" + os.str();
  });
  if (text.empty()) return nullptr;
  nlohmann::json j = nlohmann::json::parse(text.begin() + 1, text.end());
  if (!j.contains("fingerprint") || j["fingerprint"] != fingerprint)
    throw InputError(
        p.string(),
        "was made by a different calibration (study, data, assembly or sizes changed); "
        "use a new output folder or delete it to start over");
  return j;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

namespace {

std::string hex(std::uint64_t v) {
  return formatPrintf("%016llx", static_cast<unsigned long long>(v));
}

std::vector<double> packStart(const StartResult& r) {
  return Packer()
      .put(r.start)
      .put(r.theta)
      .put(r.sse)
      .put(r.evaluations)
      .put(r.nonfinite_evaluations)
      .put(r.status)
      .take();
}
StartResult unpackStart(const std::vector<double>& v) {
  Unpacker u(v);
  StartResult r;
  r.start = u.vec();
  r.theta = u.vec();
  r.sse = u.num();
  r.evaluations = static_cast<int>(u.integer());
  r.nonfinite_evaluations = static_cast<int>(u.integer());
  r.status = u.str();
  return r;
}
std::vector<double> packSweep(const SweepResult& r) {
  return Packer()
      .put(r.parameter)
      .put(r.direction)
      .put(r.edge)
      .put(r.edge_sse)
      .put(r.clipped ? 1.0 : 0.0)
      .put(r.bracketed ? 1.0 : 0.0)
      .put(r.evaluations)
      .put(r.message)
      .take();
}
SweepResult unpackSweep(const std::vector<double>& v) {
  Unpacker u(v);
  SweepResult r;
  r.parameter = static_cast<int>(u.integer());
  r.direction = static_cast<int>(u.integer());
  r.edge = u.num();
  r.edge_sse = u.num();
  r.clipped = u.num() != 0.0;
  r.bracketed = u.num() != 0.0;
  r.evaluations = static_cast<int>(u.integer());
  r.message = u.str();
  return r;
}

std::vector<double> packRay(const RaySweep& r) {
  return Packer()
      .put(r.t_edge)
      .put(r.edge_sse)
      .put(r.clipped ? 1.0 : 0.0)
      .put(r.bracketed ? 1.0 : 0.0)
      .put(r.budget_out ? 1.0 : 0.0)
      .put(r.loose ? 1.0 : 0.0)
      .put(r.bracket)
      .put(r.evaluations)
      .take();
}
RaySweep unpackRay(const std::vector<double>& v) {
  Unpacker u(v);
  RaySweep r;
  r.t_edge = u.num();
  r.edge_sse = u.num();
  r.clipped = u.num() != 0.0;
  r.bracketed = u.num() != 0.0;
  r.budget_out = u.num() != 0.0;
  r.loose = u.num() != 0.0;
  r.bracket = u.num();
  r.evaluations = static_cast<int>(u.integer());
  return r;
}

std::vector<double> packTrace(const RidgeTrace& r) {
  std::vector<double> z, cross;
  for (const auto& p : r.z) z.insert(z.end(), p.data(), p.data() + p.size());
  for (const auto& c : r.cross) {  // d·d values, or one NaN for an unknown cross-section
    if (c.size() == 0)
      cross.push_back(std::numeric_limits<double>::quiet_NaN());
    else
      cross.insert(cross.end(), c.data(), c.data() + c.size());
  }
  return Packer()
      .put(r.axis)
      .put(r.direction)
      .put(r.t)
      .put(z)
      .put(r.sse)
      .put(cross)
      .put(r.closed ? 1.0 : 0.0)
      .put(r.crossing)
      .put(r.clipped ? 1.0 : 0.0)
      .put(r.evaluations)
      .put(r.message)
      .take();
}
RidgeTrace unpackTrace(const std::vector<double>& v, int d) {
  Unpacker u(v);
  RidgeTrace r;
  r.axis = static_cast<int>(u.integer());
  r.direction = static_cast<int>(u.integer());
  r.t = u.vec();
  const std::vector<double> z = u.vec();
  for (std::size_t k = 0; k + static_cast<std::size_t>(d) <= z.size();
       k += static_cast<std::size_t>(d))
    r.z.push_back(Eigen::Map<const Eigen::VectorXd>(z.data() + k, d));
  r.sse = u.vec();
  const std::vector<double> cross = u.vec();
  for (std::size_t k = 0; k < cross.size();) {
    if (std::isnan(cross[k])) {
      r.cross.emplace_back();
      ++k;
      continue;
    }
    r.cross.push_back(Eigen::Map<const Eigen::MatrixXd>(cross.data() + k, d, d));
    k += static_cast<std::size_t>(d * d);
  }
  r.closed = u.num() != 0.0;
  r.crossing = u.num();
  r.clipped = u.num() != 0.0;
  r.evaluations = static_cast<int>(u.integer());
  r.message = u.str();
  return r;
}

}  // namespace

// ------------------------------------------------------------------ CalibrationRun: objective ..
// design
/// The resume fingerprint: everything that changes the numbers.
std::string CalibrationRun::resumeFingerprint() const {
  const LabObjective& objective = *objective_;
  nlohmann::json fp{{"assembly", assembly_.id},
                    {"label", assembly_.label()},
                    {"names", objective.names()},
                    {"lower", objective.lower()},
                    {"upper", objective.upper()},
                    {"scenario", objective.scenario().toJson()},
                    {"simulation", study_.simulation.toJson()},
                    {"options", options_.toJson()},
                    {"data", fingerprint_extra_}};
  // Only the general form adds keys, so a plain calibration keeps its fingerprint.
  if (data_.size() > 1) {
    fp["scenarios"] = nlohmann::json::array();
    for (const auto& sc : objective.scenarios()) fp["scenarios"].push_back(sc.toJson());
  }
  if (!setup_.empty()) fp["setup"] = setup_.toJson();
  for (const auto& ds : data_)
    if (ds.road_seed) fp["road_seeds"].push_back(*ds.road_seed);
  return hex(fnv1a64(fp.dump()));
}

/// Stage 0, objective: the SSE of the assembly against the data sets (LabObjective), the output
/// folder, the result's header and the resume fingerprint. Nothing is persisted.
void CalibrationRun::objective() {
  objective_ = std::make_unique<LabObjective>(study_, assembly_, data_, setup_);
  d_ = objective_->names().size();
  n_ = objective_->dataCount();
  rootWrites(options_.processes, [&] { fs::create_directories(out_dir_); });
  res_.assembly = assembly_.id;
  res_.label = assembly_.label();
  res_.names = objective_->names();
  res_.truth = objective_->truths();
  res_.n_data = n_;
  res_.lower = objective_->lower();
  res_.upper = objective_->upper();
  res_.left_out = objective_->leftOut();
  const ParameterTable table = study_.parameterTable();
  for (const auto& name : res_.names) {
    std::string unit;
    for (const auto& c : study_.calibrated)
      if (c.name == name) unit = c.unit;
    for (const auto& c : setup_.extra_calibrated)
      if (c.name == name) unit = c.unit;
    res_.units.push_back(unit);
    const auto lim = physicalLimit(name, table);
    limit_lower_.push_back(lim ? lim->lower : std::numeric_limits<double>::quiet_NaN());
    limit_upper_.push_back(lim ? lim->upper : std::numeric_limits<double>::quiet_NaN());
    limit_basis_.push_back(lim ? lim->basis : "");
  }
  fingerprint_ = resumeFingerprint();
  sse_ = [this](const std::vector<double>& th) { return objective_->sse(th); };
  if (options_.steps == "frozen") {
    // The screening and the optimiser's starts replay the steps of one reference point: the extra
    // start (e.g. a nested model's optimum) that fits best, or the box centre.
    std::vector<double> ref(d_);
    for (std::size_t k = 0; k < d_; ++k)
      ref[k] = 0.5 * (objective_->lower()[k] + objective_->upper()[k]);
    std::vector<std::vector<double>> extra;
    for (const auto& x : options_.extra_starts)
      if (x.size() == d_) {
        extra.push_back(x);
        for (std::size_t k = 0; k < d_; ++k)
          extra.back()[k] = std::clamp(x[k], objective_->lower()[k], objective_->upper()[k]);
      }
    if (extra.size() == 1) ref = extra[0];
    if (extra.size() > 1) {
      const auto f = distributedMap(
          options_.processes, extra.size(), options_.threads,
          [&](std::size_t i, int) { return std::vector<double>{objective_->sse(extra[i])}; },
          [&](std::size_t done, std::size_t total) { report("optimum: reference", done, total); });
      std::size_t best = 0;
      for (std::size_t i = 1; i < f.size(); ++i)
        if (std::isfinite(f[i][0]) && !(f[i][0] >= f[best][0]))
          best = i;  // a failed run never wins
      ref = extra[best];
    }
    reference_ = ref;
    if (!objective_->freezeSteps(ref))
      res_.warnings.push_back(
          "the integrator's steps could not be frozen at the reference point (its run failed); the "
          "optimiser's "
          "starts chose their steps adaptively");
  }
}

/// The optimiser's starting points: the best screening points (or a plain spread of starts when
/// screening is off), after the options' extra starts. `screening` receives what the screening did.
std::vector<std::vector<double>> CalibrationRun::optimiserStarts(nlohmann::json& screening) const {
  const LabObjective& objective = *objective_;
  std::vector<std::vector<double>> x0;
  if (options_.optimizer.screen_per_start > 0) {
    const auto cand =
        screeningPoints(objective.lower(), objective.upper(), options_.optimizer_starts,
                        options_.optimizer.screen_per_start, options_.seed);
    const auto f = distributedMap(
        options_.processes, cand.size(), options_.threads,
        [&](std::size_t i, int) { return std::vector<double>{objective.sse(cand[i])}; },
        [&](std::size_t done, std::size_t total) { report("optimum: screening", done, total); });
    std::vector<double> fs;
    fs.reserve(f.size());
    for (const auto& v : f) fs.push_back(v[0]);
    x0 = bestStarts(cand, fs, objective.lower(), objective.upper(), options_.optimizer_starts);
    screening = {{"points", cand.size()},
                 {"rule",
                  "the box centre and a Latin hypercube of the bounds; starts = the best, 0.05 "
                  "apart (scaled)"},
                 {"best_sse", jsonNumber(*std::min_element(fs.begin(), fs.end()))}};
  } else {
    x0 = optimizerStarts(objective.lower(), objective.upper(), options_.optimizer_starts,
                         options_.seed);
  }
  report("optimum", 0, static_cast<std::size_t>(options_.optimizer_starts));
  for (std::size_t k = options_.extra_starts.size(); k-- > 0;) {
    auto x = options_.extra_starts[k];
    if (x.size() != d_)
      throw InputError("extra optimiser start", "has " + std::to_string(x.size()) +
                                                    " values, expected " + std::to_string(d_));
    for (std::size_t i = 0; i < d_; ++i)
      x[i] = std::clamp(x[i], objective.lower()[i], objective.upper()[i]);
    x0.insert(x0.begin(), x);
  }
  return x0;
}

/// options.polish_step > 0: one more local run from the best start with that initial step, then
/// Levenberg–Marquardt from the best point so far (polishLeastSquares); both appended to `starts`.
void CalibrationRun::polish(std::vector<StartResult>& starts) const {
  const LabObjective& objective = *objective_;
  const Optimum first = collectOptimum(starts);
  if (!std::isfinite(first.sse)) return;
  OptimizerOptions po = options_.optimizer;
  po.initial_step = options_.polish_step;
  report("optimum: polish", 0, 1);
  starts.push_back(minimiseFrom(sse_, objective.lower(), objective.upper(), first.theta, po));
  const Optimum second = collectOptimum(starts);
  report("optimum: polish", 0, 1);
  starts.push_back(polishLeastSquares(objective, second.theta, {options_.threads, kPolishStep}));
}

/// Steps frozen: the starts ran on the steps of the reference point (objective()). Freezes the
/// steps again at the best start's θ and polishes it by Levenberg–Marquardt on them (appended to
/// the starts); that is the optimum, and the later stages replay the same steps. If the run at
/// the best start fails adaptively, the steps go back to adaptive and the optimum stays.
void CalibrationRun::polishOnOwnSteps() {
  if (!std::isfinite(res_.optimum.sse)) return;
  if (!objective_->freezeSteps(res_.optimum.theta)) {
    objective_->thawSteps();
    res_.warnings.push_back(
        "the integrator's steps could not be frozen at the optimiser's best point (its run "
        "failed); the later "
        "stages chose their steps adaptively");
    return;
  }
  polishFrozen();
  chooseStepAccuracy();
}

/// One Levenberg–Marquardt polish from the optimum on the steps frozen now; it becomes the optimum
/// (only its SSE is on those steps).
void CalibrationRun::polishFrozen() {
  report("optimum: polish on its own steps", 0, 1);
  PolishOptions po;
  po.threads = options_.threads;
  po.h = kPolishStepFrozen;
  po.carried = &polish_jacobian_;
  StartResult lm = polishLeastSquares(*objective_, res_.optimum.theta, po);
  lm.status = "LM_POLISH_FROZEN_STEPS";
  res_.optimum.evaluations += lm.evaluations;
  res_.optimum.starts.push_back(std::move(lm));
  res_.optimum.best_start = static_cast<int>(res_.optimum.starts.size()) - 1;
  res_.optimum.theta = res_.optimum.starts.back().theta;
  res_.optimum.sse = res_.optimum.starts.back().sse;
  report("optimum: polish on its own steps", 1, 1);
}

/// Steps frozen: is the accuracy they were chosen at enough for these data? The integrator's bias
/// moves the optimum by the shift of probeBias (steps h a tenth of the Gauss–Newton half-widths
/// of the polish's Jacobian, as the final check's are of the profile's); the intervals'
/// threshold is c s² (profile.hpp, from the optimum's SSE). While the shift exceeds an eighth of
/// the threshold (so that the final check, with its own probe, stays below a quarter), the steps
/// are chosen again at a tighter accuracy, accuracy × (threshold / 8 / shift)^(2/3), between a
/// tenth and 0.7 of the last, and the optimum polished on them; at most twice. (The shift would go
/// with the tolerance squared if the error were proportional to it; on the demonstration drive it
/// went as the tolerance^1.6, hence the exponent 1/1.5.) When a tighter accuracy does not halve
/// the shift, the shift is not the integrator's: the last accuracy and its optimum are kept. Each
/// try is recorded (steps_log_, optimum.json "steps").
void CalibrationRun::chooseStepAccuracy() {
  const double dof = n_ > static_cast<int>(d_) ? n_ - static_cast<int>(d_) : n_;
  const double t = studentQuantile(0.5 + 0.5 * options_.profile.level, dof);
  // The final check (integratorCheck) probes at a tenth of each interval's half-width; so do these
  // probes, the half-widths from the polish's Jacobian (Gauss–Newton), since the roughness and
  // the shift depend on the probe's step.
  const bool have_j =
      polish_jacobian_.J.rows() == n_ && polish_jacobian_.J.cols() == static_cast<long>(d_);
  const std::vector<double> h =
      have_j ? probeStepsFromJacobian(polish_jacobian_.J, t * t * res_.optimum.sse / dof)
             : std::vector<double>(d_, kPolishStepFrozen);
  double last_shift = 0.0, last_accuracy = 0.0;
  std::vector<double> last_theta;
  Optimum last_optimum;
  for (int round = 0; round < 3; ++round) {
    const double accuracy = objective_->stepsFrozenAccuracy();
    const double threshold = t * t * res_.optimum.sse / dof;
    LabObjective fine = fineObjective(accuracy);
    if (!fine.freezeSteps(res_.optimum.theta)) return;
    const BiasProbe p = probeBias(fine, res_.optimum.theta, h, true, "optimum: integrator bias");
    if (!p.ok) return;
    steps_log_.push_back({{"accuracy", accuracy},
                          {"optimum_shift", jsonNumber(p.shift)},
                          {"threshold", jsonNumber(threshold)},
                          {"roughness", jsonNumber(p.roughness)},
                          {"shift_floor", jsonNumber(p.shift_floor)},
                          {"probe_step", jsonNumbers(h)},
                          {"at", jsonNumbers(res_.optimum.theta)}});
    if (!(p.shift > 4 * p.shift_floor)) {
      // The shift is within what the SSE's roughness lets central differences see (jumps of the
      // model itself, e.g. a tire force that jumps at touch-down between two stage times): no
      // tighter accuracy can be shown to help, so this one stays.
      steps_log_.back()["note"] = "the shift is within the roughness floor: accuracy kept";
      return;
    }
    if (round > 0 && !(p.shift < 0.5 * last_shift)) {
      // Tighter steps did not halve the shift: it is not the integrator's bias but a jump of the
      // model itself (a tire law whose force jumps when a wheel touches down between two samples).
      // Back to the last accuracy and its optimum.
      objective_->freezeSteps(last_theta, last_accuracy);
      res_.optimum = last_optimum;
      steps_log_.back()["kept"] = false;
      return;
    }
    if (!(p.shift > threshold / 8) || round == 2) return;
    last_shift = p.shift;
    last_accuracy = accuracy;
    last_theta = objective_->stepsFrozenAt();
    last_optimum = res_.optimum;
    const double tighter =
        accuracy * std::clamp(std::pow(threshold / 8 / p.shift, 2.0 / 3.0), 0.1, 0.7);
    if (!objective_->freezeSteps(res_.optimum.theta, tighter)) {
      objective_->freezeSteps(res_.optimum.theta, accuracy);
      return;
    }
    polishFrozen();
  }
}

/// How the objective chose its steps, for optimum.json (the θ they are frozen at, to resume).
nlohmann::json CalibrationRun::stepsJson() const {
  nlohmann::json j{{"mode", options_.steps}, {"frozen", objective_->stepsFrozen()}};
  if (objective_->stepsFrozen()) {
    j["frozen_at"] = jsonNumbers(objective_->stepsFrozenAt());
    j["accuracy"] = objective_->stepsFrozenAccuracy();
    j["steps_per_data_set"] = objective_->frozenStepCounts();
    j["accuracy_choice"] = steps_log_;
  }
  if (!reference_.empty()) j["starts_frozen_at"] = jsonNumbers(reference_);
  return j;
}

/// Stage 1, optimum (optimum.json): as minimiseSse, with the screening and the starts spread over
/// ranks and threads, then the optional polish. Throws when every simulation of it failed.
void CalibrationRun::optimum() {
  const auto t0 = Clock::now();
  const fs::path opt_path = file("optimum.json");
  if (auto j = readStage(options_.processes, opt_path, fingerprint_); !j.is_null()) {
    res_.optimum = optimumFrom(j.at("optimum"));
    // The later stages replay the steps the optimum's polish was made on: frozen again at the same
    // θ.
    if (options_.steps == "frozen") {
      if (j.contains("steps") && j.at("steps").value("frozen", false)) {
        objective_->freezeSteps(numbersFromJson(j.at("steps").at("frozen_at")),
                                j.at("steps").value("accuracy", 0.0));
        // The tries, whose last probe the integrator check may take over (integratorCheck).
        if (j.at("steps").contains("accuracy_choice"))
          steps_log_ = j.at("steps").at("accuracy_choice");
      } else {
        objective_->thawSteps();
      }
    }
  } else {
    nlohmann::json screening;
    const std::vector<std::vector<double>> x0 = optimiserStarts(screening);
    const LabObjective& objective = *objective_;
    // Frozen steps: the SSE is a smooth sum of squares, so each start is a Levenberg–Marquardt run
    // (one thread each; the starts share the workers) on forward differences (the polish on the
    // best start's own steps settles it with central ones), stopped when a step gains less than a
    // thousandth of the intervals' threshold c s² ≈ 4 SSE / (n − d).
    const bool lm = objective.stepsFrozen();
    const double dof = n_ > static_cast<int>(d_) ? n_ - static_cast<int>(d_) : std::max(n_, 1);
    const auto packed = distributedMap(
        options_.processes, x0.size(), options_.threads,
        [&](std::size_t i, int) {
          if (!lm)
            return packStart(minimiseFrom(sse_, objective.lower(), objective.upper(), x0[i],
                                          options_.optimizer));
          PolishOptions po;
          po.h = kPolishStepFrozen;
          po.rel_gain = 4e-3 / dof;
          po.forward = true;
          StartResult r = polishLeastSquares(objective, x0[i], po);
          r.status = "LM";
          return packStart(r);
        },
        [&](std::size_t done, std::size_t total) { report("optimum", done, total); });
    std::vector<StartResult> starts;
    starts.reserve(packed.size());
    for (const auto& v : packed) starts.push_back(unpackStart(v));
    // With frozen steps the starts are least-squares runs already and polishOnOwnSteps polishes
    // the best on its own steps: the derivative-free polish would add nothing.
    if (options_.polish_step > 0 && !lm) polish(starts);
    res_.optimum = collectOptimum(std::move(starts));
    if (options_.steps == "frozen") polishOnOwnSteps();
    rootWrites(options_.processes, [&] {
      nlohmann::json stage{{"fingerprint", fingerprint_},
                           {"optimum", optimumJson(res_.optimum)},
                           {"steps", stepsJson()}};
      if (!screening.is_null()) stage["screening"] = screening;
      writeFileAtomic(opt_path.string(), sealJson(stage).dump(2) + "\n");
    });
  }
  if (!std::isfinite(res_.optimum.sse))
    throw std::runtime_error("assembly " + assembly_.id +
                             ": every simulation of the optimiser failed; no calibration possible");
  res_.stage_wall_s.push_back({"optimum", secondsSince(t0)});
}

/// The problem the region's sweeps share: the optimum, n and the bounds.
BoxProblem CalibrationRun::boxProblem() const {
  BoxProblem bp;
  bp.theta_hat = res_.optimum.theta;
  bp.sse_min = res_.optimum.sse;
  bp.n_data = n_;
  bp.lower = objective_->lower();
  bp.upper = objective_->upper();
  bp.validate();
  return bp;
}

/// The paper's box (region = "paper"): as calcFeasibleBox, with the 2d sweeps spread over ranks
/// and threads. Sets res_.box and res_.region; `stage` receives the box.
void CalibrationRun::paperBox(const BoxProblem& bp, nlohmann::json& stage) {
  const auto packed = distributedMap(
      options_.processes, 2 * d_, options_.threads,
      [&](std::size_t i, int) {
        return packSweep(calcBoxSweep(sse_, bp, static_cast<int>(i), options_.box));
      },
      [&](std::size_t done, std::size_t total) { report("box", done, total); });
  std::vector<SweepResult> sweeps;
  sweeps.reserve(packed.size());
  for (const auto& v : packed) sweeps.push_back(unpackSweep(v));
  res_.box = collectFeasibleBox(bp, std::move(sweeps));
  res_.region = regionFromBox(res_.box, bp);
  stage["box"] = boxJson(res_.box);
}

/// The joint region (region = "joint"): as calcJointRegion, the Jacobian stencil, then the sweeps
/// along the principal axes, then the ridge traces, each spread over ranks and threads. Sets
/// res_.region; `stage` receives the Gauss–Newton model, the sweeps and the traces.
void CalibrationRun::jointRegion(const BoxProblem& bp, nlohmann::json& stage) {
  const LabObjective& objective = *objective_;
  const auto stencil = jacobianStencil(bp, options_.joint);
  const auto residuals = distributedMap(
      options_.processes, stencil.size(), options_.threads,
      [&](std::size_t i, int) { return objective.residuals(stencil[i]); },
      [&](std::size_t done, std::size_t total) { report("region: Jacobian", done, total); });
  const JointRegionPlan plan = planJointRegion(bp, residuals, options_.joint);
  const auto packed = distributedMap(
      options_.processes, 2 * d_, options_.threads,
      [&](std::size_t i, int) {
        return packRay(calcRegionSweep(sse_, plan, static_cast<int>(i), options_.joint));
      },
      [&](std::size_t done, std::size_t total) { report("region: sweeps", done, total); });
  std::vector<RaySweep> sweeps;
  sweeps.reserve(packed.size());
  for (const auto& v : packed) sweeps.push_back(unpackRay(v));
  // A smooth SSE (frozen steps): forward differences are enough for the traces' Jacobians.
  JointRegionOptions traceOptions = options_.joint;
  traceOptions.forward_differences = objective.stepsFrozen();
  stage["ridge_differences"] = traceOptions.forward_differences ? "forward" : "central";
  const auto packed_traces = distributedMap(
      options_.processes, 2 * ridgeAxes(plan, options_.joint).size(), options_.threads,
      [&](std::size_t i, int) {
        return packTrace(
            calcRidgeTrace([&](const std::vector<double>& th) { return objective.residuals(th); },
                           plan, sweeps, static_cast<int>(i), traceOptions));
      },
      [&](std::size_t done, std::size_t total) { report("region: ridges", done, total); });
  std::vector<RidgeTrace> traces;
  traces.reserve(packed_traces.size());
  for (const auto& v : packed_traces) traces.push_back(unpackTrace(v, static_cast<int>(d_)));
  res_.region = collectJointRegion(plan, sweeps, traces, options_.joint);
  stage["gauss_newton"] = gaussNewtonJson(plan, sweeps, traces);
}

/// Stage 2, region (box.json): the region the design covers, the joint 1 % contour or the
/// paper's box.
void CalibrationRun::region() {
  const auto t0 = Clock::now();
  const fs::path box_path = file("box.json");
  if (auto j = readStage(options_.processes, box_path, fingerprint_); !j.is_null()) {
    res_.region = Region::fromJson(j.at("region"));
    if (j.contains("box")) res_.box = boxFrom(j.at("box"));
  } else {
    const BoxProblem bp = boxProblem();
    nlohmann::json stage{{"fingerprint", fingerprint_}};
    if (options_.region == "paper")
      paperBox(bp, stage);
    else
      jointRegion(bp, stage);
    stage["region"] = res_.region.toJson();
    rootWrites(options_.processes,
               [&] { writeFileAtomic(box_path.string(), sealJson(stage).dump(2) + "\n"); });
  }
  res_.stage_wall_s.push_back({"region", secondsSince(t0)});
}

/// Opens the design journal on the root (`journal`, null on the other ranks) and returns the
/// points it holds, which every rank learns from the root.
CalibrationRun::ResumedPoints CalibrationRun::openJournal(
    const std::string& journal_path, std::unique_ptr<DesignJournal>& journal) const {
  const std::size_t d = d_;
  const std::vector<double> resumed_flat =
      bytesToDoubles(onRoot(options_.processes, [&]() -> std::string {
        journal = std::make_unique<DesignJournal>(journal_path, static_cast<int>(d), fingerprint_);
        std::vector<double> v;
        for (const auto& e : journal->resumed()) {
          if (e.index < 0)
            throw InputError(journal->path(),
                             "design index " + std::to_string(e.index) + " is negative");
          v.push_back(static_cast<double>(e.index));
          v.insert(v.end(), e.theta.begin(), e.theta.end());
          v.push_back(e.sse);
        }
        return doublesToBytes(v);
      }));
  ResumedPoints resumed;
  for (std::size_t k = 0; k + d + 2 <= resumed_flat.size(); k += d + 2)
    resumed[static_cast<long>(resumed_flat[k])] = {
        std::vector<double>(resumed_flat.begin() + static_cast<long>(k) + 1,
                            resumed_flat.begin() + static_cast<long>(k + 1 + d)),
        resumed_flat[k + 1 + d]};
  return resumed;
}

/// The SSEs of one round's points `pts` (design rows first ..): those in `resumed` from there
/// (each checked against the point and taken out of `resumed`), the others simulated and
/// journalled. One process: one loop, each point journalled as it finishes. Several ranks: chunks
/// of 8 points per worker; the root journals its own points as they finish and the others' at the
/// end of each chunk (a killed job loses at most one chunk of them).
std::vector<double> CalibrationRun::evaluateRound(const Eigen::MatrixXd& pts, int first,
                                                  const std::string& stage, DesignJournal* journal,
                                                  const std::string& journal_path,
                                                  ResumedPoints& resumed) {
  const std::size_t d = d_;
  const std::size_t ranks = static_cast<std::size_t>(processCount(options_.processes));
  const std::size_t m_all = static_cast<std::size_t>(pts.rows());
  std::vector<double> out(m_all, std::numeric_limits<double>::quiet_NaN());
  auto point = [&](std::size_t t) {
    std::vector<double> th(d);
    for (std::size_t k = 0; k < d; ++k) th[k] = pts(static_cast<long>(t), static_cast<long>(k));
    return th;
  };
  std::vector<std::size_t> todo;
  for (std::size_t t = 0; t < m_all; ++t) {
    const long idx = first + static_cast<long>(t);
    const auto it = resumed.find(idx);
    if (it == resumed.end()) {
      todo.push_back(t);
      continue;
    }
    if (it->second.first != point(t))
      throw InputError(journal_path, "design point " + std::to_string(idx) +
                                         " differs from this calibration's design");
    out[t] = it->second.second;
    ++res_.resumed_points;
    resumed.erase(it);
  }
  report(stage, m_all - todo.size(), m_all);
  const std::size_t chunk = ranks == 1
                                ? std::max<std::size_t>(todo.size(), 1)
                                : 8 * ranks *
                                      static_cast<std::size_t>(distributedWorkers(
                                          options_.processes, todo.size(), options_.threads));
  for (std::size_t c0 = 0; c0 < todo.size(); c0 += chunk) {
    const std::size_t m = std::min(chunk, todo.size() - c0);
    const auto sse_of = distributedMap(
        options_.processes, m, options_.threads,
        [&](std::size_t t, int) {
          const std::size_t row = todo[c0 + t];
          const auto th = point(row);
          const double s = objective_->sse(th);
          if (journal)
            journal->append(first + static_cast<long>(row), th,
                            s);  // the root's own points, at once
          return std::vector<double>{s};
        },
        [&](std::size_t done, std::size_t) {
          report(stage, m_all - todo.size() + c0 + done, m_all);
        });
    for (std::size_t t = 0; t < m; ++t) out[todo[c0 + t]] = sse_of[t][0];
    if (ranks > 1)
      rootWrites(options_.processes, [&] {
        for (std::size_t t = 0; t < m; ++t)
          if (t % ranks != 0)
            journal->append(first + static_cast<long>(todo[c0 + t]), point(todo[c0 + t]),
                            sse_of[t][0]);
      });
  }
  return out;
}

/// design.csv: every design point with its SSE, round and log design weight.
void CalibrationRun::writeDesignTable() const {
  std::vector<double> round_of(res_.sse.size());
  for (const auto& r : res_.rounds.rounds)
    for (int i = r.first; i < r.first + r.count; ++i)
      round_of[static_cast<std::size_t>(i)] = r.index;
  rootWrites(options_.processes, [&] {
    writeDesignTableCsv(file("design.csv").string(), res_.names, res_.design, res_.sse, "sse",
                        {{"round", round_of}, {"log_design_weight", res_.rounds.log_weight}});
  });
}

/// Stage 3, design (design_journal.csv, design.csv): runAdaptiveDesign, round by round, each
/// point journalled as it finishes; a rerun takes the journalled points from the journal.
void CalibrationRun::design() {
  const auto t0 = Clock::now();
  {
    // The journal lives on the root; every rank learns the journalled points from it.
    const std::string journal_path = file("design_journal.csv").string();
    std::unique_ptr<DesignJournal> journal;
    ResumedPoints resumed = openJournal(journal_path, journal);
    int round_no = 0;
    const DesignEvaluator evaluate = [&](const Eigen::MatrixXd& pts, int first) {
      return evaluateRound(pts, first, "design round " + std::to_string(round_no++), journal.get(),
                           journal_path, resumed);
    };
    res_.rounds = runAdaptiveDesign(res_.region, n_, options_.designOptions(), evaluate);
    if (!resumed.empty())
      throw InputError(journal_path, "holds design point " +
                                         std::to_string(resumed.begin()->first) +
                                         ", which this calibration's design does not have (made by "
                                         "another version?); delete it to start over");
  }
  res_.design = res_.rounds.points;
  res_.sse = res_.rounds.sse;
  for (double s : res_.sse) res_.design_failures += std::isfinite(s) ? 0 : 1;
  writeDesignTable();
  res_.stage_wall_s.push_back({"design", secondsSince(t0)});
}

}  // namespace dtwin::calib
