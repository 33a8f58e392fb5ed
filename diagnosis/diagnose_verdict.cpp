// The verdict of diagnose() (docs/diagnosis.md, step 4): every candidate's why, the cause(s) named
// or the residual left unexplained, and the result's JSON and text.
#include "diagnosis/diagnose_internal.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

#include "common/format.hpp"

namespace dtwin::diag {
namespace {

/// The fraction of Σ z² in [t0, t1] of a series.
double chi2In(const SeriesComparison& s, double t0, double t1) {
  double a = 0.0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= t0 && s.t[i] <= t1 && std::isfinite(s.z[i])) a += s.z[i] * s.z[i];
  return a;
}

/// Where the residual of a comparison lies: the largest windows, the bands above the noise floor,
/// the strongest force-state signature.
std::string locate(const Comparison& c) {
  struct W {
    double share;
    std::string text;
  };
  std::vector<W> ws;
  for (const auto& s : c.series)
    for (const auto& w : s.windows)
      ws.push_back({w.window.share, s.channel + " in " + s.scenario + " " +
                                        fmt("%.3f", w.window.t_begin) + "-" +
                                        fmt("%.3f", w.window.t_end) + " s (" + w.label + ", " +
                                        fmt("%.0f", 100 * w.window.share) + " % of its residual)"});
  std::sort(ws.begin(), ws.end(), [](const W& a, const W& b) { return a.share > b.share; });
  std::string out;
  for (std::size_t i = 0; i < std::min<std::size_t>(2, ws.size()); ++i)
    out += (i ? "; " : "") + ws[i].text;
  std::set<std::string> bands;
  for (const auto& s : c.series)
    for (const auto& b : s.bands)
      if (b.significant) bands.insert(b.band);
  if (!bands.empty()) {
    out += std::string(out.empty() ? "" : "; ") + "residual above the noise floor in the ";
    std::size_t i = 0;
    for (const auto& b : bands) out += (i++ ? ", " : "") + b;
    out += " band" + std::string(bands.size() > 1 ? "s" : "");
  }
  double best = 0.0;
  std::string map;
  for (const auto& cm : c.maps)
    for (const auto& m : cm.maps)
      if (!m.fits.empty() && m.fits[0].explained_fraction > best) {
        best = m.fits[0].explained_fraction;
        map = cm.channel + " vs " + m.state + " looks " + m.fits[0].feature +
              (m.fits[0].feature == "knee" ? " (beyond " + fmt("%.3g", m.fits[0].knee_at) + ")"
                                           : "") +
              " (" + fmt("%.0f", 100 * best) + " % of the map)";
      }
  if (!map.empty() && best > 0.3)
    out += std::string(out.empty() ? "" : "; ") + "force-state map: " + map;
  return out.empty() ? "no localised structure" : out;
}

/// The window of the base residual a confirmed candidate fixes most, in words ("" if none).
std::string windowFixed(const Comparison& base, const Comparison& with) {
  double best_drop = 0.0;
  std::string where;
  for (std::size_t i = 0; i < base.series.size() && i < with.series.size(); ++i)
    for (const auto& win : base.series[i].windows) {
      const double before = chi2In(base.series[i], win.window.t_begin, win.window.t_end);
      const double after = chi2In(with.series[i], win.window.t_begin, win.window.t_end);
      if (before - after > best_drop) {
        best_drop = before - after;
        where = "removes " + fmt("%.0f", before > 0 ? 100 * (before - after) / before : 0.0) +
                " % of the residual of " + base.series[i].channel + " in " +
                base.series[i].scenario + " " + fmt("%.3f", win.window.t_begin) + "-" +
                fmt("%.3f", win.window.t_end) + " s (" + win.label + ")";
      }
    }
  return where;
}

/// The frequency band a confirmed candidate lowers most (of those > 2x the noise floor), in words.
std::string bandFixed(const Comparison& base, const Comparison& with) {
  double band_drop = 0.0;
  std::string band;
  for (std::size_t i = 0; i < base.series.size() && i < with.series.size(); ++i)
    for (std::size_t b = 0; b < base.series[i].bands.size() && b < with.series[i].bands.size();
         ++b) {
      const double before = base.series[i].bands[b].ratio, after = with.series[i].bands[b].ratio;
      if (before - after > band_drop && before > 2.0) {
        band_drop = before - after;
        band = base.series[i].bands[b].band + " band of " + base.series[i].channel + " from " +
               fmt("%.3g", before) + "x to " + fmt("%.3g", after) + "x the noise floor";
      }
    }
  return band;
}

/// The effect's residual signature (Effect::residualSignature) as the base residual shows it, in
/// words ("" if the effect names none or it explains <= 10 % of its map).
std::string signatureSeen(const Comparison& base, const CandidateSpec& candidate) {
  const ResidualSignature& sig = candidate.residual_signature;
  if (sig.state_map.empty()) return "";
  double ef = 0.0;
  std::string txt;
  for (const auto& cm : base.maps)
    for (const auto& m : cm.maps)
      if (m.state.rfind(sig.state_map, 0) == 0)
        for (const auto& f : m.fits)
          if (f.feature == sig.feature && f.explained_fraction > ef) {
            ef = f.explained_fraction;
            txt = cm.channel + " vs " + m.state + " shows a " + f.feature +
                  (f.feature == "knee" ? " beyond " + fmt("%.3g", f.knee_at) : "") + " (" +
                  fmt("%.0f", 100 * ef) + " % of that map)";
          }
  return !txt.empty() && ef > 0.1 ? txt : "";
}

/// One plain sentence per candidate: why it is ranked where it is.
/// `best_score`: the best screening score of the ungated candidates.
std::string whyOf(const Candidate& c, const CandidateSpec& spec, const Comparison& base,
                  const DiagnoseOptions& options, double best_score) {
  if (!c.failed.empty())
    return c.effect + ": failed, left out of the verdict: " + c.failed +
           (c.failed.back() == '.' ? "" : ".");
  if (!c.gate.empty()) return c.effect + ": not a candidate: " + c.gate + ".";
  if (!c.confirmed)
    return c.effect + ": screening score " + fmt("%.3g", c.score) +
           " (p = " + fmt("%.2g", c.p_value) + ")" +
           (c.p_value < options.screen_alpha
                ? (c.score * options.confirm_within >= best_score
                       ? ", within a factor " + fmt("%.3g", options.confirm_within) +
                             " of the best score but beyond the budget of " +
                             std::to_string(options.candidates) + " confirmations per round and " +
                             std::to_string(options.confirm_rounds) + " rounds (--candidates)"
                       : ", more than a factor " + fmt("%.3g", options.confirm_within) +
                             " below the best score and not the best of its kind: not confirmed")
                : ": explains nothing beyond noise") +
           ".";
  std::string s = c.effect + ": " + (c.delta_bic < 0 ? "ΔBIC " : "ΔBIC +") +
                  fmt("%.1f", c.delta_bic) + ", explains " + fmt("%.0f", 100 * c.explained) +
                  " % of the excess residual";
  if (c.inert)
    s += "; its parameters stay at their off values, so it is no cause (the change is the "
         "reference's optimum polished further)";
  const std::string where = windowFixed(base, c.fit->comparison);
  if (!where.empty()) s += "; " + where;
  const std::string band = bandFixed(base, c.fit->comparison);
  if (!band.empty()) s += "; lowers the " + band;
  if (!c.finding.empty() && c.delta_bic < 0) s += "; " + c.finding;
  if (!c.fit->full)
    s += c.evidence_gap <= std::max(options.full_within, options.ambiguity_log_evidence)
             ? "; calibrated to its optimum (on top of causes already named the evidence decides; "
               "the final model alone is calibrated "
               "in full)"
             : "; calibrated to its optimum only (log evidence " + fmt("%.1f", c.evidence_gap) +
                   " below the best candidate's: it can be neither the verdict nor ambiguous with "
                   "it, so no intervals)";
  const std::string sig = signatureSeen(base, spec);
  if (!sig.empty()) s += "; its signature is in the data: " + sig;
  if (c.holdout_change) s += "; held-out systematic error x" + fmt("%.2f", *c.holdout_change);
  return s + ".";
}

/// A candidate's finding in words, or its name when it has none (an effect).
std::string inWordsOf(const Candidate& c) {
  return c.finding.empty() ? inWords(c.effect) + " (" + c.effect + ")"
                           : c.finding + " (" + c.effect + ")";
}

/// What would tell `a` from `b` apart, in words.
std::string separatedBy(const Candidate& a, const Candidate& b) {
  auto timing = [](const Candidate& c) {
    return c.effect.rfind("lowpass", 0) == 0 || c.effect.rfind("delay", 0) == 0;
  };
  const auto factorOf = [](const Candidate& c) {
    return parseCornerFactor(c.effect.rfind("free:", 0) == 0 ? c.effect.substr(5) : "");
  };
  if (const auto fa = factorOf(a), fb = factorOf(b); fa && fb) {
    if (fa->value == fb->value && fa->place >= 4 && fb->place >= 4)
      return "they are one model while the whole " + fa->value +
             " is calibrated: only the ratio between the axles is known";
    return "a scenario that loads the corners unevenly (a bump under one wheel, a roll or warp "
           "input) or a force or travel "
           "channel at each corner would separate them";
  }
  if (timing(a) && timing(b))
    return "a step input or the phase above 20 Hz would separate them (a delay shifts the phase in "
           "proportion to frequency "
           "and keeps the amplitude; a low-pass lowers the amplitude too)";
  if (a.kind != b.kind)
    return "a scenario that excites one and not the other (another speed, a step, a sweep) would "
           "separate them";
  return "more data (another scenario) would separate them";
}

/// The look-alikes of the named candidate `best` (within ambiguity_log_evidence), in words: "The
/// data cannot yet tell it from: the hub_force channels look delayed by 8 ms (delay:hub_force);
/// they differ by ΔBIC 3.1; a step input ... would separate them."
std::string lookAlikes(const Candidate& best, const std::vector<const Candidate*>& alike,
                       const DiagnoseOptions& options) {
  std::string s = "Ambiguous: " + inWordsOf(best);
  for (const Candidate* c : alike) s += " or " + inWordsOf(*c);
  if (alike.size() == 1) {
    s += ": they differ by ΔBIC " + fmt("%.1f", alike.front()->fit->bic - best.fit->bic);
  } else {
    s += ": behind the first by ΔBIC ";
    for (std::size_t i = 0; i < alike.size(); ++i)
      s += (i ? ", " : "") + fmt("%.1f", alike[i]->fit->bic - best.fit->bic) + " (" +
           alike[i]->effect + ")";
  }
  s += ", less than " + fmt("%.0f", 2 * options.ambiguity_log_evidence) + "; " +
       separatedBy(best, *alike.front()) + ".";
  return s;
}

}  // namespace

