#include "python/arguments.hpp"

#include <algorithm>
#include <climits>
#include <limits>

#include "common/format.hpp"

namespace dtwin::python {
namespace {

bool isSequence(const py::handle& v) {
  if (py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v)) return false;
  return py::isinstance(v, py::module_::import("collections.abc").attr("Sequence"));
}
bool isMapping(const py::handle& v) {
  return py::isinstance(v, py::module_::import("collections.abc").attr("Mapping"));
}
bool isNumber(const py::handle& v, const char* abc) {
  return !py::isinstance<py::bool_>(v) &&
         py::isinstance(v, py::module_::import("numbers").attr(abc));
}
bool isReal(const py::handle& v) { return isNumber(v, "Real"); }
bool isStr(const py::handle& v) { return py::isinstance<py::str>(v); }
bool isPath(const py::handle& v) { return isStr(v) || py::hasattr(v, "__fspath__"); }
template <class F>
bool allOf(const py::handle& seq, F&& f) {
  for (const auto& x : seq)
    if (!f(x)) return false;
  return true;
}
bool isStrings(const py::handle& v) { return isStr(v) || (isSequence(v) && allOf(v, isStr)); }

bool accepts(ArgType type, const py::handle& v) {
  switch (type) {
    case ArgType::Str:
      return isStr(v);
    case ArgType::Path:
      return isPath(v);
    case ArgType::Paths:
      return isPath(v) || (isSequence(v) && allOf(v, isPath));
    case ArgType::Names:
      return isStrings(v);
    case ArgType::Int:
      return isNumber(v, "Integral");
    case ArgType::Float:
      return isReal(v);
    case ArgType::Bool:
      return py::isinstance<py::bool_>(v);
    case ArgType::Window:
      return isSequence(v) && py::len(v) == 2 && allOf(v, isReal);
    case ArgType::Settings:
      if (isMapping(v))
        return allOf(v.attr("items")(), [](const py::handle& kv) {
          return isStr(kv[py::int_(0)]) && (isReal(kv[py::int_(1)]) || isStr(kv[py::int_(1)]));
        });
      return isStrings(v);
    case ArgType::Effects:
      if (isMapping(v))
        return allOf(v.attr("items")(), [](const py::handle& kv) {
          const py::object settings = kv[py::int_(1)];
          return isStr(kv[py::int_(0)]) &&
                 (settings.is_none() ||
                  (isMapping(settings) && accepts(ArgType::Settings, settings)));
        });
      return isStrings(v);
    case ArgType::Progress:
      return PyCallable_Check(v.ptr()) != 0;
  }
  return false;
}

/// The expected type in a TypeError's words.
const char* described(ArgType type) {
  switch (type) {
    case ArgType::Str:
      return "a str";
    case ArgType::Path:
      return "a str or a path";
    case ArgType::Paths:
      return "a path or a list of paths";
    case ArgType::Names:
      return "a str or a list of str";
    case ArgType::Int:
      return "an int";
    case ArgType::Float:
      return "a float";
    case ArgType::Bool:
      return "a bool";
    case ArgType::Window:
      return "a pair of floats (t0, t1)";
    case ArgType::Settings:
      return "a dict {name: value} or a list of 'NAME=VALUE'";
    case ArgType::Effects:
      return "a dict {name: {parameter: value}} or a list of 'NAME[:p=v,...]'";
    case ArgType::Progress:
      return "a callable (stage, done, total)";
  }
  return "?";
}

/// The type as annotated in python/dtwin.pyi (the docstring's argument list).
const char* annotation(ArgType type) {
  switch (type) {
    case ArgType::Str:
      return "str";
    case ArgType::Path:
      return "str | os.PathLike[str]";
    case ArgType::Paths:
      return "str | os.PathLike[str] | Sequence[str | os.PathLike[str]]";
    case ArgType::Names:
      return "str | Sequence[str]";
    case ArgType::Int:
      return "int";
    case ArgType::Float:
      return "float";
    case ArgType::Bool:
      return "bool";
    case ArgType::Window:
      return "tuple[float, float]";
    case ArgType::Settings:
      return "Mapping[str, float | str] | Sequence[str]";
    case ArgType::Effects:
      return "Mapping[str, Mapping[str, float | str] | None] | Sequence[str]";
    case ArgType::Progress:
      return "Callable[[str, int, int], object]";
  }
  return "?";
}

/// "str 'abc'": the type's name and the value's repr, shortened.
std::string shown(const py::handle& v) {
  std::string r = literal(v);
  if (r.size() > 60) r = r.substr(0, 57) + "...";
  return py::str(py::type::handle_of(v).attr("__name__")).cast<std::string>() + " " + r;
}

py::object defaultObject(const Default& d) {
  switch (d.kind) {
    case Default::Kind::Required:
    case Default::Kind::None:
      return py::none();
    case Default::Kind::Bool:
      return py::bool_(d.b);
    case Default::Kind::Int:
      return py::int_(d.i);
    case Default::Kind::Float:
      return py::float_(d.f);
    case Default::Kind::Str:
      return py::str(d.s);
  }
  return py::none();
}

/// A number as text the library parses back to the same double (Python's repr is the shortest exact
/// form).
std::string numberText(const py::handle& v) {
  if (isStr(v)) return v.cast<std::string>();
  return literal(py::float_(py::reinterpret_borrow<py::object>(v)));
}

/// "NAME=VALUE" texts of a {name: value} mapping.
std::string settingsText(const py::handle& mapping, const char* separator) {
  std::string out;
  for (const auto& kv : mapping.attr("items")()) {
    if (!out.empty()) out += separator;
    out += kv[py::int_(0)].cast<std::string>() + "=" + numberText(kv[py::int_(1)]);
  }
  return out;
}

}  // namespace

