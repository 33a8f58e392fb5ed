#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "twin/bench.hpp"
#include "twin/provenance.hpp"
#include "twin/road_setting.hpp"
#include "twin/simulator.hpp"
#include "twin/study.hpp"

namespace fs = std::filesystem;

namespace dtwin::cli {
namespace {

int runList(const std::string& study_path, bool params) {
  const Study study = loadStudy(study_path);
  std::printf("study %s (%s)\n  vehicle: %s\n\nassemblies:\n", study.name.c_str(), study.path.c_str(), study.vehicle_path.c_str());
  for (const auto& a : study.assemblies()) std::printf("  %-4s %s\n", a.id.c_str(), a.label().c_str());
  std::printf("\nscenarios:\n");
  for (const auto& s : study.scenarios) std::printf("  %-10s %s\n", s.name.c_str(), s.toJson()["road"].dump().c_str());
  std::printf("\nroad types (scenarios.NAME.road.type):\n");
  for (const auto& t : roadTypes()) std::printf("  %-10s %s\n", t.name.c_str(), t.description.c_str());
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
      std::printf("      %-24s [%s] off = %g  prior [%g, %g]  %s\n", (n + "." + p.name).c_str(), p.unit.c_str(), p.default_value,
                  p.prior_lower, p.prior_upper, p.description.c_str());
    std::printf("      signature: %s\n", e->signature().c_str());
  }
  std::printf("\nother twin diagnose candidates (docs/diagnosis.md):\n");
  std::string freeable;
  for (const auto& f : freeableVehicleParameters()) freeable += (freeable.empty() ? "" : ", ") + f;
  std::printf("  free:VALUE          a fixed vehicle value freed over +-50 %% of the file's: %s\n", freeable.c_str());
  for (const auto& k : sensorModelKinds()) {
    const auto p = sensorModelParameter(k, "");
    std::printf("  %-19s %s [%s] off = %g  prior [%g, %g]\n", (k + ":GROUP").c_str(), p.description.c_str(), p.unit.c_str(), p.default_value,
                p.prior_lower, p.prior_upper);
  }
  if (!study.effects.empty()) {
    std::printf("\neffects installed by this study:");
    for (const auto& e : study.effects) std::printf(" %s", e.name.c_str());
    std::printf("\n");
  }
  std::printf("\noutput channels:\n");
  for (const auto& c : Simulator::channels(study.sensors)) std::printf("  %-26s %s\n", c.name.c_str(), c.description.c_str());
  if (params) {
    std::printf("\nparameters (value, unit, source):\n");
    const auto t = study.parameterTable();
    for (const auto& n : t.names()) {
      const auto& e = t.at(n);
      std::printf("  %-48s %12g %-8s %s\n", n.c_str(), e.value, e.spec.unit.c_str(), e.source.c_str());
    }
  }
  return 0;
}

}  // namespace

CommandHandle addListCommand(CLI::App& root, const std::string& /*command_line*/) {
  struct Cfg { std::string study = defaultStudy(); bool params = false; };
  auto cfg = std::make_shared<Cfg>();
  std::string& list_study = cfg->study;
  bool& list_params = cfg->params;
  auto* l = addSubcommand(root, "list");
  l->add_option("--study", list_study, "Study file (TOML)")->capture_default_str();
  l->add_flag("--parameters", list_params, "Also list every parameter with its value, unit and source");

  return {l, [cfg] { return runList(cfg->study, cfg->params); }};
}

}  // namespace dtwin::cli
