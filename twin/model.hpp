#pragma once
// The constant description of one assembly (Pinocchio's Model / Drake's System in spirit): which
// option each subsystem uses, which effects are installed, every fixed value, and the layout of
// the per-run parameter vector. Immutable after construction and shared by all runs and threads.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/registry.hpp"
#include "subsystems/effect.hpp"
#include "subsystems/effect_catalog.hpp"
#include "subsystems/sensor.hpp"
#include "subsystems/strut_law.hpp"
#include "subsystems/tire_law.hpp"
#include "twin/parameters.hpp"

namespace dtwin {

enum class Corner : int { FL = 0, FR = 1, RL = 2, RR = 3 };
inline constexpr std::array<const char*, 4> kCornerNames = {"fl", "fr", "rl", "rr"};
inline bool isFront(int corner) { return corner < 2; }

enum class SuspensionTopology { MacPherson, SolidAxle };

/// One assembly: an option per subsystem plus optional effects.
struct AssemblySpec {
  std::string id;                                            ///< "M1"
  std::vector<std::pair<std::string, std::string>> options;  ///< (subsystem, option), study order
  std::vector<std::string> effects;                          ///< installed effect names
  /// Fixed vehicle values made run parameters (freeableVehicleParameters(); twin diagnose's
  /// "free:" candidates): a run whose value differs rebuilds its multibody system.
  std::vector<std::string> freed;
  // A per-corner or per-axle factor ("suspension.damping@rr", twin/parameters.hpp) in `freed` is
  // made a run parameter without a rebuild (calibrated or freed at any value, 1 included).
  std::string option(const std::string& subsystem) const;
  std::string label() const;  ///< "pac2002 + macpherson [+ bump_stop] [+ free wheel.mass_kg]"
};

/// The fixed vehicle values that can be freed (AssemblySpec::freed): the masses, inertias, CG
/// height and track the multibody system is built from. The axle positions are not among them
/// (the rear wheels meet the road one wheelbase later: the road depends on them). The solid
/// axle's values are listed too and refused for a MacPherson assembly.
const std::vector<std::string>& freeableVehicleParameters();

/// The suspension options (the `suspension` subsystem's), each a mobilizer layout.
const Registry<SuspensionTopology>& suspensionOptions();

/// A place of the road signal other than the axle form (the signal under the front wheels, the
/// rear a wheelbase later): a run parameter λ (0: the axle form, 1: this form) that moves every
/// corner's weight of the signal from 1 towards `weight` and reads the signal ahead by λ times the
/// wheelbase at the corners whose `no_lag` is 1 (docs/model.md, "Where the road signal is").
/// Forms add: corner c meets the signal with weight 1 + Σ λ_f (weight_f[c] − 1), read ahead by
/// the wheelbase times Σ λ_f no_lag_f[c].
struct RoadSignalForm {
  const char* name;   ///< "road.fl_only"
  const char* whose;  ///< "the front-left wheel's": the signal, in words
  const char* description;
  double weight[4];  ///< fl, fr, rl, rr at λ = 1
  double no_lag[4];
};
const std::vector<RoadSignalForm>& roadSignalForms();

/// Subsystems and options the twin knows.
const std::map<std::string, std::vector<std::string>>& knownSubsystems();

/// A table declaring every parameter a vehicle can have: fixed data (masses, geometry), the
/// parameters of every tire and suspension option, and every effect of `catalog` (pre-set to
/// "off").
ParameterTable declareVehicleParameters(const EffectCatalog& catalog);

/// Declares the parameters of `effect` (installed as `name`) not yet in `table`, at their off
/// values: an effect made on demand (a library term, subsystems/effect.hpp kTermPrefix) is not
/// among declareVehicleParameters's.
void declareEffectParameters(ParameterTable& table, const Effect& effect, const std::string& name,
                             const std::string& where);

/// Fixed (topology-level) vehicle data, read once per model.
struct VehicleData {
  double gravity = 9.80665;
  double chassis_mass = 0, ixx = 0, iyy = 0, izz = 0, cg_height = 0;
  double a = 0, b = 0, track = 0;  ///< CG to front / rear axle, track width
  double wheel_mass = 0;
  double axle_mass = 0, axle_ixx = 0, spring_track = 0;
  double wheelbase() const { return a + b; }
  /// Total mass including wheels (and axles for a solid axle).
  double total_mass(SuspensionTopology t) const {
    return chassis_mass + 4 * wheel_mass +
           (t == SuspensionTopology::SolidAxle ? 2 * axle_mass : 0.0);
  }
};

/// The run parameters of the sensors, declared in `table` with their study values unless declared
/// already: sensors.NAME.x_m, .y_m, .z_m (a chassis sensor's position, within ±10 m) and
/// sensors.NAME.offset (a constant added to the channel, in its unit; 0). They change no force,
/// only what the sensor reads, so a calibration or a diagnosis can find a position or an offset
/// nobody measured.
void declareSensorParameters(ParameterTable& table, const std::vector<SensorSpec>& sensors);

/// InputError(where, ...) when the chassis roll, pitch and yaw inertias of `table` (all three set
/// and positive) break the triangle inequality: no rigid body has them. The vehicle file's reader
/// (io/vehicle_file.hpp) checks the file's values with it.
void checkChassisInertias(const ParameterTable& table, const std::string& where);
/// The yaw inertia a run uses: `izz` clamped into [|ixx - iyy|, ixx + iyy], the values for which
/// the three satisfy the triangle inequality. Yaw is not a degree of freedom of the model, so a
/// freed roll or pitch inertia may range over its whole prior and the yaw inertia follows it;
/// the vehicle file's own three are kept as they are (they satisfy the inequality).
double yawInertiaInTriangle(double ixx, double iyy, double izz);

/// The range a value of a road vehicle can physically take, from a small car to a light truck:
/// how far a calibration's range may be widened when the data push a value against its bound
/// (docs/calibration.md, "Values on their bounds"). `basis` says where the numbers come from.
struct PhysicalLimit {
  double lower = 0.0, upper = 0.0;
  std::string basis;
};
/// The physical limit of the value `name` (a calibrated tire or strut value, a mass, an
/// inertia, the CG, a sensor's position, the road signal's gain or delay), read against
/// `table` where it depends on the vehicle (the CG between the axles); nullopt when none is known
/// (effects' parameters: their prior range is the plausible range).
std::optional<PhysicalLimit> physicalLimit(const std::string& name, const ParameterTable& table);

/// Room for one law's parameters scaled at a corner (scaledLawValues).
using LawValueBuffer = std::array<double, 32>;

class Model {
 public:
  /// Validates the options and that every parameter this assembly needs has a value.
  /// `where` names the source (study file) for error messages.
  /// `sensors` (the study's [sensors], validated there) add output channels to every run;
  /// `catalog` (the study's) makes the assembly's effects.
  Model(AssemblySpec assembly, ParameterTable table, const std::string& where,
        std::vector<SensorSpec> sensors = {},
        std::shared_ptr<const EffectCatalog> catalog = std::make_shared<const EffectCatalog>());

