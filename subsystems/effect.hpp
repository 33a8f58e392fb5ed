#pragma once
// Optional physical effects: force elements that can be added to any assembly. Each has named
// parameters with units, an "off" value (its ParameterSpec::default_value) at which it exerts no
// force, and a signature: the trace it leaves in a residual. This catalogue is what the
// diagnosis ranks.
#include <memory>
#include <string>
#include <vector>

#include "subsystems/parameter.hpp"
#include "subsystems/road.hpp"
#include "subsystems/strut_law.hpp"

namespace dtwin {

enum class EffectKind {
  Strut,      ///< adds a force along every suspension strut (chassis side), from q and dq/dt
  TireInput,  ///< modifies the road the tire sees (effective road)
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  /// What the effect leaves in a residual, in words (used by reports and the diagnosis).
  virtual std::string signature() const = 0;
  virtual EffectKind kind() const = 0;
  virtual const std::vector<ParameterSpec>& parameters() const = 0;
  /// Strut effects: extra strut force [N] (same sign convention as StrutState).
  virtual double calcStrutForce(const StrutState& s, ParamValues p) const { return 0.0; }
  /// TireInput effects: the effective road under the contact point.
  virtual RoadSample filterRoad(const Road& road, Track t, double x, ParamValues p) const {
    return road.sample(t, x);
  }
};

/// Suspension bump stop: F = k (q - gap)^n for q > gap (compression beyond the gap), else 0.
/// Off: k = 0. Signature: a knee in force vs deflection beyond the gap; peaks clipped on bumps.
class BumpStopEffect final : public Effect {
 public:
  BumpStopEffect();
  std::string name() const override { return "bump_stop"; }
  std::string description() const override { return "progressive rubber bump stop in compression"; }
  std::string signature() const override {
    return "residual grows like a knee in force vs suspension deflection beyond the gap; only at large compression (bump peaks)";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Damper asymmetry: rebound (extension, dq/dt < 0) damping is ratio times the compression
/// damping c: extra force (ratio - 1) c dq/dt for dq/dt < 0. Off: ratio = 1.
/// Signature: different slopes of force vs deflection rate either side of zero rate.
class DamperAsymmetryEffect final : public Effect {
 public:
  DamperAsymmetryEffect();
  std::string name() const override { return "damper_asymmetry"; }
  std::string description() const override { return "rebound/compression damping ratio"; }
  std::string signature() const override {
    return "residual linear in deflection rate on the rebound side only (slope change at zero rate)";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Strut Coulomb friction, smoothed: F = F_c tanh(dq/dt / v_s). Off: F_c = 0.
/// Signature: a step in force vs deflection rate at zero rate; damps small motions most.
class StrutFrictionEffect final : public Effect {
 public:
  StrutFrictionEffect();
  std::string name() const override { return "strut_friction"; }
  std::string description() const override { return "Coulomb friction in the strut, tanh-smoothed"; }
  std::string signature() const override {
    return "residual is a step in force vs deflection rate at zero rate; strongest on small, slow motions";
  }
  EffectKind kind() const override { return EffectKind::Strut; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  double calcStrutForce(const StrutState& s, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Tire enveloping of short obstacles: the tire sees the moving average of the road over a
/// base length L centred on the contact point (a first-order stand-in for the tandem-cam
/// effective road; Zegelaar 1998). Off: L = 0 (single-point contact).
/// Signature: on short obstacles the measured force is lower and longer than the point-contact
/// model's spike; concentrated at high frequency (> 20 Hz) around obstacles.
class TireEnvelopingEffect final : public Effect {
 public:
  TireEnvelopingEffect();
  std::string name() const override { return "tire_enveloping"; }
  std::string description() const override { return "effective road: moving average over the contact length"; }
  std::string signature() const override {
    return "at short obstacles the measured peak is lower and wider than the model's; residual > 20 Hz near obstacles";
  }
  EffectKind kind() const override { return EffectKind::TireInput; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  RoadSample filterRoad(const Road& road, Track t, double x, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

/// Factory keyed by name. Throws InputError listing the known names.
std::unique_ptr<Effect> makeEffect(const std::string& name, const std::string& where);
std::vector<std::string> effectNames();

}  // namespace dtwin
