#include "study/coverage.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/validate.hpp"
#include "io/provenance.hpp"
#include "io/work.hpp"
#include "study/generate.hpp"

namespace fs = std::filesystem;

namespace dtwin::calib {
namespace {

std::string fmt(double v, int digits = 4) { return formatNumber(v, digits); }

}  // namespace

void CoverageOptions::validate() const {
  const OptionCheck check("coverage");
  check.require(
      seeds >= 2, "seeds",
      "must be >= 2 (a coverage needs several noise seeds), got " + std::to_string(seeds));
  check.require(!out_dir.empty(), "out_dir", "an output folder is required");
  calibration.validate();
}

std::pair<double, double> wilsonInterval(int k, int m) {
  if (m <= 0) return {0.0, 1.0};
  const double z = 1.959963984540054, p = static_cast<double>(k) / m, n = m;
  const double c = (p + z * z / (2 * n)) / (1 + z * z / n);
  const double h = z / (1 + z * z / n) * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n));
  return {std::max(0.0, c - h), std::min(1.0, c + h)};
}

nlohmann::json CoverageResult::toJson() const {
  nlohmann::json j;
  for (const auto& r : rows)
    j["rows"].push_back({{"assembly", r.assembly},
                         {"parameter", r.parameter},
                         {"truth", r.truth},
                         {"seeds", r.seeds},
                         {"covered", r.covered},
                         {"coverage", r.seeds ? static_cast<double>(r.covered) / r.seeds : 0.0},
                         {"coverage_wilson95", {r.wilson_low, r.wilson_high}},
                         {"interval", r.interval},
                         {"covered_profile", r.covered_profile},
                         {"covered_posterior", r.covered_posterior},
                         {"mean_ci95_width", r.mean_width},
                         {"mean_profile95_width", r.mean_width_profile},
                         {"mean_credible95_width", r.mean_width_posterior},
                         {"mean_posterior_sd", r.mean_sd},
                         {"sd_of_posterior_means", r.sd_of_means},
                         {"sd_ratio", r.sd_ratio()},
                         {"rmse_of_posterior_means", r.rmse},
                         {"sd_of_optima", r.sd_of_optima},
                         {"sd_ratio_to_optima", r.optimum_ratio()},
                         {"rmse_over_mean_sd", r.rmse_ratio()}});
  for (const auto& [a, t] : totals)
    j["assemblies"][a] = {{"covered", t.first},
                          {"pairs", t.second},
                          {"coverage", t.second ? static_cast<double>(t.first) / t.second : 0.0}};
  j["median_calibration_wall_s"] = median_calibration_wall_s;
  j["wall_s"] = wall_s;
  return j;
}

std::string CoverageResult::markdown() const {
  std::ostringstream s;
  s << "| assembly | parameter | truth | ci95 holds the truth | Wilson 95 % | profile holds | "
       "posterior holds | mean width profile | "
       "mean width posterior | mean sd | sd of means | mean sd / sd of means | sd of θ̂ | mean sd / "
       "sd of θ̂ | RMSE of means / mean sd |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    s << "| " << r.assembly << " | " << r.parameter << " | " << fmt(r.truth, 6) << " | "
      << r.covered << "/" << r.seeds << " (" << fmt(100.0 * r.covered / std::max(r.seeds, 1), 3)
      << " %, " << r.interval << ") | " << fmt(100 * r.wilson_low, 3) << "–"
      << fmt(100 * r.wilson_high, 3) << " % | " << r.covered_profile << "/" << r.seeds << " | "
      << r.covered_posterior << "/" << r.seeds << " | " << fmt(r.mean_width_profile) << " | "
      << fmt(r.mean_width_posterior) << " | " << fmt(r.mean_sd) << " | " << fmt(r.sd_of_means)
      << " | " << fmt(r.sd_ratio(), 3) << " | " << fmt(r.sd_of_optima) << " | "
      << fmt(r.optimum_ratio(), 3) << " | " << fmt(r.rmse_ratio(), 3) << " |\n";
  s << "\n| assembly | (parameter, seed) pairs whose ci95 holds the truth | profile | posterior "
       "|\n|---|---|---|---|\n";
  for (const auto& [a, t] : totals) {
    int prof = 0, post = 0;
    for (const auto& r : rows)
      if (r.assembly == a) {
        prof += r.covered_profile;
        post += r.covered_posterior;
      }
    s << "| " << a << " | " << t.first << "/" << t.second << " ("
      << fmt(100.0 * t.first / std::max(t.second, 1), 3) << " %) | " << prof << "/" << t.second
      << " (" << fmt(100.0 * prof / std::max(t.second, 1), 3) << " %) | " << post << "/" << t.second
      << " (" << fmt(100.0 * post / std::max(t.second, 1), 3) << " %) |\n";
  }
  return s.str();
}

