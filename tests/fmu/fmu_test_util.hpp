#pragma once
// What the FMU tests share: the demo study's M1 exported from a calibration folder, the FMU
// unzipped, a CSV read into columns, the inputs of a scenario as an FMU's input CSV, and the
// variables of a modelDescription.xml by name.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "io/study.hpp"
#include "io/zip_archive.hpp"
#include "test_util.hpp"
#include "twin/scenario.hpp"

namespace fmu_test {

namespace fs = std::filesystem;

inline std::string demoStudy() { return std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml"; }

/// The calibrated values the tests' calibration folder holds as its optimum (not the study's
/// truths, so that a value taken from elsewhere shows).
inline const std::vector<std::pair<std::string, double>>& calibrated() {
  static const std::vector<std::pair<std::string, double>> v = {{"tire.stiffness", 195000.0},
                                                                {"tire.damping", 2900.0},
                                                                {"suspension.stiffness", 31000.0},
                                                                {"suspension.damping", 2700.0}};
  return v;
}

/// `--set NAME=VALUE` of every calibrated value: `twin simulate` at the calibration's optimum.
inline std::string setCalibrated() {
  std::ostringstream s;
  s.precision(17);
  for (const auto& [n, v] : calibrated()) s << " --set " << n << "=" << v;
  return s.str();
}

/// A calibration folder of M1 (summary.json with the optimum, posterior.csv with two draws).
inline fs::path writeCalibration(const fs::path& dir) {
  fs::create_directories(dir);
  std::ostringstream theta, header, draw;
  theta.precision(17);
  for (std::size_t i = 0; i < calibrated().size(); ++i) {
    theta << (i ? "," : "") << calibrated()[i].second;
    header << calibrated()[i].first << ",";
  }
  dtwin_test::writeText(dir / "summary.json", "{\"assembly\": \"M1\", \"optimum\": {\"theta\": [" +
                                                  theta.str() + "]}}\n");
  dtwin_test::writeText(dir / "posterior.csv", header.str() + "tau,design_index\n" + theta.str() +
                                                   ",1e-4,0\n180000,3000,30000,2500,1e-4,1\n");
  return dir;
}

/// Writes every member of `fmu` under `dir`; returns the member names.
inline std::vector<std::string> unzipTo(const fs::path& fmu, const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& m : dtwin::readZipArchive(dtwin_test::slurp(fmu), fmu.string())) {
    names.push_back(m.name);
    if (m.name.back() == '/') continue;
    fs::create_directories((dir / m.name).parent_path());
    dtwin_test::writeText(dir / m.name, m.data);
  }
  return names;
}

/// A CSV of numbers read into named columns (the header's quotes removed).
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> cols;
  const std::vector<double>* column(const std::string& n) const {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == n) return &cols[i];
    return nullptr;
  }
};

inline Table readCsv(const fs::path& p) {
  Table t;
  std::istringstream in(dtwin_test::slurp(p));
  std::string line;
  std::getline(in, line);
  std::istringstream h(line);
  for (std::string f; std::getline(h, f, ',');) {
    f.erase(std::remove(f.begin(), f.end(), '"'), f.end());
    f.erase(std::remove(f.begin(), f.end(), '\r'), f.end());
    t.names.push_back(f);
  }
  t.cols.resize(t.names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream r(line);
    std::size_t i = 0;
    for (std::string f; std::getline(r, f, ',') && i < t.cols.size(); ++i)
      t.cols[i].push_back(std::stod(f));
  }
  return t;
}

/// The inputs of scenario `name` of the demo study at every `dt` from 0 to its end: the speed and
/// the road under each wheel (front: the distance travelled; rear: less the wheelbase).
struct ScenarioInputs {
  std::vector<double> t, speed;
  std::vector<std::array<double, 4>> road;
};

inline ScenarioInputs scenarioInputs(const std::string& name, double dt) {
  const dtwin::Study s = dtwin::loadStudy(demoStudy());
  const dtwin::ScenarioSpec& sc = s.scenario(name);
  const auto model = s.makeModel(s.assembly("M1"));
  const auto road = dtwin::makeRoad(sc, model->vehicle(), s.seed);
  const double wb = model->vehicle().wheelbase();
  ScenarioInputs in;
  const auto n = static_cast<std::size_t>(std::llround(sc.duration_s / dt));
  for (std::size_t k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) * dt, x = sc.speed.distance(t);
    in.t.push_back(t);
    // The speed just after t: a scenario that starts at speed (ramp_s = 0) has 0 at t = 0 and its
    // speed right after, with no acceleration between (SpeedProfile); an FMU takes the slope of
    // its speed input between communication points for the acceleration, so it is given the
    // speed the car drives at.
    in.speed.push_back(sc.speed.speed(std::max(t, 1e-12)));
    std::array<double, 4> h{};
    for (int c = 0; c < 4; ++c)
      h[static_cast<std::size_t>(c)] = road->sampleAt(c, x - (c < 2 ? 0.0 : wb)).height_m;
    in.road.push_back(h);
  }
  return in;
}

inline std::string inputCsv(const ScenarioInputs& in) {
  std::ostringstream o;
  o.precision(17);
  o << "time,in_speed_mps,in_road_fl_m,in_road_fr_m,in_road_rl_m,in_road_rr_m\n";
  for (std::size_t k = 0; k < in.t.size(); ++k) {
    o << in.t[k] << "," << in.speed[k];
    for (double h : in.road[k]) o << "," << h;
    o << "\n";
  }
  return o.str();
}

/// name -> valueReference of a modelDescription.xml.
inline std::map<std::string, unsigned> valueReferences(const std::string& xml) {
  std::map<std::string, unsigned> out;
  const std::regex r("<ScalarVariable name=\"([^\"]+)\" valueReference=\"([0-9]+)\"");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), r); it != std::sregex_iterator();
       ++it)
    out[(*it)[1]] = static_cast<unsigned>(std::stoul((*it)[2]));
  return out;
}

/// The largest |a - b| of a column of two tables over their common rows (rows of equal time),
/// and the range of b there.
struct Difference {
  double max_abs = 0.0, range = 0.0;
  std::size_t rows = 0;
};

/// Rows at t < t_min are left out.
inline Difference compare(const Table& a, const Table& b, const std::string& col,
                          double t_min = 0.0, const std::string& time_a = "time",
                          const std::string& time_b = "time_s") {
  Difference d;
  const auto *ta = a.column(time_a), *tb = b.column(time_b), *ca = a.column(col),
             *cb = b.column(col);
  if (!ta || !tb || !ca || !cb) return {std::nan(""), 0, 0};
  double lo = 1e300, hi = -1e300;
  std::size_t j = 0;
  for (std::size_t i = 0; i < ta->size(); ++i) {
    while (j < tb->size() && (*tb)[j] < (*ta)[i] - 1e-9) ++j;
    if (j >= tb->size() || std::abs((*tb)[j] - (*ta)[i]) > 1e-9 || (*ta)[i] < t_min) continue;
    d.max_abs = std::max(d.max_abs, std::abs((*ca)[i] - (*cb)[j]));
    lo = std::min(lo, (*cb)[j]);
    hi = std::max(hi, (*cb)[j]);
    ++d.rows;
  }
  d.range = hi - lo;
  return d;
}

}  // namespace fmu_test
