#include "diagnosis/candidates.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/names.hpp"
#include "subsystems/sensor.hpp"

namespace dtwin::diag {
namespace {

constexpr const char* kFree = "free:";
constexpr const char* kWiden = "widen:";
constexpr const char* kPlace = "place:";
constexpr const char* kRoadGain = "road.gain";
constexpr const char* kRoadDelay = "road.delay_s";

std::string num(const char* f, double v) { return formatPrintf(f, v); }

/// `v` to four significant digits in plain notation where it reads well (29910, not 2.991e+04).
std::string plain(double v) {
  const double a = std::abs(v);
  if (!(a >= 1e4 && a < 1e9)) return formatPrintf("%.4g", v);
  const double scale = std::pow(10.0, std::floor(std::log10(a)) - 3);
  return formatPrintf("%.0f", std::round(v / scale) * scale);
}

/// The unit suffix of a channel name ("hub_force_fl_N" -> "N"), "" when it has none.
std::string unitSuffix(const std::string& channel) {
  const auto u = channel.rfind('_');
  return u == std::string::npos ? "" : channel.substr(u + 1);
}

bool calibratedInStudy(const Study& study, const std::string& name) {
  return std::any_of(study.calibrated.begin(), study.calibrated.end(),
                     [&](const CalibratedParameter& c) { return c.name == name; });
}

/// "sensors.NAME.x_m", ".y_m" or ".z_m": where a chassis sensor sits.
bool isSensorPosition(const std::string& value) {
  if (value.rfind("sensors.", 0) != 0 || value.size() < 13) return false;
  const std::string tail = value.substr(value.size() - 4);
  return tail == ".x_m" || tail == ".y_m" || tail == ".z_m";
}

/// A road-signal form's share v in words, with its 95 % interval when given.
std::string roadFormFinding(const RoadSignalForm& f, double v, double lower, double upper) {
  const std::string interval = std::isfinite(lower) && std::isfinite(upper)
                                   ? " (share " + formatPrintf("%.2f", v) +
                                         ", 95 %: " + formatPrintf("%.2f", lower) + " to " +
                                         formatPrintf("%.2f", upper) + ")"
                                   : " (share " + formatPrintf("%.2f", v) + ")";
  const bool whole = std::isfinite(lower) && std::isfinite(upper)
                         ? (lower <= 1.0 && upper >= 1.0) || std::abs(v - 1.0) <= 0.1
                         : std::abs(v - 1.0) <= 0.15;
  const std::string name = f.name;
  if (name == "road.all_at_once")
    return whole ? "the road signal reaches all four wheels at once, the rear without the "
                   "wheelbase's lag" +
                       interval
                 : "the rear wheels meet the road signal earlier than a wheelbase after the front "
                   "ones" +
                       interval;
  std::string rest = "the other three wheels meet none of it";
  if (name == "road.left_only") rest = "the right wheels meet none of it";
  if (name == "road.right_only") rest = "the left wheels meet none of it";
  if (whole)
    return std::string("the road signal behaves as ") + f.whose + " road alone: " + rest + interval;
  return std::string("the road signal lies between the road under both axles and ") + f.whose +
         " road alone" + interval;
}

/// Where a sensor acts, in words: "the sensor seat acts as if it sat 1.35 m ahead of the CG,
/// over the front axle (the study puts it 0.4 m ahead)". a, b: CG to the front and rear axle;
/// track: the track width.
std::string sensorPlaceFinding(const std::string& value, double v, double study_v, double a,
                               double b, double track) {
  const std::string sensor = value.substr(8, value.rfind('.') - 8);
  const char axis = value[value.size() - 3];
  auto metres = [](double x) { return formatPrintf("%.2f m", std::abs(x)); };
  if (axis == 'x') {
    auto where_x = [&](double x) {
      return x >= 0 ? metres(x) + " ahead of the CG" : metres(x) + " behind the CG";
    };
    const double L = a + b, near = 0.1 * L;
    std::string place;
    if (a > 0 && b > 0) {
      if (std::abs(v - a) <= near)
        place = ", over the front axle";
      else if (v > a)
        place = ", ahead of the front axle";
      else if (std::abs(v + b) <= near)
        place = ", over the rear axle";
      else if (v < -b)
        place = ", behind the rear axle";
      else
        place = ", between the axles";
    }
    return "the sensor " + sensor + " acts as if it sat " + where_x(v) + place +
           " (the study puts it " + where_x(study_v) + ")";
  }
  if (axis == 'y') {
    auto where_y = [&](double y) {
      return y == 0
                 ? std::string("on the centre line")
                 : metres(y) + (y > 0 ? " left of the centre line" : " right of the centre line");
    };
    std::string place;
    if (track > 0) {
      const double h = 0.5 * track, near = 0.15 * track;
      if (std::abs(v - h) <= near)
        place = ", over the left wheels";
      else if (std::abs(v + h) <= near)
        place = ", over the right wheels";
      else if (std::abs(v) > h)
        place = v > 0 ? ", outside the left wheels" : ", outside the right wheels";
      else
        place = ", between the wheels";
    }
    return "the sensor " + sensor + " acts as if it sat " + where_y(v) + place +
           " (the study puts it " + where_y(study_v) + ")";
  }
  return "the sensor " + sensor + " acts as if it sat " + metres(v) +
         (v >= 0 ? " above" : " below") + " the CG (the study puts it " +
         formatPrintf("%.2f m", study_v) + ")";
}

/// Where a sensor acts in both coordinates, in words: "the sensor seat acts as if it sat 1.52 m
/// ahead of the CG and 0.78 m left of the centre line: over the front-left wheel (the study puts it
/// 0.00 m ahead of the CG, on the centre line)".
std::string sensorCornerFinding(const std::string& sensor, double x, double y, double study_x,
                                double study_y, double a, double b, double track) {
  auto fore = [](double v) {
    return formatPrintf("%.2f m", std::abs(v)) + (v >= 0 ? " ahead of the CG" : " behind the CG");
  };
  auto across = [](double v) {
    return v == 0 ? std::string("on the centre line")
                  : formatPrintf("%.2f m", std::abs(v)) +
                        (v > 0 ? " left of the centre line" : " right of the centre line");
  };
  std::string place;
  if (a > 0 && b > 0 && track > 0) {
    const double L = a + b, h = 0.5 * track;
    const bool front = std::abs(x - a) <= 0.1 * L, rear = std::abs(x + b) <= 0.1 * L;
    const bool left = std::abs(y - h) <= 0.15 * track, right = std::abs(y + h) <= 0.15 * track,
               centre = std::abs(y) <= 0.15 * track;
    const std::string axle = front ? "front" : rear ? "rear" : "";
    if (!axle.empty() && (left || right))
      place = "over the " + axle + "-" + (left ? "left" : "right") + " wheel";
    else if (!axle.empty() && centre)
      place = "over the middle of the " + axle + " axle";
    else if (!axle.empty())
      place = "over the " + axle + " axle";
    else if (left || right)
      place = std::string("over the ") + (left ? "left" : "right") + " wheels' line, " +
              (x > a    ? "ahead of the front axle"
               : x < -b ? "behind the rear axle"
                        : "between the axles");
    else
      place = x > a    ? "ahead of the front axle"
              : x < -b ? "behind the rear axle"
                       : "between the axles";
  }
  return "the sensor " + sensor + " acts as if it sat " + fore(x) + " and " + across(y) +
         (place.empty() ? "" : ": " + place) + " (the study puts it " + fore(study_x) + ", " +
         across(study_y) + ")";
}

/// The road-signal form `name` ("road.fl_only"), or null.
const RoadSignalForm* roadForm(const std::string& name) {
  for (const auto& f : roadSignalForms())
    if (name == f.name) return &f;
  return nullptr;
}

/// The freeable vehicle values `assembly` has (the solid axle's only with a solid axle).
std::vector<std::string> freeableOf(const AssemblySpec& assembly) {
  std::vector<std::string> out;
  for (const auto& f : freeableVehicleParameters())
    if (f.rfind("solid_axle.", 0) != 0 || assembly.option("suspension") == "solid_axle")
      out.push_back(f);
  return out;
}

/// The part a factor's value belongs to: "damper", "spring", "tire".
std::string factorPart(const std::string& value) {
  if (value == "suspension.damping") return "damper";
  if (value == "suspension.stiffness") return "spring";
  return "tire";
}

/// The quantity a factor scales, in words: "damping", "stiffness", "vertical stiffness".
std::string factorQuantity(const std::string& value) {
  if (value == "tire.stiffness") return "vertical stiffness";
  return value.substr(value.find('.') + 1);
}

/// A corner's name in words: "fl" -> "front-left".
std::string cornerInWords(int place) {
  static const char* const words[] = {"front-left", "front-right", "rear-left",
                                      "rear-right", "front",       "rear"};
  return words[place];
}

/// What a per-corner or per-axle factor away from 1 leaves in the data, in words.
std::string factorSignature(const CornerFactor& f, bool relative) {
  const std::string part = factorPart(f.value), q = factorQuantity(f.value);
  const std::string name = f.value + "@" + kFactorPlaces[static_cast<std::size_t>(f.place)];
  if (f.place < 4)
    return "the " + cornerInWords(f.place) + " " + part + "'s " + q +
           " differs from the other corners' (" + name +
           " is not 1): a pitch, roll or warp response the same change at all four corners cannot "
           "make";
  return relative ? "the front and rear " + part + "s' " + q +
                        " are in another ratio than the vehicle file's (" + name + " is not 1)"
                  : "both " + cornerInWords(f.place) + " " + part + "s' " + q +
                        " differs from the vehicle file's (" + name + " is not 1)";
}

/// A ratio in percent: 0.5512 -> "55 %" (two significant digits below 10 %: "4.2 %").
std::string percent(double v) {
  return formatPrintf(std::abs(v) < 0.1 ? "%.2g %%" : "%.0f %%", 100 * v);
}

/// "wheel.mass_kg" -> "wheel mass"; "chassis.roll_inertia_kgm2" -> "chassis roll inertia".
/// The freeable CG shift at a fixed wheelbase (twin/model.hpp), 0 in the vehicle file.
constexpr const char* kCgShift = "chassis.cg_x_m";

std::string valueInWords(const std::string& name) {
  std::string w = name;
  for (const char* unit : {"_kgm2", "_kg", "_m"}) {
    const std::string u = unit;
    if (w.size() > u.size() && w.compare(w.size() - u.size(), u.size(), u) == 0) {
      w.resize(w.size() - u.size());
      break;
    }
  }
  std::replace(w.begin(), w.end(), '.', ' ');
  std::replace(w.begin(), w.end(), '_', ' ');
  return w;
}

}  // namespace

std::vector<std::pair<std::string, std::vector<std::string>>> channelGroups(
    const std::vector<std::string>& channels) {
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
  std::vector<std::string> units;
  for (const auto& c : channels)
    if (std::find(units.begin(), units.end(), unitSuffix(c)) == units.end())
      units.push_back(unitSuffix(c));
  for (const auto& u : units) {
    std::vector<std::string> members;
    for (const auto& c : channels)
      if (unitSuffix(c) == u) members.push_back(c);
    std::string name;
    if (members.size() == 1) {
      name = members[0].substr(0, members[0].size() - (u.empty() ? 0 : u.size() + 1));
    } else {
      std::string prefix = members[0];
      for (const auto& m : members) {
        std::size_t k = 0;
        while (k < prefix.size() && k < m.size() && prefix[k] == m[k]) ++k;
        prefix.resize(k);
      }
      const auto cut = prefix.rfind('_');
      name = cut == std::string::npos ? "" : prefix.substr(0, cut);
      if (name.empty())
        name = u.empty() ? "channels" : u;  // nothing in common: the unit names the group
    }
    groups.push_back({name, members});
  }
  return groups;
}

bool hasCandidateForm(const std::string& name) {
  if (name.rfind(kFree, 0) == 0) return name.size() > std::string(kFree).size();
  if (name.rfind(kWiden, 0) == 0) return name.size() > std::string(kWiden).size();
  if (name.rfind(kPlace, 0) == 0) return name.size() > std::string(kPlace).size();
  if (const auto eq = name.find('='); eq != std::string::npos)
    return eq > 0 && eq + 1 < name.size();
  const auto colon = name.find(':');
  if (colon != std::string::npos) {
    const auto& kinds = sensorModelKinds();
    return std::find(kinds.begin(), kinds.end(), name.substr(0, colon)) != kinds.end() &&
           colon + 1 < name.size();
  }
  return !name.empty();
}

bool isCandidateName(const std::string& name, const EffectCatalog& catalog) {
  if (!hasCandidateForm(name)) return false;
  return name.find(':') != std::string::npos || name.find('=') != std::string::npos ||
         catalog.contains(name);
}

std::string factorPlaceInWords(const std::string& factor) {
  const auto f = parseCornerFactor(factor);
  if (!f) return factor;
  const std::string part = factorPart(f->value);
  return f->place < 4 ? "the " + cornerInWords(f->place) + " " + part
                      : "both " + cornerInWords(f->place) + " " + part + "s";
}

std::vector<std::string> cornerCandidates(const Study& study, const AssemblySpec& assembly) {
  // The factors the assembly's laws have: a model with every factor freed holds those it can
  // apply as run parameters (the hub input has no tire compliance, so no tire factor).
  AssemblySpec all = assembly;
  for (const auto& n : cornerFactorNames())
    if (std::find(all.freed.begin(), all.freed.end(), n) == all.freed.end()) all.freed.push_back(n);
  const auto names = study.makeModel(all)->runParameterNames();
  const auto calibrated = [&](const std::string& v) {
    return std::any_of(study.calibrated.begin(), study.calibrated.end(),
                       [&](const CalibratedParameter& c) { return c.name == v; });
  };
  std::vector<std::string> out;
  for (const char* value : kCornerFactorValues)
    for (int place = 0; place < 6; ++place) {
      const std::string n = cornerFactorName(value, place);
      if (std::find(names.begin(), names.end(), n) == names.end()) continue;
      if (place == 5 && calibrated(value)) continue;  // the front factor's mirror (see the header)
      out.push_back(kFree + n);
    }
  // The catalogue's effects of a part that wears at one strut, at each corner ("bump_stop@rr").
  const auto& catalog = study.effectCatalog();
  for (const auto& e : catalog.names()) {
    if (!catalog.make(e, "")->screenedAtEachCorner()) continue;
    for (const char* c : kEffectCorners) out.push_back(e + "@" + c);
  }
  return out;
}

std::vector<std::string> defaultCandidates(const Study& study, const AssemblySpec& assembly,
                                           const std::vector<std::string>& channels,
                                           bool measured_road, bool each_wheel) {
  std::vector<std::string> out = study.effectCatalog().names();
  for (const auto& f : freeableOf(assembly)) out.push_back(kFree + f);
  for (const auto& f : cornerCandidates(study, assembly)) out.push_back(f);
  for (const auto& [group, members] : channelGroups(channels))
    for (const auto& k : sensorModelKinds()) out.push_back(k + ":" + group);
  for (const auto& f : sensorPlaceCandidates(study, channels)) out.push_back(f);
  if (measured_road) {
    out.push_back(std::string(kFree) + kRoadGain);
    out.push_back(std::string(kFree) + kRoadDelay);
    // Each wheel's own motion: where the signal enters is known (each column is its wheel's).
    for (const auto& f : roadSignalForms())
      if (!each_wheel && !calibratedInStudy(study, f.name) &&
          study.parameterTable().value(f.name) == 0.0)
        out.push_back(std::string(kFree) + f.name);
    if (assembly.option("tire") != "hub") out.push_back("tire=hub");
  }
  return out;
}

std::vector<std::string> sensorPlaceCandidates(const Study& study,
                                               const std::vector<std::string>& channels) {
  std::vector<std::string> out;
  for (const auto& x : study.sensors) {
    if (x.corner() >= 0 || x.relative() || x.positionMeasured()) continue;
    if (std::find(channels.begin(), channels.end(), x.channel()) == channels.end()) continue;
    const std::string p = "sensors." + x.name + ".";
    const bool fx = calibratedInStudy(study, p + "x_m"), fy = calibratedInStudy(study, p + "y_m");
    // Fore-aft and across together: where a sensor acts against the road input is one place
    // (over a corner, over an axle); one of them alone when the study calibrates the other.
    if (!fx && !fy)
      out.push_back(kPlace + x.name);
    else if (!fx)
      out.push_back(kFree + p + "x_m");
    else if (!fy)
      out.push_back(kFree + p + "y_m");
  }
  return out;
}

namespace {
/// A calibrated value's range widened to its physical limit (widen:VALUE).
CandidateSpec rangeCandidate(const std::string& name, const Study& study,
                             const std::string& where) {
  CandidateSpec c;
  c.name = name;
  const std::string value = name.substr(std::string(kWiden).size());
  const auto cp = std::find_if(study.calibrated.begin(), study.calibrated.end(),
                               [&](const CalibratedParameter& x) { return x.name == value; });
  if (cp == study.calibrated.end()) {
    std::vector<std::string> known;
    for (const auto& x : study.calibrated) known.push_back(x.name);
    throw InputError(where,
                     unknownNameRule("calibrated value (widen: takes a value the study calibrates)",
                                     value, known));
  }
  const auto table = study.parameterTable();
  const auto limit = physicalLimit(value, table);
  if (!limit)
    throw InputError(where, "'" + value + "' has no known physical limit to widen its range to");
  ParameterSpec p = table.at(value).spec;
  p.prior_lower = std::min(cp->lower, limit->lower);
  p.prior_upper = std::max(cp->upper, limit->upper);
  if (p.prior_lower >= cp->lower && p.prior_upper <= cp->upper)
    throw InputError(where, "'" + value + "' is calibrated over [" + num("%.4g", cp->lower) + ", " +
                                num("%.4g", cp->upper) +
                                "], which holds its physical limits already: nothing to widen");
  p.unit = cp->unit.empty() ? p.unit : cp->unit;
  c.kind = "range";
  c.parameters = {p};
  c.calibrated_names = {value};
  c.study_lower = cp->lower;
  c.study_upper = cp->upper;
  c.signature = value + " lies outside the study's range [" + num("%.4g", cp->lower) + ", " +
                num("%.4g", cp->upper) + "] " + p.unit + " (searched within its physical limits [" +
                num("%.4g", p.prior_lower) + ", " + num("%.4g", p.prior_upper) +
                "]: " + limit->basis + ")";
  return c;
}

/// Another option of a subsystem (SUBSYSTEM=OPTION).
CandidateSpec optionCandidate(const std::string& name, const AssemblySpec& assembly,
                              const std::string& where) {
  CandidateSpec c;
  c.name = name;
  const auto eq = name.find('=');
  const std::string sub = name.substr(0, eq), opt = name.substr(eq + 1);
  const auto& known = knownSubsystems();
  std::vector<std::string> subs;
  subs.reserve(known.size());
  for (const auto& [k, _] : known) subs.push_back(k);
  if (!known.count(sub)) throw InputError(where, unknownNameRule("subsystem", sub, subs));
  const auto& opts = known.at(sub);
  if (std::find(opts.begin(), opts.end(), opt) == opts.end())
    throw InputError(where, unknownNameRule(sub + " option", opt, opts));
  if (assembly.option(sub).empty())
    throw InputError(where, "assembly " + assembly.id + " has no " + sub + " subsystem to swap");
  if (assembly.option(sub) == opt)
    throw InputError(
        where, "assembly " + assembly.id + " has the " + sub + " option '" + opt + "' already");
  c.kind = "option";
  c.options = {{sub, opt}};
  c.signature = sub == "tire" && opt == "hub"
                    ? "the road signal is the hub's own motion, not the road under a tire: no tire "
                      "filtering between the signal and the "
                      "wheel (no wheel-hop resonance driven through a tire compliance)"
                    : "the " + sub + " behaves as the '" + opt + "' option, not '" +
                          assembly.option(sub) + "'";
  return c;
}

/// A fixed value freed (free:VALUE): a vehicle value, a law's constant or an input-side value.
CandidateSpec freeCandidate(const std::string& name, const Study& study,
                            const AssemblySpec& assembly, const std::string& where) {
  CandidateSpec c;
  c.name = name;
  const std::string value = name.substr(std::string(kFree).size());
  for (const auto& cp : study.calibrated)
    if (cp.name == value)
      throw InputError(where,
                       "'" + value + "' is calibrated already: only a fixed value can be freed");
  auto freeable = freeableOf(assembly);
  const auto corner_factor = parseCornerFactor(value);
  const bool factor =
      corner_factor.has_value();  // freed through AssemblySpec::freed, without a rebuild
  if (!factor && std::find(freeable.begin(), freeable.end(), value) == freeable.end()) {
    if (const std::string rule = cornerFactorRule(value); !rule.empty())
      throw InputError(where, rule);
    // A fixed value of the assembly's laws (the tire radius, a strut-law constant): a run
    // parameter already, so it is calibrated without a rebuild. Not a calibrated one.
    const auto model = study.makeModel(assembly, {});
    for (const auto& n : model->runParameterNames()) {
      bool calibrated = false;
      for (const auto& cp : study.calibrated) calibrated = calibrated || cp.name == n;
      if (!calibrated && n.find("preload") == std::string::npos) freeable.push_back(n);
    }
    if (std::find(freeable.begin(), freeable.end(), value) == freeable.end()) {
      throw InputError(
          where, unknownNameRule("fixed value that can be freed in assembly " + assembly.id, value,
                                 freeable));
    }
    c.law_value = true;
  }
  const auto table = study.parameterTable();
  ParameterSpec p = table.at(value).spec;
  const double v = table.value(value);
  p.default_value = v;
  // The search range: ±50 % about the file's value (a sensor's position ±0.5 m, its offset ±20
  // noise sd; the CG's shift ±10 % of the wheelbase), inside the value's valid set.
  std::string range = "±50 %", why_lower = "its smallest valid value",
              why_upper = "its largest valid value";
  double lo = 0.5 * v, hi = 1.5 * v, valid_lo = p.min_value, valid_hi = p.max_value;
  if (factor) {  // a per-corner or per-axle factor: its documented prior range
    range = "[" + num("%g", kFactorPriorLower) + ", " + num("%g", kFactorPriorUpper) + "]";
    lo = kFactorPriorLower;
    hi = kFactorPriorUpper;
  } else if (value ==
             kRoadDelay) {  // the road signal's delay: ±0.1 s about its value (0 is a fine value)
    range = "±0.1 s";
    lo = v - 0.1;
    hi = v + 0.1;
  } else if (roadForm(value)) {  // a road-signal form's share: past both ends of [0, 1], so that 0
                                 // and 1 are inside
    range = "[-0.5, 1.5]";
    lo = -0.5;
    hi = 1.5;
  } else if (value.rfind("sensors.", 0) ==
             0) {  // where a sensor sits, or its offset: absolute ranges (0 is a fine value)
    const std::string sensor = value.substr(8, value.rfind('.') - 8);
    if (value.size() > 7 && value.compare(value.size() - 7, 7, ".offset") == 0) {
      double sd = 0.0;
      for (const auto& x : study.sensors)
        if (x.name == sensor) sd = x.noise_sd;
      if (!(sd > 0))
        throw InputError(where, "'" + value + "': its search range is ±20 noise sd about " +
                                    num("%.4g", v) + ", and sensor '" + sensor +
                                    "' has no noise_sd (give it one in [sensors." + sensor + "])");
      range = "±20 noise sd";
      lo = v - 20 * sd;
      hi = v + 20 * sd;
    } else {
      const SensorSpec* sp = nullptr;
      for (const auto& x : study.sensors)
        if (x.name == sensor) sp = &x;
      const auto limit = physicalLimit(value, table);
      if (sp && !sp->positionMeasured() && limit) {
        // Not declared measured: anywhere within the car's body and beyond, to the physical limit
        // (a sensor that acts as if it sat ahead of the front axle is a finding, not a bound).
        range = "its physical limit";
        lo = limit->lower;
        hi = limit->upper;
      } else {
        // Measured: five standard deviations about the study's value, at least 5 cm.
        const double half = std::max(0.05, 5 * (sp ? sp->position_sd_m : 0.1));
        range = "±" + num("%g", half) + " m";
        lo = v - half;
        hi = v + half;
      }
    }
  } else if (value == kCgShift) {  // a shift from the file's CG (0): ±10 % of the wheelbase, the CG
                                   // between the axles
    const double a = table.value("geometry.cg_to_front_axle_m"),
                 b = table.value("geometry.cg_to_rear_axle_m");
    range = "±10 % of the wheelbase";
    lo = v - 0.1 * (a + b);
    hi = v + 0.1 * (a + b);
    valid_lo = std::max(valid_lo, -0.9 * b);
    valid_hi = std::min(valid_hi, 0.9 * a);
    why_lower = "90 % of the way to the rear axle";
    why_upper = "90 % of the way to the front axle";
  }
  p.prior_lower = std::max(lo, valid_lo);
  p.prior_upper = std::min(hi, valid_hi);
  if (!(p.prior_lower < p.prior_upper))
    throw InputError(where, "'" + value + "' is " + num("%.4g", v) + " " + p.unit +
                                ": no range of " + range + " about it to search");
  const bool input = value == kRoadGain || value == kRoadDelay || roadForm(value);
  const bool place = isSensorPosition(value);
  c.kind = input ? "input" : place ? "place" : "parameter";
  if (place)
    for (const char* g :
         {"geometry.cg_to_front_axle_m", "geometry.cg_to_rear_axle_m", "geometry.track_m"})
      c.geometry.push_back(table.contains(g) ? table.value(g) : 0.0);
  c.relative = factor && std::any_of(study.calibrated.begin(), study.calibrated.end(),
                                     [&](const CalibratedParameter& cp) {
                                       return cp.name == corner_factor->value;
                                     });
  c.parameters = {p};
  c.calibrated_names = {value};
  if (const RoadSignalForm* f = roadForm(value))
    c.signature = std::string("the road signal is ") + f->whose +
                  " road, not the road under both axles (the rear a wheelbase later)";
  else if (place)
    c.signature = "the sensor " + value.substr(8, value.rfind('.') - 8) +
                  " acts where the study does not put it (" + value + " = " + num("%.4g", v) +
                  " m): it sees another mix of heave, pitch and roll";
  else
    c.signature =
        input    ? (value == kRoadGain
                        ? "the road signal is scaled (its gain is not 1)"
                        : "the road signal is shifted in time against the measured channels (a delay)")
        : factor ? factorSignature(*corner_factor, c.relative)
                 : "a fixed vehicle value (" + value + " = " + num("%.4g", v) + " " + p.unit +
                       ") is wrong";
  if (p.prior_lower > lo)
    c.range_note = "searched from " + num("%.4g", p.prior_lower) + ", not " + num("%.4g", lo) +
                   " (" + why_lower + ")";
  if (p.prior_upper < hi)
    c.range_note += (c.range_note.empty() ? "searched up to " : "; up to ") +
                    num("%.4g", p.prior_upper) + ", not " + num("%.4g", hi) + " (" + why_upper +
                    ")";
  if (!c.range_note.empty()) {
    c.range_note = "its " + range + " range was clipped to stay valid: " + c.range_note;
    c.signature += "; " + c.range_note;
  }
  return c;
}

/// Where a chassis sensor acts, fore-aft and across together (place:NAME): its x and y freed as one
/// candidate, each over the range freeCandidate gives it.
CandidateSpec placeCandidate(const std::string& name, const Study& study,
                             const AssemblySpec& assembly, const std::string& where) {
  const std::string sensor = name.substr(std::string(kPlace).size());
  std::vector<std::string> known;
  const SensorSpec* sp = nullptr;
  for (const auto& x : study.sensors)
    if (x.corner() < 0 && !x.relative()) {
      known.push_back(x.name);
      if (x.name == sensor) sp = &x;
    }
  if (!sp)
    throw InputError(
        where,
        unknownNameRule("chassis sensor (place: takes a [sensors] table's name on the chassis)",
                        sensor, known));
  const CandidateSpec x = freeCandidate("free:sensors." + sensor + ".x_m", study, assembly, where);
  const CandidateSpec y = freeCandidate("free:sensors." + sensor + ".y_m", study, assembly, where);
  CandidateSpec c = x;
  c.name = name;
  c.parameters.push_back(y.parameters[0]);
  c.calibrated_names.push_back(y.calibrated_names[0]);
  c.signature = "the sensor " + sensor + " acts where the study does not put it (at " +
                num("%.3g", x.parameters[0].default_value) + ", " +
                num("%.3g", y.parameters[0].default_value) +
                " m from the CG): it sees another mix of heave, pitch and roll";
  return c;
}

/// A sensor model on a channel group (KIND:GROUP).
CandidateSpec sensorCandidate(const std::string& name, const std::vector<std::string>& channels,
                              const std::string& where) {
  CandidateSpec c;
  c.name = name;
  const auto colon = name.find(':');
  c.sensor_kind = name.substr(0, colon);
  const std::string group = name.substr(colon + 1);
  ParameterSpec p = sensorModelParameter(c.sensor_kind, where);
  std::vector<std::string> known;
  for (const auto& [g, members] : channelGroups(channels)) {
    known.push_back(g);
    if (g == group) c.channels = members;
  }
  // A single fitted channel may also be named by itself.
  if (c.channels.empty() && std::find(channels.begin(), channels.end(), group) != channels.end())
    c.channels = {group};
  if (c.channels.empty())
    throw InputError(where, unknownNameRule("channel group of the fitted data", group, known));
  c.kind = "sensor";
  c.parameters = {p};
  c.calibrated_names = {name + "." + p.name};
  c.signature = "the " + group + " channels were distorted by the logger (" + c.sensor_kind + ")";
  return c;
}
}  // namespace

CandidateSpec candidateSpec(const std::string& name, const Study& study,
                            const AssemblySpec& assembly, const std::vector<std::string>& channels,
                            const std::string& where) {
  CandidateSpec c;
  c.name = name;
  if (name.rfind(kWiden, 0) == 0) return rangeCandidate(name, study, where);
  if (name.find('=') != std::string::npos) return optionCandidate(name, assembly, where);
  if (name.rfind(kFree, 0) == 0) return freeCandidate(name, study, assembly, where);
  const auto colon = name.find(':');
  if (name.rfind(kPlace, 0) == 0) return placeCandidate(name, study, assembly, where);
  if (colon != std::string::npos) return sensorCandidate(name, channels, where);
  const auto effect =
      study.effectCatalog().make(name, where);  // InputError naming the known effects
  c.kind = "effect";
  for (const auto& p : effect->parameters())
    if (!p.shape) {
      c.parameters.push_back(p);
      c.calibrated_names.push_back(name + "." + p.name);
    }
  c.signature = effect->signature();
  if (const EffectPlace at = splitEffectPlace(name, where); at.corner >= 0)
    c.signature = "at the " + cornerInWords(at.corner) + " corner only: " + c.signature;
  c.residual_signature = effect->residualSignature();
  c.engagement_threshold = effect->engagementThreshold();
  return c;
}

void CandidateSpec::install(calib::CalibrationSetup& setup) const {
  if (kind == "option") {
    for (const auto& o : options) setup.options.push_back(o);
    return;
  }
  if (kind == "range") {
    setup.bounds[calibrated_names[0]] = {parameters[0].prior_lower, parameters[0].prior_upper};
    return;
  }
  if (kind == "effect") {
    EffectSetting es;
    es.name = name;
    setup.extra_effects.push_back(es);
  } else if (kind == "parameter" || kind == "input" || kind == "place") {
    if (!law_value) setup.freed.push_back(calibrated_names[0]);
  } else {
    setup.sensor_models.push_back({name, sensor_kind, channels});
  }
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    CalibratedParameter cp;
    cp.name = calibrated_names[k];
    cp.unit = parameters[k].unit;
    cp.lower = parameters[k].prior_lower;
    cp.upper = parameters[k].prior_upper;
    setup.extra_calibrated.push_back(cp);
  }
}