/// Every candidate's why line of the current stage, against its reference comparison `ref`.
void explainStage(Diagnosis& d, const Comparison& ref) {
  auto& cands = d.stage();
  double best_score = 0;
  for (const auto& c : cands)
    if (c.gate.empty() && c.failed.empty()) best_score = std::max(best_score, c.score);
  for (auto& c : cands) {
    const auto& spec = d.spec(c.effect);
    c.why = whyOf(c, spec, ref, d.options, best_score);
    if (!spec.range_note.empty())
      c.why.insert(c.why.size() - 1, " (" + spec.range_note + ")");  // before the full stop
  }
}

/// The confirmed candidates with strong evidence (ΔBIC < −bic_strong against the stage's
/// reference), best first.
std::vector<const Candidate*> strongOf(const std::vector<Candidate>& cands,
                                       const DiagnoseOptions& options) {
  std::vector<const Candidate*> named;
  for (const auto& c : cands)
    if (c.confirmed && c.delta_bic < -options.bic_strong && !c.inert) named.push_back(&c);
  return named;
}

/// The strong candidates within ambiguity_log_evidence of the first.
std::vector<const Candidate*> alikeOf(const std::vector<const Candidate*>& named,
                                      const DiagnoseOptions& options) {
  std::vector<const Candidate*> alike;
  for (std::size_t i = 1; i < named.size(); ++i)
    if (named.front()->fit->log_evidence - named[i]->fit->log_evidence <
        options.ambiguity_log_evidence)
      alike.push_back(named[i]);
  return alike;
}

