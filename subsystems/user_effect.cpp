#include "subsystems/user_effect.hpp"

#include <muParser.h>

#include <array>
#include <atomic>
#include <cctype>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/units.hpp"
#include "subsystems/random.hpp"

namespace dtwin {

namespace {

/// One thread's compiled expression: a muparser Parser bound to its own variables. A Parser binds
/// variables by address and is not to be shared between threads, so each thread compiles its own
/// copy on first use (UserEffect::local).
struct Compiled {
  mu::Parser parser;
  std::vector<double> vars;  ///< the state variables, then the parameters
  std::vector<std::size_t>
      used;  ///< the indices into vars the expression reads (the only ones set per call)
};

/// Compiles `expr` with `names` bound to `c.vars`; rethrows muparser's error as one line.
void compile(Compiled& c, const std::string& expr, const std::vector<std::string>& names,
             const std::string& where) {
  c.vars.assign(names.size(), 0.0);
  try {
    for (std::size_t i = 0; i < names.size(); ++i) c.parser.DefineVar(names[i], &c.vars[i]);
    c.parser.SetExpr(expr);
    (void)c.parser.Eval();  // parses now: an unknown symbol or a syntax error is found here
    const auto used = c.parser.GetUsedVar();
    for (std::size_t i = 0; i < names.size(); ++i)
      if (used.count(names[i])) c.used.push_back(i);
  } catch (const mu::Parser::exception_type& e) {
    std::string msg = e.GetMsg();
    for (char& ch : msg)
      if (ch == '\n' || ch == '\r') ch = ' ';
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw InputError(where + ": force", "'" + expr + "': " + msg + " (symbols: " + known + ")");
  }
}

enum class Element { Strut, Tire, AxleRoll, Chassis };

/// Whether `expr` names the identifier `name` (a whole word, not part of a longer name).
bool usesName(const std::string& expr, const std::string& name) {
  const auto word = [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
  };
  for (std::size_t at = expr.find(name); at != std::string::npos; at = expr.find(name, at + 1))
    if ((at == 0 || !word(expr[at - 1])) &&
        (at + name.size() == expr.size() || !word(expr[at + name.size()])))
      return true;
  return false;
}

const std::vector<UserEffectVariable> kStrutVars = {
    {"q", "m", "strut deflection, compression positive, 0 at design ride height", -0.1, 0.1},
    {"v", "m/s", "its rate dq/dt", -1.0, 1.0},
    {"dq", "m",
     "q minus the other main strut's q on the same axle (left minus right on the left strut)",
     -0.05, 0.05},
    {"dv", "m/s", "v minus the other strut's v on the same axle", -0.5, 0.5},
    {"k", "N/m", "the main spring's stiffness (a calibrated parameter)", 3e4, 3e4},
    {"c", "N*s/m", "the main damper's damping (a calibrated parameter)", 2.5e3, 2.5e3},
    {"t", "s", "time", 0.0, 20.0},
    {"u", "m/s", "vehicle forward speed", 0.0, 30.0},
    {"front", "1", "1 on the front axle, 0 on the rear", 0.0, 1.0},
    {"vb", "m/s",
     "the body's absolute vertical velocity at the strut's top (up positive; a skyhook's sensor)",
     -0.5, 0.5},
    {"vw", "m/s",
     "the wheel centre's absolute vertical velocity (up positive; a groundhook's sensor)", -1.0,
     1.0},
    {"vr", "m/s", "the road signal's vertical velocity under the wheel (a feed-forward's input)",
     -1.0, 1.0}};
/// The strut variables that need the absolute motion at the corner (Effect::needsMotion).
const char* const kMotionVars[] = {"vb", "vw", "vr"};
const std::vector<UserEffectVariable> kTireVars = {
    {"qt", "m", "tire deflection, positive in contact", -0.01, 0.05},
    {"vt", "m/s", "the rate the tire's damping acts on (minus the hub's vertical velocity)", -0.5,
     0.5},
    {"fz", "N", "the tire law's normal force", 0.0, 8000.0},
    {"zr", "m", "road height under the wheel", -0.05, 0.05},
    {"t", "s", "time", 0.0, 20.0},
    {"u", "m/s", "vehicle forward speed", 0.0, 30.0},
    {"front", "1", "1 on the front axle, 0 on the rear", 0.0, 1.0}};
const std::vector<UserEffectVariable> kAxleVars = {
    {"dq", "m", "left minus right main-strut deflection", -0.05, 0.05},
    {"dv", "m/s", "its rate", -0.5, 0.5},
    {"t", "s", "time", 0.0, 20.0},
    {"u", "m/s", "vehicle forward speed", 0.0, 30.0},
    {"front", "1", "1 on the front axle, 0 on the rear", 0.0, 1.0}};
const std::vector<UserEffectVariable> kChassisVars = {
    {"z", "m", "mass-centre height above its start", -0.05, 0.05},
    {"w", "m/s", "its rate", -0.5, 0.5},
    {"pitch", "rad", "pitch angle from its start", -0.05, 0.05},
    {"roll", "rad", "roll angle from its start", -0.05, 0.05},
    {"t", "s", "time", 0.0, 20.0},
    {"u", "m/s", "vehicle forward speed", 0.0, 30.0}};

bool elementOf(const std::string& name, Element& e) {
  if (name == "strut")
    e = Element::Strut;
  else if (name == "tire")
    e = Element::Tire;
  else if (name == "axle_roll")
    e = Element::AxleRoll;
  else if (name == "chassis")
    e = Element::Chassis;
  else
    return false;
  return true;
}

class UserEffect final : public Effect {
 public:
  /// `id` (newId()) names this object in each thread's list of recent compiled copies.
  UserEffect(UserEffectSpec spec, std::uint64_t id) : spec_(std::move(spec)), id_(id) {
    (void)elementOf(spec_.element, element_);
    for (const auto& v : userEffectVariables(spec_.element)) names_.push_back(v.name);
    nstate_ = names_.size();
    if (element_ == Element::Strut)
      for (const char* m : kMotionVars) motion_ = motion_ || usesName(spec_.force, m);
    for (const auto& p : spec_.parameters) {
      names_.push_back(p.name);
      ParameterSpec s = effectParameter(p.name, p.unit, "user-defined (" + spec_.force + ")",
                                        p.value, p.lower, p.upper, p.lower, p.upper);
      s.shape = p.shape;
      specs_.push_back(s);
    }
  }
  std::string name() const override { return spec_.name; }
  std::string description() const override {
    return "user-defined " + spec_.element + " force " + spec_.force;
  }
  std::string signature() const override {
    return "a " + spec_.element + " force " + spec_.force + " (user-defined)";
  }
  EffectKind kind() const override {
    switch (element_) {
      case Element::Tire:
        return EffectKind::TireLoad;
      case Element::AxleRoll:
        return EffectKind::AxleCoupling;
      case Element::Chassis:
        return EffectKind::ChassisForce;
      case Element::Strut:
        break;
    }
    return EffectKind::Strut;
  }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override {
    const double x[] = {s.deflection_m,
                        s.rate_mps,
                        s.deflection_m - s.other_deflection_m,
                        s.rate_mps - s.other_rate_mps,
                        s.base_stiffness,
                        s.base_damping,
                        s.time_s,
                        s.speed_mps,
                        s.front ? 1.0 : 0.0,
                        s.body_velocity_mps,
                        s.wheel_velocity_mps,
                        s.road_velocity_mps};
    return eval(x, p);
  }
  bool needsMotion() const override { return motion_; }
  double calcTireLoad(const TireState& s, ParamValues p) const override {
    const double x[] = {s.deflection_m, s.deflection_rate_mps, s.normal_force_N,   s.road_height_m,
                        s.time_s,       s.forward_speed_mps,   s.front ? 1.0 : 0.0};
    return eval(x, p);
  }
  double calcAxleForce(const AxleState& a, ParamValues p) const override {
    const double x[] = {a.q_left - a.q_right, a.v_left - a.v_right, a.time_s, a.speed_mps,
                        a.front ? 1.0 : 0.0};
    return eval(x, p);
  }
  double calcAxleCouplingForce(double q_left, double q_right, bool front,
                               ParamValues p) const override {
    AxleState a;
    a.q_left = q_left;
    a.q_right = q_right;
    a.front = front;
    return calcAxleForce(a, p);
  }
  double calcChassisForce(const ChassisState& s, ParamValues p) const override {
    const double x[] = {s.heave_m,  s.heave_rate_mps, s.pitch_rad,
                        s.roll_rad, s.time_s,         s.speed_mps};
    return eval(x, p);
  }
  /// The force at state variables `x` (userEffectVariables order) and parameters `p`.
  double eval(const double* x, ParamValues p) const {
    Compiled& c = local();
    for (std::size_t i : c.used) c.vars[i] = i < nstate_ ? x[i] : p[i - nstate_];
    return c.parser.Eval();
  }
  /// Compiles once on this thread (checks the expression; throws InputError).
  void check() const { (void)local(); }

