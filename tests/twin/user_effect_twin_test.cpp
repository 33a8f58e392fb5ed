// User-defined effects in a study file ([user_effects.NAME], subsystems/user_effect.hpp) through
// the whole twin: the damper asymmetry written as an expression gives the built-in effect's trace
// bit for bit, and bad definitions are one-line errors naming the file, the line and the field.
// Each study's definitions are its own (its EffectCatalog): two studies in one process, one after
// the other or in parallel threads, never see each other's.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "common/errors.hpp"
#include "io/study.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

namespace fs = std::filesystem;

namespace {

/// The demo study with `extra` appended (its vehicle path made absolute), written to `dir`.
std::string studyWith(const fs::path& dir, const std::string& extra) {
  std::string text = dtwin_test::slurp(std::string(DTWIN_SOURCE_DIR) + "/data/studies/demo.toml");
  const std::string rel = "vehicle = \"../vehicle/midsize_sedan.toml\"";
  text.replace(
      text.find(rel), rel.size(),
      "vehicle = \"" + std::string(DTWIN_SOURCE_DIR) + "/data/vehicle/midsize_sedan.toml\"");
  const fs::path p = dir / "study.toml";
  dtwin_test::writeText(p, text + "\n" + extra);
  return p.string();
}

struct Cli {
  int code;
  std::string err;
};
Cli twin(const std::string& args, const fs::path& dir) {
  const std::string cmd = std::string(DTWIN_TWIN_EXE) + " " + args + " > " +
                          (dir / "out.txt").string() + " 2> " + (dir / "err.txt").string();
  const int st = std::system(cmd.c_str());
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, dtwin_test::slurp(dir / "err.txt")};
}

const char* kMyAsymmetry = R"([user_effects.my_asymmetry]
element = "strut"
force = "v < 0 ? (ratio - 1) * c * v : 0"
parameters = { ratio = { value = 1.0, unit = "1", lower = 0.5, upper = 3.0 } }
)";

}  // namespace

TEST(UserEffectTwin, AnExpressionGivesTheBuiltInEffectsTraceBitForBit) {
  const fs::path dir = dtwin_test::freshDir("user_effect_twin");
  const std::string study = studyWith(dir, kMyAsymmetry);
  for (const char* e : {"damper_asymmetry", "my_asymmetry"}) {
    const Cli r = twin("simulate --study " + study + " --scenario lab --quiet --effect " + e +
                           ":ratio=2.2 --out " + (dir / (std::string(e) + ".csv")).string(),
                       dir);
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const std::string a = dtwin_test::slurp(dir / "damper_asymmetry.csv"),
                    b = dtwin_test::slurp(dir / "my_asymmetry.csv");
  ASSERT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == b) << "the user-defined effect's trace differs from the built-in one";
  // Off (ratio at its value 1), the trace is the base model's.
  ASSERT_EQ(twin("simulate --study " + study + " --scenario lab --quiet --out " +
                     (dir / "base.csv").string(),
                 dir)
                .code,
            0);
  ASSERT_EQ(
      twin("simulate --study " + study + " --scenario lab --quiet --effect my_asymmetry --out " +
               (dir / "off.csv").string(),
           dir)
          .code,
      0);
  EXPECT_TRUE(dtwin_test::slurp(dir / "base.csv") == dtwin_test::slurp(dir / "off.csv"));
  // `twin list` shows it with its parameter.
  ASSERT_EQ(twin("list --study " + study, dir).code, 0);
  EXPECT_NE(dtwin_test::slurp(dir / "out.txt").find("my_asymmetry.ratio"), std::string::npos);
}

