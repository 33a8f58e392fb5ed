#include "twin/study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "common/errors.hpp"

namespace dtwin {
namespace {

/// Reader over one TOML table that remembers which keys were consumed, so that unknown keys are
/// reported instead of silently ignored.
class TableReader {
 public:
  TableReader(const toml::table& t, std::string file, std::string prefix)
      : t_(t), file_(std::move(file)), prefix_(std::move(prefix)) {}

  std::string where(const std::string& key) const {
    const toml::node* n = t_.get(key);
    const int line = n ? static_cast<int>(n->source().begin.line) : static_cast<int>(t_.source().begin.line);
    return file_ + ":" + std::to_string(line) + ": " + field(key);
  }
  std::string field(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }
  bool has(const std::string& key) const { return t_.contains(key); }

  std::optional<double> number(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value<double>()) return *v;
    throw InputError(where(key), "must be a number");
  }
  double number(const std::string& key, double def) { return number(key).value_or(def); }
  double required(const std::string& key) {
    auto v = number(key);
    if (!v) throw InputError(where(key), "is required");
    return *v;
  }
  double positive(const std::string& key, double def) {
    const double v = number(key, def);
    if (!(v > 0)) throw InputError(where(key), "must be > 0, got " + std::to_string(v));
    return v;
  }
  std::optional<std::string> string(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value<std::string>()) return *v;
    throw InputError(where(key), "must be a string");
  }
  std::optional<long> integer(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return std::nullopt;
    if (auto v = n->value_exact<int64_t>()) return static_cast<long>(*v);
    throw InputError(where(key), "must be an integer");
  }
  const toml::table* table(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return nullptr;
    if (auto* tt = n->as_table()) return tt;
    throw InputError(where(key), "must be a table");
  }
  const toml::array* array(const std::string& key) {
    used_.insert(key);
    const toml::node* n = t_.get(key);
    if (!n) return nullptr;
    if (auto* a = n->as_array()) return a;
    throw InputError(where(key), "must be an array");
  }
  std::vector<std::string> strings(const std::string& key) {
    std::vector<std::string> out;
    if (auto* a = array(key))
      for (auto&& el : *a) {
        auto v = el.value<std::string>();
        if (!v) throw InputError(where(key), "must be an array of strings");
        out.push_back(*v);
      }
    return out;
  }
  /// Throws for any key not read.
  void finish() const {
    for (auto&& [k, n] : t_) {
      const std::string key(k.str());
      if (!used_.count(key)) {
        std::vector<std::string> known(used_.begin(), used_.end());
        const std::string hint = closestName(key, known);
        throw InputError(where(key), "unknown field" + (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)"));
      }
    }
  }
  const std::string& file() const { return file_; }

 private:
  const toml::table& t_;
  std::string file_, prefix_;
  std::set<std::string> used_;
};

RoadSpec parseRoad(TableReader& r, const std::string& scenario) {
  RoadSpec rs;
  const toml::table* t = r.table("road");
  if (!t) throw InputError(r.where("road"), "is required (a table with a 'type')");
  TableReader rr(*t, r.file(), r.field("road"));
  const std::string type = rr.string("type").value_or("");
  if (type == "flat") {
    rs.type = RoadSpec::Type::Flat;
  } else if (type == "bump") {
    rs.type = RoadSpec::Type::Bump;
    rs.bump_height_m = rr.number("height_m", 0.2);
    rs.bump_length_m = rr.positive("length_m", 0.1);
    rs.bump_time_s = rr.number("time_s", 6.0);
    if (rs.bump_time_s < 0) throw InputError(rr.where("time_s"), "must be >= 0");
  } else if (type == "iso8608") {
    rs.type = RoadSpec::Type::Iso;
    const std::string cls = rr.string("class").value_or("D");
    if (cls.size() != 1 || cls[0] < 'A' || cls[0] > 'H') throw InputError(rr.where("class"), "must be one of A..H, got '" + cls + "'");
    rs.iso_class = cls[0];
    rs.smooth_until_s = rr.number("smooth_until_s", 0.0);
    if (auto* band = rr.array("band_cycles_per_m")) {
      if (band->size() != 2 || !band->get(0)->value<double>() || !band->get(1)->value<double>())
        throw InputError(rr.where("band_cycles_per_m"), "must be two numbers [n_min, n_max]");
      rs.n_min = *band->get(0)->value<double>();
      rs.n_max = *band->get(1)->value<double>();
      if (!(rs.n_min > 0 && rs.n_max > rs.n_min)) throw InputError(rr.where("band_cycles_per_m"), "needs 0 < n_min < n_max");
    }
    rs.dx_m = rr.positive("dx_m", 0.01);
    if (rs.n_max >= 0.25 / rs.dx_m) throw InputError(rr.where("dx_m"), "must give >= 4 points per shortest wavelength (dx < 0.25/n_max)");
    rs.taper_m = rr.positive("taper_m", 1.0);
    const std::string tracks = rr.string("tracks").value_or("independent");
    if (tracks == "independent") rs.coherence = IsoRoadSpec::Coherence::Independent;
    else if (tracks == "identical") rs.coherence = IsoRoadSpec::Coherence::Identical;
    else throw InputError(rr.where("tracks"), "must be \"independent\" or \"identical\", got \"" + tracks + "\"");
  } else if (type == "csv") {
    rs.type = RoadSpec::Type::Csv;
    auto p = rr.string("path");
    if (!p) throw InputError(rr.where("path"), "is required for a csv road");
    namespace fs = std::filesystem;
    rs.csv_path = fs::path(*p).is_absolute() ? *p : (fs::path(r.file()).parent_path() / *p).lexically_normal().string();
  } else {
    throw InputError(rr.where("type"), "must be one of flat, bump, iso8608, csv, got \"" + type + "\"");
  }
  rr.finish();
  return rs;
}

}  // namespace

