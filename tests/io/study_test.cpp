// Study-file parsing: every bad input gives an InputError naming the file, the line or field,
// and the rule broken.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>

#include "common/errors.hpp"
#include "io/provenance.hpp"
#include "io/study.hpp"

using namespace dtwin;

namespace {
const std::string kSrc = DTWIN_SOURCE_DIR;

std::string readFile(const std::string& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Writes the paper study with `from` replaced by `to` into a temp file next to the data
/// (so that the relative vehicle path resolves) and returns its path.
std::string variant(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = readFile(kSrc + "/data/studies/paper.toml");
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  const std::string path = ::testing::TempDir() + "/" + name + ".toml";
  std::string t2 = text;
  const std::string veh = "vehicle = \"../vehicle/midsize_sedan.toml\"";
  t2.replace(t2.find(veh), veh.size(),
             "vehicle = \"" + kSrc + "/data/vehicle/midsize_sedan.toml\"");
  std::ofstream(path) << t2;
  return path;
}

std::string errorOf(const std::string& path) {
  try {
    loadStudy(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(Study, PaperAndDemoLoad) {
  const Study s = loadStudy(kSrc + "/data/studies/paper.toml");
  EXPECT_EQ(s.calibrated.size(), 4u);
  EXPECT_EQ(s.sizes.at("lhs_points"), 2000);
  EXPECT_DOUBLE_EQ(s.noise_variance_N2, 18000.0);
  const Study d = loadStudy(kSrc + "/data/studies/demo.toml");
  EXPECT_EQ(d.sizes.at("lhs_points"), 200);
}

TEST(Study, TruthOverridesVehicleNominal) {
  const std::string p = variant("truth", "truth = 180e3", "truth = 200e3");
  const Study s = loadStudy(p);
  EXPECT_DOUBLE_EQ(s.parameterTable().value("tire.stiffness"), 200e3);
}

TEST(Study, MalformedTomlNamesFileAndLine) {
  const std::string p = variant("malformed", "[noise]", "[noise");
  const std::string e = errorOf(p);
  EXPECT_NE(e.find(p + ":"), std::string::npos) << e;
  EXPECT_NE(e.find("malformed TOML"), std::string::npos) << e;
}

TEST(Study, UnknownOptionEffectFieldAndScenario) {
  EXPECT_NE(
      errorOf(variant("opt", "\"fiala\"]", "\"michelin\"]")).find("unknown tire option 'michelin'"),
      std::string::npos);
  const std::string e2 =
      errorOf(variant("eff", "[noise]", "[effects.bumpstop]\nstiffness = 1.0\n[noise]"));
  EXPECT_NE(e2.find("unknown effect 'bumpstop'"), std::string::npos) << e2;
  const std::string e3 = errorOf(variant("field", "variance_N2", "varience_N2"));
  EXPECT_NE(e3.find("noise.varience_N2: unknown field (did you mean 'variance_N2'?)"),
            std::string::npos)
      << e3;
  const Study s = loadStudy(kSrc + "/data/studies/paper.toml");
  try {
    s.scenario("track");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("unknown scenario 'track' (this study defines: lab, field)"),
        std::string::npos)
        << e.what();
  }
  try {
    s.assembly("M9");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("unknown assembly 'M9' (this study defines: M1, M2, M3, M4)"),
        std::string::npos)
        << e.what();
  }
}

TEST(Study, BoundsAndSigns) {
  const std::string e1 = errorOf(variant("bounds", "lower = 120e3", "lower = 900e3"));
  EXPECT_NE(e1.find("calibrated[0].lower: lower bound must be < upper bound"), std::string::npos)
      << e1;
  const std::string e2 =
      errorOf(variant("sign", "lower = 500.0\nupper = 7000.0", "lower = -500.0\nupper = 7000.0"));
  EXPECT_NE(e2.find("bound of tire.damping must be >= 0"), std::string::npos) << e2;
  const std::string e3 = errorOf(variant("unit", "unit = \"N/m\"", "unit = \"kN/m\""));
  EXPECT_NE(e3.find("unit of 'tire.stiffness' must be \"N/m\", got \"kN/m\""), std::string::npos)
      << e3;
  const std::string e4 = errorOf(variant("truth_out", "truth = 3000.0", "truth = 9000.0"));
  EXPECT_NE(e4.find("calibrated[1].truth: must lie within [lower, upper]"), std::string::npos)
      << e4;
}

// What the catalogue and the sizes can judge is judged when the file is read, not at first use.
TEST(Study, AssembliesRoadsAndSizesAreCheckedWhenRead) {
  const std::string e1 = errorOf(
      variant("m9", "[subsystems]", "[assemblies]\ninclude = [\"M1\", \"M9\"]\n\n[subsystems]"));
  EXPECT_NE(e1.find(".toml:9: assemblies.include: names assembly 'M9', which [subsystems] does not "
                    "define (it defines M1..M4)"),
            std::string::npos)
      << e1;
  const std::string e2 = errorOf(
      variant("twice", "[subsystems]", "[assemblies]\ninclude = [\"M2\", \"M2\"]\n\n[subsystems]"));
  EXPECT_NE(e2.find("assemblies.include: names assembly 'M2' twice"), std::string::npos) << e2;
  const std::string e3 =
      errorOf(variant("smooth", "smooth_until_s = 6.0", "smooth_until_s = -1.0"));
  EXPECT_NE(
      e3.find(
          "scenarios.field.road.smooth_until_s: must be >= 0 s (0: rough from the start), got -1"),
      std::string::npos)
      << e3;
  const std::string e4 = errorOf(variant("burn", "gibbs_burn_in = 15000", "gibbs_burn_in = 50000"));
  EXPECT_NE(
      e4.find("sizes.gibbs_burn_in: gibbs_burn_in (50000) must be below gibbs_iterations (50000)"),
      std::string::npos)
      << e4;
  const std::string e5 = errorOf(variant("iters", "gibbs_iterations = 50000\ngibbs_burn_in = 15000",
                                         "gibbs_iterations = 10000"));
  EXPECT_NE(
      e5.find(
          "sizes.gibbs_iterations: gibbs_burn_in (15000) must be below gibbs_iterations (10000)"),
      std::string::npos)
      << e5;
  EXPECT_EQ(
      loadStudy(variant("m2", "[subsystems]", "[assemblies]\ninclude = [\"M2\"]\n\n[subsystems]"))
          .assemblies()
          .size(),
      1u);
}

// The [calibration] table: defaults, the paper's procedure, and every bad value named.
TEST(Study, CalibrationSettings) {
  const Study d = loadStudy(kSrc + "/data/studies/demo.toml");
  EXPECT_EQ(d.calibration.region, "joint");
  EXPECT_EQ(d.calibration.designOrDefault(), "adaptive");
  const Study p =
      loadStudy(variant("cal_paper", "[noise]", "[calibration]\nregion = \"paper\"\n\n[noise]"));
  EXPECT_EQ(p.calibration.region, "paper");
  EXPECT_EQ(p.calibration.designOrDefault(), "lhs");
  const Study q = loadStudy(variant(
      "cal_all", "[noise]",
      "[calibration]\nregion = \"paper\"\ndesign = \"adaptive\"\nround_points = 50\nmax_rounds = "
      "3\n"
      "target_ess = 250.5\nmargin = 1.5\nridge_steps = 5\nsteps = \"adaptive\"\n\n[noise]"));
  EXPECT_EQ(q.calibration.designOrDefault(), "adaptive");
  EXPECT_EQ(q.calibration.round_points, 50);
  EXPECT_EQ(q.calibration.max_rounds, 3);
  EXPECT_DOUBLE_EQ(q.calibration.target_ess, 250.5);
  EXPECT_DOUBLE_EQ(q.calibration.margin, 1.5);
  EXPECT_EQ(q.calibration.ridge_steps, 5);
  EXPECT_EQ(q.calibration.steps, "adaptive");
  EXPECT_EQ(d.calibration.steps, "frozen");
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"region = \"box\"", "calibration.region: must be \"joint\""},
      {"design = \"grid\"", "calibration.design: must be \"adaptive\""},
      {"round_points = 1", "calibration.round_points: must be an integer >= 2, got 1"},
      {"max_rounds = -1", "calibration.max_rounds: must be an integer in [0, 100], got -1"},
      {"target_ess = 0", "calibration.target_ess: must be a finite number > 0"},
      {"target_ess = nan", "calibration.target_ess: must be a finite number"},
      {"margin = 0.5", "calibration.margin: must be a number in [1, 10]"},
      {"ridge_steps = -2", "calibration.ridge_steps: must be an integer in [0, 1000], got -2"},
      {"steps = \"fixed\"", "calibration.steps: must be \"frozen\""},
      {"max_round = 3", "calibration.max_round: unknown field (did you mean 'max_rounds'?)"},
  };
  for (const auto& [line, want] : bad) {
    const std::string e =
        errorOf(variant("cal_bad", "[noise]", "[calibration]\n" + line + "\n\n[noise]"));
    EXPECT_NE(e.find(want), std::string::npos) << line << " -> " << e;
    EXPECT_NE(e.find(".toml:"), std::string::npos) << e;
  }
}

TEST(Study, CsvRoadMustExistAndCoverTheRun) {
  const std::string p =
      variant("csvroad", "road = { type = \"bump\", height_m = 0.2, length_m = 0.1, time_s = 6.0 }",
              "road = { type = \"csv\", path = \"no_such_road.csv\" }");
  const std::string short_road = ::testing::TempDir() + "/no_such_road.csv";
  std::remove(short_road.c_str());  // hermetic: a previous run may have left it
  const Study s = loadStudy(p);
  auto model = s.makeModel(s.assembly("M1"));
  try {
    makeRoad(s.scenario("lab"), model->vehicle(), 1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_road.csv: cannot be read (a road profile)"),
              std::string::npos)
        << e.what();
  }
  std::ofstream(short_road) << "distance_m,left_m,right_m\n0,0,0\n1,0,0\n2,0,0\n";
  try {
    makeRoad(s.scenario("lab"), model->vehicle(), 1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("road profile covers distance_m"), std::string::npos)
        << e.what();
  }
}

TEST(Study, SettingsFromTheCommandLine) {
  const Study s = loadStudy(kSrc + "/data/studies/paper.toml");
  EXPECT_THROW(parseSetting("tire.stiffness", "--set"), InputError);
  try {
    s.makeModel(s.assembly("M1"), {}, {parseSetting("tire.stifness=2e5", "--set")});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "unknown parameter 'tire.stifness' (did you mean 'tire.stiffness'?)"),
              std::string::npos)
        << e.what();
  }
  try {
    s.makeModel(s.assembly("M1"), {}, {parseSetting("suspension.damping=-5", "--set")});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("suspension.damping must be >= 0"), std::string::npos)
        << e.what();
  }
  auto m = s.makeModel(s.assembly("M1"), {parseEffectSetting("bump_stop:stiffness=1e6,gap_m=0.03",
                                                             "--effect", s.effectCatalog())});
  EXPECT_DOUBLE_EQ(m->table().value("bump_stop.gap_m"), 0.03);
  EXPECT_GE(m->slot("bump_stop.stiffness"), 0);
}

// The one provenance writer: the three fields every JSON output opens with, the rest kept.
TEST(Provenance, StampAddsProgramCommandAndTimeAndKeepsTheRest) {
  nlohmann::json j{{"study", "s.toml"}, {"command", "an older command"}};
  nlohmann::json& out = dtwin::stampProvenance(j, "twin simulate --assembly M1");
  EXPECT_EQ(&out, &j);
  EXPECT_EQ(j.at("study"), "s.toml");
  EXPECT_EQ(j.at("command"), "twin simulate --assembly M1");
  EXPECT_EQ(j.at("program").at("name"), "twin");
  EXPECT_EQ(j.at("program"), dtwin::programInfo());
  const std::string t = j.at("created_utc").get<std::string>();
  EXPECT_TRUE(std::regex_match(t, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)"))) << t;
}
