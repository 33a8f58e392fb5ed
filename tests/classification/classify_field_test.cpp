// End to end at tiny sizes: field records made by M3 (twin generate field's generator, 10-10.5 s
// window, p = 501) classified between syntheses of M3 and M4; then the twin CLI on the same files.
// Asserts only what is robust at these sizes: well-formed outputs, probabilities summing to 1,
// wins summing to the record count.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "classification/classify_field.hpp"
#include "classification/synthesis.hpp"
#include "common/errors.hpp"
#include "io/provenance.hpp"
#include "study/generate.hpp"
#include "twin/trace.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::classify;

namespace {
const std::string kDemo = std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml";

using dtwin_test::slurp;

struct World {
  Study study = loadStudy(kDemo);
  // One folder per process: ctest runs the tests of this file in parallel processes.
  fs::path dir = fs::temp_directory_path() / ("dtwin_classify_field_" + std::to_string(::getpid()));
  std::string field_csv;
  ~World() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  World() {
    fs::remove_all(dir);
    fs::create_directories(dir / "calib");
    FieldOptions fo;
    fo.runs = 6;
    fo.t_begin_s = 10.0;
    fo.t_end_s = 10.5;
    fo.threads = 2;
    const FieldResult f = generateField(study, study.assembly("M3"), fo);
    field_csv = (dir / "field.csv").string();
    writeFieldCsv(field_csv, f.data);
    writeFileAtomic(sidecarPath(field_csv), f.provenance.dump(2));
    for (const char* id : {"M3", "M4"}) {
      fs::create_directories(dir / "calib" / id);
      std::ofstream((dir / "calib" / id / "posterior.csv").string())
          << "tire.stiffness,tire.damping,suspension.stiffness,suspension.damping,tau,design_"
             "index\n"
             "180000,3000,30000,2500,5.5e-05,0\n"
             "182000,2900,31000,2400,5.6e-05,1\n";
      SynthesisOptions so;
      so.draws = 8;
      so.roads_per_draw = 2;
      so.road_library = 30;
      so.block = 4;
      so.threads = 2;
      so.t_begin_s = 10.0;
      so.t_end_s = 10.5;
      synthesizeAssembly(study, study.assembly(id),
                         calib::readPosteriorCsv((dir / "calib" / id / "posterior.csv").string()),
                         so, (dir / "synth" / id).string());
    }
  }
};

World& world() {
  static World w;
  return w;
}

int run(const std::string& args, std::string* err = nullptr) {
  const std::string e = (world().dir / "stderr.txt").string();
  const int rc =
      std::system((std::string(DTWIN_TWIN_EXE) + " " + args + " > /dev/null 2> " + e).c_str());
  if (err) *err = slurp(e);
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}
}  // namespace

