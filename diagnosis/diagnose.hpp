#pragma once
// `twin diagnose` (docs/diagnosis.md): which physical effect of the catalogue (subsystems/
// effect.hpp) the assembly is missing, given measurements.
//
//  1. Calibrate the base assembly on the measurements (calib::calibrateAssembly, channels
//     weighted by 1/σ_c², σ_c² from the repetitions), compare it (compareModel).
//  2. Screen every effect cheaply: at the base optimum θ̂, the effect's contribution g at a few
//     probe values of its parameters, with the span of ∂η/∂θ projected out (what re-calibrating θ
//     could absorb), gives the score S = rᵀ P_{g⊥} r of the standardised residual r — χ² with
//     rank(g⊥) degrees of freedom when the effect is absent. Gate: an effect whose largest
//     plausible contribution is invisible in these data (e.g. the travel never reaches a
//     plausible bump-stop gap) is not a candidate.
//  3. Confirm the candidates whose screening score is within a factor of the best, and the best of
//     each kind, within a budget, by re-calibrating with the effect's parameters added (the
//     same machinery; bounds = the effect's prior range) and compare evidence by BIC:
//     BIC = SSE_w,min + k ln n (σ known: −2 ln L = SSE_w + const), log evidence ≈ −BIC/2.
//     The evidence needs the optimum alone: every candidate is first calibrated to its optimum,
//     then those within options.full_within of the best log evidence in full (intervals).
//  4. Verdict: "effect" (a confirmed effect with ΔBIC < −10 that leaves no significant lack of
//     fit, or explains most of the excess), "none" (no lack of fit and no candidate), or
//     "unexplained" (significant residual that no catalogue effect explains), with ambiguity
//     stated when two effects' evidence is within a factor e^3.
//  5. Apply (options.apply): effects added in turn, each re-calibrated; the before/after table
//     and waterfall.
// diagnose() runs these as named stages (diagnose.cpp; screen, confirm and refine, verdict, apply
// in diagnose_screen.cpp, diagnose_confirm.cpp, diagnose_verdict.cpp, diagnose_apply.cpp).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibration/calibrate.hpp"
#include "common/progress.hpp"
#include "diagnosis/candidates.hpp"
#include "diagnosis/compare.hpp"
#include "diagnosis/measurements.hpp"
#include "diagnosis/proposal.hpp"

