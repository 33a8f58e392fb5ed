#pragma once
// `twin simulate` as one library call: one assembly (or every one) of a study over one of its
// scenarios, each trace and its sidecar written atomically. A failed run writes no trace (a
// partial trace would pass for a result); with every assembly a summary.json records them all.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/study.hpp"
#include "twin/simulator.hpp"
#include "twin/trace.hpp"

namespace dtwin {

struct SimulateRequest {
  std::string assembly = "M1";  ///< an assembly id, or "all"
  std::string scenario = "lab";
  std::string out;  ///< a .csv file (one assembly) or a folder (all); "" writes no file (the values
                    ///< are kept)
  std::vector<ParameterSetting> sets;  ///< overrides (--set)
  std::vector<EffectSetting> effects;  ///< added effects (--effect)
  std::vector<std::string> channels;   ///< written channels (time_s always); empty: all
  std::optional<std::pair<double, double>> window;  ///< rows with t0 <= time_s <= t1
  std::optional<std::uint64_t> seed;                ///< of random roads; unset: the study's
  SimulationOptions simulation;  ///< the integration (the study's, with overrides)
  std::string command;           ///< recorded in every sidecar
  /// Keep each run's written rows and channels in SimulateRun::values (always when out is "").
  bool keep_values = false;
  /// InputError naming the field ("simulate.channels", "simulate.out", ...) for a bad request.
  void validate(const Study& study) const;
};

/// One run of a request.
struct SimulateRun {
  std::string assembly, label;
  bool ok = false;
  std::string message;  ///< why it failed
  double peak_hub_force_fl_N = 0.0, static_hub_force_fl_N = 0.0;
  long steps = 0;
  double wall_s = 0.0;
  std::string trace;  ///< the CSV written ("" when the run failed or no out was given)
  /// The rows and channels the CSV holds (Trace::select), when kept (SimulateRequest::keep_values).
  Trace values;
  /// Effects installed at their off values, each with a hint how to switch it on.
  std::vector<std::string> off_effects;
};

/// Runs the request (validated first), calling `on_run` after each run; returns every run.
std::vector<SimulateRun> simulateScenario(
    const Study& study, const SimulateRequest& request,
    const std::function<void(const SimulateRun&)>& on_run = {});

}  // namespace dtwin
