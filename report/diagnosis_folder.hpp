#pragma once
// The files of a diagnosis folder as its report section reads them (report/diagnosis_report.cpp):
// diagnosis.json and the comparisons before and after, checked, and the JSON helpers both files
// use. Private to the report library; in a namespace of its own, since the study report keeps
// helpers of the same names (at, dbl, str) in its own file.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dtwin::report::diagnosis_folder {

using nlohmann::json;
namespace fs = std::filesystem;

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// j[key], or null when j is not an object or has no such key.
const json& at(const json& j, const char* key);
/// A number (null, as nlohmann writes NaN, and anything else: NaN).
double dbl(const json& j);
/// A string (anything else: "").
std::string str(const json& j);
/// The effects of a step joined with "+" ("base" when there are none).
std::string joinEffects(const json& effects);

struct Band {
  std::string name;
  double ratio;
};

struct Series {
  std::string data_set, scenario, channel, unit;
  double rms, nrmse, coverage, systematic_rms;
  std::vector<double> t, measured, predicted, lo, hi;
  std::vector<Band> bands;
  std::string key() const { return data_set + "\n" + scenario + "\n" + channel; }
  std::string name() const {
    return scenario + " " + channel + " (" + fs::path(data_set).filename().string() + ")";
  }
};

struct MapBin {
  double centre, mean, se;
};

struct StateMap {
  std::string channel, state, feature;
  double explained = kNaN, knee_at = kNaN;
  std::vector<MapBin> bins;
};

struct Comparison {
  std::string file;
  std::vector<Series> series;
  std::vector<StateMap> maps;
  const Series* find(const std::string& key) const {
    for (const auto& s : series)
      if (s.key() == key) return &s;
    return nullptr;
  }
  const StateMap* findMap(const std::string& channel, const std::string& state) const {
    for (const auto& m : maps)
      if (m.channel == channel && m.state == state) return &m;
    return nullptr;
  }
};

/// What a diagnosis folder holds for its section: diagnosis.json, and the "before" (base) and
/// "after" comparisons (report/diagnosis_report.hpp says which comparison is "after").
struct DiagnosisInput {
  std::string diag_dir;
  fs::path dir;
  json d;  ///< diagnosis.json
  std::string verdict, effect, assembly;
  bool has_steps = false;  ///< `steps` exist (--apply)
  Comparison base, after;
  std::string after_name, after_label;
  bool has_after = false;
  const json& steps() const { return at(d, "steps"); }
};

/// Reads and checks diagnosis.json, comparisons/base.json and the "after" comparison (InputError
/// naming the file).
DiagnosisInput readDiagnosisInput(const std::string& diag_dir);

}  // namespace dtwin::report::diagnosis_folder
