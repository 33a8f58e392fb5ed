// The confirmation stage of diagnose() (docs/diagnosis.md, step 3): the candidates re-calibrated
// with their effect, the base refined and the candidates weighed; then the forward stagewise
// selection.
#include "diagnosis/diagnose_internal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "twin/model.hpp"

namespace dtwin::diag {

/// The candidates to confirm (docs/diagnosis.md, "Confirmation"), in order: among the ungated ones
/// with p < screen_alpha, every one whose screening score is within a factor
/// options.confirm_within of the best (the best of each kind first, then the others, by score);
/// then the best of each kind (effect, parameter, sensor, ...) not already in, by score; at most
/// options.candidates in all (the work budget). A later round passes the indices the rounds before
/// took as `tried`: they are left out, and options are not added again.
std::vector<std::size_t> chooseConfirmations(const std::vector<Candidate>& cands,
                                             const DiagnoseOptions& options,
                                             const std::set<std::size_t>& tried) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < cands.size(); ++i)
    if (cands[i].gate.empty() && cands[i].failed.empty() && cands[i].p_value < options.screen_alpha)
      order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cands[a].score > cands[b].score; });
  std::vector<std::size_t> chosen;
  if (order.empty()) return chosen;
  const double best = cands[order.front()].score;
  // Within the factor, the best of each kind comes first, then the rest by score: when the budget
  // cannot hold them all, two mirror images of one kind (the road signal at the front-left or at
  // the front-right wheel) do not take the slots of a cause of another kind (the sensor's place).
  std::vector<std::size_t> rest;
  std::set<std::string> kinds;
  for (std::size_t i : order)
    if (!tried.count(i) && cands[i].score * options.confirm_within >= best)
      (kinds.insert(cands[i].kind).second ? chosen : rest).push_back(i);
  for (std::size_t i : rest) chosen.push_back(i);
  // Beyond the factor, the best of each kind not confirmed yet (in the first round only).
  if (tried.empty())
    for (std::size_t i : order)
      if (kinds.insert(cands[i].kind).second) chosen.push_back(i);
  if (chosen.size() > static_cast<std::size_t>(options.candidates))
    chosen.resize(static_cast<std::size_t>(options.candidates));
  // Another option of a subsystem is not nested in the model: no score can screen it, so it is
  // always confirmed, beyond the budget.
  if (tried.empty())
    for (std::size_t i = 0; i < cands.size(); ++i)
      if (cands[i].kind == "option" && cands[i].gate.empty() && cands[i].failed.empty())
        chosen.push_back(i);
  return chosen;
}

namespace {

/// Its own parameters all at their off values in its fit: the candidate adds nothing; an SSE below
/// the reference's then comes from polishing the reference's values further, not from it.
bool isInert(const Diagnosis& d, const Candidate& c) {
  const auto& spec = d.spec(c.effect);
  if (!spec.addsParameters()) return false;
  const auto own = d.parametersOf(c.effect, *c.fit);
  return !own.empty() && std::all_of(own.begin(), own.end(), [&](const EffectParameter& p) {
    for (const auto& ps : spec.parameters)
      if (c.effect + "." + ps.name == p.name || ps.name == p.name ||
          (spec.calibrated_names.size() == 1 && spec.calibrated_names[0] == p.name))
        return std::abs(p.optimum - ps.default_value) <= 1e-6 * (ps.prior_upper - ps.prior_lower);
    return false;
  });
}

/// A confirmed candidate weighed against its stage's reference `ref`: ΔBIC, the share of the
/// base's excess residual it removes, the held-out change.
void weigh(const Diagnosis& d, Candidate& c, const Figures& ref) {
  const Comparison& base = d.res.base.comparison;
  const double base_excess = base.lack_of_fit - static_cast<double>(base.lack_of_fit_dof);
  c.delta_bic = c.fit->bic - ref.bic;
  c.explained =
      base_excess > 0
          ? std::clamp((ref.comparison.lack_of_fit - c.fit->comparison.lack_of_fit) / base_excess,
                       0.0, 1.0)
          : 0.0;
  if (c.fit->holdout && ref.holdout && ref.holdout->systematic_rms_sd > 0)
    c.holdout_change = c.fit->holdout->systematic_rms_sd / ref.holdout->systematic_rms_sd;
}

}  // namespace

