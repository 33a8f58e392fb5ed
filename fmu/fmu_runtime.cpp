// The runtime of the FMU `twin export-fmu` writes (docs/fmu.md): the FMI 2.0 co-simulation
// functions, each translated into one call of the twin the FMU holds (study/cosim.hpp), which it
// rebuilds from the FMU's resources at fmi2Instantiate. Built as the shared library dtwin_fmu.so
// that the export copies into the FMU's binaries/linux64 as <modelIdentifier>.so, beside the
// libraries it needs (found by its run path $ORIGIN). No exception leaves a function: a failure is
// logged through the importer's logger (one line) and returned as fmi2Error.
#include <cctype>
#include <cstring>
#include <memory>
#include <string>

#include <fmi2Functions.h>
#include "common/errors.hpp"
#include "study/cosim.hpp"

namespace {

enum class Mode { Instantiated, Initialization, Stepping, Terminated, Failed };

struct Instance {
  std::string name, resources;
  fmi2CallbackFunctions callbacks{};
  bool logging = false;
  std::unique_ptr<dtwin::CoSimTwin> twin;
  Mode mode = Mode::Instantiated;
};

void log(const Instance* inst, fmi2Status status, const char* category, const std::string& msg) {
  if (!inst || !inst->callbacks.logger) return;
  if (status == fmi2OK && !inst->logging) return;
  std::string escaped;  // the logger reads its message as a printf format
  for (const char c : msg) escaped += c == '%' ? std::string("%%") : std::string(1, c);
  inst->callbacks.logger(inst->callbacks.componentEnvironment, inst->name.c_str(), status, category,
                         escaped.c_str());
}

/// A path from the resourceLocation URI ("file:///dir/resources/", "file:/dir/...", or a plain
/// path), percent-escapes decoded.
std::string uriToPath(const std::string& uri) {
  std::string p = uri;
  if (p.rfind("file://localhost/", 0) == 0)
    p = p.substr(16);
  else if (p.rfind("file://", 0) == 0)
    p = p.substr(7);
  else if (p.rfind("file:", 0) == 0)
    p = p.substr(5);
  std::string out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i] == '%' && i + 2 < p.size() + 0 &&
        std::isxdigit(static_cast<unsigned char>(p[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(p[i + 2]))) {
      out += static_cast<char>(std::stoi(p.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += p[i];
    }
  }
  return out;
}

/// Runs `f` on the instance; any exception is logged and becomes fmi2Error (the instance is then
/// failed when `fatal_to_run`).
template <class F>
fmi2Status guarded(fmi2Component c, const char* what, F&& f, bool fatal_to_run = false) {
  auto* inst = static_cast<Instance*>(c);
  if (!inst) return fmi2Error;
  try {
    return f(*inst);
  } catch (const std::exception& e) {
    log(inst, fmi2Error, "logStatusError", std::string(what) + ": " + e.what());
  } catch (...) {
    log(inst, fmi2Error, "logStatusError", std::string(what) + ": stopped");
  }
  if (fatal_to_run) inst->mode = Mode::Failed;
  return fmi2Error;
}

fmi2Status noVariables(fmi2Component c, size_t nvr, const char* what) {
  if (nvr == 0) return fmi2OK;
  log(static_cast<Instance*>(c), fmi2Error, "logStatusError",
      std::string(what) + ": the twin has only Real variables");
  return fmi2Error;
}

fmi2Status unsupported(fmi2Component c, const char* what) {
  log(static_cast<Instance*>(c), fmi2Error, "logStatusError",
      std::string(what) + " is not supported (see the capability flags of modelDescription.xml)");
  return fmi2Error;
}

}  // namespace

extern "C" {

const char* fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char* fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t, const fmi2String[]) {
  if (!c) return fmi2Error;
  static_cast<Instance*>(c)->logging = loggingOn != fmi2False;
  return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions* functions, fmi2Boolean,
                              fmi2Boolean loggingOn) {
  auto inst = std::make_unique<Instance>();
  inst->name = instanceName ? instanceName : "twin";
  if (functions) inst->callbacks = *functions;
  inst->logging = loggingOn != fmi2False;
  if (fmuType != fmi2CoSimulation) {
    log(inst.get(), fmi2Error, "logStatusError",
        "fmi2Instantiate: this FMU is for co-simulation only (no model exchange)");
    return nullptr;
  }
  if (!fmuResourceLocation) {
    log(inst.get(), fmi2Error, "logStatusError", "fmi2Instantiate: no fmuResourceLocation");
    return nullptr;
  }
  try {
    inst->resources = uriToPath(fmuResourceLocation);
    inst->twin = std::make_unique<dtwin::CoSimTwin>(inst->resources);
    if (!fmuGUID || inst->twin->guid() != fmuGUID)
      throw dtwin::InputError("fmi2Instantiate", "the GUID " + std::string(fmuGUID ? fmuGUID : "") +
                                                     " is not this FMU's " + inst->twin->guid());
  } catch (const std::exception& e) {
    log(inst.get(), fmi2Error, "logStatusError", std::string("fmi2Instantiate: ") + e.what());
    return nullptr;
  }
  log(inst.get(), fmi2OK, "logAll", "instantiated from " + inst->resources);
  return inst.release();
}

void fmi2FreeInstance(fmi2Component c) { delete static_cast<Instance*>(c); }

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean, fmi2Real, fmi2Real startTime,
                               fmi2Boolean, fmi2Real) {
  return guarded(c, "fmi2SetupExperiment", [&](Instance&) {
    if (startTime != 0.0)
      throw dtwin::InputError("fmi2SetupExperiment",
                              "startTime must be 0 (the twin starts at its static equilibrium at "
                              "t = 0)");
    return fmi2OK;
  });
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  return guarded(c, "fmi2EnterInitializationMode", [](Instance& i) {
    i.mode = Mode::Initialization;
    return fmi2OK;
  });
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  return guarded(
      c, "fmi2ExitInitializationMode",
      [](Instance& i) {
        i.twin->start();
        i.mode = Mode::Stepping;
        return fmi2OK;
      },
      true);
}

