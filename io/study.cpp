#include "io/study.hpp"

#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/toml_reader.hpp"
#include "io/measurement.hpp"
#include "io/speed_trace_file.hpp"
#include "io/vehicle_file.hpp"
#include "twin/road_setting.hpp"

namespace dtwin {
namespace {

/// [study]: name, description, seed and the vehicle file (relative to the study file).
void readStudyTable(TableReader& top, Study& s) {
  namespace fs = std::filesystem;
  const std::string& path = top.file();
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
    s.vehicle_path = r.resolvePath(*v);
    r.finish();
  } else {
    throw InputError(path, "missing [study] table");
  }
}

/// [subsystems]: the options of each subsystem, in the file's order (the assemblies are their
/// combinations).
void readSubsystems(TableReader& top, Study& s) {
  const std::string& path = top.file();
  if (auto* t = top.table("subsystems")) {
    TableReader r(*t, path, "subsystems");
    // toml++ iterates keys alphabetically; assemblies follow the file's order.
    std::vector<std::pair<int, std::string>> keys;
    for (auto&& [k, n] : *t)
      keys.push_back({static_cast<int>(n.source().begin.line), std::string(k.str())});
    std::sort(keys.begin(), keys.end());
    for (const auto& [line, sub] : keys) {
      const auto& known = knownSubsystems();
      if (!known.count(sub)) {
        std::vector<std::string> names;
        names.reserve(known.size());
        for (const auto& [name, options] : known) names.push_back(name);
        throw InputError(r.where(sub), unknownNameRule("subsystem", sub, names));
      }
      auto opts = r.strings(sub);
      if (opts.empty()) throw InputError(r.where(sub), "must list at least one option");
      for (std::size_t i = 0; i < opts.size(); ++i) {
        const auto& o = opts[i];
        const auto& ko = known.at(sub);
        if (std::find(opts.begin(), opts.begin() + static_cast<long>(i), o) !=
            opts.begin() + static_cast<long>(i))
          throw InputError(r.where(sub), "option '" + o + "' is listed twice");
        if (std::find(ko.begin(), ko.end(), o) == ko.end())
          throw InputError(r.where(sub), unknownNameRule(sub + " option", o, ko));
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
    if (!found)
      throw InputError(path + ": subsystems",
                       std::string("must name the '") + req + "' subsystem's options");
  }
}

/// [assemblies]: which combinations to include.
void readAssemblies(TableReader& top, Study& s) {
  const std::string& path = top.file();
  if (auto* t = top.table("assemblies")) {
    TableReader r(*t, path, "assemblies");
    s.include = r.strings("include");
    r.finish();
    // Each id names an assembly of the [subsystems] product (M1 .. Mn), once.
    std::size_t n = 1;
    for (const auto& [name, options] : s.subsystems) n *= options.size();
    std::set<std::string> seen;
    for (const auto& id : s.include) {
      bool known = false;
      for (std::size_t k = 1; k <= n && !known; ++k) known = id == "M" + std::to_string(k);
      if (!known)
        throw InputError(r.where("include"),
                         "names assembly '" + id +
                             "', which [subsystems] does not define (it defines M1.." + "M" +
                             std::to_string(n) + ")");
      if (!seen.insert(id).second)
        throw InputError(r.where("include"), "names assembly '" + id + "' twice");
    }
  }
}

/// [[calibrated]]: the calibrated parameters with their bounds and, when known, their truths.
void readCalibrated(TableReader& top, Study& s) {
  const std::string& path = top.file();
  if (auto* a = top.array("calibrated")) {
    int i = 0;
    for (auto&& el : *a) {
      const auto* t = el.as_table();
      if (!t)
        throw InputError(top.where("calibrated"), "must be an array of tables [[calibrated]]");
      TableReader r(*t, path, "calibrated[" + std::to_string(i++) + "]");
      CalibratedParameter c;
      auto n = r.string("name");
      if (!n) throw InputError(r.where("name"), "is required");
      c.name = *n;
      c.unit = r.string("unit").value_or("");
      c.lower = r.required("lower");
      c.upper = r.required("upper");
      if (!(c.lower < c.upper))
        throw InputError(r.where("lower"), "lower bound must be < upper bound, got " +
                                               std::to_string(c.lower) +
                                               " >= " + std::to_string(c.upper));
      c.truth = r.number("truth");
      if (c.truth && (*c.truth < c.lower || *c.truth > c.upper))
        throw InputError(r.where("truth"), "must lie within [lower, upper]");
      r.finish();
      s.calibrated.push_back(c);
    }
  }
}

/// [fixed]: parameter values that override the vehicle file.
void readFixed(TableReader& top, Study& s) {
  const std::string& path = top.file();
  if (auto* t = top.table("fixed")) {
    TableReader r(*t, path, "fixed");
    for (auto&& [k, n] : *t) {
      const std::string key(k.str());
      s.fixed.push_back({key, r.required(key), r.where(key), path + " [fixed]"});
    }
    r.finish();
  }
}

/// [user_effects.NAME]: an effect whose force is an expression (subsystems/user_effect.hpp), each
/// checked and added to `catalog` by name, so [effects], --effect, --hidden-effect and the
/// diagnosis can name it.
void readUserEffects(TableReader& top, EffectCatalog& catalog) {
  const std::string& path = top.file();
  auto* t = top.table("user_effects");
  if (!t) return;
  for (auto&& [key, node] : *t) {
    const std::string name(key.str());
    const std::string field = "user_effects." + name;
    auto* ut = node.as_table();
    if (!ut)
      throw InputError(path + ":" + std::to_string(node.source().begin.line) + ": " + field,
                       "must be a table (element, force, parameters)");
    TableReader r(*ut, path, field);
    UserEffectSpec u;
    u.name = name;
    u.where = path + ":" + std::to_string(ut->source().begin.line) + ": " + field;
    u.element = r.string("element").value_or("");
    if (u.element.empty())
      throw InputError(r.where("element"),
                       "is required (\"strut\", \"tire\", \"axle_roll\" or \"chassis\")");
    u.force = r.string("force").value_or("");
    if (auto* pt = r.table("parameters")) {
      TableReader pr(*pt, path, field + ".parameters");
      for (auto&& [pk, pn] : *pt) {
        const std::string pname(pk.str());
        const toml::table* one = pr.table(pname);
        if (!one)
          throw InputError(pr.where(pname),
                           "must be { value, unit, lower, upper } (optionally shape = true)");
        TableReader vr(*one, path, field + ".parameters." + pname);
        UserEffectParameter p;
        p.name = pname;
        p.unit = vr.string("unit").value_or("");
        if (p.unit.empty()) throw InputError(vr.where("unit"), "is required (\"1\" for none)");
        p.value = vr.required("value");
        p.lower = vr.required("lower");
        p.upper = vr.required("upper");
        p.shape = vr.boolean("shape").value_or(false);
        vr.finish();
        u.parameters.push_back(p);
      }
      pr.finish();
    }
    r.finish();
    catalog.add(u);  // every check of the definition (InputError naming file:line and field)
  }
}

/// [effects.NAME]: effects installed in every assembly, with their parameter values.
void readEffects(TableReader& top, Study& s) {
  const std::string& path = top.file();
  if (auto* t = top.table("effects")) {
    TableReader r(*t, path, "effects");
    for (auto&& [k, n] : *t) {
      const std::string eff(k.str());
      s.effectCatalog().make(eff, r.where(eff));  // validates the name
      const toml::table* et = r.table(eff);
      EffectSetting es{eff, {}};
      TableReader er(*et, path, "effects." + eff);
      for (auto&& [pk, pn] : *et) {
        const std::string key(pk.str());
        es.values.push_back(
            {eff + "." + key, er.required(key), er.where(key), path + " [effects." + eff + "]"});
      }
      er.finish();
      s.effects.push_back(es);
    }
    r.finish();
  }
}

/// speed = { csv = "FILE" }: a measured speed trace (path relative to the study file), which must
/// cover the scenario from time 0 to its duration, at most 100 m/s; the ramp's fields may not be
/// given too.
void readSpeedTrace(TableReader& rs, const std::string& csv, ScenarioSpec& sc) {
  namespace fs = std::filesystem;
  for (const char* f : {"v_final_mps", "ramp_s"})
    if (rs.has(f))
      throw InputError(
          rs.where(f),
          "give either csv (a measured speed trace) or v_final_mps and ramp_s, not both");
  const std::string file = rs.resolvePath(csv);
  auto trace = std::make_shared<const SpeedTrace>(readSpeedTraceCsv(file));
  if (trace->startTime() > 0 || trace->endTime() < sc.duration_s)
    throw InputError(rs.where("csv"),
                     "the speed trace " + file + " covers " + formatNumber(trace->startTime()) +
                         ".." + formatNumber(trace->endTime()) + " s but the scenario needs 0.." +
                         formatNumber(sc.duration_s) + " s");
  const auto& v = trace->speeds();
  const auto top = std::max_element(v.begin(), v.end());
  if (*top > 100)
    throw InputError(rs.where("csv"), "the speed trace " + file + " reaches " + formatNumber(*top) +
                                          " m/s at sample " + std::to_string(top - v.begin()) +
                                          "; at most 100 m/s");
  sc.speed.trace = std::move(trace);
}

/// [scenarios.NAME]: duration, speed profile and road (one of the registered road types), in the
/// file's order.
void readScenarios(TableReader& top, Study& s, bool required) {
  const std::string& path = top.file();
  if (auto* t = top.table("scenarios")) {
    std::vector<std::pair<int, std::string>> keys;
    for (auto&& [k, n] : *t)
      keys.push_back({static_cast<int>(n.source().begin.line), std::string(k.str())});
    std::sort(keys.begin(), keys.end());
    TableReader outer(*t, path, "scenarios");
    for (const auto& [line, key] : keys) {
      const toml::table* st = outer.table(key);
      TableReader r(*st, path, "scenarios." + key);
      ScenarioSpec sc;
      sc.name = key;
      sc.duration_s = r.positive("duration_s", 15.0);
      if (sc.duration_s > 86400)
        throw InputError(r.where("duration_s"),
                         "must be at most 86400 s, got " + formatNumber(sc.duration_s));
      if (auto* sp = r.table("speed")) {
        TableReader rs(*sp, path, r.field("speed"));
        sc.speed.start_m = rs.number("start_m", 0.0);
        if (!(std::isfinite(sc.speed.start_m) && std::abs(sc.speed.start_m) <= 1e7))
          throw InputError(rs.where("start_m"), "must be a finite distance of at most 1e7 m, got " +
                                                    formatNumber(sc.speed.start_m));
        if (auto csv = rs.string("csv")) {
          readSpeedTrace(rs, *csv, sc);
        } else {
          sc.speed.v_final_mps = rs.number("v_final_mps", 8.9408);
          sc.speed.ramp_s = rs.number("ramp_s", 5.0);
          if (sc.speed.v_final_mps < 0 || sc.speed.v_final_mps > 100)
            throw InputError(rs.where("v_final_mps"),
                             "must lie in [0, 100] m/s, got " + formatNumber(sc.speed.v_final_mps));
          if (sc.speed.ramp_s < 0) throw InputError(rs.where("ramp_s"), "must be >= 0");
        }
        rs.finish();
      }
      sc.road = parseRoadSetting(r);
      sc.road->check(sc, r.where("road"));
      r.finish();
      s.scenarios.push_back(sc);
    }
  }
  if (s.scenarios.empty() && required) throw InputError(path, "no [scenarios.*] defined");
}

/// [simulation]: integrator options (SimulationOptions::validate, errors at the study file's line).
void readSimulation(TableReader& top, Study& s) {
  const std::string& path = top.file();
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
    o.max_wall_s = r.number("max_wall_s", o.max_wall_s);
    o.hub_motion = r.string("hub_motion").value_or(o.hub_motion);
    if (auto n = r.integer("max_internal_steps")) o.max_internal_steps = static_cast<long>(*n);
    r.finish();
    try {
      o.validate();
    } catch (const InputError& e) {  // "simulation.<field>": name the line of the study file
      throw InputError(r.where(e.where().substr(e.where().rfind('.') + 1)), e.rule());
    }
  }
}

/// [noise]: the measurement noise variance.
void readNoise(TableReader& top, Study& s) {
  const std::string& path = top.file();
  if (auto* t = top.table("noise")) {
    TableReader r(*t, path, "noise");
    s.noise_variance_N2 = r.number("variance_N2", s.noise_variance_N2);
    if (!(s.noise_variance_N2 >= 0)) throw InputError(r.where("variance_N2"), "must be >= 0");
    r.finish();
  }
}

/// [sizes]: the study sizes (StudySizes::fields()), positive integers.
void readSizes(TableReader& top, Study& s) {
  const std::string& path = top.file();
  if (auto* t = top.table("sizes")) {
    TableReader r(*t, path, "sizes");
    for (auto&& [k, n] : *t) {
      const std::string key(k.str());
      if (!StudySizes{}.asMap().count(key)) continue;  // reported by finish()
      const long v = *r.integer(key);
      if (v <= 0)
        throw InputError(r.where(key), "must be a positive integer, got " + std::to_string(v));
      const long most = StudySizes::maximum(key);
      if (v > most)
        throw InputError(r.where(key), "must be at most " + std::to_string(most) +
                                           " (docs/study-file.md, Limits), got " +
                                           std::to_string(v));
      s.sizes.at(key) = v;
    }
    if (s.sizes.gibbs_burn_in >= s.sizes.gibbs_iterations)
      throw InputError(r.where(t->contains("gibbs_burn_in") ? "gibbs_burn_in" : "gibbs_iterations"),
                       "gibbs_burn_in (" + std::to_string(s.sizes.gibbs_burn_in) +
                           ") must be below gibbs_iterations (" +
                           std::to_string(s.sizes.gibbs_iterations) + ")");
    r.finish();
  }
}

/// [sensors.NAME]: where a sensor is mounted, what it measures and how the logger filtered it.
void readSensors(TableReader& top, Study& s) { s.sensors = readSensorTables(top); }
}  // namespace

std::vector<SensorSpec> readSensorTables(TableReader& top,
                                         const std::vector<SensorSpec>& existing) {
  std::vector<SensorSpec> out;
  const std::string& path = top.file();
  auto* t = top.table("sensors");
  if (!t) return out;
  std::vector<std::string> taken;
  for (const auto& c : runChannels(existing)) taken.push_back(c.name);
  for (auto&& [key, node] : *t) {
    const std::string name(key.str());
    const std::string field = "sensors." + name;
    auto* st = node.as_table();
    if (!st)
      throw InputError(path + ":" + std::to_string(node.source().begin.line) + ": " + field,
                       "must be a table");
    TableReader r(*st, path, field);
    const std::string where = path + ":" + std::to_string(st->source().begin.line) + ": " + field;
    SensorSpec x;
    x.name = name;
    x.mount = r.string("body").value_or("chassis");
    const auto q = r.string("quantity");
    if (!q)
      throw InputError(r.where("quantity"),
                       "is required (\"displacement_z\", \"velocity_z\" or \"acceleration_z\")");
    x.quantity = parseSensorQuantity(*q, r.where("quantity"));
    if (auto* a = r.array("position_m")) {
      if (a->size() != 3)
        throw InputError(r.where("position_m"), "must be [x, y, z] in metres (3 numbers), got " +
                                                    std::to_string(a->size()));
      for (std::size_t i = 0; i < 3; ++i) {
        const auto v = (*a)[i].value<double>();
        if (!v) throw InputError(r.where("position_m"), "must be [x, y, z] in metres (3 numbers)");
        x.position_m[i] = *v;
      }
    }
    if (auto* f = r.table("filter")) {
      TableReader fr(*f, path, field + ".filter");
      const auto order = fr.integer("order");
      if (!order)
        throw InputError(fr.where("order"), "is required (1 or 2; leave filter out for none)");
      x.filter.order = static_cast<int>(*order);
      x.filter.cutoff_hz = fr.number("cutoff_hz", 0.0);
      x.filter.damping = fr.number("damping", x.filter.damping);
      fr.finish();
    }
    x.noise_sd = r.number("noise_sd", 0.0);
    if (r.has("position_sd_m")) {
      x.position_sd_m = r.number("position_sd_m", -1.0);
      if (!(x.position_sd_m >= 0.0))  // a negative number would read as "not declared"
        throw InputError(
            r.where("position_sd_m"),
            "must be a finite number of metres in [0, 10], got " + formatNumber(x.position_sd_m));
    }
    r.finish();
    try {
      x.validate(field);
    } catch (const InputError& e) {  // the line of the sensor's table
      throw InputError(path + ":" + std::to_string(st->source().begin.line) + ": " + e.where(),
                       e.rule());
    }
    if (std::find(taken.begin(), taken.end(), x.channel()) != taken.end())
      throw InputError(where, "its channel " + x.channel() +
                                  " is already a channel of the twin: choose another sensor name");
    taken.push_back(x.channel());
    out.push_back(x);
  }
  return out;
}

namespace {

/// [lab]: lab times (given, or automatic), channels.
void readLab(TableReader& top, Study& s) {
  const std::string& path = top.file();
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
        if (!std::isfinite(*v) || *v < 0)
          throw InputError(r.where("times_s"), item + " must be a finite time >= 0");
        if (!lab.times_s.empty() && !(*v > lab.times_s.back()))
          throw InputError(
              r.where("times_s"),
              item + " must be greater than the one before it (times strictly increasing)");
        const double k = *v * s.simulation.output_rate_hz;
        if (std::abs(k - std::round(k)) > 1e-6)
          throw InputError(r.where("times_s"),
                           item + " is not on the output grid (multiples of 1/output_rate_hz = " +
                               std::to_string(1.0 / s.simulation.output_rate_hz) + " s)");
        lab.times_s.push_back(std::round(k) / s.simulation.output_rate_hz);
        ++i;
      }
      if (lab.times_s.empty())
        throw InputError(r.where("times_s"),
                         "must list at least one time (or leave it out for automatic times)");
    }
    lab.channels = r.strings("channels");
    std::vector<std::string> known;
    for (const auto& c : measurableChannels(s.sensors)) known.push_back(c.name);
    for (std::size_t i = 0; i < lab.channels.size(); ++i) {
      const auto& c = lab.channels[i];
      if (std::find(known.begin(), known.end(), c) == known.end()) {
        const std::string hint = closestName(c, known);
        throw InputError(r.where("channels"),
                         "unknown channel '" + c + "'" +
                             (hint.empty() ? std::string(" (see `twin list`)")
                                           : " (did you mean '" + hint + "'?)"));
      }
      if (std::find(lab.channels.begin(), lab.channels.begin() + static_cast<long>(i), c) !=
          lab.channels.begin() + static_cast<long>(i))
        throw InputError(r.where("channels"), "channel '" + c + "' listed twice");
    }
    if (r.has("auto_times")) {
      if (!lab.times_s.empty())
        throw InputError(r.where("auto_times"), "give either times_s or auto_times, not both");
      lab.auto_times = *r.integer("auto_times");
      if (lab.auto_times <= 0)
        throw InputError(r.where("auto_times"),
                         "must be a positive integer, got " + std::to_string(lab.auto_times));
    }
    if (r.has("min_separation_s")) {
      if (!lab.times_s.empty())
        throw InputError(r.where("min_separation_s"),
                         "applies to automatic times only (times_s is given)");
      lab.min_separation_s = *r.number("min_separation_s");
      if (!(lab.min_separation_s >= 0))
        throw InputError(r.where("min_separation_s"), "must be >= 0");
    }
    r.finish();
  }
}

