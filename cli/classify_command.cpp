// `twin classify`: Bayesian classification of field records among synthesized assemblies, and
// the cost-aware recommendation (study/classify.hpp).
#include <cstdio>
#include <memory>
#include <sstream>

#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "study/classify.hpp"
#include "study/request.hpp"

namespace dtwin::cli {
namespace {

struct ClassifyConfig {
  std::string study = defaultStudy(), field, synthetic, assembly = "all", covariance = "auto",
              prior, out;
  double threshold = 10.0;
  int threads = 0;
  bool quiet = false;
};

int runClassify(const ClassifyConfig& cfg, const std::string& command) {
  const Study study = loadStudy(cfg.study);
  ClassifyRequest req;
  if (cfg.assembly != "all") {
    std::stringstream ss(cfg.assembly);
    std::string id;
    while (std::getline(ss, id, ',')) req.options.assemblies.push_back(id);
  }
  req.options.covariance = cfg.covariance;
  req.prior = cfg.prior;
  req.options.threshold = cfg.threshold;
  req.options.threads = cfg.threads;
  req.options.command = command;
  req.field = cfg.field;
  req.synthetic = cfg.synthetic;
  req.out = cfg.out;
  const ClassifyRun run = classifyFieldRecords(study, req);
  if (!cfg.quiet) std::fputs(run.text().c_str(), stdout);
  return 0;
}

}  // namespace

CommandHandle addClassifyCommand(CLI::App& root, const CommandContext& context) {
  const std::string& command_line = context.command_line;
  auto cfg = std::make_shared<ClassifyConfig>();
  auto* c = addSubcommand(root, "classify");
  c->add_option("--study", cfg->study, "Study file (TOML)")->capture_default_str();
  c->add_option("--field", cfg->field,
                "Field data CSV (run,road_seed,t_...), e.g. from twin generate field")
      ->required();
  c->add_option("--synthetic", cfg->synthetic,
                "Folder written by twin synthesize (DIR/<id>/moments.bin, synthesis.json)")
      ->required();
  c->add_option("--assembly", cfg->assembly,
                "Assemblies to compare (comma separated or repeated), or 'all' (those synthesized)")
      ->capture_default_str()
      ->delimiter(',')
      ->multi_option_policy(CLI::MultiOptionPolicy::Join);
  c->add_option("--covariance", cfg->covariance,
                "auto (Ledoit-Wolf when some assembly has fewer than 2p synthetic vectors, else "
                "sample), sample or ledoit-wolf")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "sample", "ledoit-wolf"}));
  c->add_option("--prior", cfg->prior,
                "Prior probabilities, e.g. M1=0.25,M2=0.25,M3=0.25,M4=0.25 (default: uniform)");
  c->add_option("--threshold", cfg->threshold,
                "Decisive evidence threshold on 2 ln B for the recommendation")
      ->capture_default_str();
  c->add_option("--threads", cfg->threads,
                "Assemblies modelled at once (0: all cores; about 0.6 GB each at 5001 samples)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  c->add_option("--out", cfg->out, "Output folder: records.csv and summary.json")->required();
  c->add_flag("--quiet", cfg->quiet, "Print nothing on success");
  addExamples(c, {"twin classify --study data/studies/demo.toml --field out/field.csv --synthetic "
                  "out/synthetic --out out/classification"});
  CommandHandle handle{c, [cfg, command_line] { return runClassify(*cfg, command_line); }, {}};
  // Library errors name FieldClassifyOptions fields ("field_classify.threshold"); the fields whose
  // flag is not "--" + the field with '_' as '-':
  handle.field_flags["assemblies"] = "--assembly";
  return handle;
}

}  // namespace dtwin::cli
