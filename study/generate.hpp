#pragma once
// Synthetic measurements (docs/method.md §3): lab data (one assembly at the study's true parameters
// over the lab scenario, plus Gaussian noise, R repetitions, condensed to a few significant
// times) and field data (N runs on independent random roads, a window of one channel, plus
// noise). Everything is deterministic: noise and road seeds derive from (seed, a purpose-specific
// stream constant, repetition or run index) through RandomStream, never from execution order,
// so the output does not depend on the number of threads.
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/distributed.hpp"
#include "common/progress.hpp"
#include "common/run_error.hpp"
#include "io/measurement.hpp"
#include "io/study.hpp"

namespace dtwin {

/// Stream constants of RandomStream(seed, stream, index) (ASCII tags; recorded in sidecars).
inline constexpr std::uint64_t kLabNoiseStream =
    0x4C41424E4F495345ULL;  // "LABNOISE"; index: repetition - 1
/// The lab noise stream of a scenario: kLabNoiseStream xor FNV-1a 64 of its name, so lab files of
/// two scenarios made with one seed have independent noise (with one stream, the same noise
/// sequence went into both, and a diagnosis pooling them saw it twice: the lack-of-fit z had
/// twice its nominal spread).
std::uint64_t labNoiseStream(const std::string& scenario);
inline constexpr std::uint64_t kFieldRoadStream =
    0x4649454C44524F44ULL;  // "FIELDROD"; index: run - 1
inline constexpr std::uint64_t kFieldNoiseStream =
    0x4649454C444E4F49ULL;  // "FIELDNOI"; index: run - 1

/// The road seed of field run `run` (1-based): RandomStream(seed, kFieldRoadStream, run - 1).bits()
/// >> 11, i.e. in [0, 2^53): exact as a double (MATLAB) and as a signed 64-bit integer.
/// `twin simulate --scenario field --seed <road seed>` reproduces that run without noise.
std::uint64_t fieldRoadSeed(std::uint64_t seed, std::size_t run);

/// When a scenario's obstacle starts: a bump road's time_s, a random road's smooth_until_s, else 0.
double obstacleTime(const ScenarioSpec& scenario);

/// Automatic lab times (docs/study-file.md, [lab]): on the output grid of `noise_free`, the local
/// extrema of `channel` (sign changes of the discrete derivative; a flat run counts once, at its
/// middle sample) at or after `obstacle_time_s`, ranked by |value - value at t = 0| (the static
/// value); greedily keep the largest `count` that are at least `min_separation_s` from every one
/// kept; returned in time order. Fewer than `count` if there are fewer extrema.
std::vector<double> automaticLabTimes(const Trace& noise_free, const std::string& channel,
                                      double obstacle_time_s, std::size_t count,
                                      double min_separation_s);

/// Which times the lab data carry.
enum class LabTimesMode {
  Study,  ///< the study's rule (default): [lab] times_s if given, else the automatic times
  All,    ///< every output sample in `window` (default: the whole scenario), decimated to `rate_hz`
};

/// Hidden effects (diagnosis tests): the data are made by the assembly with these effects
/// switched on (Study::makeModel's extra effects); recorded in the sidecar under `hidden_effects`.
/// `hiddenEffectsJson` gives [{name, parameters: {param: value used}}] for every parameter of each
/// hidden effect, the off/default values of those not given included.
nlohmann::json hiddenEffectsJson(const Model& model, const std::vector<EffectSetting>& hidden);
/// One line from hiddenEffectsJson: "bump_stop (exponent=2, gap_m=0.02 m, stiffness=2e+06 N/m^n)";
/// effects separated by "; ".
std::string hiddenEffectsSummary(const nlohmann::json& hidden_effects_json,
                                 const EffectCatalog& catalog);

struct LabOptions {
  std::string scenario = "lab";
  long repetitions = 0;                     ///< <= 0: the study's sizes.lab_repetitions
  std::optional<std::uint64_t> seed;        ///< default: the study's seed
  std::optional<double> noise_variance_N2;  ///< default: the study's [noise] variance_N2
  std::vector<EffectSetting>
      hidden_effects;  ///< effects switched on in the assembly that makes the data
  /// Fixed vehicle values changed in the model that makes the data (a wheel mass 20 % heavier than
  /// the vehicle file's): names from freeableVehicleParameters(), or a per-corner or per-axle
  /// factor (twin/parameters.hpp: "suspension.damping@rr" = 0.5, a worn damper at one corner).
  std::vector<ParameterSetting> hidden_values;
  /// Sensor models (subsystems/sensor.hpp: kind, parameter value) applied to every data channel
  /// before the noise, e.g. {"lowpass", 0.0064} for a 25 Hz first-order low-pass.
  std::vector<std::pair<std::string, double>> hidden_sensor;
  LabTimesMode times_mode = LabTimesMode::Study;
  /// times_mode All: the window [T0, T1] in s (inclusive; default: [0, duration]); must lie in
  /// the scenario. Ignored (must be unset) otherwise.
  std::optional<std::pair<double, double>> window;
  /// times_mode All: samples per second kept (default: the output rate); output_rate / rate_hz
  /// must be an integer step. Kept samples are the output samples k (time k / output rate) with
  /// k a multiple of that step, in the window. Ignored (must be unset) otherwise.
  std::optional<double> rate_hz;
  std::vector<std::string> channels;  ///< empty: the study's [lab] channels
  std::string command;                ///< recorded in the provenance
  /// The process context (common/distributed.hpp; nullptr: this process alone): every process
  /// makes the lab data (one run), only the root writes them (generateLabFile).
  const Distributed* processes = nullptr;
};

struct LabResult {
  LabData data;                 ///< records: repetition, then channel, then time
  std::vector<double> times_s;  ///< the condensed times (times_mode All: every kept sample)
  std::string times_rule;       ///< how the times were chosen
  Trace noise_free;             ///< the full noise-free trace of the run
  nlohmann::json provenance;    ///< the sidecar (docs/data-files.md)
};

/// Lab data: `assembly` at the study's parameters (calibrated truths applied) over the lab
/// scenario (with options.hidden_effects switched on), noise N(0, sigma^2) added to channels in N
/// (other channels are written noise-free, and the provenance says so), repetitions 1..R, at the
/// [lab] times or the automatic ones, or (times_mode All) every sample of a window at a rate.
/// Throws InputError for bad settings (errors about window, rate, channels and hidden effects
/// name the fields "lab.window", "lab.rate_hz", "lab.channels", "lab.hidden_effects"),
/// RunFailedError if the simulation fails.
LabResult generateLab(const Study& study, const AssemblySpec& assembly,
                      const LabOptions& options = {}, const ProgressFn& progress = {});

struct FieldOptions {
  std::string scenario = "field";
  std::string channel = "hub_force_fl_N";
  double t_begin_s = 10.0, t_end_s = 15.0;  ///< window kept (inclusive), on the output grid
  long runs = 0;                            ///< <= 0: the study's sizes.field_runs
  std::optional<std::uint64_t> seed;        ///< default: the study's seed
  std::optional<double> noise_variance_N2;  ///< default: the study's [noise] variance_N2
  std::vector<EffectSetting>
      hidden_effects;  ///< effects switched on in the assembly that makes the data
  /// Fixed vehicle values changed in the model that makes the data (a wheel mass 20 % heavier than
  /// the vehicle file's): names from freeableVehicleParameters().
  std::vector<ParameterSetting> hidden_values;
  /// Sensor models (subsystems/sensor.hpp: kind, parameter value) applied to every data channel
  /// before the noise, e.g. {"lowpass", 0.0064} for a 25 Hz first-order low-pass.
  std::vector<std::pair<std::string, double>> hidden_sensor;
  int threads = 0;  ///< <= 0: all cores
  const Distributed* processes =
      nullptr;  ///< the process context (common/distributed.hpp); nullptr: this process alone
  std::string command;
};

struct FieldResult {
  FieldData data;
  nlohmann::json provenance;
};

/// Field data: runs 1..N of `assembly` (with options.hidden_effects switched on) on independent
/// roads of the field scenario (road seed of run k: fieldRoadSeed(seed, k)), the window of
/// `channel`, plus noise (channels in N only), in parallel on options.threads workers (one
/// Simulator each, one shared Model). Throws InputError for bad settings, RunFailedError naming the
/// lowest failing run and its seed.
FieldResult generateField(const Study& study, const AssemblySpec& assembly,
                          const FieldOptions& options = {}, const ProgressFn& progress = {});

/// `twin generate lab` and `twin generate field` as one call each: refuses an `out` that is not a
/// .csv file or whose folder cannot be written (InputError "generate.out", before any run), makes
/// the data (generateLab / generateField) and writes `out` and its JSON sidecar atomically (only
/// the root of options.processes writes).
LabResult generateLabFile(const Study& study, const AssemblySpec& assembly,
                          const LabOptions& options, const std::string& out,
                          const ProgressFn& progress = {});
FieldResult generateFieldFile(const Study& study, const AssemblySpec& assembly,
                              const FieldOptions& options, const std::string& out,
                              const ProgressFn& progress = {});

}  // namespace dtwin