/// [calibration]: region, design, rounds, interval and the region's margins.
void readCalibrationSettings(TableReader& top, Study& s) {
  const std::string& path = top.file();
  if (auto* t = top.table("calibration")) {
    TableReader r(*t, path, "calibration");
    auto& c = s.calibration;
    if (auto v = r.string("region")) {
      if (*v != "joint" && *v != "paper")
        throw InputError(
            r.where("region"),
            "must be \"joint\" (the joint 1 % likelihood-ratio region, default) or \"paper\" "
            "(the paper's one-at-a-time box), got \"" +
                *v + "\"");
      c.region = *v;
    }
    if (auto v = r.string("design")) {
      if (*v != "adaptive" && *v != "lhs")
        throw InputError(
            r.where("design"),
            "must be \"adaptive\" (Latin hypercube, then rounds where the posterior lies) or "
            "\"lhs\" (one Latin hypercube), got \"" +
                *v + "\"");
      c.design = *v;
    }
    if (auto v = r.integer("round_points")) {
      c.round_points = *v;
      if (c.round_points < 2)
        throw InputError(r.where("round_points"),
                         "must be an integer >= 2, got " + std::to_string(c.round_points));
    }
    if (auto v = r.integer("max_rounds")) {
      c.max_rounds = *v;
      if (c.max_rounds < 0 || c.max_rounds > 100)
        throw InputError(r.where("max_rounds"),
                         "must be an integer in [0, 100], got " + std::to_string(c.max_rounds));
    }
    if (auto v = r.number("target_ess")) {
      c.target_ess = *v;
      if (!(std::isfinite(c.target_ess) && c.target_ess > 0))
        throw InputError(r.where("target_ess"), "must be a finite number > 0");
    }
    if (auto v = r.string("interval")) {
      if (*v != "profile" && *v != "posterior")
        throw InputError(
            r.where("interval"),
            "must be \"profile\" (the profile-likelihood interval, default) or \"posterior\" "
            "(the posterior's central interval), got \"" +
                *v + "\"");
      c.interval = *v;
    }
    if (auto v = r.string("steps")) {
      if (*v != "frozen" && *v != "adaptive")
        throw InputError(r.where("steps"),
                         "must be \"frozen\" (one step sequence per stage, a smooth SSE; default) "
                         "or \"adaptive\" "
                         "(each run chooses its own steps), got \"" +
                             *v + "\"");
      c.steps = *v;
    }
    if (auto v = r.number("margin")) {
      c.margin = *v;
      if (!(std::isfinite(c.margin) && c.margin >= 1 && c.margin <= 10))
        throw InputError(r.where("margin"), "must be a number in [1, 10]");
    }
    if (auto v = r.integer("ridge_steps")) {
      c.ridge_steps = *v;
      if (c.ridge_steps < 0 || c.ridge_steps > 1000)
        throw InputError(r.where("ridge_steps"),
                         "must be an integer in [0, 1000], got " + std::to_string(c.ridge_steps));
    }
    r.finish();
  }
}

