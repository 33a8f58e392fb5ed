#include "study/diagnose.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "calibration/folder.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"
#include "common/parallel.hpp"
#include "diagnosis/baseline.hpp"
#include "diagnosis/discrepancy.hpp"
#include "diagnosis/measurements.hpp"
#include "io/provenance.hpp"
#include "io/work.hpp"
#include "report/compare_page.hpp"
#include "report/diagnosis_report.hpp"

namespace fs = std::filesystem;

namespace dtwin {
namespace {

std::vector<calib::DataSet> loadSets(const Study& study, const std::vector<std::string>& args,
                                     const std::string& flag) {
  std::vector<calib::DataSet> sets;
  sets.reserve(args.size());
  for (const auto& a : args)
    sets.push_back(diag::loadMeasurement(study, diag::parseMeasurementArg(a, flag)));
  return sets;
}

void checkOutFolder(const std::string& out, const std::string& field) {
  if (!out.empty() && fs::exists(out) && !fs::is_directory(out))
    throw InputError(field, "'" + out + "' exists and is not a folder");
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

/// Where one series fails in time: the windows' counts in words, the largest windows (the listed
/// ones, largest share first, at most 8), then one line for the rest.
void appendFailingWindows(const diag::SeriesComparison& s, std::string& out) {
  constexpr std::size_t kWindowsShown =
      8;  // compare.html lists every listed window, compare.json every one found
  if (!s.windows_note.empty())
    out += formatPrintf("  windows: %s %s: %s\n", s.scenario.c_str(), s.channel.c_str(),
                        s.windows_note.c_str());
  const std::size_t shown = std::min(s.windows.size(), kWindowsShown);
  double held = 0.0;
  for (std::size_t k = 0; k < shown; ++k) {
    const auto& w = s.windows[k];
    held += w.window.share;
    out += formatPrintf(
        "  fails: %s %s %.3f-%.3f s, peak |z| %.1f, %.0f %% of its residual: %s (%.1f m/s)\n",
        s.scenario.c_str(), s.channel.c_str(), w.window.t_begin, w.window.t_end, w.window.peak_z,
        100 * w.window.share, w.label.c_str(), w.speed_mps);
  }
  const diag::WindowSummary& ws = s.window_summary;
  if (ws.merged > shown)
    out += formatPrintf(
        "  fails: %s %s in %zu more windows holding %.0f %% of its residual (--out: compare.html "
        "lists the %zu largest, "
        "compare.json every window)\n",
        s.scenario.c_str(), s.channel.c_str(), ws.merged - shown,
        100 * std::max(0.0, ws.merged_share - held), ws.listed);
}

/// The road input of a data set (diagnosis/baseline.hpp) up to its last record.
diag::RoadInput roadInputOf(const Study& study, const VehicleData& vehicle,
                            const calib::DataSet& ds) {
  return diag::roadInput(study.scenario(ds.scenario), vehicle, ds.road_seed.value_or(study.seed),
                         0.001, dataSpan(ds.data));
}

/// The FIR baseline of every compared channel, fitted on `train` (twin compare --baseline), and
/// its fit percentage on each compared series.
void addBaseline(const Study& study, const VehicleData& vehicle,
                 const std::vector<calib::DataSet>& train, const std::vector<calib::DataSet>& sets,
                 CompareRun& run, const SayFn& say) {
  std::vector<diag::RoadInput> train_in, test_in;
  std::vector<const LabData*> train_data;
  std::vector<const diag::RoadInput*> train_ptr;
  for (const auto& ds : train) train_in.push_back(roadInputOf(study, vehicle, ds));
  for (std::size_t i = 0; i < train.size(); ++i) {
    train_data.push_back(&train[i].data);
    train_ptr.push_back(&train_in[i]);
  }
  for (const auto& ds : sets) test_in.push_back(roadInputOf(study, vehicle, ds));
  std::map<std::string, diag::FirBaseline> fitted;
  for (auto& s : run.comparison.series) {
    if (!fitted.count(s.channel)) {
      fitted.emplace(s.channel, diag::fitFirBaseline(s.channel, train_data, train_ptr));
      if (say) say("baseline for " + s.channel + ": " + fitted.at(s.channel).describe());
    }
    for (std::size_t k = 0; k < sets.size(); ++k)
      if (sets[k].name == s.data_set)
        s.baseline_fit_percent =
            diag::firFitPercent(fitted.at(s.channel), sets[k].data, test_in[k]);
  }
  for (const auto& [channel, b] : fitted) run.baseline[channel] = b.describe();
}

/// Throws InputError for a drive of `sets` whose road is flat under every wheel: a filter from the
/// road has nothing to follow there.
void requireRoadSignal(const Study& study, const VehicleData& vehicle,
                       const std::vector<calib::DataSet>& sets) {
  for (const auto& ds : sets) {
    const diag::RoadInput in = roadInputOf(study, vehicle, ds);
    bool flat = true;
    for (const auto& u : in.u)
      flat = flat && std::all_of(u.begin(), u.end(), [&](double v) { return v == u.front(); });
    if (flat)
      throw InputError(ds.name + "@" + ds.scenario,
                       "its road is flat under every wheel: no road signal for the --discrepancy "
                       "filter to follow");
  }
}

/// The discrepancy filter of every compared channel (twin compare --discrepancy): the physics at
/// the posterior rows `rows` simulated on the calibration drives `train` (the mean over the rows
/// that simulated), the filter fitted on its residual, and the hybrid scored on each compared
/// series.
void addDiscrepancy(const Study& study, const AssemblySpec& assembly,
                    const calib::CalibrationSetup& setup,
                    const std::vector<std::vector<double>>& rows,
                    const std::vector<calib::DataSet>& train,
                    const std::vector<calib::DataSet>& sets, int threads, CompareRun& run,
                    const SayFn& say) {
  const calib::LabObjective tobj(study, assembly, train, setup);
  std::vector<diag::RoadInput> train_in, test_in;
  for (const auto& ds : train) train_in.push_back(roadInputOf(study, tobj.model().vehicle(), ds));
  std::vector<std::vector<double>> preds(rows.size());
  parallelFor(rows.size(), threads, [&](std::size_t i, int) { preds[i] = tobj.predict(rows[i]); });
  std::vector<double> mean(static_cast<std::size_t>(tobj.dataCount()), 0.0);
  double ok = 0;
  for (const auto& p : preds)
    if (!p.empty()) {
      for (std::size_t i = 0; i < p.size(); ++i) mean[i] += p[i];
      ok += 1;
    }
  if (ok == 0)
    throw std::runtime_error(
        "compare: every simulation of the posterior draws on the --discrepancy drive failed");
  for (auto& m : mean) m /= ok;
  std::vector<std::vector<double>> physics;
  std::size_t offset = 0;
  for (const auto& ds : train) {
    physics.emplace_back(mean.begin() + static_cast<long>(offset),
                         mean.begin() + static_cast<long>(offset + ds.data.records.size()));
    offset += ds.data.records.size();
  }
  for (const auto& ds : sets) test_in.push_back(roadInputOf(study, tobj.model().vehicle(), ds));
  std::vector<diag::DiscrepancyDrive> drives;
  for (std::size_t i = 0; i < train.size(); ++i)
    drives.push_back({&train[i].data, &physics[i], &train_in[i]});
  std::map<std::string, diag::DiscrepancyFilter> fitted;
  for (auto& s : run.comparison.series) {
    if (!fitted.count(s.channel)) {
      fitted.emplace(s.channel, diag::fitDiscrepancy(s.channel, drives));
      if (say) say("discrepancy for " + s.channel + ": " + fitted.at(s.channel).describe());
    }
    for (std::size_t k = 0; k < sets.size(); ++k)
      if (sets[k].name == s.data_set)
        s.discrepancy = diag::scoreDiscrepancy(fitted.at(s.channel), s.t, s.predicted_mean,
                                               sets[k].data, test_in[k]);
  }
}

/// The study as the calibration in `folder` simulated it: at the accuracy its steps were chosen
/// at (summary.json integrator_check.accuracy) when that is tighter than the study's
/// [simulation] accuracy (docs/calibration.md, "The accuracy from the data"), with a note saying
/// so; the study itself otherwise. A comparison at the looser accuracy would score the
/// integrator's error the calibration kept out of its fit.
Study asCalibrated(const Study& study, const calib::CalibrationFolder& folder,
                   std::vector<std::string>& notes) {
  const auto& s = folder.summary;
  if (!s.is_object() || !s.contains("integrator_check")) return study;
  const auto& c = s.at("integrator_check");
  if (!c.is_object() || !c.contains("accuracy") || !c.at("accuracy").is_number()) return study;
  const double accuracy = c.at("accuracy").get<double>();
  if (!(accuracy > 0.0 && accuracy < study.simulation.accuracy)) return study;
  Study at = study;
  at.simulation.accuracy = accuracy;
  notes.push_back("simulated at integrator accuracy " + formatPrintf("%.3g", accuracy) +
                  ", the accuracy the calibration chose its steps at (the study's [simulation] "
                  "accuracy " +
                  formatPrintf("%.3g", study.simulation.accuracy) +
                  " leaves an integrator error these data see)");
  return at;
}

}  // namespace

std::string CompareRun::text() const {
  const diag::Comparison& c = comparison;
  std::string out = diag::comparisonTable(c);
  for (const auto& s : c.series) {
    appendFailingWindows(s, out);
    for (const auto& b : s.bands)
      if (b.significant)
        out += formatPrintf(
            "  fails: %s %s band %s (%.1f-%.1f Hz): residual %.3g x the noise floor, coherence "
            "with the road %.2f\n",
            s.scenario.c_str(), s.channel.c_str(), b.band.c_str(), b.lo_hz, b.hi_hz, b.ratio,
            b.coherence);
    if (s.discrepancy) {
      const diag::SeriesDiscrepancy& d = *s.discrepancy;
      out += formatPrintf(
          "  discrepancy: %s %s: fit %.1f %% physics + filter, %.1f %% physics alone%s; the filter "
          "is %.0f %% of the "
          "prediction\n    %s\n",
          s.scenario.c_str(), s.channel.c_str(), d.hybrid_fit_percent, s.fit_percent,
          std::isnan(s.baseline_fit_percent)
              ? ""
              : formatPrintf(", %.1f %% FIR baseline", s.baseline_fit_percent).c_str(),
          100 * d.share, d.filter.summary.c_str());
    }
  }
  for (const auto& cm : c.maps)
    for (const auto& m : cm.maps)
      if (!m.fits.empty() && m.fits[0].explained_fraction > 0.3)
        out += formatPrintf("  state: %s vs %s: %s explains %.0f %% of the map%s\n",
                            cm.channel.c_str(), m.state.c_str(), m.fits[0].feature.c_str(),
                            100 * m.fits[0].explained_fraction,
                            m.fits[0].feature == "knee"
                                ? (" (knee at " + formatExact(m.fits[0].knee_at) + ")").c_str()
                                : "");
  for (const auto& n : c.notes) out += "  note: " + n + "\n";
  return out;
}

CompareRun compareMeasurements(const Study& study_file, const CompareRequest& request,
                               const SayFn& say) {
  checkOutFolder(request.out, "compare.out");
  const calib::CalibrationFolder folder = calib::readCalibrationFolder(request.calibration);
  std::vector<std::string> accuracy_notes;
  const Study study = asCalibrated(study_file, folder, accuracy_notes);
  CompareRun run;
  run.assembly = calib::calibratedAssembly(study, folder);
  const calib::CalibrationSetup& setup = folder.setup;
  const auto sets = loadSets(study, request.data, "--data");
  const auto discrepancy = loadSets(study, request.discrepancy, "--discrepancy");
  const calib::PosteriorSample& sample = folder.posterior;
  calib::LabObjective obj(study, run.assembly, sets, setup);
  const auto rows =
      diag::posteriorRows(sample.names, sample.theta, obj.names(), request.draws, sample.path);
  requireRoadSignal(study, obj.model().vehicle(), discrepancy);
  std::vector<StageWork> work{diag::estimateCompareWork(sets, rows.size())};
  if (!discrepancy
           .empty()) {  // the draws on the calibration drive (the run at their mean is not made)
    work.push_back(diag::estimateCompareWork(discrepancy, rows.size() - 1));
    work.back().stage = "discrepancy";
  }
  checkWork(work, "--data", request.force);
  const auto noise = diag::estimateChannelNoise(study, sets);
  if (say)
    say("comparing " + run.assembly.id + " (" + obj.model().assembly().label() + ") from " +
        request.calibration + " with " + plural(sets.size(), "measurement file") + " at " +
        std::to_string(rows.size()) + " posterior draws");
  diag::CompareOptions co;
  co.threads = request.threads;
  co.fitted_parameters = static_cast<int>(obj.names().size());
  run.comparison = diag::compareModel(obj, sets, rows, noise, co);
  for (const auto& n : accuracy_notes) run.comparison.notes.push_back(n);
  // What the calibration found of its own values: a value on its bound is no estimate.
  for (const auto& f : folder.bound_findings)
    run.comparison.notes.push_back("the calibration: " + f.sentence());
  // --discrepancy without --baseline: the FIR baseline on the discrepancy's drive, beside the
  // hybrid.
  const std::vector<std::string>& baseline =
      request.baseline.empty() ? request.discrepancy : request.baseline;
  if (!baseline.empty())
    addBaseline(
        study, obj.model().vehicle(),
        request.baseline.empty() ? discrepancy : loadSets(study, request.baseline, "--baseline"),
        sets, run, say);
  if (!discrepancy.empty())
    addDiscrepancy(study, run.assembly, setup, rows, discrepancy, sets, request.threads, run, say);
  nlohmann::json& j = run.json;
  j = run.comparison.toJson(true);
  stampProvenance(j, request.command);
  j["study"] = study.path;
  j["calibration"] = request.calibration;
  j["assembly"] = run.assembly.id;
  j["setup"] = setup.toJson();
  j["data"] = request.data;
  if (!baseline.empty()) j["baseline"] = {{"data", baseline}, {"model", run.baseline}};
  if (!discrepancy.empty()) j["discrepancy"] = {{"data", request.discrepancy}};
  if (!request.out.empty()) {
    run.written = (fs::path(request.out) / "compare.json").string();
    rootWrites(request.processes, [&] { writeFileAtomic(run.written, j.dump(2) + "\n"); });
    // The interactive page beside it, titled without absolute paths.
    std::string title = "twin compare: " + study.name + ", " + run.assembly.id + " (" +
                        run.assembly.label() + ") against";
    for (const auto& d : request.data) title += " " + fs::path(d).filename().string();
    const std::string page = (fs::path(request.out) / "compare.html").string();
    const std::string html = comparePage(run.comparison.toJson(true), title);
    rootWrites(request.processes, [&] { writeFileAtomic(page, html); });
    run.pages.push_back("wrote " + page +
                        " (zoom into the drive, the failing windows listed beside it)");
  }
  return run;
}

namespace {

/// The .toml items of `apply` replaced by the names of their [user_effects], which join `study`.
std::vector<std::string> expandApply(Study& study, const std::vector<std::string>& apply) {
  std::vector<std::string> out;
  for (const auto& a : apply) {
    if (a.size() > 5 && a.compare(a.size() - 5, 5, ".toml") == 0) {
      const auto specs = loadUserEffects(a);
      study.addUserEffects(specs);
      for (const auto& u : specs) out.push_back(u.name);
    } else {
      out.push_back(a);
    }
  }
  return out;
}

nlohmann::json optionsJson(const diag::DiagnoseOptions& o) {
  return {{"calibration", o.calibration.toJson()},
          {"candidates", o.candidates},
          {"confirm_within", o.confirm_within},
          {"causes", o.causes},
          {"screen_alpha", o.screen_alpha},
          {"bic_strong", o.bic_strong},
          {"ambiguity_log_evidence", o.ambiguity_log_evidence},
          {"full_within",
           std::isinf(o.full_within) ? nlohmann::json("all") : nlohmann::json(o.full_within)},
          {"explained_min", o.explained_min},
          {"lack_of_fit_alpha", o.lack_of_fit_alpha},
          {"compare_draws", o.compare_draws},
          {"effects", o.effects},
          {"apply", o.apply},
          {"propose_terms", o.propose_terms}};
}

/// What diagnosis.json holds: the result with how it was made.
nlohmann::json diagnosisJson(const Study& study, const DiagnoseRequest& request,
                             const DiagnoseRun& run) {
  nlohmann::json j = run.result.toJson();
  stampProvenance(j, run.options.command);
  j["study"] = study.path;
  j["data"] = request.data;
  j["holdout"] = request.holdout;
  j["options"] = optionsJson(run.options);
  return j;
}

/// diagnosis.json, proposal.toml and comparisons/*.json of a finished diagnosis, on the root rank.
void writeDiagnosis(const DiagnoseRequest& request, const DiagnoseRun& run) {
  const diag::DiagnosisResult& r = run.result;
  const fs::path out(request.out);
  rootWrites(request.options.processes, [&] {
    writeFileAtomic((out / "diagnosis.json").string(), run.json.dump(2) + "\n");
    if (!r.proposal.empty())
      writeFileAtomic((out / "proposal.toml").string(),
                      "# Proposed by twin diagnose (" + run.options.command +
                          "): paste into the study file, or pass this file to --apply.\n" +
                          r.proposalToml());
    // Full comparisons (series data for plots): the base, every confirmed candidate, every cause,
    // every step.
    writeFileAtomic((out / "comparisons" / "base.json").string(),
                    r.base.comparison.toJson(true).dump() + "\n");
    for (const auto& c : r.candidates)
      if (c.confirmed)
        writeFileAtomic((out / "comparisons" / (c.effect + ".json")).string(),
                        c.fit->comparison.toJson(true).dump() + "\n");
    for (std::size_t k = 1; k < r.causes.size(); ++k) {  // the models with the causes found in turn
      std::string name;
      for (const auto& e : r.causes[k].fit.effects) name += (name.empty() ? "" : "+") + e;
      writeFileAtomic((out / "comparisons" / (name + ".json")).string(),
                      r.causes[k].fit.comparison.toJson(true).dump() + "\n");
    }
    for (std::size_t k = 1; k < r.steps.size(); ++k) {
      std::string name;
      for (const auto& e : r.steps[k].effects) name += (name.empty() ? "" : "+") + e;
      writeFileAtomic((out / "comparisons" / (name + ".json")).string(),
                      r.steps[k].comparison.toJson(true).dump() + "\n");
    }
  });
}

/// The pages beside diagnosis.json: compare.html (the base and each cause or applied step,
/// overlaid) and report.html (needs gnuplot); a page that cannot be drawn is a note, not a
/// failure of the diagnosis.
void writeDiagnosisPages(const Study& study, const DiagnoseRequest& request, DiagnoseRun& run) {
  const fs::path out(request.out);
  try {
    const std::string page = (out / "compare.html").string();
    writeFileAtomic(page,
                    diagnosisPage(run.result, study.name + ", " + request.assembly, request.data));
    run.pages.push_back("wrote " + page +
                        " (the models overlaid: zoom into the data, the base's failing windows "
                        "listed)");
  } catch (const InputError& e) {
    run.pages.push_back(std::string("note: no interactive page (") + e.what() + ")");
  }
  try {
    const std::string html = (out / "report.html").string();
    report::writeDiagnosisReport(request.out, html, run.options.command);
    run.pages.push_back("wrote " + html);
  } catch (const InputError& e) {
    run.pages.push_back(std::string("note: no HTML report (") + e.what() + ")");
  }
}

}  // namespace

DiagnoseRun diagnoseMeasurements(const Study& base_study, const DiagnoseRequest& request,
                                 const SayFn& say, const diag::DiagnoseProgress& progress) {
  Study study = base_study;
  checkOutFolder(request.out, "diagnose.out");
  const AssemblySpec assembly = study.assembly(request.assembly);
  const auto fit = loadSets(study, request.data, "--data");
  const auto hold = loadSets(study, request.holdout, "--holdout");
  DiagnoseRun run;
  run.options = request.options;
  run.options.apply = expandApply(study, request.options.apply);
  run.options.validate();
  const auto work = diag::estimateDiagnoseWork(study, assembly, fit, hold, run.options);
  checkWork(work, "--data", request.force);
  const std::string out =
      request.out.empty()
          ? (fs::temp_directory_path() / ("twin-diagnose-" + std::to_string(::getpid()))).string()
          : request.out;
  if (say) {
    std::size_t records = 0;
    for (const auto& s : fit) records += s.data.records.size();
    say("diagnosing " + assembly.id + " (" + assembly.label() + ") on " +
        plural(fit.size(), "measurement file") + " (" + std::to_string(records) + " records)" +
        (hold.empty() ? "" : ", " + std::to_string(hold.size()) + " held out") +
        "; calibrations in " + (fs::path(out) / "calibrations").string());
    double sims = 0, simulated = 0;
    for (const auto& w : work) {
      sims += w.simulations;
      simulated += w.simulated_s;
    }
    say("budget: at most " +
        plural(static_cast<std::size_t>(run.options.candidates), "confirmation") + " per round, " +
        std::to_string(run.options.confirm_rounds) + " rounds per stage, " +
        plural(static_cast<std::size_t>(run.options.causes), "cause") +
        " (--candidates, --causes); estimate with one round per stage " +
        formatPrintf("%.3g simulations, %.3g simulated s", sims, simulated));
  }
  run.result = diag::diagnose(study, assembly, fit, hold, run.options, out, progress);
  run.json = diagnosisJson(study, request, run);
  if (!request.out.empty()) {
    writeDiagnosis(request, run);
    run.written = (fs::path(request.out) / "diagnosis.json").string();
    if (isRootProcess(request.options.processes)) writeDiagnosisPages(study, request, run);
  }
  return run;
}

}  // namespace dtwin
