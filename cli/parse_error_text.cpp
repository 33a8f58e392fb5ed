#include "cli/parse_error_text.hpp"

#include <cerrno>
#include <cfloat>
#include <cstdlib>
#include <regex>
#include <vector>

#include "common/format.hpp"
#include "common/names.hpp"

namespace dtwin::cli {

namespace {

/// The option `name` ("--level", "level", "-n") of `app`, or null.
const CLI::Option* findOption(const CLI::App& app, const std::string& name) {
  for (const CLI::Option* o : app.get_options([](const CLI::Option*) { return true; }))
    if (o->check_name(name)) return o;
  return nullptr;
}

/// Every long flag of `app` ("--assembly", ...), for the near-name hint.
std::vector<std::string> longFlags(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options([](const CLI::Option*) { return true; }))
    for (const auto& n : o->get_lnames()) names.push_back("--" + n);
  return names;
}

/// What a value of type `type` (CLI11's type name: FLOAT, INT, UINT, TEXT, ...) is, in words.
std::string kindOf(const std::string& type) {
  if (type.find("FLOAT") != std::string::npos || type.find("NUMBER") != std::string::npos)
    return "a number";
  if (type.find("UINT") != std::string::npos) return "a whole number of 0 or more";
  if (type.find("INT") != std::string::npos) return "a whole number";
  if (type.find("BOOL") != std::string::npos) return "true or false";
  return "a value";
}

bool isNumber(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno == 0;
}

/// "in [a, b]", "above 0" (the largest double stands for no upper bound).
std::string rangeText(const std::string& lo, const std::string& hi) {
  double a = 0, b = 0;
  if (!isNumber(lo, a) || !isNumber(hi, b)) return "in [" + lo + ", " + hi + "]";
  const bool open_above = b >= DBL_MAX * 0.5;
  if (open_above) return a <= DBL_MIN ? "above 0" : "of " + formatPrintf("%g", a) + " or more";
  return "in [" + formatPrintf("%g", a) + ", " + formatPrintf("%g", b) + "]";
}

/// The members of CLI11's "{a,b,c}".
std::vector<std::string> setMembers(const std::string& braces) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : braces) {
    if (c == '{' || c == '}') continue;
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

/// A validator's message about option `name`, in our words ("" if not recognised).
std::string validationText(const CLI::App& app, const std::string& name, const std::string& rule) {
  std::smatch m;
  const std::regex range(R"(^Value (.*) not in range (\S+) to (\S+)$)");
  const std::regex member(R"(^(.*) not in (\{.*\})$)");
  const std::regex missing(R"(^(File|Directory|Path) does not exist: (.*)$)");
  const std::regex parsing(R"(^Failed parsing (.*) as a (.*)$)");
  const CLI::Option* opt = findOption(app, name);
  const std::string kind = opt ? kindOf(opt->get_type_name()) : "a number";
  if (std::regex_match(rule, m, range)) {
    double v = 0;
    const std::string where = rangeText(m[2], m[3]);
    if (isNumber(m[1], v))
      return name + ": " + std::string(m[1]) + " is out of range (it takes " + kind + " " + where +
             ")";
    return name + ": '" + std::string(m[1]) + "' is not " + kind + " (it takes " + kind + " " +
           where + ")";
  }
  if (std::regex_match(rule, m, member))
    return name + ": " + unknownNameRule("value", m[1], setMembers(m[2]));
  if (std::regex_match(rule, m, missing)) {
    const std::string what = m[1] == "File" ? "file" : m[1] == "Directory" ? "folder" : "path";
    return name + ": " + what + " '" + std::string(m[2]) + "' not found";
  }
  if (std::regex_match(rule, m, parsing))
    return name + ": '" + std::string(m[1]) + "' is not " + kindOf(m[2]);
  return "";
}

/// The arguments no option of `app` took, as our message.
std::string extrasText(const CLI::App& app) {
  const std::vector<std::string> left = app.remaining(false);
  for (const auto& arg : left) {
    if (arg.size() < 2 || arg[0] != '-') continue;
    const std::string flag = arg.substr(0, arg.find('='));
    const std::string hint = closestName(flag, longFlags(app));
    return "unknown option '" + flag + "'" +
           (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)");
  }
  if (!left.empty())
    return "unexpected argument '" + left.front() +
           "': every input is given by its option (e.g. --data FILE)";
  return "unexpected arguments";
}

std::string lowerFirst(std::string s) {
  if (!s.empty() && s[0] >= 'A' && s[0] <= 'Z') s[0] = static_cast<char>(s[0] - 'A' + 'a');
  return s;
}

}  // namespace

