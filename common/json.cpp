#include "common/json.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/errors.hpp"

namespace dtwin {

nlohmann::json readJsonFile(const std::string& path, const std::string& hint) {
  const std::string text = readTextFile(path, hint);
  try {
    return nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    throw InputError(path, "is not valid JSON: " + jsonErrorInWords(e));
  }
}

std::string jsonErrorInWords(const std::exception& e) {
  std::string w = e.what();
  if (w.rfind("[json.exception.", 0) == 0) {
    const auto close = w.find("] ");
    if (close != std::string::npos) w = w.substr(close + 2);
  }
  return w;
}

nlohmann::json jsonNumber(double v) {
  if (std::isfinite(v)) return v;
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

double numberFromJson(const nlohmann::json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s == "-inf") return -std::numeric_limits<double>::infinity();
  return std::numeric_limits<double>::quiet_NaN();
}

nlohmann::json jsonNumbers(const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : v) a.push_back(jsonNumber(x));
  return a;
}

std::vector<double> numbersFromJson(const nlohmann::json& j) {
  std::vector<double> v;
  for (const auto& x : j) v.push_back(numberFromJson(x));
  return v;
}

}  // namespace dtwin
