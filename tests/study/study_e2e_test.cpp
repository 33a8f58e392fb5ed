// End to end on the demo study (reduced sizes): M1 generated the data, so M1 must be the most
// frequent winner; the recommendation must follow the documented rule (the cheapest assembly
// whose joint evidence is not decisively worse than the best: 2 (L_best - L_m) < 10).
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {
using dtwin_test::slurp;
}  // namespace

TEST(StudyEndToEnd, DemoStudyPicksTheGeneratingAssemblyAndFollowsTheRule) {
  const fs::path tmp = fs::temp_directory_path() / "e2e";
  fs::create_directories(tmp);
  dtwin_test::writeDemoStudy(
      tmp / "demo_small.toml",
      "lab_repetitions = 10\nfield_runs = 20\nlhs_points = 60\ngibbs_iterations = "
      "6000\ngibbs_burn_in = 1000\n"
      "posterior_draws = 40\nroads_per_draw = 5\nroad_library = 200\noptimizer_starts = 2\n");
  const std::string cmd = std::string(DTWIN_TWIN_EXE) + " study --study " +
                          (tmp / "demo_small.toml").string() + " --quiet --out " +
                          (tmp / "study").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);

  const auto sum = nlohmann::json::parse(slurp(tmp / "study" / "summary.json"));
  const auto cls = nlohmann::json::parse(slurp(tmp / "study" / "classification" / "summary.json"));
  // M1 is the most frequent winner.
  int total = 0, best_wins = -1;
  std::string most;
  for (auto& [id, n] : sum["wins"].items()) {
    total += n.get<int>();
    if (n.get<int>() > best_wins) best_wins = n.get<int>(), most = id;
  }
  EXPECT_EQ(total, 20);
  EXPECT_EQ(most, "M1") << sum["wins"].dump();
  // The recommendation follows the rule, recomputed here from the summary's numbers.
  std::string best;
  double lbest = -std::numeric_limits<double>::infinity();
  for (auto& [id, l] : cls["total_log_likelihood"].items())
    if (l.get<double>() > lbest) lbest = l.get<double>(), best = id;
  std::string cheapest;
  double cost = std::numeric_limits<double>::infinity();
  for (auto& [id, l] : cls["total_log_likelihood"].items()) {
    if (2.0 * (lbest - l.get<double>()) >= 10.0) continue;
    const double c = cls["cost_s_per_s"][id].get<double>();
    if (c < cost) cost = c, cheapest = id;
  }
  EXPECT_EQ(sum["recommended"], cheapest) << cls["recommendation"].dump();
  EXPECT_NE(sum["recommendation_sentence"].get<std::string>().find(cheapest + " is recommended"),
            std::string::npos);
  for (const char* st : {"lab", "field", "calibrate", "synthesize", "classify"})
    EXPECT_GT(sum["stages"][st].get<double>(), 0.0) << st;
}