std::string Default::literal() const {
  if (kind == Kind::Required) return "";
  return python::literal(defaultObject(*this));
}

// ------------------------------------------------------------------ CallSignature
CallSignature& CallSignature::arg(std::string name, ArgType type, Default def) {
  params_.push_back({std::move(name), type, std::move(def), keyword_only_});
  return *this;
}

CallSignature& CallSignature::keywordOnly() {
  keyword_only_ = true;
  return *this;
}

std::string CallSignature::textSignature() const {
  std::string s = name_ + "(";
  std::vector<std::string> parts;
  if (method_) parts.push_back("self, /");
  bool star = false;
  for (const Param& p : params_) {
    if (p.keyword_only && !star) {
      parts.push_back("*");
      star = true;
    }
    parts.push_back(p.def.kind == Default::Kind::Required ? p.name
                                                          : p.name + "=" + p.def.literal());
  }
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
  return s + ")";
}

std::string CallSignature::doc(const std::string& summary) const {
  std::string d = textSignature() + "\n--\n\n" + summary;
  if (params_.empty()) return d;
  d += "\n\nArguments (a wrong type raises TypeError):";
  for (const Param& p : params_) {
    d += "\n    " + p.name + ": " + annotation(p.type);
    if (p.def.kind == Default::Kind::None) d += " | None";
    if (p.def.kind != Default::Kind::Required) d += " = " + p.def.literal();
  }
  return d;
}

Arguments CallSignature::bind(const py::args& args, const py::kwargs& kwargs) const {
  const std::string head = shown_ + "()";
  const std::size_t positional = static_cast<std::size_t>(std::count_if(
      params_.begin(), params_.end(), [](const Param& p) { return !p.keyword_only; }));
  if (args.size() > positional)
    throw py::type_error(head + " takes at most " + std::to_string(positional) +
                         " positional argument" + (positional == 1 ? "" : "s") + " (" +
                         std::to_string(args.size()) + " given)");
  std::vector<py::object> values(params_.size());
  for (std::size_t i = 0; i < args.size(); ++i)
    values[i] = py::reinterpret_borrow<py::object>(args[i]);
  for (const auto& [key, value] : kwargs) {
    const std::string k = key.cast<std::string>();
    const auto it =
        std::find_if(params_.begin(), params_.end(), [&](const Param& p) { return p.name == k; });
    if (it == params_.end())
      throw py::type_error(head + " got an unexpected keyword argument '" + k + "'");
    py::object& slot = values[static_cast<std::size_t>(it - params_.begin())];
    if (slot) throw py::type_error(head + " got multiple values for argument '" + k + "'");
    slot = py::reinterpret_borrow<py::object>(value);
  }
  for (std::size_t i = 0; i < params_.size(); ++i) {
    const Param& p = params_[i];
    if (!values[i]) {
      if (p.def.kind == Default::Kind::Required)
        throw py::type_error(head + " missing required argument '" + p.name + "'");
      values[i] = defaultObject(p.def);
    }
    if (values[i].is_none() && p.def.kind == Default::Kind::None) continue;
    if (!accepts(p.type, values[i]))
      throw py::type_error(head + ": " + p.name + " expects " + described(p.type) + ", got " +
                           shown(values[i]));
  }
  return Arguments(*this, std::move(values));
}

// ------------------------------------------------------------------ Arguments
Arguments::Arguments(const CallSignature& call, std::vector<py::object> values)
    : call_(&call), values_(std::move(values)) {}

const Param& Arguments::param(const std::string& name, std::size_t* index) const {
  const auto& ps = call_->params();
  const auto it =
      std::find_if(ps.begin(), ps.end(), [&](const Param& p) { return p.name == name; });
  if (it == ps.end())
    throw std::logic_error("python: " + call_->name() + "() has no argument '" + name + "'");
  if (index) *index = static_cast<std::size_t>(it - ps.begin());
  return *it;
}

