#include "twin/model.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <limits>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "twin/trace.hpp"

namespace dtwin {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

ParameterSpec fixedSpec(std::string name, std::string unit, std::string desc, double lo,
                        bool lo_incl) {
  ParameterSpec s;
  s.name = std::move(name);
  s.unit = std::move(unit);
  s.description = std::move(desc);
  s.min_value = lo;
  s.min_inclusive = lo_incl;
  s.max_value = kInf;
  return s;
}

std::string fullName(const std::string& subsystem, const std::string& option,
                     const ParameterSpec& s) {
  return s.shared ? subsystem + "." + s.name : subsystem + "." + option + "." + s.name;
}

}  // namespace

std::string AssemblySpec::option(const std::string& subsystem) const {
  for (auto& [s, o] : options)
    if (s == subsystem) return o;
  return {};
}

std::string AssemblySpec::label() const {
  std::string out;
  for (auto& [s, o] : options) out += (out.empty() ? "" : " + ") + o;
  for (auto& e : effects) out += " + " + e;
  for (auto& f : freed) out += " + free " + f;
  return out;
}

const std::vector<std::string>& freeableVehicleParameters() {
  static const std::vector<std::string> names = {"wheel.mass_kg",
                                                 "chassis.mass_kg",
                                                 "chassis.roll_inertia_kgm2",
                                                 "chassis.pitch_inertia_kgm2",
                                                 "chassis.cg_height_m",
                                                 "chassis.cg_x_m",
                                                 "geometry.track_m",
                                                 "solid_axle.mass_kg",
                                                 "solid_axle.roll_inertia_kgm2",
                                                 "solid_axle.spring_track_m"};
  return names;
}

namespace {}  // namespace

const Registry<SuspensionTopology>& suspensionOptions() {
  // Each is a mobilizer layout of the simulator (its system builder, twin/vehicle_system.cpp), so a
  // new one needs simulator code, not only an entry here.
  static const Registry<SuspensionTopology> r(
      "suspension option",
      {
          {"macpherson",
           "independent struts: each wheel carrier slides along the chassis z axis (paper eq. 4)",
           SuspensionTopology::MacPherson},
          {"solid_axle",
           "a rigid axle per axle (heave and roll), each wheel on it through a compliant interface "
           "(paper eq. 5)",
           SuspensionTopology::SolidAxle},
      });
  return r;
}

const std::vector<RoadSignalForm>& roadSignalForms() {
  // Per corner (fl, fr, rl, rr): the weight of the signal at the form, and whether the corner
  // reads it without the wheelbase's lag (a rear wheel that is itself the signal's place).
  static const std::vector<RoadSignalForm> forms = {
      {"road.fl_only",
       "the front-left wheel's",
       "share of the way to the road signal at the front-left wheel alone (0: under both axles)",
       {1, 0, 0, 0},
       {0, 0, 0, 0}},
      {"road.fr_only",
       "the front-right wheel's",
       "share of the way to the road signal at the front-right wheel alone (0: under both axles)",
       {0, 1, 0, 0},
       {0, 0, 0, 0}},
      {"road.rl_only",
       "the rear-left wheel's",
       "share of the way to the road signal at the rear-left wheel alone, without the wheelbase's "
       "lag (0: under both axles)",
       {0, 0, 1, 0},
       {0, 0, 1, 0}},
      {"road.rr_only",
       "the rear-right wheel's",
       "share of the way to the road signal at the rear-right wheel alone, without the wheelbase's "
       "lag (0: under both axles)",
       {0, 0, 0, 1},
       {0, 0, 0, 1}},
      {"road.left_only",
       "the left track's",
       "share of the way to the road signal under the left wheels alone, the rear a wheelbase "
       "later (0: under both axles)",
       {1, 0, 1, 0},
       {0, 0, 0, 0}},
      {"road.right_only",
       "the right track's",
       "share of the way to the road signal under the right wheels alone, the rear a wheelbase "
       "later (0: under both axles)",
       {0, 1, 0, 1},
       {0, 0, 0, 0}},
      {"road.all_at_once",
       "every wheel's at once",
       "share of the way to the same road signal at all four wheels at once, the rear without the "
       "wheelbase's lag (0: the rear a wheelbase later)",
       {1, 1, 1, 1},
       {0, 0, 1, 1}},
  };
  return forms;
}

