#pragma once
// A linear data-driven baseline (docs/diagnosis.md, "Prediction on a drive it was not fitted to"):
// does the physics earn its keep? A system-identification user judges a model on a drive it was
// not fitted to, against the simplest model the data alone give: an FIR filter from the road
// under the four wheels to the channel,
//
//     y(t) ≈ b + Σ_c Σ_{j=0}^{L−1} h_{c,j} u_c(t − j Δ),
//
// fitted by least squares on the calibration drive and scored on the other, by the same fit
// percentage as the model (compare.hpp SeriesComparison::fit_percent).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/measurement.hpp"
#include "twin/model.hpp"
#include "twin/scenario.hpp"

namespace dtwin::diag {

/// The road height under each wheel (fl, fr, rl, rr) against time, on a uniform grid of step dt_s
/// from 0: the front wheels at the distance driven, the rear ones a wheelbase behind.
struct RoadInput {
  double dt_s = 0.01;
  std::array<std::vector<double>, 4> u;
  /// u_c(t), linear between grid points; before 0 the start's value, after the end the last.
  double at(int corner, double t) const;
};

/// The road input of scenario `sc` (its road built for `vehicle` with `seed`) up to `duration_s`.
RoadInput roadInput(const ScenarioSpec& sc, const VehicleData& vehicle, std::uint64_t seed, double dt_s, double duration_s);

struct FirBaseline {
  std::string channel;
  double dt_s = 0.02;   ///< tap spacing Δ
  int taps = 50;        ///< L per wheel (memory L Δ)
  std::vector<double> coef;  ///< b, then h_{c,j} wheel by wheel
  long training_records = 0;
  double predict(const RoadInput& in, double t) const;
  /// "FIR 4 x 50 taps at 0.02 s from the road under the wheels, least squares on N records"
  std::string describe() const;
};

/// The baseline of `channel` fitted by least squares (a ridge of 1e-9 of the normal matrix's mean
/// diagonal, for a road that does not excite every lag) on every record of `channel` in each
/// `train` data set, read with its road input. Throws InputError when the data hold fewer records
/// of the channel than coefficients.
FirBaseline fitFirBaseline(const std::string& channel, const std::vector<const LabData*>& train, const std::vector<const RoadInput*>& inputs,
                           double dt_s = 0.02, int taps = 50);

/// The fit percentage (100 (1 − ‖y − ŷ‖ / ‖y − mean y‖)) of `baseline` on every record of its
/// channel in `data`; NaN when `data` holds none.
double firFitPercent(const FirBaseline& baseline, const LabData& data, const RoadInput& input);

}  // namespace dtwin::diag