/// Confirm (step 3): the candidates chooseConfirmations picks, re-calibrated with their effect.
/// Returns their indices in res.candidates.
std::vector<std::size_t> confirm(Diagnosis& d) {
  auto& cands = d.stage();
  const std::vector<std::size_t> to_confirm = chooseConfirmations(cands, d.options);
  const std::string on_top = d.installed.empty() ? "" : " on " + joinEffects(d.installed);
  // Each candidate's confirmation is its own (docs/diagnosis.md, "When a candidate fails"): one
  // whose calibration, intervals or comparison throws (its region found no point inside the
  // bounds, an internal error) is reported with the candidate, and the diagnosis goes on with the
  // others. Bad input and a full disk end the run.
  auto calibrate = [&](Candidate& c, const std::string& stage, bool full) {
    return d.isolatedStep(
        [&] {
          if (d.options.before_candidate_step)
            d.options.before_candidate_step(joinEffects(d.withInstalled(c.effect)),
                                            full ? "full" : "optimum");
          c.fit = d.calibrateWith(d.withInstalled(c.effect), stage, c.screening_estimate,
                                  c.screening_theta, full);
        },
        [&](const std::string& reason) {
          c.fit.reset();
          c.failed = std::string(full ? "its calibration in full failed: "
                                      : "its confirming calibration failed: ") +
                     reason;
        });
  };
  // First every candidate's optimum (its evidence), then the full calibration (intervals, the
  // posterior's comparison) of those that could be the verdict or ambiguous with it.
  std::vector<std::size_t> optimised;
  std::set<std::size_t> tried;
  auto round = [&](const std::vector<std::size_t>& chosen, int r) {
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      auto& c = cands[chosen[k]];
      tried.insert(chosen[k]);
      const std::string stage = "confirm " + c.effect + on_top + " (" + std::to_string(k + 1) +
                                "/" + std::to_string(chosen.size()) +
                                (r > 0 ? ", round " + std::to_string(r + 1) : "") + ")";
      if (calibrate(c, stage, false)) optimised.push_back(chosen[k]);
    }
  };
  round(to_confirm, 0);
  // The screening score is the weighted SSE the linearised model says a candidate removes. A
  // candidate whose best values move the others far (a controller beside a sensor's fitted place,
  // a delay against a low-pass) may remove three times its score, or a tenth of it: the order
  // within the factor is not to be trusted, so the next rounds of the budget confirm the
  // candidates within it that the first left out.
  // A later round looks for a candidate the screening under-rated: one that removes more than
  // those confirmed. Once one of them leaves no significant lack of fit, the residual is the
  // noise's and no candidate can remove more; the rounds stop.
  auto explained = [&] {
    return std::any_of(optimised.begin(), optimised.end(), [&](std::size_t i) {
      return cands[i].fit->comparison.lack_of_fit_p >= d.options.lack_of_fit_alpha;
    });
  };
  for (int r = 1; r < d.options.confirm_rounds && !explained(); ++r) {
    const auto next = chooseConfirmations(cands, d.options, tried);
    if (next.empty()) break;
    round(next, r);
  }
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i : optimised) best = std::max(best, cands[i].fit->log_evidence);
  const double margin = std::max(d.options.full_within, d.options.ambiguity_log_evidence);
  std::vector<std::size_t> confirmed;
  for (std::size_t i : optimised) {
    auto& c = cands[i];
    c.evidence_gap = best - c.fit->log_evidence;
    // On top of causes already named (a later stage of the stagewise selection) the evidence
    // decides alone; only the final model's intervals are reported, so it alone is calibrated in
    // full, once the selection ends (furtherCauses).
    if (d.installed.empty() && c.evidence_gap <= margin &&
        !calibrate(c, "confirm " + c.effect + " in full", true))
      continue;
    c.confirmed = true;
    c.finding = d.findingOf(c.effect, *c.fit);
    c.inert = isInert(d, c);
    confirmed.push_back(i);
  }
  return confirmed;
}

