#include "subsystems/user_effect.hpp"

#include <muParser.h>

#include <atomic>
#include <cctype>
#include <cmath>
#include <mutex>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace dtwin {

namespace {

/// One thread's compiled expression: a muparser Parser bound to its own variables. A Parser binds
/// variables by address and is not to be shared between threads, so each thread compiles its own
/// copy on first use (UserStrutEffect::local).
struct Compiled {
  mu::Parser parser;
  std::vector<double> vars;  ///< the state variables, then the parameters
};

/// Compiles `expr` with `names` bound to `c.vars`; rethrows muparser's error as one line.
void compile(Compiled& c, const std::string& expr, const std::vector<std::string>& names, const std::string& where) {
  c.vars.assign(names.size(), 0.0);
  try {
    for (std::size_t i = 0; i < names.size(); ++i) c.parser.DefineVar(names[i], &c.vars[i]);
    c.parser.SetExpr(expr);
    (void)c.parser.Eval();  // parses now: an unknown symbol or a syntax error is found here
  } catch (const mu::Parser::exception_type& e) {
    std::string msg = e.GetMsg();
    for (char& ch : msg)
      if (ch == '\n' || ch == '\r') ch = ' ';
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw InputError(where + ": force", "'" + expr + "': " + msg + " (symbols: " + known + ")");
  }
}

class UserStrutEffect final : public Effect {
 public:
  /// `id` keys each thread's compiled copy: one per registered definition (shared by every
  /// object made from it), a fresh one otherwise (newId()).
  UserStrutEffect(UserEffectSpec spec, std::uint64_t id) : spec_(std::move(spec)), id_(id) {
    names_ = userEffectVariables("strut");
    for (const auto& p : spec_.parameters) {
      names_.push_back(p.name);
      ParameterSpec s = effectParameter(p.name, p.unit, "user-defined (" + spec_.force + ")", p.value, p.lower, p.upper, p.lower, p.upper);
      s.shape = p.shape;
      specs_.push_back(s);
    }
  }
  std::string name() const override { return spec_.name; }
  std::string description() const override { return "user-defined strut force " + spec_.force; }
  std::string signature() const override { return "a strut force " + spec_.force + " (user-defined)"; }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override {
    Compiled& c = local();
    c.vars[0] = s.deflection_m;
    c.vars[1] = s.rate_mps;
    c.vars[2] = s.base_stiffness;
    c.vars[3] = s.base_damping;
    for (std::size_t i = 0; i < p.size(); ++i) c.vars[4 + i] = p[i];
    return c.parser.Eval();
  }
  /// Compiles once on this thread (checks the expression; throws InputError).
  void check() const { (void)local(); }