/// The cause a stage names: its best strong candidate, with its look-alikes.
Cause causeOf(const Candidate& c, const std::vector<const Candidate*>& alike) {
  Cause k;
  k.name = c.effect;
  k.kind = c.kind;
  k.finding = c.finding;
  k.delta_bic = c.delta_bic;
  k.explained = c.explained;
  k.fit = *c.fit;
  for (const Candidate* a : alike) k.ambiguous_with.push_back(a->effect);
  return k;
}

namespace {

/// A cause in one sentence: "Wrong vehicle value: the wheel mass is about 35 kg, not 29.46 kg
/// (free:wheel.mass_kg, ΔBIC −512.3, explains 64 % of the excess residual)".
std::string causeInWords(const Cause& k) {
  const std::string evidence = "ΔBIC " + fmt("%.1f", k.delta_bic) + ", explains " +
                               fmt("%.0f", 100 * k.explained) + " % of the excess residual";
  if (const auto f =
          parseCornerFactor(k.name.rfind("free:", 0) == 0 ? k.name.substr(5) : std::string());
      k.kind == "parameter" && f)
    return std::string(f->place < 4 ? "Fault at one corner: " : "Fault on one axle: ") + k.finding +
           " (" + k.name + ", " + evidence + ")";
  if (k.kind == "parameter")
    return "Wrong vehicle value: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "sensor")
    return "Sensor distortion: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "input") return "Road signal: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "place")
    return "Sensor place: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "range")
    return "Far from the prior: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.kind == "option") return "Structure: " + k.finding + " (" + k.name + ", " + evidence + ")";
  if (k.name.find('@') != std::string::npos)
    return "Missing effect at one corner: " + inWords(k.name) + " (" + k.name + ", " + evidence +
           ")";
  return "Missing effect: " + k.name + " (" + evidence + ")";
}