namespace dtwin::diag {

struct DiagnoseOptions {
  calib::CalibrationOptions
      calibration;  ///< sizes of every calibration (base, candidates, applied)
  /// The work budget of the confirmation: at most this many screened candidates are re-calibrated.
  /// Within it, every candidate whose screening score is within a factor confirm_within of the
  /// best, then the best of each kind (effect, parameter, sensor) (docs/diagnosis.md,
  /// "Confirmation").
  int candidates = 6;
  double confirm_within =
      2.0;  ///< screening scores within this factor of the best are confirmed side by side
  /// Rounds of the budget per stage (docs/diagnosis.md, "Confirmation"): after a round, the next
  /// `candidates` of those within the factor are confirmed too, up to this many rounds, while no
  /// confirmed candidate leaves the residual at the noise (lack_of_fit_alpha).
  int confirm_rounds = 3;
  /// At most this many causes named by forward stagewise selection (docs/diagnosis.md, "More
  /// than one cause"); 1: the best candidate alone, as before.
  int causes = 3;
  double screen_alpha = 0.01;  ///< family-wise level of the screening (Bonferroni over every probe)
  double bic_strong =
      10.0;  ///< ΔBIC below −bic_strong names an effect (Kass & Raftery 1995: strong)
  double ambiguity_log_evidence = 3.0;  ///< two effects closer than this in log evidence: ambiguous
  /// Confirmed candidates whose log evidence at their optimum is within this (and at least within
  /// ambiguity_log_evidence) of the best confirmed one are calibrated in full (region, design,
  /// profile: their intervals and posterior comparison); the others, which cannot be the verdict
  /// nor ambiguous with it, stop at their optimum. Infinity: every confirmed candidate in full.
  double full_within = 10.0;
  double explained_min =
      0.8;  ///< share of the excess residual a named effect must explain when a lack of fit remains
  double lack_of_fit_alpha = 1e-3;  ///< level of the lack-of-fit test
  int compare_draws = 20;           ///< posterior rows per comparison
  std::vector<std::string>
      effects;  ///< the catalogue to rank (empty: every effect not already installed)
  std::vector<std::string>
      apply;        ///< effects added in turn after the verdict (`twin diagnose --apply`)
  int threads = 0;  ///< worker threads (0: all cores)
  const Distributed* processes =
      nullptr;  ///< the process context (common/distributed.hpp); nullptr: this process alone
  /// When the verdict is "unexplained": at most this many library terms proposed (proposal.hpp;
  /// 0: no proposal; at most 3, the exhaustive subset search's limit).
  int propose_terms = 3;
  std::string command;  ///< recorded in every calibration folder
  /// A seam for tests: when set, called before each step of a model's screening and confirmation
  /// with the model (its candidates joined by '+', as its calibration folder: "bump_stop",
  /// "tire=hub+skyhook") and the step ("screen", "optimum", "full", "compare"). What it throws
  /// fails that candidate as a failure of the step itself would (docs/diagnosis.md, "When a
  /// candidate fails"). Empty: nothing is called.
  std::function<void(const std::string& model, const std::string& step)> before_candidate_step;
  /// Throws InputError("diagnose.<field>", rule) for a field out of range, an unknown or repeated
  /// effect in effects or apply (common/validate.hpp); checks calibration too. diagnose() calls it.
  void validate() const;
};

/// Progress: stage text, done, total.
using DiagnoseProgress = StageProgress;  // common/progress.hpp

struct EffectParameter {
  std::string name, unit;
  double mean = 0, sd = 0, optimum = 0;
  double q025 = 0, q975 = 0;  ///< the 95 % interval printed (ci95: profile likelihood by default)
  double post_q025 = 0, post_q975 = 0;  ///< the posterior's central 95 % interval
  std::string interval = "profile";     ///< which interval q025/q975 are
};

/// Error figures of one calibrated model (a row of the before/after table).
struct Figures {
  std::string label;                 ///< "base", "+ bump_stop", ...
  std::vector<std::string> effects;  ///< effects installed and calibrated
  double sse_min = 0, bic = 0, log_evidence = 0;
  int parameters = 0;
  Comparison comparison;
  std::optional<Comparison> holdout;  ///< on the held-out data, when given
  std::string folder;                 ///< the calibration's folder
  std::vector<EffectParameter> effect_parameters;
  /// Every calibrated value of the model (the study's and the candidates'), in the calibration's
  /// order.
  std::vector<EffectParameter> values;
  /// The calibration's integrator check: !ok when the optimum and the intervals follow the
  /// integrator rather than the data (its message says what to tighten).
  calib::IntegratorCheck integrator;
  /// The design's importance ESS: below kResolvedEss the posterior's mean ± sd stand on a
  /// handful of design points and are not printed as figures (the optimum and the profile
  /// interval are).
  double importance_ess = 0;
  static constexpr double kResolvedEss = 10.0;
  /// Its values on their bounds and values the data do not determine (calibration/bounds.hpp).
  std::vector<calib::BoundFinding> bounds;
  /// The study's calibrated values this model lacks (another tire option): not calibrated.
  std::vector<std::string> left_out;
  /// false: the calibration stopped at its optimum (DiagnoseOptions::full_within): effect
  /// parameters carry the optimum only, the comparison is at the optimum, no integrator check ran.
  bool full = true;
  nlohmann::json toJson() const;
};

struct Candidate {
  std::string effect;  ///< the candidate's name (an effect, free:<value> or <sensor model>:<group>)
  std::string kind;  ///< "effect" | "parameter" | "sensor" | "input" | "place" | "range" | "option"
                     ///< (candidates.hpp)
  std::string signature;
  std::string finding;  ///< confirmed: what the calibrated candidate says, in words
                        ///< (CandidateSpec::finding)
  std::string gate;     ///< empty: passed the gate; else why it cannot matter here
  /// Empty: its screening and confirmation finished; else the step that failed and why, on one
  /// line ("its confirming calibration failed: ..."): an internal error or a simulation failure
  /// in this candidate alone, which the diagnosis reports and goes on without it.
  std::string failed;
  double score = 0;  ///< max over probes of rᵀ P r
  int score_dof = 1;
  double p_value = 1.0;   ///< Bonferroni-adjusted over every probe of every effect
  double max_signal = 0;  ///< largest ‖g⊥‖² over the probes (noise units)
  /// The screening's estimate of the effect's parameters (best probe, linearised amplitude):
  /// an extra optimiser start of the confirmation.
  std::vector<double> screening_estimate;
  /// ... and of the base parameters with it: θ̂ + J⁺ (r − G c) (the joint linearised fit).
  std::vector<double> screening_theta;
  bool confirmed = false;
  /// Confirmed with every parameter of its own at its off value: it adds nothing, so it is never
  /// named, whatever its ΔBIC (which then comes from the reference's optimum polished further).
  bool inert = false;
  std::optional<Figures> fit;  ///< the re-calibration with the effect (confirmed candidates)
  double evidence_gap = 0;  ///< confirmed: log evidence below the best confirmed candidate's (>= 0)
  double delta_bic = 0;     ///< BIC(with effect) − BIC(base)
  double explained = 0;     ///< share of the base's excess residual (χ² − dof) it removes
  std::optional<double> holdout_change;  ///< held-out systematic RMS after / before
  std::string why;                       ///< one plain sentence
};

/// A cause the verdict names (forward stagewise selection: each strong against the model with the
/// causes before it).
struct Cause {
  std::string name, kind, finding;  ///< finding: at the joint fit of every cause named
  double delta_bic = 0;             ///< against the model with the causes before it
  double explained = 0;  ///< its share of the base's excess residual (the drop at its step)
  std::vector<EffectParameter> parameters;  ///< in the joint fit of every cause named
  std::vector<std::string>
      ambiguous_with;  ///< candidates of its stage within ambiguity_log_evidence
  Figures fit;  ///< the model with it and every cause before it (its comparison: what remains)
};

/// A later stage of the stagewise selection: the causes installed and the candidates screened and
/// confirmed on top of them.
struct FurtherStage {
  std::vector<std::string> installed;
  std::vector<Candidate> candidates;
};

struct DiagnosisResult {
  std::string assembly, verdict;  ///< verdict: "effect" | "none" | "unexplained"
  std::string summary;            ///< plain sentences
  std::string named_effect;  ///< when verdict == "effect": the candidate named (an effect, a freed
                             ///< value or a sensor model)
  std::string named_kind;    ///< its kind: "effect" | "parameter" | "sensor"
  std::string finding;       ///< a freed value or a sensor model: what it found, in words
  std::vector<std::string> ambiguous_with;
  /// When a strong subsystem option (another structure) was weighed at its best against the
  /// first chain of causes: which chain reached the lower BIC, in words ("" when none was).
  std::string structure_note;
  std::string unexplained_location;
  Figures base;
  /// When a candidate's base parameters (its effect off) fitted better than the base optimum, the
  /// base was re-calibrated from there: that candidate, and the base's SSE before.
  std::string base_refined_from;
  double base_unrefined_sse = 0;
  std::vector<Candidate>
      candidates;  ///< every effect: confirmed ones first (by evidence), then by score, gated last
  /// The causes named, strongest first (verdict "effect"; with "unexplained", those that explain
  /// too little together). causes.front() is named_effect.
  std::vector<Cause> causes;
  std::vector<FurtherStage> further;  ///< the stages after the first (one per cause after the
                                      ///< first, and the last that found none)
  std::vector<Figures> steps;         ///< options.apply: base, + e1, + e1 + e2, ...
  /// Verdict "unexplained": the terms the sparse regression proposes (proposal.hpp), best first,
  /// and what it found in words (also when it proposes nothing).
  std::vector<ProposedTerm> proposal;
  std::string proposal_note;
  /// The proposal as ready-to-paste [user_effects] tables ("" when there is none).
  std::string proposalToml() const;
  std::vector<std::string> fitted_channels, left_out_channels;
  /// What failed beyond one candidate (a later stage of the stagewise selection, the joint
  /// calibration of the causes in full, another structure's chain, the proposal, a refinement of
  /// the base), one line each: the diagnosis went on without it (docs/diagnosis.md, "When a
  /// candidate fails"). A failed candidate is reported with the candidate (Candidate::failed).
  std::vector<std::string> failures;
  nlohmann::json toJson() const;
  /// The report printed by the CLI.
  std::string text() const;
};

/// The work of diagnose() (io/work.hpp), upper estimates: the base calibration and its
/// refinement, the screening probes of every catalogue effect, `candidates` confirmations and every
/// applied effect, each a calibration on `fit`, and a comparison of each calibrated model on `fit`
/// and `holdout`. Names the stages "diagnose base", "diagnose screening", "diagnose confirm",
/// "diagnose apply", "diagnose compare".
std::vector<StageWork> estimateDiagnoseWork(const Study& study, const AssemblySpec& assembly,
                                            const std::vector<calib::DataSet>& fit,
                                            const std::vector<calib::DataSet>& holdout,
                                            const DiagnoseOptions& options);

/// Runs the diagnosis of `assembly` on `fit` (and, when not empty, the held-out data `holdout`),
/// persisting every calibration under out_dir/calibrations/<effects> (resumable: a rerun reuses
/// them). Throws InputError for bad input: options.validate(), no fit data ("diagnose.fit"), no
/// channel with a noise estimate, an effect of options.effects or options.apply already installed.
DiagnosisResult diagnose(const Study& study, const AssemblySpec& assembly,
                         const std::vector<calib::DataSet>& fit,
                         const std::vector<calib::DataSet>& holdout, const DiagnoseOptions& options,
                         const std::string& out_dir, const DiagnoseProgress& progress = {});

/// The calibration setup of `candidates` (each installed, its diagnosed parameters calibrated over
/// their prior range) with the channel weights.
calib::CalibrationSetup candidatesSetup(const std::vector<CandidateSpec>& candidates,
                                        const std::map<std::string, double>& weights);

}  // namespace dtwin::diag
