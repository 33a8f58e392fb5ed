// posterior.csv read and written (io/posterior_file.hpp).
#include "io/posterior_file.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "common/checksum.hpp"
#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"

namespace fs = std::filesystem;

namespace dtwin {

PosteriorSample parsePosteriorCsv(const std::string& text, const std::string& name) {
  PosteriorSample ps;
  ps.path = name;
  CsvReader csv(text, name);
  std::vector<std::string> header;
  while (csv.next()) {
    const std::string at = csv.where();
    const auto& f = csv.fields();
    if (header.empty()) {
      header.assign(f.begin(), f.end());
      if (header.size() < 3 || header[header.size() - 2] != "tau" ||
          header.back() != "design_index") {
        std::string got;
        for (const auto& h : header) got += (got.empty() ? "" : ",") + h;
        throw InputError(
            at,
            "header must be the calibrated parameter names, then tau, then design_index "
            "(as `twin calibrate` writes posterior.csv), got '" +
                got + "'");
      }
      std::set<std::string> seen;
      for (std::size_t c = 0; c + 2 < header.size(); ++c) {
        if (header[c].empty())
          throw InputError(at, "header: column " + std::to_string(c + 1) + " has no name");
        if (header[c] == "tau" || header[c] == "design_index" || !seen.insert(header[c]).second)
          throw InputError(at, "header: column '" + header[c] + "' appears twice");
        ps.names.push_back(header[c]);
      }
      continue;
    }
    if (f.size() != header.size())
      throw InputError(at, "expected " + std::to_string(header.size()) + " fields, got " +
                               std::to_string(f.size()));
    std::vector<double> th(ps.names.size());
    for (std::size_t c = 0; c < ps.names.size(); ++c) {
      if (!parseNumber(f[c], th[c]))
        throw InputError(at + ": " + ps.names[c],
                         "must be a number, got '" + std::string(f[c]) + "'");
      if (!std::isfinite(th[c]))
        throw InputError(at + ": " + ps.names[c], "must be finite, got " + std::string(f[c]));
    }
    double tau = 0;
    const std::string ft(f[ps.names.size()]);
    if (!parseNumber(ft, tau)) throw InputError(at + ": tau", "must be a number, got '" + ft + "'");
    if (!(std::isfinite(tau) && tau > 0))
      throw InputError(at + ": tau", "must be a finite number > 0 (a precision), got " + ft);
    const std::string_view fd = f.back();
    long k = -1;
    const auto r = std::from_chars(fd.data(), fd.data() + fd.size(), k);
    if (r.ec != std::errc() || r.ptr != fd.data() + fd.size() || k < 0)
      throw InputError(at + ": design_index",
                       "must be an integer >= 0, got '" + std::string(fd) + "'");
    ps.theta.push_back(std::move(th));
    ps.tau.push_back(tau);
    ps.design_index.push_back(k);
  }
  if (header.empty())
    throw InputError(name, "empty file (expected the header <parameters>,tau,design_index)");
  if (ps.tau.empty()) throw InputError(name, "no rows after the header (line 1)");
  return ps;
}

void checkPosteriorChecksum(const std::string& path, const std::string& text) {
  const fs::path summary = fs::path(path).parent_path() / "summary.json";
  std::error_code ec;
  if (!fs::is_regular_file(summary, ec)) return;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(readTextFile(summary.string()));
  } catch (const std::exception&) {
    return;  // not a calibration's summary: nothing recorded to check against
  }
  if (!j.is_object() || !j.contains("posterior_checksum") || !j["posterior_checksum"].is_string())
    return;
  const std::string recorded = j["posterior_checksum"].get<std::string>();
  if (recorded != contentChecksum(text))
    throw InputError(path, "fails its checksum (" + summary.string() + " records " + recorded +
                               "): it changed after the calibration wrote it and is not used; "
                               "rerun that calibration into its folder to write it again");
}

PosteriorSample readPosteriorCsv(const std::string& path) {
  if (!fs::exists(path)) throw InputError(path, "posterior file not found");
  const std::string text = readTextFile(path);
  checkPosteriorChecksum(path, text);
  return parsePosteriorCsv(text, path);
}

std::string posteriorCsv(const std::vector<std::string>& names,
                         const std::vector<std::vector<double>>& theta,
                         const std::vector<double>& tau, const std::vector<long>& design_index) {
  DTWIN_CHECK(theta.size() == tau.size() && tau.size() == design_index.size(),
              "posterior columns of unequal length");
  std::string csv;
  for (const auto& nm : names) csv += nm + ",";
  csv += "tau,design_index\n";
  for (std::size_t t = 0; t < tau.size(); ++t) {
    DTWIN_CHECK(theta[t].size() == names.size(), "posterior row of the wrong length");
    for (double v : theta[t]) csv += formatExact(v) + ",";
    csv += formatExact(tau[t]);
    csv += "," + std::to_string(design_index[t]) + "\n";
  }
  return csv;
}

}  // namespace dtwin
