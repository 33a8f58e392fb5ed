#include "calibration/folder.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "common/json.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/provenance.hpp"
#include "twin/trace.hpp"

namespace fs = std::filesystem;

namespace dtwin::calib {
namespace {

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t')) --b;
  std::string t = s.substr(a, b - a);
  if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = t.substr(1, t.size() - 2);
  return t;
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t c = line.find(',', start);
    out.push_back(trim(line.substr(start, c == std::string::npos ? std::string::npos : c - start)));
    if (c == std::string::npos) break;
    start = c + 1;
  }
  return out;
}

}  // namespace

PosteriorSample parsePosteriorCsv(const std::string& text, const std::string& name) {
  PosteriorSample ps;
  ps.path = name;
  std::istringstream in(text);
  std::string line;
  long line_no = 0;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    ++line_no;
    if (line_no == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty()) continue;
    const std::string at = name + ":" + std::to_string(line_no);
    if (header.empty()) {
      header = splitFields(line);
      if (header.size() < 3 || header[header.size() - 2] != "tau" || header.back() != "design_index")
        throw InputError(at, "header must be the calibrated parameter names, then tau, then design_index "
                             "(as `twin calibrate` writes posterior.csv), got '" + line + "'");
      std::set<std::string> seen;
      for (std::size_t c = 0; c + 2 < header.size(); ++c) {
        if (header[c].empty()) throw InputError(at, "header: column " + std::to_string(c + 1) + " has no name");
        if (header[c] == "tau" || header[c] == "design_index" || !seen.insert(header[c]).second)
          throw InputError(at, "header: column '" + header[c] + "' appears twice");
        ps.names.push_back(header[c]);
      }
      continue;
    }
    const auto f = splitFields(line);
    if (f.size() != header.size())
      throw InputError(at, "expected " + std::to_string(header.size()) + " fields, got " + std::to_string(f.size()));
    std::vector<double> th(ps.names.size());
    for (std::size_t c = 0; c < ps.names.size(); ++c) {
      if (!parseNumber(f[c], th[c])) throw InputError(at + ": " + ps.names[c], "must be a number, got '" + f[c] + "'");
      if (!std::isfinite(th[c])) throw InputError(at + ": " + ps.names[c], "must be finite, got " + f[c]);
    }
    double tau = 0;
    const std::string& ft = f[ps.names.size()];
    if (!parseNumber(ft, tau)) throw InputError(at + ": tau", "must be a number, got '" + ft + "'");
    if (!(std::isfinite(tau) && tau > 0)) throw InputError(at + ": tau", "must be a finite number > 0 (a precision), got " + ft);
    const std::string& fd = f.back();
    long k = -1;
    const auto r = std::from_chars(fd.data(), fd.data() + fd.size(), k);
    if (r.ec != std::errc() || r.ptr != fd.data() + fd.size() || k < 0)
      throw InputError(at + ": design_index", "must be an integer >= 0, got '" + fd + "'");
    ps.theta.push_back(std::move(th));
    ps.tau.push_back(tau);
    ps.design_index.push_back(k);
  }
  if (header.empty()) throw InputError(name, "empty file (expected the header <parameters>,tau,design_index)");
  if (ps.tau.empty()) throw InputError(name, "no rows after the header (line 1)");
  return ps;
}

PosteriorSample readPosteriorCsv(const std::string& path) {
  if (!fs::exists(path)) throw InputError(path, "posterior file not found");
  return parsePosteriorCsv(readTextFile(path), path);
}

std::string posteriorCsv(const std::vector<std::string>& names, const std::vector<std::vector<double>>& theta,
                         const std::vector<double>& tau, const std::vector<long>& design_index) {
  DTWIN_CHECK(theta.size() == tau.size() && tau.size() == design_index.size(), "posterior columns of unequal length");
  std::string csv;
  for (const auto& nm : names) csv += nm + ",";
  csv += "tau,design_index\n";
  char buf[64];
  for (std::size_t t = 0; t < tau.size(); ++t) {
    DTWIN_CHECK(theta[t].size() == names.size(), "posterior row of the wrong length");
    for (double v : theta[t]) csv += formatExact(v) + ",";
    csv += formatExact(tau[t]);
    std::snprintf(buf, sizeof buf, ",%ld\n", design_index[t]);
    csv += buf;
  }
  return csv;
}

CalibrationFolder readCalibrationFolder(const std::string& dir) {
  const fs::path d(dir);
  if (!fs::is_directory(d)) throw InputError(dir, "is not a folder (give one written by `twin calibrate` or `twin diagnose`)");
  CalibrationFolder f;
  f.dir = dir;
  const fs::path summary_path = d / "summary.json";
  if (!fs::exists(summary_path) && fs::exists(d / "optimum.json"))
    throw InputError(dir, "holds only an optimum (a `twin diagnose` candidate that could not be the verdict stops there); "
                          "rerun that diagnosis with --all-intervals to calibrate it in full");
  if (!fs::exists(summary_path))
    throw InputError(dir, "has no summary.json (give a folder written by `twin calibrate` or `twin diagnose`)");
  const std::string where = summary_path.string();
  try {
    f.summary = nlohmann::json::parse(readTextFile(where));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, std::string("is not valid JSON: ") + e.what());
  }
  if (!f.summary.is_object()) throw InputError(where, "must hold a JSON object");
  if (!f.summary.contains("assembly")) throw InputError(where + ": assembly", "is missing");
  if (!f.summary["assembly"].is_string() || f.summary["assembly"].get<std::string>().empty())
    throw InputError(where + ": assembly", "must be a non-empty string (an assembly id), got " + f.summary["assembly"].dump());
  f.assembly = f.summary["assembly"].get<std::string>();
  if (f.summary.contains("setup")) {
    try {
      f.setup = CalibrationSetup::fromJson(f.summary["setup"]);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw InputError(where + ": setup", std::string("is malformed: ") + e.what());
    }
  }
  f.posterior = readPosteriorCsv((d / "posterior.csv").string());
  return f;
}

AssemblySpec calibratedAssembly(const Study& study, const CalibrationFolder& folder) {
  std::string known;
  for (const auto& a : study.assemblies()) {
    if (a.id == folder.assembly) return a;
    known += (known.empty() ? "" : ", ") + a.id;
  }
  throw InputError((fs::path(folder.dir) / "summary.json").string() + ": assembly",
                   "'" + folder.assembly + "' is not an assembly of the study " + study.path + " (it defines: " + known + ")");
}

}  // namespace dtwin::calib
