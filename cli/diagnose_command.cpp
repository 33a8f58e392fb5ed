// `twin compare` and `twin diagnose` (diagnosis/compare.hpp, diagnosis/diagnose.hpp,
// docs/diagnosis.md): the model against measurements, where it fails, which effect is missing.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numeric>

#include "calibration/calibrate.hpp"
#include "calibration/folder.hpp"
#include "classification/synthesis.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "diagnosis/compare.hpp"
#include "diagnosis/diagnose.hpp"
#include "report/diagnosis_report.hpp"
#include "diagnosis/measurements.hpp"
#include "common/errors.hpp"
#include "twin/distributed.hpp"
#include "io/provenance.hpp"
#include "io/study.hpp"

namespace fs = std::filesystem;

namespace dtwin::cli {
namespace {

std::vector<calib::DataSet> loadSets(const Study& study, const std::vector<std::string>& args, const std::string& flag) {
  std::vector<calib::DataSet> sets;
  for (const auto& a : args) sets.push_back(diag::loadMeasurement(study, diag::parseMeasurementArg(a, flag)));
  return sets;
}

void checkOutFolder(const std::string& out) {
  if (!out.empty() && fs::exists(out) && !fs::is_directory(out)) throw InputError("--out", "'" + out + "' exists and is not a folder");
}

// ------------------------------------------------------------------ compare
struct CompareConfig {
  std::string study = defaultStudy(), calibration, out;
  std::vector<std::string> data;
  int draws = 30, threads = 0;
  bool quiet = false, force = false;
};

int runCompare(const CompareConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  checkOutFolder(cfg.out);
  const calib::CalibrationFolder folder = calib::readCalibrationFolder(cfg.calibration);
  const AssemblySpec assembly = calib::calibratedAssembly(study, folder);
  const calib::CalibrationSetup& setup = folder.setup;
  const auto sets = loadSets(study, cfg.data, "--data");
  const calib::PosteriorSample& sample = folder.posterior;
  calib::LabObjective obj(study, assembly, sets, setup);
  const auto rows = diag::posteriorRows(sample.names, sample.theta, obj.names(), cfg.draws, sample.path);
  checkWork({diag::estimateCompareWork(sets, rows.size())}, "--data", cfg.force);
  const auto noise = diag::estimateChannelNoise(study, sets);
  if (!cfg.quiet)
    std::printf("comparing %s (%s) from %s with %zu measurement file%s at %zu posterior draws\n", assembly.id.c_str(),
                obj.model().assembly().label().c_str(), cfg.calibration.c_str(), sets.size(), sets.size() == 1 ? "" : "s",
                rows.size());
  diag::CompareOptions co;
  co.threads = cfg.threads;
  co.fitted_parameters = static_cast<int>(obj.names().size());
  const auto c = diag::compareModel(obj, sets, rows, noise, co);
  if (!cfg.quiet) {
    std::printf("%s", diag::comparisonTable(c).c_str());
    constexpr std::size_t kWindowsShown = 8;  // the rest are in compare.json
    for (const auto& s : c.series) {
      // The windows that hold the most of the residual, in time order; a long drive may have hundreds.
      std::vector<std::size_t> order(s.windows.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.windows[a].window.share > s.windows[b].window.share; });
      const std::size_t shown = std::min(order.size(), kWindowsShown);
      std::sort(order.begin(), order.begin() + static_cast<long>(shown));
      for (std::size_t k = 0; k < shown; ++k) {
        const auto& w = s.windows[order[k]];
        std::printf("  fails: %s %s %.3f-%.3f s, peak |z| %.1f, %.0f %% of its residual: %s (%.1f m/s)\n", s.scenario.c_str(),
                    s.channel.c_str(), w.window.t_begin, w.window.t_end, w.window.peak_z, 100 * w.window.share, w.label.c_str(),
                    w.speed_mps);
      }
      if (order.size() > shown) {
        double rest = 0.0;
        for (std::size_t k = shown; k < order.size(); ++k) rest += s.windows[order[k]].window.share;
        std::printf("  fails: %s %s in %zu more windows holding %.0f %% of its residual (--out: compare.json lists every window)\n",
                    s.scenario.c_str(), s.channel.c_str(), order.size() - shown, 100 * rest);
      }
      for (const auto& b : s.bands)
        if (b.significant)
          std::printf("  fails: %s %s band %s (%.1f-%.1f Hz): residual %.3g x the noise floor, coherence with the road %.2f\n",
                      s.scenario.c_str(), s.channel.c_str(), b.band.c_str(), b.lo_hz, b.hi_hz, b.ratio, b.coherence);
    }
    for (const auto& cm : c.maps)
      for (const auto& m : cm.maps)
        if (!m.fits.empty() && m.fits[0].explained_fraction > 0.3)
          std::printf("  state: %s vs %s: %s explains %.0f %% of the map%s\n", cm.channel.c_str(), m.state.c_str(),
                      m.fits[0].feature.c_str(), 100 * m.fits[0].explained_fraction,
                      m.fits[0].feature == "knee" ? (" (knee at " + formatExact(m.fits[0].knee_at) + ")").c_str() : "");
    for (const auto& n : c.notes) std::printf("  note: %s\n", n.c_str());
  }
  if (!cfg.out.empty()) {
    nlohmann::json j = c.toJson(true);
    j["program"] = programInfo();
    j["command"] = command;
    j["created_utc"] = utcNow();
    j["study"] = study.path;
    j["calibration"] = cfg.calibration;
    j["assembly"] = assembly.id;
    j["setup"] = setup.toJson();
    j["data"] = cfg.data;
    rootWrites([&] { writeFileAtomic((fs::path(cfg.out) / "compare.json").string(), j.dump(2) + "\n"); });
    if (!cfg.quiet) std::printf("wrote %s\n", (fs::path(cfg.out) / "compare.json").string().c_str());
  }
  return 0;
}

// ------------------------------------------------------------------ diagnose
struct DiagnoseConfig {
  std::string study = defaultStudy(), assembly = "M1", out;
  std::vector<std::string> data, holdout, effects, apply;
  int threads = 0, candidates = 3, draws = 20, propose = 3;
  long lhs_points = -1, iterations = -1, burn_in = -1, starts = -1;
  std::string steps;
  bool quiet = false, force = false, all_intervals = false;
};

std::vector<std::string> splitCommas(const std::vector<std::string>& v) {
  std::vector<std::string> out;
  for (const auto& s : v) {
    std::size_t a = 0;
    while (a <= s.size()) {
      const auto b = s.find(',', a);
      const std::string part = s.substr(a, b == std::string::npos ? std::string::npos : b - a);
      if (!part.empty()) out.push_back(part);
      if (b == std::string::npos) break;
      a = b + 1;
    }
  }
  return out;
}

int runDiagnose(const DiagnoseConfig& cfg, const std::string& command) {
  Study study = loadStudy(cfg.study);
  checkOutFolder(cfg.out);
  const AssemblySpec assembly = study.assembly(cfg.assembly);
  const auto fit = loadSets(study, cfg.data, "--data");
  const auto hold = loadSets(study, cfg.holdout, "--holdout");
  diag::DiagnoseOptions o;
  o.calibration = calib::CalibrationOptions::fromStudy(study);
  if (cfg.lhs_points > 0) o.calibration.lhs_points = static_cast<int>(cfg.lhs_points);
  if (cfg.iterations > 0) o.calibration.gibbs_iterations = static_cast<int>(cfg.iterations);
  if (cfg.burn_in >= 0) o.calibration.gibbs_burn_in = static_cast<int>(cfg.burn_in);
  if (cfg.starts > 0) o.calibration.optimizer_starts = static_cast<int>(cfg.starts);
  if (!cfg.steps.empty()) o.calibration.steps = cfg.steps;
  if (o.calibration.gibbs_burn_in >= o.calibration.gibbs_iterations)
    throw InputError("--burn-in", "must be below the number of iterations (" + std::to_string(o.calibration.gibbs_iterations) + ")");
  o.calibration.validate();
  o.candidates = cfg.candidates;
  if (cfg.all_intervals) o.full_within = std::numeric_limits<double>::infinity();
  o.propose_terms = cfg.propose;
  o.compare_draws = cfg.draws;
  o.effects = splitCommas(cfg.effects);
  // An --apply item that is a .toml file (e.g. a diagnosis's proposal.toml): its [user_effects]
  // join the study's effects and are applied in their order.
  for (const auto& a : splitCommas(cfg.apply)) {
    if (a.size() > 5 && a.compare(a.size() - 5, 5, ".toml") == 0) {
      const auto specs = loadUserEffects(a);
      study.addUserEffects(specs);
      for (const auto& u : specs) o.apply.push_back(u.name);
    } else {
      o.apply.push_back(a);
    }
  }
  o.threads = cfg.threads;
  o.command = command;
  o.validate();
  checkWork(diag::estimateDiagnoseWork(study, assembly, fit, hold, o), "--data", cfg.force);
  const std::string out = cfg.out.empty() ? (fs::temp_directory_path() / ("twin-diagnose-" + std::to_string(::getpid()))).string() : cfg.out;
  const bool bar_on = progressOn(cfg.quiet);
  if (!cfg.quiet) {
    std::size_t records = 0;
    for (const auto& s : fit) records += s.data.records.size();
    std::printf("diagnosing %s (%s) on %zu measurement file%s (%zu records)%s; calibrations in %s\n", assembly.id.c_str(),
                assembly.label().c_str(), fit.size(), fit.size() == 1 ? "" : "s", records,
                hold.empty() ? "" : (", " + std::to_string(hold.size()) + " held out").c_str(), (fs::path(out) / "calibrations").string().c_str());
  }
  ProgressBar bar("diagnose", bar_on, stderrIsTerminal());
  std::string current;
  const auto r = diag::diagnose(study, assembly, fit, hold, o, out, [&](const std::string& stage, std::size_t d, std::size_t t) {
    if (stage != current) {
      current = stage;
      bar.restart(stage);
    }
    bar.update(d, t);
  });
  bar.finish();
  if (!cfg.quiet) std::printf("%s", r.text().c_str());
  if (!cfg.out.empty()) {
    nlohmann::json j = r.toJson();
    j["program"] = programInfo();
    j["command"] = command;
    j["created_utc"] = utcNow();
    j["study"] = study.path;
    j["data"] = cfg.data;
    j["holdout"] = cfg.holdout;
    j["options"] = {{"calibration", o.calibration.toJson()}, {"candidates", o.candidates}, {"screen_alpha", o.screen_alpha},
                    {"bic_strong", o.bic_strong}, {"ambiguity_log_evidence", o.ambiguity_log_evidence},
                    {"full_within", std::isinf(o.full_within) ? nlohmann::json("all") : nlohmann::json(o.full_within)},
                    {"explained_min", o.explained_min}, {"lack_of_fit_alpha", o.lack_of_fit_alpha}, {"compare_draws", o.compare_draws},
                    {"effects", o.effects}, {"apply", o.apply}, {"propose_terms", o.propose_terms}};
    rootWrites([&] {
      writeFileAtomic((fs::path(cfg.out) / "diagnosis.json").string(), j.dump(2) + "\n");
      if (!r.proposal.empty())
        writeFileAtomic((fs::path(cfg.out) / "proposal.toml").string(),
                        "# Proposed by twin diagnose (" + command + "): paste into the study file, or pass this file to --apply.\n" +
                            r.proposalToml());
      // Full comparisons (series data for plots): the base, every confirmed candidate, every step.
      writeFileAtomic((fs::path(cfg.out) / "comparisons" / "base.json").string(), r.base.comparison.toJson(true).dump() + "\n");
      for (const auto& c : r.candidates)
        if (c.confirmed)
          writeFileAtomic((fs::path(cfg.out) / "comparisons" / (c.effect + ".json")).string(), c.fit->comparison.toJson(true).dump() + "\n");
      for (std::size_t k = 1; k < r.steps.size(); ++k) {
        std::string name;
        for (const auto& e : r.steps[k].effects) name += (name.empty() ? "" : "+") + e;
        writeFileAtomic((fs::path(cfg.out) / "comparisons" / (name + ".json")).string(), r.steps[k].comparison.toJson(true).dump() + "\n");
      }
    });
    if (!cfg.quiet) std::printf("\nwrote %s\n", (fs::path(cfg.out) / "diagnosis.json").string().c_str());
    // The HTML page (overlays, band powers, force-state map, waterfall); needs gnuplot.
    if (isRootRank()) {
      const std::string html = (fs::path(cfg.out) / "report.html").string();
      try {
        report::writeDiagnosisReport(cfg.out, html, command);
        if (!cfg.quiet) std::printf("wrote %s\n", html.c_str());
      } catch (const InputError& e) {
        std::printf("note: no HTML report (%s)\n", e.what());
      }
    }
  }
  return 0;
}

}  // namespace

