#include "common/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <system_error>

#include "common/errors.hpp"
#include "common/files.hpp"

namespace dtwin {
namespace {

/// "2026-12-07T01:02:03Z": when the holder started.
std::string utcStamp() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

/// What the holder wrote into the lock file ("pid 1234, started ..."), or "" when unreadable.
std::string holderOf(int fd) {
  char buf[256];
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  if (n <= 0) return std::string();
  std::string s(buf, static_cast<std::size_t>(n));
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s.find('\n') == std::string::npos ? s : std::string();
}

/// Takes the lock on this process; returns the open descriptor (-1, after a note, on a filesystem
/// without locks). `created` tells whether the folder was made here.
int lockFolder(const std::string& dir, const std::string& path, const std::string& flag,
               bool& created) {
  const std::string where = flag + " " + dir;
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw InputError(where, "exists and is not a folder");
  created = !std::filesystem::exists(dir, ec);
  // A run that ends removes its lock file (and the folder it made, when empty): a lock taken on a
  // file that was removed meanwhile is no lock, so the file locked must still be the one at `path`.
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(where, "cannot create the folder: " + ec.message());
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0 && errno == ENOENT) continue;  // the folder went away meanwhile
    if (fd < 0) throw InputError(where, systemError("cannot open its lock file " + path));
    int rc;
    do rc = ::flock(fd, LOCK_EX | LOCK_NB);
    while (rc != 0 && errno == EINTR);
    if (rc != 0 && (errno == ENOLCK || errno == ENOSYS || errno == EOPNOTSUPP || errno == EINVAL)) {
      // A filesystem without locks (some cluster filesystems): run as before, and say so.
      std::fprintf(
          stderr, "twin: note: %s: %s\n", where.c_str(),
          systemError("the folder cannot be locked; a second run into it is not detected").c_str());
      ::close(fd);
      return -1;
    }
    if (rc != 0) {
      const int err = errno;
      const std::string holder = err == EWOULDBLOCK ? holderOf(fd) : std::string();
      ::close(fd);
      if (err != EWOULDBLOCK) {
        errno = err;
        throw InputError(where, systemError("cannot lock " + path));
      }
      throw InputError(where, "in use by another twin run" +
                                  (holder.empty() ? std::string() : " (" + holder + ")") +
                                  "; wait for it or choose another folder");
    }
    struct stat locked {
    }, named{};
    if (::fstat(fd, &locked) != 0 || ::stat(path.c_str(), &named) != 0 ||
        locked.st_ino != named.st_ino || locked.st_dev != named.st_dev) {
      ::close(fd);  // its holder removed it as it ended: lock the new one
      continue;
    }
    const std::string me = "pid " + std::to_string(::getpid()) + ", started " + utcStamp() + "\n";
    if (::ftruncate(fd, 0) == 0) {
      try {
        writeAll(fd, me, path);
      } catch (const std::exception&) {
        // the lock holds without its note: a second run names no holder
      }
    }
    return fd;
  }
  throw InputError(where, "cannot lock " + path +
                              ": it keeps being removed (another twin run starting and ending?)");
}

}  // namespace

FolderLock::FolderLock(const std::string& dir, const std::string& flag,
                       const Distributed* processes)
    : dir_(dir), path_((std::filesystem::path(dir) / ".lock").string()) {
  if (dir.empty()) return;  // no folder: nothing to lock
  onRoot(processes, [&]() -> std::string {
    fd_ = lockFolder(dir, path_, flag, created_dir_);
    return std::string();
  });
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  // Removed while still held, then released (closing the descriptor); a run that failed before it
  // wrote anything leaves the folder as it found it.
  ::unlink(path_.c_str());
  ::close(fd_);
  if (created_dir_) ::rmdir(dir_.c_str());  // only when empty
}

}  // namespace dtwin
