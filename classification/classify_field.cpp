#include "classification/classify_field.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "calibration/calibrate.hpp"
#include "classification/moments.hpp"
#include "classification/shrinkage.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "common/parallel.hpp"
#include "common/validate.hpp"
#include "io/provenance.hpp"
#include "twin/trace.hpp"

namespace fs = std::filesystem;

namespace dtwin::classify {
namespace {

nlohmann::json readJsonFile(const fs::path& p) {
  std::ifstream in(p);
  if (!in) throw InputError(p.string(), "cannot open");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw InputError(p.string(), std::string("not valid JSON: ") + jsonErrorInWords(e));
  }
  return j;
}

}  // namespace

void FieldClassifyOptions::validate() const {
  const OptionCheck check("field_classify");
  std::set<std::string> seen;
  for (const auto& id : assemblies)
    check.require(seen.insert(id).second, "assemblies", id + " appears twice");
  check.require(covariance == "auto" || covariance == "sample" || covariance == "ledoit-wolf",
                "covariance", "must be auto, sample or ledoit-wolf, got '" + covariance + "'");
  for (const auto& [id, p] : prior)
    check.require(std::isfinite(p) && p > 0, "prior",
                  "the prior of " + id + " must be a finite number > 0, got " + formatNumber(p));
  check.positive("threshold", threshold);
  check.nonNegative("tie_tolerance", tie_tolerance);
  check.atLeast("threads", threads, 0);
  factor.validate();
}

