#include "study/lab_bands.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include <nlohmann/json.hpp>

#include "calibration/calibrate.hpp"
#include "calibration/summary.hpp"
#include "common/errors.hpp"
#include "common/json.hpp"
#include "common/parallel.hpp"
#include "common/validate.hpp"
#include "io/provenance.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace dtwin::study {

namespace {

json readJson(const fs::path& p) {
  return readJsonFile(p.string(), " (is this a `twin study` folder?)");
}

/// Rows ⌊(k + ½)·S / K⌋ of a sample of S rows, K = min(S, draws).
std::vector<std::size_t> evenRows(std::size_t S, int draws) {
  const std::size_t K = std::min<std::size_t>(S, static_cast<std::size_t>(draws));
  std::vector<std::size_t> rows;
  for (std::size_t k = 0; k < K; ++k)
    rows.push_back(static_cast<std::size_t>((static_cast<double>(k) + 0.5) *
                                            static_cast<double>(S) / static_cast<double>(K)));
  return rows;
}

/// The band of every channel of `data` from the predictions of its records by the draws `ok`
/// (`preds[k][i]`: draw k, record i; every repetition at (channel, t) has the same prediction).
std::vector<ChannelBand> bandsOf(const LabData& data, const std::vector<std::vector<double>>& preds,
                                 const std::vector<std::size_t>& ok,
                                 const std::vector<double>& sd) {
  std::vector<ChannelBand> out;
  std::map<std::pair<std::string, double>, std::size_t> first;  // (channel, t) -> its first record
  for (std::size_t i = 0; i < data.records.size(); ++i)
    first.emplace(std::make_pair(data.records[i].channel, data.records[i].time_s), i);
  for (const auto& ch : data.channels()) {
    ChannelBand p;
    p.channel = ch;
    for (double t : data.times(ch)) {
      const std::size_t i = first.at({ch, t});
      std::vector<double> eta;
      eta.reserve(ok.size());
      for (std::size_t k : ok) eta.push_back(preds[k][i]);
      const std::vector<double> eta_unsorted = eta;
      std::sort(eta.begin(), eta.end());
      p.times.push_back(t);
      p.lo.push_back(quantileSorted(eta, 0.025));
      p.med.push_back(quantileSorted(eta, 0.5));
      p.hi.push_back(quantileSorted(eta, 0.975));
      p.plo.push_back(normalMixtureQuantile(eta_unsorted, sd, 0.025));
      p.phi.push_back(normalMixtureQuantile(eta_unsorted, sd, 0.975));
    }
    out.push_back(std::move(p));
  }
  return out;
}

/// The lab data's channels on `points` evenly spaced times from 0 to the last lab time and as many
/// from the first lab time to the last (where the lab measured, the response is resolved finely),
/// merged with the lab times (one record per channel and time, value 0: only their predictions
/// count).
LabData denseGrid(const LabData& lab, int points) {
  double t_end = 0.0, t_first = INFINITY;
  for (const auto& r : lab.records) {
    t_end = std::max(t_end, r.time_s);
    t_first = std::min(t_first, r.time_s);
  }
  LabData dense;
  for (const auto& ch : lab.channels()) {
    const std::vector<double> lab_times = lab.times(ch);
    std::set<double> times(lab_times.begin(), lab_times.end());
    for (int k = 0; k < points; ++k) {
      times.insert(t_end * k / (points - 1));
      times.insert(t_first + (t_end - t_first) * k / (points - 1));
    }
    for (double t : times) dense.records.push_back(LabRecord{1, t, ch, 0.0});
  }
  return dense;
}

/// The bands of one assembly from its predictions on the dense data (rows that failed are empty
/// vectors).
void summarise(AssemblyBands& a, const std::vector<std::size_t>& rows,
               const std::vector<std::vector<double>>& preds, const LabData& dense,
               std::vector<std::string>& warnings) {
  std::vector<std::size_t> ok;
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (preds[k].size() == dense.records.size()) ok.push_back(k);
  a.drawn = rows.size();
  a.failures = rows.size() - ok.size();
  if (ok.empty()) {
    warnings.push_back(
        a.assembly.id +
        ": every posterior draw failed to simulate the lab scenario; no predictive band");
    return;
  }
  std::vector<double> sd;
  sd.reserve(ok.size());
  for (std::size_t k : ok) sd.push_back(1.0 / std::sqrt(a.posterior.tau[rows[k]]));
  std::vector<double> sd_sorted = sd;
  std::sort(sd_sorted.begin(), sd_sorted.end());
  a.noise_sd = quantileSorted(sd_sorted, 0.5);
  a.channels = bandsOf(dense, preds, ok, sd);
}

}  // namespace