TEST(ClassifyField, FieldRecordsOfM3AgainstM3AndM4) {
  World& w = world();
  FieldClassifyOptions o;
  const auto c = classifyFieldFile(w.study, w.field_csv, (w.dir / "synth").string(), o);
  ASSERT_EQ(c.models.size(), 2u);
  EXPECT_EQ(c.models[0].id, "M3");
  EXPECT_EQ(c.models[1].id, "M4");
  EXPECT_EQ(c.records.size(), 6u);
  // 16 vectors per assembly < 2p = 1002: Ledoit-Wolf, and the output says why.
  EXPECT_EQ(c.covariance_method, "ledoit-wolf");
  EXPECT_NE(c.covariance_reason.find("2p = 1002"), std::string::npos) << c.covariance_reason;
  int wins = 0;
  for (int m = 0; m < 2; ++m) {
    wins += c.result.wins[static_cast<std::size_t>(m)];
    EXPECT_FALSE(c.models[static_cast<std::size_t>(m)].factorization.empty());
    EXPECT_GT(c.models[static_cast<std::size_t>(m)].cost_s_per_s, 0.0);
  }
  EXPECT_EQ(wins, 6);
  for (Eigen::Index r = 0; r < c.result.probability.rows(); ++r) {
    EXPECT_NEAR(c.result.probability.row(r).sum(), 1.0, 1e-12);
    for (Eigen::Index m = 0; m < 2; ++m) EXPECT_TRUE(std::isfinite(c.log_likelihood(r, m)));
  }
  EXPECT_TRUE(c.recommendation.recommended == "M3" || c.recommendation.recommended == "M4");
  // The assemblies' models built one at a time give the same numbers bit for bit.
  FieldClassifyOptions one = o;
  one.threads = 1;
  o.threads = 2;
  const auto c1 = classifyFieldFile(w.study, w.field_csv, (w.dir / "synth").string(), one);
  const auto c2 = classifyFieldFile(w.study, w.field_csv, (w.dir / "synth").string(), o);
  EXPECT_TRUE((c1.log_likelihood.array() == c2.log_likelihood.array()).all());
  EXPECT_TRUE((c1.log_likelihood.array() == c.log_likelihood.array()).all());

  writeFieldClassification(c, (w.dir / "cls").string());
  const auto s = nlohmann::json::parse(slurp(w.dir / "cls" / "summary.json"));
  EXPECT_EQ(s["wins"]["M3"].get<int>() + s["wins"]["M4"].get<int>(), 6);
  EXPECT_EQ(s["recommended"], c.recommendation.recommended);
  EXPECT_FALSE(s["recommendation_sentence"].get<std::string>().empty());
  for (const char* key : {"probability", "bayes_factors", "factorization", "covariance",
                          "cost_s_per_s", "program", "field", "models"})
    EXPECT_TRUE(s.contains(key)) << key;
  ASSERT_EQ(s["bayes_factors"].size(), 1u);
  EXPECT_FALSE(s["bayes_factors"][0]["category"].get<std::string>().empty());
  EXPECT_EQ(s["field"]["channel"], "hub_force_fl_N");
  std::istringstream csv(slurp(w.dir / "cls" / "records.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "record,loglik_M3,loglik_M4,logpost_M3,logpost_M4,prob_M3,prob_M4,winner,tie");
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 8) << line;
  }
  EXPECT_EQ(rows, 6);
}

