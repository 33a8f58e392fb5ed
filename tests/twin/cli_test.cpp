// The `twin` executable: exit codes, one-line errors, outputs and sidecars.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace {
const std::string kSrc = DTWIN_SOURCE_DIR;

using Result = dtwin_test::TwinRun;
using dtwin_test::slurp;

Result twin(const std::string& args) { return dtwin_test::runTwin(args); }
}  // namespace

TEST(Cli, SimulateWritesTraceAndSidecar) {
  const std::string out = ::testing::TempDir() + "/cli/m3.csv";
  const auto r = twin("simulate --study " + kSrc +
                      "/data/studies/paper.toml --assembly M3 --scenario lab --out " + out +
                      " --set tire.stiffness=2.0e5 --window 5.9,6.3");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = slurp(out);
  EXPECT_EQ(csv.substr(0, csv.find('\n')).substr(0, 22), "time_s,speed_mps,hub_f");
  const auto j = nlohmann::json::parse(slurp(::testing::TempDir() + "/cli/m3.json"));
  EXPECT_EQ(j["assembly"]["id"], "M3");
  EXPECT_DOUBLE_EQ(j["run_parameters"]["tire.stiffness"]["value"].get<double>(), 2.0e5);
  EXPECT_EQ(j["run_parameters"]["tire.stiffness"]["source"], "--set");
  EXPECT_TRUE(j["stats"]["ok"].get<bool>());
  EXPECT_GT(j["stats"]["wall_s"].get<double>(), 0.0);
  EXPECT_TRUE(j.contains("program"));
  EXPECT_EQ(j["simulation"]["integrator"], "rosenbrock");
}

TEST(Cli, BadInputsExitTwoWithOneLine) {
  const std::string study = kSrc + "/data/studies/paper.toml";
  const std::string out = ::testing::TempDir() + "/cli/bad.csv";
  struct Case {
    std::string args, expect;
  };
  const std::vector<Case> cases = {
      {"simulate --study " + study + " --assembly M7 --out " + out, "unknown assembly 'M7'"},
      {"simulate --study " + study + " --scenario moon --out " + out, "unknown scenario 'moon'"},
      {"simulate --study " + study + " --effect warp_drive --out " + out,
       "--effect: unknown effect 'warp_drive'"},
      {"simulate --study " + study + " --set tire.stiffness=-1 --out " + out,
       "tire.stiffness must be > 0"},
      {"simulate --study " + study + " --set tire.stiffness=abc --out " + out, "must be a number"},
      {"simulate --study /nonexistent/study.toml --out " + out,
       "/nonexistent/study.toml: study file not found"},
      {"simulate --study " + study + " --out " + ::testing::TempDir() + "/cli/bad.txt",
       "--out: must name a .csv file"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = twin(c.args);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing may be written on bad input";
}

TEST(Cli, ListShowsAssembliesEffectsScenarios) {
  const auto r = twin("list --study " + kSrc + "/data/studies/paper.toml");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* s : {"M1", "M4", "pac2002 + macpherson", "bump_stop", "tire_enveloping",
                        "strut_friction", "damper_asymmetry", "lab", "field", "hub_force_fl_N"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}
