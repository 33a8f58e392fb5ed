// `twin synthesize`: synthetic field data of calibrated assemblies (posterior draws on library
// roads, plus noise), accumulated as streaming moments (classification/synthesis.hpp).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "classification/synthesis.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/errors.hpp"
#include "twin/distributed.hpp"
#include "io/provenance.hpp"
#include "io/study.hpp"

namespace fs = std::filesystem;

namespace dtwin::cli {
namespace {

struct SynthesizeConfig {
  std::string study = defaultStudy(), calibration, assembly = "all", out, scenario = "field", channel = "hub_force_fl_N";
  long draws = 0, roads = 0, library = 0, block = 16, leaf_blocks = 2;
  int threads = 0;
  std::optional<std::uint64_t> seed;  ///< unset: the study's
  std::vector<double> window;
  bool no_branch = false, no_fourth = false, quiet = false, force = false;
};

int runSynthesize(const SynthesizeConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  study.scenario(cfg.scenario);  // validates the name
  std::vector<AssemblySpec> targets;
  if (cfg.assembly == "all") targets = study.assemblies();
  else targets.push_back(study.assembly(cfg.assembly));
  if (!fs::is_directory(cfg.calibration)) throw InputError(cfg.calibration, "calibration folder not found (--calibration)");
  if (fs::exists(cfg.out) && !fs::is_directory(cfg.out)) throw InputError("--out", "'" + cfg.out + "' exists and is not a folder");
  {
    Study sized = study;
    overrideSize(sized, "posterior_draws", cfg.draws, "--draws");
    overrideSize(sized, "roads_per_draw", cfg.roads, "--roads");
    overrideSize(sized, "road_library", cfg.library, "--library");
    std::vector<std::string> stages;
    for (const auto& a : targets) stages.push_back("synthesize " + a.id);
    checkCommandWork(sized, stages, cfg.force);
  }
  // Read every posterior first: a missing or malformed one stops before any simulation.
  std::vector<calib::PosteriorSample> posteriors;
  for (const auto& a : targets) {
    const std::string p = (fs::path(cfg.calibration) / a.id / "posterior.csv").string();
    if (!fs::exists(p))
      throw InputError(p, "not found: calibrate assembly " + a.id + " first (twin calibrate --assembly " + a.id + ")");
    posteriors.push_back(calib::readPosteriorCsv(p));
  }
  classify::SynthesisOptions opt;
  opt.draws = cfg.draws;
  opt.roads_per_draw = cfg.roads;
  opt.road_library = cfg.library;
  opt.block = cfg.block;
  opt.leaf_blocks = cfg.leaf_blocks;
  opt.threads = cfg.threads;
  if (cfg.seed) opt.seed = *cfg.seed;
  opt.scenario = cfg.scenario;
  opt.channel = cfg.channel;
  if (!cfg.window.empty()) {
    if (cfg.window.size() != 2 || !(cfg.window[0] < cfg.window[1])) throw InputError("--window", "expects T0,T1 with T0 < T1");
    opt.t_begin_s = cfg.window[0];
    opt.t_end_s = cfg.window[1];
  }
  opt.branch = !cfg.no_branch;
  opt.track_fourth_moment = !cfg.no_fourth;
  opt.command = command;

  const bool bar_on = progressOn(cfg.quiet);
  nlohmann::json index;
  index["program"] = programInfo();
  index["command"] = command;
  index["created_utc"] = utcNow();
  index["study"] = study.path;
  index["calibration"] = cfg.calibration;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const auto& a = targets[i];
    const std::string dir = (fs::path(cfg.out) / a.id).string();
    classify::SynthesisResult r;
    {
      ProgressBar bar(a.id + " synthesize", bar_on, stderrIsTerminal());
      r = classify::synthesizeAssembly(study, a, posteriors[i], opt, dir,
                                       [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    }
    index["assemblies"].push_back({{"assembly", a.id}, {"label", a.label()}, {"synthesis", (fs::path(a.id) / "synthesis.json").string()},
                                   {"moments", (fs::path(a.id) / "moments.bin").string()}});
    if (!cfg.quiet) {
      const auto& j = r.info;
      std::printf("%-4s %-24s %ld draws x %ld roads (library %ld) -> %lld vectors of %zu samples (%s %g..%g s), failures %ld, "
                  "cost %.4g s/s (median run %.3f s), %s%.1f s -> %s\n",
                  a.id.c_str(), a.label().c_str(), r.draws, r.roads_per_draw, r.road_library, static_cast<long long>(r.moments.count()),
                  r.times_s.size(), j["channel"].get<std::string>().c_str(), r.times_s.front(), r.times_s.back(), r.failures,
                  r.cost_s_per_s, r.median_run_wall_s,
                  r.reused ? "reused finished files, " : (r.resumed_blocks ? ("resumed at block " + std::to_string(r.resumed_blocks) + ", ").c_str() : ""),
                  r.wall_s, (fs::path(dir) / "moments.bin").string().c_str());
      for (std::size_t k = 0; k < r.failure_list.size() && k < 5; ++k)
        std::printf("       failed: draw %ld road %ld (library road %ld, seed %llu): %s\n", r.failure_list[k].draw, r.failure_list[k].road,
                    r.failure_list[k].library_index, static_cast<unsigned long long>(r.failure_list[k].road_seed),
                    r.failure_list[k].message.c_str());
    }
  }
  rootWrites([&] { writeFileAtomic((fs::path(cfg.out) / "synthesize.json").string(), index.dump(2) + "\n"); });
  return 0;
}

}  // namespace

CommandHandle addSynthesizeCommand(CLI::App& root, const std::string& command_line) {
  auto cfg = std::make_shared<SynthesizeConfig>();
  auto* c = addSubcommand(root, "synthesize");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option("--calibration", cfg->calibration, "Folder written by twin calibrate (reads DIR/<id>/posterior.csv)")->required();
  c->add_option("--assembly", cfg->assembly, "Assembly id (M1, M2, ...) or 'all'")->capture_default_str();
  c->add_option("--out", cfg->out, "Output folder: OUT/<id>/moments.bin and OUT/<id>/synthesis.json per assembly, and OUT/synthesize.json listing them; a "
                "rerun into it resumes")->required();
  c->add_option("--draws", cfg->draws, "Posterior draws M (default: the study's sizes.posterior_draws)")->check(CLI::Range(1L, 100000000L));
  c->add_option("--roads", cfg->roads, "Roads per draw R (default: sizes.roads_per_draw)")->check(CLI::Range(1L, 100000L));
  c->add_option("--library", cfg->library, "Road library size L >= R (default: sizes.road_library)")->check(CLI::Range(1L, 1000000000L));
  c->add_option("--block", cfg->block, "Draws per accumulation block (part of the result's definition)")
      ->capture_default_str()->check(CLI::Range(1L, 100000L));
  c->add_option("--leaf-blocks", cfg->leaf_blocks,
                "Blocks per leaf of the fixed accumulation tree (part of the result's definition)")
      ->capture_default_str()->check(CLI::Range(1L, 100000L));
  c->add_option("--threads", cfg->threads, "Worker threads (0: all cores; never changes the result)")
      ->capture_default_str()->check(CLI::Range(0, 1024));
  addSeedOption(c, cfg->seed, "Seed of draws, roads and noise (default: the study's seed)");
  c->add_option("--scenario", cfg->scenario, "Scenario with a random road")->capture_default_str();
  c->add_option("--channel", cfg->channel, "Channel kept")->capture_default_str();
  c->add_option("--window", cfg->window, "Time window kept, T0,T1 [s] (default 10,15)")->delimiter(',')->expected(2);
  c->add_flag("--no-branch", cfg->no_branch, "Simulate every road from t = 0 (default: the smooth start once per draw)");
  c->add_flag("--no-fourth-moment", cfg->no_fourth, "Do not accumulate the moments Ledoit-Wolf needs");
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success (no progress bar)");
  addForceOption(c, cfg->force);
  addExamples(c, {
               "twin synthesize --study data/studies/demo.toml --calibration out/calibration --assembly M3 --draws 4 --roads 2 --library 8 --window 10,10.05 --out out/synthetic",
               "twin synthesize --study data/studies/demo.toml --calibration out/calibration --assembly M4 --draws 4 --roads 2 --library 8 --window 10,10.05 --out out/synthetic"});
  CommandHandle handle{c, [cfg, command_line] { return runSynthesize(*cfg, command_line); }, {}};
  // Library errors name SynthesisOptions fields ("synthesis.road_library"); the fields whose flag
  // is not "--" + the field with '_' as '-':
  handle.field_flags["roads_per_draw"] = "--roads";
  handle.field_flags["road_library"] = "--library";
  handle.field_flags["t_begin_s"] = "--window";
  handle.field_flags["t_end_s"] = "--window";
  return handle;
}

}  // namespace dtwin::cli
