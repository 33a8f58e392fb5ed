// Faults a user meets in a resumable output folder, from the command line: two runs into one
// folder at once (the second refuses at once, names the holder and writes nothing; the first ends
// as a run alone), stage files and the design journal changed on disk (set aside with a note, the
// stages redone, the same numbers bit for bit), and a changed posterior.csv (refused by its
// readers).
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using dtwin_test::slurp;

namespace {

/// Evaluated at use, after main() has given this process its own TMPDIR (tests/test_main.cpp).
fs::path kTmp() { return fs::temp_directory_path() / "dtwin_resume_faults"; }

dtwin_test::TwinRun twin(const std::string& args) { return dtwin_test::runTwin(args, kTmp()); }

/// The small calibration every case runs (M3, 12 design points, no adaptive rounds).
std::string calibrateArgs(const fs::path& out) {
  return "calibrate --quiet --assembly M3 --starts 1 --lhs-points 12 --iterations 300 --burn-in "
         "100 --max-rounds 0 "
         "--ridge-steps 0 --threads 2 --data " +
         (kTmp() / "lab.csv").string() + " --out " + out.string();
}

/// summary.json's numbers: the result without what says when, how long or by which command.
nlohmann::json numbers(const fs::path& summary) {
  nlohmann::json j = nlohmann::json::parse(slurp(summary));
  for (const char* k : {"created_utc", "command", "stages_wall_s", "median_run_wall_s", "program"})
    j.erase(k);
  return j;
}

std::size_t lineCount(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

/// `text` with the first digit at or after `from` changed (to the next one): still well formed.
std::string changeDigit(std::string text, std::size_t from) {
  for (std::size_t i = from; i < text.size(); ++i)
    if (text[i] >= '1' && text[i] <= '8') {
      ++text[i];
      return text;
    }
  ADD_FAILURE() << "no digit after " << from;
  return text;
}

class ResumeFaults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::remove_all(kTmp());
    fs::create_directories(kTmp());
    ASSERT_EQ(twin("generate lab --quiet --out " + (kTmp() / "lab.csv").string()).code, 0);
    const auto r =
        twin(calibrateArgs(kTmp() / "alone"));  // the undisturbed run every case is held to
    ASSERT_EQ(r.code, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(kTmp()); }
  static fs::path alone() { return kTmp() / "alone" / "M3"; }
  /// A copy of the undisturbed run's folder.
  static fs::path copyOfAlone(const std::string& name) {
    const fs::path d = kTmp() / name;
    fs::remove_all(d);
    fs::copy(kTmp() / "alone", d, fs::copy_options::recursive);
    return d;
  }
};

}  // namespace

