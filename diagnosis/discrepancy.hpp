#pragma once
// What the physics misses, as a filter (docs/diagnosis.md, "What the physics misses, as a
// filter"): when the best physical model leaves a residual that follows the road, a linear filter
// from the road under the wheels to the residual (measured − physics), fitted on the calibration
// drive, says what is missing as an engineer reads it (the car's response against the model's,
// band by band: gain and phase) and gives a hybrid prediction, physics + filter. The filter is an
// FIR of baseline.hpp's kind (fitFir: its input, wheels, taps and ridge, or no filter at all,
// chosen by two-fold cross-validation on the calibration drive alone), so it never predicts a
// drive worse than nothing did on the halves of the drive it was fitted to. A prediction aid, not
// physics: it names no cause and holds no parameter a calibration could check.
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "diagnosis/baseline.hpp"
#include "io/measurement.hpp"

namespace dtwin::diag {

struct DiscrepancyOptions {
  double dt_s = 0.02;  ///< the taps' spacing Δ
  std::vector<int> taps{5, 10, 25,
                        50};  ///< the road's orders cross-validated (memory L Δ: 0.1 to 1 s)
  /// Taps on the model's own prediction cross-validated: 0 (a filter of the road alone), 1 (a gain
  /// on the prediction), 10 (a short filter of it: the model's response reshaped, a resonance
  /// moved).
  std::vector<int> model_taps{0, 1, 10};
  /// Throws InputError("discrepancy.<field>", rule) for a field out of range.
  void validate() const;
};

/// The car (physics + filter) against the physics in one band of vehicleBands: the H1 estimate
/// R = 1 + Σ P_ŷd / Σ P_ŷŷ over the band's bins (ŷ the physics prediction, d the filter's output,
/// on the calibration drive): the complex gain from the model's response to the car's.
struct DiscrepancyBand {
  std::string band;
  double lo_hz = 0, hi_hz = 0;
  double gain = 1;         ///< |R|: 1.3 is 1.3 times the model's gain
  double phase_deg = 0;    ///< arg R: > 0 the car responds earlier than the model
  double lead_ms = 0;      ///< the phase as a time at the band's centre √(lo hi) (> 0 earlier)
  double model_share = 0;  ///< the band's share of the physics prediction's power
  double filter_ratio = 0;  ///< √(Σ P_dd / Σ P_ŷŷ): the filter's RMS in the band over the model's
  bool read =
      false;  ///< the model has power enough there (model_share ≥ 1 %) for R to mean something
  std::string words;  ///< e.g. "the car responds 40° earlier at 0.5–2 Hz than the model (64 ms),
                      ///< with 1.3 times its gain"
};

/// The discrepancy filter of one channel.
struct DiscrepancyFilter {
  std::string channel;
  FirBaseline
      fir;  ///< from the road to the residual; fir.none(): the cross-validation chose no filter
  /// The two-fold cross-validated residual sum of squares of no filter and of the form chosen.
  double cv_sse_none = std::numeric_limits<double>::quiet_NaN(),
         cv_sse_chosen = std::numeric_limits<double>::quiet_NaN();
  int candidates = 0;  ///< forms scored (no filter included)
  /// The car over the model per Welch bin (0 < f ≤ the Nyquist frequency, bins where the model
  /// has 0.1 % of its peak power), on the calibration drive: what compare.html draws.
  std::vector<double> freq_hz, gain, phase_deg;
  std::vector<DiscrepancyBand> bands;
  std::string response_note;  ///< where the response was estimated, or why there is none
  /// The bands in words and what would do that (e.g. "a feed-forward ... would").
  std::string summary;
  /// "FIR from the road's vertical velocity under the 2 front wheels, 10 taps at 0.02 s (memory 0.2
  /// s), ridge 1e-05: ..."
  std::string describe() const;
  nlohmann::json toJson() const;
};

/// One calibration drive as the discrepancy is fitted on it: the measurements, the physics
/// prediction at each record (same order as data->records; the prediction of records of other
/// channels is not read) and the road under the wheels.
struct DiscrepancyDrive {
  const LabData* data = nullptr;
  const std::vector<double>* physics = nullptr;
  const RoadInput* road = nullptr;
};

/// Fits the discrepancy of `channel` on the calibration drives: fitFir on the residual
/// (measured − physics) of every record of `channel`, among the options' taps, both inputs, every
/// distinct wheel or the front ones alone, baseline.hpp's ridges, and no filter; then the car's
/// response over the model's per band (DiscrepancyBand) on the drive with the most times of the
/// channel (a uniform grid of its distinct times, uniformGrid; Welch segments of up to 5 s).
/// Throws InputError when the drives hold fewer records of `channel` than the smallest form's
/// coefficients.
DiscrepancyFilter fitDiscrepancy(const std::string& channel,
                                 const std::vector<DiscrepancyDrive>& calibration,
                                 const DiscrepancyOptions& options = {});

/// The hybrid on one compared series (a drive the filter was not fitted to).
struct SeriesDiscrepancy {
  DiscrepancyFilter filter;
  /// 100 (1 − ‖y − ŷ − d‖ / ‖y − mean y‖) over every measured value, as
  /// SeriesComparison::fit_percent.
  double hybrid_fit_percent = std::numeric_limits<double>::quiet_NaN();
  /// The physics alone recomputed from the same records (equals SeriesComparison::fit_percent).
  double physics_fit_percent = std::numeric_limits<double>::quiet_NaN();
  /// RMS of the filter's output over RMS of the hybrid's prediction, each about its mean over the
  /// series' times (a hub force's weight does not hide the filter).
  double share = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> hybrid;  ///< the hybrid's prediction at the series' times
  /// The filter, the three fit percentages (the FIR baseline's NaN when none) and the share.
  nlohmann::json toJson(double baseline_fit_percent, bool with_series_data) const;
};

/// Scores `filter` on a series: its distinct times `t` (ascending) and the physics prediction
/// there (`physics`), the measured values the records of filter.channel in `data` (each
/// repetition), `road` the drive's road input.
SeriesDiscrepancy scoreDiscrepancy(const DiscrepancyFilter& filter, const std::vector<double>& t,
                                   const std::vector<double>& physics, const LabData& data,
                                   const RoadInput& road);

}  // namespace dtwin::diag
