#pragma once
// The arguments of the module's calls (docs/python.md), from one table per call: their names,
// order, defaults and types. The table gives the call its signature (a text signature, so
// inspect.signature and help() show the keywords and their defaults), the argument list of its
// docstring, and the binding of what Python passed: every value's type is checked before any work,
// a wrong one raises TypeError naming the call, the keyword and the expected type
// ("simulate(): accuracy expects a float, got str 'abc'"). python/dtwin.pyi says the same types.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "python/bridge.hpp"

namespace dtwin::python {

/// What an argument accepts (each also None when its default is None).
enum class ArgType {
  Str,       ///< str
  Path,      ///< str or os.PathLike
  Paths,     ///< a path, or a sequence (list, tuple) of paths
  Names,     ///< str ("A,B": comma-separated) or a sequence of str
  Int,       ///< int (numbers.Integral, numpy's too), not bool
  Float,     ///< float or int (numbers.Real), not bool
  Bool,      ///< bool
  Window,    ///< (t0, t1): a sequence of two numbers
  Settings,  ///< {name: number or str} or a sequence of "NAME=VALUE"
  Effects,   ///< {name: {parameter: number} or None} or a sequence of "NAME[:p=v,...]"
  Progress,  ///< a callable (stage, done, total)
};

/// An argument's default: none (required), None, or a bool, int, float or str.
struct Default {
  enum class Kind { Required, None, Bool, Int, Float, Str } kind = Kind::None;
  bool b = false;
  long i = 0;
  double f = 0.0;
  std::string s;
  static Default required() { return make(Kind::Required); }
  static Default none() { return make(Kind::None); }
  static Default of(bool v) {
    Default d = make(Kind::Bool);
    d.b = v;
    return d;
  }
  static Default of(int v) {
    Default d = make(Kind::Int);
    d.i = v;
    return d;
  }
  static Default of(double v) {
    Default d = make(Kind::Float);
    d.f = v;
    return d;
  }
  static Default of(const char* v) {
    Default d = make(Kind::Str);
    d.s = v;
    return d;
  }
  static Default make(Kind k) {
    Default d;
    d.kind = k;
    return d;
  }
  /// As Python source ("None", "'M1'", "2.0", "False").
  std::string literal() const;
};

struct Param {
  std::string name;
  ArgType type;
  Default def;
  bool keyword_only = false;
};

class Arguments;

/// One call's table: `CallSignature("simulate", true).arg(...).keywordOnly().arg(...)`.
class CallSignature {
 public:
  /// `method`: bound to a Study (the text signature starts with self, positional-only). `shown`:
  /// the call's name in errors, when not `name` (the constructor: "Study").
  CallSignature(std::string name, bool method, std::string shown = "")
      : name_(std::move(name)), shown_(shown.empty() ? name_ : std::move(shown)), method_(method) {}
  CallSignature& arg(std::string name, ArgType type, Default def = Default::none());
  /// The arguments added after this are keyword-only (the `*` of a Python signature).
  CallSignature& keywordOnly();

  const std::string& name() const { return name_; }
  const std::vector<Param>& params() const { return params_; }
  /// "simulate(self, /, assembly='M1', scenario='lab', *, set=None, ...)".
  std::string textSignature() const;
  /// The docstring: the text signature line CPython reads (`name(...)\n--\n\n`), `summary`, and
  /// one line per argument with its type and default.
  std::string doc(const std::string& summary) const;
  /// What Python passed, bound to the names (defaults filled in) and type-checked: TypeError for a
  /// wrong type, an unknown or repeated keyword, too many positional or a missing argument.
  Arguments bind(const py::args& args, const py::kwargs& kwargs) const;

 private:
  std::string name_, shown_;
  bool method_;
  bool keyword_only_ = false;
  std::vector<Param> params_;
};

/// The bound arguments of one call, converted on demand (their types were checked by bind).
/// A value that has the right type but cannot be right (an int beyond 64 bits, a negative seed)
/// raises dtwin.InputError naming the keyword, as `twin` names the flag.
class Arguments {
 public:
  Arguments(const CallSignature& call, std::vector<py::object> values);
  const std::string& call() const { return call_->name(); }

  const py::object& operator[](const std::string& name) const;
  /// The call's keywords for the library's errors (bridge.hpp), `fields` naming the option fields
  /// that differ from their keyword.
  Keywords keywords(std::map<std::string, std::string> fields = {}) const;
  bool isNone(const std::string& name) const { return (*this)[name].is_none(); }

  std::string str(const std::string& name) const;                      ///< Str ("" for None)
  std::string path(const std::string& name) const;                     ///< Path ("" for None)
  std::vector<std::string> paths(const std::string& name) const;       ///< Paths (empty for None)
  std::vector<std::string> names(const std::string& name) const;       ///< Names, split on commas
  std::vector<std::string> strings(const std::string& name) const;     ///< Names, as given
  long integer(const std::string& name) const;                         ///< Int
  int smallInteger(const std::string& name) const;                     ///< Int within int's range
  std::optional<long> optionalInteger(const std::string& name) const;  ///< Int or None
  std::optional<double> optionalReal(const std::string& name) const;   ///< Float or None
  double real(const std::string& name) const;                          ///< Float
  bool flag(const std::string& name) const;                            ///< Bool
  /// Int or None, in [0, 2^64 - 1] (the range of `twin --seed`).
  std::optional<std::uint64_t> seed(const std::string& name) const;
  std::vector<double> window(const std::string& name) const;         ///< Window (empty for None)
  std::vector<std::string> settings(const std::string& name) const;  ///< Settings, as `--set` texts
  std::vector<std::string> effects(
      const std::string& name) const;  ///< Effects, as `--effect` texts

 private:
  const Param& param(const std::string& name, std::size_t* index = nullptr) const;
  [[noreturn]] void invalid(const std::string& name, const std::string& rule) const;
  const CallSignature* call_;
  std::vector<py::object> values_;
};

}  // namespace dtwin::python