std::string parseErrorText(const CLI::App& app, const CLI::ParseError& e) {
  const std::string what = oneLine(e.what());
  std::smatch m;
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) return extrasText(app);
  if (dynamic_cast<const CLI::ConversionError*>(&e)) {
    const std::regex convert(R"(^Could not convert: (\S+) = (.*)$)");
    const std::regex allowed(R"(^The value (.*) is not an allowed value for (\S+)$)");
    const std::regex flag_value(R"(^(\S+): Should be true/false or a number$)");
    const std::regex flag_many(R"(^(\S+): too many inputs for a flag$)");
    if (std::regex_match(what, m, convert)) {
      const CLI::Option* opt = findOption(app, m[1]);
      return std::string(m[1]) + ": '" + std::string(m[2]) + "' is not " +
             (opt ? kindOf(opt->get_type_name()) : std::string("a valid value"));
    }
    if (std::regex_match(what, m, allowed))
      return std::string(m[2]) + ": '" + std::string(m[1]) + "' is not an allowed value";
    if (std::regex_match(what, m, flag_value))
      return std::string(m[1]) + " is a switch: give it alone, or =true / =false";
    if (std::regex_match(what, m, flag_many))
      return std::string(m[1]) + " is a switch and takes no value";
  }
  if (dynamic_cast<const CLI::ValidationError*>(&e)) {
    const std::regex named(R"(^(-?-?[A-Za-z0-9_][A-Za-z0-9_-]*): (.*)$)");
    if (std::regex_match(what, m, named))
      if (std::string t = validationText(app, m[1], m[2]); !t.empty()) return t;
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
    const std::regex missing(R"(^(\S+): \d+ required (\S+) missing$)");
    const std::regex count(R"(^Expected (exactly|at least) (\d+) arguments? to (\S+), got (\d+)$)");
    if (std::regex_match(what, m, missing)) {
      const std::string kind = kindOf(m[2]);
      return std::string(m[1]) + " needs a value" +
             (kind == "a value" ? std::string() : " (" + kind + ")");
    }
    if (std::regex_match(what, m, count))
      return std::string(m[3]) + " takes " + std::string(m[1]) + " " + std::string(m[2]) +
             " value(s), got " + std::string(m[4]);
  }
  if (dynamic_cast<const CLI::RequiredError*>(&e)) {
    const std::regex required(R"(^(\S+) is required$)");
    if (std::regex_match(what, m, required))
      return "the option " + std::string(m[1]) + " is required";
  }
  if (dynamic_cast<const CLI::ExcludesError*>(&e)) {
    const std::regex excludes(R"(^(\S+) excludes (\S+)$)");
    if (std::regex_match(what, m, excludes))
      return std::string(m[1]) + " and " + std::string(m[2]) + " cannot be given together";
  }
  if (dynamic_cast<const CLI::RequiresError*>(&e)) {
    const std::regex requires_(R"(^(\S+) requires (\S+)$)");
    if (std::regex_match(what, m, requires_))
      return std::string(m[1]) + " needs " + std::string(m[2]) + " as well";
  }
  return lowerFirst(what);
}

}  // namespace dtwin::cli