const py::object& Arguments::operator[](const std::string& name) const {
  std::size_t i = 0;
  param(name, &i);
  return values_[i];
}

Keywords Arguments::keywords(std::map<std::string, std::string> fields) const {
  Keywords k;
  for (const Param& p : call_->params()) k.names.insert(p.name);
  k.fields = std::move(fields);
  return k;
}

void Arguments::invalid(const std::string& name, const std::string& rule) const {
  PyErr_SetString(exceptions().input_error.ptr(), oneLine(name + ": " + rule).c_str());
  throw py::error_already_set();
}

std::string Arguments::str(const std::string& name) const {
  const py::object& v = (*this)[name];
  return v.is_none() ? std::string() : v.cast<std::string>();
}

std::string Arguments::path(const std::string& name) const {
  const py::object& v = (*this)[name];
  return v.is_none() ? std::string() : pathText(v, name);
}

std::vector<std::string> Arguments::paths(const std::string& name) const {
  return stringList((*this)[name], name);
}

std::vector<std::string> Arguments::strings(const std::string& name) const {
  return stringList((*this)[name], name);
}

std::vector<std::string> Arguments::names(const std::string& name) const {
  std::vector<std::string> out;
  for (const auto& s : strings(name))
    for (auto& part : splitOn(s, ','))
      if (!part.empty()) out.push_back(std::move(part));
  return out;
}

long Arguments::integer(const std::string& name) const {
  const py::object i = py::reinterpret_steal<py::object>(PyNumber_Index((*this)[name].ptr()));
  if (!i) throw py::error_already_set();
  int overflow = 0;
  const long v = PyLong_AsLongAndOverflow(i.ptr(), &overflow);
  if (overflow != 0)
    invalid(name, "must be an integer in [" + std::to_string(LONG_MIN) + ", " +
                      std::to_string(LONG_MAX) + "], got " + literal(i));
  return v;
}

int Arguments::smallInteger(const std::string& name) const {
  const long v = integer(name);
  if (v < INT_MIN || v > INT_MAX)
    invalid(name, "must be an integer in [" + std::to_string(INT_MIN) + ", " +
                      std::to_string(INT_MAX) + "], got " + std::to_string(v));
  return static_cast<int>(v);
}

std::optional<long> Arguments::optionalInteger(const std::string& name) const {
  if (isNone(name)) return std::nullopt;
  return integer(name);
}

double Arguments::real(const std::string& name) const {
  const double v = PyFloat_AsDouble((*this)[name].ptr());
  if (v == -1.0 && PyErr_Occurred()) throw py::error_already_set();
  return v;
}

std::optional<double> Arguments::optionalReal(const std::string& name) const {
  if (isNone(name)) return std::nullopt;
  return real(name);
}

bool Arguments::flag(const std::string& name) const { return (*this)[name].cast<bool>(); }

std::optional<std::uint64_t> Arguments::seed(const std::string& name) const {
  if (isNone(name)) return std::nullopt;
  const py::object i = py::reinterpret_steal<py::object>(PyNumber_Index((*this)[name].ptr()));
  if (!i) throw py::error_already_set();
  const unsigned long long v = PyLong_AsUnsignedLongLong(i.ptr());
  if (PyErr_Occurred()) {
    PyErr_Clear();
    invalid(name, "must be an integer in [0, " +
                      std::to_string(std::numeric_limits<std::uint64_t>::max()) + "], got " +
                      literal(i));
  }
  return static_cast<std::uint64_t>(v);
}

std::vector<double> Arguments::window(const std::string& name) const {
  std::vector<double> out;
  if (isNone(name)) return out;
  for (const auto& x : (*this)[name])
    out.push_back(py::float_(py::reinterpret_borrow<py::object>(x)).cast<double>());
  return out;
}

std::vector<std::string> Arguments::settings(const std::string& name) const {
  const py::object& v = (*this)[name];
  if (v.is_none()) return {};
  if (!isMapping(v)) return stringList(v, name);
  std::vector<std::string> out;
  for (const auto& kv : v.attr("items")())
    out.push_back(kv[py::int_(0)].cast<std::string>() + "=" + numberText(kv[py::int_(1)]));
  return out;
}

std::vector<std::string> Arguments::effects(const std::string& name) const {
  const py::object& v = (*this)[name];
  if (v.is_none()) return {};
  if (!isMapping(v)) return stringList(v, name);
  std::vector<std::string> out;
  for (const auto& kv : v.attr("items")()) {
    std::string text = kv[py::int_(0)].cast<std::string>();
    const py::object settings = kv[py::int_(1)];
    if (!settings.is_none()) {
      const std::string s = settingsText(settings, ",");
      if (!s.empty()) text += ":" + s;
    }
    out.push_back(std::move(text));
  }
  return out;
}

}  // namespace dtwin::python
