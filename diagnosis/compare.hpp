#pragma once
// The model against measurements (`twin compare`, docs/diagnosis.md): the posterior predictive
// mean and 95 % band per channel, error figures, and where the model fails — in time (windows
// where the standardised residual leaves the band, labelled with what the vehicle was doing), in
// frequency (Welch PSD of the residual per band against the noise floor, coherence with the road)
// and in state (residual binned against suspension deflection and rate, tire deflection, speed,
// left-right deflection difference; signature fits on those force-state maps).
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/calibrate.hpp"
#include "diagnosis/discrepancy.hpp"
#include "diagnosis/frequency_response.hpp"
#include "diagnosis/measurements.hpp"
#include "diagnosis/signal.hpp"
#include "io/work.hpp"

namespace dtwin::diag {

/// A window of large standardised residual with what the vehicle was doing.
struct LabelledWindow {
  Window window;
  std::string label;     ///< e.g. "front wheels on the bump", "rough road"
  double speed_mps = 0;  ///< at the window's middle
};

/// One state map of one channel: the residual binned against a state of the model.
struct StateMap {
  std::string state;  ///< e.g. "susp_defl_fl_m", "roll_defl_front_m" (left − right)
  std::vector<Bin> bins;
  std::vector<SignatureFit> fits;  ///< best first
};

/// One (data set, channel).
struct SeriesComparison {
  std::string data_set, scenario, channel, unit;
  bool fitted = false;          ///< has a noise estimate (weighed in the lack-of-fit test)
  double noise_variance = 0.0;  ///< per measured value [unit²]
  long noise_dof = 0;           ///< of its estimate (0: known, from the study)
  std::string noise_source;
  std::vector<double> t;                 ///< distinct times, ascending
  std::vector<int> repetitions;          ///< values at each time
  std::vector<double> measured_mean;     ///< mean over repetitions
  std::vector<double> predicted_mean;    ///< mean over the posterior draws
  std::vector<double> band_lo, band_hi;  ///< 95 % posterior predictive band (draw spread + noise)
  std::vector<double> z;  ///< (measured mean − predicted mean) / its standard deviation
  // Error figures over every measured value (each repetition):
  double rms = 0, nrmse = 0, max_abs = 0, max_at_s = 0, coverage = 0;
  /// The fit percentage of system identification (MATLAB's `compare`): 100 (1 − ‖y − ŷ‖ / ‖y −
  /// mean y‖) over every measured value; 100: exact, 0: no better than the mean, < 0: worse.
  double fit_percent = 0;
  /// The same figure for the FIR baseline fitted on other data (twin compare --baseline), NaN
  /// when none was asked for.
  double baseline_fit_percent = std::numeric_limits<double>::quiet_NaN();
  /// The filter from the road to the residual fitted on other data and the hybrid's fit (twin
  /// compare --discrepancy, diagnosis/discrepancy.hpp); empty when none was asked for.
  std::optional<SeriesDiscrepancy> discrepancy;
  /// RMS of the systematic part: sqrt(max(0, mean_t (ȳ_t − η_t)² − mean_t σ²/R_t)).
  double systematic_rms = 0;
  double lack_of_fit = 0;  ///< Σ_t R_t (ȳ_t − η_t)² / σ² (fitted series)
  /// Where in time (fitted series; rankWindows): the listed windows, largest share of Σ z² first,
  /// every window found (chronological, for compare.json), their counts, and the counts in words.
  std::vector<LabelledWindow> windows;
  std::vector<Window> all_windows;
  WindowSummary window_summary;
  std::string windows_note;
  /// Where in frequency: empty when there are too few times, no noise estimate, or the rate
  /// changes (uniformGrid); bands_note says why, or what the spectrum was made of.
  std::vector<BandReport> bands;
  std::string bands_note;
  /// The frequency response from the road under the channel's wheel (the front-left road for a
  /// chassis channel) to the measured and to the predicted values (seriesResponse).
  SeriesResponse frequency_response;
};

/// The force-state maps of one channel, pooled over every data set that measured it.
struct ChannelMaps {
  std::string channel;
  std::vector<StateMap> maps;
};

struct Comparison {
  std::vector<SeriesComparison> series;
  std::vector<ChannelMaps> maps;
  long draws = 0, failures = 0;
  /// Lack-of-fit test over the fitted series: X = Σ lack_of_fit, k = points − parameters. The
  /// σ_c² are estimated from repetitions, so X/k is compared with F(k, d2), d2 the effective
  /// noise dof (χ²_k/k when every σ² is known); z is Paulson's normal deviate, p = 1 − Φ(z).
  double lack_of_fit = 0, lack_of_fit_z = 0, lack_of_fit_p = 1;
  long lack_of_fit_dof = 0;
  double noise_dof_effective = 0;
  /// sqrt(max(0, X − dof) / points): the systematic residual in noise standard deviations.
  double systematic_rms_sd = 0;
  std::vector<std::string> notes;
  nlohmann::json toJson(bool with_series_data = false) const;
};

struct CompareOptions {
  int threads = 0;
  double window_threshold = 4.0;  ///< |z| that opens a window
  double window_merge_s = 0.05, window_min_s = 0.0;
  /// Many windows (rankWindows): merged until at most window_max_merged remain; the fewest of the
  /// largest holding window_listed_share of their share are listed, at most window_max_listed.
  int window_max_merged = 200, window_max_listed = 20;
  double window_listed_share = 0.8;
  int state_bins = 12;
  /// Parameters absorbed by the fit (for the lack-of-fit dof).
  int fitted_parameters = 0;
  /// Throws InputError("compare.<field>", rule) for a field out of range (common/validate.hpp).
  /// compareModel() calls it.
  void validate() const;
};

/// Compares `objective`'s assembly at the posterior `draws` (θ rows in objective.names() order;
/// at least one) with the measurements `sets` (the data sets the objective was built from, same
/// order). The states for the maps and the road input come from the run at the draws' mean. `noise`
/// (estimateChannelNoise) gives σ² per channel; channels absent from it are compared with σ² = 0
/// (not fitted). Throws InputError for bad options (options.validate()) or no draws.
Comparison compareModel(const calib::LabObjective& objective,
                        const std::vector<calib::DataSet>& sets,
                        const std::vector<std::vector<double>>& draws,
                        const std::map<std::string, ChannelNoise>& noise,
                        const CompareOptions& options = {});

/// The work of compareModel() (io/work.hpp): `draws` posterior rows (plus the run at their
/// mean) over every data set, each simulated up to its last record.
StageWork estimateCompareWork(const std::vector<calib::DataSet>& sets, std::size_t draws);

/// The windows of a fitted series (sc.t, sc.z) ranked by their share of the residual and merged
/// when many (rankWindows with the options' window settings): sets sc.windows (the listed ones,
/// each described by `describe`, which gives its label and speed), sc.all_windows,
/// sc.window_summary and sc.windows_note. compareModel calls it with the scenario's geometry.
void addWindows(SeriesComparison& sc, const CompareOptions& options,
                const std::function<LabelledWindow(const Window&)>& describe);

/// The windows' counts in words: "2033 windows over 98 % of the record: the model misses
/// throughout, not in a few places; merged to 187 (neighbours closer than 6.4 s), the 20 largest,
/// listed, hold 34 % of the residual"; "" when there is no window.
std::string windowsNote(const WindowSummary& summary);

/// The residual's spectrum per band of a series (sc.t, measured and predicted means,
/// repetitions, noise_variance, fitted) on the uniform grid of its times (uniformGrid: the
/// longest stretch between gaps, resampled when the clock jitters), with `road` (the road under
/// the channel's wheel at sc.t; empty: no coherence) as the coherence input: sets sc.bands and
/// sc.bands_note. Needs 64 times on the grid.
void addResidualBands(SeriesComparison& sc, const std::vector<double>& road);

/// What the vehicle is doing in [t0, t1] of a scenario (obstacle crossings of each axle, rough
/// section, smooth road), e.g. "front wheels on the bump".
std::string describeScenarioWindow(const ScenarioSpec& scenario, const VehicleData& vehicle,
                                   double t0, double t1);

/// Evenly spaced rows (at most `count`) of a posterior sample, reordered to `names`.
std::vector<std::vector<double>> posteriorRows(const std::vector<std::string>& sample_names,
                                               const std::vector<std::vector<double>>& rows,
                                               const std::vector<std::string>& names, int count,
                                               const std::string& where);

/// Plain-text table of a comparison's error figures (one line per series).
std::string comparisonTable(const Comparison& c);

}  // namespace dtwin::diag
