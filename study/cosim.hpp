#pragma once
// The twin inside an FMU (`twin export-fmu`, docs/fmu.md) as one object the FMU's runtime (fmu/)
// drives: rebuilt from the FMU's resources folder, its variables (inputs, outputs, parameters, in
// valueReference order), their values, the start at the static equilibrium and the steps. Every
// FMI call of the runtime is one call here; the export writes the resources it reads
// (study/export_fmu.hpp) and opens them once itself, so an FMU that is written also starts.
#include <memory>
#include <string>
#include <vector>

namespace dtwin {

/// One variable of the FMU (all are Real). valueReference = index in CoSimTwin::variables() + 1.
struct CoSimVariable {
  enum class Kind { Input, Output, Parameter } kind = Kind::Output;
  std::string name, unit, description;
  double start = 0.0;  ///< inputs' and parameters' start value (outputs: their value at t = 0)
};

/// The files of the resources folder the runtime reads (relative to it).
inline constexpr const char* kCoSimConfig = "runtime/fmu.json";

class CoSimTwin {
 public:
  /// Opens `resources` (the unzipped FMU's resources folder): runtime/fmu.json, the study and the
  /// vehicle file it names. InputError naming the file and the field when one is missing or bad.
  explicit CoSimTwin(const std::string& resources);
  ~CoSimTwin();
  CoSimTwin(const CoSimTwin&) = delete;
  CoSimTwin& operator=(const CoSimTwin&) = delete;

  const std::vector<CoSimVariable>& variables() const;
  /// The identity the FMU's modelDescription.xml carries (fmu.json "guid").
  const std::string& guid() const;
  /// The integrator's settings, for the description ("rosenbrock, accuracy 3e-4, ...").
  std::string integration() const;

  /// Sets variable `index`: a parameter before start(), an input at any time. InputError for an
  /// output, a parameter after start(), or an index out of range.
  void set(std::size_t index, double value);
  /// The value of variable `index`: an output's at time() (after start(); its start value before).
  double get(std::size_t index) const;

  /// The static equilibrium at t = 0 with the parameters and inputs set. InputError for values
  /// the model refuses; std::runtime_error (one line) when the start cannot be made.
  void start();
  /// Integrates from time() to time() + h (> 0) with the inputs set now. std::runtime_error (one
  /// line) when it fails; InputError when `t` is not time() (to 1e-9 s) or h <= 0.
  void step(double t, double h);
  bool started() const;
  double time() const;
  /// Integrator steps so far.
  long integratorSteps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dtwin