/// The summary of a verdict "effect": the cause, or the causes strongest first, and how far the
/// integrator's jitter limits the evidence.
std::string effectSummary(const Diagnosis& d, const Candidate& best,
                          const std::vector<const Candidate*>& alike) {
  const auto& res = d.res;
  const auto& options = d.options;
  const Cause& first = res.causes.front();
  std::string s;
  if (res.causes.size() == 1) {
    s = causeInWords(first) + ".";
  } else {
    double total = 0;
    for (const auto& k : res.causes) total += k.explained;
    s = std::to_string(res.causes.size()) +
        " causes, each strong against the model with those before it (together " +
        fmt("%.0f", 100 * std::min(1.0, total)) + " % of the excess residual):";
    std::string apply;
    for (std::size_t i = 0; i < res.causes.size(); ++i) {
      s += " " + std::to_string(i + 1) + ". " + causeInWords(res.causes[i]) + ".";
      apply += (i ? "," : "") + res.causes[i].name;
    }
    s += " Apply them together with --apply " + apply + ".";
  }
  // The evidence is a difference of two minimised SSEs, each as uncertain as the integrator's
  // jitter.
  const double jitter = res.base.integrator.jitter + first.fit.integrator.jitter;
  if (!first.fit.integrator.ok || !res.base.integrator.ok)
    s += -first.delta_bic > options.bic_strong + 2 * jitter
             ? " The integrator's jitter in the SSE (" + fmt("%.3g", jitter) +
                   ") is far below this evidence, so the verdict stands, but " +
                   (first.fit.integrator.ok
                        ? std::string("the base calibration's intervals do not (note below); the "
                                      "model with the cause's do")
                        : std::string("the intervals do not (note below)")) +
                   "."
             : " Caution: the integrator's jitter in the SSE (" + fmt("%.3g", jitter) +
                   ") is comparable with this evidence: tighten [simulation] accuracy and rerun "
                   "before trusting the verdict (note below).";
  if (!alike.empty()) s += " " + lookAlikes(best, alike, options);
  return s;
}

}  // namespace

/// The lead's own structure weighed with the others installed (docs/diagnosis.md, "Structure
/// first"): when structure first added other structures to a lead that is itself a structure,
/// each other strong candidate of the lead's structure (the road signal at another corner, or at
/// all four wheels) leads instead, structure first runs again from it, and the model with the
/// lower BIC stands. A road form that fits best alone (the signal at every wheel, standing in for
/// an accelerometer's place) may fit worse than another once the place is found.
namespace {
void leadAlternatives(Diagnosis& d, const std::vector<const Candidate*>& named) {
  auto& res = d.res;
  const std::string key = structureOf(*named.front());
  if (key.empty() || res.causes.size() < 2) return;
  auto words = [](const std::vector<Cause>& c) {
    std::string w;
    for (const auto& k : c) w += (w.empty() ? "" : " + ") + k.name;
    return w;
  };
  for (const Candidate* a : named) {
    if (a == named.front() || structureOf(*a) != key) continue;
    auto chain = std::move(res.causes);
    auto stages = std::move(res.further);
    res.causes = {causeOf(*a, {})};
    res.further.clear();
    std::vector<const Candidate*> from{a};
    for (const Candidate* c : named)
      if (c != a) from.push_back(c);
    const bool ran =
        d.isolated("the structures from " + a->effect, [&] { structureFirst(d, from); });
    const bool weighed = ran && res.causes.size() >= 2;
    const bool better = weighed && res.causes.back().fit.bic < chain.back().fit.bic;
    if (weighed)
      res.structure_note += (res.structure_note.empty() ? "" : " ") + std::string("With ") +
                            a->effect + " leading instead, " + words(res.causes) + " reaches BIC " +
                            fmt("%.1f", res.causes.back().fit.bic) + " against " +
                            fmt("%.1f", chain.back().fit.bic) + " for " + words(chain) + ": " +
                            (better ? "it stands." : "the latter stands.");
    if (!better) {
      res.causes = std::move(chain);
      res.further = std::move(stages);
    }
    d.installed.clear();
    for (std::size_t k = 0; k + 1 < res.causes.size(); ++k)
      d.installed.push_back(res.causes[k].name);
    d.reference = nullptr;
  }
}
}  // namespace

