#include "study/export_fmu.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <toml++/toml.h>

#include "calibration/folder.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"
#include "common/hash.hpp"
#include "common/validate.hpp"
#include "io/fmi_description.hpp"
#include "io/provenance.hpp"
#include "io/zip_archive.hpp"
#include "study/cosim.hpp"

namespace fs = std::filesystem;

namespace dtwin {

namespace {

constexpr const char* kRuntimeLibrary = "dtwin_fmu.so";

/// The calibrated values the FMU starts from, by name, and where they come from.
struct Values {
  std::vector<std::pair<std::string, double>> parameters;
  std::string from;
  nlohmann::json calibration_summary;  ///< null without a calibration
  AssemblySpec assembly;
  calib::CalibrationSetup setup;
};

std::vector<double> optimumTheta(const calib::CalibrationFolder& f) {
  const std::string where = (fs::path(f.dir) / "summary.json").string() + ": optimum.theta";
  const auto& s = f.summary;
  if (!s.contains("optimum") || !s["optimum"].is_object() || !s["optimum"].contains("theta") ||
      !s["optimum"]["theta"].is_array())
    throw InputError(where, "is missing (the calibration has no optimum; give --draw K)");
  std::vector<double> theta;
  for (const auto& v : s["optimum"]["theta"]) {
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw InputError(where, "must hold finite numbers");
    theta.push_back(v.get<double>());
  }
  if (theta.size() != f.posterior.names.size())
    throw InputError(where, "has " + std::to_string(theta.size()) + " values for the " +
                                std::to_string(f.posterior.names.size()) +
                                " calibrated parameters of posterior.csv");
  return theta;
}

Values calibratedValues(const Study& study, const ExportFmuRequest& r) {
  Values v;
  if (r.calibration.empty()) {
    v.assembly = study.assembly(r.assembly);
    const auto model = study.makeModel(v.assembly, r.effects, r.sets);
    const auto d = model->defaultRunValues();
    for (const auto& c : study.calibrated)
      if (const int slot = model->slot(c.name); slot >= 0)
        v.parameters.push_back({c.name, d[static_cast<std::size_t>(slot)]});
    v.from = "the study's values";
    return v;
  }
  const calib::CalibrationFolder f = calib::readCalibrationFolder(r.calibration);
  v.assembly = calib::calibratedAssembly(study, f);
  if (!r.assembly.empty() && r.assembly != v.assembly.id)
    throw InputError("export-fmu.assembly", "'" + r.assembly +
                                                "' is not the calibration's assembly " +
                                                v.assembly.id + " (" + r.calibration + ")");
  v.setup = f.setup;
  if (!f.setup.sensor_models.empty())
    throw InputError((fs::path(f.dir) / "summary.json").string() + ": setup.sensor_models",
                     "a sensor model distorts the data, not the twin: an FMU cannot carry it");
  std::vector<double> theta;
  if (r.draw) {
    if (*r.draw >= static_cast<long>(f.posterior.size()))
      throw InputError("export-fmu.draw", "draw " + std::to_string(*r.draw) + " is past the " +
                                              std::to_string(f.posterior.size()) + " draws of " +
                                              f.posterior.path);
    theta = f.posterior.theta[static_cast<std::size_t>(*r.draw)];
    v.from = "draw " + std::to_string(*r.draw) + " of " + r.calibration;
  } else {
    theta = optimumTheta(f);
    v.from = "the optimum of " + r.calibration;
  }
  for (std::size_t k = 0; k < theta.size(); ++k)
    v.parameters.push_back({f.posterior.names[k], theta[k]});
  v.calibration_summary = f.summary;
  return v;
}

nlohmann::json settingsJson(const std::vector<ParameterSetting>& s) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& p : s) a.push_back({{"name", p.name}, {"value", p.value}});
  return a;
}

/// The accuracy the calibration chose its integrator steps at (summary.json
/// integrator_check.accuracy) when it is tighter than the study's, else 0: the twin runs at it, as
/// `twin compare` does (docs/calibration.md, "The accuracy from the data").
double calibratedAccuracy(const Study& study, const nlohmann::json& summary) {
  if (!summary.is_object() || !summary.contains("integrator_check")) return 0.0;
  const auto& c = summary.at("integrator_check");
  if (!c.is_object() || !c.contains("accuracy") || !c.at("accuracy").is_number()) return 0.0;
  const double a = c.at("accuracy").get<double>();
  return a > 0.0 && a < study.simulation.accuracy ? a : 0.0;
}

