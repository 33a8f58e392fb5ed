// Private to diagnosis/ (not installed): what the stages of diagnose() share, the Diagnosis they
// read and extend, the base model's linearisation, the screening's probes, and each stage's entry
// (diagnose_screen.cpp, diagnose_confirm.cpp, diagnose_verdict.cpp, diagnose_apply.cpp).
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "calibration/calibrate.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "diagnosis/candidates.hpp"
#include "diagnosis/diagnose.hpp"

namespace dtwin::diag {

// ------------------------------------------------------------------ helpers (diagnose.cpp)
std::string fmt(const char* f, double v);
std::string joinEffects(const std::vector<std::string>& e);
std::string inWords(const std::string& effect);
nlohmann::json paramsJson(const std::vector<EffectParameter>& ps);
std::vector<double> offValues(const CandidateSpec& c);

// ------------------------------------------------------------------ Diagnosis
/// What the stages of one diagnosis share (docs/diagnosis.md, "twin diagnose"): the inputs, the
/// fitted data and their weights, the catalogue, every calibration's optimum and the result
/// being built. Each stage below reads and extends it.
struct Diagnosis {
  Diagnosis(const Study& s, const AssemblySpec& a, const DiagnoseOptions& o, std::string out,
            const DiagnoseProgress& p)
      : study(s), assembly(a), options(o), out_dir(std::move(out)), progress(p) {}
  const Study& study;
  const AssemblySpec& assembly;
  const DiagnoseOptions& options;
  const std::string out_dir;
  const DiagnoseProgress& progress;
  std::map<std::string, ChannelNoise> noise;  ///< per fitted channel
  std::map<std::string, double> weights;      ///< 1/σ_c² per fitted channel
  std::vector<calib::DataSet> fit_sets,
      hold_sets;                       ///< the fitted channels of the fit and held-out data
  std::string data_hash;               ///< of fit_sets: a calibration folder's identity
  std::vector<std::string> catalogue;  ///< the candidates ranked (no installed effect)
  std::map<std::string, CandidateSpec>
      specs;  ///< every candidate of the catalogue and of options.apply
  std::map<std::string, std::vector<double>>
      optima;  ///< every calibration's optimum, by joinEffects(effects)
  std::map<std::string, std::vector<std::string>>
      optima_names;  ///< ... and the names of its values
  /// The optimiser's extra starts of each calibration folder, fixed by its first call: a folder
  /// calibrated again (in full after its optimum, or from another stage) resumes the same
  /// calibration instead of meeting a different one.
  std::map<std::string, std::vector<std::vector<double>>> starts_of;
  std::unique_ptr<calib::LabObjective>
      base_obj;  ///< the current stage's reference model on fit_sets (screening, refinement)
  DiagnosisResult res;
  /// Forward stagewise (docs/diagnosis.md, "More than one cause"): the causes installed so far.
  /// Empty in the first stage, whose reference is the base; later stages screen and confirm on
  /// top of them, and their candidates are res.further.back().candidates.
  std::vector<std::string> installed;
  /// The current stage's reference model (res.base in the first stage).
  const Figures* reference = nullptr;

  /// The parameters of candidate `name` in the calibration `f` (which may hold other causes too;
  /// a widened range's value is the study's, among f.values).
  std::vector<EffectParameter> parametersOf(const std::string& name, const Figures& f) const {
    std::vector<EffectParameter> out;
    for (const auto& n : spec(name).calibrated_names)
      for (const auto& p : f.values)
        if (p.name == n) out.push_back(p);
    return out;
  }
  /// What `f` says of candidate `name`, in words (CandidateSpec::finding at its mean values).
  std::string findingOf(const std::string& name, const Figures& f) const {
    std::vector<double> values;
    const auto ps = parametersOf(name, f);
    values.reserve(ps.size());
    for (const auto& p : ps) values.push_back(p.mean);
    // The first value's printed interval, when it has one (a full calibration).
    const bool interval = !ps.empty() && ps[0].interval != "none";
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return spec(name).finding(values, interval ? ps[0].q025 : nan, interval ? ps[0].q975 : nan);
  }
  /// The candidates of the current stage.
  std::vector<Candidate>& stage() {
    return installed.empty() ? res.candidates : res.further.back().candidates;
  }
  /// `name` installed on top of the causes of the current stage.
  std::vector<std::string> withInstalled(const std::string& name) const {
    auto e = installed;
    e.push_back(name);
    return e;
  }

  /// Runs `step`; when it throws anything but bad input or a full disk (which end the run), gives
  /// the reason in one line to `on_failure` and returns false (docs/diagnosis.md, "When a
  /// candidate fails").
  template <class F, class G>
  static bool isolatedStep(F&& step, G&& on_failure) {
    try {
      step();
      return true;
    } catch (const InputError&) {
      throw;
    } catch (const StorageError&) {
      throw;
    } catch (const std::exception& e) {
      on_failure(oneLine(e.what()));
      return false;
    }
  }
  /// isolatedStep, recording "<what> failed: <reason>" in res.failures.
  template <class F>
  bool isolated(const std::string& what, F&& step) {
    return isolatedStep(step, [&](const std::string& reason) {
      res.failures.push_back(what + " failed: " + reason);
    });
  }