TEST_F(ResumeFaults, AFolderInUseIsRefusedByEveryCommandThatResumes) {
  const fs::path out = kTmp() / "held";
  fs::remove_all(out);
  fs::create_directories(out);
  // The test process holds the lock, as a run would.
  const int fd = ::open((out / ".lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string holder = "pid " + std::to_string(::getpid()) + ", started 2001-02-03T04:05:06Z";
  ASSERT_EQ(::write(fd, (holder + "\n").data(), holder.size() + 1),
            static_cast<ssize_t>(holder.size() + 1));
  const std::string lab = (kTmp() / "lab.csv").string();
  for (const std::string& args :
       {calibrateArgs(out),
        "diagnose --quiet --force --assembly M3 --data " + lab + " --out " + out.string(),
        "study --quiet --force --out " + out.string(),
        "coverage --quiet --force --assembly M3 --seeds 2 --out " + out.string(),
        "synthesize --quiet --force --assembly M3 --draws 2 --calibration " +
            (kTmp() / "alone").string() + " --out " + out.string()}) {
    const auto r = twin(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err, "twin: error: --out " + out.string() + ": in use by another twin run (" +
                         holder + "); wait for it or choose another folder\n")
        << args;
  }
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(out)) files.insert(e.path().filename().string());
  EXPECT_EQ(files, std::set<std::string>{".lock"});  // the refused runs wrote nothing
  EXPECT_EQ(slurp(out / ".lock"), holder + "\n");
  ::close(fd);  // released: the next run goes ahead
  const auto r = twin(calibrateArgs(out));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(numbers(out / "M3" / "summary.json"), numbers(alone() / "summary.json"));
}

TEST_F(ResumeFaults, TwoRunsStartedTogetherTheSecondRefusesTheFirstEndsAsAlone) {
  const fs::path out = kTmp() / "shared", rc = kTmp() / "first_rc";
  fs::remove_all(out);
  fs::remove(rc);
  // The first run in the background; its exit code lands in first_rc.
  ASSERT_EQ(std::system(("(" + std::string(DTWIN_TWIN_EXE) + " " + calibrateArgs(out) + " > " +
                         (kTmp() / "first.out").string() + " 2> " +
                         (kTmp() / "first.err").string() + "; echo $? > " + rc.string() + ") &")
                            .c_str()),
            0);
  const auto t0 = std::chrono::steady_clock::now();
  while (slurp(out / ".lock").find('\n') ==
         std::string::npos) {  // its lock taken and its holder written
    ASSERT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(60))
        << "the first run never started";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const std::string holder = slurp(out / ".lock");
  const auto second = twin(calibrateArgs(out));
  const bool first_still_running = !fs::exists(rc);
  EXPECT_EQ(second.code, 2) << second.err;
  EXPECT_EQ(second.err, "twin: error: --out " + out.string() + ": in use by another twin run (" +
                            holder.substr(0, holder.size() - 1) +
                            "); wait for it or choose another folder\n");
  EXPECT_EQ(second.out, "");
  EXPECT_TRUE(first_still_running) << "the first run ended before the second was refused";
  while (slurp(rc).find('\n') == std::string::npos) {
    ASSERT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(600))
        << "the first run never ended";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(slurp(rc), "0\n") << slurp(kTmp() / "first.err");
  EXPECT_FALSE(fs::exists(out / ".lock"));  // removed by its holder as it ended
  EXPECT_EQ(numbers(out / "M3" / "summary.json"), numbers(alone() / "summary.json"));
  EXPECT_EQ(slurp(out / "M3" / "posterior.csv"), slurp(alone() / "posterior.csv"));
}

TEST_F(ResumeFaults, StageFilesChangedOnDiskAreSetAsideAndRedoneToTheSameNumbers) {
  const fs::path dir = copyOfAlone("damaged"), m3 = dir / "M3";
  // The design journal: a digit of line 5 changed (the line stays well formed).
  const std::string journal = slurp(m3 / "design_journal.csv");
  std::size_t line5 = 0;
  for (int k = 0; k < 4; ++k) line5 = journal.find('\n', line5) + 1;
  dtwin_test::writeText(m3 / "design_journal.csv",
                        changeDigit(journal, journal.find(',', line5) + 1));
  // optimum.json: a digit of its SSE overwritten; box.json: bytes in the middle overwritten.
  const std::string optimum = slurp(m3 / "optimum.json");
  dtwin_test::writeText(m3 / "optimum.json", changeDigit(optimum, optimum.find("\"sse\"")));
  std::string box = slurp(m3 / "box.json");
  box.replace(box.size() / 2, 4, "\x01\x02\x03\x04");
  dtwin_test::writeText(m3 / "box.json", box);
  fs::remove(m3 / "summary.json");
  fs::remove(m3 / "posterior.csv");

  const auto r = twin(calibrateArgs(dir));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string m = m3.string();
  EXPECT_NE(r.err.find("twin: note: " + m +
                       "/design_journal.csv: line 5 fails its checksum: the stage is redone, not "
                       "trusted (set aside as " +
                       m + "/design_journal.csv.corrupt)\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("twin: note: " + m +
                       "/optimum.json: fails its checksum: the stage is redone, not trusted"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("twin: note: " + m + "/box.json: "), std::string::npos) << r.err;
  EXPECT_EQ(lineCount(r.err), 3u) << r.err;
  for (const char* f : {"design_journal.csv.corrupt", "optimum.json.corrupt", "box.json.corrupt"})
    EXPECT_TRUE(fs::exists(m3 / f)) << f;
  EXPECT_EQ(slurp(m3 / "design_journal.csv.corrupt"),
            changeDigit(journal, journal.find(',', line5) + 1));
  // The same numbers as the undisturbed run, bit for bit, and the same files.
  EXPECT_EQ(numbers(m3 / "summary.json"), numbers(alone() / "summary.json"));
  for (const char* f : {"posterior.csv", "design.csv", "optimum.json",
                        "box.json"})  // the journal: in completion order
    EXPECT_EQ(slurp(m3 / f), slurp(alone() / f)) << f;
  // A third run trusts what the second wrote: no note.
  const auto again = twin(calibrateArgs(dir));
  EXPECT_EQ(again.code, 0);
  EXPECT_EQ(again.err, "");
}

TEST_F(ResumeFaults, AChangedPosteriorIsRefusedByItsReaders) {
  const fs::path dir = copyOfAlone("post"), post = dir / "M3" / "posterior.csv";
  const auto summary = nlohmann::json::parse(slurp(dir / "M3" / "summary.json"));
  ASSERT_TRUE(summary.contains("posterior_checksum"));
  const std::string text = slurp(post);
  std::size_t middle = text.size() / 2;
  middle = text.find('\n', middle) + 1;  // a row in the middle: its first value changed
  dtwin_test::writeText(post, changeDigit(text, middle));
  const std::string rule = post.string() + ": fails its checksum (" +
                           (dir / "M3" / "summary.json").string() + " records " +
                           summary["posterior_checksum"].get<std::string>() +
                           "): it changed after the calibration wrote it and is not used";
  const std::string lab = (kTmp() / "lab.csv").string();
  for (const std::string& args :
       {"compare --quiet --draws 2 --calibration " + (dir / "M3").string() + " --data " + lab,
        "synthesize --quiet --force --assembly M3 --draws 2 --calibration " + dir.string() +
            " --out " + (kTmp() / "syn").string()}) {
    const auto r = twin(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(rule), std::string::npos) << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
  }
  EXPECT_FALSE(fs::exists(kTmp() / "syn" / "M3" / "moments.bin"));
  // The undamaged file reads; a rerun of the calibration writes it again.
  EXPECT_EQ(
      twin("compare --quiet --draws 2 --calibration " + alone().string() + " --data " + lab).code,
      0);
  EXPECT_EQ(twin(calibrateArgs(dir)).code, 0);
  EXPECT_EQ(slurp(post), slurp(alone() / "posterior.csv"));
}
