// The last stages of diagnose(): a proposal of strut-force terms for an unexplained residual
// (docs/diagnosis.md) and apply (step 5), the named effects added in turn.
#include "diagnosis/diagnose_internal.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Dense>

#include "common/parallel.hpp"
#include "subsystems/effect.hpp"

namespace dtwin::diag {

// ------------------------------------------------------------------ propose

namespace {

/// Each library term's amplitude: the one that makes its force peak at 200 N over the base run's
/// suspension states (0 for a term that exerts no force there).
std::vector<double> termAmplitudes(const std::vector<LibraryTerm>& library,
                                   const std::vector<Trace>& traces) {
  std::vector<double> amplitude(library.size(), 0.0);
  const char* corners[] = {"fl", "fr", "rl", "rr"};
  for (std::size_t j = 0; j < library.size(); ++j) {
    double peak = 0;
    for (const auto& t : traces)
      for (int c = 0; c < 4; ++c) {
        const auto& q = t.column(std::string("susp_defl_") + corners[c] + "_m");
        const auto& v = t.column(std::string("susp_rate_") + corners[c] + "_mps");
        const auto& qo = t.column(std::string("susp_defl_") + corners[c ^ 1] +
                                  "_m");  // the other side of the axle
        const auto& vo = t.column(std::string("susp_rate_") + corners[c ^ 1] + "_mps");
        for (std::size_t i = 0; i < q.size(); ++i)
          peak = std::max(peak, std::abs(library[j].f({q[i], v[i], q[i] - qo[i], v[i] - vo[i]})));
      }
    if (peak > 0) amplitude[j] = 200.0 / peak;
  }
  return amplitude;
}

/// The predictions with each library term added at its amplitude to the base optimum (empty for
/// a term of amplitude 0 or whose run failed).
std::vector<std::vector<double>> termPredictions(const Diagnosis& d,
                                                 const std::vector<LibraryTerm>& library,
                                                 const std::vector<double>& amplitude,
                                                 const std::vector<double>& theta_hat) {
  std::vector<std::unique_ptr<calib::LabObjective>> objs(library.size());
  for (std::size_t j = 0; j < library.size(); ++j) {
    if (amplitude[j] == 0) continue;
    calib::CalibrationSetup setup;
    setup.channel_weights = d.weights;
    EffectSetting es;
    es.name = kTermPrefix + library[j].expr;
    setup.extra_effects.push_back(es);
    CalibratedParameter a;
    a.name = es.name + ".a";
    a.unit = library[j].unit;
    a.lower = -1e12;
    a.upper = 1e12;
    setup.extra_calibrated.push_back(a);
    objs[j] = std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets, setup);
  }
  std::vector<std::vector<double>> eta(library.size());
  d.report("propose: library terms", 0, library.size());
  parallelFor(library.size(), d.options.threads, [&](std::size_t j, int) {
    if (!objs[j]) return;
    auto th = theta_hat;
    th.push_back(amplitude[j]);
    eta[j] = objs[j]->predict(th);
  });
  d.report("propose: library terms", library.size(), library.size());
  return eta;
}

/// The proposal's sentence: how many terms, the first's ΔBIC, their share, the weak ones left out.
std::string proposalNote(const std::vector<ProposedTerm>& proposal, const std::string& lib_words,
                         std::size_t dropped, double bic_strong) {
  double kept_share = 0;
  for (const auto& t : proposal) kept_share += t.explained;
  return "A sparse regression of the residual on " + lib_words +
         " (best subset by BIC, linearised at the base optimum) proposes " +
         std::to_string(proposal.size()) + " term" + (proposal.size() > 1 ? "s" : "") + " (ΔBIC " +
         fmt("%.1f", proposal.front().delta_bic) + " for the first; together about " +
         fmt("%.0f", 100 * std::min(1.0, kept_share)) + " % of the excess residual" +
         (dropped ? "; " + std::to_string(dropped) + " weaker term" + (dropped > 1 ? "s" : "") +
                        " with ΔBIC above −" + fmt("%.0f", bic_strong) + " left out"
                  : std::string()) +
         "): paste it into the study file, or pass proposal.toml to --apply, and apply it.";
}

}  // namespace