const std::map<std::string, std::vector<std::string>>& knownSubsystems() {
  static const std::map<std::string, std::vector<std::string>> k = [] {
    const std::vector<std::string> susp = suspensionOptions().names();
    // `strut` is optional in a study: without it every assembly uses the first registered law.
    return std::map<std::string, std::vector<std::string>>{
        {"tire", tireLawNames()}, {"suspension", susp}, {"strut", strutLawNames()}};
  }();
  return k;
}

ParameterTable declareVehicleParameters(const EffectCatalog& catalog) {
  ParameterTable t;
  auto fixed = [&](const char* n, const char* u, const char* d, double lo = 0.0,
                   bool incl = false) { t.declare(fixedSpec(n, u, d, lo, incl)); };
  fixed("environment.gravity_mps2", "m/s^2", "gravitational acceleration");
  fixed("chassis.mass_kg", "kg", "sprung mass");
  fixed("chassis.roll_inertia_kgm2", "kg*m^2", "sprung-mass roll inertia about the CG");
  fixed("chassis.pitch_inertia_kgm2", "kg*m^2", "sprung-mass pitch inertia about the CG");
  fixed("chassis.yaw_inertia_kgm2", "kg*m^2", "sprung-mass yaw inertia about the CG");
  fixed("chassis.cg_height_m", "m", "sprung-mass CG height above ground at design ride height");
  fixed("geometry.cg_to_front_axle_m", "m", "longitudinal distance sprung CG to front axle");
  fixed("geometry.cg_to_rear_axle_m", "m", "longitudinal distance sprung CG to rear axle");
  fixed("geometry.track_m", "m", "track width (wheel centre to wheel centre)");
  // Not in a vehicle file: a diagnosis frees it (free:chassis.cg_x_m) to move the weight
  // distribution at a fixed wheelbase; 0 is the file's CG.
  t.declare(fixedSpec("chassis.cg_x_m", "m",
                      "forward shift of the sprung CG from the vehicle file's position at a fixed "
                      "wheelbase (a - x, b + x)",
                      -kInf, true));
  t.set("chassis.cg_x_m", 0.0, "default (the vehicle file's CG)", "");
  // The road signal as the run reads it: its gain and its delay relative to the measured channels
  // (1 and 0: as logged). Not in a vehicle file; a calibration or a diagnosis may move them.
  t.declare(fixedSpec("road.gain", "1", "gain of the road signal (1: as logged)", 0.0, false));
  t.set("road.gain", 1.0, "default (the road as logged)", "");
  {
    ParameterSpec d = fixedSpec(
        "road.delay_s", "s",
        "delay of the road signal relative to the measured channels (positive: logged late)", -1.0,
        true);
    d.max_value = 1.0;
    t.declare(d);
    t.set("road.delay_s", 0.0, "default (the road as logged)", "");
  }
  // Where the road signal enters (docs/model.md, "Where the road signal is"): each form's share
  // λ moves the run from the axle form (0: the signal under the front wheels, the rear a
  // wheelbase later) towards that form (1). Not in a vehicle file; a study may fix them and a
  // diagnosis weighs them.
  for (const RoadSignalForm& f : roadSignalForms()) {
    ParameterSpec d = fixedSpec(f.name, "1", f.description, -1.0, true);
    d.max_value = 2.0;
    t.declare(d);
    t.set(f.name, 0.0, "default (the signal under the front axle, the rear a wheelbase later)", "");
  }
  fixed("wheel.mass_kg", "kg", "wheel (unsprung) mass, each");
  fixed("solid_axle.mass_kg", "kg", "axle beam mass (solid axle only), each axle");
  fixed("solid_axle.roll_inertia_kgm2", "kg*m^2", "axle roll inertia about its centre");
  fixed("solid_axle.spring_track_m", "m", "lateral distance between the axle's spring seats");
  // Tire options.
  std::vector<std::string> declared;
  for (const auto& opt : knownSubsystems().at("tire")) {
    auto law = makeTireLaw(opt, "");
    for (auto s : law->parameters()) {
      s.name = fullName("tire", opt, s);
      if (t.contains(s.name)) continue;
      t.declare(s);
      // A law's own constant with a stated default (the hub link's stiffness and damping) needs
      // no vehicle file entry; a vehicle file may still set it.
      if (!s.shared && s.default_value != 0.0)
        t.set(s.name, s.default_value, "default of the " + opt + " option", "");
    }
  }
  // Suspension options: the parameters of every strut law, per suspension option (the
  // contract's shared stiffness and damping once).
  for (const auto& law_name : strutLawNames()) {
    const auto law = makeStrutLaw(law_name, "");
    for (const auto& opt : knownSubsystems().at("suspension"))
      for (auto s : law->parameters()) {
        s.name = fullName("suspension", opt, s);
        if (!t.contains(s.name)) t.declare(s);
      }
  }
  declareCornerFactors(t);
  fixed("suspension.solid_axle.interface_stiffness", "N/m",
        "wheel/axle interface stiffness k_wa (eq. 5)");
  fixed("suspension.solid_axle.interface_damping", "N*s/m",
        "wheel/axle interface damping c_wa (eq. 5)", 0.0, true);
  fixed("suspension.solid_axle.interface_preload_N", "N", "wheel/axle interface preload F0 (eq. 5)",
        -kInf, true);
  fixed("suspension.solid_axle.interface_travel_limit_m", "m",
        "wheel/axle interface travel before its hardstop");
  fixed("suspension.solid_axle.interface_hardstop_stiffness", "N/m",
        "wheel/axle interface hardstop stiffness", 0.0, true);
  // Effects: pre-set to their "off" values.
  for (const auto& e : catalog.names()) {
    auto eff = catalog.make(e, "");
    for (auto s : eff->parameters()) {
      s.name = e + "." + s.name;
      const double off = s.default_value;
      t.declare(s);
      t.set(s.name, off, "effect default (off)", "");
    }
  }
  return t;
}

