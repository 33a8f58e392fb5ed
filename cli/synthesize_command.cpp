// `twin synthesize`: synthetic field data of calibrated assemblies (posterior draws on library
// roads, plus noise), accumulated as streaming moments. Parses, calls study/synthesize.hpp, prints.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/folder_lock.hpp"
#include "study/request.hpp"
#include "study/synthesize.hpp"

namespace fs = std::filesystem;

namespace dtwin::cli {
namespace {

struct SynthesizeConfig {
  const Distributed* processes = nullptr;  ///< the process context (CommandContext)
  std::string study = defaultStudy(), calibration, assembly = "all", out, scenario = "field",
              channel = "hub_force_fl_N";
  long draws = 0, roads = 0, library = 0, block = 16, leaf_blocks = 2;
  int threads = 0;
  std::optional<std::uint64_t> seed;  ///< unset: the study's
  std::vector<double> window;
  bool no_branch = false, no_fourth = false, quiet = false, force = false;
};

int runSynthesize(const SynthesizeConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  SynthesizeRequest req;
  req.calibration = cfg.calibration;
  req.assembly = cfg.assembly;
  req.out = cfg.out;
  req.force = cfg.force;
  classify::SynthesisOptions& opt = req.options;
  opt.draws = cfg.draws;
  opt.roads_per_draw = cfg.roads;
  opt.road_library = cfg.library;
  opt.block = cfg.block;
  opt.leaf_blocks = cfg.leaf_blocks;
  opt.threads = cfg.threads;
  opt.processes = cfg.processes;
  if (cfg.seed) opt.seed = *cfg.seed;
  opt.scenario = cfg.scenario;
  opt.channel = cfg.channel;
  applyTimeWindow(cfg.window, opt.t_begin_s, opt.t_end_s);
  opt.branch = !cfg.no_branch;
  opt.track_fourth_moment = !cfg.no_fourth;
  opt.command = command;

  const FolderLock lock(cfg.out, "--out", cfg.processes);  // one run at a time in the folder
  const bool bar_on = progressOn(cfg.quiet, cfg.processes);
  std::unique_ptr<ProgressBar> bar;  // one per assembly, as it starts
  std::string stage;
  synthesizeAssemblies(
      study, req,
      [&](const std::string& s, std::size_t done, std::size_t total) {
        if (!bar || s != stage) {
          bar.reset();
          stage = s;
          bar = std::make_unique<ProgressBar>(s, bar_on, stderrIsTerminal());
        }
        bar->update(done, total);
      },
      [&](const SynthesizeRun& run) {
        bar.reset();
        if (!cfg.quiet) std::fputs(run.text().c_str(), stdout);
      });
  return 0;
}

}  // namespace

CommandHandle addSynthesizeCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<SynthesizeConfig>();
  cfg->processes = context.processes;
  auto* c = addSubcommand(root, "synthesize");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option("--calibration", cfg->calibration,
                "Folder written by twin calibrate (reads DIR/<id>/posterior.csv)")
      ->required();
  c->add_option("--assembly", cfg->assembly, "Assembly id (M1, M2, ...) or 'all'")
      ->capture_default_str();
  c->add_option("--out", cfg->out,
                "Output folder: OUT/<id>/moments.bin and OUT/<id>/synthesis.json per assembly, and "
                "OUT/synthesize.json listing them; a "
                "rerun into it resumes")
      ->required();
  c->add_option("--draws", cfg->draws,
                "Posterior draws M (default: the study's sizes.posterior_draws)")
      ->check(CLI::Range(1L, 100000000L));
  c->add_option("--roads", cfg->roads, "Roads per draw R (default: sizes.roads_per_draw)")
      ->check(CLI::Range(1L, 100000L));
  c->add_option("--library", cfg->library, "Road library size L >= R (default: sizes.road_library)")
      ->check(CLI::Range(1L, 1000000000L));
  c->add_option("--block", cfg->block,
                "Draws per accumulation block (part of the result's definition)")
      ->capture_default_str()
      ->check(CLI::Range(1L, 100000L));
  c->add_option("--leaf-blocks", cfg->leaf_blocks,
                "Blocks per leaf of the fixed accumulation tree (part of the result's definition)")
      ->capture_default_str()
      ->check(CLI::Range(1L, 100000L));
  c->add_option("--threads", cfg->threads,
                "Worker threads (0: all cores; never changes the result)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  addSeedOption(c, cfg->seed, "Seed of draws, roads and noise (default: the study's seed)");
  c->add_option("--scenario", cfg->scenario, "Scenario with a random road")->capture_default_str();
  c->add_option("--channel", cfg->channel, "Channel kept")->capture_default_str();
  c->add_option("--window", cfg->window, "Time window kept, T0,T1 [s] (default 10,15)")
      ->delimiter(',')
      ->expected(2);
  c->add_flag("--no-branch", cfg->no_branch,
              "Simulate every road from t = 0 (default: the smooth start once per draw)");
  c->add_flag("--no-fourth-moment", cfg->no_fourth,
              "Do not accumulate the moments Ledoit-Wolf needs");
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success (no progress bar)");
  addForceOption(c, cfg->force);
  addExamples(
      c, {"twin synthesize --study data/studies/demo.toml --calibration out/calibration --assembly "
          "M3 --draws 4 --roads 2 --library 8 --window 10,10.05 --out out/synthetic",
          "twin synthesize --study data/studies/demo.toml --calibration out/calibration --assembly "
          "M4 --draws 4 --roads 2 --library 8 --window 10,10.05 --out out/synthetic"});
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