namespace {

/// One noise seed of one assembly: its lab data (generated at the study's truths, written to
/// `adir`) calibrated as `twin calibrate` would, in adir/seed_<seed>/.
CalibrationResult calibrateSeed(const Study& study, const AssemblySpec& a, const fs::path& adir,
                                std::uint64_t seed, const CoverageOptions& options,
                                const StageProgress& progress) {
  LabOptions lo;
  lo.seed = seed;
  lo.command = options.command;
  const LabResult lab = generateLab(study, a, lo);
  const std::string lab_path = (adir / ("lab_" + std::to_string(seed) + ".csv")).string();
  rootWrites(options.calibration.processes, [&] {
    writeLabCsv(lab_path, lab.data, measurableChannels(study.sensors));
    writeFileAtomic(fs::path(lab_path).replace_extension(".json").string(),
                    lab.provenance.dump(2) + "\n");
  });
  CalibrationOptions co = options.calibration;
  co.command = options.command;
  co.data_path = lab_path;
  std::ostringstream csv;
  for (const auto& r : lab.data.records)
    csv << r.repetition << ',' << formatExact(r.time_s) << ',' << r.channel << ','
        << formatExact(r.value) << '\n';
  const std::string hash = std::to_string(fnv1a64(csv.str()));
  return calibrateAssembly(study, a, lab.data, "lab", co,
                           (adir / ("seed_" + std::to_string(seed))).string(), hash, progress);
}

/// The row of one parameter (with a truth) over the seeds' summaries (summary.json's content).
CoverageRow coverageRow(const std::string& assembly, const std::string& parameter, double truth,
                        const std::vector<nlohmann::json>& summaries) {
  CoverageRow row;
  row.assembly = assembly;
  row.parameter = parameter;
  row.truth = truth;
  std::vector<double> means, optima;
  double sse = 0.0;
  for (const auto& s : summaries) {
    const auto& e = s.at("parameters").at(parameter);
    const double lo = e.at("ci95")[0].get<double>(), hi = e.at("ci95")[1].get<double>(),
                 m = e.at("mean").get<double>();
    const auto& cr = e.at("credible95");
    const auto& pr = e.contains("profile95") ? e.at("profile95") : cr;
    row.interval = e.at("interval").get<std::string>();
    ++row.seeds;
    row.covered += (row.truth >= lo && row.truth <= hi) ? 1 : 0;
    row.covered_profile +=
        (row.truth >= pr[0].get<double>() && row.truth <= pr[1].get<double>()) ? 1 : 0;
    row.covered_posterior +=
        (row.truth >= cr[0].get<double>() && row.truth <= cr[1].get<double>()) ? 1 : 0;
    row.mean_width += hi - lo;
    row.mean_width_profile += pr[1].get<double>() - pr[0].get<double>();
    row.mean_width_posterior += cr[1].get<double>() - cr[0].get<double>();
    row.mean_sd += e.at("sd").get<double>();
    means.push_back(m);
    optima.push_back(e.at("optimum").get<double>());
    sse += (m - row.truth) * (m - row.truth);
  }
  row.mean_width /= row.seeds;
  row.mean_width_profile /= row.seeds;
  row.mean_width_posterior /= row.seeds;
  row.mean_sd /= row.seeds;
  auto sdOf = [](const std::vector<double>& v) {
    double mean = 0.0, ss = 0.0;
    for (double x : v) mean += x / static_cast<double>(v.size());
    for (double x : v) ss += (x - mean) * (x - mean);
    return std::sqrt(ss / static_cast<double>(v.size() - 1));
  };
  row.sd_of_means = sdOf(means);
  row.sd_of_optima = sdOf(optima);
  row.rmse = std::sqrt(sse / row.seeds);
  std::tie(row.wilson_low, row.wilson_high) = wilsonInterval(row.covered, row.seeds);
  return row;
}

/// coverage.json and coverage.md in options.out_dir.
void writeCoverage(const Study& study, const CoverageOptions& options, const CoverageResult& res) {
  nlohmann::json j = res.toJson();
  stampProvenance(j, options.command);
  j["study"] = study.path;
  j["seeds"] = {{"first", options.first_seed},
                {"count", options.seeds},
                {"rule", "lab noise seed s = first .. first + count - 1"}};
  j["calibration_options"] = options.calibration.toJson();
  rootWrites(options.calibration.processes, [&] {
    writeFileAtomic((fs::path(options.out_dir) / "coverage.json").string(), j.dump(2) + "\n");
    std::string md =
        "# Coverage of the 95 % intervals\n\nStudy `" + study.path + "`, noise seeds " +
        std::to_string(options.first_seed) + "–" +
        std::to_string(options.first_seed + static_cast<std::uint64_t>(options.seeds) - 1) +
        ", region `" + options.calibration.region + "`, design `" +
        (options.calibration.design.adaptive ? "adaptive" : "lhs") + "`, ci95 = the `" +
        options.calibration.interval + "` interval.\n\n" + res.markdown();
    writeFileAtomic((fs::path(options.out_dir) / "coverage.md").string(), md);
  });
}

}  // namespace

