// `twin synthesize` as one call (study/synthesize.hpp).
#include "study/synthesize.hpp"

#include <cstdio>
#include <filesystem>

#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "io/provenance.hpp"
#include "io/work.hpp"

namespace dtwin {

namespace fs = std::filesystem;

std::string SynthesizeRun::text() const {
  const auto& r = result;
  const auto& j = r.info;
  char line[1024];
  std::snprintf(line, sizeof line,
                "%-4s %-24s %ld draws x %ld roads (library %ld) -> %lld vectors of %zu samples (%s "
                "%g..%g s), failures %ld, "
                "cost %.4g s/s (median run %.3f s), %s%.1f s -> %s\n",
                assembly.id.c_str(), assembly.label().c_str(), r.draws, r.roads_per_draw,
                r.road_library, static_cast<long long>(r.moments.count()), r.times_s.size(),
                j["channel"].get<std::string>().c_str(), r.times_s.front(), r.times_s.back(),
                r.failures, r.cost_s_per_s, r.median_run_wall_s,
                r.reused
                    ? "reused finished files, "
                    : (r.resumed_blocks
                           ? ("resumed at block " + std::to_string(r.resumed_blocks) + ", ").c_str()
                           : ""),
                r.wall_s, (fs::path(dir) / "moments.bin").string().c_str());
  std::string out = line;
  for (std::size_t k = 0; k < r.failure_list.size() && k < 5; ++k) {
    std::snprintf(line, sizeof line,
                  "       failed: draw %ld road %ld (library road %ld, seed %llu): %s\n",
                  r.failure_list[k].draw, r.failure_list[k].road, r.failure_list[k].library_index,
                  static_cast<unsigned long long>(r.failure_list[k].road_seed),
                  r.failure_list[k].message.c_str());
    out += line;
  }
  return out;
}

std::vector<SynthesizeRun> synthesizeAssemblies(
    const Study& study, const SynthesizeRequest& request, const StageProgress& progress,
    const std::function<void(const SynthesizeRun&)>& done) {
  const auto& opt = request.options;
  study.scenario(opt.scenario);  // validates the name
  std::vector<AssemblySpec> targets;
  if (request.assembly == "all")
    targets = study.assemblies();
  else
    targets.push_back(study.assembly(request.assembly));
  if (!fs::is_directory(request.calibration))
    throw InputError(request.calibration, "calibration folder not found (--calibration)");
  if (fs::exists(request.out) && !fs::is_directory(request.out))
    throw InputError("--out", "'" + request.out + "' exists and is not a folder");
  {
    Study sized = study;
    overrideSize(sized, "posterior_draws", opt.draws, "--draws");
    overrideSize(sized, "roads_per_draw", opt.roads_per_draw, "--roads");
    overrideSize(sized, "road_library", opt.road_library, "--library");
    std::vector<std::string> stages;
    stages.reserve(targets.size());
    for (const auto& a : targets) stages.push_back("synthesize " + a.id);
    checkCommandWork(sized, stages, request.force);
  }
  // Read every posterior first: a missing or malformed one stops before any simulation.
  std::vector<calib::PosteriorSample> posteriors;
  for (const auto& a : targets) {
    const std::string p = (fs::path(request.calibration) / a.id / "posterior.csv").string();
    if (!fs::exists(p))
      throw InputError(p, "not found: calibrate assembly " + a.id +
                              " first (twin calibrate --assembly " + a.id + ")");
    posteriors.push_back(calib::readPosteriorCsv(p));
  }
  nlohmann::json index;
  stampProvenance(index, opt.command);
  index["study"] = study.path;
  index["calibration"] = request.calibration;
  std::vector<SynthesizeRun> runs;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    SynthesizeRun run;
    run.assembly = targets[i];
    const auto& a = run.assembly;
    run.dir = (fs::path(request.out) / a.id).string();
    const std::string stage = a.id + " synthesize";
    run.result = classify::synthesizeAssembly(study, a, posteriors[i], opt, run.dir,
                                              [&](std::size_t d, std::size_t t) {
                                                if (progress) progress(stage, d, t);
                                              });
    index["assemblies"].push_back({{"assembly", a.id},
                                   {"label", a.label()},
                                   {"synthesis", (fs::path(a.id) / "synthesis.json").string()},
                                   {"moments", (fs::path(a.id) / "moments.bin").string()}});
    if (done) done(run);
    runs.push_back(std::move(run));
  }
  rootWrites(opt.processes, [&] {
    writeFileAtomic((fs::path(request.out) / "synthesize.json").string(), index.dump(2) + "\n");
  });
  return runs;
}

}  // namespace dtwin
