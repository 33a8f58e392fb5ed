#pragma once
// What `twin diagnose` can propose (docs/diagnosis.md, "Candidates"). Six kinds, all confirmed
// and applied the same way:
//   effect     a force element of the catalogue (subsystems/effect.hpp), built in or user-defined:
//              "bump_stop", "my_damper"
//   parameter  a fixed vehicle value freed with a prior range of ±50 % about the vehicle file's
//              value (twin/model.hpp freeableVehicleParameters): "free:wheel.mass_kg"; or, when
//              named, any fixed value of the assembly's laws: "free:tire.unloaded_radius_m"
//   sensor     a model of how the logger distorted a group of channels (subsystems/sensor.hpp
//              sensorModelKinds): "lowpass:hub_force" (every fitted channel hub_force_*_N)
//   input      the road signal's gain or its delay relative to the measured channels (run
//              parameters of every model): "free:road.gain", "free:road.delay_s"
//   range      a calibrated value's range widened to its physical limit (twin/model.hpp
//              physicalLimit), when the data push it against a bound: "widen:chassis.mass_kg"
//   option     another option of a subsystem, a structure rather than a force: "tire=hub" (the road
//              signal is the hub's motion, not the road under a tire)
//   place      where a chassis sensor acts, when the study does not declare its position measured
//              (SensorSpec::position_sd_m): "free:sensors.seat.x_m", searched to its physical limit
// The input kind also holds the road signal's place (twin/model.hpp roadSignalForms):
// "free:road.fl_only" moves the signal from under both axles to the front-left wheel alone.
// The first four have diagnosed parameters with an "off" value (the nested base model) and a
// prior range, screened by a score test at the base optimum. A range candidate is screened by the
// score of its value beyond the bound; an option is not nested and is always confirmed. Each
// installs itself into a calibration setup.
#include <limits>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"
#include "subsystems/effect.hpp"
#include "subsystems/effect_catalog.hpp"