  const AssemblySpec& assembly() const { return assembly_; }
  const ParameterTable& table() const { return table_; }
  const VehicleData& vehicle() const { return vehicle_; }
  SuspensionTopology topology() const { return topology_; }
  const TireLaw& tire() const { return *tire_; }
  /// The main struts' law (the study's `strut` option; the first registered law by default).
  const StrutLaw& strut() const { return *strut_; }
  /// The solid axle's wheel/axle interface law (paper eq. 5): always linear, fixed data.
  const StrutLaw& interfaceLaw() const { return interface_law_; }
  const std::vector<std::shared_ptr<const Effect>>& effects() const { return effects_; }
  const std::vector<SensorSpec>& sensors() const { return sensors_; }

  /// Names of the per-run parameters (the run vector's layout).
  const std::vector<std::string>& runParameterNames() const { return run_names_; }
  /// Slot of a run parameter, or -1 if `name` is not a run parameter of this model.
  int slot(const std::string& name) const;
  /// True when `name` is a shared parameter of a tire option ("tire.stiffness") that this
  /// assembly's tire option does not have (the hub input has no tire compliance): a study's
  /// calibrated value of the other options, left out of this assembly's calibration.
  bool lacksOptionParameter(const std::string& name) const;
  /// The run vector filled from the table's values.
  std::vector<double> defaultRunValues() const;
  /// Checks a run vector (ranges, law combinations). Returns "" or "<name> <rule>".
  std::string checkRunValues(const std::vector<double>& v) const;