fmi2Status fmi2Terminate(fmi2Component c) {
  return guarded(c, "fmi2Terminate", [](Instance& i) {
    i.mode = Mode::Terminated;
    return fmi2OK;
  });
}

fmi2Status fmi2Reset(fmi2Component c) {
  return guarded(c, "fmi2Reset", [](Instance& i) {
    i.twin = std::make_unique<dtwin::CoSimTwin>(i.resources);
    i.mode = Mode::Instantiated;
    return fmi2OK;
  });
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
  return guarded(c, "fmi2GetReal", [&](Instance& i) {
    for (size_t k = 0; k < nvr; ++k) value[k] = i.twin->get(static_cast<std::size_t>(vr[k]) - 1);
    return fmi2OK;
  });
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
  return guarded(c, "fmi2SetReal", [&](Instance& i) {
    for (size_t k = 0; k < nvr; ++k) i.twin->set(static_cast<std::size_t>(vr[k]) - 1, value[k]);
    return fmi2OK;
  });
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2Integer[]) {
  return noVariables(c, nvr, "fmi2GetInteger");
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2Boolean[]) {
  return noVariables(c, nvr, "fmi2GetBoolean");
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2String[]) {
  return noVariables(c, nvr, "fmi2GetString");
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference[], size_t nvr,
                          const fmi2Integer[]) {
  return noVariables(c, nvr, "fmi2SetInteger");
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference[], size_t nvr,
                          const fmi2Boolean[]) {
  return noVariables(c, nvr, "fmi2SetBoolean");
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t nvr,
                         const fmi2String[]) {
  return noVariables(c, nvr, "fmi2SetString");
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate*) {
  return unsupported(c, "fmi2GetFMUstate");
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate) {
  return unsupported(c, "fmi2SetFMUstate");
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate*) {
  return unsupported(c, "fmi2FreeFMUstate");
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate, size_t*) {
  return unsupported(c, "fmi2SerializedFMUstateSize");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate, fmi2Byte[], size_t) {
  return unsupported(c, "fmi2SerializeFMUstate");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte[], size_t, fmi2FMUstate*) {
  return unsupported(c, "fmi2DeSerializeFMUstate");
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2ValueReference[], size_t, const fmi2Real[],
                                        fmi2Real[]) {
  return unsupported(c, "fmi2GetDirectionalDerivative");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                       const fmi2Integer[], const fmi2Real[]) {
  return unsupported(c, "fmi2SetRealInputDerivatives");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2Integer[], fmi2Real[]) {
  return unsupported(c, "fmi2GetRealOutputDerivatives");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean) {
  return guarded(
      c, "fmi2DoStep",
      [&](Instance& i) {
        if (i.mode != Mode::Stepping)
          throw dtwin::InputError("fmi2DoStep", "only after initialisation and before terminate");
        i.twin->step(currentCommunicationPoint, communicationStepSize);
        return fmi2OK;
      },
      true);
}

fmi2Status fmi2CancelStep(fmi2Component c) { return unsupported(c, "fmi2CancelStep"); }

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind, fmi2Status*) {
  return unsupported(c, "fmi2GetStatus");
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
  return guarded(c, "fmi2GetRealStatus", [&](Instance& i) {
    if (s != fmi2LastSuccessfulTime)
      throw dtwin::InputError("fmi2GetRealStatus", "only fmi2LastSuccessfulTime is known");
    *value = i.twin->time();
    return fmi2OK;
  });
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer*) {
  return unsupported(c, "fmi2GetIntegerStatus");
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
  return guarded(c, "fmi2GetBooleanStatus", [&](Instance& i) {
    if (s != fmi2Terminated)
      throw dtwin::InputError("fmi2GetBooleanStatus", "only fmi2Terminated is known");
    *value = i.mode == Mode::Failed ? fmi2True : fmi2False;
    return fmi2OK;
  });
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String*) {
  return unsupported(c, "fmi2GetStringStatus");
}

}  // extern "C"