nlohmann::json CalibrationSettings::toJson() const {
  return {{"region", region}, {"design", designOrDefault()}, {"round_points", round_points}, {"max_rounds", max_rounds},
          {"target_ess", target_ess}, {"margin", margin}, {"ridge_steps", ridge_steps}, {"interval", interval}};
}

const std::map<std::string, long>& knownSizes() {
  static const std::map<std::string, long> k = {
      {"lab_repetitions", 10}, {"field_runs", 500},     {"lhs_points", 2000},      {"gibbs_iterations", 50000},
      {"gibbs_burn_in", 15000}, {"posterior_draws", 10000}, {"roads_per_draw", 5}, {"road_library", 50000},
      {"optimizer_starts", 4}};
  return k;
}

Study loadStudy(const std::string& path) {
  namespace fs = std::filesystem;
  if (!fs::exists(path)) throw InputError(path, "study file not found");
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line), "malformed TOML: " + std::string(e.description()));
  }
  Study s;
  s.path = path;
  s.sizes = knownSizes();
  TableReader top(root, path, "");

  if (auto* t = top.table("study")) {
    TableReader r(*t, path, "study");
    s.name = r.string("name").value_or(fs::path(path).stem().string());
    s.description = r.string("description").value_or("");
    if (auto seed = r.integer("seed")) {
      if (*seed < 0) throw InputError(r.where("seed"), "must be >= 0");
      s.seed = static_cast<std::uint64_t>(*seed);
    }
    auto v = r.string("vehicle");
    if (!v) throw InputError(r.where("vehicle"), "is required (path to a vehicle data file)");
    s.vehicle_path = fs::path(*v).is_absolute() ? *v : (fs::path(path).parent_path() / *v).lexically_normal().string();
    r.finish();
  } else {
    throw InputError(path, "missing [study] table");
  }

  if (auto* t = top.table("subsystems")) {
    TableReader r(*t, path, "subsystems");
    // toml++ iterates keys alphabetically; assemblies follow the file's order.
    std::vector<std::pair<int, std::string>> keys;
    for (auto&& [k, n] : *t) keys.push_back({static_cast<int>(n.source().begin.line), std::string(k.str())});
    std::sort(keys.begin(), keys.end());
    for (const auto& [line, sub] : keys) {
      const auto& known = knownSubsystems();
      if (!known.count(sub)) throw InputError(r.where(sub), "unknown subsystem '" + sub + "' (known: suspension, tire)");
      auto opts = r.strings(sub);
      if (opts.empty()) throw InputError(r.where(sub), "must list at least one option");
      for (auto& o : opts) {
        const auto& ko = known.at(sub);
        if (std::find(ko.begin(), ko.end(), o) == ko.end()) {
          std::string list;
          for (auto& x : ko) list += (list.empty() ? "" : ", ") + x;
          throw InputError(r.where(sub), "unknown " + sub + " option '" + o + "' (known: " + list + ")");
        }
      }
      s.subsystems.push_back({sub, opts});
    }
    r.finish();
  } else {
    throw InputError(path, "missing [subsystems] table");
  }
  for (const auto& req : {"tire", "suspension"}) {
    bool found = false;
    for (auto& [n, o] : s.subsystems) found |= n == req;
    if (!found) throw InputError(path + ": subsystems", std::string("must name the '") + req + "' subsystem's options");
  }

  if (auto* t = top.table("assemblies")) {
    TableReader r(*t, path, "assemblies");
    s.include = r.strings("include");
    r.finish();
  }

  if (auto* a = top.array("calibrated")) {
    int i = 0;
    for (auto&& el : *a) {
      const auto* t = el.as_table();
      if (!t) throw InputError(top.where("calibrated"), "must be an array of tables [[calibrated]]");
      TableReader r(*t, path, "calibrated[" + std::to_string(i++) + "]");
      CalibratedParameter c;
      auto n = r.string("name");
      if (!n) throw InputError(r.where("name"), "is required");
      c.name = *n;
      c.unit = r.string("unit").value_or("");
      c.lower = r.required("lower");
      c.upper = r.required("upper");
      if (!(c.lower < c.upper))
        throw InputError(r.where("lower"), "lower bound must be < upper bound, got " + std::to_string(c.lower) + " >= " + std::to_string(c.upper));
      c.truth = r.number("truth");
      if (c.truth && (*c.truth < c.lower || *c.truth > c.upper))
        throw InputError(r.where("truth"), "must lie within [lower, upper]");
      r.finish();
      s.calibrated.push_back(c);
    }
  }

  if (auto* t = top.table("fixed")) {
    TableReader r(*t, path, "fixed");
    for (auto&& [k, n] : *t) {
      const std::string key(k.str());
      s.fixed.push_back({key, r.required(key), r.where(key), path + " [fixed]"});
    }
    r.finish();
  }

  if (auto* t = top.table("effects")) {
    TableReader r(*t, path, "effects");
    for (auto&& [k, n] : *t) {
      const std::string eff(k.str());
      makeEffect(eff, r.where(eff));  // validates the name
      const toml::table* et = r.table(eff);
      EffectSetting es{eff, {}};
      TableReader er(*et, path, "effects." + eff);
      for (auto&& [pk, pn] : *et) {
        const std::string key(pk.str());
        es.values.push_back({eff + "." + key, er.required(key), er.where(key), path + " [effects." + eff + "]"});
      }
      er.finish();
      s.effects.push_back(es);
    }
    r.finish();
  }

  if (auto* t = top.table("scenarios")) {
    std::vector<std::pair<int, std::string>> keys;
    for (auto&& [k, n] : *t) keys.push_back({static_cast<int>(n.source().begin.line), std::string(k.str())});
    std::sort(keys.begin(), keys.end());
    TableReader outer(*t, path, "scenarios");
    for (const auto& [line, key] : keys) {
      const toml::table* st = outer.table(key);
      TableReader r(*st, path, "scenarios." + key);
      ScenarioSpec sc;
      sc.name = key;
      sc.duration_s = r.positive("duration_s", 15.0);
      if (auto* sp = r.table("speed")) {
        TableReader rs(*sp, path, r.field("speed"));
        sc.speed.v_final_mps = rs.number("v_final_mps", 8.9408);
        sc.speed.ramp_s = rs.number("ramp_s", 5.0);
        if (sc.speed.v_final_mps < 0) throw InputError(rs.where("v_final_mps"), "must be >= 0");
        if (sc.speed.ramp_s < 0) throw InputError(rs.where("ramp_s"), "must be >= 0");
        rs.finish();
      }
      sc.road = parseRoad(r, sc.name);
      if (sc.road.type == RoadSpec::Type::Bump && sc.road.bump_time_s >= sc.duration_s)
        throw InputError(r.where("road"), "bump time_s must be before the end of the scenario");
      r.finish();
      s.scenarios.push_back(sc);
    }
  }
  if (s.scenarios.empty()) throw InputError(path, "no [scenarios.*] defined");

  if (auto* t = top.table("simulation")) {
    TableReader r(*t, path, "simulation");
    auto& o = s.simulation;
    o.integrator = r.string("integrator").value_or(o.integrator);
    o.accuracy = r.number("accuracy", o.accuracy);
    o.max_step_s = r.number("max_step_s", o.max_step_s);
    o.obstacle_max_step_s = r.number("obstacle_max_step_s", o.obstacle_max_step_s);
    o.obstacle_margin_before_s = r.number("obstacle_margin_before_s", o.obstacle_margin_before_s);
    o.obstacle_margin_after_s = r.number("obstacle_margin_after_s", o.obstacle_margin_after_s);
    o.output_rate_hz = r.number("output_rate_hz", o.output_rate_hz);
    const std::string rule = o.check();
    if (!rule.empty()) throw InputError(path + ": simulation", rule);
    r.finish();
  }

  if (auto* t = top.table("noise")) {
    TableReader r(*t, path, "noise");
    s.noise_variance_N2 = r.number("variance_N2", s.noise_variance_N2);
    if (!(s.noise_variance_N2 >= 0)) throw InputError(r.where("variance_N2"), "must be >= 0");
    r.finish();
  }

  if (auto* t = top.table("sizes")) {
    TableReader r(*t, path, "sizes");
    for (auto&& [k, n] : *t) {
      const std::string key(k.str());
      if (!knownSizes().count(key)) continue;  // reported by finish()
      const long v = *r.integer(key);
      if (v <= 0) throw InputError(r.where(key), "must be a positive integer, got " + std::to_string(v));
      s.sizes[key] = v;
    }
    r.finish();
  }
  if (auto* t = top.table("lab")) {
    TableReader r(*t, path, "lab");
    auto& lab = s.lab;
    lab.where = path + ":" + std::to_string(t->source().begin.line) + ": lab";
    if (auto* a = r.array("times_s")) {
      std::size_t i = 0;
      for (auto&& el : *a) {
        auto v = el.value<double>();
        if (!v) throw InputError(r.where("times_s"), "must be an array of numbers (seconds)");
        const std::string item = "element " + std::to_string(i) + " (" + std::to_string(*v) + ")";
        if (!std::isfinite(*v) || *v < 0) throw InputError(r.where("times_s"), item + " must be a finite time >= 0");
        if (!lab.times_s.empty() && !(*v > lab.times_s.back()))
          throw InputError(r.where("times_s"), item + " must be greater than the one before it (times strictly increasing)");
        const double k = *v * s.simulation.output_rate_hz;
        if (std::abs(k - std::round(k)) > 1e-6)
          throw InputError(r.where("times_s"), item + " is not on the output grid (multiples of 1/output_rate_hz = " +
                                                   std::to_string(1.0 / s.simulation.output_rate_hz) + " s)");
        lab.times_s.push_back(std::round(k) / s.simulation.output_rate_hz);
        ++i;
      }
      if (lab.times_s.empty()) throw InputError(r.where("times_s"), "must list at least one time (or leave it out for automatic times)");
    }
    lab.channels = r.strings("channels");
    std::vector<std::string> known;
    for (const auto& c : Simulator::channels())
      if (c.name != "time_s") known.push_back(c.name);
    for (std::size_t i = 0; i < lab.channels.size(); ++i) {
      const auto& c = lab.channels[i];
      if (std::find(known.begin(), known.end(), c) == known.end()) {
        const std::string hint = closestName(c, known);
        throw InputError(r.where("channels"), "unknown channel '" + c + "'" +
                                                  (hint.empty() ? std::string(" (see `twin list`)") : " (did you mean '" + hint + "'?)"));
      }
      if (std::find(lab.channels.begin(), lab.channels.begin() + static_cast<long>(i), c) != lab.channels.begin() + static_cast<long>(i))
        throw InputError(r.where("channels"), "channel '" + c + "' listed twice");
    }
    if (r.has("auto_times")) {
      if (!lab.times_s.empty()) throw InputError(r.where("auto_times"), "give either times_s or auto_times, not both");
      lab.auto_times = *r.integer("auto_times");
      if (lab.auto_times <= 0) throw InputError(r.where("auto_times"), "must be a positive integer, got " + std::to_string(lab.auto_times));
    }
    if (r.has("min_separation_s")) {
      if (!lab.times_s.empty()) throw InputError(r.where("min_separation_s"), "applies to automatic times only (times_s is given)");
      lab.min_separation_s = *r.number("min_separation_s");
      if (!(lab.min_separation_s >= 0)) throw InputError(r.where("min_separation_s"), "must be >= 0");
    }
    r.finish();
  }
  if (auto* t = top.table("calibration")) {
    TableReader r(*t, path, "calibration");
    auto& c = s.calibration;
    if (auto v = r.string("region")) {
      if (*v != "joint" && *v != "paper")
        throw InputError(r.where("region"), "must be \"joint\" (the joint 1 % likelihood-ratio region, default) or \"paper\" "
                                            "(the paper's one-at-a-time box), got \"" + *v + "\"");
      c.region = *v;
    }
    if (auto v = r.string("design")) {
      if (*v != "adaptive" && *v != "lhs")
        throw InputError(r.where("design"), "must be \"adaptive\" (Latin hypercube, then rounds where the posterior lies) or "
                                            "\"lhs\" (one Latin hypercube), got \"" + *v + "\"");
      c.design = *v;
    }
    if (auto v = r.integer("round_points")) {
      c.round_points = *v;
      if (c.round_points < 2) throw InputError(r.where("round_points"), "must be an integer >= 2, got " + std::to_string(c.round_points));
    }
    if (auto v = r.integer("max_rounds")) {
      c.max_rounds = *v;
      if (c.max_rounds < 0 || c.max_rounds > 100)
        throw InputError(r.where("max_rounds"), "must be an integer in [0, 100], got " + std::to_string(c.max_rounds));
    }
    if (auto v = r.number("target_ess")) {
      c.target_ess = *v;
      if (!(std::isfinite(c.target_ess) && c.target_ess > 0)) throw InputError(r.where("target_ess"), "must be a finite number > 0");
    }
    if (auto v = r.string("interval")) {
      if (*v != "profile" && *v != "posterior")
        throw InputError(r.where("interval"), "must be \"profile\" (the profile-likelihood interval, default) or \"posterior\" "
                                              "(the posterior's central interval), got \"" + *v + "\"");
      c.interval = *v;
    }
    if (auto v = r.number("margin")) {
      c.margin = *v;
      if (!(std::isfinite(c.margin) && c.margin >= 1 && c.margin <= 10)) throw InputError(r.where("margin"), "must be a number in [1, 10]");
    }
    if (auto v = r.integer("ridge_steps")) {
      c.ridge_steps = *v;
      if (c.ridge_steps < 0 || c.ridge_steps > 1000)
        throw InputError(r.where("ridge_steps"), "must be an integer in [0, 1000], got " + std::to_string(c.ridge_steps));
    }
    r.finish();
  }
  top.finish();

  // Cross-checks against the vehicle data: names, units and bounds of calibrated parameters.
  const ParameterTable table = s.parameterTable();
  for (std::size_t i = 0; i < s.calibrated.size(); ++i) {
    const auto& c = s.calibrated[i];
    const std::string where = path + ": calibrated[" + std::to_string(i) + "]";
    if (!table.contains(c.name)) throw InputError(where + ".name", "unknown parameter '" + c.name + "'");
    const auto& spec = table.at(c.name).spec;
    if (!c.unit.empty() && c.unit != spec.unit)
      throw InputError(where + ".unit", "unit of '" + c.name + "' must be \"" + spec.unit + "\", got \"" + c.unit + "\"");
    for (double b : {c.lower, c.upper}) {
      const std::string rule = checkParameterValue(spec, b);
      if (!rule.empty()) throw InputError(where, "bound of " + c.name + " " + rule);
    }
  }
  for (const auto& a : s.assemblies()) s.makeModel(a);  // validates every assembly now
  return s;
}

