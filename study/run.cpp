#include "study/run.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "calibration/calibrate.hpp"
#include "classification/classify_field.hpp"
#include "classification/synthesis.hpp"
#include "common/errors.hpp"
#include "twin/generate.hpp"
#include "twin/measurement.hpp"
#include "twin/distributed.hpp"
#include "twin/provenance.hpp"

namespace fs = std::filesystem;

namespace dtwin::study {
namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// A stage's output file is complete once it exists: every writer here is atomic. Under MPI the
/// root looks and every rank gets its answer.
bool done(const fs::path& p) {
  return onRoot([&] { return std::string(fs::exists(p) ? "1" : "0"); }) == "1";
}


}  // namespace

nlohmann::json runStudy(const Study& study, const StudyRunOptions& options, const std::string& out_dir,
                        const StudyProgress& progress, const StudyLog& log) {
  auto say = [&](const std::string& s) {
    if (log) log(s);
  };
  auto report = [&](const std::string& stage, std::size_t d, std::size_t t) {
    if (progress) progress(stage, d, t);
  };
  const auto t_all = std::chrono::steady_clock::now();
  const fs::path out(out_dir);
  const bool root = Distributed::instance().isRoot();  // only the root writes files and runs stage 5
  rootWrites([&] { fs::create_directories(out); });
  const auto assemblies = study.assemblies();
  if (assemblies.empty()) throw InputError(study.path, "the study defines no assemblies");
  const AssemblySpec& truth_assembly = assemblies.front();  // the highest fidelity generates the data

  // The study's fingerprint: a rerun into the same folder must be the same study.
  rootWrites([&] {
    nlohmann::json fp{{"study_file", std::to_string(calib::fnv1a64(readFileBytes(study.path)))},
                      {"vehicle_file", std::to_string(calib::fnv1a64(readFileBytes(study.vehicle_path)))},
                      {"lab_file", options.lab_file.empty() ? "" : std::to_string(calib::fnv1a64(readFileBytes(options.lab_file)))},
                      {"field_file", options.field_file.empty() ? "" : std::to_string(calib::fnv1a64(readFileBytes(options.field_file)))}};
    const fs::path record = out / "study.json";
    if (fs::exists(record)) {
      nlohmann::json j;
      try {
        std::ifstream in(record);
        in >> j;
      } catch (const std::exception&) {
        throw InputError(record.string(), "is not a study record; use an empty --out folder");
      }
      if (j.value("fingerprint", nlohmann::json()) != fp)
        throw InputError(record.string(), "was made by a different study, vehicle or data file; use a new --out folder or delete it");
    } else {
      writeFileAtomic(record.string(), nlohmann::json{{"fingerprint", fp}, {"study", study.path}, {"program", programInfo()},
                                                      {"command", options.command}, {"created_utc", utcNow()}}
                                               .dump(2) + "\n");
    }
  });

  nlohmann::json stages = nlohmann::json::object();
  // ---- 1. lab data
  auto t0 = std::chrono::steady_clock::now();
  std::string lab_path = options.lab_file;
  if (lab_path.empty()) {
    lab_path = (out / "lab" / "lab.csv").string();
    if (!done(sidecarPath(lab_path))) {
      rootWrites([&] {  // one simulation: the root alone
        report("lab", 0, 1);
        LabOptions lo;
        lo.command = options.command;
        const LabResult r = generateLab(study, truth_assembly, lo);
        writeLabCsv(lab_path, r.data);
        writeFileAtomic(sidecarPath(lab_path), r.provenance.dump(2) + "\n");  // last: marks the stage done
        report("lab", 1, 1);
        say("lab: " + truth_assembly.id + " at the truth, " + std::to_string(r.data.records.size()) + " records -> " + lab_path);
      });
    }
  }
  const std::string lab_bytes = rootFileBytes(lab_path);
  const LabData lab = parseLabCsv(lab_bytes, lab_path);
  stages["lab"] = since(t0);

  // ---- 2. field data
  t0 = std::chrono::steady_clock::now();
  std::string field_path = options.field_file;
  if (field_path.empty()) {
    field_path = (out / "field" / "field.csv").string();
    if (!done(sidecarPath(field_path))) {
      FieldOptions fo;
      fo.threads = options.threads;
      fo.command = options.command;
      const FieldResult r = generateField(study, truth_assembly, fo, [&](std::size_t d, std::size_t t) { report("field", d, t); });
      rootWrites([&] {
        writeFieldCsv(field_path, r.data);
        writeFileAtomic(sidecarPath(field_path), r.provenance.dump(2) + "\n");
      });
      say("field: " + std::to_string(r.data.rowCount()) + " records of " + truth_assembly.id + " on class-D roads -> " + field_path);
    }
  }
  stages["field"] = since(t0);

  // ---- 3. calibration of every assembly
  t0 = std::chrono::steady_clock::now();
  calib::CalibrationOptions co = calib::CalibrationOptions::fromStudy(study);
  co.threads = options.threads;
  co.command = options.command;
  co.data_path = lab_path;
  const std::string lab_hash = std::to_string(calib::fnv1a64(lab_bytes));
  nlohmann::json calibrated;
  for (const auto& a : assemblies) {
    const fs::path dir = out / "calibration" / a.id;
    const auto r = calib::calibrateAssembly(study, a, lab, "lab", co, dir.string(), lab_hash,
                                            [&](const std::string& s, std::size_t d, std::size_t t) {
                                              report("calibrate " + a.id + " " + s, d, t);
                                            });
    nlohmann::json j = r.toJson();
    j["program"] = programInfo();
    j["command"] = options.command;
    j["study"] = study.path;
    j["data"] = {{"path", lab_path}, {"records", lab.records.size()}, {"fnv1a64", lab_hash}};
    j["options"] = co.toJson();
    rootWrites([&] { writeFileAtomic((dir / "summary.json").string(), j.dump(2) + "\n"); });
    calibrated[a.id] = {{"sse_min", j["sse_min"]}, {"parameters", j["parameters"]}, {"tau", j["tau"]}};
    say("calibrate " + a.id + " (" + a.label() + "): SSE_min " + std::to_string(r.optimum.sse) + ", " +
        std::to_string(r.posterior.distinct_points) + " distinct design points");
  }
  stages["calibrate"] = since(t0);

  // ---- 4. synthetic field data from every posterior
  t0 = std::chrono::steady_clock::now();
  for (const auto& a : assemblies) {
    classify::SynthesisOptions so;
    so.threads = options.threads;
    so.command = options.command;
    const std::string post_path = (out / "calibration" / a.id / "posterior.csv").string();
    const auto post = calib::parsePosteriorCsv(onRoot([&] {
                                          if (!fs::exists(post_path)) throw InputError(post_path, "posterior file not found");
                                          return readFileBytes(post_path);
                                        }),
                                        post_path);
    const auto r = classify::synthesizeAssembly(study, a, post, so, (out / "synthetic" / a.id).string(),
                                      [&](std::size_t d, std::size_t t) { report("synthesize " + a.id, d, t); });
    say("synthesize " + a.id + ": " + std::to_string(r.simulations) + " simulations, " + std::to_string(r.failures) + " failed" +
        (r.reused ? " (reused)" : ""));
  }
  stages["synthesize"] = since(t0);

  // ---- 5. classification and recommendation: no simulation, the root alone (it wrote the files).
  if (!root) return nlohmann::json{{"rank", Distributed::instance().rank()}, {"stages", stages}};
  t0 = std::chrono::steady_clock::now();
  report("classify", 0, 1);
  classify::FieldClassifyOptions fo;
  fo.command = options.command;
  const classify::FieldClassification c = classifyFieldFile(study, field_path, (out / "synthetic").string(), fo);
  classify::writeFieldClassification(c, (out / "classification").string());
  report("classify", 1, 1);
  stages["classify"] = since(t0);
  stages["total"] = since(t_all);

  nlohmann::json s;
  s["program"] = programInfo();
  s["command"] = options.command;
  s["created_utc"] = utcNow();
  s["study"] = study.path;
  s["wins"] = c.summary["wins"];
  s["recommended"] = c.summary["recommended"];
  s["recommendation_sentence"] = c.summary["recommendation_sentence"];
  s["stages"] = stages;
  s["stages_note"] = "wall seconds of this invocation per stage (a resumed stage costs only what was left)";
  s["records"] = c.records.size();
  s["calibration"] = calibrated;
  s["paths"] = {{"lab", lab_path},
                {"field", field_path},
                {"calibration", (out / "calibration").string()},
                {"synthetic", (out / "synthetic").string()},
                {"classification", (out / "classification" / "summary.json").string()}};
  writeFileAtomic((out / "summary.json").string(), s.dump(2) + "\n");
  return s;
}

}  // namespace dtwin::study
