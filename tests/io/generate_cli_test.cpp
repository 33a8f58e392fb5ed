// `twin generate lab|field`: outputs readable by the measurement readers, sidecars, exit codes.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "io/measurement.hpp"

using namespace dtwin;

namespace {
const std::string kSrc = DTWIN_SOURCE_DIR;

using Result = dtwin_test::TwinRun;
using dtwin_test::slurp;

Result twin(const std::string& args) { return dtwin_test::runTwin(args); }
}  // namespace

TEST(GenerateCli, LabWritesTidyCsvAndSidecar) {
  const std::string out = ::testing::TempDir() + "/gen/lab.csv";
  const auto r = twin("generate lab --out " + out + " --repetitions 3 --seed 11 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  const LabData d = readLabCsv(out);
  EXPECT_EQ(d.repetitions(), (std::vector<long>{1, 2, 3}));
  EXPECT_EQ(d.channels(), (std::vector<std::string>{"hub_force_fl_N"}));
  EXPECT_EQ(d.records.size(), 15u);
  const auto j = nlohmann::json::parse(slurp(::testing::TempDir() + "/gen/lab.json"));
  EXPECT_EQ(j["kind"], "lab");
  EXPECT_EQ(j["seed"], 11);
  EXPECT_EQ(j["assembly"]["id"], "M1");
  EXPECT_EQ(j["lab"]["times_s"].size(), 5u);
  EXPECT_DOUBLE_EQ(j["truth"]["suspension.damping"]["value"].get<double>(), 2500.0);
  EXPECT_TRUE(j.contains("program"));
  EXPECT_NE(j["command"].get<std::string>().find("generate lab"), std::string::npos);
}

TEST(GenerateCli, FieldWritesMatrix) {
  const std::string out = ::testing::TempDir() + "/gen/field.csv";
  const auto r =
      twin("generate field --out " + out + " --runs 2 --threads 2 --window 10,10.01 --assembly M3");
  ASSERT_EQ(r.code, 0) << r.err;
  const FieldData d = readFieldCsv(out);
  EXPECT_EQ(d.rowCount(), 2u);
  EXPECT_EQ(d.columnCount(), 11u);
  EXPECT_EQ(d.road_seeds.size(), 2u);
  const auto j = nlohmann::json::parse(slurp(::testing::TempDir() + "/gen/field.json"));
  EXPECT_EQ(j["kind"], "field");
  EXPECT_EQ(j["assembly"]["id"], "M3");
  EXPECT_EQ(j["field"]["per_run"][1]["road_seed"], d.road_seeds[1]);
}

TEST(GenerateCli, BadInputsExitTwo) {
  const std::string out = ::testing::TempDir() + "/gen_bad/lab.csv";
  struct Case {
    std::string args, expect;
  };
  const std::vector<Case> cases = {
      {"generate lab --out " + out + " --assembly M9", "unknown assembly 'M9'"},
      {"generate lab --out " + ::testing::TempDir() + "/gen_bad/lab.txt",
       "--out: must name a .csv file"},
      {"generate lab --study /nonexistent/s.toml --out " + out,
       "/nonexistent/s.toml: study file not found"},
      {"generate lab --out " + out + " --scenario moon", "unknown scenario 'moon'"},
      {"generate field --out " + out + " --runs 1 --channel hub_force_fl_kN",
       "wrong unit suffix '_kN'"},
      {"generate field --out " + out + " --runs 1 --window 10,99", "lies outside the scenario"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = twin(c.args);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  }
  // Options of the other kind and a missing kind are usage errors (exit 2 too).
  EXPECT_EQ(twin("generate lab --out " + out + " --runs 3").code, 2);
  EXPECT_EQ(twin("generate --out " + out).code, 2);
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing may be written on bad input";
}

TEST(GenerateCli, HiddenEffectIsUsedRecordedAndPrinted) {
  const std::string dir = ::testing::TempDir() + "/gen_hidden";
  const std::string common =
      " --scenario diag_bump --repetitions 2 --times all --window 0.9,2.0 --rate 200";
  const auto base = twin("generate lab --out " + dir + "/base.csv" + common + " --quiet");
  ASSERT_EQ(base.code, 0) << base.err;
  const auto r = twin("generate lab --out " + dir + "/hidden.csv" + common +
                      " --channels hub_force_fl_N,susp_defl_fl_m --hidden-effect "
                      "bump_stop:stiffness=2e6,gap_m=0.02");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("hidden effect used to make the data: bump_stop (exponent=2, gap_m=0.02 m, "
                       "stiffness=2e+06 N/m^n)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("times: all samples in [0.9,2] at 200 Hz (221 times)"), std::string::npos)
      << r.out;

  // Times: 0.9, 0.905, ..., 2.0 for every repetition and channel.
  std::vector<double> expected;
  for (int k = 900; k <= 2000; k += 5) expected.push_back(k / 1000.0);
  const LabData b = readLabCsv(dir + "/base.csv"), h = readLabCsv(dir + "/hidden.csv");
  EXPECT_EQ(b.channels(), (std::vector<std::string>{"hub_force_fl_N"}));
  EXPECT_EQ(h.channels(), (std::vector<std::string>{"hub_force_fl_N", "susp_defl_fl_m"}));
  for (const LabData* d : {&b, &h})
    for (long rep : {1L, 2L})
      for (const auto& ch : d->channels()) {
        std::vector<double> t;
        for (const auto& rec : d->records)
          if (rec.repetition == rep && rec.channel == ch) t.push_back(rec.time_s);
        EXPECT_EQ(t, expected) << "repetition " << rep << " " << ch;
      }
  // The hub force differs at the bump (after 1 s), not before it.
  double diff_before = 0, diff_after = 0;
  for (const auto& rb : b.records)
    for (const auto& rh : h.records)
      if (rh.repetition == rb.repetition && rh.channel == rb.channel && rh.time_s == rb.time_s) {
        double& d = rb.time_s <= 0.98 ? diff_before : diff_after;
        d = std::max(d, std::abs(rh.value - rb.value));
      }
  EXPECT_EQ(diff_before, 0.0);
  EXPECT_GT(diff_after, 20.0) << "the stop pushes near the compression peaks (1.2 and 1.8 s)";

  const auto j = nlohmann::json::parse(slurp(dir + "/hidden.json"));
  ASSERT_EQ(j["hidden_effects"].size(), 1u);
  EXPECT_EQ(j["hidden_effects"][0]["name"], "bump_stop");
  EXPECT_EQ(j["hidden_effects"][0]["parameters"],
            nlohmann::json({{"stiffness", 2e6}, {"gap_m", 0.02}, {"exponent", 2.0}}));
  EXPECT_EQ(j["lab"]["times"]["source"], "all");
  EXPECT_NE(j["lab"]["times"]["rule"].get<std::string>().find("all samples in [0.9,2] at 200 Hz"),
            std::string::npos);
  EXPECT_FALSE(nlohmann::json::parse(slurp(dir + "/base.json")).contains("hidden_effects"));

  // Field data with a hidden effect: recorded and printed too, and different from the base.
  const std::string fcommon = " --scenario diag_rough --runs 1 --threads 1 --window 0,3";
  ASSERT_EQ(twin("generate field --out " + dir + "/fbase.csv" + fcommon + " --quiet").code, 0);
  const auto f = twin("generate field --out " + dir + "/fhid.csv" + fcommon +
                      " --hidden-effect damper_asymmetry:ratio=2.5");
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_NE(f.out.find("hidden effect used to make the data: damper_asymmetry (ratio=2.5)\n"),
            std::string::npos)
      << f.out;
  const FieldData fb = readFieldCsv(dir + "/fbase.csv"), fh = readFieldCsv(dir + "/fhid.csv");
  ASSERT_EQ(fb.values.size(), fh.values.size());
  double fdiff = 0;
  for (std::size_t i = 0; i < fb.values.size(); ++i)
    fdiff = std::max(fdiff, std::abs(fb.values[i] - fh.values[i]));
  EXPECT_GT(fdiff, 200.0);
  EXPECT_EQ(
      nlohmann::json::parse(slurp(dir + "/fhid.json"))["hidden_effects"][0]["parameters"]["ratio"],
      2.5);
}

TEST(GenerateCli, TimesAutoIsTheDefault) {
  const std::string dir = ::testing::TempDir() + "/gen_auto";
  ASSERT_EQ(
      twin("generate lab --scenario diag_bump --repetitions 2 --quiet --out " + dir + "/a.csv")
          .code,
      0);
  ASSERT_EQ(twin("generate lab --scenario diag_bump --repetitions 2 --quiet --times auto --out " +
                 dir + "/b.csv")
                .code,
            0);
  EXPECT_EQ(slurp(dir + "/a.csv"), slurp(dir + "/b.csv"));
  EXPECT_EQ(nlohmann::json::parse(slurp(dir + "/a.json"))["lab"]["times"]["source"], "automatic");
}

TEST(GenerateCli, BadDiagnosisFlagsExitTwoWithOneLine) {
  const std::string out = ::testing::TempDir() + "/gen_bad2/lab.csv";
  struct Case {
    std::string args, expect;
  };
  const std::vector<Case> cases = {
      {"generate lab --scenario diag_bump --times all --rate 300 --out " + out,
       "--rate: must divide the output rate 1000 Hz into an integer step"},
      {"generate lab --scenario diag_bump --rate 200 --out " + out,
       "--rate: needs every sample kept (times mode all)"},
      {"generate lab --scenario diag_bump --times all --window 0,9 --out " + out,
       "--window: 0 .. 9 s lies outside"},
      {"generate lab --scenario diag_bump --times all --channels hub_force_fl_N,bogus_m --out " +
           out,
       "--channels: unknown channel"},
      {"generate lab --scenario diag_bump --hidden-effect bump_stp:stiffness=1 --out " + out,
       "--hidden-effect"},
      {"generate lab --scenario diag_bump --hidden-effect bump_stop:stiffnes=1 --out " + out,
       "--hidden-effect stiffnes: unknown parameter 'bump_stop.stiffnes'"},
      {"generate field --scenario diag_rough --runs 1 --window 0,3 --hidden-effect warp_drive "
       "--out " +
           out,
       "--hidden-effect"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = twin(c.args);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  }
  EXPECT_EQ(twin("generate lab --times some --out " + out).code, 2);
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing may be written on bad input";
}