TEST(ClassifyField, PriorsSampleCovarianceAndMismatchedWindows) {
  World& w = world();
  FieldClassifyOptions o;
  o.prior = parsePriorList("M3=0.9,M4=0.1", "--prior");
  o.covariance = "sample";  // 16 vectors for p = 501: singular, rescued by jitter (reported)
  const auto c = classifyFieldFile(w.study, w.field_csv, (w.dir / "synth").string(), o);
  EXPECT_EQ(c.covariance_method, "sample");
  for (const auto& m : c.models)
    EXPECT_NE(m.factorization.find("jitter"), std::string::npos) << m.factorization;
  EXPECT_NEAR(std::exp(c.result.log_prior[0]), 0.9, 1e-15);
  EXPECT_THROW(parsePriorList("M3=0.5,M3=0.5", "--prior"), InputError);
  EXPECT_THROW(parsePriorList("M3", "--prior"), InputError);
  FieldClassifyOptions bad;
  bad.prior = {{"M3", 1.0}};
  EXPECT_THROW(classifyFieldFile(w.study, w.field_csv, (w.dir / "synth").string(), bad),
               InputError);  // no prior for M4
  // Field data over another window than the syntheses'.
  const FieldData f = readFieldCsv(w.field_csv);
  FieldData shorter = f;
  shorter.times_s.resize(201);
  shorter.values.clear();
  for (std::size_t r = 0; r < f.rowCount(); ++r)
    for (std::size_t k = 0; k < 201; ++k) shorter.values.push_back(f.at(r, k));
  try {
    classifyField(w.study, shorter, "hub_force_fl_N", (w.dir / "synth").string(),
                  FieldClassifyOptions{});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not the field data's"), std::string::npos) << e.what();
  }
  // The same ends and count, one time moved inside: the message names the first differing sample
  // (the two windows would otherwise read identically).
  FieldData shifted = f;
  shifted.times_s[7] += 0.0004;
  try {
    classifyField(w.study, shifted, "hub_force_fl_N", (w.dir / "synth").string(),
                  FieldClassifyOptions{});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("differ first at sample 8"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(classifyField(w.study, f, "susp_defl_fl_m", (w.dir / "synth").string(),
                             FieldClassifyOptions{}),
               InputError);
}

TEST(ClassifyField, CommandLine) {
  World& w = world();
  const std::string study = " --study " + kDemo;
  const std::string d = w.dir.string();
  std::string err;
  // synthesize from the same posteriors reuses nothing (other folder) and ends like the library.
  ASSERT_EQ(run("synthesize" + study + " --calibration " + d + "/calib --assembly M3 --out " + d +
                    "/cli_synth --draws 8 --roads 2 "
                    "--library 30 --block 4 --threads 2 --window 10,10.5 --quiet",
                &err),
            0)
      << err;
  EXPECT_TRUE(slurp(w.dir / "cli_synth" / "M3" / "moments.bin") ==
              slurp(w.dir / "synth" / "M3" / "moments.bin"));
  ASSERT_EQ(run("classify" + study + " --field " + w.field_csv + " --synthetic " + d +
                    "/synth --out " + d + "/cli_cls --threshold 6 --quiet",
                &err),
            0)
      << err;
  EXPECT_TRUE(fs::exists(w.dir / "cli_cls" / "records.csv"));
  const auto s = nlohmann::json::parse(slurp(w.dir / "cli_cls" / "summary.json"));
  EXPECT_EQ(s["recommendation"]["threshold_two_ln_b"], 6.0);
  // Bad input: exit code 2, one line.
  EXPECT_EQ(run("classify" + study + " --field " + w.field_csv + " --synthetic " + d +
                    "/nowhere --out " + d + "/x",
                &err),
            2);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("synthetic data folder not found"), std::string::npos) << err;
  EXPECT_EQ(
      run("synthesize" + study + " --calibration " + d + "/calib --assembly M1 --out " + d + "/x",
          &err),
      2);
  EXPECT_NE(err.find("posterior.csv: not found"), std::string::npos) << err;
  EXPECT_EQ(run("classify" + study + " --field " + w.field_csv + " --synthetic " + d +
                    "/synth --prior M3=2 --out " + d + "/x",
                &err),
            2);
}

// Options errors name the field as "field_classify.<field>" (common/validate.hpp); the factor
// options as "factor.<field>".
TEST(ClassifyField, OptionsNameTheField) {
  auto where = [](const FieldClassifyOptions& o) -> std::string {
    try {
      o.validate();
    } catch (const InputError& e) {
      return e.where();
    }
    return "no error";
  };
  FieldClassifyOptions o;
  EXPECT_EQ(where(o), "no error");
  o.covariance = "diagonal";
  EXPECT_EQ(where(o), "field_classify.covariance");
  o = {};
  o.threshold = 0.0;
  EXPECT_EQ(where(o), "field_classify.threshold");
  o = {};
  o.tie_tolerance = -1e-12;
  EXPECT_EQ(where(o), "field_classify.tie_tolerance");
  o = {};
  o.assemblies = {"M3", "M3"};
  EXPECT_EQ(where(o), "field_classify.assemblies");
  o = {};
  o.prior = {{"M3", 0.5}, {"M4", -0.5}};
  EXPECT_EQ(where(o), "field_classify.prior");
  o = {};
  o.factor.jitter_initial = 0.0;
  EXPECT_EQ(where(o), "factor.jitter_initial");
  o = {};
  o.threads = -1;
  EXPECT_EQ(where(o), "field_classify.threads");
}
