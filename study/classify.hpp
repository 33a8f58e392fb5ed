#pragma once
// `twin classify` as one call: the field records classified among the synthesized assemblies, and
// the cost-aware recommendation (classification/classify_field.hpp), written to a folder.
#include <string>

#include "classification/classify_field.hpp"
#include "io/study.hpp"

namespace dtwin {

struct ClassifyRequest {
  std::string field;      ///< the field records (CSV matrix run,road_seed,t_...)
  std::string synthetic;  ///< the folder `twin synthesize` wrote (DIR/<id>/moments.bin, ...)
  std::string out;        ///< the folder: records.csv and summary.json
  std::string prior;      ///< "M1=0.25,M2=0.75" (errors name --prior); "": uniform
  classify::FieldClassifyOptions options;  ///< the prior is set from `prior`
};

/// One classification, written.
struct ClassifyRun {
  classify::FieldClassification result;
  std::string out;  ///< the folder written
  /// The lines `twin classify` prints: the records and the covariance, each model, the evidence,
  /// the recommendation and the files written.
  std::string text() const;
};

/// Checks the request (the options, `out` a folder or absent, the field file and the synthetic
/// folder there: InputError before any work), classifies the field records and writes the folder.
ClassifyRun classifyFieldRecords(const Study& study, const ClassifyRequest& request);

}  // namespace dtwin
