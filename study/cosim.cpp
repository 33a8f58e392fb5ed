#include "study/cosim.hpp"

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"
#include "io/study.hpp"
#include "twin/stepped_run.hpp"

namespace fs = std::filesystem;

namespace dtwin {

namespace {

constexpr std::size_t kInputs = 9;  // speed, the road under each wheel, the actuator in each strut

std::vector<CoSimVariable> inputVariables() {
  std::vector<CoSimVariable> v;
  using K = CoSimVariable::Kind;
  v.push_back({K::Input, "in_speed_mps", "m/s", "forward speed, >= 0", 0.0});
  for (const char* c : kCornerNames)
    v.push_back({K::Input, std::string("in_road_") + c + "_m", "m",
                 std::string("road signal under the ") + c +
                     " wheel: the road's height, or the hub's motion when the road enters at the "
                     "hub (tire = \"hub\")",
                 0.0});
  for (const char* c : kCornerNames)
    v.push_back({K::Input, std::string("in_actuator_") + c + "_N", "N",
                 std::string("actuator force in the ") + c +
                     " strut: positive pushes the body up and the wheel down",
                 0.0});
  return v;
}

const nlohmann::json& field(const nlohmann::json& j, const char* name, const std::string& where) {
  if (!j.is_object() || !j.contains(name)) throw InputError(where + ": " + name, "is missing");
  return j.at(name);
}

std::string text(const nlohmann::json& j, const char* name, const std::string& where) {
  const auto& f = field(j, name, where);
  if (!f.is_string()) throw InputError(where + ": " + name, "must be a string");
  return f.get<std::string>();
}

double number(const nlohmann::json& j, const char* name, const std::string& where) {
  const auto& f = field(j, name, where);
  if (!f.is_number() || !std::isfinite(f.get<double>()))
    throw InputError(where + ": " + name, "must be a finite number");
  return f.get<double>();
}

std::vector<ParameterSetting> settings(const nlohmann::json& list, const std::string& where) {
  std::vector<ParameterSetting> out;
  if (!list.is_array()) throw InputError(where, "must be a list");
  for (const auto& s : list)
    out.push_back({text(s, "name", where), number(s, "value", where), where, "FMU resources"});
  return out;
}

}  // namespace

struct CoSimTwin::Impl {
  std::string guid, integration;
  std::vector<CoSimVariable> vars;
  std::vector<int> slots;  ///< per parameter variable: its run slot
  std::size_t n_out = 0;
  std::shared_ptr<const Model> model;
  SimulationOptions options;
  std::vector<double> values;
  StepInputs inputs;
  std::unique_ptr<SteppedRun> run;

  std::size_t firstParameter() const { return kInputs + n_out; }
};

CoSimTwin::CoSimTwin(const std::string& resources) : impl_(std::make_unique<Impl>()) {
  Impl& I = *impl_;
  const fs::path dir(resources);
  const std::string where = (dir / kCoSimConfig).string();
  if (!fs::exists(where)) throw InputError(where, "is missing: not the resources of a twin FMU");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(readTextFile(where));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, oneLine(std::string("is not valid JSON: ") + e.what()));
  }
  I.guid = text(j, "guid", where);
  const Study study =
      loadStudy((dir / "runtime" / text(j, "study", where)).string(), /*scenarios_required=*/false);
  AssemblySpec spec = study.assembly(text(j, "assembly", where));
  for (const auto& f : field(j, "freed", where)) spec.freed.push_back(f.get<std::string>());
  for (const auto& o : field(j, "options", where)) {
    const auto sub = o.at(0).get<std::string>();
    auto it = std::find_if(spec.options.begin(), spec.options.end(),
                           [&](const auto& p) { return p.first == sub; });
    if (it == spec.options.end())
      throw InputError(where + ": options", "assembly " + spec.id + " has no subsystem " + sub);
    it->second = o.at(1).get<std::string>();
  }
  std::vector<EffectSetting> effects;
  for (const auto& e : field(j, "effects", where))
    effects.push_back({text(e, "name", where + ": effects"),
                       settings(field(e, "values", where + ": effects"), where + ": effects")});
  I.model = study.makeModel(spec, effects, settings(field(j, "sets", where), where + ": sets"));
  I.options = study.simulation;
  I.values = I.model->defaultRunValues();
  I.vars = inputVariables();
  for (const auto& ch : SteppedRun::channels(I.model->sensors()))
    I.vars.push_back({CoSimVariable::Kind::Output, ch.name, ch.unit, ch.description, 0.0});
  I.n_out = I.vars.size() - kInputs;
  for (const auto& p : field(j, "parameters", where)) {
    const std::string name = text(p, "name", where + ": parameters");
    if (I.model->lacksOptionParameter(name)) continue;  // e.g. the tire's, with the hub input
    const int slot = I.model->slot(name);
    if (slot < 0)
      throw InputError(where + ": parameters", "'" + name + "' is not a run parameter of " +
                                                   spec.id + " (" + I.model->assembly().label() +
                                                   ")");
    const double v = number(p, "value", where + ": parameters");
    I.values[static_cast<std::size_t>(slot)] = v;
    I.slots.push_back(slot);
    const auto& ps = I.model->table().at(name).spec;
    I.vars.push_back({CoSimVariable::Kind::Parameter, name, ps.unit, ps.description, v});
  }
  I.integration = I.options.integrator + ", accuracy " + formatNumber(I.options.accuracy) +
                  ", largest step " + formatNumber(I.options.max_step_s) + " s";
}
CoSimTwin::~CoSimTwin() = default;

