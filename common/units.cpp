#include "common/units.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "common/format.hpp"

namespace dtwin {

bool Dimension::operator==(const Dimension& o) const {
  auto same = [](double a, double b) { return std::abs(a - b) < 1e-9; };
  return same(mass, o.mass) && same(length, o.length) && same(time, o.time);
}

namespace {

const char* const kSymbols = "1, kg, m, s, N, Pa, J, W, Hz, rad";

std::optional<Dimension> symbol(const std::string& s) {
  if (s == "1" || s == "rad") return Dimension{};
  if (s == "kg") return Dimension{1, 0, 0};
  if (s == "m") return Dimension{0, 1, 0};
  if (s == "s") return Dimension{0, 0, 1};
  if (s == "N") return Dimension{1, 1, -2};
  if (s == "Pa") return Dimension{1, -1, -2};
  if (s == "J") return Dimension{1, 2, -2};
  if (s == "W") return Dimension{1, 2, -3};
  if (s == "Hz") return Dimension{0, 0, -1};
  return std::nullopt;
}

/// Recursive descent over: term = factor (('*' | '/') factor)*; factor = (symbol | '(' term ')')
/// ['^' number].
class UnitParser {
 public:
  explicit UnitParser(const std::string& text) : t_(text) {}
  std::optional<Dimension> parse(std::string& rule) {
    auto d = term();
    skip();
    if (d && i_ != t_.size()) fail("unexpected '" + t_.substr(i_, 1) + "'");
    if (!d || !err_.empty()) {
      rule = err_;
      return std::nullopt;
    }
    return d;
  }

 private:
  void skip() {
    while (i_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[i_]))) ++i_;
  }
  void fail(const std::string& why) {
    if (err_.empty())
      err_ = "unit '" + t_ + "': " + why + " (SI symbols " + kSymbols +
             ", joined by *, / and ^, e.g. \"N*s/m\")";
  }
  std::optional<Dimension> term() {
    auto d = factor();
    if (!d) return std::nullopt;
    for (;;) {
      skip();
      if (i_ >= t_.size() || (t_[i_] != '*' && t_[i_] != '/')) return d;
      const char op = t_[i_++];
      auto e = factor();
      if (!e) return std::nullopt;
      d = op == '*' ? *d * *e : *d / *e;
    }
  }
  std::optional<Dimension> factor() {
    skip();
    std::optional<Dimension> d;
    if (i_ < t_.size() && t_[i_] == '(') {
      ++i_;
      d = term();
      skip();
      if (!d) return std::nullopt;
      if (i_ >= t_.size() || t_[i_] != ')') {
        fail("a '(' is not closed");
        return std::nullopt;
      }
      ++i_;
    } else {
      const std::size_t b = i_;
      while (i_ < t_.size() && (std::isalnum(static_cast<unsigned char>(t_[i_])) || t_[i_] == '_'))
        ++i_;
      const std::string s = t_.substr(b, i_ - b);
      if (s.empty()) {
        fail(i_ < t_.size() ? "expected a symbol at '" + t_.substr(i_, 1) + "'"
                            : "expected a symbol at the end");
        return std::nullopt;
      }
      d = symbol(s);
      if (!d) {
        fail("unknown symbol '" + s + "'" +
             (s.size() > 1 && symbol(s.substr(1)) ? " (prefixes are not allowed: values are SI)"
                                                  : ""));
        return std::nullopt;
      }
    }
    skip();
    if (i_ < t_.size() && t_[i_] == '^') {
      ++i_;
      skip();
      const char* start = t_.c_str() + i_;
      const char* stop = t_.c_str() + t_.size();
      if (start != stop && *start == '+') ++start;  // as strtod, which this replaced, accepted
      double e = 0;
      const auto r = std::from_chars(start, stop, e);  // whatever the locale
      if (r.ec != std::errc() || r.ptr == start || !std::isfinite(e)) {
        fail("'^' must be followed by a number");
        return std::nullopt;
      }
      i_ = static_cast<std::size_t>(r.ptr - t_.c_str());
      d = d->pow(e);
    }
    return d;
  }
  std::string t_;
  std::size_t i_ = 0;
  std::string err_;
};

std::string power(const char* sym, double e) {
  if (std::abs(e - 1.0) < 1e-9) return sym;
  return formatPrintf("%s^%.6g", sym, e);
}

}  // namespace

std::optional<Dimension> parseUnit(const std::string& unit, std::string& rule) {
  if (unit.find_first_not_of(" \t") == std::string::npos) {
    rule = "a unit is required (\"1\" for none)";
    return std::nullopt;
  }
  return UnitParser(unit).parse(rule);
}

std::string formatUnit(const Dimension& d) {
  const bool newton = std::abs(d.mass - 1.0) < 1e-9;
  Dimension rest = newton ? d / Dimension::force() : d;
  std::string num = newton ? "N" : "", den;
  auto add = [&](const char* sym, double e) {
    if (std::abs(e) < 1e-9) return;
    std::string& side = e > 0 ? num : den;
    side += (side.empty() ? "" : "*") + power(sym, std::abs(e));
  };
  if (!newton) add("kg", rest.mass);
  add("m", rest.length);
  add("s", rest.time);
  if (num.empty()) num = "1";
  if (den.empty()) return num;
  return num + "/" + (den.find('*') == std::string::npos ? den : "(" + den + ")");
}

double scaleFactor(const Dimension& d, double fm, double fl, double ft) {
  return std::pow(fm, d.mass) * std::pow(fl, d.length) * std::pow(ft, d.time);
}

}  // namespace dtwin