/// Verdict (step 4): every candidate's why, then "effect" (the best confirmed candidate with
/// ΔBIC < −bic_strong, and the causes stagewise selection adds on top of it, which together leave
/// no significant lack of fit or explain at least explained_min of the excess; ambiguity
/// stated), "none" (no significant lack of fit in the base: nothing to explain, whatever a
/// candidate's ΔBIC) or "unexplained" (with where).
void verdict(Diagnosis& d) {
  auto& res = d.res;
  const auto& options = d.options;
  const Comparison& base = res.base.comparison;
  explainStage(d, base);
  const double alpha = options.lack_of_fit_alpha;
  const bool base_bad = base.lack_of_fit_p < alpha;
  const auto named = strongOf(res.candidates, options);
  res.unexplained_location = locate(base);
  if (named.empty()) {
    if (base_bad) {
      res.verdict = "unexplained";
      res.summary = "Unexplained residual: the base model leaves a significant lack of fit (z = " +
                    fmt("%.1f", base.lack_of_fit_z) +
                    ") that no catalogue effect explains. Where: " + res.unexplained_location + ".";
    } else {
      res.verdict = "none";
      res.summary =
          "No missing effect found: the residual is consistent with the measurement noise (lack of "
          "fit z = " +
          fmt("%.1f", base.lack_of_fit_z) + ", p = " + fmt("%.2g", base.lack_of_fit_p) +
          ") and no catalogue effect passes the screening and the evidence test.";
    }
    return;
  }
  if (!base_bad) {
    // The base fits to the noise: there is no excess residual for a cause to explain. A candidate
    // may still lower the BIC by fitting the noise a little better (or a trace the log's own
    // processing leaves, such as its resampling); it is reported, not named.
    std::string best;
    for (std::size_t i = 0; i < named.size() && i < 3; ++i)
      best += (i ? ", " : "") + named[i]->effect + " ΔBIC " + fmt("%.1f", named[i]->delta_bic);
    res.verdict = "none";
    res.summary =
        "No missing effect found: the residual is consistent with the measurement noise (lack of "
        "fit z = " +
        fmt("%.1f", base.lack_of_fit_z) + ", p = " + fmt("%.2g", base.lack_of_fit_p) +
        "). Candidates that fit it slightly better (" + best +
        ") have no excess residual to explain and are not named; --apply adds one to see what it "
        "changes.";
    return;
  }
  const auto alike = alikeOf(named, options);
  res.causes.push_back(causeOf(*named.front(), alike));
  const auto catalogue = d.catalogue;
  structureFirst(d, named);
  leadAlternatives(d, named);
  furtherCauses(d);
  // Another structure (a subsystem option) is not nested in the forces found on the first cause's
  // model: a car whose road enters at the hub and whose struts carry a controller may fit worse
  // with the hub input alone than with a tire and a delay, and better with both changes. So each
  // strong option that the chain did not take is weighed at its best: the stagewise selection is
  // run again from it, and the chain whose final model has the lower BIC is the verdict.
  const Candidate* lead = named.front();
  for (const Candidate* c : named)
    if (c->effect == res.causes.front().name) lead = c;  // another of its structure leads instead
  for (const Candidate* o : named) {
    if (o->kind != "option" || o == named.front()) continue;
    if (std::any_of(res.causes.begin(), res.causes.end(),
                    [&](const Cause& k) { return k.name == o->effect; }))
      continue;
    auto chain = std::move(res.causes);
    auto stages = std::move(res.further);
    res.causes = {causeOf(*o, {})};
    res.further.clear();
    d.catalogue = catalogue;
    if (!d.isolated("the chain from the structure " + o->effect, [&] { furtherCauses(d); })) {
      res.causes = std::move(chain);  // the first chain stands
      res.further = std::move(stages);
      d.installed.clear();
      d.reference = nullptr;
      d.base_obj =
          std::make_unique<calib::LabObjective>(d.study, d.assembly, d.fit_sets, d.setupOf({}));
      continue;
    }
    const double bic_chain = chain.back().fit.bic, bic_alt = res.causes.back().fit.bic;
    auto words = [](const std::vector<Cause>& c) {
      std::string w;
      for (const auto& k : c) w += (w.empty() ? "" : " + ") + k.name;
      return w;
    };
    const std::string weighed = "The structure " + o->effect +
                                " was weighed at its best: " + words(res.causes) + " reaches BIC " +
                                fmt("%.1f", bic_alt) + ", " + words(chain) + " BIC " +
                                fmt("%.1f", bic_chain);
    if (bic_alt < bic_chain) {
      res.structure_note = weighed + ": the first is kept.";
      lead = o;
    } else {
      res.structure_note = weighed + ": the second is kept.";
      res.causes = std::move(chain);
      res.further = std::move(stages);
    }
  }
  d.catalogue = catalogue;
  const Cause& last = res.causes.back();
  double total = 0;
  for (const auto& k : res.causes) total += k.explained;
  const bool after_bad = last.fit.comparison.lack_of_fit_p < alpha;
  if (after_bad && total < options.explained_min) {
    res.verdict = "unexplained";
    res.unexplained_location = locate(last.fit.comparison);
    std::string names;
    for (std::size_t i = 0; i < res.causes.size(); ++i)
      names += (i ? (i + 1 == res.causes.size() ? " and " : ", ") : "") + res.causes[i].name;
    res.summary = std::string("Unexplained residual: the best catalogue ") +
                  (res.causes.size() == 1 ? "effect, " : "causes, ") + names + ", explain" +
                  (res.causes.size() == 1 ? "s" : "") + " only " + fmt("%.0f", 100 * total) +
                  " % of the excess residual and a significant lack of fit remains (z = " +
                  fmt("%.1f", last.fit.comparison.lack_of_fit_z) + "); " +
                  (res.causes.size() == 1 ? "it is" : "they are") +
                  " not named. Where: " + res.unexplained_location + ".";
    return;
  }
  res.verdict = "effect";
  const Cause& first = res.causes.front();
  res.named_effect = first.name;
  res.named_kind = first.kind;
  res.finding = first.finding;
  res.ambiguous_with = first.ambiguous_with;
  res.summary =
      lead == named.front() ? effectSummary(d, *lead, alike) : effectSummary(d, *lead, {});
  if (!res.structure_note.empty()) res.summary += " " + res.structure_note;
  if (after_bad)
    res.summary += " A smaller significant residual remains (z = " +
                   fmt("%.1f", last.fit.comparison.lack_of_fit_z) +
                   "): " + locate(last.fit.comparison) + ".";
}