void checkChassisInertias(const ParameterTable& table, const std::string& where) {
  const char* names[3] = {"chassis.roll_inertia_kgm2", "chassis.pitch_inertia_kgm2",
                          "chassis.yaw_inertia_kgm2"};
  double i[3];
  for (int k = 0; k < 3; ++k) {
    if (!table.contains(names[k]) || !table.at(names[k]).has_value)
      return;  // "no value" is reported by the Model
    i[k] = table.value(names[k]);
  }
  if (!(i[0] > 0 && i[1] > 0 && i[2] > 0)) return;  // the parameters' own ranges refuse these
  if (i[0] + i[1] >= i[2] && i[1] + i[2] >= i[0] && i[0] + i[2] >= i[1]) return;
  throw InputError(
      where, "the chassis inertias roll " + formatNumber(i[0]) + ", pitch " + formatNumber(i[1]) +
                 " and yaw " + formatNumber(i[2]) +
                 " kg*m^2 break the triangle inequality (each at most the sum of the other "
                 "two): no rigid body has them");
}

double yawInertiaInTriangle(double ixx, double iyy, double izz) {
  return std::clamp(izz, std::abs(ixx - iyy), ixx + iyy);
}

void declareSensorParameters(ParameterTable& table, const std::vector<SensorSpec>& sensors) {
  auto declare = [&](const std::string& name, const std::string& unit, const std::string& desc,
                     double lo, double hi, double v) {
    if (table.contains(name)) return;
    ParameterSpec s;
    s.name = name;
    s.unit = unit;
    s.description = desc;
    s.min_value = lo;
    s.max_value = hi;
    s.default_value = v;
    table.declare(s);
    table.set(name, v, "sensor " + name.substr(0, name.rfind('.')), "[sensors]");
  };
  const char* axis[3] = {"x_m", "y_m", "z_m"};
  const char* words[3] = {"forward", "left", "up"};
  for (const auto& x : sensors) {
    const std::string p = "sensors." + x.name + ".";
    if (x.corner() < 0 && !x.relative())
      for (int k = 0; k < 3; ++k)
        declare(p + axis[k], "m",
                std::string("the sensor's position from the centre of mass, ") + words[k], -10.0,
                10.0, x.position_m[static_cast<std::size_t>(k)]);
    declare(p + "offset", x.unit(), "a constant the sensor adds to what it measures", -kInf, kInf,
            0.0);
  }
}

void declareEffectParameters(ParameterTable& table, const Effect& effect, const std::string& name,
                             const std::string& where) {
  for (auto s : effect.parameters()) {
    s.name = name + "." + s.name;
    if (table.contains(s.name)) continue;
    const double off = s.default_value;
    table.declare(s);
    table.set(s.name, off, "effect default (off)", where);
  }
}

