// The files of a diagnosis folder read for its report section (report/diagnosis_folder.hpp).
#include "report/diagnosis_folder.hpp"

#include <cmath>
#include <exception>

#include "common/errors.hpp"
#include "common/json.hpp"

namespace dtwin::report::diagnosis_folder {

const json& at(const json& j, const char* key) {
  static const json null;
  if (!j.is_object()) return null;
  const auto it = j.find(key);
  return it == j.end() ? null : *it;
}

double dbl(const json& j) { return j.is_number() ? j.get<double>() : kNaN; }

std::string str(const json& j) { return j.is_string() ? j.get<std::string>() : std::string(); }

std::string joinEffects(const json& effects) {
  std::string s;
  for (const auto& e : effects) s += (s.empty() ? "" : "+") + str(e);
  return s.empty() ? "base" : s;
}

namespace {

json readJson(const fs::path& p) {
  return readJsonFile(p.string(), " (is this the output folder of `twin diagnose`?)");
}

std::vector<double> numbers(const json& j, const char* what) {
  if (!j.is_array())
    throw InputError("", std::string("field ") + what + " must be an array of numbers");
  std::vector<double> v;
  v.reserve(j.size());
  for (const auto& e : j) v.push_back(dbl(e));
  return v;
}

/// Reads a full comparison (diagnosis/compare.hpp Comparison::toJson(true)).
Comparison readComparison(const fs::path& p) {
  const json j = readJson(p);
  Comparison c;
  c.file = p.string();
  try {
    if (!j.is_object() || !at(j, "series").is_array())
      throw InputError("", "has no array `series`");
    for (const auto& e : j["series"]) {
      Series s;
      s.data_set = str(at(e, "data_set"));
      s.scenario = str(at(e, "scenario"));
      s.channel = str(at(e, "channel"));
      s.unit = str(at(e, "unit"));
      if (s.channel.empty()) throw InputError("", "a series has no `channel`");
      s.rms = dbl(at(e, "rms"));
      s.nrmse = dbl(at(e, "nrmse"));
      s.coverage = dbl(at(e, "coverage95"));
      s.systematic_rms = dbl(at(e, "systematic_rms"));
      s.t = numbers(at(e, "t"), "t");
      s.measured = numbers(at(e, "measured_mean"), "measured_mean");
      s.predicted = numbers(at(e, "predicted_mean"), "predicted_mean");
      s.lo = numbers(at(e, "band_lo"), "band_lo");
      s.hi = numbers(at(e, "band_hi"), "band_hi");
      const std::size_t n = s.t.size();
      if (n == 0 || s.measured.size() != n || s.predicted.size() != n || s.lo.size() != n ||
          s.hi.size() != n)
        throw InputError(
            "", "series " + s.channel +
                    ": t, measured_mean, predicted_mean, band_lo and band_hi must be non-empty "
                    "arrays of one length");
      for (const auto& b : at(e, "bands"))
        s.bands.push_back({str(at(b, "band")), dbl(at(b, "ratio"))});
      c.series.push_back(std::move(s));
    }
    for (const auto& cm : at(j, "state_maps")) {
      for (const auto& m : at(cm, "maps")) {
        StateMap sm;
        sm.channel = str(at(cm, "channel"));
        sm.state = str(at(m, "state"));
        for (const auto& b : at(m, "bins"))
          sm.bins.push_back({dbl(at(b, "centre")), dbl(at(b, "mean_residual")), dbl(at(b, "se"))});
        for (const auto& f : at(m, "fits")) {
          const double e = dbl(at(f, "explained_fraction"));
          if (std::isfinite(e) && (!std::isfinite(sm.explained) || e > sm.explained)) {
            sm.explained = e;
            sm.feature = str(at(f, "feature"));
            sm.knee_at = dbl(at(f, "knee_at"));
          }
        }
        c.maps.push_back(std::move(sm));
      }
    }
  } catch (const InputError& e) {
    throw InputError(p.string(), e.rule());
  } catch (const std::exception& e) {
    throw InputError(p.string(), std::string("is malformed: ") + jsonErrorInWords(e));
  }
  return c;
}

}  // namespace

DiagnosisInput readDiagnosisInput(const std::string& diag_dir) {
  DiagnosisInput in;
  in.diag_dir = diag_dir;
  in.dir = fs::path(diag_dir);
  if (!fs::is_directory(in.dir))
    throw InputError(diag_dir, "is not a folder (give the output folder of `twin diagnose`)");
  const fs::path diag_file = in.dir / "diagnosis.json";
  in.d = readJson(diag_file);
  const json& d = in.d;
  if (!d.is_object() || !at(d, "verdict").is_string() || !at(d, "base").is_object())
    throw InputError(diag_file.string(),
                     "is not a diagnosis (needs a string `verdict` and an object `base`)");
  for (const char* k : {"ranked", "screening", "steps"})
    if (!at(d, k).is_null() && !at(d, k).is_array())
      throw InputError(diag_file.string(), std::string("field `") + k + "` must be an array");
  in.verdict = str(at(d, "verdict"));
  in.effect = str(at(d, "effect"));
  in.assembly = str(at(d, "assembly"));
  const json& steps = in.steps();
  in.has_steps = steps.is_array() && !steps.empty();

  in.base = readComparison(in.dir / "comparisons" / "base.json");
  if (!in.effect.empty()) {
    in.after_name = in.effect;
    in.after_label = "with " + in.effect;
  } else if (in.has_steps && steps.size() > 1) {
    in.after_name = joinEffects(at(steps[1], "effects"));
    in.after_label = "with " + in.after_name + " (applied)";
  }
  in.has_after = !in.after_name.empty();
  if (in.has_after) in.after = readComparison(in.dir / "comparisons" / (in.after_name + ".json"));
  return in;
}

}  // namespace dtwin::report::diagnosis_folder