namespace {
/// The "screening" (every candidate) and "ranked" (the confirmed ones) arrays of one stage into
/// `j`; `ref_log_evidence`: the stage's reference model's.
void candidatesJson(const std::vector<Candidate>& candidates, double ref_log_evidence,
                    nlohmann::json& j) {
  j["ranked"] = nlohmann::json::array();
  j["screening"] = nlohmann::json::array();
  for (const auto& c : candidates) {
    nlohmann::json s{{"effect", c.effect},   {"kind", c.kind},
                     {"score", c.score},     {"score_dof", c.score_dof},
                     {"p_value", c.p_value}, {"max_signal", c.max_signal},
                     {"gate", c.gate},       {"confirmed", c.confirmed},
                     {"why", c.why},         {"signature", c.signature}};
    if (!c.failed.empty()) s["failed"] = c.failed;
    j["screening"].push_back(s);
    if (!c.confirmed) continue;
    nlohmann::json r{{"effect", c.effect},
                     {"log_evidence", c.fit->log_evidence},
                     {"log_evidence_vs_base", c.fit->log_evidence - ref_log_evidence},
                     {"delta_bic", c.delta_bic},
                     {"explained_fraction", c.explained},
                     {"kind", c.kind},
                     {"finding", c.finding},
                     {"parameters", paramsJson(c.fit->effect_parameters)},
                     {"why", c.why},
                     {"fit", c.fit->toJson()}};
    if (c.holdout_change) r["holdout_systematic_rms_ratio"] = *c.holdout_change;
    j["ranked"].push_back(r);
  }
}
}  // namespace