  // Slot layouts of the elements (indices into the run vector).
  const std::vector<int>& tireSlots() const { return tire_slots_; }
  const std::vector<int>& suspensionSlots() const { return susp_slots_; }
  const std::vector<int>& interfaceSlots() const { return iface_slots_; }
  int interfacePreloadSlot() const { return iface_preload_slot_; }
  const std::vector<std::vector<int>>& effectSlots() const { return effect_slots_; }
  /// Each installed effect's corner (0-3, kEffectCorners) when installed at one ("bump_stop@rr"),
  /// -1 when it acts at every corner.
  const std::vector<int>& effectCorners() const { return effect_corners_; }
  /// Whether effect i acts at `corner`.
  bool effectActsAt(std::size_t i, int corner) const {
    return effect_corners_[i] < 0 || effect_corners_[i] == corner;
  }

  /// Per sensor (sensors() order): the run slots of its chassis position x, y, z (-1 for a wheel
  /// or travel sensor) and of its offset, the sensors' run parameters
  /// (declareSensorParameters): calibrated or freed like any run parameter, read by the output.
  struct SensorSlots {
    int x = -1, y = -1, z = -1, offset = -1;
  };
  const std::vector<SensorSlots>& sensorSlots() const { return sensor_slots_; }

  /// Run slots of the road signal's gain `road.gain` [1] (1: as logged) and its delay relative
  /// to the measured channels `road.delay_s` [s] (0; positive: the signal was logged late). Run
  /// parameters of every model: a calibration or a diagnosis may find them (docs/model.md).
  int roadGainSlot() const { return road_gain_slot_; }
  int roadDelaySlot() const { return road_delay_slot_; }
  /// The run slot of roadSignalForms()[0]; the others follow in their order.
  int roadFormSlot() const { return road_form_slot_; }

  /// A law parameter scaled at one corner: its index in the law's parameters() and the run slot
  /// of a factor on it (docs/model.md, "Per-corner and per-axle values").
  struct ScaledParameter {
    std::size_t index = 0;
    int slot = -1;
  };
  /// Per corner (Corner order): the factors on its main strut's and its tire's law parameters
  /// that are run parameters, the axle's before the corner's; empty (the common case) when none
  /// is, and then the force elements multiply by nothing.
  const std::array<std::vector<ScaledParameter>, 4>& strutFactors() const { return strut_factors_; }
  const std::array<std::vector<ScaledParameter>, 4>& tireFactors() const { return tire_factors_; }
  /// A law's `n` parameters at p + p0 as one corner uses them: the run vector itself when
  /// `factors` is empty (nothing multiplied), else a copy in `buf` with each factor applied.
  static ParamValues scaledLawValues(const double* p, std::size_t p0, std::size_t n,
                                     const std::vector<ScaledParameter>& factors,
                                     LawValueBuffer& buf);

  /// Run slots of the freed vehicle values (AssemblySpec::freed), in that order.
  const std::vector<int>& freedSlots() const { return freed_slots_; }
  /// True when `values` (a run vector) holds this model's own freed vehicle values (always true
  /// without freed values): a system built from this model runs them.
  bool builtFor(const std::vector<double>& values) const;
  /// This model with the freed vehicle values of `values` written into its table (the same run
  /// layout): what a run of `values` must be built from. InputError for a value outside its
  /// valid range.
  std::shared_ptr<const Model> withFreedValues(const std::vector<double>& values) const;

  /// Static tire load [N] and main-strut static force [N] per corner (from masses and geometry).
  double staticTireLoad(int corner) const;
  double staticStrutForce(int corner) const;

 private:
  int addRunParameter(const std::string& name);
  void addCornerFactors();

  AssemblySpec assembly_;
  ParameterTable table_;
  VehicleData vehicle_;
  SuspensionTopology topology_;
  std::unique_ptr<TireLaw> tire_;
  std::unique_ptr<StrutLaw> strut_;
  LinearStrut interface_law_;
  std::vector<std::shared_ptr<const Effect>> effects_;
  std::vector<SensorSpec> sensors_;
  std::shared_ptr<const EffectCatalog> catalog_;
  std::vector<std::string> run_names_;
  std::map<std::string, int> slots_;
  std::vector<int> tire_slots_, susp_slots_, iface_slots_;
  int iface_preload_slot_ = -1;
  int road_gain_slot_ = -1, road_delay_slot_ = -1, road_form_slot_ = -1;
  std::vector<std::vector<int>> effect_slots_;
  std::vector<int> effect_corners_;
  std::vector<int> freed_slots_;
  std::array<std::vector<ScaledParameter>, 4> strut_factors_, tire_factors_;
  std::vector<SensorSlots> sensor_slots_;
  std::string where_;
};

}  // namespace dtwin
