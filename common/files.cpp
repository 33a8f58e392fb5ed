#include "common/files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/errors.hpp"

namespace dtwin {

std::string readTextFile(const std::string& path, const std::string& hint) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "is a folder, not a file" + hint);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot be read" + hint);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string systemError(const std::string& what) { return what + ": " + std::strerror(errno); }

void writeAll(int fd, const std::string& data, const std::string& path) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t w = ::write(fd, data.data() + done, data.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      if (StorageError::isStorageFull(errno)) throw StorageError(path, errno);
      throw std::runtime_error(systemError(path + ": cannot write"));
    }
    done += static_cast<std::size_t>(w);
  }
}

void syncParentDirectory(const std::string& path) {
  std::string dir = std::filesystem::path(path).parent_path().string();
  if (dir.empty()) dir = ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

void writeFileAtomic(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  std::error_code ec;
  if (p.has_parent_path()) fs::create_directories(p.parent_path(), ec);
  if (ec && StorageError::isStorageFull(ec.value()))
    throw StorageError(p.parent_path().string(), ec.value());
  if (ec)
    throw InputError(path,
                     "cannot create folder " + p.parent_path().string() + ": " + ec.message());
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0 && StorageError::isStorageFull(errno)) throw StorageError(path, errno);
  if (fd < 0) throw InputError(path, systemError("cannot write (is the folder writable?) " + tmp));
  try {
    writeAll(fd, content, tmp);
    if (::fsync(fd) != 0) {
      if (StorageError::isStorageFull(errno)) throw StorageError(tmp, errno);
      throw std::runtime_error(systemError(tmp + ": fsync"));
    }
  } catch (const StorageError& e) {  // named by the file the user knows, not the temporary one
    ::close(fd);
    ::unlink(tmp.c_str());
    throw StorageError(path, e.errorNumber());
  } catch (const std::exception& e) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw InputError(path, std::string("write failed (disk full?): ") + e.what());
  }
  ::close(fd);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    if (StorageError::isStorageFull(err)) {
      ::unlink(tmp.c_str());
      throw StorageError(path, err);
    }
    const std::string msg = systemError("cannot replace file");
    ::unlink(tmp.c_str());
    throw InputError(path, msg);
  }
  syncParentDirectory(path);
}

}  // namespace dtwin
