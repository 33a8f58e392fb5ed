#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "study/bench.hpp"

namespace dtwin::cli {

CommandHandle addBenchCommand(CLI::App& root, const CommandContext& /*context*/) {
  auto cfg = std::make_shared<BenchRequest>();
  cfg->study = defaultStudy();
  std::string& bench_study = cfg->study;
  int& bench_runs = cfg->runs;
  bool& bench_md = cfg->markdown;
  std::vector<std::string>& bench_ids = cfg->assemblies;
  auto* b = addSubcommand(root, "bench");
  b->add_option("--study", bench_study, "Study file (TOML)")->capture_default_str();
  b->add_option("--runs", bench_runs, "Timed runs per case (median reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  b->add_option("--assembly", bench_ids, "Only these assemblies (comma separated or repeated)")
      ->delimiter(',');
  b->add_flag("--markdown", bench_md, "Print a markdown table (for docs/performance.md)");
  b->add_option("--import", cfg->import_rows,
                "Instead: time `twin import` on a synthetic 100 Hz log of this many rows (360000: "
                "one hour), as CSV and as MF4")
      ->check(CLI::Range(2L, 100000000L));
  b->add_option("--user-effect", cfg->user_effect,
                "Instead: time a user-defined strut effect against the built-in one of the same "
                "form, over this many evaluations")
      ->check(CLI::Range(1000L, 1000000000L));
  b->add_flag("--hand-ode", cfg->hand_ode,
              "Instead: the bump run of one assembly (--assembly, default M3) against a "
              "hand-written 7-DOF ODE of the same vehicle, "
              "both integrated by ROS34PW2")
      ->excludes("--import")
      ->excludes("--user-effect");
  auto* acc = b->add_flag(
      "--accumulation", cfg->accumulation,
      "Instead: a synthesis's cost per draw and per accumulation step for one assembly "
      "(--assembly, default "
      "the first), and its wall time on 1 to 256 single-core MPI ranks modelled from them");
  acc->excludes("--import")->excludes("--user-effect")->excludes("--hand-ode");
  b->add_option("--link-gb-per-s", cfg->link_gb_per_s,
                "With --accumulation: the bandwidth between ranks the model assumes [GB/s]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->needs(acc);
  auto* scen = b->add_option("--scenario", cfg->scenario,
                             "With --user-effect: the study's scenario of the whole runs timed")
                   ->capture_default_str();
  scen->needs("--user-effect");
  addExamples(b, {"twin bench --study data/studies/demo.toml --assembly M3 --runs 1",
                  "twin bench --import 20000 --runs 1"});

  return {b, [cfg] {
            runBench(
                *cfg, [](const std::string& text) { std::fputs(text.c_str(), stdout); },
                [](const std::string& text) { std::fputs(text.c_str(), stderr); });
            return 0;
          }};
}

}  // namespace dtwin::cli