/// Propose (verdict "unexplained"; docs/diagnosis.md): every library term (proposal.hpp) simulated
/// as a small strut force at θ̂ (its peak 200 N over the base run's states), its contribution
/// projected off span(J), and the best subset of at most options.propose_terms terms by BIC. A
/// subset is proposed only when it beats the empty model by more than bic_strong.
void propose(Diagnosis& d) {
  auto& res = d.res;
  const Linearisation lin = linearise(d);
  double q_comp = 0, q_reb = 0;
  const auto traces = d.base_obj->traces(lin.theta_hat);
  for (const auto& t : traces)
    for (const char* c : {"fl", "fr", "rl", "rr"})
      for (double q : t.column(std::string("susp_defl_") + c + "_m")) {
        q_comp = std::max(q_comp, q);
        q_reb = std::max(q_reb, -q);
      }
  const auto library = termLibrary(q_comp, q_reb);
  const auto amplitude = termAmplitudes(library, traces);
  const auto eta = termPredictions(d, library, amplitude, lin.theta_hat);
  const auto& w = d.base_obj->weights();
  const long n = lin.r.size();
  std::vector<std::size_t> used;
  for (std::size_t j = 0; j < library.size(); ++j)
    if (!eta[j].empty()) used.push_back(j);
  Eigen::MatrixXd G(n, static_cast<long>(used.size()));
  for (std::size_t k = 0; k < used.size(); ++k)
    for (long i = 0; i < n; ++i) {
      const auto ii = static_cast<std::size_t>(i);
      G(i, static_cast<long>(k)) =
          std::sqrt(w[ii]) * (eta[used[k]][ii] - lin.eta_hat[ii]) / amplitude[used[k]];
    }
  Eigen::MatrixXd Gp = lin.project(G);
  std::vector<double> norm(used.size(), 0.0);
  for (std::size_t k = 0; k < used.size(); ++k) {
    norm[k] = Gp.col(static_cast<long>(k)).norm();
    if (norm[k] > 0) Gp.col(static_cast<long>(k)) /= norm[k];
  }
  const auto fit = bestSubsetByBic(Gp, lin.r, d.options.propose_terms);
  const double gain = fit.bic_empty - fit.bic;
  const std::string lib_words = std::to_string(used.size()) + " strut-force terms";
  if (fit.chosen.empty() || gain <= d.options.bic_strong) {
    res.proposal_note = "No proposal: no subset of the " + lib_words +
                        " explains the residual (best BIC gain " + fmt("%.1f", gain) + ").";
    return;
  }
  const double excess = std::max(
      fit.sse_empty - static_cast<double>(n - static_cast<long>(lin.theta_hat.size())), 1e-12);
  const double ln_n = std::log(static_cast<double>(n));
  for (std::size_t i = 0; i < fit.chosen.size(); ++i) {
    const std::size_t k = fit.chosen[i], j = used[k];
    ProposedTerm t;
    t.force = "a * (" + (library[j].gap > 0 ? library[j].g_expr : library[j].expr) + ")";
    t.unit = library[j].unit;
    t.gap = library[j].gap;
    t.coefficient = fit.coef[i] / norm[k];
    t.delta_bic = -(fit.drop_sse[i] - fit.sse - ln_n);
    t.explained = std::clamp((fit.drop_sse[i] - fit.sse) / excess, 0.0, 1.0);
    res.proposal.push_back(t);
  }
  std::sort(res.proposal.begin(), res.proposal.end(),
            [](const ProposedTerm& a, const ProposedTerm& b) { return a.delta_bic < b.delta_bic; });
  // A term the subset keeps for a small BIC gain (between ln n and bic_strong) is not worth a
  // user's effect: only the strongly supported ones are proposed.
  const auto weak =
      std::find_if(res.proposal.begin(), res.proposal.end(),
                   [&](const ProposedTerm& t) { return t.delta_bic >= -d.options.bic_strong; });
  const std::size_t dropped = static_cast<std::size_t>(res.proposal.end() - weak);
  res.proposal.erase(weak, res.proposal.end());
  if (res.proposal.empty()) {
    res.proposal_note = "No proposal: no term of the " + lib_words +
                        " explains the residual strongly (ΔBIC below −" +
                        fmt("%.0f", d.options.bic_strong) + ").";
    return;
  }
  for (std::size_t i = 0; i < res.proposal.size(); ++i)
    res.proposal[i].name = "proposed_" + std::to_string(i + 1);
  res.proposal_note = proposalNote(res.proposal, lib_words, dropped, d.options.bic_strong);
  res.summary += " " + res.proposal_note;
}

// ------------------------------------------------------------------ apply

/// Apply (step 5): options.apply's effects added in turn, each model re-calibrated (a lone effect
/// confirmed above is reused); res.steps = base, + e1, + e1 + e2, ...
void apply(Diagnosis& d) {
  const auto& effects = d.options.apply;
  if (effects.empty()) return;
  auto& res = d.res;
  res.steps.push_back(res.base);
  std::vector<std::string> acc;
  for (const auto& effect : effects) {
    acc.push_back(effect);
    std::vector<double> start, theta;
    const Figures* confirmed =
        nullptr;  // a calibration with exactly these effects, in full, already made
    auto look = [&](const std::vector<Candidate>& cands) {
      for (const auto& c : cands)
        if (c.fit && c.fit->full && c.fit->effects == acc) confirmed = &*c.fit;
    };
    look(res.candidates);
    for (const auto& st : res.further) look(st.candidates);
    for (const auto& c : res.candidates)
      if (c.effect == effect) {
        start = c.screening_estimate;
        theta = c.screening_theta;
      }
    if (confirmed) {
      res.steps.push_back(*confirmed);
      continue;
    }
    // A step that fails ends the table at the steps before it (res.failures says why).
    Figures step;
    if (!d.isolated("applying " + joinEffects(acc), [&] {
          step = d.calibrateWith(acc, "apply " + joinEffects(acc), start, theta);
        }))
      break;
    res.steps.push_back(std::move(step));
  }
}

}  // namespace dtwin::diag
