// `twin generate lab|field`: outputs readable by the measurement readers, sidecars, exit codes.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "twin/measurement.hpp"

using namespace dtwin;

namespace {
const std::string kSrc = DTWIN_SOURCE_DIR;

struct Result {
  int code;
  std::string err, out;
};

using dtwin_test::slurp;

Result twin(const std::string& args) {
  const std::string dir = ::testing::TempDir();
  const std::string cmd = std::string(DTWIN_TWIN_EXE) + " " + args + " > " + dir + "/gen_out.txt 2> " + dir + "/gen_err.txt";
  const int st = std::system(cmd.c_str());
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, slurp(dir + "/gen_err.txt"), slurp(dir + "/gen_out.txt")};
}
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
  const auto r = twin("generate field --out " + out + " --runs 2 --threads 2 --window 10,10.01 --assembly M3");
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
      {"generate lab --out " + ::testing::TempDir() + "/gen_bad/lab.txt", "--out: must name a .csv file"},
      {"generate lab --study /nonexistent/s.toml --out " + out, "/nonexistent/s.toml: study file not found"},
      {"generate lab --out " + out + " --scenario moon", "unknown scenario 'moon'"},
      {"generate field --out " + out + " --runs 1 --channel hub_force_fl_kN", "wrong unit suffix '_kN'"},
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
