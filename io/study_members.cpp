// What a study read from its file answers (io/study.hpp): its assemblies and their models, its
// parameter table, its JSON record and its sizes; and the NAME=VALUE settings of the command line.
// The file itself is read in io/study.cpp.
#include "io/study.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/vehicle_file.hpp"
#include "twin/parameters.hpp"

namespace dtwin {
nlohmann::json CalibrationSettings::toJson() const {
  return {
      {"region", region},           {"design", designOrDefault()}, {"round_points", round_points},
      {"max_rounds", max_rounds},   {"target_ess", target_ess},    {"margin", margin},
      {"ridge_steps", ridge_steps}, {"interval", interval},        {"steps", steps}};
}

const std::vector<std::pair<std::string, long StudySizes::*>>& StudySizes::fields() {
  static const std::vector<std::pair<std::string, long StudySizes::*>> f = {
      {"field_runs", &StudySizes::field_runs},
      {"gibbs_burn_in", &StudySizes::gibbs_burn_in},
      {"gibbs_iterations", &StudySizes::gibbs_iterations},
      {"lab_repetitions", &StudySizes::lab_repetitions},
      {"lhs_points", &StudySizes::lhs_points},
      {"optimizer_starts", &StudySizes::optimizer_starts},
      {"posterior_draws", &StudySizes::posterior_draws},
      {"road_library", &StudySizes::road_library},
      {"roads_per_draw", &StudySizes::roads_per_draw}};
  return f;
}

long StudySizes::*StudySizes::member(const std::string& name) {
  for (const auto& [n, m] : fields())
    if (n == name) return m;
  throw std::out_of_range("unknown study size '" + name + "'");
}

long StudySizes::maximum(const std::string& name) {
  static const std::map<std::string, long> most = {
      {"lab_repetitions", 10000},     {"field_runs", 100000},      {"lhs_points", 1000000},
      {"gibbs_iterations", 20000000}, {"gibbs_burn_in", 20000000}, {"posterior_draws", 1000000},
      {"roads_per_draw", 1000},       {"road_library", 10000000},  {"optimizer_starts", 1000}};
  (void)member(name);  // DTWIN_CHECK on an unknown name
  return most.at(name);
}

long StudySizes::at(const std::string& name) const { return this->*member(name); }

long& StudySizes::at(const std::string& name) { return this->*member(name); }

std::map<std::string, long> StudySizes::asMap() const {
  std::map<std::string, long> m;
  for (const auto& [n, member] : fields()) m[n] = this->*member;
  return m;
}

void Study::addUserEffects(const std::vector<UserEffectSpec>& specs) {
  auto next = std::make_shared<EffectCatalog>(*catalog);
  for (const auto& u : specs) next->add(u);
  catalog = std::move(next);
}

std::vector<AssemblySpec> Study::assemblies() const {
  std::vector<AssemblySpec> out;
  std::vector<std::size_t> idx(subsystems.size(), 0);
  int n = 0;
  while (true) {
    AssemblySpec a;
    a.id = "M" + std::to_string(++n);
    for (std::size_t i = 0; i < subsystems.size(); ++i)
      a.options.push_back({subsystems[i].first, subsystems[i].second[idx[i]]});
    for (const auto& e : effects) a.effects.push_back(e.name);
    if (include.empty() || std::find(include.begin(), include.end(), a.id) != include.end())
      out.push_back(a);
    std::size_t k = subsystems.size();
    while (k > 0) {
      --k;
      if (++idx[k] < subsystems[k].second.size()) break;
      idx[k] = 0;
      if (k == 0) return out;
    }
    if (subsystems.empty()) return out;
  }
}

AssemblySpec Study::assembly(const std::string& id) const {
  std::string known;
  for (const auto& a : assemblies()) {
    if (a.id == id) return a;
    known += (known.empty() ? "" : ", ") + a.id;
  }
  throw InputError(path + ": assemblies",
                   "unknown assembly '" + id + "' (this study defines: " + known + ")");
}

const ScenarioSpec& Study::scenario(const std::string& n) const {
  std::string known;
  for (const auto& sc : scenarios) {
    if (sc.name == n) return sc;
    known += (known.empty() ? "" : ", ") + sc.name;
  }
  throw InputError(path + ": scenarios",
                   "unknown scenario '" + n + "' (this study defines: " + known + ")");
}

ParameterTable Study::parameterTable(const std::vector<ParameterSetting>& overrides) const {
  ParameterTable t = declareVehicleParameters(*catalog);
  loadVehicleFile(t, vehicle_path);
  declareSensorParameters(t,
                          sensors);  // before [fixed], which may set a sensor's position or offset
  for (const auto& f : fixed) t.set(f.name, f.value, f.source, f.where);
  if (!fixed.empty()) checkChassisInertias(t, path + ": fixed");
  for (std::size_t i = 0; i < calibrated.size(); ++i)
    if (calibrated[i].truth && t.contains(calibrated[i].name))
      t.set(calibrated[i].name, *calibrated[i].truth, path + " [calibrated] truth",
            path + ": calibrated[" + std::to_string(i) + "].truth");
  for (const auto& e : effects) {
    // An effect installed at one corner ("bump_stop@rr") has its own parameters, declared here.
    if (e.name.find('@') != std::string::npos)
      declareEffectParameters(t, *catalog->make(e.name, path + ": effects"), e.name,
                              path + ": effects");
    for (const auto& v : e.values) t.set(v.name, v.value, v.source, v.where);
  }
  for (const auto& o : overrides) t.set(o.name, o.value, o.source, o.where);
  return t;
}

std::shared_ptr<const Model> Study::makeModel(
    const AssemblySpec& a, const std::vector<EffectSetting>& extra,
    const std::vector<ParameterSetting>& overrides) const {
  AssemblySpec spec = a;
  // A calibrated vehicle value (a mass, an inertia, the CG) builds the multibody system: it is
  // freed, so each run is built with its own value (docs/calibration.md, "Vehicle values").
  const auto& freeable = freeableVehicleParameters();
  // A calibrated per-corner or per-axle factor is a run parameter at any value, 1 included
  // (twin/parameters.hpp), without a rebuild.
  for (const auto& c : calibrated)
    if ((std::find(freeable.begin(), freeable.end(), c.name) != freeable.end() ||
         parseCornerFactor(c.name)) &&
        std::find(spec.freed.begin(), spec.freed.end(), c.name) == spec.freed.end())
      spec.freed.push_back(c.name);
  ParameterTable table = parameterTable();
  for (const auto& e : extra) {
    declareEffectParameters(table, *catalog->make(e.name, "model.effects"), e.name,
                            "model.effects");
    if (std::find(spec.effects.begin(), spec.effects.end(), e.name) == spec.effects.end())
      spec.effects.push_back(e.name);
  }
  // Then the extra effects' values and the overrides, in that order of precedence (as
  // parameterTable's).
  for (const auto& e : extra)
    for (const auto& v : e.values) table.set(v.name, v.value, v.source, v.where);
  for (const auto& o : overrides) table.set(o.name, o.value, o.source, o.where);
  return std::make_shared<const Model>(spec, std::move(table), path, sensors, catalog);
}

std::vector<std::string> LabSettings::channelsOrDefault() const {
  return channels.empty() ? std::vector<std::string>{"hub_force_fl_N"} : channels;
}

nlohmann::json LabSettings::toJson() const {
  nlohmann::json j = {{"channels", channelsOrDefault()}};
  if (times_s.empty()) {
    j["auto_times"] = auto_times;
    j["min_separation_s"] = min_separation_s;
  } else {
    j["times_s"] = times_s;
  }
  return j;
}

nlohmann::json Study::toJson() const {
  nlohmann::json j;
  j["path"] = path;
  j["name"] = name;
  j["seed"] = seed;
  j["vehicle"] = vehicle_path;
  for (auto& [sname, o] : subsystems) j["subsystems"][sname] = o;
  for (auto& c : calibrated) {
    nlohmann::json cj = {
        {"name", c.name}, {"unit", c.unit}, {"lower", c.lower}, {"upper", c.upper}};
    if (c.truth) cj["truth"] = *c.truth;
    j["calibrated"].push_back(cj);
  }
  j["noise_variance_N2"] = noise_variance_N2;
  for (const auto& x : sensors) j["sensors"].push_back(x.toJson());
  for (const auto& u : catalog->userEffects()) {
    nlohmann::json uj{{"name", u.name}, {"element", u.element}, {"force", u.force}};
    for (const auto& p : u.parameters)
      uj["parameters"][p.name] = {{"value", p.value},
                                  {"unit", p.unit},
                                  {"lower", p.lower},
                                  {"upper", p.upper},
                                  {"shape", p.shape}};
    j["user_effects"].push_back(uj);
  }
  j["sizes"] = sizes.asMap();
  j["lab"] = lab.toJson();
  j["calibration"] = calibration.toJson();
  return j;
}

ParameterSetting parseSetting(const std::string& text, const std::string& where) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(where, "expected NAME=VALUE, got '" + text + "'");
  const std::string name = text.substr(0, eq), val = text.substr(eq + 1);
  double v = 0;
  if (!parseNumber(val, v))
    throw InputError(where, "value of " + name + " must be a number, got '" + val + "'");
  return {name, v, where + " " + name, where};
}

EffectSetting parseEffectSetting(const std::string& text, const std::string& where,
                                 const EffectCatalog& catalog) {
  // A library term's name holds a colon itself ("term:q * v:a=3e4"): its settings follow the last.
  const bool term = text.rfind(kTermPrefix, 0) == 0;
  const auto colon = term ? (text.find(':', std::string(kTermPrefix).size()) == std::string::npos
                                 ? std::string::npos
                                 : text.rfind(':'))
                          : text.find(':');
  EffectSetting e;
  e.name = text.substr(0, colon);
  catalog.make(e.name, where);
  if (colon != std::string::npos) {
    for (const auto& item : splitOn(text.substr(colon + 1), ',')) {
      auto s = parseSetting(item, where);
      s.name = e.name + "." + s.name;
      e.values.push_back(s);
    }
  }
  return e;
}

}  // namespace dtwin
