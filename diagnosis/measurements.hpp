#pragma once
// Measurement files for comparison and diagnosis (docs/diagnosis.md): the tidy lab layout
// (repetition,time_s,channel,value; several channels, any number of repetitions), each file tied
// to a scenario of the study. A file may come from a real vehicle: channel names and unit suffixes
// are validated, times must lie inside the scenario; times off the simulation's output grid are
// compared with the output interpolated there (twin/trace.hpp GridSample).
#include <map>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"
#include "io/study.hpp"

namespace dtwin::diag {

/// "FILE[@SCENARIO]" as given on the command line.
struct MeasurementSpec {
  std::string path, scenario;  ///< scenario empty: taken from the file's JSON sidecar
};

/// Parses "FILE[@SCENARIO]" (the last '@' separates). `flag` names the option in errors.
MeasurementSpec parseMeasurementArg(const std::string& text, const std::string& flag);

/// Reads, validates and ties one file to its scenario. The scenario is spec.scenario, else the
/// "scenario" of the file's sidecar (FILE with .json, written by `twin generate lab`); a file
/// with neither is refused. The random road's seed comes from the sidecar's road.seed (else the
/// study's seed is used: a measurement on a real road needs a csv-road scenario). Errors
/// (InputError, one line): unreadable or malformed file (the lab reader's rules: unknown channel,
/// wrong unit suffix, NaN, non-monotone time, ...), unknown scenario, a time after the end of the
/// scenario (file:line, the rule broken).
calib::DataSet loadMeasurement(const Study& study, const MeasurementSpec& spec);

/// The noise of one channel of one data set: the pooled within-(channel, time) variance of the
/// repetitions ("pure error", dof = Σ (R_t − 1)), or, with a single repetition, the noise_sd² of
/// the study's sensor with this channel, else the study's [noise] variance for force channels
/// (unit N). dof = 0 and variance = 0 when none exists.
struct ChannelNoise {
  double variance = 0.0;
  long dof = 0;
  std::string source;  ///< "repetitions" | "study [noise]" | "none"
};
ChannelNoise estimateNoise(const Study& study, const LabData& data, const std::string& channel);

/// A force channel (unit suffix "_N"): the study's [noise] variance applies to it.
bool isForce(const std::string& channel);

/// Per channel over all data sets (pooled pure error; study [noise] for N channels without
/// repetitions). Channels with no noise estimate (zero variance) are left out: a diagnosis cannot
/// weigh them (they are compared but not fitted); `left_out` lists them with the reason.
std::map<std::string, ChannelNoise> estimateChannelNoise(
    const Study& study, const std::vector<calib::DataSet>& sets,
    std::vector<std::string>* left_out = nullptr);

}  // namespace dtwin::diag
