// The registry of `twin`'s subcommands (cli/commands.hpp): each name with its description, what
// adds it to the root application, and whether it runs on every MPI rank.
#include "cli/commands.hpp"

namespace dtwin::cli {

const Registry<CommandEntry>& commandRegistry() {
  // One entry per command, in the order `twin --help` lists them (by group, kCommandGroups): its
  // description (the command's own --help), what adds it, whether it runs on every MPI rank, its
  // group, its one-line task (`twin --help`) and whether a rerun resumes it. A new command: its
  // file cli/<name>_command.cpp with add<Name>Command (declared in cli/commands.hpp), its entry
  // here, and the file in cli/CMakeLists.txt.
  static const Registry<CommandEntry> r(
      "command",
      {
          {"simulate",
           "Simulate one assembly (or all) over one scenario; writes a CSV trace and a JSON "
           "sidecar",
           {&addSimulateCommand, false, kCommandGroups[0],
            "simulate an assembly (or all) over a scenario: a CSV trace and its JSON sidecar",
            false}},
          {"generate",
           "Make synthetic measurements: lab data (condensed, repeated) or field data (random "
           "roads)",
           {&addGenerateCommand, true, kCommandGroups[0],
            "make synthetic measurements: lab data or field records, with noise", false}},
          {"calibrate",
           "Calibrate assemblies against lab data: NLopt optimum, feasible box, Latin hypercube "
           "design, two-block Griddy Gibbs (resumable: rerun the same command to continue)",
           {&addCalibrateCommand, true, kCommandGroups[0],
            "calibrate each assembly's values on lab data, with 95 % intervals", true}},
          {"coverage",
           "Measure how often the calibration's 95 % intervals hold the truth: each assembly's own "
           "lab data over N noise seeds, calibrated as `twin calibrate` would (resumable: rerun "
           "the same command to continue)",
           {&addCoverageCommand, false, kCommandGroups[0],
            "check how often the calibration's 95 % intervals hold the true values", true}},
          {"synthesize",
           "Synthetic field data per calibrated assembly: posterior draws, each on R roads of a "
           "seeded road library, plus noise N(0, 1/tau); the window's mean and covariance are "
           "accumulated (resumable: rerun the same command to continue)",
           {&addSynthesizeCommand, true, kCommandGroups[0],
            "synthesize field data from each calibrated assembly", true}},
          {"classify",
           "Classify field records among synthesized assemblies (Gaussian likelihood per assembly, "
           "posterior probabilities, Bayes factors) and recommend the cheapest assembly not "
           "decisively worse",
           {&addClassifyCommand, false, kCommandGroups[0],
            "classify field records among the assemblies; recommend the cheapest one that fits",
            false}},
          {"study",
           "Run the whole method: lab and field data, calibrate every assembly, synthesise field "
           "data, classify, recommend (resumable: rerun the same command to continue)",
           {&addStudyCommand, true, kCommandGroups[0],
            "run the whole method: data, calibration, synthesis, classification, choice", true}},
          {"report",
           "Write a self-contained HTML report of a study folder (lab data vs posterior predictive "
           "bands, posteriors, field-record selection, evidence vs cost, provenance) and/or of "
           "diagnosis folders; needs gnuplot",
           {&addReportCommand, false, kCommandGroups[0],
            "write an HTML report of a study folder and/or of diagnoses", false}},
          {"import",
           "Turn a logger's CSV (one row per time, one column per signal) into measurements, a "
           "speed trace, a road logged against time and a study holding the drive as a scenario "
           "(docs/measurements.md)",
           {&addImportCommand, false, kCommandGroups[1],
            "turn a logger's CSV into measurements and a study holding the drive", false}},
          {"compare",
           "Compare a calibrated assembly with measurements: posterior predictive mean and 95 % "
           "band per channel, RMS, NRMSE, max error, coverage, and where it fails (time windows, "
           "frequency bands, force-state maps)",
           {&addCompareCommand, false, kCommandGroups[1],
            "compare a calibrated assembly with measurements: where and how it fails", false}},
          {"diagnose",
           "Name the physical effect the assembly is missing: calibrate the base on the "
           "measurements, screen the effect catalogue (score test), confirm the best by "
           "re-calibration and evidence (BIC); --apply adds effects in turn and shows the error "
           "fall (resumable)",
           {&addDiagnoseCommand, false, kCommandGroups[1],
            "name what the assembly misses (an effect, a wrong value, a sensor) and add it", true}},
          {"changes",
           "List the values that changed between two calibrations of one car (two drives): each "
           "value's change with its 95 % interval from both calibrations' intervals, significant "
           "ones first (Holm's rule, family-wise 5 %), as text, changes.json and changes.html",
           {&addChangesCommand, false, kCommandGroups[1],
            "list the values that changed between two calibrations of one car", false}},
          {"export-fmu",
           "Export one assembly with its calibrated values (and any --effect, --set) as an FMI "
           "2.0 co-simulation FMU for linux64: inputs the speed, the road under each wheel and an "
           "actuator force per strut; outputs every channel (docs/fmu.md)",
           {&addExportFmuCommand, false, kCommandGroups[2],
            "export a calibrated assembly as an FMI 2.0 co-simulation FMU", false}},
          {"list",
           "Show the assemblies, scenarios, calibrated parameters, effects and channels a study "
           "defines",
           {&addListCommand, false, kCommandGroups[2],
            "show what a study defines: assemblies, scenarios, parameters, effects, channels",
            false}},
          {"bench",
           "Measure wall time per 15 s run for every assembly on the bump and the rough road",
           {&addBenchCommand, false, kCommandGroups[2], "time the simulations on this machine",
            false}},
          {"help",
           "Show the commands by task, or a command's options and examples (as `twin COMMAND "
           "--help`)",
           {&addHelpCommand, false, kCommandGroups[2],
            "show this overview, or a command's help: twin help COMMAND", false}},
      });
  return r;
}

CLI::App* addSubcommand(CLI::App& root, const std::string& name) {
  return root.add_subcommand(name, commandRegistry().at(name, "twin").description);
}

}  // namespace dtwin::cli