 private:
  Compiled& local() const {
    // The copies are this object's, one per thread that evaluates it, made on first use and freed
    // with the object. A thread remembers its last few (object id, copy) pairs, so the hot path is
    // a short scan and no lock; ids are unique for the process's life, so a remembered pair of an
    // object since destroyed never matches a live one.
    struct Recent {
      std::uint64_t id = 0;
      Compiled* copy = nullptr;
    };
    thread_local std::array<Recent, 8> recent{};
    thread_local std::size_t next = 0, last = 0;
    if (recent[last].id == id_) return *recent[last].copy;  // a run evaluates one effect many times
    for (std::size_t i = 0; i < recent.size(); ++i)
      if (recent[i].id == id_) {
        last = i;
        return *recent[i].copy;
      }
    Compiled* c = nullptr;
    {
      std::lock_guard<std::mutex> lock(copies_mutex_);
      auto& slot = copies_[std::this_thread::get_id()];
      if (!slot) {
        auto fresh = std::make_unique<Compiled>();
        compile(*fresh, spec_.force, names_, spec_.where);
        slot = std::move(fresh);
      }
      c = slot.get();
    }
    last = next++ % recent.size();
    recent[last] = {id_, c};
    return *c;
  }
  UserEffectSpec spec_;
  std::uint64_t id_ = 0;
  mutable std::mutex copies_mutex_;
  mutable std::unordered_map<std::thread::id, std::unique_ptr<Compiled>> copies_;
  Element element_ = Element::Strut;
  bool motion_ = false;             ///< the expression reads vb, vw or vr
  std::vector<std::string> names_;  ///< the state variables, then the parameters
  std::size_t nstate_ = 0;
  std::vector<ParameterSpec> specs_;
};

std::uint64_t newId() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

bool isIdentifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char ch : s)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_')) return false;
  return true;
}

