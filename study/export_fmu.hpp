#pragma once
// `twin export-fmu` as one library call: one assembly of a study with its calibrated values (the
// posterior's optimum or one of its draws) and any applied effects (--effect, --set as `twin
// simulate` takes them) as an FMI 2.0 co-simulation FMU for linux64 (docs/fmu.md): the
// modelDescription.xml, the runtime library with the libraries it needs, and as resources the
// study, the calibration's summary, a provenance record and what the runtime rebuilds the twin
// from (study/cosim.hpp). The FMU is written atomically, and only after the twin it holds was
// rebuilt from those resources and started.
#include <optional>
#include <string>
#include <vector>

#include "io/study.hpp"

namespace dtwin {

struct ExportFmuRequest {
  std::string
      calibration;  ///< a calibration folder (`twin calibrate`'s OUT/<id>); "": the study's values
  std::string assembly;  ///< required without a calibration; with one, must be its assembly
  std::string out;       ///< the .fmu file
  std::optional<long>
      draw;  ///< a posterior draw (row of posterior.csv, from 0); unset: the optimum
  std::vector<ParameterSetting> sets;  ///< overrides (--set); a calibrated value's wins over it
  std::vector<EffectSetting> effects;  ///< added effects (--effect)
  /// The folder of the runtime library (dtwin_fmu.so) and the libraries it needs; "": the
  /// environment's DTWIN_FMU_BINARIES, else this build's.
  std::string binaries;
  double step_size_s = 1e-3;  ///< the DefaultExperiment's communication step
  double stop_time_s = 10.0;  ///< the DefaultExperiment's stop time
  std::string command;        ///< recorded in the provenance
  /// InputError naming the flag ("export-fmu.out", ...) for a bad request.
  void validate() const;
};

struct ExportFmuResult {
  std::string fmu;  ///< the file written
  std::string assembly, label, model_identifier, guid;
  std::string values_from;  ///< "the optimum of DIR", "draw K of DIR" or "the study's values"
  std::size_t inputs = 0, outputs = 0, parameters = 0;
  std::vector<std::string> libraries;  ///< the binaries/linux64 files
  std::vector<std::string> notes;      ///< e.g. the calibration's tighter integrator accuracy
  std::size_t bytes = 0;
  double wall_s = 0.0;
  /// Lines a front end prints.
  std::string text() const;
};

ExportFmuResult exportFmu(const Study& study, const ExportFmuRequest& request);

}  // namespace dtwin
