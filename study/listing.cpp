// `twin list`: what a study holds, and every registry of the twin (study/listing.hpp).
#include "study/listing.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "common/format.hpp"
#include "io/study.hpp"
#include "subsystems/user_effect.hpp"
#include "twin/road_setting.hpp"
#include "twin/simulator.hpp"

namespace dtwin {
namespace {

/// "[lo, hi]" of a parameter's valid range: "(" when the lower end is excluded, "∞" with a round
/// bracket for no bound.
std::string validRange(const ParameterSpec& p) {
  auto end = [](double v) {
    return std::isinf(v) ? std::string(v < 0 ? "−∞" : "∞") : formatNumber(v);
  };
  return std::string(p.min_inclusive && std::isfinite(p.min_value) ? "[" : "(") + end(p.min_value) +
         ", " + end(p.max_value) + (std::isfinite(p.max_value) ? "]" : ")");
}

/// A parameter list for a table cell: "`name` [unit] valid range, ...".
std::string parameterCell(const std::vector<ParameterSpec>& params, bool with_prior) {
  std::string out;
  for (const auto& p : params) {
    out += (out.empty() ? "" : "; ") + ("`" + p.name + "` [" + p.unit + "] " + validRange(p));
    if (with_prior)
      out += ", off " + formatNumber(p.default_value) + ", prior [" + formatNumber(p.prior_lower) +
             ", " + formatNumber(p.prior_upper) + "]";
  }
  return out.empty() ? "–" : out;
}

/// One registry as a Markdown table between markers (docs/registries.md is this output).
template <class Value, class Extra>
void printRegistry(std::string& out, const Registry<Value>& r, const std::string& title,
                   const std::string& extra_header, Extra extra) {
  out += formatPrintf("\n## %s\n\n| %s | description |%s\n|---|---|%s\n", title.c_str(),
                      r.what().c_str(),
                      extra_header.empty() ? "" : (" " + extra_header + " |").c_str(),
                      extra_header.empty() ? "" : "---|");
  for (const auto& e : r) {
    out += formatPrintf("| `%s` | %s |", e.name.c_str(), e.description.c_str());
    if (!extra_header.empty()) out += formatPrintf(" %s |", extra(e.value).c_str());
    out += formatPrintf("\n");
  }
}

}  // namespace

std::string registriesMarkdown(const Registry<bool>& commands) {
  std::string out = formatPrintf(
      "# Registries\n\nEvery extension point of the twin, as its registry holds it "
      "(common/registry.hpp). This page is\n"
      "written by `twin list --registries > docs/registries.md`, and a test fails when it and the\n"
      "registries differ (tests/docs/registry_docs_test.cpp): edit the registry, then "
      "regenerate.\n");
  const auto none = [](const auto&) { return std::string(); };
  printRegistry(out, tireLawRegistry(), "Tire laws (`[subsystems] tire`)",
                "parameters (`tire.NAME` or `tire.LAW.NAME`)", [](const Factory<TireLaw>& make) {
                  return parameterCell(make()->parameters(), false);
                });
  printRegistry(
      out, strutLawRegistry(), "Strut laws (`[subsystems] strut`)",
      "parameters (`suspension.NAME` or `suspension.OPTION.NAME`)",
      [](const Factory<StrutLaw>& make) { return parameterCell(make()->parameters(), false); });
  printRegistry(out, suspensionOptions(), "Suspension options (`[subsystems] suspension`)", "",
                none);
  printRegistry(
      out, effectRegistry(), "Effects (`[effects.NAME]`, `--effect`, the diagnosis catalogue)",
      "parameters (`EFFECT.NAME`)",
      [](const EffectFactory& make) { return parameterCell(make()->parameters(), true); });
  printRegistry(out, roadTypes(), "Road types (`scenarios.NAME.road.type`)", "", none);
  printRegistry(out, sensorQuantities(), "Sensor quantities (`[sensors.NAME] quantity`)", "", none);
  printRegistry(out, sensorModels(),
                "Sensor models (diagnosis candidates `MODEL:GROUP`, `--hidden-sensor`)",
                "parameter", [](const ParameterSpec& p) { return parameterCell({p}, true); });
  printRegistry(out, integrators(), "Integrators (`[simulation] integrator`)", "", none);
  printRegistry(out, commands, "Commands (`twin COMMAND`)", "runs on every MPI rank",
                [](bool distributed) { return std::string(distributed ? "yes" : "no"); });
  out += formatPrintf(
      "\n## Variables of user-defined effects (`[user_effects.NAME] element`)\n\n| element | "
      "variable | unit | meaning | checked over |\n|---|---|---|---|---|\n");
  for (const auto& el : userEffectElements())
    for (const auto& v : userEffectVariables(el))
      out += formatPrintf("| `%s` | `%s` | %s | %s | [%s, %s] |\n", el.c_str(), v.name.c_str(),
                          v.unit.c_str(), v.meaning.c_str(), formatNumber(v.lo).c_str(),
                          formatNumber(v.hi).c_str());
  return out;
}

std::string studyListing(const std::string& study_path, bool parameters) {
  const Study study = loadStudy(study_path);
  std::string out =
      formatPrintf("study %s (%s)\n  vehicle: %s\n\nassemblies:\n", study.name.c_str(),
                   study.path.c_str(), study.vehicle_path.c_str());
  for (const auto& a : study.assemblies())
    out += formatPrintf("  %-4s %s\n", a.id.c_str(), a.label().c_str());
  out += formatPrintf("\nscenarios:\n");
  for (const auto& s : study.scenarios)
    out += formatPrintf("  %-10s %s\n", s.name.c_str(), s.toJson()["road"].dump().c_str());
  out += formatPrintf("\nroad types (scenarios.NAME.road.type):\n");
  for (const auto& t : roadTypes())
    out += formatPrintf("  %-10s %s\n", t.name.c_str(), t.description.c_str());
  out += formatPrintf("\nsubsystem options:\n");
  for (const auto& [sub, options] : knownSubsystems()) {
    std::string list;
    for (const auto& o : options) list += (list.empty() ? "" : ", ") + o;
    out += formatPrintf("  %-10s %s\n", sub.c_str(), list.c_str());
  }
  out += formatPrintf("\ncalibrated parameters:\n");
  for (const auto& c : study.calibrated)
    out += formatPrintf("  %-24s [%g, %g] %s%s\n", c.name.c_str(), c.lower, c.upper, c.unit.c_str(),
                        c.truth ? (" truth " + std::to_string(*c.truth)).c_str() : "");
  out += formatPrintf("\neffects (add with --effect NAME:param=value,...; all default to off):\n");
  for (const auto& n : study.effectCatalog().names()) {
    auto e = study.effectCatalog().make(n, "");
    out += formatPrintf("  %-18s %s\n", n.c_str(), e->description().c_str());
    for (const auto& p : e->parameters())
      out += formatPrintf("      %-24s [%s] off = %g  prior [%g, %g]  %s\n",
                          (n + "." + p.name).c_str(), p.unit.c_str(), p.default_value,
                          p.prior_lower, p.prior_upper, p.description.c_str());
    out += formatPrintf("      signature: %s\n", e->signature().c_str());
  }
  out += formatPrintf("\nother twin diagnose candidates (docs/diagnosis.md):\n");
  std::string freeable;
  for (const auto& f : freeableVehicleParameters()) freeable += (freeable.empty() ? "" : ", ") + f;
  out += formatPrintf(
      "  free:VALUE          a fixed vehicle value freed over +-50 %% of the file's (the CG shift "
      "chassis.cg_x_m over "
      "+-10 %% of the wheelbase): %s\n",
      freeable.c_str());
  std::string factored;
  for (const char* v : kCornerFactorValues)
    factored += (factored.empty() ? "" : ", ") + std::string(v);
  out += formatPrintf(
      "  free:VALUE@PLACE    a per-corner or per-axle factor (docs/model.md) freed over [%g, %g], "
      "when named (not in the "
      "default catalogue): VALUE one of %s; PLACE fl, fr, rl, rr, front or rear\n",
      kFactorPriorLower, kFactorPriorUpper, factored.c_str());
  for (const auto& k : sensorModelKinds()) {
    const auto p = sensorModelParameter(k, "");
    out += formatPrintf("  %-19s %s [%s] off = %g  prior [%g, %g]\n", (k + ":GROUP").c_str(),
                        p.description.c_str(), p.unit.c_str(), p.default_value, p.prior_lower,
                        p.prior_upper);
  }
  if (!study.effects.empty()) {
    out += formatPrintf("\neffects installed by this study:");
    for (const auto& e : study.effects) out += formatPrintf(" %s", e.name.c_str());
    out += formatPrintf("\n");
  }
  out += formatPrintf("\noutput channels:\n");
  for (const auto& c : Simulator::channels(study.sensors))
    out += formatPrintf("  %-26s %s\n", c.name.c_str(), c.description.c_str());
  if (parameters) {
    out += formatPrintf("\nparameters (value, unit, source):\n");
    const auto t = study.parameterTable();
    for (const auto& n : t.names()) {
      const auto& e = t.at(n);
      out += formatPrintf("  %-48s %12g %-8s %s\n", n.c_str(), e.value, e.spec.unit.c_str(),
                          e.source.c_str());
    }
  }
  return out;
}

}  // namespace dtwin