/// "q = -0.08 m, v = -1 m/s": the state's variables that are not 0, k and c left out.
std::string describeState(const std::vector<UserEffectVariable>& vars,
                          const std::vector<double>& x) {
  std::string out;
  for (std::size_t i = 0; i < vars.size(); ++i) {
    if (x[i] == 0.0 || vars[i].name == "k" || vars[i].name == "c") continue;
    out += (out.empty() ? "" : ", ") + vars[i].name + " = " + formatNumber(x[i]) +
           (vars[i].unit == "1" ? "" : " " + vars[i].unit);
  }
  return out.empty() ? "every variable 0" : out;
}

/// The states the checks evaluate at: for a strut a grid of q and v (the rest 0, k and c at their
/// values), then states drawn in every variable's range (fixed seed: the same checks every run).
std::vector<std::vector<double>> checkStates(const std::string& element) {
  const auto& vars = userEffectVariables(element);
  std::vector<std::vector<double>> out;
  std::vector<double> base(vars.size(), 0.0);
  for (std::size_t i = 0; i < vars.size(); ++i)
    if (vars[i].lo == vars[i].hi) base[i] = vars[i].lo;
  if (element == "strut") {
    for (double q : {-0.08, -0.02, 0.0, 0.02, 0.08})
      for (double v : {-1.0, -0.1, 0.0, 0.1, 1.0}) {
        auto x = base;
        x[0] = q;
        x[1] = v;
        out.push_back(x);
      }
  } else {
    out.push_back(base);
  }
  RandomStream rng(0x75e4, 16);
  for (int k = 0; k < 48; ++k) {
    auto x = base;
    for (std::size_t i = 0; i < vars.size(); ++i) {
      x[i] = vars[i].lo + (vars[i].hi - vars[i].lo) * rng.uniform();
      if (vars[i].name == "front") x[i] = std::round(x[i]);
    }
    out.push_back(x);
  }
  return out;
}