namespace {

/// The base polished again from every strongly favoured candidate's base parameters (its effect
/// off); when that fits better than the base optimum, the base is re-calibrated from there.
void refineBase(Diagnosis& d, const std::vector<std::size_t>& to_confirm) {
  auto& res = d.res;
  std::vector<double> better;
  double better_sse = res.base.sse_min - 1.0;  // below the integrator's noise in the SSE: no change
  for (std::size_t i : to_confirm) {
    const auto& c = res.candidates[i];
    if (c.fit->bic - res.base.bic >= -d.options.bic_strong) continue;
    if (!d.spec(c.effect).addsParameters()) continue;  // not the base's values plus its own
    auto th = d.optima.at(joinEffects({c.effect}));
    th.resize(d.optima.at("base").size());
    d.isolated("the base's refinement from " + c.effect, [&] {
      d.report("refine base from " + c.effect, 0, 1);
      const auto p = calib::polishLeastSquares(*d.base_obj, th, {d.options.threads});
      d.report("refine base from " + c.effect, 1, 1);
      if (p.sse < better_sse) {
        better_sse = p.sse;
        better = p.theta;
        res.base_refined_from = c.effect;
      }
    });
  }
  if (!better.empty()) {
    Figures refined;
    if (d.isolated("the refined base's calibration",
                   [&] { refined = d.calibrateWith({}, "base (refined)", {}, better); })) {
      res.base_unrefined_sse = res.base.sse_min;
      res.base = std::move(refined);
    } else {
      res.base_refined_from.clear();
    }
  }
}

}  // namespace

/// Refine (the end of step 3): the evidence for an effect must not come from a base optimum the
/// optimiser missed. The base is polished again from every strongly favoured candidate's base
/// parameters (its effect switched off); when that fits better, the base is re-calibrated from
/// there and becomes the reference of every ΔBIC and of the lack-of-fit figures (first stage only:
/// a later stage's reference is the previous stage's confirmed fit). Then each confirmed candidate
/// is weighed against the stage's reference (ΔBIC, share of the base's excess residual it removes,
/// held-out change) and the stage's candidates are ranked: confirmed by log evidence, then by
/// score, gated last.
void refine(Diagnosis& d, const std::vector<std::size_t>& to_confirm) {
  auto& res = d.res;
  auto& cands = d.stage();
  if (d.installed.empty()) refineBase(d, to_confirm);
  const Figures& ref = d.installed.empty() ? res.base : *d.reference;
  for (std::size_t i : to_confirm) weigh(d, cands[i], ref);
  std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) {
    auto cls = [](const Candidate& c) {
      return c.confirmed ? 0 : (c.gate.empty() && c.failed.empty() ? 1 : 2);
    };
    if (cls(a) != cls(b)) return cls(a) < cls(b);
    if (a.confirmed) return a.fit->log_evidence > b.fit->log_evidence;
    return a.score > b.score;
  });
}

/// The structure a candidate changes (docs/diagnosis.md, "Structure first"): where a sensor sits
/// (one per sensor), where the road signal enters, or a subsystem's option; "" for a force, a
/// value or a sensor model.
std::string structureOf(const Candidate& c) {
  if (c.kind == "place") return c.effect;
  if (c.kind == "option") return "option:" + c.effect.substr(0, c.effect.find('='));
  if (c.kind == "input")
    for (const auto& f : roadSignalForms())
      if (c.effect == std::string("free:") + f.name) return "road form";
  return "";
}

