// A write that fills the storage raises StorageError (not InputError, not an internal error), and
// `twin` says what to do on one line. The storage is filled for real: a child process lowers its
// file size limit (RLIMIT_FSIZE) with SIGXFSZ ignored, so a write past it fails with EFBIG.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "common/errors.hpp"
#include "common/files.hpp"

namespace {

namespace fs = std::filesystem;

/// What the child reports through a pipe: "storage <what>", "input <what>", "other <what>" or
/// "none" (nothing thrown).
std::string inChildWithFileLimit(rlim_t bytes, void (*write)(const std::string&),
                                 const std::string& path) {
  int fds[2];
  if (::pipe(fds) != 0) return "pipe failed";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit lim{bytes, bytes};
    ::setrlimit(RLIMIT_FSIZE, &lim);
    std::string msg = "none";
    try {
      write(path);
    } catch (const dtwin::StorageError& e) {
      msg = std::string("storage ") + e.what() + " errno=" + std::to_string(e.errorNumber());
    } catch (const dtwin::InputError& e) {
      msg = std::string("input ") + e.what();
    } catch (const std::exception& e) {
      msg = std::string("other ") + e.what();
    }
    if (::write(fds[1], msg.data(), msg.size()) < 0) ::_exit(3);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string got;
  char buf[512];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;)
    got.append(buf, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int st = 0;
  ::waitpid(pid, &st, 0);
  return got;
}

}  // namespace

TEST(StorageError, AtomicWriteOverTheFileLimitIsAStorageError) {
  const fs::path dir = dtwin_test::freshDir("storage_atomic");
  const std::string path = (dir / "sub" / "summary.json").string();
  const std::string got = inChildWithFileLimit(
      4096, [](const std::string& p) { dtwin::writeFileAtomic(p, std::string(100000, 'x')); },
      path);
  EXPECT_EQ(got, "storage " + path + ": cannot write: the file size limit is reached (" +
                     std::strerror(EFBIG) + ") errno=" + std::to_string(EFBIG));
  EXPECT_FALSE(fs::exists(path)) << "the old file or none, never a part";
  for (const auto& e : fs::directory_iterator(dir / "sub"))
    ADD_FAILURE() << "left behind: " << e.path();
}

TEST(StorageError, AppendOverTheFileLimitIsAStorageError) {
  const fs::path dir = dtwin_test::freshDir("storage_append");
  const std::string path = (dir / "design_journal.csv").string();
  const std::string got = inChildWithFileLimit(
      1000,
      [](const std::string& p) {
        const int fd = ::open(p.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
        dtwin::writeAll(fd, std::string(5000, 'y'), p);
      },
      path);
  EXPECT_EQ(got.rfind("storage " + path + ": cannot write: the file size limit is reached", 0), 0u)
      << got;
}

TEST(StorageError, TheReasonOfEachErrno) {
  EXPECT_EQ(dtwin::StorageError("a.csv", ENOSPC).what(),
            std::string("a.csv: cannot write: the disk is full (") + std::strerror(ENOSPC) + ")");
  EXPECT_EQ(dtwin::StorageError("a.csv", EDQUOT).what(),
            std::string("a.csv: cannot write: the disk quota is used up (") +
                std::strerror(EDQUOT) + ")");
  EXPECT_TRUE(dtwin::StorageError::isStorageFull(ENOSPC));
  EXPECT_TRUE(dtwin::StorageError::isStorageFull(EDQUOT));
  EXPECT_TRUE(dtwin::StorageError::isStorageFull(EFBIG));
  EXPECT_FALSE(dtwin::StorageError::isStorageFull(EACCES));
}

// `twin calibrate` under a file size limit (prlimit): one line, no "internal error", what to do.
TEST(StorageError, CalibrateOnAFullDiskSaysFreeSpaceAndRerun) {
  if (std::system("command -v prlimit > /dev/null 2>&1") != 0) GTEST_SKIP() << "no prlimit";
  const fs::path dir = dtwin_test::freshDir("storage_cli");
  const std::string src = DTWIN_SOURCE_DIR;
  // Lab data first (small files), then a calibration whose files outgrow 20 kB.
  auto r = dtwin_test::runTwin("generate lab --study " + src +
                                   "/data/studies/demo.toml --repetitions 2 --out " +
                                   (dir / "lab.csv").string() + " --quiet",
                               dir);
  ASSERT_EQ(r.code, 0) << r.err;
  // SIGXFSZ ignored (a shell `trap '' XFSZ` is inherited through exec), the write gets EFBIG.
  const std::string cmd = "cd '" + dir.string() + "' && (trap '' XFSZ; prlimit --fsize=20000 " +
                          DTWIN_TWIN_EXE + " calibrate --study " + src +
                          "/data/studies/demo.toml --data lab.csv --assembly M3 --lhs-points 20 "
                          "--iterations 600 --burn-in 200 --max-rounds 0 --ridge-steps 0 --quiet "
                          "--out cal) > out.txt 2> err.txt";
  const int st = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(st)) << "killed by a signal";
  const std::string err = dtwin_test::slurp(dir / "err.txt");
  EXPECT_EQ(WEXITSTATUS(st), 1) << err;
  EXPECT_EQ(err.rfind("twin: cal/M3/", 0), 0u) << err;
  EXPECT_NE(err.find(": cannot write: the file size limit is reached ("), std::string::npos) << err;
  EXPECT_NE(err.find("; free space and rerun the same command — it resumes where it stopped\n"),
            std::string::npos)
      << err;
  EXPECT_EQ(err.find("internal error"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}