  void report(const std::string& stage, std::size_t done, std::size_t total) const {
    if (progress) progress(stage, done, total);
  }
  const CandidateSpec& spec(const std::string& name) const { return specs.at(name); }
  /// The calibration setup with `names` installed, weighted by `weights`.
  calib::CalibrationSetup setupOf(const std::vector<std::string>& names) const {
    std::vector<CandidateSpec> cs;
    cs.reserve(names.size());
    for (const auto& n : names) cs.push_back(spec(n));
    return candidatesSetup(cs, weights);
  }
  /// One calibration with `effects` installed (persisted under out_dir/calibrations, resumable),
  /// compared on the fit and held-out data. effect_start, theta_start: the screening's estimate of
  /// the effects' and the base parameters (extra optimiser starts); a base given theta_start is
  /// the refined base and has its own folder. full = false: the optimum alone
  /// (calib::calibrateOptimum), compared at the optimum; a later full call resumes from it.
  Figures calibrateWith(const std::vector<std::string>& effects, const std::string& stage,
                        const std::vector<double>& effect_start = {},
                        const std::vector<double>& theta_start = {}, bool full = true);

 private:
  /// The optimiser's extra starts of a calibration with `effects` (see calibrateWith).
  std::vector<std::vector<double>> extraStarts(const std::vector<std::string>& effects,
                                               const std::vector<double>& effect_start,
                                               const std::vector<double>& theta_start) const;
  /// The model calibrated with `setup` compared with the data at evenly spaced posterior rows of
  /// `r`.
  void compareFigures(Figures& f, const calib::CalibrationResult& r,
                      const calib::CalibrationSetup& setup, const std::string& stage) const;
};

// ------------------------------------------------------------------ screen (diagnose_screen.cpp)
/// The base model linearised at its optimum θ̂: the standardised residual r, the sensitivities
/// J = ∂η/∂θ (weighted, central differences) and J's QR (the span re-calibrating θ could absorb).
struct Linearisation {
  std::vector<double> theta_hat, eta_hat;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;  ///< ∂η/∂θ, weighted
  Eigen::HouseholderQR<Eigen::MatrixXd> qr;
  /// Per value of θ: +1 (−1) when it sits on its lower (upper) bound and the residual pushes it
  /// beyond (the unconstrained step Jₖᵀ r points out of the range): re-calibrating may move it
  /// back inside only, so it is not projected out like the free values; 0 otherwise.
  std::vector<int> held;
  Eigen::MatrixXd Q;  ///< orthonormal basis of the span of J's columns not held
  /// G with what re-calibrating the free values could absorb (span(Q)) projected out.
  Eigen::MatrixXd project(const Eigen::MatrixXd& G) const { return G - Q * (Q.transpose() * G); }
  /// G with the span of the free columns of J other than `k` projected out: what re-calibrating
  /// every free value but θ_k could absorb (the score of θ_k beyond its bound).
  Eigen::MatrixXd projectWithout(std::size_t k, const Eigen::MatrixXd& G) const;
  /// The score of a probe group whose contributions are `Gp` (project(G), or projectWithout(skip,
  /// G) for θ_skip's own probes): the weighted SSE the group removes, S = ‖r‖² − min ‖r − Gp c −
  /// H a‖² over c and over a ≥ 0, H the held values' columns (projected alike, signed inward),
  /// less what H alone removes. With no held value, S = rᵀ P_Gp r. `coef` receives the c of the
  /// minimum; `rank` the rank of Gp (the score's degrees of freedom).
  double score(const Eigen::MatrixXd& Gp, long skip, Eigen::VectorXd& coef, long& rank) const;
};

/// One probe of one effect: columns of its parameter vectors (one strength parameter moved per
/// column, at one level, the scanned shape-like parameters at one point), tested together.
struct ProbeGroup {
  std::size_t effect;                     ///< index into the catalogue
  std::vector<std::vector<double>> cols;  ///< parameter vectors, one per column
  /// A range candidate: the index in θ of the widened value, which each column's one value
  /// replaces (instead of parameters appended to θ); -1 otherwise.
  long theta_index = -1;
};

Linearisation linearise(const Diagnosis& d);
/// Fills lin.held and lin.Q from lin.J and lin.r, given which values sit on their lower or upper
/// bound (linearise() calls it; a test may on a hand-made J).
void setProjection(Linearisation& lin, const std::vector<bool>& at_lower,
                   const std::vector<bool>& at_upper);
std::vector<ProbeGroup> probesOf(std::size_t e, const CandidateSpec& candidate,
                                 double at = std::numeric_limits<double>::quiet_NaN(),
                                 long theta_index = -1);
void screen(Diagnosis& d);

// ------------------------------------------------------------------ confirm, refine, further
// causes (diagnose_confirm.cpp)
std::vector<std::size_t> confirm(Diagnosis& d);
void refine(Diagnosis& d, const std::vector<std::size_t>& to_confirm);
void furtherCauses(Diagnosis& d);
/// The other structures of the first stage weighed on top of a first cause that is one
/// (diagnose_confirm.cpp).
void structureFirst(Diagnosis& d, const std::vector<const Candidate*>& named);
std::string structureOf(const Candidate& c);

// ------------------------------------------------------------------ verdict (diagnose_verdict.cpp)
void explainStage(Diagnosis& d, const Comparison& ref);
std::vector<const Candidate*> strongOf(const std::vector<Candidate>& cands,
                                       const DiagnoseOptions& options);
std::vector<const Candidate*> alikeOf(const std::vector<const Candidate*>& named,
                                      const DiagnoseOptions& options);
Cause causeOf(const Candidate& c, const std::vector<const Candidate*>& alike);
void verdict(Diagnosis& d);

// ------------------------------------------------------------------ propose, apply
// (diagnose_apply.cpp)
void propose(Diagnosis& d);
void apply(Diagnosis& d);

/// The candidates a stage confirms, in order (docs/diagnosis.md, "Confirmation";
/// diagnose_confirm.cpp). `tried`: the indices a round before took (left out; the factor still
/// counts from the best score of all).
std::vector<std::size_t> chooseConfirmations(const std::vector<Candidate>& cands,
                                             const DiagnoseOptions& options,
                                             const std::set<std::size_t>& tried = {});

}  // namespace dtwin::diag
