#include <cstdio>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "study/export_fmu.hpp"
#include "study/request.hpp"

namespace dtwin::cli {
namespace {

struct ExportFmuConfig {
  std::string study = defaultStudy(), calibration, assembly, out, binaries;
  std::vector<std::string> sets, effects;
  std::optional<long> draw;
  double step = 1e-3, stop_time = 10.0;
  bool quiet = false;
};

int runExportFmu(const ExportFmuConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  ExportFmuRequest req;
  req.calibration = cfg.calibration;
  req.assembly = cfg.assembly;
  req.out = cfg.out;
  req.draw = cfg.draw;
  req.binaries = cfg.binaries;
  req.step_size_s = cfg.step;
  req.stop_time_s = cfg.stop_time;
  for (const auto& s : cfg.sets) req.sets.push_back(parseSetting(s, "--set"));
  for (const auto& e : cfg.effects)
    req.effects.push_back(parseEffectSetting(e, "--effect", study.effectCatalog()));
  req.command = command;
  const ExportFmuResult r = exportFmu(study, req);
  if (!cfg.quiet) std::fputs(r.text().c_str(), stdout);
  return 0;
}

}  // namespace

CommandHandle addExportFmuCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<ExportFmuConfig>();
  ExportFmuConfig& c = *cfg;
  auto* s = addSubcommand(root, "export-fmu");
  s->add_option("--study", c.study, "Study file (TOML)")->capture_default_str();
  s->add_option("--calibration", c.calibration,
                "Calibration folder (`twin calibrate`'s OUT/<id>): the FMU starts from its values");
  s->add_option("--assembly", c.assembly,
                "Assembly id (M1, ...): required without --calibration (the study's values then)");
  s->add_option("--draw", c.draw,
                "A posterior draw (row of posterior.csv, from 0) instead of the optimum");
  s->add_option("--out", c.out, "The .fmu file to write")->required();
  s->add_option("--set", c.sets, "Override a parameter: NAME=VALUE; repeatable");
  s->add_option("--effect", c.effects, "Add an effect: NAME[:param=value,...]; repeatable");
  s->add_option("--step", c.step, "The default communication step [s] of the FMU's experiment")
      ->capture_default_str();
  s->add_option("--stop-time", c.stop_time, "The default stop time [s] of the FMU's experiment")
      ->capture_default_str();
  s->add_option(
      "--binaries", c.binaries,
      "Folder of the FMU runtime (dtwin_fmu.so and its libraries); default: this build's");
  s->add_flag("--quiet", c.quiet, "Print nothing on success");
  addExamples(s,
              {"twin export-fmu --study data/studies/demo.toml --calibration out/calibration_rr/M1 "
               "--out out/m1.fmu",
               "twin export-fmu --study data/studies/demo.toml --assembly M1 --effect "
               "skyhook:damping=2500 --out out/m1_skyhook.fmu"});
  CommandHandle handle{s, [cfg, command_line] { return runExportFmu(*cfg, command_line); }};
  handle.field_flags = {{"effects", "--effect"}, {"step", "--step"}, {"stop-time", "--stop-time"}};
  return handle;
}

}  // namespace dtwin::cli
