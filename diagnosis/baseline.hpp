#pragma once
// A linear data-driven baseline (docs/diagnosis.md, "Prediction on a drive it was not fitted to"):
// does the physics earn its keep? A system-identification user judges a model on a drive it was
// not fitted to, against the simplest model the data alone give: an FIR filter from the road
// under the four wheels to the channel,
//
//     y(t) ≈ b + Σ_c Σ_{j=0}^{L−1} h_{c,j} u_c(t − j Δ),
//
// u_c the road's height under wheel c, or its vertical velocity (u_c(t) − u_c(t − Δ)) / Δ: an
// FIR on the velocity has no gain at zero frequency, so a road's slow drift (a logged signal's
// offset from drive to drive) does not become a prediction. fitFirBaseline chooses the input by
// a two-fold cross-validation on the training data alone (never on the drive it is scored on),
// fits it by least squares on the whole calibration drive, and it is scored on the other, by the
// same fit percentage as the model (compare.hpp SeriesComparison::fit_percent).
#include <array>
#include <cstdint>
#include <optional>
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
RoadInput roadInput(const ScenarioSpec& sc, const VehicleData& vehicle, std::uint64_t seed,
                    double dt_s, double duration_s);

enum class FirInput { Height, Velocity };

struct FirBaseline {
  std::string channel;
  double dt_s = 0.02;  ///< tap spacing Δ
  int taps = 50;       ///< L per wheel (memory L Δ)
  FirInput input = FirInput::Height;
  /// The wheels whose road enters (0 fl, 1 fr, 2 rl, 3 rr), in the order of the coefficients.
  std::vector<int> corners{0, 1, 2, 3};
  double ridge = 1e-9;  ///< λ: the normal matrix's diagonal raised by λ times its mean
  /// The two-fold cross-validated residual sum of squares of each candidate form on the training
  /// data (height and velocity, from every distinct wheel and from the front ones alone): the
  /// choice of `input` and `corners`. Empty when the input was given.
  std::vector<double> cv_sse;
  std::vector<double> coef;  ///< b, then h_{c,j} wheel by wheel, then g_j on the model's prediction
  long training_records = 0;
  /// No filter: the cross-validation chose to predict 0 (FirSearch::allow_none); taps 0, no wheels,
  /// coef {0}.
  bool none() const { return taps == 0; }
  /// Taps on the model's own prediction after the road's (a discrepancy filter, discrepancy.hpp;
  /// 0 for the baseline): predict() then needs `model`, the prediction as u[0] against time.
  int model_taps = 0;
  double predict(const RoadInput& in, double t, const RoadInput* model = nullptr) const;
  /// "FIR from the road's vertical velocity under the 4 wheels, 50 taps each at 0.02 s, least
  /// squares on N records (the input chosen by two-fold cross-validation on them)"
  std::string describe() const;
};

/// The forms an FIR is chosen among (fitFir): every combination of taps, input, wheels and ridge
/// is scored by two-fold cross-validation on the training data, and the best is fitted on all of
/// it.
struct FirSearch {
  std::vector<int> taps{50};  ///< L per wheel (a form's memory L Δ)
  std::vector<FirInput> inputs{FirInput::Height, FirInput::Velocity};
  bool front_only =
      true;  ///< also the front wheels alone (when the rear wheels' road differs from theirs)
  std::vector<double> ridges{1e-9, 1e-7, 1e-5, 1e-3, 1e-1};
  /// Taps on the model's prediction (fitFir's `models`), each count a candidate; {0}: none.
  std::vector<int> model_taps{0};
  /// "No filter" (a prediction of 0; FirBaseline::none()) is a candidate too, scored first: a
  /// form must predict the held halves better than nothing to be chosen.
  bool allow_none = false;
};

/// The FIR of `channel` on `train` (records, with their road inputs) among the forms of `search`,
/// chosen by two-fold cross-validation (each data set's records split at its middle time; each
/// half predicted by the FIR fitted on the other) and fitted by ridge least squares on every
/// record. Wheels whose road repeats another's exactly (one signal for both tracks) enter once.
/// When a half holds fewer records than a form's coefficients, that form is not scored; when none
/// can be, the first input and taps of the search from every distinct wheel with the smallest
/// ridge. Throws InputError when the data hold fewer records of the channel than the
/// coefficients of the form fitted.
/// `models` (needed when search.model_taps holds a count above 0): per training set, the model's
/// prediction as u[0] against time, whose taps enter after the road's.
FirBaseline fitFir(const std::string& channel, const std::vector<const LabData*>& train,
                   const std::vector<const RoadInput*>& inputs, double dt_s,
                   const FirSearch& search, const std::vector<const RoadInput*>& models = {});

/// The baseline of `channel` fitted by least squares (with a ridge, below) on every record of
/// `channel` in each `train` data set, read with its road input. Wheels whose road repeats
/// another's exactly (one signal for both tracks) enter once. `input` empty: the form whose
/// two-fold cross-validated error is lowest (each data set's records split at its middle time; each
/// half predicted by the FIR fitted on the other), among height and velocity, from every wheel and
/// from the front ones alone (the rear wheels' road is the front's, later: near-collinear taps),
/// and ridges λ from 1e-9 to 0.1 (a least-squares FIR has any gain in a band the training drive
/// leaves unexcited, and a faster drive excites it). `input` given: that input from every distinct
/// wheel, λ = 1e-9. Throws InputError when the data hold fewer records of the channel than
/// coefficients.
FirBaseline fitFirBaseline(const std::string& channel, const std::vector<const LabData*>& train,
                           const std::vector<const RoadInput*>& inputs, double dt_s = 0.02,
                           int taps = 50, std::optional<FirInput> input = std::nullopt);

/// The fit percentage (100 (1 − ‖y − ŷ‖ / ‖y − mean y‖)) of `baseline` on every record of its
/// channel in `data`; NaN when `data` holds none.
double firFitPercent(const FirBaseline& baseline, const LabData& data, const RoadInput& input);

}  // namespace dtwin::diag