/// The study the runtime reads: the user's, its vehicle file beside it, without the scenarios
/// (their roads and speed traces are the FMU's inputs) and the [lab] times that need them;
/// `accuracy` > 0 replaces [simulation] accuracy.
std::string runtimeStudy(const Study& study, double accuracy) {
  toml::table t;
  try {
    t = toml::parse_file(study.path);
  } catch (const toml::parse_error& e) {
    throw InputError(study.path, oneLine(std::string("cannot be read again: ") + e.what()));
  }
  if (auto* s = t["study"].as_table()) s->insert_or_assign("vehicle", "vehicle.toml");
  t.erase("scenarios");
  t.erase("lab");
  if (accuracy > 0.0) {
    if (!t.contains("simulation")) t.insert("simulation", toml::table{});
    if (auto* sim = t["simulation"].as_table()) sim->insert_or_assign("accuracy", accuracy);
  }
  std::ostringstream os;
  os << "# Written by twin export-fmu from " << study.path
     << ": the study without its scenarios and [lab]\n"
     << t << "\n";
  return os.str();
}

std::string binariesDir(const ExportFmuRequest& r) {
  std::string d = r.binaries;
  if (d.empty())
    if (const char* e = std::getenv("DTWIN_FMU_BINARIES")) d = e;
#ifdef DTWIN_FMU_BINARY_DIR
  if (d.empty()) d = DTWIN_FMU_BINARY_DIR;
#endif
  if (d.empty())
    throw InputError("export-fmu.binaries",
                     "this build has no FMU runtime (configured with DTWIN_BUILD_FMU=OFF); give "
                     "--binaries DIR");
  if (!fs::exists(fs::path(d) / kRuntimeLibrary))
    throw InputError("export-fmu.binaries",
                     "'" + d + "' holds no " + kRuntimeLibrary + " (build the target dtwin_fmu)");
  return d;
}

std::string modelIdentifier(const Study& study, const std::string& assembly) {
  std::string id = "twin_" + study.name + "_" + assembly;
  for (char& c : id)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return id;
}

/// A folder of its own under the system's temporary folder, removed with the object.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    path = fs::temp_directory_path() /
           ("twin-export-fmu-" + std::to_string(::getpid()) + "-" +
            hexId(fnv1a64(utcNow() + std::to_string(reinterpret_cast<std::uintptr_t>(this)))));
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

nlohmann::json fmuConfig(const Values& v, const ExportFmuRequest& r, const std::string& guid) {
  nlohmann::json effects = nlohmann::json::array();
  std::vector<EffectSetting> all = v.setup.extra_effects;
  all.insert(all.end(), r.effects.begin(), r.effects.end());
  for (const auto& e : all)
    effects.push_back({{"name", e.name}, {"values", settingsJson(e.values)}});
  nlohmann::json params = nlohmann::json::array();
  for (const auto& [name, value] : v.parameters) {
    double x = value;
    for (const auto& s : r.sets)
      if (s.name == name) x = s.value;  // --set wins
    params.push_back({{"name", name}, {"value", x}});
  }
  nlohmann::json options = nlohmann::json::array();
  for (const auto& o : v.setup.options) options.push_back({o.first, o.second});
  return {{"format", "dtwin FMU runtime 1"},
          {"guid", guid},
          {"study", "study.toml"},
          {"assembly", v.assembly.id},
          {"freed", v.setup.freed},
          {"options", options},
          {"effects", effects},
          {"sets", settingsJson(r.sets)},
          {"parameters", params}};
}

FmiModelInfo describe(const CoSimTwin& twin, const Study& study, const ExportFmuRequest& r,
                      const std::string& id, const std::string& label) {
  FmiModelInfo info;
  info.model_name = "twin " + study.name + " " + label;
  info.model_identifier = id;
  info.guid = twin.guid();
  info.description =
      "twin: " + study.name + ", assembly " + label + "; integrated with " + twin.integration();
  info.generation_tool = "twin " + programInfo().value("version", std::string("?"));
  info.generation_time_utc = utcNow();
  info.step_size_s = r.step_size_s;
  info.stop_time_s = r.stop_time_s;
  for (const auto& v : twin.variables()) {
    FmiVariable f;
    f.name = v.name;
    f.unit = v.unit;
    f.description = v.description;
    if (v.kind == CoSimVariable::Kind::Input) {
      f.causality = "input";
      f.variability = "continuous";
      f.start = v.start;
    } else if (v.kind == CoSimVariable::Kind::Output) {
      f.causality = "output";
      f.variability = "continuous";
    } else {
      f.causality = "parameter";
      f.variability = "fixed";
      f.initial = "exact";
      f.start = v.start;
    }
    info.variables.push_back(f);
  }
  return info;
}

void addTree(const fs::path& root, const std::string& prefix, std::vector<ZipMember>& out) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files)
    out.push_back({prefix + fs::relative(f, root).generic_string(), readTextFile(f.string())});
}

}  // namespace

