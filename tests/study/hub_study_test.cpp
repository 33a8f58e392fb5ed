// The paper's method with the road-input option in the catalogue: a study whose tire options are
// pac2002 and hub (the road signal as the hub's motion) runs whole. The hub assemblies leave the
// tire's calibrated values out (they have none), and the classification weighs them like any
// other assembly.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include <nlohmann/json.hpp>

#include "test_util.hpp"

namespace fs = std::filesystem;

TEST(HubStudy, AStudyWithTheHubInputAsATireOptionRunsWhole) {
  const fs::path dir = dtwin_test::freshDir("hub_study");
  const fs::path study = dtwin_test::writeTinyStudy(dir / "study.toml");
  std::string s = dtwin_test::slurp(study);
  s = std::regex_replace(s, std::regex("tire = \\[[^\\]]*\\]"), "tire = [\"pac2002\", \"hub\"]");
  s = std::regex_replace(s, std::regex("include = \\[[^\\]]*\\]"), "include = [\"M1\", \"M3\"]");
  dtwin_test::writeText(study, s);
  const auto r = dtwin_test::runTwin(
      "study --study " + study.string() + " --out " + (dir / "out").string() + " --quiet", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto m3 =
      nlohmann::json::parse(dtwin_test::slurp(dir / "out" / "calibration" / "M3" / "summary.json"));
  EXPECT_EQ(m3.at("label"), "hub + macpherson");
  EXPECT_EQ(m3.at("left_out"), nlohmann::json({"tire.stiffness", "tire.damping"}));
  EXPECT_EQ(m3.at("parameter_order"),
            nlohmann::json({"suspension.stiffness", "suspension.damping"}));
  const auto summary = nlohmann::json::parse(dtwin_test::slurp(dir / "out" / "summary.json"));
  ASSERT_TRUE(summary.at("wins").contains("M3"));
  // The field records come from M1 (a tire under the road): the tire assembly wins them.
  EXPECT_EQ(summary.at("recommended"), "M1");
  EXPECT_GT(summary.at("wins").at("M1").get<int>(), summary.at("wins").at("M3").get<int>());
}
