// The checksums of resumable files (common/checksum.hpp) and the lock on an output folder
// (common/folder_lock.hpp): a changed byte is seen, spacing is not; a damaged file is set aside
// with one note; a held folder is refused with its holder named, and freed when the holder ends.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "common/checksum.hpp"
#include "common/errors.hpp"
#include "common/folder_lock.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using dtwin_test::slurp;

TEST(Checksum, LineChecksumIsThe32BitFnv1a) {
  EXPECT_EQ(lineChecksum(""), "811c9dc5");   // the offset basis
  EXPECT_EQ(lineChecksum("a"), "e40c292c");  // published test vectors
  EXPECT_EQ(lineChecksum("foobar"), "bf9cf968");
  EXPECT_NE(lineChecksum("7,1.25,-3,0.5"), lineChecksum("7,1.25,-8,0.5"));
  EXPECT_EQ(contentChecksum(""), "fnv1a64:cbf29ce484222325");  // the 64-bit offset basis
  EXPECT_EQ(contentChecksum("a"), "fnv1a64:af63dc4c8601ec8c");
}

TEST(Checksum, SealedJsonHoldsThroughSpacingAndBreaksOnAChangedValue) {
  const nlohmann::json stage{
      {"fingerprint", "abc"},
      {"optimum",
       {{"theta", {0.1, 1.0 / 3.0, 180000.0, 1e-300, -2.5e17}}, {"sse", 12345.678901234567}}},
      {"count", 42},
      {"flag", true}};
  const nlohmann::json sealed = sealJson(stage);
  EXPECT_EQ(checkSeal(stage), Seal::absent);  // a file written before checksums: trusted as before
  for (int indent : {-1, 0, 2, 4})            // the file's spacing does not matter, its values do
    EXPECT_EQ(checkSeal(nlohmann::json::parse(sealed.dump(indent))), Seal::holds) << indent;
  EXPECT_EQ(sealJson(sealed), sealed);  // sealing again gives the same checksum
  std::string text = sealed.dump(2);
  const std::size_t at = text.find("12345.678901234567");
  ASSERT_NE(at, std::string::npos);
  text[at + 3] = '9';  // one digit
  EXPECT_EQ(checkSeal(nlohmann::json::parse(text)), Seal::broken);
  nlohmann::json other = sealed;
  other["count"] = 43;
  EXPECT_EQ(checkSeal(other), Seal::broken);
  other = sealed;
  other[kChecksumKey] = 7;
  EXPECT_EQ(checkSeal(other), Seal::broken);
}

TEST(Checksum, ADamagedFileIsSetAsideWithOneNote) {
  const fs::path dir = dtwin_test::freshDir("dtwin_checksum_aside");
  const fs::path f = dir / "box.json";
  dtwin_test::writeText(f, "{\"a\":1}\n");
  dtwin_test::writeText(dir / "box.json.corrupt", "older");
  ::testing::internal::CaptureStderr();
  const std::string aside = setAsideCorrupt(f.string(), "fails its checksum");
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(aside, f.string() + ".corrupt");
  EXPECT_FALSE(fs::exists(f));
  EXPECT_EQ(slurp(aside), "{\"a\":1}\n");  // the latest damaged one replaces an older one
  EXPECT_EQ(err, "twin: note: " + f.string() +
                     ": fails its checksum: the stage is redone, not trusted (set aside as " +
                     aside + ")\n");
}

TEST(FolderLock, ASecondHolderIsRefusedWithTheFirstNamed) {
  const fs::path dir = dtwin_test::freshDir("dtwin_folder_lock") / "out";
  {
    const FolderLock first(dir.string(), "--out", nullptr);
    EXPECT_TRUE(fs::is_directory(dir));
    EXPECT_EQ(first.path(), (dir / ".lock").string());
    const std::string holder = slurp(dir / ".lock");
    EXPECT_EQ(holder.rfind("pid " + std::to_string(::getpid()) + ", started 20", 0), 0u) << holder;
    try {  // flock locks an open file: a second open in the same process is a second holder
      const FolderLock second(dir.string(), "--out", nullptr);
      FAIL() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "--out " + dir.string());
      EXPECT_EQ(e.rule(), "in use by another twin run (" + holder.substr(0, holder.size() - 1) +
                              "); wait for it or choose another folder");
    }
    EXPECT_EQ(slurp(dir / ".lock"), holder);  // the refused run wrote nothing
  }
  EXPECT_FALSE(fs::exists(dir));  // released and removed with the first, with the folder it made
  {
    const FolderLock again(dir.string(), "--out", nullptr);
    dtwin_test::writeText(dir / "result.csv", "1\n");
  }
  EXPECT_FALSE(fs::exists(dir / ".lock"));
  EXPECT_TRUE(fs::exists(dir / "result.csv"));  // a folder with results stays
  const FolderLock none("", "--out", nullptr);  // no folder: nothing to lock
  EXPECT_THROW(FolderLock((dir / "result.csv").string(), "--out", nullptr),
               InputError);  // a file, not a folder
}

TEST(FolderLock, ALockFileRemovedByItsEndingHolderIsNotTrusted) {
  // A second run opened the first's lock file just before the first removed it and ended: its
  // lock on that file locks nothing, so it locks the file now at the path instead.
  const fs::path dir = dtwin_test::freshDir("dtwin_folder_lock_removed");
  const int stale = ::open((dir / ".lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(stale, 0);
  fs::remove(dir / ".lock");
  {
    const FolderLock lock(dir.string(), "--out", nullptr);
    EXPECT_TRUE(fs::exists(dir / ".lock"));
    EXPECT_EQ(::flock(stale, LOCK_EX | LOCK_NB), 0);  // the removed file is free: no one's lock
    EXPECT_THROW(FolderLock(dir.string(), "--out", nullptr), InputError);
  }
  ::close(stale);
}

TEST(FolderLock, AKilledHolderNeverBlocksTheNextRun) {
  const fs::path dir = dtwin_test::freshDir("dtwin_folder_lock_killed");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // holds the lock until killed
    ::close(ready[0]);
    try {
      const FolderLock held(dir.string(), "--out", nullptr);
      (void)!::write(ready[1], "x", 1);
      for (;;) ::pause();
    } catch (...) {
    }
    ::_exit(1);
  }
  ::close(ready[1]);
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  ::close(ready[0]);
  try {
    const FolderLock second(dir.string(), "--out", nullptr);
    ADD_FAILURE() << "the child's lock did not hold";
  } catch (const InputError& e) {
    EXPECT_NE(e.rule().find("pid " + std::to_string(child) + ","), std::string::npos) << e.rule();
  }
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status));
  const FolderLock next(dir.string(), "--out", nullptr);  // the kernel released it
  EXPECT_NE(slurp(dir / ".lock").find("pid " + std::to_string(::getpid()) + ","),
            std::string::npos);
}
