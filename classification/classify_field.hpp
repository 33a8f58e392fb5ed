#pragma once
// Classification of field records among synthesized assemblies (docs/method.md §5, bullets 2–4):
// the glue between synthesis.hpp (moments.bin + synthesis.json per assembly), the mathematics
// (moments, shrinkage, mvn, classify, recommend) and the output files. `twin classify` is a thin
// front end to this; `twin study` can call it too.
//
// \par Steps
//  1. For each assembly m (folder SYNTH/<id>/ written by synthesizeAssembly): load the moments,
//     check that its window (times, channel) is the field data's.
//  2. Covariance: "sample" (M2 / (n − 1)) or "ledoit-wolf" (calcLedoitWolf, needs the fourth
//     moment); "auto" picks Ledoit–Wolf when some assembly has fewer than 2p synthetic vectors
//     (n < 2p: the sample covariance is singular, n <= p, or poorly conditioned) and the sample
//     covariance otherwise; the same method for every assembly, and the reason is reported.
//  3. One GaussianModel per assembly (Cholesky; LDLT or jitter when it fails — reported per
//     assembly), built and evaluated one assembly at a time (memory: ~3 p×p matrices at once).
//  4. ℓ_{r,m} = ln N(y_r; μ_m, Σ_m) for every record, classifyRecords with the priors (ℓ + ln π,
//     softmax, winners, ties, spread, Bayes factors with Kass–Raftery categories).
//  5. recommendAssembly on the joint log likelihoods L_m = Σ_r ℓ_{r,m} (priors cancel in B) and the
//     cost per assembly from synthesis.json (median wall s per simulated s of its runs).
//
// \par Files (writeFieldClassification)
//   records.csv   record,loglik_<id>...,logpost_<id>...,prob_<id>...,winner,tie   (one row per
//                 field record; record = the field file's run number; loglik = ln N(y; μ_m, Σ_m),
//                 logpost = ℓ_m = ln π_m + loglik (unnormalised), prob = P(M_m | y); numbers in
//                 the shortest exact form, -inf written as -inf; tie 0/1)
//   summary.json  see FieldClassification::summary
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "classification/classify.hpp"
#include "classification/mvn.hpp"
#include "classification/recommend.hpp"
#include "io/measurement.hpp"
#include "io/study.hpp"

namespace dtwin::classify {

struct FieldClassifyOptions {
  /// Assembly ids to compare; empty: every assembly of the study with SYNTH/<id>/synthesis.json.
  std::vector<std::string> assemblies;
  /// "auto" (default), "sample" or "ledoit-wolf".
  std::string covariance = "auto";
  /// (id, π) per compared assembly; empty: uniform.
  std::vector<std::pair<std::string, double>> prior;
  double threshold = 10.0;  ///< on 2 ln B for the recommendation (recommend.hpp)
  double tie_tolerance = 1e-12;
  FactorOptions factor;
  /// Assemblies whose models are built at once (0: all cores); each holds its p×p matrices
  /// (about 0.6 GB at p = 5001). Never changes the numbers.
  int threads = 0;
  std::string command;  ///< recorded in summary.json
  /// InputError whose where() is "field_classify.<field>" (common/validate.hpp): no assembly twice,
  /// a known covariance, each prior finite and > 0, threshold finite and > 0, tie_tolerance
  /// finite and >= 0, and factor.validate().
  void validate() const;
};

struct AssemblyModelInfo {
  std::string id, label, dir;
  std::int64_t vectors = 0;          ///< n
  int dimension = 0;                 ///< p
  std::string covariance;            ///< "sample" | "ledoit-wolf"
  double shrinkage_intensity = 0.0;  ///< Ledoit–Wolf ρ (0 for the sample covariance)
  std::string factorization;         ///< GaussianModel::factorization()
  double jitter = 0.0, jitter_absolute = 0.0, log_det = 0.0, relative_min_pivot = 0.0;
  double cost_s_per_s = 0.0;  ///< from synthesis.json
  double build_wall_s = 0.0;  ///< load + covariance + factor + evaluate
  nlohmann::json synthesis;   ///< selected fields of synthesis.json
};

struct FieldClassification {
  std::vector<long> records;              ///< field run numbers
  std::vector<AssemblyModelInfo> models;  ///< in comparison order
  std::string covariance_method, covariance_reason;
  Eigen::MatrixXd log_likelihood;  ///< R×M: ℓ_{r,m}
  ClassificationResult result;
  Recommendation recommendation;
  /// summary.json: wins (id → count), tied_records, probability (id → min, q1, median, q3, max,
  /// mean), total_log_likelihood, joint_probability, bayes_factors (pairs a < b: 2 ln B, ln B,
  /// favoured, Kass–Raftery category), factorization (id → path), covariance (method, reason),
  /// models (per assembly details), cost_s_per_s, prior, recommended, recommendation_sentence,
  /// recommendation (best, candidates, 2 ln B vs the best, cost ratio, threshold), field and
  /// synthesis provenance, program, command, created_utc, report (text).
  nlohmann::json summary;
  /// records.csv text (see the file header).
  std::string recordsCsv() const;
};

/// Classifies the records of `field` (its window must be each synthesis's) among the assemblies
/// synthesized in `synthetic_dir`. `field_channel` is the field data's channel if known (the
/// sidecar says it; "" skips the check). `field_info` goes into summary.json as provenance.
/// InputError for a bad option, a missing or mismatching synthesis, a Ledoit–Wolf request on
/// moments without the fourth moment, or a covariance no factorisation accepts.
FieldClassification classifyField(const Study& study, const FieldData& field,
                                  const std::string& field_channel,
                                  const std::string& synthetic_dir,
                                  const FieldClassifyOptions& options,
                                  const nlohmann::json& field_info = nullptr);

/// Reads a field CSV (and its sidecar FILE.json when present, for the channel) and classifies it.
FieldClassification classifyFieldFile(const Study& study, const std::string& field_csv,
                                      const std::string& synthetic_dir,
                                      const FieldClassifyOptions& options);

/// Writes out_dir/records.csv and out_dir/summary.json atomically.
void writeFieldClassification(const FieldClassification& c, const std::string& out_dir);

/// Parses "M1=0.25,M2=0.25,..." (CLI --prior); `where` prefixes errors.
std::vector<std::pair<std::string, double>> parsePriorList(const std::string& text,
                                                           const std::string& where);

}  // namespace dtwin::classify
