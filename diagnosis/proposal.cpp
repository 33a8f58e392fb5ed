#include "diagnosis/proposal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace dtwin::diag {
namespace {

/// Three significant digits: how a term's constants are printed.
std::string num(double v) { return formatNumber(v, 3); }

/// `v` as num() prints it, read back: the constant of the term that is simulated.
double asPrinted(double v) {
  double back = 0;
  DTWIN_CHECK(parseNumber(num(v), back), "a printed number reads back");
  return back;
}

double sgn(double x) { return (x > 0) - (x < 0); }

}  // namespace

std::vector<LibraryTerm> termLibrary(double q_comp, double q_reb) {
  using S = StrutSample;
  std::vector<LibraryTerm> lib = {
      {"q * abs(q)", "N/m^2", [](const S& s) { return s.q * std::abs(s.q); }, 0, {}},
      {"q^2", "N/m^2", [](const S& s) { return s.q * s.q; }, 0, {}},
      {"q^3", "N/m^3", [](const S& s) { return s.q * s.q * s.q; }, 0, {}},
      {"v * abs(v)", "N*s^2/m^2", [](const S& s) { return s.v * std::abs(s.v); }, 0, {}},
      {"v^3", "N*s^3/m^3", [](const S& s) { return s.v * s.v * s.v; }, 0, {}},
      {"q * v", "N*s/m^2", [](const S& s) { return s.q * s.v; }, 0, {}},
      {"sign(v)", "N", [](const S& s) { return sgn(s.v); }, 0, {}},
      {"sign(v) * sqrt(abs(v))",
       "N*s^0.5/m^0.5",
       [](const S& s) { return sgn(s.v) * std::sqrt(std::abs(s.v)); },
       0,
       {}},
      {"(v < 0 ? v : 0)", "N*s/m", [](const S& s) { return s.v < 0 ? s.v : 0.0; }, 0, {}},
      {"dq * abs(dq)", "N/m^2", [](const S& s) { return s.dq * std::abs(s.dq); }, 0, {}},
      {"dq^3", "N/m^3", [](const S& s) { return s.dq * s.dq * s.dq; }, 0, {}},
      {"dv", "N*s/m", [](const S& s) { return s.dv; }, 0, {}},
      {"q * dq", "N/m^2", [](const S& s) { return s.q * s.dq; }, 0, {}},
  };
  for (double frac : {0.2, 0.4, 0.6, 0.8}) {
    if (q_comp > 0) {
      const double g = asPrinted(frac * q_comp);  // so the proposal is the term simulated
      lib.push_back({"max(q - " + num(g) + ", 0)", "N/m",
                     [g](const S& s) { return std::max(s.q - g, 0.0); }, g, "max(q - g, 0)"});
      lib.push_back({"max(q - " + num(g) + ", 0)^2", "N/m^2",
                     [g](const S& s) { return std::pow(std::max(s.q - g, 0.0), 2); }, g,
                     "max(q - g, 0)^2"});
    }
    if (q_reb > 0) {
      const double g = asPrinted(frac * q_reb);
      lib.push_back({"max(-q - " + num(g) + ", 0)", "N/m",
                     [g](const S& s) { return std::max(-s.q - g, 0.0); }, g, "max(-q - g, 0)"});
      lib.push_back({"max(-q - " + num(g) + ", 0)^2", "N/m^2",
                     [g](const S& s) { return std::pow(std::max(-s.q - g, 0.0), 2); }, g,
                     "max(-q - g, 0)^2"});
    }
  }
  return lib;
}

SubsetFit bestSubsetByBic(const Eigen::MatrixXd& G, const Eigen::VectorXd& r, int max_terms) {
  const long m = G.cols();
  const double ln_n = std::log(static_cast<double>(std::max<long>(r.size(), 2)));
  const Eigen::MatrixXd gram = G.transpose() * G;
  const Eigen::VectorXd b = G.transpose() * r;
  SubsetFit best;
  best.sse_empty = best.sse = r.squaredNorm();
  best.bic_empty = best.bic = best.sse;
  auto sseOf = [&](const std::vector<std::size_t>& s, Eigen::VectorXd* coef) {
    const long k = static_cast<long>(s.size());
    if (k == 0) return r.squaredNorm();
    Eigen::MatrixXd A(k, k);
    Eigen::VectorXd bb(k);
    for (long i = 0; i < k; ++i) {
      bb[i] = b[static_cast<long>(s[static_cast<std::size_t>(i)])];
      for (long j = 0; j < k; ++j)
        A(i, j) = gram(static_cast<long>(s[static_cast<std::size_t>(i)]),
                       static_cast<long>(s[static_cast<std::size_t>(j)]));
    }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(A);
    if (ldlt.info() != Eigen::Success || ldlt.rcond() < 1e-10)
      return std::numeric_limits<double>::infinity();
    const Eigen::VectorXd c = ldlt.solve(bb);
    if (coef) *coef = c;
    return r.squaredNorm() - bb.dot(c);
  };
  std::vector<std::size_t> s;
  std::function<void(long)> visit = [&](long from) {
    if (!s.empty()) {
      const double sse = sseOf(s, nullptr);
      const double bic = sse + static_cast<double>(s.size()) * ln_n;
      if (bic < best.bic) {
        best.bic = bic;
        best.sse = sse;
        best.chosen = s;
      }
    }
    if (static_cast<int>(s.size()) == max_terms) return;
    for (long j = from; j < m; ++j) {
      s.push_back(static_cast<std::size_t>(j));
      visit(j + 1);
      s.pop_back();
    }
  };
  visit(0);
  if (!best.chosen.empty()) {
    Eigen::VectorXd c;
    sseOf(best.chosen, &c);
    best.coef.assign(c.data(), c.data() + c.size());
    for (std::size_t i = 0; i < best.chosen.size(); ++i) {
      auto without = best.chosen;
      without.erase(without.begin() + static_cast<long>(i));
      best.drop_sse.push_back(sseOf(without, nullptr));
    }
  }
  return best;
}

std::string ProposedTerm::toml() const {
  const double far = 5.0 * coefficient;
  std::string g;
  if (gap > 0)
    g = ", g = { value = " + num(gap) + ", unit = \"m\", lower = " + num(0.5 * gap) +
        ", upper = " + num(2 * gap) + ", shape = true }";
  return "[user_effects." + name + "]\nelement = \"strut\"\nforce = \"" + force +
         "\"\nparameters = { a = { value = 0, unit = \"" + unit +
         "\", lower = " + num(std::min(0.0, far)) + ", upper = " + num(std::max(0.0, far)) + " }" +
         g + " }\n";
}

nlohmann::json ProposedTerm::toJson() const {
  return {{"name", name},
          {"force", force},
          {"unit", unit},
          {"gap_m", gap},
          {"coefficient", coefficient},
          {"delta_bic", delta_bic},
          {"explained_fraction", explained},
          {"toml", toml()}};
}

}  // namespace dtwin::diag