TEST(UserEffectTwin, BadDefinitionsInTheStudyFileAreOneLineErrors) {
  const fs::path dir = dtwin_test::freshDir("user_effect_bad");
  struct Case {
    std::string extra, expect;
  };
  const std::vector<Case> cases = {
      {"[user_effects.soft]\nelement = \"strut\"\nforce = \"a * q * w\"\nparameters = { a = { "
       "value = 0, unit = \"N/m\", lower = 0, upper = 1e5 } }\n",
       "study.toml:"},
      {"[user_effects.soft]\nelement = \"strut\"\nforce = \"a * q\"\nparameters = { a = { value = "
       "0, unit = \"N/m\", lower = 0 } }\n",
       "user_effects.soft.parameters.a.upper: is required"},
      {"[user_effects.damper_asymmetry]\nelement = \"strut\"\nforce = \"a * q\"\nparameters = { a "
       "= { value = 0, unit = \"N/m\", lower = 0, upper = 1 } }\n",
       "user_effects.damper_asymmetry: 'damper_asymmetry' is a built-in effect's name"},
      {"[user_effects.soft]\nforce = \"a * q\"\n", "user_effects.soft.element: is required"},
      {"[user_effects.soft]\nelement = \"strut\"\nforce = \"a * q\"\ncolour = \"red\"\nparameters "
       "= { a = { value = 0, unit = \"N/m\", lower = 0, upper = 1 } }\n",
       "colour"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.extra);
    const std::string study = studyWith(dir, c.extra);
    const Cli r = twin("list --study " + study, dir);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
  // The unknown symbol's message names the line of the table and the field.
  const std::string study = studyWith(
      dir, std::string("[user_effects.soft]\nelement = \"strut\"\nforce = \"a * q * w\"\n") +
               "parameters = { a = { value = 0, unit = \"N/m\", lower = 0, upper = 1e5 } }\n");
  const Cli r = twin("list --study " + study, dir);
  EXPECT_NE(r.err.find(": user_effects.soft: force: 'a * q * w': Unexpected token \"w\""),
            std::string::npos)
      << r.err;
}

namespace {

/// Two studies that define `extra` differently (a strut force in q, one in v), and one more
/// effect only the second knows.
struct TwoStudies {
  fs::path dir_a = dtwin_test::freshDir("user_effect_two_a"),
           dir_b = dtwin_test::freshDir("user_effect_two_b");
  dtwin::Study a = dtwin::loadStudy(studyWith(dir_a, R"([user_effects.extra]
element = "strut"
force = "a * q"
parameters = { a = { value = 0, unit = "N/m", lower = 0, upper = 1e5 } }
)"));
  dtwin::Study b = dtwin::loadStudy(studyWith(dir_b, R"([user_effects.extra]
element = "strut"
force = "a * v"
parameters = { a = { value = 0, unit = "N*s/m", lower = 0, upper = 1e4 } }

[user_effects.only_b]
element = "chassis"
force = "f"
parameters = { f = { value = 0, unit = "N", lower = -1000, upper = 1000 } }
)"));
};

/// The front-left hub force of the lab run of `study`'s first assembly with `extra` at a = value.
std::vector<double> hubForce(const dtwin::Study& study, double value) {
  using namespace dtwin;
  const auto model = study.makeModel(
      study.assemblies().front(), {EffectSetting{"extra", {{"extra.a", value, "test", "test"}}}});
  Simulator sim(model, study.simulation);
  const ScenarioSpec& sc = study.scenario("lab");
  auto road = makeRoad(sc, model->vehicle(), study.seed);
  const RunResult r = sim.run(model->defaultRunValues(), *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r.trace.column("hub_force_fl_N");
}

}  // namespace

TEST(UserEffectTwin, TwoStudiesInOneProcessSeeOnlyTheirOwnDefinitions) {
  const TwoStudies s;
  auto has = [](const dtwin::Study& st, const std::string& n) {
    return st.effectCatalog().contains(n);
  };
  EXPECT_TRUE(has(s.a, "extra"));
  EXPECT_FALSE(has(s.a, "only_b"));
  EXPECT_TRUE(has(s.b, "only_b"));
  EXPECT_NE(s.a.effectCatalog().make("extra", "t")->description().find("a * q"), std::string::npos);
  EXPECT_NE(s.b.effectCatalog().make("extra", "t")->description().find("a * v"), std::string::npos);
  EXPECT_FALSE(s.a.parameterTable().contains("only_b.f"));
  EXPECT_TRUE(s.b.parameterTable().contains("only_b.f"));
  EXPECT_EQ(s.a.parameterTable().at("extra.a").spec.unit, "N/m");
  EXPECT_EQ(s.b.parameterTable().at("extra.a").spec.unit, "N*s/m");
  try {
    (void)s.a.makeModel(s.a.assemblies().front(), {dtwin::EffectSetting{"only_b", {}}});
    ADD_FAILURE() << "the first study knows only_b";
  } catch (const dtwin::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown effect 'only_b'"), std::string::npos) << e.what();
  }
  // The same name runs each study's own law: a spring in q and a damper in v give other traces,
  // and the first study's trace is the same before and after the second was used.
  const auto first = hubForce(s.a, 2e4);
  const auto other = hubForce(s.b, 2e3);
  EXPECT_NE(first, other);
  EXPECT_EQ(hubForce(s.a, 2e4), first);
  // Adding to a copy leaves the original's catalogue alone.
  dtwin::Study copy = s.a;
  ASSERT_EQ(s.b.effectCatalog().userEffects().size(), 2u);
  copy.addUserEffects({s.b.effectCatalog().userEffects()[1]});
  EXPECT_TRUE(has(copy, "only_b"));
  EXPECT_FALSE(has(s.a, "only_b"));
}

TEST(UserEffectTwin, TwoStudiesRunInParallelThreadsAsTheyDoAlone) {
  const TwoStudies s;
  const auto alone_a = hubForce(s.a, 2e4), alone_b = hubForce(s.b, 2e3);
  std::vector<double> par_a, par_b;
  std::thread ta([&] { par_a = hubForce(s.a, 2e4); });
  std::thread tb([&] { par_b = hubForce(s.b, 2e3); });
  ta.join();
  tb.join();
  EXPECT_EQ(par_a, alone_a);
  EXPECT_EQ(par_b, alone_b);
  EXPECT_NE(par_a, par_b);
}