std::string CandidateSpec::finding(const std::vector<double>& values, double lower,
                                   double upper) const {
  if (kind == "option")
    return options.size() == 1 && options[0] == std::pair<std::string, std::string>{"tire", "hub"}
               ? "the road signal behaves as the hub's motion, not the road under a tire"
               : "the structure is that of " + name;
  if (values.size() != parameters.size() || values.empty()) return "";
  const double v = values[0];
  if (kind == "range") {
    const bool above = v > study_upper;
    if (!above && v >= study_lower) return "";
    const std::string& value = calibrated_names[0];
    std::string far = above ? "above" : "below";
    if (value == "chassis.mass_kg")
      far = above ? "heavier than" : "lighter than";
    else if (value.find("stiffness") != std::string::npos)
      far = above ? "stiffer than" : "softer than";
    else if (value.find("damping") != std::string::npos)
      far = above ? "more damped than" : "less damped than";
    return "the " + valueInWords(value) + " is about " + plain(v) + " " + parameters[0].unit +
           ", " + far + " the study's range allows (" + plain(above ? study_upper : study_lower) +
           " " + parameters[0].unit + ")";
  }
  if (kind == "input") {
    if (calibrated_names[0] == kRoadGain)
      return "the road signal looks scaled by " + num("%.3g", v) + " (its gain)";
    if (const RoadSignalForm* f = roadForm(calibrated_names[0]))
      return roadFormFinding(*f, v, lower, upper);
    return "the road signal looks logged " + num("%.3g", 1e3 * std::abs(v)) + " ms " +
           (v >= 0 ? "late" : "early") + " relative to the measured channels";
  }
  if (kind == "place" && values.size() == 2)
    return sensorCornerFinding(name.substr(std::string(kPlace).size()), values[0], values[1],
                               parameters[0].default_value, parameters[1].default_value,
                               geometry[0], geometry[1], geometry[2]);
  if (kind == "place")
    return sensorPlaceFinding(calibrated_names[0], v, parameters[0].default_value, geometry[0],
                              geometry[1], geometry[2]);
  if (kind == "parameter" && calibrated_names[0] == kCgShift)
    return "the sprung CG lies about " + num("%.3g", std::abs(v - parameters[0].default_value)) +
           " m " + (v >= parameters[0].default_value ? "ahead of" : "behind") +
           " the vehicle file's position (the same wheelbase)";
  if (const auto f = parseCornerFactor(calibrated_names[0]); kind == "parameter" && f) {
    // "the rear-right damper gives about 55 % of the damping of the other three (95 %: 51 % to 59
    // %)"
    const std::string q = factorQuantity(f->value), part = factorPart(f->value);
    const std::string interval = std::isfinite(lower) && std::isfinite(upper)
                                     ? " (95 %: " + percent(lower) + " to " + percent(upper) + ")"
                                     : "";
    const bool tire = part == "tire";
    if (f->place < 4)
      return factorPlaceInWords(calibrated_names[0]) + (tire ? " has about " : " gives about ") +
             percent(v) + " of the " + q + " of " +
             (relative ? "the other three" : "its nominal " + part + " (the vehicle file's)") +
             interval;
    if (relative) {
      // The ratio between the axles (cornerCandidates), said of the axle with the lower value: a
      // worn part loses damping or stiffness, so "the rear dampers give 55 % of the front ones'"
      // reads as the finding it most likely is, where "the front give 182 % of the rear" would not.
      const bool flip = v > 1;
      const int low = flip ? 9 - f->place : f->place;  // front 4 <-> rear 5
      const std::string axle = cornerInWords(low), other = low == 4 ? "rear" : "front";
      const std::string ratio_interval = interval.empty()
                                             ? ""
                                             : " (95 %: " + percent(flip ? 1 / upper : lower) +
                                                   " to " + percent(flip ? 1 / lower : upper) + ")";
      return "the " + axle + " " + part + "s " + (tire ? "have" : "give") + " about " +
             percent(flip ? 1 / v : v) + " of the " + q + " of the " + other + " ones" +
             ratio_interval + " (which axle changed, these data cannot tell while the whole " + q +
             " is calibrated)";
    }
    return factorPlaceInWords(calibrated_names[0]) + (tire ? " have about " : " give about ") +
           percent(v) + " of their nominal " + q + interval;
  }
  if (kind == "parameter")
    return "the " + valueInWords(calibrated_names[0]) + " is about " + plain(v) + " " +
           parameters[0].unit + ", not " + num("%.4g", parameters[0].default_value) + " " +
           parameters[0].unit;
  if (kind != "sensor") return "";
  const std::string group = name.substr(name.find(':') + 1);
  if (sensor_kind == "gain") return "the " + group + " channels look scaled by " + num("%.3g", v);
  if (sensor_kind == "delay")
    return "the " + group + " channels look " + (v >= 0 ? "delayed" : "early") + " by " +
           num("%.3g", 1e3 * std::abs(v)) + " ms";
  return "the " + group + " channels look filtered at about " +
         num("%.3g", v > 0 ? 1.0 / (2.0 * kPi * v) : 0.0) + " Hz (" +
         (sensor_kind == "lowpass" ? "first" : "second") + "-order low-pass)";
}

}  // namespace dtwin::diag
