#include "classification/recommend.hpp"
#include "common/format.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <sstream>

#include "common/errors.hpp"
#include "common/validate.hpp"

namespace dtwin::classify {

namespace {

// `v` with 1 decimal, or with more until the printed value still satisfies `ok`.
template <class Ok>
std::string decimals(double v, Ok ok) {
  for (int d = 1; d <= 12; ++d) {
    std::string text = formatFixed(v, d);
    double back = 0;
    if (parseNumber(text, back) && ok(back)) return text;
  }
  return formatNumber(v, 17);
}

}  // namespace

void RecommendOptions::validate() const {
  const OptionCheck check("recommend");
  check.positive("threshold", threshold);
}

Recommendation recommendAssembly(const std::vector<ModelCost>& models,
                                 const RecommendOptions& options) {
  options.validate();
  const std::string where = "recommendation";
  if (models.empty()) throw InputError(where, "no models given");
  std::set<std::string> ids;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const ModelCost& mc = models[m];
    const std::string field = where + ": model " + std::to_string(m) + " (" + mc.id + ")";
    if (mc.id.empty()) throw InputError(where + ": model " + std::to_string(m), "id is empty");
    if (!ids.insert(mc.id).second) throw InputError(field, "duplicate id");
    if (std::isnan(mc.log_evidence) || mc.log_evidence == std::numeric_limits<double>::infinity())
      throw InputError(field,
                       "log_evidence must be finite or -inf, got " + formatNumber(mc.log_evidence));
    if (!(std::isfinite(mc.cost) && mc.cost > 0.0))
      throw InputError(field, "cost must be > 0 and finite, got " + formatNumber(mc.cost));
  }

  Recommendation r;
  const int M = static_cast<int>(models.size());
  r.best_index = 0;
  for (int m = 1; m < M; ++m)
    if (models[m].log_evidence > models[r.best_index].log_evidence) r.best_index = m;
  const ModelCost& best = models[r.best_index];
  if (best.log_evidence == -std::numeric_limits<double>::infinity())
    throw InputError(where, "every model has log_evidence -inf");

  for (int m = 0; m < M; ++m) {
    const double t = 2.0 * (best.log_evidence - models[m].log_evidence);
    r.two_ln_b.push_back(t);
    if (t < options.threshold) {
      r.candidate_indices.push_back(m);
      r.candidates.push_back(models[m].id);
    }
  }
  // Cheapest candidate; ties: higher evidence, then lower index (candidates are in index order).
  r.recommended_index = r.candidate_indices.front();
  for (int m : r.candidate_indices) {
    const ModelCost& c = models[m];
    const ModelCost& cur = models[r.recommended_index];
    if (c.cost < cur.cost || (c.cost == cur.cost && c.log_evidence > cur.log_evidence))
      r.recommended_index = m;
  }
  const ModelCost& rec = models[r.recommended_index];
  r.recommended = rec.id;
  r.best = best.id;
  r.cost_ratio = best.cost / rec.cost;

  const std::string thr = formatNumber(options.threshold);
  if (r.recommended_index != r.best_index) {
    const double t = r.two_ln_b[r.recommended_index];
    r.explanation =
        rec.id + " is recommended: it is " +
        decimals(r.cost_ratio, [](double x) { return x > 1.0; }) + "x cheaper than " + best.id +
        " (the best by evidence) and its evidence is not decisively worse (2 ln B = " +
        decimals(t, [&](double x) { return x < options.threshold; }) + " < " + thr + ").";
  } else {
    bool any_cheaper = false;
    for (const ModelCost& c : models) any_cheaper = any_cheaper || c.cost < best.cost;
    if (M == 1)
      r.explanation = best.id + " is recommended: it is the only assembly.";
    else if (any_cheaper)
      r.explanation = best.id +
                      " is recommended: it has the strongest evidence and every cheaper assembly "
                      "is decisively worse (2 ln B \u2265 " +
                      thr + ").";
    else
      r.explanation =
          best.id +
          " is recommended: it has the strongest evidence and no other assembly is cheaper.";
  }
  return r;
}

}  // namespace dtwin::classify