void ExportFmuRequest::validate() const {
  const OptionCheck check("export-fmu");
  check.require(fs::path(out).extension() == ".fmu", "out",
                "must name a .fmu file, got '" + out + "'");
  check.require(!calibration.empty() || !assembly.empty(), "assembly",
                "give --calibration DIR or --assembly ID");
  check.require(!draw || *draw >= 0, "draw", "must be >= 0");
  check.require(!draw || !calibration.empty(), "draw", "needs --calibration");
  check.require(step_size_s > 0 && step_size_s <= 10, "step", "must be in (0, 10] s");
  check.require(stop_time_s > 0 && stop_time_s <= 86400, "stop-time", "must be in (0, 86400] s");
}

std::string ExportFmuResult::text() const {
  std::string s = "wrote " + fmu + " (" + formatNumber(static_cast<double>(bytes) / 1e6, 3) +
                  " MB, " + formatFixed(wall_s, 1) + " s): FMI 2.0 co-simulation, linux64\n";
  s += "  assembly " + assembly + " (" + label + "), values: " + values_from + "\n";
  s += "  " + std::to_string(inputs) + " inputs, " + std::to_string(outputs) + " outputs, " +
       std::to_string(parameters) + " parameters; modelIdentifier " + model_identifier + "\n";
  for (const auto& n : notes) s += "  note: " + n + "\n";
  return s;
}

ExportFmuResult exportFmu(const Study& study, const ExportFmuRequest& request) {
  const auto t0 = std::chrono::steady_clock::now();
  request.validate();
  const std::string bin = binariesDir(request);
  const Values v = calibratedValues(study, request);
  const std::string id = modelIdentifier(study, v.assembly.id);
  const std::string guid =
      "{" + hexId(fnv1a64(study.path + v.assembly.id + v.from + utcNow() + request.command)) + "}";
  const ScratchDir scratch;
  const fs::path res = scratch.path / "resources";
  const nlohmann::json config = fmuConfig(v, request, guid);
  writeFileAtomic((res / kCoSimConfig).string(), config.dump(2) + "\n");
  const double accuracy = calibratedAccuracy(study, v.calibration_summary);
  writeFileAtomic((res / "runtime" / "study.toml").string(), runtimeStudy(study, accuracy));
  writeFileAtomic((res / "runtime" / "vehicle.toml").string(), readTextFile(study.vehicle_path));
  writeFileAtomic((res / "study.toml").string(), readTextFile(study.path));
  if (!v.calibration_summary.is_null())
    writeFileAtomic((res / "calibration" / "summary.json").string(),
                    v.calibration_summary.dump(2) + "\n");
  // The twin as the runtime will see it: rebuilt from these files and started.
  CoSimTwin twin(res.string());
  twin.start();
  ExportFmuResult out;
  out.fmu = request.out;
  out.assembly = v.assembly.id;
  out.label = v.assembly.label();
  out.model_identifier = id;
  out.guid = guid;
  out.values_from = v.from;
  if (accuracy > 0.0)
    out.notes.push_back("integrated at accuracy " + formatNumber(accuracy, 3) +
                        ", the accuracy the calibration chose its steps at (the study's is " +
                        formatNumber(study.simulation.accuracy, 3) + ")");
  for (const auto& x : twin.variables()) {
    out.inputs += x.kind == CoSimVariable::Kind::Input;
    out.outputs += x.kind == CoSimVariable::Kind::Output;
    out.parameters += x.kind == CoSimVariable::Kind::Parameter;
  }
  nlohmann::json prov = {{"study", study.path},
                         {"calibration", request.calibration},
                         {"assembly", out.assembly},
                         {"values", v.from},
                         {"fmi", "2.0 co-simulation"},
                         {"model_identifier", id},
                         {"guid", guid},
                         {"runtime", config}};
  stampProvenance(prov, request.command);
  writeFileAtomic((res / "provenance.json").string(), prov.dump(2) + "\n");
  std::vector<ZipMember> members{
      {"modelDescription.xml",
       fmi2ModelDescription(describe(twin, study, request, id, out.label))}};
  std::vector<fs::path> libraries;
  for (const auto& e : fs::directory_iterator(bin))
    if (e.is_regular_file()) libraries.push_back(e.path());
  std::sort(libraries.begin(), libraries.end());
  for (const auto& p : libraries) {
    const std::string name = p.filename().string();
    const std::string as = name == kRuntimeLibrary ? id + ".so" : name;
    members.push_back({"binaries/linux64/" + as, readTextFile(p.string())});
    out.libraries.push_back(as);
  }
  addTree(res, "resources/", members);
  const std::string bytes = zipArchive(members);
  writeFileAtomic(request.out, bytes);
  out.bytes = bytes.size();
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace dtwin
