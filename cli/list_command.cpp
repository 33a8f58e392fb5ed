#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "study/listing.hpp"

namespace dtwin::cli {
namespace {

/// `twin list --registries`: every registry as Markdown, the program's commands among them.
int runRegistries() {
  std::vector<RegistryEntry<bool>> commands;
  for (const auto& c : commandRegistry())
    commands.push_back({c.name, c.description, c.value.distributed});
  std::fputs(registriesMarkdown(Registry<bool>(commandRegistry().what(), commands)).c_str(),
             stdout);
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

  return {l, [cfg] {
            if (cfg->registries) return runRegistries();
            std::fputs(studyListing(cfg->study, cfg->params).c_str(), stdout);
            return 0;
          }};
}

}  // namespace dtwin::cli