/// The calibrated parameters against the vehicle's parameter table: names, units and bounds.
void checkCalibratedAgainstVehicle(const Study& s) {
  const ParameterTable table = s.parameterTable();
  for (std::size_t i = 0; i < s.calibrated.size(); ++i) {
    const auto& c = s.calibrated[i];
    const std::string where = s.path + ": calibrated[" + std::to_string(i) + "]";
    if (!table.contains(c.name)) throw InputError(where + ".name", table.unknownRule(c.name));
    const auto& spec = table.at(c.name).spec;
    if (!c.unit.empty() && c.unit != spec.unit)
      throw InputError(where + ".unit", "unit of '" + c.name + "' must be \"" + spec.unit +
                                            "\", got \"" + c.unit + "\"");
    for (double b : {c.lower, c.upper}) {
      const std::string rule = checkParameterValue(spec, b);
      if (!rule.empty()) throw InputError(where, "bound of " + c.name + " " + rule);
    }
    if (c.name == "chassis.cg_x_m") {  // the CG stays between the axles at every value searched
      const double a = table.value("geometry.cg_to_front_axle_m"),
                   b = table.value("geometry.cg_to_rear_axle_m");
      if (!(c.lower > -b && c.upper < a))
        throw InputError(where,
                         "bounds of chassis.cg_x_m must keep the CG between the axles: inside (" +
                             formatNumber(-b) + ", " + formatNumber(a) + ") m, got [" +
                             formatNumber(c.lower) + ", " + formatNumber(c.upper) + "]");
    }
  }
}

}  // namespace