std::vector<AssemblySpec> Study::assemblies() const {
  std::vector<AssemblySpec> out;
  std::vector<std::size_t> idx(subsystems.size(), 0);
  int n = 0;
  while (true) {
    AssemblySpec a;
    a.id = "M" + std::to_string(++n);
    for (std::size_t i = 0; i < subsystems.size(); ++i) a.options.push_back({subsystems[i].first, subsystems[i].second[idx[i]]});
    for (const auto& e : effects) a.effects.push_back(e.name);
    if (include.empty() || std::find(include.begin(), include.end(), a.id) != include.end()) out.push_back(a);
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
  throw InputError(path + ": assemblies", "unknown assembly '" + id + "' (this study defines: " + known + ")");
}

const ScenarioSpec& Study::scenario(const std::string& n) const {
  std::string known;
  for (const auto& sc : scenarios) {
    if (sc.name == n) return sc;
    known += (known.empty() ? "" : ", ") + sc.name;
  }
  throw InputError(path + ": scenarios", "unknown scenario '" + n + "' (this study defines: " + known + ")");
}

ParameterTable Study::parameterTable(const std::vector<ParameterSetting>& overrides) const {
  ParameterTable t = declareVehicleParameters();
  loadVehicleFile(t, vehicle_path);
  for (const auto& f : fixed) t.set(f.name, f.value, f.source, f.where);
  for (std::size_t i = 0; i < calibrated.size(); ++i)
    if (calibrated[i].truth && t.contains(calibrated[i].name))
      t.set(calibrated[i].name, *calibrated[i].truth, path + " [calibrated] truth", path + ": calibrated[" + std::to_string(i) + "].truth");
  for (const auto& e : effects)
    for (const auto& v : e.values) t.set(v.name, v.value, v.source, v.where);
  for (const auto& o : overrides) t.set(o.name, o.value, o.source, o.where);
  return t;
}

std::shared_ptr<const Model> Study::makeModel(const AssemblySpec& a, const std::vector<EffectSetting>& extra,
                                              const std::vector<ParameterSetting>& overrides) const {
  AssemblySpec spec = a;
  std::vector<ParameterSetting> all;
  for (const auto& e : extra) {
    makeEffect(e.name, "--effect");
    if (std::find(spec.effects.begin(), spec.effects.end(), e.name) == spec.effects.end()) spec.effects.push_back(e.name);
    all.insert(all.end(), e.values.begin(), e.values.end());
  }
  all.insert(all.end(), overrides.begin(), overrides.end());
  return std::make_shared<const Model>(spec, parameterTable(all), path);
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
    nlohmann::json cj = {{"name", c.name}, {"unit", c.unit}, {"lower", c.lower}, {"upper", c.upper}};
    if (c.truth) cj["truth"] = *c.truth;
    j["calibrated"].push_back(cj);
  }
  j["noise_variance_N2"] = noise_variance_N2;
  j["sizes"] = sizes;
  j["lab"] = lab.toJson();
  j["calibration"] = calibration.toJson();
  return j;
}

ParameterSetting parseSetting(const std::string& text, const std::string& where) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError(where, "expected NAME=VALUE, got '" + text + "'");
  const std::string name = text.substr(0, eq), val = text.substr(eq + 1);
  char* end = nullptr;
  const double v = std::strtod(val.c_str(), &end);
  if (val.empty() || *end != '\0') throw InputError(where, "value of " + name + " must be a number, got '" + val + "'");
  return {name, v, where + " " + name, where};
}

EffectSetting parseEffectSetting(const std::string& text, const std::string& where) {
  const auto colon = text.find(':');
  EffectSetting e;
  e.name = text.substr(0, colon);
  makeEffect(e.name, where);
  if (colon != std::string::npos) {
    std::stringstream ss(text.substr(colon + 1));
    std::string item;
    while (std::getline(ss, item, ',')) {
      auto s = parseSetting(item, where);
      s.name = e.name + "." + s.name;
      e.values.push_back(s);
    }
  }
  return e;
}

}  // namespace dtwin
