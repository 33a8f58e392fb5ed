// The speed trace file reader (io/speed_trace_file.hpp).
#include "io/speed_trace_file.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"

namespace dtwin {

namespace {

/// The speed units a trace header may name, with their factor to m/s.
const std::vector<std::pair<std::string, double>>& speedUnits() {
  static const std::vector<std::pair<std::string, double>> units = {
      {"mps", 1.0}, {"kmh", 1.0 / 3.6}, {"mph", 0.44704}};
  return units;
}

}  // namespace

SpeedTrace parseSpeedTraceCsv(const std::string& text, const std::string& name) {
  CsvReader csv(text, name);
  auto joined = [&] {
    std::string out;
    for (auto f : csv.fields()) out += (out.empty() ? "" : ",") + std::string(f);
    return out;
  };
  std::string known;
  for (const auto& [u, f] : speedUnits()) known += (known.empty() ? "" : ", ") + ("speed_" + u);
  if (!csv.next())
    throw InputError(name + ":1",
                     "empty file; expected the header 'time_s,speed_<unit>' (" + known + ")");
  const auto& h = csv.fields();
  if (h.empty() || h[0] != "time_s" || h.size() > 2)
    throw InputError(csv.where(), "header must be 'time_s,speed_<unit>' (" + known + "), got '" +
                                      joined() + "'");
  const std::string c1 = h.size() == 2 ? std::string(h[1]) : "";
  double to_mps = 0;
  for (const auto& [u, f] : speedUnits())
    if (c1 == "speed_" + u) to_mps = f;
  if (to_mps == 0)
    throw InputError(csv.where(), "unknown speed column '" + c1 + "'; known: " + known);
  std::vector<double> t, v;
  while (csv.next()) {
    const auto& f = csv.fields();
    if (f.size() != 2)
      throw InputError(csv.where(),
                       "expected 2 columns (time_s," + c1 + "), got '" + joined() + "'");
    double tv = 0, sv = 0;
    const std::string a(f[0]), b(f[1]);
    if (!parseNumber(a, tv) || !std::isfinite(tv))
      throw InputError(csv.where(), "time_s: '" + a + "' is not a finite number");
    if (!parseNumber(b, sv) || !std::isfinite(sv))
      throw InputError(csv.where(), c1 + ": '" + b + "' is not a finite number");
    if (sv < 0) throw InputError(csv.where(), c1 + ": must be >= 0, got " + b);
    if (!t.empty() && !(tv > t.back()))
      throw InputError(csv.where(),
                       "time_s: must increase, got " + a + " after " + formatNumber(t.back(), 17));
    t.push_back(tv);
    v.push_back(sv * to_mps);
  }
  if (t.size() < 2)
    throw InputError(name, "a speed trace needs at least 2 rows, got " + std::to_string(t.size()));
  return SpeedTrace(std::move(t), std::move(v), name);
}

SpeedTrace readSpeedTraceCsv(const std::string& path) {
  return parseSpeedTraceCsv(readTextFile(path, " (a speed trace: time_s,speed_<unit>)"), path);
}

}  // namespace dtwin