/// Every scenario's output trace must fit in memory: duration x output rate at most 1e7 samples.
void checkScenarioSamples(const Study& s) {
  for (const auto& sc : s.scenarios) {
    const double samples = sc.duration_s * s.simulation.output_rate_hz;
    if (samples > 1e7)
      throw InputError(s.path + ": scenarios." + sc.name + ".duration_s",
                       "gives " + formatNumber(samples, 3) +
                           " output samples at simulation.output_rate_hz = " +
                           formatNumber(s.simulation.output_rate_hz) +
                           " Hz; at most 1e7 (docs/study-file.md, Limits)");
  }
}

/// The TOML file `path` parsed; InputError naming the file (a `kind`, e.g. "study file") when it is
/// missing or a folder, or the line when it is malformed.
toml::table parseTomlFile(const std::string& path, const std::string& kind) {
  namespace fs = std::filesystem;
  if (!fs::exists(path)) throw InputError(path, kind + " not found");
  if (fs::is_directory(path)) throw InputError(path, "is a folder, not a " + kind);
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line),
                     "malformed TOML: " + std::string(e.description()));
  }
}

std::vector<UserEffectSpec> loadUserEffects(const std::string& path) {
  const toml::table root = parseTomlFile(path, "file of user-defined effects");
  TableReader top(root, path, "");
  EffectCatalog catalog;
  readUserEffects(top, catalog);
  top.finish();  // nothing but [user_effects] tables
  if (catalog.userEffects().empty()) throw InputError(path, "holds no [user_effects.NAME] table");
  return catalog.userEffects();
}

/// The study file, table by table (each reader checks its own fields and reports unknown ones),
/// then the cross-checks that need the whole study.
Study loadStudy(const std::string& path, bool scenarios_required) {
  const toml::table root = parseTomlFile(path, "study file");
  Study s;
  s.path = path;
  TableReader top(root, path, "");

  readStudyTable(top, s);
  readSubsystems(top, s);
  readAssemblies(top, s);
  readCalibrated(top, s);
  readFixed(top, s);
  {
    auto catalog = std::make_shared<EffectCatalog>();
    readUserEffects(top, *catalog);  // before [effects] and the assemblies, which may name them
    s.catalog = std::move(catalog);
  }
  readEffects(top, s);
  readScenarios(top, s, scenarios_required);
  readSimulation(top, s);
  readNoise(top, s);
  readSensors(top, s);
  readSizes(top, s);
  readLab(top, s);  // after [simulation]: lab times lie on its output grid
  readCalibrationSettings(top, s);
  top.finish();
  checkScenarioSamples(s);
  checkCalibratedAgainstVehicle(s);
  for (const auto& a : s.assemblies()) s.makeModel(a);  // validates every assembly now
  return s;
}

}  // namespace dtwin
