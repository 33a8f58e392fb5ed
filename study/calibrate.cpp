#include "study/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <tuple>

#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"
#include "common/hash.hpp"
#include "common/validate.hpp"
#include "diagnosis/candidates.hpp"
#include "diagnosis/measurements.hpp"
#include "io/measurement.hpp"
#include "io/provenance.hpp"
#include "io/work.hpp"

namespace fs = std::filesystem;

namespace dtwin {

void CalibrateRequest::validate(const Study& study) const {
  const OptionCheck check("calibrate");
  (void)study.scenario(scenario);
  for (const auto& id : assemblies) (void)study.assembly(id);
  if (!fs::exists(data)) throw InputError(data, "lab data file not found (--data)");
  check.require(!(fs::exists(out) && !fs::is_directory(out)), "out",
                "'" + out + "' exists and is not a folder");
  options.validate();
  for (std::size_t i = 0; i < free.size(); ++i) {
    check.require(std::find(free.begin(), free.begin() + static_cast<long>(i), free[i]) ==
                      free.begin() + static_cast<long>(i),
                  "free", "names '" + free[i] + "' twice");
    for (const auto& a : calibrationTargets(study, *this)) (void)freedValueSpec(study, a, free[i]);
  }
}

diag::CandidateSpec freedValueSpec(const Study& study, const AssemblySpec& assembly,
                                   const std::string& value) {
  const std::string where = OptionCheck("calibrate").where("free");
  if (value.rfind("free:", 0) == 0)
    throw InputError(where,
                     "'" + value + "': give the value's name alone (" + value.substr(5) + ")");
  if (const auto eq = value.find('='); eq != std::string::npos)
    throw InputError(
        where, "'" + value +
                   "': a freed value is searched over its range and takes no value; give '" +
                   value.substr(0, eq) + "' alone (a fixed value is the study's [fixed] table)");
  auto spec = diag::candidateSpec("free:" + value, study, assembly, {}, where);
  if (spec.kind != "parameter" && spec.kind != "input" && spec.kind != "place")
    throw InputError(where, "'" + value + "' is not a fixed value that can be freed");
  return spec;
}

namespace {

/// The line said before the work starts: what is calibrated against what, with which sizes.
std::string calibrationPlan(const CalibrateRequest& request, std::size_t targets,
                            const LabData& data) {
  const calib::CalibrationOptions& opt = request.options;
  const std::string rounds = opt.design.adaptive
                                 ? " + up to " + std::to_string(opt.design.max_rounds) +
                                       " adaptive rounds of " +
                                       std::to_string(opt.designOptions().round_points)
                                 : std::string();
  return formatPrintf(
      "calibrating %zu assembl%s against %s (%zu records): %d starts, %s region, %d design "
      "points%s, %d Gibbs "
      "iterations (%d burn-in)",
      targets, targets == 1 ? "y" : "ies", request.data.c_str(), data.records.size(),
      opt.optimizer_starts, opt.region.c_str(), opt.lhs_points, rounds.c_str(),
      opt.gibbs_iterations, opt.gibbs_burn_in);
}

}  // namespace

std::map<std::string, double> channelWeights(const Study& study, const calib::DataSet& set) {
  const auto channels = set.data.channels();
  if (channels.size() < 2 || std::all_of(channels.begin(), channels.end(), diag::isForce))
    return {};
  std::vector<std::string> left;
  const auto noise = diag::estimateChannelNoise(study, {set}, &left);
  if (!left.empty())
    throw InputError(set.name, "channel " + left.front() +
                                   ": the data hold several channels, fitted together only when "
                                   "each has a noise to weigh it by "
                                   "(give its sensor a noise_sd, or repeat the measurement)");
  std::map<std::string, double> weights;
  for (const auto& [c, n] : noise) weights[c] = 1.0 / n.variance;
  return weights;
}

void CalibrationOverrides::applyTo(calib::CalibrationOptions& opt) const {
  if (lhs_points > 0) opt.lhs_points = static_cast<int>(lhs_points);
  if (iterations > 0) opt.gibbs_iterations = static_cast<int>(iterations);
  if (burn_in >= 0) opt.gibbs_burn_in = static_cast<int>(burn_in);
  if (starts > 0) opt.optimizer_starts = static_cast<int>(starts);
  if (!region.empty()) {
    opt.region = region;
    if (design.empty()) opt.design.adaptive = region == "joint";  // the region's default design
  }
  if (!design.empty()) opt.design.adaptive = design == "adaptive";
  if (!interval.empty()) opt.interval = interval;
  if (!steps.empty()) opt.steps = steps;
  if (max_rounds >= 0) opt.design.max_rounds = static_cast<int>(max_rounds);
  if (ridge_steps >= 0) opt.joint.ridge_steps = static_cast<int>(ridge_steps);
}

Study CalibrationOverrides::sized(const Study& study) const {
  Study s = study;
  overrideSize(s, "lhs_points", lhs_points, "--lhs-points");
  overrideSize(s, "gibbs_iterations", iterations, "--iterations");
  overrideSize(s, "optimizer_starts", starts, "--starts");
  return s;
}

std::pair<std::string, std::string> calibrationData(const std::string& data,
                                                    const std::string& field,
                                                    const std::string& scenario) {
  const diag::MeasurementSpec spec = diag::parseMeasurementArg(data, field);
  const std::string s = dataScenario(spec.path, scenario.empty() ? spec.scenario : scenario,
                                     readSidecarFacts(spec.path));
  return {spec.path, s.empty() ? std::string("lab") : s};
}

void checkDataScenario(const std::string& data, const std::string& scenario) {
  const diag::MeasurementSpec spec = diag::parseMeasurementArg(data, "--data");
  if (!spec.scenario.empty() && spec.scenario != scenario)
    throw InputError("--scenario", "'" + scenario + "' differs from the scenario of --data " +
                                       data + ": give it once, as --data FILE@SCENARIO");
}

CalibrateRequest calibrateRequest(const Study& study, const CalibrateSettings& settings) {
  CalibrateRequest req;
  std::tie(req.data, req.scenario) = calibrationData(settings.data, "--data", settings.scenario);
  req.assemblies = settings.assemblies;
  req.out = settings.out;
  req.free = settings.free;
  req.command = settings.command;
  calib::CalibrationOptions& opt = req.options;
  opt = calib::CalibrationOptions::fromStudy(study);
  opt.threads = settings.threads;
  opt.processes = settings.processes;
  if (settings.seed) opt.seed = *settings.seed;
  settings.overrides.applyTo(opt);
  req.validate(study);  // before anything is printed
  checkCalibrateWork(study, req, settings.overrides, settings.force);
  return req;
}

void checkCalibrateWork(const Study& study, const CalibrateRequest& request,
                        const CalibrationOverrides& overrides, bool force) {
  std::vector<std::string> stages;
  for (const auto& a : calibrationTargets(study, request)) stages.push_back("calibrate " + a.id);
  checkCommandWork(overrides.sized(study), stages, force);
}

std::vector<AssemblySpec> calibrationTargets(const Study& study, const CalibrateRequest& request) {
  if (request.assemblies.empty()) return study.assemblies();
  std::vector<AssemblySpec> out;
  for (const auto& id : request.assemblies) out.push_back(study.assembly(id));
  return out;
}

std::string CalibrateRun::text() const {
  const calib::CalibrationResult& r = result;
  const AssemblySpec& a = assembly;
  const double noise_var = r.posterior.tau.mean > 0 ? 1.0 / r.posterior.tau.mean : 0.0;
  const std::string noise =
      weights.empty() ? formatPrintf("noise sd %.3g %s", std::sqrt(noise_var), unit.c_str())
                      : formatPrintf("weighted by 1/noise_sd^2: the noise %.3g times the stated",
                                     std::sqrt(noise_var));
  std::string s = formatPrintf(
      "%-4s %-26s SSE_min %.4g  tau %.3g (%s)  design %ld points in %zu round%s (importance ESS "
      "%.0f)  "
      "distinct points %d  top share %.2f  failures %ld  %.1f s\n",
      a.id.c_str(), a.label().c_str(), r.optimum.sse, r.posterior.tau.mean, noise.c_str(),
      static_cast<long>(r.design.rows()), r.rounds.rounds.size(),
      r.rounds.rounds.size() == 1 ? "" : "s", r.rounds.ess, r.posterior.distinct_points,
      r.posterior.top_share, r.design_failures, r.stage_wall_s.back().second);
  const bool profile_first = r.interval == "profile";
  for (std::size_t k = 0; k < r.names.size(); ++k) {
    const auto& p = r.posterior.parameters[k];
    const std::string truth = r.truth[k] ? " truth " + formatExact(*r.truth[k]) : std::string();
    if (k < r.profile.lower.size())
      s += formatPrintf(
          "       %-22s mean %-11.5g sd %-10.4g 95%% %s [%.5g, %.5g], %s [%.5g, %.5g]%s\n",
          r.names[k].c_str(), p.mean, p.sd, profile_first ? "profile" : "posterior",
          profile_first ? r.profile.lower[k] : p.q025, profile_first ? r.profile.upper[k] : p.q975,
          profile_first ? "posterior" : "profile", profile_first ? p.q025 : r.profile.lower[k],
          profile_first ? p.q975 : r.profile.upper[k], truth.c_str());
    else
      s += formatPrintf("       %-22s mean %-11.5g sd %-10.4g 95%% [%.5g, %.5g]%s\n",
                        r.names[k].c_str(), p.mean, p.sd, p.q025, p.q975, truth.c_str());
  }
  if (const auto& c = r.profile.correlation; c.blocks > 0 && !c.kappa.empty()) {
    const auto [lo, hi] = std::minmax_element(c.kappa.begin(), c.kappa.end());
    s += formatPrintf(
        "       note: one drive's residuals run in stretches (correlated in time): each profile "
        "interval's threshold is scaled by "
        "its kappa (from %d blocks of consecutive samples; %.2g to %.2g) and taken from t with %d "
        "dof (docs/calibration.md)\n",
        c.blocks, *lo, *hi, c.blocks - 1);
  }
  s += calib::boundFindingsText(r.bounds, "       ");
  if (!r.left_out.empty()) {
    std::string names;
    for (const auto& n : r.left_out) names += (names.empty() ? "" : ", ") + n;
    s += "       note: " + names + " not calibrated: " + a.label() + " does not have " +
         (r.left_out.size() == 1 ? "it" : "them") +
         " (the road enters at the hub, with no tire compliance)\n";
  }
  if (r.posterior.design_too_coarse) s += "       note: " + r.posterior.message + "\n";
  for (const auto& w : r.rounds.warnings) s += "       note: " + w + "\n";
  for (const auto& m : r.region.messages) s += "       note: " + m + "\n";
  if (r.design_failures)
    s += formatPrintf("       note: %ld design simulations failed (SSE = inf, weight 0)\n",
                      r.design_failures);
  if (!r.integrator.ok) s += "       note: " + r.integrator.message + "\n";
  return s;
}

void calibrateAssemblies(const Study& study, const CalibrateRequest& request, const SayFn& say,
                         const std::function<StageProgress(const AssemblySpec&)>& progress_of,
                         const std::function<void(const CalibrateRun&)>& on_done) {
  calib::CalibrationOptions opt = request.options;
  opt.command = request.command;
  opt.data_path = request.data;
  CalibrateRequest checked = request;
  checked.options = opt;
  checked.validate(study);
  const auto targets = calibrationTargets(study, request);
  const LabData data = readLabCsv(request.data, measurableChannels(study.sensors));
  const std::string data_hash = std::to_string(fnv1a64(readTextFile(request.data)));
  const calib::DataSet set{request.data, request.scenario, data, std::nullopt};
  calib::CalibrationSetup setup;
  setup.channel_weights = channelWeights(study, set);
  if (say) say(calibrationPlan(request, targets.size(), data));
  nlohmann::json index;
  stampProvenance(index, request.command);
  index["study"] = study.path;
  index["data"] = request.data;
  for (const auto& a : targets) {
    CalibrateRun run;
    run.assembly = a;
    const std::string dir = (fs::path(request.out) / a.id).string();
    run.weights = setup.channel_weights;
    if (const auto ch = data.channels(); !ch.empty()) {
      const std::string u = channelUnit(measurableChannels(study.sensors), ch.front());
      if (!u.empty()) run.unit = u;
    }
    calib::CalibrationSetup with =
        setup;  // the freed values, this assembly's (a law's value may differ between them)
    for (const auto& v : request.free) freedValueSpec(study, a, v).install(with);
    const StageProgress progress = progress_of ? progress_of(a) : StageProgress{};
    run.result =
        with.empty()
            ? calibrateAssembly(study, a, data, request.scenario, opt, dir, data_hash, progress)
            : calibrateAssembly(study, a, {set}, with, opt, dir, data_hash, progress);
    index["assemblies"].push_back({{"assembly", a.id},
                                   {"label", a.label()},
                                   {"summary", (fs::path(a.id) / "summary.json").string()}});
    if (on_done) on_done(run);
  }
  rootWrites(request.options.processes, [&] {
    writeFileAtomic((fs::path(request.out) / "calibration.json").string(), index.dump(2) + "\n");
  });
}

}  // namespace dtwin
