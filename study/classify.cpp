#include "study/classify.hpp"

#include <filesystem>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace fs = std::filesystem;

namespace dtwin {

ClassifyRun classifyFieldRecords(const Study& study, const ClassifyRequest& request) {
  classify::FieldClassifyOptions opt = request.options;
  if (!request.prior.empty()) opt.prior = classify::parsePriorList(request.prior, "--prior");
  opt.validate();
  if (fs::exists(request.out) && !fs::is_directory(request.out))
    throw InputError("--out", "'" + request.out + "' exists and is not a folder");
  if (!fs::exists(request.field))
    throw InputError(request.field, "field data file not found (--field)");
  if (!fs::is_directory(request.synthetic))
    throw InputError(request.synthetic, "synthetic data folder not found (--synthetic)");
  ClassifyRun run;
  run.result = classify::classifyFieldFile(study, request.field, request.synthetic, opt);
  classify::writeFieldClassification(run.result, request.out);
  run.out = request.out;
  return run;
}

std::string ClassifyRun::text() const {
  const classify::FieldClassification& c = result;
  std::string s = formatPrintf("%zu field records x %d samples; covariance: %s (%s)\n",
                               c.records.size(), c.models.empty() ? 0 : c.models.front().dimension,
                               c.covariance_method.c_str(), c.covariance_reason.c_str());
  for (const auto& m : c.models)
    s += formatPrintf("  %-4s %-24s n = %lld, factorization %s%s, cost %.4g s/s\n", m.id.c_str(),
                      m.label.c_str(), static_cast<long long>(m.vectors), m.factorization.c_str(),
                      m.covariance == "ledoit-wolf"
                          ? (", shrinkage " + std::to_string(m.shrinkage_intensity)).c_str()
                          : "",
                      m.cost_s_per_s);
  s += c.result.briefReport();
  s += c.recommendation.explanation + "\n";
  s += "-> " + (fs::path(out) / "records.csv").string() + ", " +
       (fs::path(out) / "summary.json").string() + "\n";
  return s;
}

}  // namespace dtwin