const std::vector<CoSimVariable>& CoSimTwin::variables() const { return impl_->vars; }
const std::string& CoSimTwin::guid() const { return impl_->guid; }
std::string CoSimTwin::integration() const { return impl_->integration; }
bool CoSimTwin::started() const { return impl_->run != nullptr; }
double CoSimTwin::time() const { return impl_->run ? impl_->run->time() : 0.0; }
long CoSimTwin::integratorSteps() const { return impl_->run ? impl_->run->steps() : 0; }

void CoSimTwin::set(std::size_t index, double value) {
  Impl& I = *impl_;
  if (index >= I.vars.size())
    throw InputError("valueReference " + std::to_string(index + 1), "is not a variable");
  const CoSimVariable& v = I.vars[index];
  if (!std::isfinite(value)) throw InputError(v.name, "must be finite");
  if (v.kind == CoSimVariable::Kind::Output)
    throw InputError(v.name, "is an output: it cannot be set");
  if (v.kind == CoSimVariable::Kind::Parameter) {
    if (I.run) throw InputError(v.name, "is a fixed parameter: set it before initialisation ends");
    I.values[static_cast<std::size_t>(I.slots[index - I.firstParameter()])] = value;
    return;
  }
  if (index == 0) {
    I.inputs.speed_mps = value;
  } else if (index < 5) {
    I.inputs.road_m[index - 1] = value;
  } else {
    I.inputs.actuator_N[index - 5] = value;
  }
}

double CoSimTwin::get(std::size_t index) const {
  const Impl& I = *impl_;
  if (index >= I.vars.size())
    throw InputError("valueReference " + std::to_string(index + 1), "is not a variable");
  const CoSimVariable& v = I.vars[index];
  if (v.kind == CoSimVariable::Kind::Parameter)
    return I.values[static_cast<std::size_t>(I.slots[index - I.firstParameter()])];
  if (v.kind == CoSimVariable::Kind::Output) return I.run ? I.run->outputs()[index - kInputs] : 0.0;
  if (index == 0) return I.inputs.speed_mps;
  if (index < 5) return I.inputs.road_m[index - 1];
  return I.inputs.actuator_N[index - 5];
}

void CoSimTwin::start() {
  Impl& I = *impl_;
  auto run = std::make_unique<SteppedRun>(I.model, I.options);
  run->start(I.values, I.inputs);
  I.run = std::move(run);
}

void CoSimTwin::step(double t, double h) {
  Impl& I = *impl_;
  if (!I.run) throw InputError("doStep", "before initialisation ended");
  if (!(h > 0)) throw InputError("doStep", "communicationStepSize must be > 0");
  if (std::abs(t - I.run->time()) > 1e-9 * std::max(1.0, std::abs(t)))
    throw InputError("doStep", "currentCommunicationPoint " + formatExact(t) +
                                   " s is not the FMU's time " + formatExact(I.run->time()) + " s");
  I.run->advance(I.run->time() + h, I.inputs);
}

}  // namespace dtwin
