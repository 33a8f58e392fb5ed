#pragma once
// The `tire_enveloping` effect (docs/model.md, "Effects"; registered in subsystems/effect.cpp).
#include "subsystems/effect.hpp"

namespace dtwin {

/// Tire enveloping of short obstacles: the tire sees the moving average of the road over a
/// base length L centred on the contact point (a first-order stand-in for the tandem-cam
/// effective road; Zegelaar 1998). Off: L = 0 (single-point contact).
/// Signature: on short obstacles the measured force is lower and longer than the point-contact
/// model's spike; concentrated at high frequency (> 20 Hz) around obstacles.
class TireEnvelopingEffect final : public Effect {
 public:
  TireEnvelopingEffect();
  std::string name() const override { return "tire_enveloping"; }
  std::string description() const override {
    return "effective road: moving average over the contact length";
  }
  std::string signature() const override {
    return "at short obstacles the measured peak is lower and wider than the model's; residual > "
           "20 Hz near obstacles";
  }
  EffectKind kind() const override { return EffectKind::TireInput; }
  const std::vector<ParameterSpec>& parameters() const override { return specs_; }
  RoadSample filterRoad(const Road& road, Track t, double x, ParamValues p) const override;

 private:
  std::vector<ParameterSpec> specs_;
};

}  // namespace dtwin