 private:
  Compiled& local() const {
    // Per thread and per definition (by a unique id, not an address that may be reused). The last
    // one used is kept apart: a run evaluates one effect many times, so the hot path skips the map.
    thread_local std::unordered_map<std::uint64_t, std::unique_ptr<Compiled>> cache;
    thread_local std::uint64_t last_id = 0;
    thread_local Compiled* last = nullptr;
    if (last_id == id_) return *last;
    auto& slot = cache[id_];
    if (!slot) {
      auto c = std::make_unique<Compiled>();
      compile(*c, spec_.force, names_, spec_.where);
      slot = std::move(c);
    }
    last_id = id_;
    last = slot.get();
    return *slot;
  }
  UserEffectSpec spec_;
  std::uint64_t id_ = 0;
  std::vector<std::string> names_;
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

}  // namespace

std::vector<std::string> userEffectVariables(const std::string& element) {
  if (element == "strut") return {"q", "v", "k", "c"};
  return {};
}

std::unique_ptr<Effect> makeUserEffect(const UserEffectSpec& spec) {
  const std::string& w = spec.where;
  if (spec.element != "strut")
    throw InputError(w + ": element", "unknown element '" + spec.element + "' (known: strut)");
  const auto state = userEffectVariables(spec.element);
  std::string state_list;
  for (const auto& n : state) state_list += (state_list.empty() ? "" : ", ") + n;
  if (spec.force.empty()) throw InputError(w + ": force", "is required (an expression in " + state_list + " and the parameters)");
  std::vector<std::string> seen = state;
  for (const auto& p : spec.parameters) {
    const std::string pw = w + ": parameters." + p.name;
    if (!isIdentifier(p.name)) throw InputError(pw, "a parameter's name must be letters, digits and '_', starting with a letter");
    for (const auto& s : seen)
      if (s == p.name) throw InputError(pw, "the name is taken (state variables: " + state_list + "; or another parameter)");
    seen.push_back(p.name);
    if (p.unit.empty()) throw InputError(pw + ".unit", "is required (\"1\" for none)");
    if (!std::isfinite(p.lower) || !std::isfinite(p.upper) || !(p.lower < p.upper))
      throw InputError(pw, "needs a prior range with finite lower < upper, got [" + formatNumber(p.lower) + ", " + formatNumber(p.upper) + "]");
    if (!std::isfinite(p.value) || p.value < p.lower || p.value > p.upper)
      throw InputError(pw + ".value", "must lie in [lower, upper] = [" + formatNumber(p.lower) + ", " + formatNumber(p.upper) + "], got " +
                                          formatNumber(p.value));
  }
  auto effect = std::make_unique<UserStrutEffect>(spec, newId());
  effect->check();
  // Off at the values, and finite across the prior ranges, over a grid of strut states.
  std::vector<double> off, probe;
  for (const auto& p : spec.parameters) off.push_back(p.value);
  const double qs[] = {-0.08, -0.02, 0.0, 0.02, 0.08}, vs[] = {-1.0, -0.1, 0.0, 0.1, 1.0};
  for (double q : qs)
    for (double v : vs) {
      StrutState s;
      s.deflection_m = q;
      s.rate_mps = v;
      s.base_stiffness = 3e4;
      s.base_damping = 2.5e3;
      const double f = effect->calcStrutForce(s, off);
      if (!std::isfinite(f) || f != 0.0)
        throw InputError(w + ": force", "must be 0 with every parameter at its value (the effect off); at q = " + formatNumber(q) +
                                            " m, v = " + formatNumber(v) + " m/s it is " + formatNumber(f) + " N");
      // The corners of the first 10 parameters' ranges (the others at their values): at most 1024.
      for (int corner = 0; corner < (1 << std::min<std::size_t>(spec.parameters.size(), 10)); ++corner) {
        probe = off;
        for (std::size_t i = 0; i < spec.parameters.size() && i < 10; ++i)
          probe[i] = (corner >> i) & 1 ? spec.parameters[i].upper : spec.parameters[i].lower;
        const double g = effect->calcStrutForce(s, probe);
        if (!std::isfinite(g))
          throw InputError(w + ": force", "is not finite (" + formatNumber(g) + ") at q = " + formatNumber(q) + " m, v = " + formatNumber(v) +
                                              " m/s with the parameters at the corners of their prior ranges");
      }
    }
  return effect;
}

namespace {

struct UserRegistry {
  struct Entry {
    UserEffectSpec spec;
    std::uint64_t id = 0;  ///< the key of the definition's compiled copies
  };
  std::mutex m;
  std::vector<Entry> entries;  ///< in registration order
};
UserRegistry& userRegistry() {
  static UserRegistry r;
  return r;
}

bool sameDefinition(const UserEffectSpec& a, const UserEffectSpec& b) {
  if (a.element != b.element || a.force != b.force || a.parameters.size() != b.parameters.size()) return false;
  for (std::size_t i = 0; i < a.parameters.size(); ++i) {
    const auto &x = a.parameters[i], &y = b.parameters[i];
    if (x.name != y.name || x.unit != y.unit || x.value != y.value || x.lower != y.lower || x.upper != y.upper || x.shape != y.shape)
      return false;
  }
  return true;
}

}  // namespace

void registerUserEffect(const UserEffectSpec& spec) {
  for (const auto& e : effectRegistry())
    if (e.name == spec.name) throw InputError(spec.where, "'" + spec.name + "' is a built-in effect's name; give the user-defined one another");
  (void)makeUserEffect(spec);  // every check, before it becomes known
  auto& r = userRegistry();
  std::lock_guard<std::mutex> lock(r.m);
  for (const auto& e : r.entries)
    if (e.spec.name == spec.name) {
      if (sameDefinition(e.spec, spec)) return;
      throw InputError(spec.where, "another definition of '" + spec.name + "' is in use (" + e.spec.where +
                                       "): one process holds one definition per name");
    }
  r.entries.push_back({spec, newId()});
}

std::unique_ptr<Effect> makeRegisteredUserEffect(const std::string& name) {
  auto& r = userRegistry();
  std::lock_guard<std::mutex> lock(r.m);
  for (const auto& e : r.entries)
    if (e.spec.name == name) return std::make_unique<UserStrutEffect>(e.spec, e.id);  // checked when registered
  return nullptr;
}

std::vector<std::string> userEffectNames() {
  auto& r = userRegistry();
  std::lock_guard<std::mutex> lock(r.m);
  std::vector<std::string> out;
  for (const auto& e : r.entries) out.push_back(e.spec.name);
  return out;
}

}  // namespace dtwin
