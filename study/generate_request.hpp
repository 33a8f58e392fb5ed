#pragma once
// `twin generate lab` and `twin generate field` as one call each, from the settings a front end
// gives (the effects, values and sensor models as text, the window as two numbers): the options
// built and checked, the work within the limits, the data made and written (study/generate.hpp),
// and the lines to print.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/distributed.hpp"
#include "common/progress.hpp"
#include "io/study.hpp"

namespace dtwin {

struct GenerateRequest {
  std::string out;       ///< the CSV file; its JSON sidecar is written beside it
  std::string assembly;  ///< "": the study's first (M1, the highest fidelity by convention)
  std::string scenario;  ///< "": lab, field
  std::optional<std::uint64_t> seed;  ///< unset: the study's
  std::vector<std::string>
      hidden_effects;                      ///< NAME[:param=value,...] (errors name --hidden-effect)
  std::vector<std::string> hidden_values;  ///< lab: NAME=VALUE (errors name --hidden-value)
  std::vector<std::string> hidden_sensor;  ///< lab: KIND=VALUE (errors name --hidden-sensor)
  bool all_times = false;                  ///< lab: every output sample in the window at the rate
  std::vector<double> window;              ///< T0,T1 [s]; empty: lab the whole run, field 10,15
  std::optional<double> rate_hz;           ///< lab with all_times: samples per second kept
  std::vector<std::string> channels;       ///< lab; empty: the study's [lab] channels
  std::string channel = "hub_force_fl_N";  ///< field: the channel kept
  long repetitions = 0;                    ///< lab; <= 0: the study's sizes.lab_repetitions
  long runs = 0;                           ///< field; <= 0: the study's sizes.field_runs
  int threads = 0;                         ///< field; <= 0: all cores
  const Distributed* processes = nullptr;  ///< the process context; nullptr: this process alone
  bool force = false;                      ///< run even above the work limits
  std::string command;                     ///< recorded in the sidecar
};

/// What a generation tells its user.
struct GenerateRun {
  /// One line each: a channel written without noise ("channel X is not in N; it is written
  /// without noise").
  std::vector<std::string> notes;
  /// The lines `twin generate` prints: what was made, where it went, the hidden settings used.
  std::string text;
};

/// `twin generate lab`: InputError for a bad setting (naming its flag or the options' field) or
/// work above the limits, before any run; RunFailedError when the run fails.
GenerateRun generateLabData(const Study& study, const GenerateRequest& request,
                            const ProgressFn& progress = {});
/// `twin generate field`, likewise.
GenerateRun generateFieldData(const Study& study, const GenerateRequest& request,
                              const ProgressFn& progress = {});

}  // namespace dtwin
