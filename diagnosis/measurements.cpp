#include "diagnosis/measurements.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "common/json.hpp"
#include "io/provenance.hpp"
#include "twin/trace.hpp"

namespace fs = std::filesystem;

namespace dtwin::diag {

MeasurementSpec parseMeasurementArg(const std::string& text, const std::string& flag) {
  MeasurementSpec s;
  const auto at = text.rfind('@');
  if (at == std::string::npos) {
    s.path = text;
  } else {
    s.path = text.substr(0, at);
    s.scenario = text.substr(at + 1);
    if (s.scenario.empty())
      throw InputError(flag + " " + text,
                       "'@' must be followed by a scenario name (FILE@SCENARIO)");
  }
  if (s.path.empty()) throw InputError(flag + " " + text, "names no file (FILE[@SCENARIO])");
  return s;
}

calib::DataSet loadMeasurement(const Study& study, const MeasurementSpec& spec) {
  if (!fs::exists(spec.path)) throw InputError(spec.path, "no such file");
  calib::DataSet ds;
  ds.name = spec.path;
  ds.data = readLabCsv(spec.path, measurableChannels(study.sensors));
  // The sidecar (when there is one) names the scenario and the random road's seed.
  const SidecarFacts facts = readSidecarFacts(spec.path);
  ds.road_seed = facts.road_seed;
  ds.scenario = dataScenario(spec.path, spec.scenario, facts);
  if (ds.scenario.empty())
    throw InputError(spec.path, "no scenario: name it as " + spec.path +
                                    "@SCENARIO (the file has no sidecar naming one)");
  const ScenarioSpec& sc = study.scenario(ds.scenario);  // InputError lists the known names
  for (std::size_t i = 0; i < ds.data.records.size(); ++i) {
    const auto& r = ds.data.records[i];
    if (r.time_s > sc.duration_s)
      throw InputError(spec.path + ":" + std::to_string(i + 2) + ": time_s",
                       formatExact(r.time_s) + " s lies after the end of scenario '" + sc.name +
                           "' (" + formatExact(sc.duration_s) + " s)");
  }
  return ds;
}

namespace {
struct Accum {
  double ss = 0.0;
  long dof = 0;
};
void addPureError(const LabData& data, const std::string& channel, Accum& acc) {
  std::map<double, std::vector<double>> by_time;
  for (const auto& r : data.records)
    if (r.channel == channel) by_time[r.time_s].push_back(r.value);
  for (const auto& [t, v] : by_time) {
    if (v.size() < 2) continue;
    double m = 0.0;
    for (double x : v) m += x;
    m /= static_cast<double>(v.size());
    for (double x : v) acc.ss += (x - m) * (x - m);
    acc.dof += static_cast<long>(v.size()) - 1;
  }
}
/// The noise_sd of the study's sensor with this channel (0: none given, or no such sensor).
double sensorNoiseSd(const Study& study, const std::string& channel) {
  for (const auto& x : study.sensors)
    if (x.channel() == channel) return x.noise_sd;
  return 0.0;
}
}  // namespace

bool isForce(const std::string& channel) {
  return channel.size() > 2 && channel.compare(channel.size() - 2, 2, "_N") == 0;
}

ChannelNoise estimateNoise(const Study& study, const LabData& data, const std::string& channel) {
  Accum a;
  addPureError(data, channel, a);
  ChannelNoise n;
  if (a.dof > 0) {
    n.variance = a.ss / static_cast<double>(a.dof);
    n.dof = a.dof;
    n.source = "repetitions";
  } else if (const double sd = sensorNoiseSd(study, channel); sd > 0) {
    n.variance = sd * sd;
    n.source = "sensor noise_sd";
  } else if (isForce(channel)) {
    n.variance = study.noise_variance_N2;
    n.source = "study [noise]";
  } else {
    n.source = "none";
  }
  return n;
}

std::map<std::string, ChannelNoise> estimateChannelNoise(const Study& study,
                                                         const std::vector<calib::DataSet>& sets,
                                                         std::vector<std::string>* left_out) {
  std::map<std::string, Accum> acc;
  std::vector<std::string> order;
  for (const auto& s : sets)
    for (const auto& c : s.data.channels()) {
      if (!acc.count(c)) order.push_back(c);
      addPureError(s.data, c, acc[c]);
    }
  std::map<std::string, ChannelNoise> out;
  for (const auto& c : order) {
    ChannelNoise n;
    if (acc[c].dof > 0 && acc[c].ss > 0) {
      n.variance = acc[c].ss / static_cast<double>(acc[c].dof);
      n.dof = acc[c].dof;
      n.source = "repetitions";
    } else if (const double sd = sensorNoiseSd(study, c); acc[c].dof == 0 && sd > 0) {
      n.variance = sd * sd;
      n.source = "sensor noise_sd";
    } else if (acc[c].dof == 0 && isForce(c)) {
      n.variance = study.noise_variance_N2;
      n.source = "study [noise]";
    } else {
      if (left_out)
        left_out->push_back(c + (acc[c].dof > 0
                                     ? " (its repetitions agree exactly: no noise to weigh it by)"
                                     : " (one repetition, and no [noise] variance for its unit nor "
                                       "a sensor noise_sd)"));
      continue;
    }
    out[c] = n;
  }
  return out;
}

}  // namespace dtwin::diag