/// Structure first (docs/diagnosis.md, "Structure first"). Where the sensor sits, where the road
/// signal enters and which law carries it do not add like forces: each changes how every other
/// part is seen, so each alone may explain less than a force that stands in for it, and the
/// forward stagewise selection, screening on top of one of them, never comes back to the others.
/// So when the first cause is a structure, the best strong candidate of each other structure of
/// the first stage (one per sensor's place, one road form, one per subsystem's option) is weighed
/// on top of the causes so far, in the order of their first-stage evidence, each re-calibrated
/// (to its optimum) and kept as the next cause when strong against the model without it.
void structureFirst(Diagnosis& d, const std::vector<const Candidate*>& named) {
  auto& res = d.res;
  if (named.empty() || structureOf(*named.front()).empty()) return;
  // The other structures' strong candidates, grouped by structure in the order of each group's
  // best first-stage evidence (named is ordered by it).
  std::vector<std::string> keys;
  std::map<std::string, std::vector<Candidate>> groups;
  for (const Candidate* c : named)
    if (const auto s = structureOf(*c); !s.empty() && s != structureOf(*named.front())) {
      if (!groups.count(s)) keys.push_back(s);
      groups[s].push_back(*c);
    }
  for (const auto& key : keys) {
    if (static_cast<int>(res.causes.size()) >= d.options.causes) break;
    d.installed.clear();
    for (const auto& k : res.causes) d.installed.push_back(k.name);
    res.further.push_back({d.installed, {}});
    // Each strong candidate of the structure (the road signal at one corner, or at all four
    // wheels at once) on top of the causes so far: the best of them is the structure's.
    for (auto c : groups.at(key)) {
      // Its own values at the first stage's optimum: a start beside the off values.
      std::vector<double> own;
      for (const auto& p : d.parametersOf(c.effect, *c.fit)) own.push_back(p.optimum);
      if (own.size() != d.spec(c.effect).calibrated_names.size()) own.clear();
      c.fit.reset();
      c.confirmed = false;
      c.holdout_change.reset();
      const std::string stage = "structure " + c.effect + " on " + joinEffects(d.installed);
      if (!d.isolatedStep(
              [&] { c.fit = d.calibrateWith(d.withInstalled(c.effect), stage, own, {}, false); },
              [&](const std::string& reason) {
                c.failed = "its confirming calibration failed: " + reason;
              })) {
        c.fit.reset();
        res.further.back().candidates.push_back(c);
        continue;
      }
      c.confirmed = true;
      c.inert = isInert(d, c);
      c.finding = d.findingOf(c.effect, *c.fit);
      weigh(d, c, res.causes.back().fit);
      res.further.back().candidates.push_back(c);
    }
    auto& cands = res.further.back().candidates;
    std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) {
      if (a.confirmed != b.confirmed) return a.confirmed;
      return a.confirmed && a.fit->log_evidence > b.fit->log_evidence;
    });
    for (auto& c : cands)
      if (c.confirmed) c.evidence_gap = cands.front().fit->log_evidence - c.fit->log_evidence;
    d.reference = &res.causes.back().fit;
    explainStage(d, d.reference->comparison);
    const auto strong = strongOf(cands, d.options);
    if (!strong.empty()) res.causes.push_back(causeOf(*strong.front(), alikeOf(strong, d.options)));
  }
  d.installed.clear();
  for (std::size_t k = 0; k + 1 < res.causes.size(); ++k) d.installed.push_back(res.causes[k].name);
  d.reference = nullptr;
}

/// More than one cause (docs/diagnosis.md, step 4): forward stagewise selection. While the model
/// with the causes named so far leaves a significant lack of fit and fewer than options.causes
/// are named, they are installed, every other candidate is screened and confirmed on top of them
/// (ΔBIC against the model with them), and the best strong one becomes the next cause.
void furtherCauses(Diagnosis& d) {
  auto& res = d.res;
  while (static_cast<int>(res.causes.size()) < d.options.causes &&
         res.causes.back().fit.comparison.lack_of_fit_p < d.options.lack_of_fit_alpha) {
    d.installed.push_back(res.causes.back().name);
    d.reference = &res.causes.back().fit;
    std::vector<std::string> catalogue;
    for (const auto& e : d.catalogue)
      if (std::find(d.installed.begin(), d.installed.end(), e) == d.installed.end())
        catalogue.push_back(e);
    d.catalogue = catalogue;
    res.further.push_back({d.installed, {}});
    // The stage's own screening (the model with the causes so far, linearised) failing ends the
    // selection with the causes named so far; its candidates' failures are their own (confirm).
    if (!d.isolated("the stage on top of " + joinEffects(d.installed), [&] {
          screen(d);
          refine(d, confirm(d));
        })) {
      res.further.pop_back();
      break;
    }
    explainStage(d, d.reference->comparison);
    const auto named = strongOf(d.stage(), d.options);
    if (named.empty()) break;
    res.causes.push_back(causeOf(*named.front(), alikeOf(named, d.options)));
  }
  // Every cause's parameters and finding from the model with all of them (a joint calibration),
  // calibrated in full (its intervals; a later stage stops its candidates at their optimum).
  // If that calibration fails, the causes keep the joint model at its optimum (no intervals).
  if (!res.causes.back().fit.full) {
    const std::vector<std::string> effects = res.causes.back().fit.effects;
    Figures all;
    if (d.isolated("the calibration in full of " + joinEffects(effects), [&] {
          all =
              d.calibrateWith(effects, "final " + joinEffects(effects) + " in full", {}, {}, true);
        }))
      res.causes.back().fit = std::move(all);
  }
  const Figures& all = res.causes.back().fit;
  for (auto& k : res.causes) {
    k.parameters = d.parametersOf(k.name, all);
    k.finding = d.findingOf(k.name, all);
  }
  // The proposal (an unexplained verdict) linearises the base model again.
  d.installed.clear();
  d.reference = nullptr;
  d.base_obj =
      std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets, d.setupOf({}));
}

}  // namespace dtwin::diag