CommandHandle addCompareCommand(CLI::App& root, const std::string& command_line) {
  auto cfg = std::make_shared<CompareConfig>();
  auto* c = addSubcommand(root, "compare");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option("--calibration", cfg->calibration,
                "Calibration folder (summary.json + posterior.csv) from `twin calibrate` (OUT/<id>) or `twin diagnose` "
                "(OUT/calibrations/<name>)")
      ->required();
  c->add_option("--data", cfg->data, "Measurement file FILE[@SCENARIO] (tidy lab layout); repeatable")->required();
  c->add_option("--draws", cfg->draws, "Posterior rows (evenly spaced) for the predictive band")->capture_default_str()->check(CLI::Range(1, 100000));
  c->add_option("--threads", cfg->threads, "Worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, 1024));
  c->add_option("--out", cfg->out, "Folder for compare.json (figures and the overlay series)");
  addForceOption(c, cfg->force);
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  return {c, [cfg, command_line] { return runCompare(*cfg, command_line); }};
}

CommandHandle addDiagnoseCommand(CLI::App& root, const std::string& command_line) {
  auto cfg = std::make_shared<DiagnoseConfig>();
  auto* c = addSubcommand(root, "diagnose");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option("--assembly", cfg->assembly, "Assembly id (M1, M2, ...)")->capture_default_str();
  c->add_option("--data", cfg->data, "Measurement file FILE[@SCENARIO] to fit (tidy lab layout); repeatable")->required();
  c->add_option("--holdout", cfg->holdout, "Held-out measurement file FILE[@SCENARIO] (not fitted; error reported); repeatable");
  c->add_option("--effects", cfg->effects,
                "Only rank these candidates (comma separated): effects, free:<vehicle value> (e.g. free:wheel.mass_kg) or "
                "<lowpass|lowpass2|gain|delay>:<channel group> (e.g. lowpass:hub_force); default: every effect not installed, "
                "every freeable vehicle value and every sensor model (docs/diagnosis.md)");
  c->add_option("--apply", cfg->apply,
                "Add these candidates in turn (comma separated) and print the before/after table; a .toml file (e.g. a diagnosis's "
                "proposal.toml) adds its [user_effects]");
  c->add_option("--candidates", cfg->candidates, "Screened effects confirmed by re-calibration (at most)")->capture_default_str()->check(CLI::Range(0, 100));
  c->add_flag("--all-intervals", cfg->all_intervals,
             "Calibrate every confirmed candidate in full (intervals, posterior comparison); by default only those within 10 of "
             "the best candidate's log evidence are, the others stop at their optimum");
  c->add_option("--propose", cfg->propose, "When unexplained: propose at most this many library terms (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 3));
  c->add_option("--draws", cfg->draws, "Posterior rows per comparison")->capture_default_str()->check(CLI::Range(1, 100000));
  c->add_option("--threads", cfg->threads, "Worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, 1024));
  c->add_option("--lhs-points", cfg->lhs_points, "Design points per calibration (default: sizes.lhs_points)")->check(CLI::Range(2L, 10000000L));
  c->add_option("--iterations", cfg->iterations, "Gibbs iterations (default: sizes.gibbs_iterations)")->check(CLI::Range(1L, 100000000L));
  c->add_option("--burn-in", cfg->burn_in, "Gibbs burn-in (default: sizes.gibbs_burn_in)")->check(CLI::Range(0L, 100000000L));
  c->add_option("--starts", cfg->starts, "Optimiser starts (default: sizes.optimizer_starts)")->check(CLI::Range(1L, 10000L));
  c->add_option("--steps", cfg->steps,
                "Integrator steps of every calibration: frozen (a smooth SSE, the accuracy chosen from the data) or adaptive; "
                "default: the study's [calibration] steps")
      ->check(CLI::IsMember({"frozen", "adaptive"}));
  c->add_option("--out", cfg->out, "Folder: diagnosis.json, comparisons/, calibrations/ (resumable)");
  addForceOption(c, cfg->force);
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  CommandHandle handle{c, [cfg, command_line] { return runDiagnose(*cfg, command_line); }, {}};
  // Library errors name DiagnoseOptions fields and diagnose()'s arguments ("diagnose.compare_draws");
  // the fields whose flag is not "--" + the field with '_' as '-':
  handle.field_flags["compare_draws"] = "--draws";
  handle.field_flags["fit"] = "--data";
  return handle;
}

}  // namespace dtwin::cli
