// The registry of `twin`'s subcommands (cli/commands.hpp): each name with its description, what
// adds it to the root application, and whether it runs on every MPI rank.
#include "cli/commands.hpp"

namespace dtwin::cli {

const Registry<CommandEntry>& commandRegistry() {
  // One line per command, in the order `twin --help` lists them. A new command: its file
  // cli/<name>_command.cpp with add<Name>Command (declared in cli/commands.hpp), its line here, and
  // the file in cli/CMakeLists.txt.
  static const Registry<CommandEntry> r(
      "command",
      {
          {"simulate", "Simulate one assembly (or all) over one scenario; writes a CSV trace and a JSON sidecar",
           {&addSimulateCommand, false}},
          {"list", "Show the assemblies, scenarios, calibrated parameters, effects and channels a study defines",
           {&addListCommand, false}},
          {"bench", "Measure wall time per 15 s run for every assembly on the bump and the rough road",
           {&addBenchCommand, false}},
          {"generate", "Make synthetic measurements: lab data (condensed, repeated) or field data (random roads)",
           {&addGenerateCommand, true}},
          {"calibrate", "Calibrate assemblies against lab data: NLopt optimum, feasible box, Latin hypercube design, two-block Griddy Gibbs (resumable: rerun the same command to continue)",
           {&addCalibrateCommand, true}},
          {"coverage", "Measure how often the calibration's 95 % intervals hold the truth: each assembly's own lab data over N noise seeds, calibrated as `twin calibrate` would (resumable: rerun the same command to continue)",
           {&addCoverageCommand, false}},
          {"synthesize", "Synthetic field data per calibrated assembly: posterior draws, each on R roads of a seeded road library, plus noise N(0, 1/tau); the window's mean and covariance are accumulated (resumable: rerun the same command to continue)",
           {&addSynthesizeCommand, true}},
          {"classify", "Classify field records among synthesized assemblies (Gaussian likelihood per assembly, posterior probabilities, Bayes factors) and recommend the cheapest assembly not decisively worse",
           {&addClassifyCommand, false}},
          {"study", "Run the whole method: lab and field data, calibrate every assembly, synthesise field data, classify, recommend (resumable: rerun the same command to continue)",
           {&addStudyCommand, true}},
          {"report", "Write a self-contained HTML report of a study folder (lab data vs posterior predictive bands, posteriors, field-record selection, evidence vs cost, provenance) and/or of diagnosis folders; needs gnuplot",
           {&addReportCommand, false}},
          {"compare", "Compare a calibrated assembly with measurements: posterior predictive mean and 95 % band per channel, RMS, NRMSE, max error, coverage, and where it fails (time windows, frequency bands, force-state maps)",
           {&addCompareCommand, false}},
          {"diagnose", "Name the physical effect the assembly is missing: calibrate the base on the measurements, screen the effect catalogue (score test), confirm the best by re-calibration and evidence (BIC); --apply adds effects in turn and shows the error fall (resumable)",
           {&addDiagnoseCommand, false}},
          {"import", "Turn a logger's CSV (one row per time, one column per signal) into measurements, a speed trace, a road logged against time and a study holding the drive as a scenario (docs/measurements.md)",
           {&addImportCommand, false}},
      });
  return r;
}

CLI::App* addSubcommand(CLI::App& root, const std::string& name) {
  return root.add_subcommand(name, commandRegistry().at(name, "twin").description);
}

}  // namespace dtwin::cli
