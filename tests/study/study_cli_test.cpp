// `twin study` end to end on a tiny study: a run killed with SIGKILL at six points across the
// stages and rerun each time with the same command (thread counts alternating) ends with the same
// files as an uninterrupted run; the summary has the fields scripts rely on.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>
#include <vector>

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
  const std::string base =
      std::string(DTWIN_TWIN_EXE) + " study --study " + study.string() + " --quiet";
  ASSERT_EQ(std::system((base + " --threads 2 --out " + (kTmp() / "whole").string()).c_str()), 0);

  const nlohmann::json s = nlohmann::json::parse(slurp(kTmp() / "whole" / "summary.json"));
  ASSERT_TRUE(s.contains("wins") && s.contains("recommended") && s.contains("stages"));
  int wins = 0;
  for (auto& [id, n] : s["wins"].items()) wins += n.get<int>();
  EXPECT_EQ(wins, 4);
  EXPECT_TRUE(s["recommended"] == "M3" || s["recommended"] == "M4");
  for (const char* st : {"lab", "field", "calibrate", "synthesize", "classify"})
    EXPECT_TRUE(s["stages"].contains(st)) << st;

  // Kill a second run with SIGKILL at points across the stages, rerunning it each time (the
  // thread count alternating), then let it finish: it must end with the same files.
  const fs::path cut = kTmp() / "cut";
  const fs::path pid = kTmp() / "pid";
  const std::vector<fs::path> kill_points = {
      cut / "lab" / "lab.csv",                            // field data being generated
      cut / "calibration" / "M3" / "design_journal.csv",  // M3's design running
      cut / "calibration" / "M4" / "design_journal.csv",  // M4's design running
      cut / "synthetic" / "M3",                           // synthesis started
      cut / "synthetic" / "M4",                           // second assembly's synthesis
      cut / "classification",                             // classification started
  };
  int killed = 0;
  for (std::size_t k = 0; k < kill_points.size(); ++k) {
    const std::string threads = k % 2 ? " --threads 1" : " --threads 2";
    ASSERT_EQ(
        std::system(
            (base + threads + " --out " + cut.string() + " & echo $! > " + pid.string()).c_str()),
        0);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string alive = "kill -0 $(cat " + pid.string() + ") 2>/dev/null";
    while (!fs::exists(kill_points[k]) && std::system(alive.c_str()) == 0) {
      ASSERT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(300))
          << "never reached " << kill_points[k];
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(
        20 * static_cast<int>(k)));  // land inside the stage, not at its door
    if (std::system(("kill -9 $(cat " + pid.string() + ") 2>/dev/null").c_str()) == 0) ++killed;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    if (fs::exists(cut / "summary.json")) break;  // the run finished before this point
  }
  EXPECT_GE(killed, 5) << "the kills must interrupt the run at five points at least";
  ASSERT_EQ(std::system((base + " --threads 1 --out " + cut.string()).c_str()), 0);
  for (const char* f : {"classification/records.csv", "calibration/M3/posterior.csv",
                        "calibration/M4/posterior.csv", "synthetic/M3/moments.bin",
                        "synthetic/M4/moments.bin", "field/field.csv", "lab/lab.csv"})
    EXPECT_EQ(slurp(kTmp() / "whole" / f), slurp(cut / f)) << f;
  const nlohmann::json r = nlohmann::json::parse(slurp(cut / "summary.json"));
  EXPECT_EQ(r["wins"], s["wins"]);
  EXPECT_EQ(r["recommended"], s["recommended"]);
  fs::remove_all(kTmp());
}