nlohmann::json DiagnosisResult::toJson() const {
  nlohmann::json j;
  j["assembly"] = assembly;
  j["verdict"] = verdict;
  j["summary"] = summary;
  if (!named_effect.empty()) {
    j["effect"] = named_effect;
    j["kind"] = named_kind;
    j["finding"] = finding;
  }
  j["ambiguous_with"] = ambiguous_with;
  if (!structure_note.empty()) j["structure_note"] = structure_note;
  if (verdict != "none") j["unexplained_location"] = unexplained_location;
  j["fitted_channels"] = fitted_channels;
  j["left_out_channels"] = left_out_channels;
  j["failed"] = nlohmann::json::array();  // every candidate that failed, of every stage, and what
                                          // failed beyond one
  for (const auto& c : candidates)
    if (!c.failed.empty()) j["failed"].push_back({{"candidate", c.effect}, {"reason", c.failed}});
  for (const auto& st : further)
    for (const auto& c : st.candidates)
      if (!c.failed.empty())
        j["failed"].push_back(
            {{"candidate", c.effect}, {"on_top_of", st.installed}, {"reason", c.failed}});
  for (const auto& f : failures) j["failed"].push_back({{"reason", f}});
  j["base"] = base.toJson();
  if (!base_refined_from.empty())
    j["base_refined"] = {{"from", base_refined_from},
                         {"sse_min_weighted_before", base_unrefined_sse}};
  candidatesJson(candidates, base.log_evidence, j);
  j["causes"] = nlohmann::json::array();
  for (const auto& k : causes) {
    nlohmann::json c{{"name", k.name},
                     {"kind", k.kind},
                     {"finding", k.finding},
                     {"delta_bic", k.delta_bic},
                     {"explained_fraction", k.explained},
                     {"lack_of_fit_z_after", k.fit.comparison.lack_of_fit_z},
                     {"parameters", paramsJson(k.parameters)},
                     {"ambiguous_with", k.ambiguous_with},
                     {"folder", k.fit.folder}};
    j["causes"].push_back(c);
  }
  j["further_stages"] = nlohmann::json::array();
  for (const auto& st : further) {
    nlohmann::json f{{"installed", st.installed}};
    // The stage's reference: the model with its installed causes.
    double ref = base.log_evidence;
    for (const auto& k : causes)
      if (k.fit.effects == st.installed) ref = k.fit.log_evidence;
    candidatesJson(st.candidates, ref, f);
    j["further_stages"].push_back(f);
  }
  j["evidence_estimator"] =
      "BIC = SSE_w,min + k ln n with SSE_w = sum of (y - eta)^2 / sigma_c^2 (sigma_c^2 from the "
      "repetitions); log evidence ~ -BIC/2";
  if (!proposal.empty() || !proposal_note.empty()) {
    j["proposal"] = {{"note", proposal_note}, {"terms", nlohmann::json::array()}};
    for (const auto& t : proposal) j["proposal"]["terms"].push_back(t.toJson());
  }
  if (!steps.empty()) {
    j["before"] = steps.front().toJson();
    j["after"] = steps.back().toJson();
    j["steps"] = nlohmann::json::array();
    for (const auto& s : steps) j["steps"].push_back(s.toJson());
  }
  return j;
}

std::string DiagnosisResult::proposalToml() const {
  std::string s;
  for (const auto& t : proposal) s += (s.empty() ? "" : "\n") + t.toml();
  return s;
}