std::vector<std::pair<std::string, double>> parsePriorList(const std::string& text,
                                                           const std::string& where) {
  std::vector<std::pair<std::string, double>> out;
  std::set<std::string> seen;
  for (const auto& item : splitOn(text, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(
          where,
          "expects ID=PROBABILITY,... (e.g. M1=0.4,M2=0.2,M3=0.2,M4=0.2), got '" + item + "'");
    const std::string id = item.substr(0, eq), v = item.substr(eq + 1);
    double p = 0;
    if (!parseNumber(v, p) || !std::isfinite(p) || !(p > 0))
      throw InputError(where, "prior of " + id + " must be a number > 0, got '" + v + "'");
    if (!seen.insert(id).second) throw InputError(where, id + " appears twice");
    out.push_back({id, p});
  }
  if (out.empty()) throw InputError(where, "is empty");
  return out;
}

std::string FieldClassification::recordsCsv() const {
  std::string s = "record";
  for (const auto& m : models) s += ",loglik_" + m.id;
  for (const auto& m : models) s += ",logpost_" + m.id;
  for (const auto& m : models) s += ",prob_" + m.id;
  s += ",winner,tie\n";
  for (std::size_t r = 0; r < records.size(); ++r) {
    s += std::to_string(records[r]);
    const auto ri = static_cast<Eigen::Index>(r);
    for (Eigen::Index m = 0; m < log_likelihood.cols(); ++m)
      s += "," + formatExact(log_likelihood(ri, m));
    for (Eigen::Index m = 0; m < result.log_posterior.cols(); ++m)
      s += "," + formatExact(result.log_posterior(ri, m));
    for (Eigen::Index m = 0; m < result.probability.cols(); ++m)
      s += "," + formatExact(result.probability(ri, m));
    s += "," + models[static_cast<std::size_t>(result.winner[r])].id + "," +
         (result.tie[r] ? "1" : "0") + "\n";
  }
  return s;
}

namespace {

/// The assemblies to compare: those named by the options, else every assembly of the study with
/// a synthesis in the folder.
std::vector<AssemblySpec> comparedAssemblies(const Study& study, const fs::path& sdir,
                                             const FieldClassifyOptions& opt) {
  std::vector<AssemblySpec> targets;
  if (opt.assemblies.empty()) {
    for (const auto& a : study.assemblies())
      if (fs::exists(sdir / a.id / "synthesis.json")) targets.push_back(a);
    if (targets.empty())
      throw InputError(sdir.string(),
                       "holds no synthesis of any assembly of " + study.path +
                           " (expected <id>/synthesis.json, written by twin synthesize)");
  } else {
    for (const auto& id : opt.assemblies) targets.push_back(study.assembly(id));
  }
  return targets;
}

/// Each target's synthesis.json, checked: finished (moments.bin exists), the field data's window
/// and channel, a recorded cost (step 1 of the file header).
std::vector<nlohmann::json> readSyntheses(const std::vector<AssemblySpec>& targets,
                                          const fs::path& sdir, const FieldData& field,
                                          const std::string& field_channel) {
  const int p = static_cast<int>(field.columnCount());
  std::vector<nlohmann::json> infos;
  for (const auto& a : targets) {
    const fs::path info_path = sdir / a.id / "synthesis.json";
    if (!fs::exists(info_path))
      throw InputError(info_path.string(),
                       "not found: synthesize assembly " + a.id + " first (twin synthesize)");
    if (!fs::exists(sdir / a.id / "moments.bin"))
      throw InputError((sdir / a.id / "moments.bin").string(),
                       "not found (the synthesis of " + a.id + " did not finish)");
    const nlohmann::json j = readJsonFile(info_path);
    const std::string where = info_path.string();
    try {
      const auto samples = j.at("samples").get<long>();
      const auto w = j.at("window_s").get<std::vector<double>>();
      const double rate = j.at("output_rate_hz").get<double>();
      bool same = samples == p;
      int first_diff = -1;  // the first sample whose time differs (when the counts agree)
      for (int k = 0; same && k < p; ++k)
        if (std::abs(field.times_s[static_cast<std::size_t>(k)] - (w.at(0) + k / rate)) >= 1e-9) {
          same = false;
          first_diff = k;
        }
      if (!same) {
        // Two windows with the same ends and counts can still differ inside: name the first sample.
        const std::string inside =
            first_diff < 0 ? ""
                           : "; they differ first at sample " + std::to_string(first_diff + 1) +
                                 ": " + formatExact(w.at(0) + first_diff / rate) +
                                 " s in the synthesis (" + formatExact(rate) + " Hz), " +
                                 formatExact(field.times_s[static_cast<std::size_t>(first_diff)]) +
                                 " s in the field data";
        throw InputError(
            where,
            "the synthesis window (" + std::to_string(samples) + " samples, " +
                formatExact(w.at(0)) + ".." + formatExact(w.at(1)) +
                " s) is not the field data's (" + std::to_string(p) + " samples, " +
                formatExact(field.times_s.front()) + ".." + formatExact(field.times_s.back()) +
                " s)" + inside +
                "; synthesize with the field data's window (synthesis options t_begin_s, t_end_s)");
      }
      const std::string ch = j.at("channel").get<std::string>();
      if (!field_channel.empty() && ch != field_channel)
        throw InputError(
            where, "the synthesis is of channel " + ch + ", the field data of " + field_channel);
      if (!(j.at("cost").at("wall_s_per_simulated_s_median").get<double>() > 0))
        throw InputError(where, "records no cost (no successful run?)");
    } catch (const nlohmann::json::exception& e) {
      throw InputError(where, std::string("malformed synthesis.json: ") + jsonErrorInWords(e));
    }
    infos.push_back(j);
  }
  return infos;
}

/// The covariance method for every assembly and why (step 2 of the file header): the requested
/// one, or for "auto" Ledoit–Wolf when the smallest synthesis has fewer than 2p vectors.
void chooseCovariance(const std::vector<nlohmann::json>& infos, int p, const std::string& requested,
                      FieldClassification& out) {
  long n_min = std::numeric_limits<long>::max();
  for (const auto& j : infos) n_min = std::min(n_min, j.at("vectors").get<long>());
  if (requested != "auto") {
    out.covariance_method = requested;
    out.covariance_reason = "requested (covariance = " + requested + ")";
  } else if (n_min < 2L * p) {
    out.covariance_method = "ledoit-wolf";
    out.covariance_reason =
        "automatic: the smallest synthesis has n = " + std::to_string(n_min) +
        " vectors < 2p = " + std::to_string(2L * p) + " (p = " + std::to_string(p) +
        " samples per record), so the sample covariance is " +
        (n_min <= p ? "singular (n <= p)" : "poorly conditioned") +
        "; Ledoit-Wolf shrinkage towards a scaled identity is used for every assembly";
  } else {
    out.covariance_method = "sample";
    out.covariance_reason = "automatic: every synthesis has n >= 2p = " + std::to_string(2L * p) +
                            " vectors, so the unbiased sample covariance M2/(n-1) is used";
  }
}

/// The field records as the columns of a p×R matrix.
Eigen::MatrixXd recordsAsColumns(const FieldData& field) {
  const int p = static_cast<int>(field.columnCount());
  const long R = static_cast<long>(field.rowCount());
  Eigen::MatrixXd Y(p, R);
  for (long r = 0; r < R; ++r)
    for (int k = 0; k < p; ++k)
      Y(k, r) = field.at(static_cast<std::size_t>(r), static_cast<std::size_t>(k));
  return Y;
}

/// One assembly's Gaussian model (steps 2–4 of the file header): its moments, the covariance by
/// `method`, the factor, and ℓ of every record (column of Y) into `loglik`; one assembly's p×p
/// matrices at a time.
AssemblyModelInfo fitAssembly(const AssemblySpec& a, const nlohmann::json& j, const fs::path& sdir,
                              const std::string& method, const FactorOptions& factor,
                              const Eigen::MatrixXd& Y, Eigen::Ref<Eigen::VectorXd> loglik) {
  const auto t0 = std::chrono::steady_clock::now();
  const int p = static_cast<int>(Y.rows());
  AssemblyModelInfo info;
  info.id = a.id;
  info.label = a.label();
  info.dir = (sdir / a.id).string();
  info.covariance = method;
  info.cost_s_per_s = j.at("cost").at("wall_s_per_simulated_s_median").get<double>();
  info.synthesis = {{"fingerprint", j.value("fingerprint", "")},
                    {"draws", j.value("draws", 0L)},
                    {"roads_per_draw", j.value("roads_per_draw", 0L)},
                    {"road_library", j.value("road_library", 0L)},
                    {"vectors", j.value("vectors", 0L)},
                    {"failures", j.value("failures", 0L)},
                    {"seed", j.value("seed", std::uint64_t{0})},
                    {"posterior", j.value("posterior", nlohmann::json())},
                    {"cost", j.at("cost")}};
  Eigen::VectorXd mean;
  Eigen::MatrixXd cov;
  {
    const std::string mpath = (sdir / a.id / "moments.bin").string();
    const MomentAccumulator acc = MomentAccumulator::load(mpath);
    if (acc.dimension() != p)
      throw InputError(mpath, "dimension " + std::to_string(acc.dimension()) +
                                  " differs from the field data's " + std::to_string(p));
    if (acc.count() < 2) throw InputError(mpath, "holds fewer than 2 vectors; no covariance");
    info.vectors = acc.count();
    info.dimension = acc.dimension();
    mean = acc.mean();
    if (method == "ledoit-wolf") {
      if (!acc.tracksFourthMoment())
        throw InputError(
            mpath,
            "was synthesized without the fourth moment, which Ledoit-Wolf needs; resynthesize "
            "(twin synthesize tracks it by default) or choose the sample covariance (option "
            "covariance)");
      LedoitWolfEstimate lw = calcLedoitWolf(acc, true);
      info.shrinkage_intensity = lw.intensity;
      cov = std::move(lw.covariance);
    } else {
      cov = acc.covariance();
    }
  }
  try {
    const GaussianModel g(mean, cov, factor);
    cov.resize(0, 0);
    info.factorization = g.factorization();
    info.jitter = g.jitter();
    info.jitter_absolute = g.jitterAbsolute();
    info.log_det = g.logDeterminant();
    info.relative_min_pivot = g.relativeMinPivot();
    loglik = g.logPdfBatch(Y);
  } catch (const InputError& e) {
    throw InputError("assembly " + a.id + " (" + method + " covariance)", e.what());
  }
  info.build_wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return info;
}

/// The options of classifyRecords: the compared ids, the tie tolerance, and the priors in
/// comparison order (every compared assembly needs one when any is given).
ClassifyOptions recordOptions(const std::vector<AssemblySpec>& targets,
                              const FieldClassifyOptions& opt) {
  const OptionCheck check("field_classify");
  ClassifyOptions co;
  for (const auto& a : targets) co.model_ids.push_back(a.id);
  co.tie_tolerance = opt.tie_tolerance;
  if (opt.prior.empty()) return co;
  for (const auto& [id, v] : opt.prior) {
    bool known = false;
    for (const auto& a : targets) known = known || a.id == id;
    check.require(known, "prior", id + " is not among the compared assemblies");
  }
  for (const auto& a : targets) {
    double v = -1;
    for (const auto& [id, pv] : opt.prior)
      if (id == a.id) v = pv;
    check.require(v >= 0, "prior",
                  "gives no probability for " + a.id + " (give one for every compared assembly)");
    co.prior.push_back(v);
  }
  return co;
}

/// summary.json (FieldClassification::summary) of a finished classification.
nlohmann::json classificationSummary(const Study& study, const FieldData& field,
                                     const std::string& field_channel,
                                     const std::string& synthetic_dir,
                                     const FieldClassifyOptions& opt,
                                     const nlohmann::json& field_info,
                                     const std::vector<std::string>& ids,
                                     const FieldClassification& out) {
  const int M = static_cast<int>(ids.size());
  nlohmann::json s;
  stampProvenance(s, opt.command);
  s["study"] = study.path;
  s["field"] = field_info.is_null() ? nlohmann::json::object() : field_info;
  s["field"]["records"] = static_cast<long>(field.rowCount());
  s["field"]["samples"] = static_cast<int>(field.columnCount());
  s["field"]["window_s"] = {field.times_s.front(), field.times_s.back()};
  if (!field_channel.empty()) s["field"]["channel"] = field_channel;
  s["synthetic_dir"] = synthetic_dir;
  s["assemblies"] = ids;
  for (int m = 0; m < M; ++m)
    s["prior"][ids[static_cast<std::size_t>(m)]] = std::exp(out.result.log_prior[m]);
  s["covariance"] = {{"method", out.covariance_method},
                     {"reason", out.covariance_reason},
                     {"requested", opt.covariance}};
  for (int m = 0; m < M; ++m) {
    const auto& info = out.models[static_cast<std::size_t>(m)];
    const auto& id = info.id;
    s["wins"][id] = out.result.wins[static_cast<std::size_t>(m)];
    const auto& sp = out.result.spread[static_cast<std::size_t>(m)];
    s["probability"][id] = {{"min", sp.min}, {"q1", sp.q1},   {"median", sp.median},
                            {"q3", sp.q3},   {"max", sp.max}, {"mean", sp.mean}};
    s["total_log_likelihood"][id] = jsonNumber(out.result.total_log_likelihood[m]);
    s["joint_probability"][id] = jsonNumber(out.result.joint_probability[m]);
    s["factorization"][id] = info.factorization;
    s["cost_s_per_s"][id] = info.cost_s_per_s;
    s["models"][id] = {{"label", info.label},
                       {"folder", info.dir},
                       {"vectors", info.vectors},
                       {"dimension", info.dimension},
                       {"covariance", info.covariance},
                       {"shrinkage_intensity", info.shrinkage_intensity},
                       {"factorization", info.factorization},
                       {"jitter_relative", info.jitter},
                       {"jitter_absolute", info.jitter_absolute},
                       {"log_det", jsonNumber(info.log_det)},
                       {"relative_min_pivot", jsonNumber(info.relative_min_pivot)},
                       {"cost_s_per_s", info.cost_s_per_s},
                       {"build_wall_s", info.build_wall_s},
                       {"synthesis", info.synthesis}};
  }
  s["tied_records"] = out.result.tied_records;
  s["bayes_factors"] = nlohmann::json::array();
  for (const auto& pr : out.result.pairs)
    s["bayes_factors"].push_back(
        {{"a", ids[static_cast<std::size_t>(pr.a)]},
         {"b", ids[static_cast<std::size_t>(pr.b)]},
         {"two_ln_b", jsonNumber(pr.two_ln_b)},
         {"log_bayes_factor", jsonNumber(pr.log_bayes_factor)},
         {"favoured", pr.favoured >= 0 ? nlohmann::json(ids[static_cast<std::size_t>(pr.favoured)])
                                       : nlohmann::json(nullptr)},
         {"category", pr.category},
         {"meaning",
          "2 ln B_ab = 2 sum_r (loglik_a - loglik_b) over all records; Kass-Raftery scale"}});
  const auto& rec = out.recommendation;
  s["recommended"] = rec.recommended;
  s["recommendation_sentence"] = rec.explanation;
  nlohmann::json tl = nlohmann::json::object();
  for (int m = 0; m < M; ++m)
    tl[ids[static_cast<std::size_t>(m)]] = jsonNumber(rec.two_ln_b[static_cast<std::size_t>(m)]);
  s["recommendation"] = {
      {"recommended", rec.recommended},
      {"best_by_evidence", rec.best},
      {"candidates", rec.candidates},
      {"two_ln_b_vs_best", tl},
      {"cost_ratio_best_to_recommended", rec.cost_ratio},
      {"threshold_two_ln_b", opt.threshold},
      {"rule",
       "the cheapest assembly (median wall s per simulated s of its synthesis runs) whose joint "
       "evidence is not decisively worse than the best: 2 (L_best - L_m) < threshold"},
      {"sentence", rec.explanation}};
  s["report"] = out.result.fullReport();
  return s;
}

}  // namespace

// The steps of the file header: the compared assemblies and their syntheses → the covariance
// method → one Gaussian model per assembly and ℓ of every record → classification →
// recommendation → summary.json.
FieldClassification classifyField(const Study& study, const FieldData& field,
                                  const std::string& field_channel,
                                  const std::string& synthetic_dir, const FieldClassifyOptions& opt,
                                  const nlohmann::json& field_info) {
  opt.validate();
  if (field.rowCount() == 0 || field.columnCount() == 0)
    throw InputError("field data", "holds no records");
  const fs::path sdir(synthetic_dir);
  if (!fs::is_directory(sdir)) throw InputError(synthetic_dir, "synthetic data folder not found");
  const std::vector<AssemblySpec> targets = comparedAssemblies(study, sdir, opt);
  const int M = static_cast<int>(targets.size());
  const int p = static_cast<int>(field.columnCount());

  FieldClassification out;
  out.records = field.runs;
  const std::vector<nlohmann::json> infos = readSyntheses(targets, sdir, field, field_channel);
  chooseCovariance(infos, p, opt.covariance, out);
  const Eigen::MatrixXd Y = recordsAsColumns(field);
  out.log_likelihood.resize(static_cast<long>(field.rowCount()), M);
  out.models.resize(static_cast<std::size_t>(M));
  // Each assembly's model on its own worker, into its own column (the lowest failing assembly's
  // error is the one thrown, whatever the thread count).
  parallelFor(static_cast<std::size_t>(M), opt.threads, [&](std::size_t m, int) {
    out.models[m] = fitAssembly(targets[m], infos[m], sdir, out.covariance_method, opt.factor, Y,
                                out.log_likelihood.col(static_cast<Eigen::Index>(m)));
  });
  for (Eigen::Index r = 0; r < out.log_likelihood.rows(); ++r)
    for (int m = 0; m < M; ++m)
      if (std::isnan(out.log_likelihood(r, m)))
        throw InputError("field record " + std::to_string(field.runs[static_cast<std::size_t>(r)]),
                         "log likelihood is NaN");

  const ClassifyOptions co = recordOptions(targets, opt);
  out.result = classifyRecords(out.log_likelihood, co);

  // Cost-aware recommendation on the joint evidence.
  std::vector<ModelCost> mc;
  mc.reserve(static_cast<std::size_t>(M));
  for (int m = 0; m < M; ++m)
    mc.push_back({targets[static_cast<std::size_t>(m)].id, out.result.total_log_likelihood[m],
                  out.models[static_cast<std::size_t>(m)].cost_s_per_s});
  RecommendOptions ro;
  ro.threshold = opt.threshold;
  out.recommendation = recommendAssembly(mc, ro);
  out.summary = classificationSummary(study, field, field_channel, synthetic_dir, opt, field_info,
                                      co.model_ids, out);
  return out;
}

FieldClassification classifyFieldFile(const Study& study, const std::string& field_csv,
                                      const std::string& synthetic_dir,
                                      const FieldClassifyOptions& options) {
  if (!fs::exists(field_csv)) throw InputError(field_csv, "field data file not found");
  const FieldData field = readFieldCsv(field_csv);
  std::string channel;
  nlohmann::json info{{"path", field_csv},
                      {"fnv1a64", hexId(calib::fnv1a64(readTextFile(field_csv)))}};
  const std::string side = sidecarPath(field_csv);
  if (fs::exists(side)) {
    try {
      const nlohmann::json j = readJsonFile(side);
      if (j.contains("field") && j["field"].contains("channel"))
        channel = j["field"]["channel"].get<std::string>();
      info["sidecar"] = side;
      if (j.contains("assembly")) info["generated_by"] = j["assembly"];
    } catch (const nlohmann::json::exception&) {
      // a sidecar we cannot read says nothing about the channel
    }
  }
  if (channel.empty())
    info["channel_note"] = "no sidecar with the channel: assumed to be the synthesis's";
  return classifyField(study, field, channel, synthetic_dir, options, info);
}

void writeFieldClassification(const FieldClassification& c, const std::string& out_dir) {
  fs::create_directories(out_dir);
  writeFileAtomic((fs::path(out_dir) / "records.csv").string(), c.recordsCsv());
  writeFileAtomic((fs::path(out_dir) / "summary.json").string(), c.summary.dump(2) + "\n");
}

}  // namespace dtwin::classify