std::optional<PhysicalLimit> physicalLimit(const std::string& name, const ParameterTable& table) {
  // Passenger cars to light trucks (and a logger's estimate of the road for the road values). The
  // bounds are wide on purpose: they say what no road vehicle has, not what is typical.
  static const std::map<std::string, PhysicalLimit> limits = {
      {"tire.stiffness",
       {50e3, 2e6,
        "road-vehicle tires are 150 to 450 kN/m, truck tires up to about 1.5 MN/m; far stiffer is "
        "a wheel that follows the road signal (the hub input)"}},
      {"tire.damping", {0.0, 2e4, "tire damping is a few hundred to a few thousand N s/m"}},
      {"suspension.stiffness",
       {3e3, 4e5, "wheel rates run from 10 kN/m (soft cars) to 300 kN/m (trucks)"}},
      {"suspension.damping", {100.0, 6e4, "damping per corner of a road vehicle"}},
      {"chassis.mass_kg", {150.0, 8000.0, "sprung masses from a small car to a light truck"}},
      {"chassis.pitch_inertia_kgm2", {100.0, 2e4, "pitch inertias of road vehicles"}},
      {"chassis.roll_inertia_kgm2", {30.0, 5000.0, "roll inertias of road vehicles"}},
      {"chassis.cg_height_m", {0.15, 1.6, "CG heights of road vehicles"}},
      {"wheel.mass_kg", {3.0, 200.0, "a wheel with its carrier, small car to truck"}},
      {"solid_axle.mass_kg", {10.0, 400.0, "axle beams"}},
      {"road.gain",
       {0.1, 10.0, "a road signal off by more than a factor of 10 is no estimate of the road"}},
      {"road.delay_s", {-0.5, 0.5, "a logger's channels more than 0.5 s apart are not one record"}},
      {"road.fl_only", {-0.5, 1.5, "a share of the way from the axle form to the form"}},
      {"road.fr_only", {-0.5, 1.5, "a share of the way from the axle form to the form"}},
      {"road.rl_only", {-0.5, 1.5, "a share of the way from the axle form to the form"}},
      {"road.rr_only", {-0.5, 1.5, "a share of the way from the axle form to the form"}},
      {"road.left_only", {-0.5, 1.5, "a share of the way from the axle form to the form"}},
      {"road.right_only", {-0.5, 1.5, "a share of the way from the axle form to the form"}},
      {"road.all_at_once", {-0.5, 1.5, "a share of the way from the axle form to the form"}},
  };
  if (const auto it = limits.find(name); it != limits.end()) return it->second;
  if (parseCornerFactor(name))
    return PhysicalLimit{0.05, 5.0,
                         "a corner's spring, damper or tire more than a factor of 5 off the "
                         "others' is another part, not a fault of one"};
  if (name == "chassis.cg_x_m" && table.contains("geometry.cg_to_front_axle_m") &&
      table.contains("geometry.cg_to_rear_axle_m")) {
    const double a = table.value("geometry.cg_to_front_axle_m"),
                 b = table.value("geometry.cg_to_rear_axle_m");
    return PhysicalLimit{-0.9 * b, 0.9 * a, "the CG lies between the axles"};
  }
  if (name.rfind("sensors.", 0) == 0) {
    const auto dot = name.rfind('.');
    const std::string axis = name.substr(dot + 1);
    if (axis == "x_m") return PhysicalLimit{-4.0, 4.0, "a point of the car's body, from the CG"};
    if (axis == "y_m") return PhysicalLimit{-1.3, 1.3, "a point of the car's body, from the CG"};
    if (axis == "z_m") return PhysicalLimit{-1.0, 2.0, "a point of the car's body, from the CG"};
  }
  return std::nullopt;
}

