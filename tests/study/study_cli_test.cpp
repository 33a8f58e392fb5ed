// `twin study` end to end on a tiny study: a run killed with SIGKILL and rerun with the same
// command (and another thread count) ends with the same files as an uninterrupted run; the
// summary has the fields scripts rely on.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {
/// Evaluated at use, after main() has given this process its own TMPDIR (tests/test_main.cpp).
fs::path kTmp() { return fs::temp_directory_path() / "dtwin_study_cli"; }

using dtwin_test::slurp;

}  // namespace

TEST(StudyCli, KilledStudyResumesToIdenticalResults) {
  fs::remove_all(kTmp());
  fs::create_directories(kTmp());
  const fs::path study = dtwin_test::writeTinyStudy(kTmp() / "tiny.toml");
  const std::string base = std::string(DTWIN_TWIN_EXE) + " study " + study.string() + " --quiet";
  ASSERT_EQ(std::system((base + " --threads 2 --out " + (kTmp() / "whole").string()).c_str()), 0);

  const nlohmann::json s = nlohmann::json::parse(slurp(kTmp() / "whole" / "summary.json"));
  ASSERT_TRUE(s.contains("wins") && s.contains("recommended") && s.contains("stages"));
  int wins = 0;
  for (auto& [id, n] : s["wins"].items()) wins += n.get<int>();
  EXPECT_EQ(wins, 4);
  EXPECT_TRUE(s["recommended"] == "M3" || s["recommended"] == "M4");
  for (const char* st : {"lab", "field", "calibrate", "synthesize", "classify"}) EXPECT_TRUE(s["stages"].contains(st)) << st;

  // Kill a second run once the calibration of the second assembly has started, then resume it.
  const fs::path cut = kTmp() / "cut";
  ASSERT_EQ(std::system((base + " --threads 2 --out " + cut.string() + " & echo $! > " + (kTmp() / "pid").string()).c_str()), 0);
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(cut / "calibration" / "M4" / "design_journal.csv")) {
    ASSERT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(300)) << "the study never reached M4's design";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(std::system(("kill -9 $(cat " + (kTmp() / "pid").string() + ")").c_str()), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_FALSE(fs::exists(cut / "summary.json"));
  ASSERT_EQ(std::system((base + " --threads 1 --out " + cut.string()).c_str()), 0);
  for (const char* f : {"classification/records.csv", "calibration/M3/posterior.csv", "calibration/M4/posterior.csv",
                        "synthetic/M3/moments.bin", "synthetic/M4/moments.bin", "field/field.csv", "lab/lab.csv"})
    EXPECT_EQ(slurp(kTmp() / "whole" / f), slurp(cut / f)) << f;
  const nlohmann::json r = nlohmann::json::parse(slurp(cut / "summary.json"));
  EXPECT_EQ(r["wins"], s["wins"]);
  EXPECT_EQ(r["recommended"], s["recommended"]);
  fs::remove_all(kTmp());
}