/// The scaling test of dimensional homogeneity (header comment): throws InputError naming the
/// units the expression gives when they are not N, or saying it mixes units.
void checkUnits(const UserEffect& e, const UserEffectSpec& spec,
                const std::vector<Dimension>& dims) {
  const auto& vars = userEffectVariables(spec.element);
  const std::size_t nv = vars.size(), np = spec.parameters.size();
  RandomStream rng(0x0417, 16);
  std::vector<double> x(nv), p(np), xs(nv), ps(np);
  auto scaled = [&](double fm, double fl, double ft) {
    for (std::size_t i = 0; i < nv; ++i) xs[i] = x[i] * scaleFactor(dims[i], fm, fl, ft);
    for (std::size_t i = 0; i < np; ++i) ps[i] = p[i] * scaleFactor(dims[nv + i], fm, fl, ft);
    return e.eval(xs.data(), ParamValues(ps.data(), np));
  };
  const double scalings[4][3] = {{2, 1, 1}, {1, 2, 1}, {1, 1, 2}, {1.7, 2.3, 0.6}};
  for (int k = 0; k < 64; ++k) {
    for (std::size_t i = 0; i < nv; ++i) {
      x[i] = vars[i].lo + (vars[i].hi - vars[i].lo) * rng.uniform();
      if (vars[i].name == "front") x[i] = std::round(x[i]);
    }
    for (std::size_t i = 0; i < np; ++i)
      p[i] = spec.parameters[i].lower +
             (spec.parameters[i].upper - spec.parameters[i].lower) * rng.uniform();
    const double f0 = e.eval(x.data(), ParamValues(p.data(), np));
    if (!std::isfinite(f0) || f0 == 0.0) continue;
    double f[4];
    bool mismatch = false;
    for (int j = 0; j < 4; ++j) {
      f[j] = scaled(scalings[j][0], scalings[j][1], scalings[j][2]);
      const double expected =
          f0 * scaleFactor(Dimension::force(), scalings[j][0], scalings[j][1], scalings[j][2]);
      if (std::isfinite(f[j]) &&
          std::abs(f[j] - expected) > 1e-6 * std::max(std::abs(f[j]), std::abs(expected)))
        mismatch = true;
    }
    if (!mismatch) continue;
    // The units the expression gives at this point, if it scales as one unit at all.
    Dimension d;
    bool one_unit = true;
    double* exps[3] = {&d.mass, &d.length, &d.time};
    for (int j = 0; j < 3; ++j) {
      const double r = f[j] / f0;
      if (!(r > 0) || !std::isfinite(r))
        one_unit = false;
      else
        *exps[j] = std::round(std::log2(r) * 1e6) / 1e6;
    }
    if (one_unit) {
      const double expected = f0 * scaleFactor(d, 1.7, 2.3, 0.6);
      one_unit = std::isfinite(f[3]) &&
                 std::abs(f[3] - expected) <= 1e-6 * std::max(std::abs(f[3]), std::abs(expected));
    }
    const std::string given =
        "with the variables' units (docs/extending.md) and the parameters' own";
    if (one_unit)
      throw InputError(spec.where + ": force",
                       "'" + spec.force + "' gives " + formatUnit(d) + ", not N, " + given +
                           " (a bare number counts as dimensionless: make a dimensional constant a "
                           "parameter with its unit)");
    throw InputError(
        spec.where + ": force",
        "'" + spec.force + "' mixes units " + given +
            " (a bare number counts as dimensionless: make a dimensional constant a parameter with "
            "its unit; and a power "
            "whose exponent is a parameter needs a dimensionless base, e.g. F0 * (x / x0)^n)");
  }
}

}  // namespace

std::vector<std::string> userEffectElements() { return {"strut", "tire", "axle_roll", "chassis"}; }

const std::vector<UserEffectVariable>& userEffectVariables(const std::string& element) {
  static const std::vector<UserEffectVariable> none;
  Element e;
  if (!elementOf(element, e)) return none;
  switch (e) {
    case Element::Strut:
      return kStrutVars;
    case Element::Tire:
      return kTireVars;
    case Element::AxleRoll:
      return kAxleVars;
    case Element::Chassis:
      return kChassisVars;
  }
  return none;
}

