#pragma once
// Whole files in and out, with errors that name the file: the one reader and the one atomic,
// durable writer of the project (every output, the resumable stages' state, the design journal).
#include <string>

namespace dtwin {

/// The bytes of `path`; InputError(path, "cannot be read" + hint) when it cannot be opened, and
/// InputError(path, "is a folder, not a file" + hint) for a folder.
/// `hint` is appended as is (e.g. " (is this a `twin study` folder?)").
std::string readTextFile(const std::string& path, const std::string& hint = "");

/// Writes `content` to `path` atomically and durably: a temporary file in the same folder,
/// written in full and fsync'ed, renamed over `path`, then the folder fsync'ed, so that a crash
/// leaves either the old file or the new one, never a part. Creates parent folders. On failure
/// (the temporary file is removed): StorageError naming `path` when the storage is full (ENOSPC,
/// EDQUOT, EFBIG), else InputError naming the path.
void writeFileAtomic(const std::string& path, const std::string& content);

/// Writes all of `data` to the open descriptor `fd` (retrying short writes and EINTR); on
/// failure StorageError naming `path` when the storage is full (ENOSPC, EDQUOT, EFBIG), else
/// std::runtime_error naming `path`.
void writeAll(int fd, const std::string& data, const std::string& path);
/// Best effort: fsync the folder holding `path`, so a new or renamed entry survives a crash.
void syncParentDirectory(const std::string& path);
/// "what: <strerror(errno)>".
std::string systemError(const std::string& what);

}  // namespace dtwin
