#include "classification/classify.hpp"
#include "common/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "common/errors.hpp"
#include "common/statistics.hpp"
#include "common/validate.hpp"

namespace dtwin::classify {

namespace {

// Posterior probabilities softmax(ℓ + ln π) into `prob`; returns LSE(ℓ + ln π). The differences to
// the largest λ are formed from ℓ and ln π separately: λ itself is rounded at the magnitude of ℓ
// (ulp 1e-10 at ℓ = −1e6), the differences are not. ℓ has at least one finite entry.
double posteriorSoftmax(const Eigen::VectorXd& ll, const Eigen::VectorXd& log_prior,
                        Eigen::VectorXd& prob) {
  constexpr double kNegInf = -std::numeric_limits<double>::infinity();
  const Eigen::VectorXd lam = ll + log_prior;
  Eigen::Index top = 0;
  const double mx = lam.maxCoeff(&top);
  if (mx == kNegInf) {  // every model excluded: undefined
    prob.setConstant(std::numeric_limits<double>::quiet_NaN());
    return kNegInf;
  }
  const Eigen::Index M = ll.size();
  for (Eigen::Index m = 0; m < M; ++m)
    prob[m] = ll[m] == kNegInf ? kNegInf : (ll[m] - ll[top]) + (log_prior[m] - log_prior[top]);
  // std::exp, not Eigen's vectorised exp, which clamps its argument near −708 (so exp(−inf)
  // would give ~5e-309 instead of 0).
  double sum = 0.0;
  for (Eigen::Index m = 0; m < M; ++m) sum += std::exp(prob[m]);
  const double lse = std::log(sum);  // >= 0: the top term is exp(0) = 1
  for (Eigen::Index m = 0; m < M; ++m) prob[m] = std::exp(prob[m] - lse);
  return mx + lse;
}

}  // namespace

void ClassifyOptions::validate() const {
  const OptionCheck check("classify");
  check.nonNegative("tie_tolerance", tie_tolerance);
  if (prior.empty()) return;
  double sum = 0.0;
  for (std::size_t m = 0; m < prior.size(); ++m) {
    check.positive("prior[" + std::to_string(m) + "]", prior[m]);
    sum += prior[m];
  }
  check.require(std::abs(sum - 1.0) <= 1e-9, "prior",
                "must sum to 1 within 1e-9, got " + formatNumber(sum, 17));
}

void ClassifyOptions::validate(int models) const {
  validate();
  const OptionCheck check("classify");
  const auto perModel = [&](const char* field, std::size_t entries) {
    check.require(entries == 0 || static_cast<int>(entries) == models, field,
                  "has " + std::to_string(entries) + " entries, expected " +
                      std::to_string(models) + " (one per model)");
  };
  perModel("model_ids", model_ids.size());
  perModel("prior", prior.size());
}

double logSumExp(const Eigen::Ref<const Eigen::VectorXd>& v) {
  if (v.size() == 0) return -std::numeric_limits<double>::infinity();
  const double mx = v.maxCoeff();
  if (mx == -std::numeric_limits<double>::infinity()) return mx;
  double sum = 0.0;
  for (Eigen::Index i = 0; i < v.size(); ++i) sum += std::exp(v[i] - mx);
  return mx + std::log(sum);
}

std::string kassRafteryCategory(double two_ln_b) {
  if (std::isnan(two_ln_b)) return "undefined";
  const double x = std::abs(two_ln_b);
  if (x < 2.0) return "not worth more than a bare mention";
  if (x < 6.0) return "positive";
  if (x < 10.0) return "strong";
  return "very strong";
}

ClassificationResult classifyRecords(const Eigen::MatrixXd& ll, const ClassifyOptions& options) {
  const std::string where = "log-likelihood matrix";
  const Eigen::Index R = ll.rows(), M = ll.cols();
  if (R < 1 || M < 1)
    throw InputError(where, "is " + std::to_string(R) + "x" + std::to_string(M) +
                                ", needs at least one record (row) and one model (column)");
  options.validate(static_cast<int>(M));
  constexpr double kNegInf = -std::numeric_limits<double>::infinity();
  for (Eigen::Index r = 0; r < R; ++r) {
    bool any_finite = false;
    for (Eigen::Index m = 0; m < M; ++m) {
      const double v = ll(r, m);
      if (std::isnan(v) || v == std::numeric_limits<double>::infinity())
        throw InputError(where, "entry (record " + std::to_string(r) + ", model " +
                                    std::to_string(m) + ") is " + formatNumber(v) +
                                    " (must be finite or -inf)");
      any_finite = any_finite || v != kNegInf;
    }
    if (!any_finite)
      throw InputError(where, "record " + std::to_string(r) +
                                  ": every model has log-likelihood -inf (posterior undefined)");
  }

  ClassificationResult res;
  res.records = static_cast<int>(R);
  res.models = static_cast<int>(M);
  res.model_ids = options.model_ids;
  if (res.model_ids.empty())
    for (Eigen::Index m = 0; m < M; ++m) res.model_ids.push_back("M" + std::to_string(m + 1));
  res.log_prior.resize(M);
  for (Eigen::Index m = 0; m < M; ++m)
    res.log_prior[m] = options.prior.empty() ? -std::log(static_cast<double>(M))
                                             : std::log(options.prior[static_cast<std::size_t>(m)]);

  // Per record: λ = ℓ + ln π, LSE, softmax, winner with ties.
  res.log_posterior = ll.rowwise() + res.log_prior.transpose();
  res.log_marginal.resize(R);
  res.probability.resize(R, M);
  res.winner.assign(static_cast<std::size_t>(R), 0);
  Eigen::VectorXd prob(M);
  res.tie.assign(static_cast<std::size_t>(R), false);
  res.wins.assign(static_cast<std::size_t>(M), 0);
  for (Eigen::Index r = 0; r < R; ++r) {
    const Eigen::VectorXd lam = res.log_posterior.row(r).transpose();
    res.log_marginal[r] = posteriorSoftmax(ll.row(r).transpose(), res.log_prior, prob);
    res.probability.row(r) = prob.transpose();
    const double mx = lam.maxCoeff();
    int winner = -1, near = 0;
    for (Eigen::Index m = 0; m < M; ++m) {
      const double gap = mx - lam[m];  // +inf for a −inf entry
      const double scale = std::max({1.0, std::abs(mx), std::abs(lam[m])});
      if (gap <= options.tie_tolerance * scale) {
        if (winner < 0) winner = static_cast<int>(m);
        ++near;
      }
    }
    DTWIN_CHECK(winner >= 0, "the maximum is always within tolerance of itself");
    res.winner[static_cast<std::size_t>(r)] = winner;
    res.tie[static_cast<std::size_t>(r)] = near >= 2;
    res.tied_records += near >= 2 ? 1 : 0;
    ++res.wins[static_cast<std::size_t>(winner)];
  }

  // Spread of each model's posterior probability over the records.
  std::vector<double> col(static_cast<std::size_t>(R));
  for (Eigen::Index m = 0; m < M; ++m) {
    for (Eigen::Index r = 0; r < R; ++r) col[static_cast<std::size_t>(r)] = res.probability(r, m);
    std::sort(col.begin(), col.end());
    ProbabilitySpread s;
    s.min = col.front();
    s.q1 = quantileSorted(col, 0.25);
    s.median = quantileSorted(col, 0.5);
    s.q3 = quantileSorted(col, 0.75);
    s.max = col.back();
    s.mean = res.probability.col(m).mean();
    res.spread.push_back(s);
  }

  // Joint evidence over the records (independent given the model).
  res.total_log_likelihood = ll.colwise().sum().transpose();
  res.joint_probability.resize(M);
  posteriorSoftmax(res.total_log_likelihood, res.log_prior, res.joint_probability);
  res.log_bayes_factor = Eigen::MatrixXd::Zero(M, M);
  for (Eigen::Index a = 0; a < M; ++a)
    for (Eigen::Index b = a + 1; b < M; ++b) {
      const double lb = (ll.col(a) - ll.col(b)).sum();  // per record, then summed
      res.log_bayes_factor(a, b) = lb;
      res.log_bayes_factor(b, a) = -lb;
      PairwiseEvidence e;
      e.a = static_cast<int>(a);
      e.b = static_cast<int>(b);
      e.log_bayes_factor = lb;
      e.two_ln_b = 2.0 * lb;
      e.favoured = lb > 0 ? e.a : (lb < 0 ? e.b : -1);
      e.category = kassRafteryCategory(e.two_ln_b);
      res.pairs.push_back(e);
    }
  return res;
}

std::string ClassificationResult::briefReport() const {
  std::ostringstream s;
  s << "Classified " << records << " record(s) among " << models << " model(s)";
  if (tied_records > 0) s << " (" << tied_records << " tied, given to the lowest index)";
  s << ".\nWins:";
  for (int m = 0; m < models; ++m)
    s << " " << model_ids[static_cast<std::size_t>(m)] << " " << wins[static_cast<std::size_t>(m)]
      << " (" << formatFixed(100.0 * wins[static_cast<std::size_t>(m)] / records, 1) << " %)"
      << (m + 1 < models ? "," : ".");
  int best = 0;
  for (int m = 1; m < models; ++m)
    if (total_log_likelihood[m] > total_log_likelihood[best]) best = m;
  s << "\nJoint evidence: " << model_ids[static_cast<std::size_t>(best)]
    << " has the largest total log-likelihood (" << formatNumber(total_log_likelihood[best], 8)
    << ").\n";
  return s.str();
}

std::string ClassificationResult::fullReport() const {
  std::ostringstream s;
  s << briefReport();
  s << "Posterior probability per record (min / q1 / median / q3 / max, mean):\n";
  for (int m = 0; m < models; ++m) {
    const ProbabilitySpread& p = spread[static_cast<std::size_t>(m)];
    s << "  " << model_ids[static_cast<std::size_t>(m)] << ": " << formatFixed(p.min, 4) << " / "
      << formatFixed(p.q1, 4) << " / " << formatFixed(p.median, 4) << " / " << formatFixed(p.q3, 4)
      << " / " << formatFixed(p.max, 4) << ", mean " << formatFixed(p.mean, 4) << "\n";
  }
  s << "Pairwise Bayes factors over all records (Kass-Raftery scale of 2 ln B):\n";
  for (const PairwiseEvidence& e : pairs) {
    s << "  " << model_ids[static_cast<std::size_t>(e.a)] << " vs "
      << model_ids[static_cast<std::size_t>(e.b)] << ": 2 ln B = " << formatNumber(e.two_ln_b, 6);
    if (e.favoured >= 0)
      s << ", " << e.category << " (favours " << model_ids[static_cast<std::size_t>(e.favoured)]
        << ")";
    else
      s << ", " << (std::isnan(e.two_ln_b) ? "undefined" : "no evidence either way");
    s << "\n";
  }
  return s.str();
}

}  // namespace dtwin::classify
