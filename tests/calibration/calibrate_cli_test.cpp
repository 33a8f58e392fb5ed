// `twin calibrate` from the command line: bad input exits 2 with one line; a calibration killed
// with SIGKILL during its design stage and rerun with the same command ends with the same files
// as an uninterrupted one.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

namespace fs = std::filesystem;

namespace {
using dtwin_test::slurp;

using Result = dtwin_test::TwinRun;

/// Evaluated at use, after main() has given this process its own TMPDIR (tests/test_main.cpp).
fs::path kTmp() { return fs::temp_directory_path() / "dtwin_calibrate_cli"; }

Result twin(const std::string& args) { return dtwin_test::runTwin(args, kTmp()); }

std::size_t lines(const fs::path& p) {
  const std::string s = slurp(p);
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

class CalibrateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(kTmp());
    fs::create_directories(kTmp());
    ASSERT_EQ(twin("generate lab --quiet --out " + (kTmp() / "lab.csv").string()).code, 0);
  }
  void TearDown() override { fs::remove_all(kTmp()); }
};
}  // namespace

TEST_F(CalibrateCli, BadInputExitsTwoWithOneLine) {
  const std::string lab = (kTmp() / "lab.csv").string();
  struct Case {
    std::string args, expect;
  } cases[] = {
      {"calibrate --data " + (kTmp() / "missing.csv").string() + " --out " +
           (kTmp() / "o").string(),
       "lab data file not found"},
      {"calibrate --data " + lab + " --assembly M9 --out " + (kTmp() / "o").string(),
       "unknown assembly 'M9'"},
      // The library names the field (calibration.gibbs_burn_in); the CLI shows it as the flag.
      {"calibrate --data " + lab + " --iterations 100 --burn-in 100 --out " +
           (kTmp() / "o").string(),
       "error: --burn-in: must be below the number of Gibbs iterations (100), got 100"},
      {"calibrate --data " + lab + "@nowhere --out " + (kTmp() / "o").string(), "nowhere"},
  };
  for (const auto& c : cases) {
    const Result r = twin(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(kTmp() / "o" / "M1" / "posterior.csv"));
}

TEST_F(CalibrateCli, KilledRunResumesToIdenticalFiles) {
  const std::string base = std::string(DTWIN_TWIN_EXE) +
                           " calibrate --quiet --assembly M3 --starts 1 --lhs-points 300 "
                           "--max-rounds 1 --ridge-steps 0 --iterations 2000 " +
                           "--burn-in 500 --threads 1 --data " + (kTmp() / "lab.csv").string();
  ASSERT_EQ(std::system((base + " --out " + (kTmp() / "whole").string()).c_str()), 0);
  // Start the same calibration in the background, kill it with SIGKILL once the design journal
  // holds 30 points, then rerun the same command.
  const fs::path cut = kTmp() / "cut", journal = cut / "M3" / "design_journal.csv";
  ASSERT_EQ(
      std::system(
          (base + " --out " + cut.string() + " & echo $! > " + (kTmp() / "pid").string()).c_str()),
      0);
  const auto t0 = std::chrono::steady_clock::now();
  while (!(fs::exists(journal) && lines(journal) >= 31)) {
    ASSERT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(120))
        << "the design stage never started";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(std::system(("kill -9 $(cat " + (kTmp() / "pid").string() + ")").c_str()), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const std::size_t done_before = lines(journal) - 1;
  EXPECT_LT(done_before, 300u) << "killed too late to test a resume";
  EXPECT_FALSE(fs::exists(cut / "M3" / "posterior.csv"));
  ASSERT_EQ(std::system((base + " --out " + cut.string()).c_str()), 0);
  for (const char* f : {"posterior.csv", "design.csv", "optimum.json", "box.json"})
    EXPECT_EQ(slurp(kTmp() / "whole" / "M3" / f), slurp(cut / "M3" / f)) << f;
}