namespace dtwin::diag {

struct CandidateSpec {
  std::string name;  ///< as the user writes it (--effects, --apply)
  std::string kind;  ///< "effect" | "parameter" | "sensor" | "input" | "range" | "option" | "place"
  /// The diagnosed parameters (effects: the non-shape ones): default_value is the off value;
  /// prior_lower/upper the range a calibration searches. A range candidate: the widened value,
  /// prior_lower/upper its widened range, default_value unused (it is calibrated already, not
  /// added). An option: none.
  std::vector<ParameterSpec> parameters;
  /// Whether the candidate adds its parameters to the calibrated θ (not a range or an option).
  bool addsParameters() const { return kind != "range" && kind != "option"; }
  /// option: the subsystem options it replaces ((subsystem, option)).
  std::vector<std::pair<std::string, std::string>> options;
  /// range: the study's bounds of the value (the widened ones are parameters[0]'s prior range).
  double study_lower = 0.0, study_upper = 0.0;
  std::vector<std::string> calibrated_names;  ///< each parameter's name in a calibration
                                              ///< ("bump_stop.gap_m", "wheel.mass_kg")
  std::string signature;                      ///< the expected residual, in words (with range_note)
  /// parameter: how its search range was clipped to the value's valid set (a mass stays
  /// positive, the CG between the axles), in words; "" when the range was not clipped.
  std::string range_note;
  ResidualSignature residual_signature;  ///< effects only
  std::string engagement_threshold;      ///< effects only (Effect::engagementThreshold)
  std::string sensor_kind;               ///< sensors: lowpass | lowpass2 | gain | delay
  std::vector<std::string> channels;     ///< sensors: the channels distorted
  /// parameter: a fixed value of the assembly's laws, a run parameter already (calibrated
  /// without AssemblySpec::freed and without a rebuild); false for a freeable vehicle value.
  bool law_value = false;
  /// parameter: a per-corner or per-axle factor whose value the study calibrates as a whole, so
  /// the factor reads as a ratio to the other corners (or, on an axle, to the other axle) rather
  /// than to the vehicle file's value.
  bool relative = false;
  /// place: the CG to the front and the rear axle and the track width [m], for the finding's words.
  std::vector<double> geometry;
  /// Adds this candidate (installed, its diagnosed parameters calibrated over their prior range).
  void install(calib::CalibrationSetup& setup) const;
  /// The finding in plain words at calibrated `values` (one per parameter): "the wheel mass is
  /// about 35.3 kg, not 29.46 kg"; "the hub_force channels look filtered at about 25 Hz". A
  /// factor's finding names its place and, given the first value's 95 % interval
  /// (`lower`, `upper`, finite), says it: "the rear-right damper gives about 55 % of the damping of
  /// the other three (95 %: 51 % to 59 %)".
  std::string finding(const std::vector<double>& values,
                      double lower = std::numeric_limits<double>::quiet_NaN(),
                      double upper = std::numeric_limits<double>::quiet_NaN()) const;
};

/// The sensor-model groups of `channels`: channels of one unit suffix ("_N", "_mps2") share a
/// group, named by their longest common prefix up to an underscore ("hub_force" for
/// hub_force_fl_N ... hub_force_rr_N); a lone channel is named by itself without its unit.
std::vector<std::pair<std::string, std::vector<std::string>>> channelGroups(
    const std::vector<std::string>& channels);

/// The candidate `name` for `assembly` of `study` on data with the fitted `channels`.
/// InputError(where, rule) for an unknown effect, a value that cannot be freed, an unknown sensor
/// model or a channel group not in the data (each names what is known).
CandidateSpec candidateSpec(const std::string& name, const Study& study,
                            const AssemblySpec& assembly, const std::vector<std::string>& channels,
                            const std::string& where);

/// Every candidate of the default catalogue: each effect of the study's catalogue, each freeable
/// vehicle value the assembly has, the per-corner and per-axle factors (cornerCandidates), and
/// each sensor model on each channel group, the place of each sensor whose position is not declared
/// measured (sensorPlaceCandidates); when `measured_road` (a data set's road is a measured
/// signal, RoadSetting::measured), the road signal's gain, delay and place (each form of
/// roadSignalForms the study leaves at 0) and, unless the assembly has it, the hub input
/// (tire=hub). With `each_wheel` (every data set's road is each wheel's own measured motion, a
/// four-corner road) the signal's places are known and left out: only its gain and delay stay.
std::vector<std::string> defaultCandidates(const Study& study, const AssemblySpec& assembly,
                                           const std::vector<std::string>& channels,
                                           bool measured_road = false, bool each_wheel = false);

/// The sensor-place candidates of the default catalogue: "free:sensors.NAME.x_m" and ".y_m" for
/// each chassis sensor whose channel is in `channels`, whose position the study does not declare
/// measured and does not calibrate.
std::vector<std::string> sensorPlaceCandidates(const Study& study,
                                               const std::vector<std::string>& channels);

/// The per-corner and per-axle candidates of the default catalogue: the factors
/// ("free:suspension.damping@rr"), for each value with factors that the assembly's laws have, its
/// four corners and its axles; and each effect that wears at one strut
/// (Effect::screenedAtEachCorner) at each corner ("bump_stop@rr"). When the study calibrates a
/// value as a whole, its front and rear factors are one model (the overall value times f on the
/// front axle fits as well as the overall value times f on both and 1/f on the rear): only the
/// front one is a candidate, read as the ratio between the axles.
std::vector<std::string> cornerCandidates(const Study& study, const AssemblySpec& assembly);

/// A factor's place and part in words: "the rear-right damper", "both rear dampers", "the
/// front-left tire", "both front springs" (the first value of `name`, a factor name without
/// "free:").
std::string factorPlaceInWords(const std::string& factor);

/// True when `name` has the form of a candidate ("free:<value>", "widen:<value>",
/// "<subsystem>=<option>", "<sensor model>:<group>" or a non-empty effect name): the options'
/// check before the study and the data are known.
bool hasCandidateForm(const std::string& name);
/// hasCandidateForm, and an effect's name is one of `catalog`'s.
bool isCandidateName(const std::string& name, const EffectCatalog& catalog);

}  // namespace dtwin::diag