// ------------------------------------------------------------------ Model
Model::Model(AssemblySpec assembly, ParameterTable table, const std::string& where,
             std::vector<SensorSpec> sensors, std::shared_ptr<const EffectCatalog> catalog)
    : assembly_(std::move(assembly)),
      table_(std::move(table)),
      sensors_(std::move(sensors)),
      catalog_(std::move(catalog)),
      where_(where) {
  if (!catalog_) throw std::invalid_argument("Model: no effect catalogue");
  const std::string tire = assembly_.option("tire"), susp = assembly_.option("suspension");
  if (tire.empty()) throw InputError(where, "assembly " + assembly_.id + " has no tire option");
  if (susp.empty())
    throw InputError(where, "assembly " + assembly_.id + " has no suspension option");
  tire_ = makeTireLaw(tire, where);
  const std::string strut = assembly_.option("strut");
  strut_ = makeStrutLaw(strut.empty() ? strutLawNames().front() : strut, where);
  topology_ = suspensionOptions().at(susp, where).value;

  auto need = [&](const std::string& n) {
    const auto& e = table_.at(n);
    if (!e.has_value)
      throw InputError(where, "no value for required parameter '" + n +
                                  "' (set it in the vehicle file or the study)");
    return e.value;
  };
  vehicle_.gravity = need("environment.gravity_mps2");
  vehicle_.chassis_mass = need("chassis.mass_kg");
  vehicle_.ixx = need("chassis.roll_inertia_kgm2");
  vehicle_.iyy = need("chassis.pitch_inertia_kgm2");
  // Yaw is not a degree of freedom of the model: the yaw inertia enters only through the roll-pitch
  // coupling, and follows a roll or pitch inertia moved away from the vehicle file's (a freed or
  // hidden value) into the triangle inequality, which the file's own three satisfy (checked when it
  // is read).
  vehicle_.izz = yawInertiaInTriangle(vehicle_.ixx, vehicle_.iyy, need("chassis.yaw_inertia_kgm2"));
  vehicle_.cg_height = need("chassis.cg_height_m");
  // The CG moved forward by cg_x at a fixed wheelbase: the axles stay where they are on the road
  // (every road and the wheel contact points are laid out by the wheelbase and the front axle).
  const double cg_x = need("chassis.cg_x_m");
  vehicle_.a = need("geometry.cg_to_front_axle_m") - cg_x;
  vehicle_.b = need("geometry.cg_to_rear_axle_m") + cg_x;
  if (!(vehicle_.a > 0 && vehicle_.b > 0))
    throw InputError(where, "chassis.cg_x_m = " + formatNumber(cg_x) +
                                " m puts the CG outside the wheelbase (it must lie in (" +
                                formatNumber(-need("geometry.cg_to_rear_axle_m")) + ", " +
                                formatNumber(need("geometry.cg_to_front_axle_m")) + ") m)");
  vehicle_.track = need("geometry.track_m");
  vehicle_.wheel_mass = need("wheel.mass_kg");
  if (topology_ == SuspensionTopology::SolidAxle) {
    vehicle_.axle_mass = need("solid_axle.mass_kg");
    vehicle_.axle_ixx = need("solid_axle.roll_inertia_kgm2");
    vehicle_.spring_track = need("solid_axle.spring_track_m");
  }

  for (const auto& s : tire_->parameters())
    tire_slots_.push_back(addRunParameter(fullName("tire", tire, s)));
  for (const auto& s : strut_->parameters())
    susp_slots_.push_back(addRunParameter(fullName("suspension", susp, s)));
  if (topology_ == SuspensionTopology::SolidAxle) {
    iface_slots_ = {addRunParameter("suspension.solid_axle.interface_stiffness"),
                    addRunParameter("suspension.solid_axle.interface_damping"),
                    addRunParameter("suspension.solid_axle.interface_travel_limit_m"),
                    addRunParameter("suspension.solid_axle.interface_hardstop_stiffness")};
    iface_preload_slot_ = addRunParameter("suspension.solid_axle.interface_preload_N");
  }
  for (const auto& e : assembly_.effects) {
    std::shared_ptr<const Effect> eff = catalog_->make(e, where);
    declareEffectParameters(table_, *eff, e, where);
    std::vector<int> slots;
    for (const auto& s : eff->parameters()) slots.push_back(addRunParameter(e + "." + s.name));
    effects_.push_back(std::move(eff));
    effect_slots_.push_back(std::move(slots));
    effect_corners_.push_back(splitEffectPlace(e, where).corner);
  }
  for (const auto& f : assembly_.freed) {
    if (parseCornerFactor(f)) continue;  // a factor: addCornerFactors
    if (const std::string rule = cornerFactorRule(f); !rule.empty()) throw InputError(where, rule);
    const auto& freeable = freeableVehicleParameters();
    if (std::find(freeable.begin(), freeable.end(), f) == freeable.end())
      throw InputError(where, unknownNameRule("freeable vehicle value", f, freeable));
    if (f.rfind("solid_axle.", 0) == 0 && topology_ != SuspensionTopology::SolidAxle)
      throw InputError(where, "'" + f + "' cannot be freed in assembly " + assembly_.id +
                                  ": it has no solid axle");
    if (slot(f) >= 0) throw InputError(where, "'" + f + "' is freed twice");
    freed_slots_.push_back(addRunParameter(f));
  }
  addCornerFactors();
  declareSensorParameters(table_, sensors_);
  for (const auto& x : sensors_) {
    const std::string p = "sensors." + x.name + ".";
    SensorSlots s;
    if (x.corner() < 0 && !x.relative()) {
      s.x = addRunParameter(p + "x_m");
      s.y = addRunParameter(p + "y_m");
      s.z = addRunParameter(p + "z_m");
    }
    s.offset = addRunParameter(p + "offset");
    sensor_slots_.push_back(s);
  }
  road_gain_slot_ = addRunParameter("road.gain");  // last: every other slot keeps its place
  road_delay_slot_ = addRunParameter("road.delay_s");
  for (const RoadSignalForm& f : roadSignalForms()) {
    const int slot = addRunParameter(f.name);
    if (road_form_slot_ < 0) road_form_slot_ = slot;
  }
  for (const auto& n : run_names_) need(n);
  const std::string rule = checkRunValues(defaultRunValues());
  if (!rule.empty()) throw InputError(where, rule);
}

