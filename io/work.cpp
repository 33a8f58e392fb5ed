#include "io/work.hpp"

#include <algorithm>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace dtwin {
namespace {

// Upper estimates of the calibration's evaluations beyond its design (calibration/calibrate.hpp):
// the multi-start optimiser and the profile search (12 points per end, restarts) at their budgets.
constexpr double kOptimizerEvaluationsPerStart = 500;
constexpr double kProfileEvaluationsPerParameter = 2 * 12 * 100;

double duration(const Study& s, const std::string& scenario) {
  for (const auto& sc : s.scenarios)
    if (sc.name == scenario) return sc.duration_s;
  return 0.0;
}

}  // namespace

double calibrationSimulations(double design_points, double optimizer_starts, double parameters) {
  return design_points + optimizer_starts * kOptimizerEvaluationsPerStart +
         parameters * kProfileEvaluationsPerParameter;
}

double dataSpan(const LabData& data) {
  double t = 0.0;
  for (const auto& r : data.records) t = std::max(t, r.time_s);
  return t;
}

std::vector<StageWork> estimateStudyWork(const Study& s) {
  const auto& z = s.sizes;
  const double lab_s = duration(s, "lab"), field_s = duration(s, "field");
  const double rate = s.simulation.output_rate_hz;
  const double lab_times = s.lab.times_s.empty() ? static_cast<double>(s.lab.auto_times)
                                                 : static_cast<double>(s.lab.times_s.size());
  const double channels = std::max<double>(1, static_cast<double>(s.lab.channels.size()));
  std::vector<StageWork> out;
  // A lab record is ~64 bytes in memory (LabRecord with its channel name).
  out.push_back(
      {"lab", 1, lab_s, 64.0 * static_cast<double>(z.lab_repetitions) * lab_times * channels});
  // The field matrix: one row per run, one value per output sample.
  out.push_back({"field", static_cast<double>(z.field_runs),
                 static_cast<double>(z.field_runs) * field_s,
                 8.0 * static_cast<double>(z.field_runs) * field_s * rate});
  const double n_params = static_cast<double>(s.calibrated.size());
  const double round_points = static_cast<double>(
      s.calibration.round_points > 0 ? s.calibration.round_points : z.lhs_points);
  const double rounds = s.calibration.designOrDefault() == "adaptive"
                            ? static_cast<double>(s.calibration.max_rounds)
                            : 0.0;
  const double design = static_cast<double>(z.lhs_points) + rounds * round_points;
  const double calib_sims =
      calibrationSimulations(design, static_cast<double>(z.optimizer_starts), n_params);
  // The kept Gibbs draws (θ, τ, design index) and the design's outputs at the lab times.
  const double calib_mem = 8.0 * static_cast<double>(z.gibbs_iterations) * (n_params + 2) +
                           8.0 * design * lab_times * channels;
  const double synth_sims =
      static_cast<double>(z.posterior_draws) * static_cast<double>(z.roads_per_draw);
  for (const auto& a : s.assemblies()) {
    out.push_back({"calibrate " + a.id, calib_sims, calib_sims * lab_s, calib_mem});
    out.push_back({"synthesize " + a.id, synth_sims, synth_sims * field_s,
                   8.0 * static_cast<double>(z.road_library) + 8.0 * synth_sims * 2});
  }
  return out;
}

std::vector<StageWork> selectStages(const std::vector<StageWork>& all,
                                    const std::vector<std::string>& prefixes) {
  std::vector<StageWork> out;
  for (const auto& w : all)
    for (const auto& p : prefixes)
      if (w.stage == p || w.stage.compare(0, p.size() + 1, p + " ") == 0) {
        out.push_back(w);
        break;
      }
  return out;
}

void checkWork(const std::vector<StageWork>& stages, const std::string& where, bool force,
               const WorkLimits& limits) {
  if (force) return;
  double sim_s = 0, mem = 0;
  const StageWork* biggest = nullptr;
  for (const auto& w : stages) {
    sim_s += w.simulated_s;
    mem = std::max(mem, w.memory_bytes);
    if (!biggest || w.simulated_s > biggest->simulated_s) biggest = &w;
  }
  const std::string hint =
      "; reduce the sizes or pass --force to run it anyway (docs/study-file.md, Limits)";
  if (sim_s > limits.simulated_s)
    throw InputError(where, "estimated work " + formatNumber(sim_s, 3) +
                                " simulated s (largest stage: " + biggest->stage + ", " +
                                formatNumber(biggest->simulations, 3) +
                                " simulations) exceeds the limit " +
                                formatNumber(limits.simulated_s, 3) + " s" + hint);
  if (mem > limits.memory_bytes)
    throw InputError(where, "estimated memory " + formatNumber(mem / 1e9, 3) +
                                " GB exceeds the limit " +
                                formatNumber(limits.memory_bytes / 1e9, 3) + " GB" + hint);
}

void overrideSize(Study& study, const std::string& field, long value, const std::string& flag) {
  if (value <= 0) return;  // not given
  const long most = StudySizes::maximum(field);
  if (value > most)
    throw InputError(flag, "must be at most " + std::to_string(most) + " (the limit of sizes." +
                               field + "), got " + std::to_string(value));
  study.sizes.at(field) = value;
}

void checkCommandWork(const Study& study, const std::vector<std::string>& stages, bool force,
                      double repeat) {
  auto work = selectStages(estimateStudyWork(study), stages);
  for (auto& w : work) {
    w.simulations *= repeat;
    w.simulated_s *= repeat;
  }
  checkWork(work, study.path, force);
}

}  // namespace dtwin