std::unique_ptr<Effect> makeUserEffect(const UserEffectSpec& spec) {
  const std::string& w = spec.where;
  Element element;
  if (!elementOf(spec.element, element))
    throw InputError(w + ": element", "unknown element '" + spec.element +
                                          "' (known: strut, tire, axle_roll, chassis)");
  const auto& vars = userEffectVariables(spec.element);
  std::string state_list;
  for (const auto& v : vars) state_list += (state_list.empty() ? "" : ", ") + v.name;
  if (spec.force.empty())
    throw InputError(w + ": force",
                     "is required (an expression in " + state_list + " and the parameters)");
  std::vector<std::string> seen;
  std::vector<Dimension> dims;
  for (const auto& v : vars) {
    seen.push_back(v.name);
    std::string rule;
    dims.push_back(*parseUnit(v.unit, rule));
  }
  for (const auto& p : spec.parameters) {
    const std::string pw = w + ": parameters." + p.name;
    if (!isIdentifier(p.name))
      throw InputError(
          pw, "a parameter's name must be letters, digits and '_', starting with a letter");
    for (const auto& s : seen)
      if (s == p.name)
        throw InputError(pw, "the name is taken (state variables of a " + spec.element +
                                 " element: " + state_list + "; or another parameter)");
    seen.push_back(p.name);
    if (p.unit.empty()) throw InputError(pw + ".unit", "is required (\"1\" for none)");
    std::string rule;
    const auto d = parseUnit(p.unit, rule);
    if (!d) throw InputError(pw + ".unit", rule);
    dims.push_back(*d);
    if (!std::isfinite(p.lower) || !std::isfinite(p.upper) || !(p.lower < p.upper))
      throw InputError(pw, "needs a prior range with finite lower < upper, got [" +
                               formatNumber(p.lower) + ", " + formatNumber(p.upper) + "]");
    if (!std::isfinite(p.value) || p.value < p.lower || p.value > p.upper)
      throw InputError(pw + ".value", "must lie in [lower, upper] = [" + formatNumber(p.lower) +
                                          ", " + formatNumber(p.upper) + "], got " +
                                          formatNumber(p.value));
  }
  auto effect = std::make_unique<UserEffect>(spec, newId());
  effect->check();
  // Off at the values, and finite across the prior ranges, over the check states.
  std::vector<double> off, probe;
  for (const auto& p : spec.parameters) off.push_back(p.value);
  for (const auto& x : checkStates(spec.element)) {
    const double f = effect->eval(x.data(), off);
    if (!std::isfinite(f) || f != 0.0)
      throw InputError(w + ": force",
                       "must be 0 with every parameter at its value (the effect off); at " +
                           describeState(vars, x) + " it is " + formatNumber(f) + " N");
    // The corners of the first 10 parameters' ranges (the others at their values): at most 1024.
    for (int corner = 0; corner < (1 << std::min<std::size_t>(spec.parameters.size(), 10));
         ++corner) {
      probe = off;
      for (std::size_t i = 0; i < spec.parameters.size() && i < 10; ++i)
        probe[i] = (corner >> i) & 1 ? spec.parameters[i].upper : spec.parameters[i].lower;
      const double g = effect->eval(x.data(), probe);
      if (!std::isfinite(g))
        throw InputError(w + ": force",
                         "is not finite (" + formatNumber(g) + ") at " + describeState(vars, x) +
                             " with the parameters at the corners of their prior ranges");
    }
  }
  if (spec.check_units) checkUnits(*effect, spec, dims);
  return effect;
}

std::unique_ptr<Effect> remakeUserEffect(const UserEffectSpec& spec) {
  return std::make_unique<UserEffect>(spec, newId());
}

bool sameDefinition(const UserEffectSpec& a, const UserEffectSpec& b) {
  if (a.element != b.element || a.force != b.force || a.parameters.size() != b.parameters.size())
    return false;
  for (std::size_t i = 0; i < a.parameters.size(); ++i) {
    const auto &x = a.parameters[i], &y = b.parameters[i];
    if (x.name != y.name || x.unit != y.unit || x.value != y.value || x.lower != y.lower ||
        x.upper != y.upper || x.shape != y.shape)
      return false;
  }
  return true;
}

}  // namespace dtwin
