// The main() of every test executable. CTest runs the tests of one executable as separate
// processes, possibly at the same time (ctest -j), and many tests write files: each process gets
// its own temporary folder (TMPDIR and TEST_TMPDIR point into it, so ::testing::TempDir(),
// std::filesystem::temp_directory_path() and every child process such as the `twin` CLI use it),
// which is removed at the end (kept, and its path printed, when DTWIN_KEEP_TEST_TMP is set).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
  const char* base = std::getenv("TMPDIR");
  std::string templ = std::string(base && *base ? base : "/tmp") + "/dtwin_test_XXXXXX";
  const char* dir = ::mkdtemp(templ.data());
  if (dir) {
    ::setenv("TMPDIR", dir, 1);
    ::setenv("TEST_TMPDIR", (std::string(dir) + "/").c_str(), 1);
  }
  ::testing::InitGoogleTest(&argc, argv);
  const int rc = RUN_ALL_TESTS();
  const char* keep = std::getenv("DTWIN_KEEP_TEST_TMP");
  if (dir && keep && *keep) {
    std::fprintf(stderr, "test files kept in %s\n", dir);
  } else if (dir) {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  return rc;
}
