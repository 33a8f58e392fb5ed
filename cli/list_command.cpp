#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/provenance.hpp"
#include "io/study.hpp"
#include "study/bench.hpp"
#include "subsystems/user_effect.hpp"
#include "twin/road_setting.hpp"
#include "twin/simulator.hpp"

namespace fs = std::filesystem;

namespace dtwin::cli {
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
void printRegistry(const Registry<Value>& r, const std::string& title,
                   const std::string& extra_header, Extra extra) {
  std::printf("\n## %s\n\n| %s | description |%s\n|---|---|%s\n", title.c_str(), r.what().c_str(),
              extra_header.empty() ? "" : (" " + extra_header + " |").c_str(),
              extra_header.empty() ? "" : "---|");
  for (const auto& e : r) {
    std::printf("| `%s` | %s |", e.name.c_str(), e.description.c_str());
    if (!extra_header.empty()) std::printf(" %s |", extra(e.value).c_str());
    std::printf("\n");
  }
}

/// Every registry of the twin as Markdown: what docs/registries.md holds, checked by a test.
int runRegistries() {
  std::printf(
      "# Registries\n\nEvery extension point of the twin, as its registry holds it "
      "(common/registry.hpp). This page is\n"
      "written by `twin list --registries > docs/registries.md`, and a test fails when it and the\n"
      "registries differ (tests/docs/registry_docs_test.cpp): edit the registry, then "
      "regenerate.\n");
  const auto none = [](const auto&) { return std::string(); };
  printRegistry(tireLawRegistry(), "Tire laws (`[subsystems] tire`)",
                "parameters (`tire.NAME` or `tire.LAW.NAME`)", [](const Factory<TireLaw>& make) {
                  return parameterCell(make()->parameters(), false);
                });
  printRegistry(
      strutLawRegistry(), "Strut laws (`[subsystems] strut`)",
      "parameters (`suspension.NAME` or `suspension.OPTION.NAME`)",
      [](const Factory<StrutLaw>& make) { return parameterCell(make()->parameters(), false); });
  printRegistry(suspensionOptions(), "Suspension options (`[subsystems] suspension`)", "", none);
  printRegistry(effectRegistry(), "Effects (`[effects.NAME]`, `--effect`, the diagnosis catalogue)",
                "parameters (`EFFECT.NAME`)", [](const EffectFactory& make) {
                  return parameterCell(make()->parameters(), true);
                });
  printRegistry(roadTypes(), "Road types (`scenarios.NAME.road.type`)", "", none);
  printRegistry(sensorQuantities(), "Sensor quantities (`[sensors.NAME] quantity`)", "", none);
  printRegistry(sensorModels(),
                "Sensor models (diagnosis candidates `MODEL:GROUP`, `--hidden-sensor`)",
                "parameter", [](const ParameterSpec& p) { return parameterCell({p}, true); });
  printRegistry(integrators(), "Integrators (`[simulation] integrator`)", "", none);
  printRegistry(commandRegistry(), "Commands (`twin COMMAND`)", "runs on every MPI rank",
                [](const CommandEntry& c) { return std::string(c.distributed ? "yes" : "no"); });
  std::printf(
      "\n## Variables of user-defined effects (`[user_effects.NAME] element`)\n\n| element | "
      "variable | unit | meaning | checked over |\n|---|---|---|---|---|\n");
  for (const auto& el : userEffectElements())
    for (const auto& v : userEffectVariables(el))
      std::printf("| `%s` | `%s` | %s | %s | [%s, %s] |\n", el.c_str(), v.name.c_str(),
                  v.unit.c_str(), v.meaning.c_str(), formatNumber(v.lo).c_str(),
                  formatNumber(v.hi).c_str());
  return 0;
}

int runList(const std::string& study_path, bool params) {
  const Study study = loadStudy(study_path);
  std::printf("study %s (%s)\n  vehicle: %s\n\nassemblies:\n", study.name.c_str(),
              study.path.c_str(), study.vehicle_path.c_str());
  for (const auto& a : study.assemblies())
    std::printf("  %-4s %s\n", a.id.c_str(), a.label().c_str());
  std::printf("\nscenarios:\n");
  for (const auto& s : study.scenarios)
    std::printf("  %-10s %s\n", s.name.c_str(), s.toJson()["road"].dump().c_str());
  std::printf("\nroad types (scenarios.NAME.road.type):\n");
  for (const auto& t : roadTypes())
    std::printf("  %-10s %s\n", t.name.c_str(), t.description.c_str());
  std::printf("\nsubsystem options:\n");
  for (const auto& [sub, options] : knownSubsystems()) {
    std::string list;
    for (const auto& o : options) list += (list.empty() ? "" : ", ") + o;
    std::printf("  %-10s %s\n", sub.c_str(), list.c_str());
  }
  std::printf("\ncalibrated parameters:\n");
  for (const auto& c : study.calibrated)
    std::printf("  %-24s [%g, %g] %s%s\n", c.name.c_str(), c.lower, c.upper, c.unit.c_str(),
                c.truth ? (" truth " + std::to_string(*c.truth)).c_str() : "");
  std::printf("\neffects (add with --effect NAME:param=value,...; all default to off):\n");
  for (const auto& n : study.effectCatalog().names()) {
    auto e = study.effectCatalog().make(n, "");
    std::printf("  %-18s %s\n", n.c_str(), e->description().c_str());
    for (const auto& p : e->parameters())
      std::printf("      %-24s [%s] off = %g  prior [%g, %g]  %s\n", (n + "." + p.name).c_str(),
                  p.unit.c_str(), p.default_value, p.prior_lower, p.prior_upper,
                  p.description.c_str());
    std::printf("      signature: %s\n", e->signature().c_str());
  }
  std::printf("\nother twin diagnose candidates (docs/diagnosis.md):\n");
  std::string freeable;
  for (const auto& f : freeableVehicleParameters()) freeable += (freeable.empty() ? "" : ", ") + f;
  std::printf(
      "  free:VALUE          a fixed vehicle value freed over +-50 %% of the file's (the CG shift "
      "chassis.cg_x_m over "
      "+-10 %% of the wheelbase): %s\n",
      freeable.c_str());
  std::string factored;
  for (const char* v : kCornerFactorValues)
    factored += (factored.empty() ? "" : ", ") + std::string(v);
  std::printf(
      "  free:VALUE@PLACE    a per-corner or per-axle factor (docs/model.md) freed over [%g, %g], "
      "when named (not in the "
      "default catalogue): VALUE one of %s; PLACE fl, fr, rl, rr, front or rear\n",
      kFactorPriorLower, kFactorPriorUpper, factored.c_str());
  for (const auto& k : sensorModelKinds()) {
    const auto p = sensorModelParameter(k, "");
    std::printf("  %-19s %s [%s] off = %g  prior [%g, %g]\n", (k + ":GROUP").c_str(),
                p.description.c_str(), p.unit.c_str(), p.default_value, p.prior_lower,
                p.prior_upper);
  }
  if (!study.effects.empty()) {
    std::printf("\neffects installed by this study:");
    for (const auto& e : study.effects) std::printf(" %s", e.name.c_str());
    std::printf("\n");
  }
  std::printf("\noutput channels:\n");
  for (const auto& c : Simulator::channels(study.sensors))
    std::printf("  %-26s %s\n", c.name.c_str(), c.description.c_str());
  if (params) {
    std::printf("\nparameters (value, unit, source):\n");
    const auto t = study.parameterTable();
    for (const auto& n : t.names()) {
      const auto& e = t.at(n);
      std::printf("  %-48s %12g %-8s %s\n", n.c_str(), e.value, e.spec.unit.c_str(),
                  e.source.c_str());
    }
  }
  return 0;
}

}  // namespace

CommandHandle addListCommand(CLI::App& root, const CommandContext& /*context*/) {
  struct Cfg {
    std::string study = defaultStudy();
    bool params = false;
    bool registries = false;
  };
  auto cfg = std::make_shared<Cfg>();
  std::string& list_study = cfg->study;
  bool& list_params = cfg->params;
  auto* l = addSubcommand(root, "list");
  l->add_option("--study", list_study, "Study file (TOML)")->capture_default_str();
  l->add_flag("--parameters", list_params,
              "Also list every parameter with its value, unit and source");
  l->add_flag("--registries", cfg->registries,
              "Instead: every registry of the twin (laws, effects, roads, sensors, integrators, "
              "commands) as Markdown "
              "tables, as docs/registries.md holds them");
  addExamples(l, {"twin list --study data/studies/paper.toml",
                  "twin list --study data/studies/demo.toml --parameters"});

  return {l,
          [cfg] { return cfg->registries ? runRegistries() : runList(cfg->study, cfg->params); }};
}

}  // namespace dtwin::cli