CoverageResult runCoverage(const Study& study, const CoverageOptions& options,
                           const CoverageProgress& progress) {
  options.validate();
  const auto t_all = std::chrono::steady_clock::now();
  std::vector<AssemblySpec> targets;
  if (options.assemblies.empty())
    targets = study.assemblies();
  else
    for (const auto& id : options.assemblies) targets.push_back(study.assembly(id));
  CoverageResult res;
  std::vector<double> walls;
  const int count = static_cast<int>(targets.size()) * options.seeds;
  int index = 0;
  for (const auto& a : targets) {
    const fs::path adir = fs::path(options.out_dir) / a.id;
    rootWrites(options.calibration.processes, [&] { fs::create_directories(adir); });
    std::vector<nlohmann::json> summaries;
    summaries.reserve(static_cast<std::size_t>(options.seeds));
    std::vector<std::string> order;
    std::vector<std::optional<double>> truths;
    for (int k = 0; k < options.seeds; ++k, ++index) {
      const std::uint64_t seed = options.first_seed + static_cast<std::uint64_t>(k);
      if (progress) progress(a.id, seed, index, count, "lab data", 0, 1);
      const CalibrationResult cr =
          calibrateSeed(study, a, adir, seed, options,
                        [&](const std::string& stage, std::size_t done, std::size_t total) {
                          if (progress) progress(a.id, seed, index, count, stage, done, total);
                        });
      walls.push_back(cr.stage_wall_s.back().second);
      summaries.push_back(cr.toJson());
      order = cr.names;
      truths = cr.truth;
    }
    int covered_all = 0, pairs = 0;
    for (std::size_t p = 0; p < order.size(); ++p) {
      if (!truths[p]) continue;  // no truth: nothing to cover
      const CoverageRow row = coverageRow(a.id, order[p], *truths[p], summaries);
      covered_all += row.covered;
      pairs += row.seeds;
      res.rows.push_back(row);
    }
    res.totals.push_back({a.id, {covered_all, pairs}});
  }
  std::sort(walls.begin(), walls.end());
  res.median_calibration_wall_s = walls.empty() ? 0.0 : walls[walls.size() / 2];
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_all).count();
  writeCoverage(study, options, res);
  return res;
}

CoverageOptions coverageOptions(const Study& study, CoverageOptions options,
                                const CalibrationOverrides& overrides, bool force) {
  for (const auto& id : options.assemblies) study.assembly(id);  // validates the ids
  if (fs::exists(options.out_dir) && !fs::is_directory(options.out_dir))
    throw InputError("--out", "'" + options.out_dir + "' exists and is not a folder");
  std::vector<std::string> stages;
  for (const auto& id : options.assemblies) stages.push_back("calibrate " + id);
  if (stages.empty()) stages.push_back("calibrate");
  checkCommandWork(overrides.sized(study), stages, force,
                   options.seeds);  // each seed is one calibration
  const int threads = options.calibration.threads;
  const Distributed* processes = options.calibration.processes;
  options.calibration = CalibrationOptions::fromStudy(study);
  options.calibration.threads = threads;
  options.calibration.processes = processes;
  overrides.applyTo(options.calibration);
  options.validate();
  return options;
}

std::string coveragePlan(const Study& study, const CoverageOptions& options) {
  const std::size_t n_asm =
      options.assemblies.empty() ? study.assemblies().size() : options.assemblies.size();
  const auto first = static_cast<long long>(options.first_seed);
  return formatPrintf(
      "coverage: %zu assembl%s x %d noise seeds (%lld..%lld), %s region, %s design -> %s\n", n_asm,
      n_asm == 1 ? "y" : "ies", options.seeds, first, first + options.seeds - 1,
      options.calibration.region.c_str(), options.calibration.design.adaptive ? "adaptive" : "lhs",
      options.out_dir.c_str());
}

std::string coverageText(const CoverageResult& result, const std::string& out_dir) {
  return formatPrintf(
      "\n%s\nmedian calibration %.1f s, total %.0f s; %s/coverage.json, %s/coverage.md\n",
      result.markdown().c_str(), result.median_calibration_wall_s, result.wall_s, out_dir.c_str(),
      out_dir.c_str());
}

}  // namespace dtwin::calib
