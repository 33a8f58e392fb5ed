// The same commands with `mpirun -n 2` and in one process write byte-identical results:
// `twin calibrate` (posterior.csv, design.csv, optimum.json, box.json), `twin synthesize`
// (moments.bin), `twin generate field` (the CSV) and a tiny `twin study` (every calibration,
// synthesis and classification result). Skipped when twin was built without MPI or mpirun is
// not installed. Oversubscription is allowed (2 ranks on any machine).
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "common/distributed.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  EXPECT_TRUE(in.good()) << p;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::string kTwin = DTWIN_TWIN_EXE;
const std::string kDemo = (fs::path(DTWIN_SOURCE_DIR) / "data" / "studies" / "demo.toml").string();

int run(const std::string& cmd) {
  const int rc = std::system((cmd + " > /dev/null 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

bool haveMpirun() { return std::system("mpirun --version > /dev/null 2>&1") == 0; }
std::string mpirun2() { return "mpirun --allow-run-as-root --oversubscribe -n 2 "; }

#define SKIP_WITHOUT_MPI()                                                                 \
  do {                                                                                     \
    if (!dtwin::Distributed::builtWithMpi()) GTEST_SKIP() << "twin was built without MPI"; \
    if (!haveMpirun()) GTEST_SKIP() << "mpirun is not installed (Debian: openmpi-bin)";    \
  } while (0)

void expectSameFile(const fs::path& a, const fs::path& b) {
  ASSERT_TRUE(fs::exists(a)) << a;
  ASSERT_TRUE(fs::exists(b)) << b;
  EXPECT_TRUE(slurp(a) == slurp(b)) << a << " and " << b << " differ";
}

}  // namespace

TEST(MpiCli, CalibrateAndSynthesizeAreBitIdenticalWithTwoRanks) {
  SKIP_WITHOUT_MPI();
  const fs::path tmp = fs::temp_directory_path() / "mpi_cli";
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  const std::string lab = (tmp / "lab.csv").string();
  ASSERT_EQ(run(kTwin + " generate lab --study " + kDemo + " --out " + lab + " --quiet"), 0);

  const std::string calib = " calibrate --study " + kDemo + " --data " + lab +
                            " --assembly M3 --starts 3 --lhs-points 20 --max-rounds 2 "
                            "--ridge-steps 3 --iterations 300 --burn-in 100 --quiet --out ";
  ASSERT_EQ(run(kTwin + calib + (tmp / "c1").string() + " --threads 1"), 0);
  ASSERT_EQ(run(mpirun2() + kTwin + calib + (tmp / "c2").string() + " --threads 1"), 0);
  for (const char* f : {"posterior.csv", "design.csv", "optimum.json", "box.json"})
    expectSameFile(tmp / "c1" / "M3" / f, tmp / "c2" / "M3" / f);
  // Only the root journals, once per point.
  EXPECT_EQ(slurp(tmp / "c2" / "M3" / "design_journal.csv").size(),
            slurp(tmp / "c1" / "M3" / "design_journal.csv").size());

  const std::string synth =
      " synthesize --study " + kDemo + " --calibration " + (tmp / "c1").string() +
      " --assembly M3 --draws 14 --roads 2 --block 3 --window 10,10.5 --quiet --out ";
  ASSERT_EQ(run(kTwin + synth + (tmp / "s1").string() + " --threads 1"), 0);
  ASSERT_EQ(run(mpirun2() + kTwin + synth + (tmp / "s2").string() + " --threads 1"), 0);
  ASSERT_EQ(run(mpirun2() + kTwin + synth + (tmp / "s3").string() + " --threads 2"), 0);
  expectSameFile(tmp / "s1" / "M3" / "moments.bin", tmp / "s2" / "M3" / "moments.bin");
  expectSameFile(tmp / "s1" / "M3" / "moments.bin", tmp / "s3" / "M3" / "moments.bin");
  EXPECT_FALSE(fs::exists(tmp / "s2" / "M3" / "checkpoint.json"));
  // One block per leaf: five leaves in rounds of two, the last round's second rank without one.
  ASSERT_EQ(run(kTwin + synth + (tmp / "t1").string() + " --threads 1 --leaf-blocks 1"), 0);
  ASSERT_EQ(run(mpirun2() + kTwin + synth + (tmp / "t2").string() + " --threads 1 --leaf-blocks 1"),
            0);
  expectSameFile(tmp / "t1" / "M3" / "moments.bin", tmp / "t2" / "M3" / "moments.bin");
  // A rerun under MPI reuses the finished files.
  ASSERT_EQ(run(mpirun2() + kTwin + synth + (tmp / "s2").string() + " --threads 1"), 0);
  expectSameFile(tmp / "s1" / "M3" / "moments.bin", tmp / "s2" / "M3" / "moments.bin");

  const std::string field =
      " generate field --study " + kDemo + " --runs 5 --window 10,10.5 --quiet --out ";
  ASSERT_EQ(run(kTwin + field + (tmp / "f1.csv").string() + " --threads 1"), 0);
  ASSERT_EQ(run(mpirun2() + kTwin + field + (tmp / "f2.csv").string() + " --threads 1"), 0);
  expectSameFile(tmp / "f1.csv", tmp / "f2.csv");

  // An input error stops every rank with exit code 2 (mpirun passes it on) and writes nothing.
  EXPECT_NE(run(mpirun2() + kTwin + " synthesize --study " + kDemo + " --calibration " +
                (tmp / "c1").string() + " --assembly M9 --out " + (tmp / "bad").string()),
            0);
  EXPECT_FALSE(fs::exists(tmp / "bad"));
}

TEST(MpiCli, TinyStudyIsBitIdenticalWithTwoRanks) {
  SKIP_WITHOUT_MPI();
  const fs::path tmp = fs::temp_directory_path() / "mpi_study";
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  const fs::path study = dtwin_test::writeTinyStudy(tmp / "tiny.toml", 2);
  const std::string cmd =
      kTwin + " study --study " + study.string() + " --threads 1 --quiet --out ";
  ASSERT_EQ(run(cmd + (tmp / "one").string()), 0);
  ASSERT_EQ(run(mpirun2() + cmd + (tmp / "two").string()), 0);
  for (const std::string f :
       {"lab/lab.csv", "field/field.csv", "calibration/M3/posterior.csv",
        "calibration/M4/posterior.csv", "calibration/M4/design.csv", "synthetic/M3/moments.bin",
        "synthetic/M4/moments.bin", "classification/records.csv"})
    expectSameFile(tmp / "one" / f, tmp / "two" / f);
}

// A rank killed mid-calibration (a crashed node): mpirun stops the job, the root says in one line
// that the finished work is kept, and the same command run again resumes to the files of a run
// that was never stopped.
TEST(MpiCli, AKilledRankStopsTheJobAndTheRerunResumesToTheSameFiles) {
  SKIP_WITHOUT_MPI();
  const fs::path tmp = fs::temp_directory_path() / "mpi_cli_killed";
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  const std::string lab = (tmp / "lab.csv").string();
  ASSERT_EQ(run(kTwin + " generate lab --study " + kDemo + " --out " + lab + " --quiet"), 0);
  const std::string calib = " calibrate --study " + kDemo + " --data " + lab +
                            " --assembly M3 --starts 2 --lhs-points 40 --max-rounds 1 "
                            "--ridge-steps 3 --iterations 300 --burn-in 100 "
                            "--quiet --threads 1 --out ";
  ASSERT_EQ(run(kTwin + calib + (tmp / "alone").string()), 0);

  // Rank 1 dies of SIGKILL once the root has journalled 8 design points.
  const fs::path out = tmp / "killed", journal = out / "M3" / "design_journal.csv";
  const std::string script =
      "(" + mpirun2() + kTwin + calib + out.string() + " > " + (tmp / "err.txt").string() +
      " 2>&1; echo $? > " + (tmp / "rc.txt").string() +
      ") & job=$!\n"
      "for i in $(seq 600); do [ -f " +
      journal.string() + " ] && [ $(wc -l < " + journal.string() +
      ") -ge 9 ] && break; sleep 0.1; done\n"
      "for p in $(pgrep -f 'twin calibrate.*" +
      out.string() +
      "'); do\n"
      "  grep -qz '^OMPI_COMM_WORLD_RANK=1$' /proc/$p/environ 2>/dev/null && kill -9 $p\n"
      "done\nwait $job\n";
  dtwin_test::writeText(tmp / "kill.sh", script);
  ASSERT_EQ(std::system(("bash " + (tmp / "kill.sh").string()).c_str()), 0);
  EXPECT_NE(std::stoi(slurp(tmp / "rc.txt")), 0) << "the job went on without a rank";
  const std::string err = slurp(tmp / "err.txt");
  const std::string line =
      "twin: stopped by a signal; the finished work is kept: rerun the same command to resume "
      "where it stopped";
  EXPECT_NE(err.find(line), std::string::npos) << err;
  EXPECT_EQ(err.find(line), err.rfind(line)) << "one line per job, not per rank:\n" << err;
  EXPECT_FALSE(fs::exists(out / "M3" / "posterior.csv"))
      << "the rank died after the calibration ended: the test proves nothing";

  ASSERT_EQ(run(mpirun2() + kTwin + calib + out.string()), 0);
  for (const char* f : {"posterior.csv", "design.csv", "optimum.json", "box.json"})
    EXPECT_EQ(slurp(tmp / "alone" / "M3" / f), slurp(out / "M3" / f)) << f;
}