void LabBandOptions::validate() const {
  const OptionCheck check("lab_bands");
  check.atLeast("draws", draws, 2);
  check.atLeast("threads", threads, 0);  // 0: all cores
  check.atLeast("grid_points", grid_points, 2);
}

LabBands predictLabBands(const std::string& study_dir, const LabBandOptions& options) {
  options.validate();
  const fs::path dir(study_dir);
  if (!fs::is_directory(dir)) throw InputError(study_dir, "is not a folder");
  const json record = readJson(dir / "study.json");
  const json summary = readJson(dir / "summary.json");

  LabBands out;
  out.draws = options.draws;
  out.study_path = record.value("study", summary.value("study", std::string()));
  if (out.study_path.empty() || !fs::exists(out.study_path))
    throw InputError((dir / "study.json").string(),
                     "names the study file '" + out.study_path + "', which does not exist");
  out.study = loadStudy(out.study_path);
  if (record.contains("fingerprint") && record["fingerprint"].value("study_file", "") !=
                                            std::to_string(fnv1a64(readTextFile(out.study_path))))
    out.warnings.push_back(
        "the study file " + out.study_path +
        " changed after the study was run: the predictive bands use its current content");
  out.lab_path = summary.contains("paths") ? summary["paths"].value("lab", "") : "";
  if (out.lab_path.empty() || !fs::exists(out.lab_path))
    out.lab_path = (dir / "lab" / "lab.csv").string();
  out.lab = readLabCsv(out.lab_path, measurableChannels(out.study.sensors));
  // One set of runs predicts the lab times and the dense grid: the lab times are in the grid.
  const LabData dense = denseGrid(out.lab, options.grid_points);
  std::vector<std::unique_ptr<calib::LabObjective>> objectives;
  std::vector<std::vector<std::size_t>> rows;
  for (const auto& spec : out.study.assemblies()) {
    const fs::path post = dir / "calibration" / spec.id / "posterior.csv";
    if (!fs::exists(post)) continue;
    AssemblyBands a;
    a.assembly = spec;
    a.posterior = calib::readPosteriorCsv(post.string());
    objectives.push_back(std::make_unique<calib::LabObjective>(out.study, spec, dense, "lab"));
    if (objectives.back()->names() != a.posterior.names)
      throw InputError(a.posterior.path,
                       "its parameter columns are not the study's calibrated parameters");
    rows.push_back(evenRows(a.posterior.size(), options.draws));
    out.assemblies.push_back(std::move(a));
  }
  if (out.assemblies.empty())
    throw InputError((dir / "calibration").string(),
                     "holds no <id>/posterior.csv of the study's assemblies");

  std::vector<std::pair<std::size_t, std::size_t>> jobs;
  std::vector<std::vector<std::vector<double>>> preds(out.assemblies.size());
  for (std::size_t m = 0; m < out.assemblies.size(); ++m) {
    preds[m].resize(rows[m].size());
    for (std::size_t k = 0; k < rows[m].size(); ++k) jobs.emplace_back(m, k);
  }
  parallelFor(jobs.size(), options.threads, [&](std::size_t j, int /*worker*/) {
    const auto [m, k] = jobs[j];
    try {
      preds[m][k] = objectives[m]->predict(out.assemblies[m].posterior.theta[rows[m][k]]);
    } catch (const std::exception&) {
      preds[m][k].clear();  // counted as a failure
    }
  });
  for (std::size_t m = 0; m < out.assemblies.size(); ++m)
    summarise(out.assemblies[m], rows[m], preds[m], dense, out.warnings);
  return out;
}

}  // namespace dtwin::study