int Model::addRunParameter(const std::string& name) {
  auto it = slots_.find(name);
  if (it != slots_.end()) return it->second;
  const int s = static_cast<int>(run_names_.size());
  run_names_.push_back(name);
  slots_[name] = s;
  return s;
}

void Model::addCornerFactors() {
  // A factor is a run parameter when the assembly frees it (a calibration, a diagnosis) or the
  // table holds it away from 1 (--set, [fixed], a hidden value); else it is nothing at all.
  for (const auto& f : assembly_.freed) {
    if (parseCornerFactor(f) && std::count(assembly_.freed.begin(), assembly_.freed.end(), f) > 1)
      throw InputError(where_, "'" + f + "' is freed twice");
  }
  for (const auto& name : cornerFactorNames()) {
    const bool freed =
        std::find(assembly_.freed.begin(), assembly_.freed.end(), name) != assembly_.freed.end();
    const bool set = table_.contains(name) && table_.value(name) != 1.0;
    if (!freed && !set) continue;
    const CornerFactor f = *parseCornerFactor(name);
    const bool tire = f.value.rfind("tire.", 0) == 0;
    const std::string local = f.value.substr(f.value.find('.') + 1);
    const auto& specs = tire ? tire_->parameters() : strut_->parameters();
    const auto it = std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& s) {
      return s.shared && s.name == local;
    });
    if (it ==
        specs.end()) {  // the hub input has no tire compliance: a calibration leaves the factor out
      if (!set) continue;
      throw InputError(where_, "'" + name + "': assembly " + assembly_.id + " (" +
                                   assembly_.label() + ") has no " + f.value);
    }
    const ScaledParameter sp{static_cast<std::size_t>(it - specs.begin()), addRunParameter(name)};
    for (int c = 0; c < 4; ++c) {
      const bool here = f.place < 4 ? f.place == c : (f.place == 4) == isFront(c);
      if (here) (tire ? tire_factors_ : strut_factors_)[static_cast<std::size_t>(c)].push_back(sp);
    }
  }
  // The axle's factor before the corner's, whatever the order of the names: value x axle x corner.
  auto axleFirst = [&](std::vector<ScaledParameter>& v) {
    std::stable_sort(v.begin(), v.end(), [&](const ScaledParameter& a, const ScaledParameter& b) {
      auto place = [&](const ScaledParameter& x) {
        return parseCornerFactor(run_names_[static_cast<std::size_t>(x.slot)])->place;
      };
      return (place(a) >= 4) > (place(b) >= 4);
    });
  };
  for (auto& v : strut_factors_) axleFirst(v);
  for (auto& v : tire_factors_) axleFirst(v);
}

int Model::slot(const std::string& name) const {
  auto it = slots_.find(name);
  return it == slots_.end() ? -1 : it->second;
}

