// `twin classify`: Bayesian classification of field records among synthesized assemblies, and
// the cost-aware recommendation (classification/classify_field.hpp).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "classification/classify_field.hpp"
#include "cli/commands.hpp"
#include "common/errors.hpp"
#include "io/study.hpp"

namespace fs = std::filesystem;

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
  classify::FieldClassifyOptions opt;
  if (cfg.assembly != "all") {
    std::stringstream ss(cfg.assembly);
    std::string id;
    while (std::getline(ss, id, ',')) opt.assemblies.push_back(id);
  }
  opt.covariance = cfg.covariance;
  if (!cfg.prior.empty()) opt.prior = classify::parsePriorList(cfg.prior, "--prior");
  opt.threshold = cfg.threshold;
  opt.threads = cfg.threads;
  opt.command = command;
  opt.validate();
  if (fs::exists(cfg.out) && !fs::is_directory(cfg.out))
    throw InputError("--out", "'" + cfg.out + "' exists and is not a folder");
  if (!fs::exists(cfg.field)) throw InputError(cfg.field, "field data file not found (--field)");
  if (!fs::is_directory(cfg.synthetic))
    throw InputError(cfg.synthetic, "synthetic data folder not found (--synthetic)");
  const classify::FieldClassification c =
      classify::classifyFieldFile(study, cfg.field, cfg.synthetic, opt);
  classify::writeFieldClassification(c, cfg.out);
  if (!cfg.quiet) {
    std::printf("%zu field records x %d samples; covariance: %s (%s)\n", c.records.size(),
                c.models.empty() ? 0 : c.models.front().dimension, c.covariance_method.c_str(),
                c.covariance_reason.c_str());
    for (const auto& m : c.models)
      std::printf("  %-4s %-24s n = %lld, factorization %s%s, cost %.4g s/s\n", m.id.c_str(),
                  m.label.c_str(), static_cast<long long>(m.vectors), m.factorization.c_str(),
                  m.covariance == "ledoit-wolf"
                      ? (", shrinkage " + std::to_string(m.shrinkage_intensity)).c_str()
                      : "",
                  m.cost_s_per_s);
    std::printf("%s", c.result.briefReport().c_str());
    std::printf("%s\n", c.recommendation.explanation.c_str());
    std::printf("-> %s, %s\n", (fs::path(cfg.out) / "records.csv").string().c_str(),
                (fs::path(cfg.out) / "summary.json").string().c_str());
  }
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