std::string DiagnosisResult::text() const {
  std::string s;
  s += "Diagnosis of " + assembly + ": " + verdict + "\n  " + summary + "\n\n";
  if (!base_refined_from.empty())
    s += "  (The base optimum was improved from " + base_refined_from +
         "'s fit with the effect off: weighted SSE " + fmt("%.1f", base_unrefined_sse) + " -> " +
         fmt("%.1f", base.sse_min) + "; every ΔBIC is against the improved base.)\n\n";
  if (!base.bounds.empty()) {
    s += "Values on their bounds (the base calibration; docs/calibration.md):\n" +
         calib::boundFindingsText(base.bounds, "  ") + "\n";
  }
  s += "Ranked candidates (confirmed by re-calibration first):\n";
  int k = 0;
  for (const auto& c : candidates) s += "  " + std::to_string(++k) + ". " + c.why + "\n";
  for (const auto& st : further) {
    s += "\nOn top of " + joinEffects(st.installed) + " (ΔBIC against the model with it):\n";
    k = 0;
    for (const auto& c : st.candidates)
      if (c.confirmed || c.gate.empty()) s += "  " + std::to_string(++k) + ". " + c.why + "\n";
  }
  if (causes.size() > 1) {
    s += "\nCauses (forward stagewise, strongest first; parameters from the joint fit " +
         causes.back().fit.folder + "):\n";
    for (const auto& c : causes) {
      s += "  " + c.name + ": explains " + fmt("%.0f", 100 * c.explained) +
           " % of the excess residual (ΔBIC " + fmt("%.1f", c.delta_bic) + "; lack of fit z " +
           fmt("%.1f", c.fit.comparison.lack_of_fit_z) + " after it)\n";
      for (const auto& p : c.parameters)
        s += "    " + p.name + ": optimum " + fmt("%.4g", p.optimum) + " " + p.unit +
             (p.interval == "none" ? std::string()
                                   : "  (95 % " + p.interval + " [" + fmt("%.4g", p.q025) + ", " +
                                         fmt("%.4g", p.q975) + "])") +
             "\n";
    }
  }
  if (!failures.empty()) {
    s += "\nFailed (the diagnosis went on without it):\n";
    for (const auto& f : failures) s += "  " + f + "\n";
  }
  if (!causes.empty() && causes.back().fit.full && !causes.back().fit.values.empty()) {
    const Figures& all = causes.back().fit;
    s += "\nThe model with " + (causes.size() > 1 ? std::string("every cause") : "the cause") +
         " (" + joinEffects(all.effects) + "), its calibrated values:\n";
    for (const auto& p : all.values)
      s += "  " + p.name + ": optimum " + fmt("%.5g", p.optimum) + " " + p.unit + "  (95 % " +
           p.interval + " [" + fmt("%.5g", p.q025) + ", " + fmt("%.5g", p.q975) + "])\n";
    if (!all.left_out.empty()) {
      s += "  (left out, this model has no such value:";
      for (const auto& n : all.left_out) s += " " + n;
      s += ")\n";
    }
    if (!all.bounds.empty()) s += calib::boundFindingsText(all.bounds, "  ");
  }
  for (const auto& c : candidates)
    if (c.confirmed && c.fit->full && !c.fit->effect_parameters.empty()) {
      bool named = false;
      for (const auto& k : causes) named = named || k.name == c.effect;
      s += "\n  " + c.effect + " posterior" +
           (named || causes.empty() ? "" : " (calibrated in full; not among the causes)") + ":\n";
      const bool resolved = c.fit->importance_ess >= Figures::kResolvedEss;
      for (const auto& p : c.fit->effect_parameters) {
        // An unresolved design (a posterior on a handful of points) gives a mean and an sd that
        // mean nothing: the optimum is printed instead, with the profile interval.
        s += "    " + p.name +
             (resolved ? " = " + fmt("%.4g", p.mean) + " ± " + fmt("%.2g", p.sd)
                       : ": optimum " + fmt("%.4g", p.optimum)) +
             " " + p.unit + "  (95 % " +
             (p.interval == "profile" ? "profile likelihood" : "posterior") + " [" +
             fmt("%.4g", p.q025) + ", " + fmt("%.4g", p.q975) + "])" +
             (c.fit->integrator.ok ? ""
                                   : "  NOT TO BE TRUSTED: the integrator limits it (note below)") +
             (resolved || p.interval == "profile"
                  ? ""
                  : "  NOT TO BE TRUSTED: the posterior is not resolved") +
             "\n";
      }
      if (!resolved)
        s += "    (the posterior is not resolved: importance ESS " +
             fmt("%.1f", c.fit->importance_ess) + " < " + fmt("%.0f", Figures::kResolvedEss) +
             ", so no mean ± sd; raise --lhs-points, or [calibration] round_points or max_rounds "
             "in the study; see " +
             c.fit->folder + "/summary.json)\n";
    }
  // Every calibration whose integrator check failed (the base, the confirmed candidates, the
  // steps).
  std::vector<const Figures*> fits{&base};
  for (const auto& c : candidates)
    if (c.fit) fits.push_back(&*c.fit);
  for (const auto& st : steps) fits.push_back(&st);
  std::set<std::string> noted;
  for (const auto* f : fits)
    if (!f->integrator.ok && noted.insert(f->folder).second)
      s += "\n  note (" + f->label + ", " + f->folder + "): " + f->integrator.message + "\n";
  if (!proposal.empty()) {
    s += "\nProposed terms (strut force a * TERM at every strut; ready to paste into the study "
         "file):\n";
    for (const auto& t : proposal)
      s += "  " + t.name + ": " + t.force + ", a ≈ " + fmt("%.3g", t.coefficient) + " " + t.unit +
           (t.gap > 0 ? ", g = " + fmt("%.3g", t.gap) + " m" : "") + ", ΔBIC " +
           fmt("%.1f", t.delta_bic) + ", explains " + fmt("%.0f", 100 * t.explained) +
           " % of the excess residual\n";
    s += "\n" + proposalToml();
  }
  if (!left_out_channels.empty()) {
    s += "\n  Compared but not fitted: ";
    for (std::size_t i = 0; i < left_out_channels.size(); ++i)
      s += (i ? "; " : "") + left_out_channels[i];
    s += "\n";
  }
  if (!steps.empty()) {
    s += "\nBefore/after (effects added in turn):\n";
    s += formatPrintf("  %-40s %12s %12s %10s %12s\n", "model", "syst. RMS/σ", "coverage",
                      "log evid.", "Δ log evid.");
    for (const auto& st : steps) {
      double cov = 0.0;
      for (const auto& x : st.comparison.series)
        cov += x.coverage / static_cast<double>(st.comparison.series.size());
      s += formatPrintf("  %-40s %12.3f %11.1f%% %10.1f %12.1f\n", st.label.c_str(),
                        st.comparison.systematic_rms_sd, 100 * cov, st.log_evidence,
                        st.log_evidence - steps.front().log_evidence);
    }
    s += "\n  Per channel (RMS, NRMSE):\n";
    for (std::size_t i = 0; i < steps.front().comparison.series.size(); ++i) {
      const auto& f = steps.front().comparison.series[i];
      std::string line = "    " + f.scenario + " " + f.channel + ":";
      for (const auto& st : steps)
        if (i < st.comparison.series.size())
          line += "  " + fmt("%.4g", st.comparison.series[i].rms) + " (" +
                  fmt("%.3f", st.comparison.series[i].nrmse) + ")";
      s += line + "\n";
    }
  }
  return s;
}

}  // namespace dtwin::diag