bool Model::lacksOptionParameter(const std::string& name) const {
  if (const auto f = parseCornerFactor(name))
    return slot(name) < 0 && lacksOptionParameter(f->value);
  const std::string prefix = "tire.";
  if (name.rfind(prefix, 0) != 0 || slot(name) >= 0) return false;
  const std::string local = name.substr(prefix.size());
  if (local.find('.') != std::string::npos) return false;
  for (const auto& name : tireLawNames()) {
    const auto law = makeTireLaw(name, "");  // held: parameters() refers into it
    for (const auto& s : law->parameters())
      if (s.shared && s.name == local) return true;
  }
  return false;
}

std::vector<double> Model::defaultRunValues() const {
  std::vector<double> v;
  for (const auto& n : run_names_) v.push_back(table_.value(n));
  return v;
}

std::string Model::checkRunValues(const std::vector<double>& v) const {
  DTWIN_CHECK(v.size() == run_names_.size(), "run vector size");
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string rule = checkParameterValue(table_.at(run_names_[i]).spec, v[i]);
    if (!rule.empty()) return run_names_[i] + " " + rule;
  }
  std::vector<double> tp;
  for (int s : tire_slots_) tp.push_back(v[static_cast<std::size_t>(s)]);
  if (std::string rule = tire_->checkCombination(tp); !rule.empty()) return rule;
  for (int c = 0; c < 4; ++c) {  // a corner's scaled tire values must make a valid law too
    const auto& f = tire_factors_[static_cast<std::size_t>(c)];
    if (f.empty()) continue;
    LawValueBuffer buf{};
    const ParamValues scaled =
        scaledLawValues(v.data(), static_cast<std::size_t>(tire_slots_.front()), tp.size(), f, buf);
    if (std::string rule = tire_->checkCombination(scaled); !rule.empty())
      return std::string("at the ") + kCornerNames[static_cast<std::size_t>(c)] +
             " corner (its factors applied): " + rule;
  }
  return {};
}

ParamValues Model::scaledLawValues(const double* p, std::size_t p0, std::size_t n,
                                   const std::vector<ScaledParameter>& factors,
                                   LawValueBuffer& buf) {
  if (factors.empty()) return ParamValues(p + p0, n);
  DTWIN_CHECK(n <= buf.size(), "too many law parameters for a corner's scaled copy");
  std::copy(p + p0, p + p0 + n, buf.begin());
  for (const auto& f : factors) buf[f.index] *= p[f.slot];
  return ParamValues(buf.data(), n);
}

bool Model::builtFor(const std::vector<double>& values) const {
  for (int s : freed_slots_) {
    const auto i = static_cast<std::size_t>(s);
    if (i >= values.size() || values[i] != table_.value(run_names_[i])) return false;
  }
  return true;
}

std::shared_ptr<const Model> Model::withFreedValues(const std::vector<double>& values) const {
  DTWIN_CHECK(values.size() == run_names_.size(), "run vector size");
  ParameterTable t = table_;
  for (int s : freed_slots_) {
    const auto i = static_cast<std::size_t>(s);
    t.set(run_names_[i], values[i], "freed (run value)", where_ + ": " + run_names_[i]);
  }
  return std::make_shared<const Model>(assembly_, std::move(t), where_, sensors_, catalog_);
}

double Model::staticTireLoad(int corner) const {
  const auto& d = vehicle_;
  const double g = d.gravity;
  // Whole-vehicle CG from the sprung CG (x = 0) and the unsprung masses at the axles.
  const double m_unsprung_axle =
      2 * d.wheel_mass + (topology_ == SuspensionTopology::SolidAxle ? d.axle_mass : 0.0);
  const double M = d.total_mass(topology_);
  const double x_cg = m_unsprung_axle * (d.a - d.b) / M;
  const double axle_load =
      isFront(corner) ? M * g * (x_cg + d.b) / d.wheelbase() : M * g * (d.a - x_cg) / d.wheelbase();
  return 0.5 * axle_load;
}

double Model::staticStrutForce(int corner) const {
  const auto& d = vehicle_;
  const double sprung_axle =
      d.chassis_mass * d.gravity * (isFront(corner) ? d.b : d.a) / d.wheelbase();
  return 0.5 * sprung_axle;
}

}  // namespace dtwin
