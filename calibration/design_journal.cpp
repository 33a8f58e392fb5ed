#include "calibration/design_journal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/checksum.hpp"
#include "common/errors.hpp"
#include "common/files.hpp"
#include "common/format.hpp"

namespace dtwin::calib {
namespace {

const std::string kHeaderStart = "# dtwin design journal v";
const std::string kDimKey = "; dim=";
const std::string kFingerprintKey = "; fingerprint=";
const std::string kCheckKey = "; check=";
constexpr int kVersion =
    2;  // v2: a checksum ends every line; v1 (none) is still read and appended to

void appendDouble(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "inf";
    return;
  }
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
  DTWIN_CHECK(res.ec == std::errc(), "to_chars failed");
  out.append(buf, res.ptr);
}

std::string headerLine(int version, int dim, const std::string& fingerprint) {
  const std::string text = kHeaderStart + std::to_string(version) + kDimKey + std::to_string(dim) +
                           kFingerprintKey + fingerprint;
  return version == 1 ? text + "\n" : text + kCheckKey + lineChecksum(text) + "\n";
}

/// `body` (a complete line without its '\n') without the checksum a v2 line ends with (`key`
/// and 8 hex digits); false when there is none or it does not match.
bool stripChecksum(std::string& body, const std::string& key) {
  const std::size_t at = body.rfind(key);
  if (at == std::string::npos || body.size() != at + key.size() + 8) return false;
  const std::string sum = body.substr(at + key.size());
  body.resize(at);
  return sum == lineChecksum(body);
}

bool readWholeFile(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

/// Parses journal text. `complete_length` receives the length up to and including the last
/// '\n'. Returns false (and leaves `out` empty) if there is not even a complete header line.
bool parseJournal(const std::string& text, const std::string& path, JournalContents& out,
                  std::size_t& complete_length) {
  const std::size_t last_nl = text.rfind('\n');
  if (last_nl == std::string::npos) {
    complete_length = 0;
    return false;
  }
  complete_length = last_nl + 1;
  out = JournalContents{};
  out.discarded_truncated_line = complete_length < text.size();

  std::size_t pos = 0;
  int line_no = 0;
  while (pos < complete_length) {
    const std::size_t nl = text.find('\n', pos);
    std::string line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = path + ": line " + std::to_string(line_no);
    if (line_no == 1) {
      const std::string rule = "not a dtwin design journal: the header must read '" + kHeaderStart +
                               "<version>" + kDimKey + "<d>" + kFingerprintKey + "<fingerprint>'";
      std::size_t at = kHeaderStart.size();
      if (line.compare(0, at, kHeaderStart) != 0) throw InputError(where, rule);
      const std::size_t dim_at = line.find(kDimKey, at);
      if (dim_at == std::string::npos) throw InputError(where, rule);
      const std::string version = line.substr(at, dim_at - at);
      if (version != "1" && version != "2")
        throw InputError(where,
                         "journal version " + version + " is not one this program reads (1 or 2)");
      out.version = version == "1" ? 1 : 2;
      if (out.version == 2 && !stripChecksum(line, kCheckKey)) {
        out.corrupt_line = line_no;
        return true;
      }
      const std::size_t fp = line.find(kFingerprintKey, dim_at);
      if (fp == std::string::npos) throw InputError(where, rule);
      const std::string dim_text =
          line.substr(dim_at + kDimKey.size(), fp - dim_at - kDimKey.size());
      int dim = 0;
      const auto res = std::from_chars(dim_text.data(), dim_text.data() + dim_text.size(), dim);
      if (res.ec != std::errc() || res.ptr != dim_text.data() + dim_text.size() || dim < 1)
        throw InputError(where, "dim must be an integer >= 1, got '" + dim_text + "'");
      out.dim = dim;
      out.fingerprint = line.substr(fp + kFingerprintKey.size());
      continue;
    }
    if (line.empty() && out.version == 1) continue;
    if (out.version == 2 && !stripChecksum(line, ",")) {  // changed on disk after it was written
      out.corrupt_line = line_no;
      return true;
    }
    std::vector<std::string> fields;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = line.find(',', start);
      fields.push_back(line.substr(start, comma == std::string::npos ? comma : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    const std::size_t expected = static_cast<std::size_t>(out.dim) + 2;
    if (fields.size() != expected)
      throw InputError(where, "expected " + std::to_string(expected) +
                                  " comma-separated fields (index, " + std::to_string(out.dim) +
                                  " parameters, sse), got " + std::to_string(fields.size()));
    JournalEntry e;
    const std::string& idx = fields.front();
    const auto res = std::from_chars(idx.data(), idx.data() + idx.size(), e.index);
    if (res.ec != std::errc() || res.ptr != idx.data() + idx.size() || e.index < 0)
      throw InputError(where, "index must be an integer >= 0, got '" + idx + "'");
    e.theta.resize(static_cast<std::size_t>(out.dim));
    for (int j = 0; j < out.dim; ++j) {
      const std::string& f = fields[static_cast<std::size_t>(j) + 1];
      if (!parseNumber(f, e.theta[static_cast<std::size_t>(j)]) ||
          !std::isfinite(e.theta[static_cast<std::size_t>(j)]))
        throw InputError(where, "parameter " + std::to_string(j + 1) +
                                    " must be a finite number, got '" + f + "'");
    }
    if (!parseNumber(fields.back(), e.sse))
      throw InputError(where, "sse must be a number or 'inf', got '" + fields.back() + "'");
    if (std::isnan(e.sse)) e.sse = std::numeric_limits<double>::infinity();
    out.entries.push_back(std::move(e));
  }
  return true;
}

}  // namespace

JournalContents readDesignJournal(const std::string& path) {
  std::string text;
  if (!readWholeFile(path, text)) throw InputError(path, "cannot read design journal");
  JournalContents c;
  std::size_t complete = 0;
  if (!parseJournal(text, path, c, complete))
    throw InputError(path, "design journal has no complete header line");
  if (c.corrupt_line > 0)
    throw InputError(path + ": line " + std::to_string(c.corrupt_line),
                     "fails its checksum (changed after it was written)");
  return c;
}

DesignJournal::DesignJournal(const std::string& path, int dim, const std::string& fingerprint,
                             bool durable)
    : path_(path), dim_(dim), durable_(durable) {
  if (dim < 1) throw InputError(path, "journal dimension must be >= 1, got " + std::to_string(dim));
  if (fingerprint.find_first_of("\r\n") != std::string::npos)
    throw InputError(path, "journal fingerprint must not contain line breaks");

  std::string text;
  JournalContents c;
  std::size_t complete = 0;
  std::error_code ec;
  const bool exists = std::filesystem::exists(path, ec);
  if (exists && !readWholeFile(path, text))  // never truncate a journal we could not read
    throw InputError(path, "design journal exists but cannot be read");
  bool found = exists && parseJournal(text, path, c, complete);
  if (found &&
      c.corrupt_line > 0) {  // damaged on disk: set aside, and the points are computed again
    setAsideCorrupt(path, "line " + std::to_string(c.corrupt_line) + " fails its checksum");
    set_aside_ = true;
    found = false;
    text.clear();
  }
  if (found) {
    if (c.dim != dim || c.fingerprint != fingerprint) {
      std::ostringstream os;
      os << "design journal belongs to a different design (";
      if (c.dim != dim) os << "dim " << c.dim << " in the file, " << dim << " expected";
      if (c.dim != dim && c.fingerprint != fingerprint) os << "; ";
      if (c.fingerprint != fingerprint)
        os << "fingerprint '" << c.fingerprint << "' in the file, '" << fingerprint << "' expected";
      os << "); refusing to resume: remove the file or use the study it was made for";
      throw InputError(path, os.str());
    }
    if (c.discarded_truncated_line && ::truncate(path.c_str(), static_cast<off_t>(complete)) != 0)
      throw std::runtime_error(systemError(path + ": cannot cut off the truncated last line"));
    resumed_ = std::move(c.entries);
    discarded_ = c.discarded_truncated_line;
    version_ = c.version;
    fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) throw InputError(path, systemError("cannot open design journal for appending"));
  } else {
    // New journal (or one killed before its header line was complete), in the current version.
    discarded_ = exists && !text.empty();
    version_ = kVersion;
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
    if (fd_ < 0) throw InputError(path, systemError("cannot create design journal"));
    try {
      writeAll(fd_, headerLine(version_, dim, fingerprint), path);
      if (durable_ && ::fsync(fd_) != 0) {
        if (StorageError::isStorageFull(errno))
          throw StorageError(path, errno);  // delayed allocation
        throw std::runtime_error(systemError(path + ": fsync"));
      }
    } catch (...) {
      ::close(fd_);
      throw;
    }
    if (durable_) syncParentDirectory(path);
  }
}

DesignJournal::~DesignJournal() {
  if (fd_ >= 0) ::close(fd_);
}

void DesignJournal::append(std::int64_t index, const std::vector<double>& theta, double sse) {
  if (index < 0)
    throw InputError(path_, "design-point index must be >= 0, got " + std::to_string(index));
  if (theta.size() != static_cast<std::size_t>(dim_))
    throw InputError(path_, "point " + std::to_string(index) + " has " +
                                std::to_string(theta.size()) + " parameters, the journal " +
                                std::to_string(dim_));
  std::string line = std::to_string(index);
  for (std::size_t j = 0; j < theta.size(); ++j) {
    if (!std::isfinite(theta[j]))
      throw InputError(path_, "point " + std::to_string(index) + ": parameter " +
                                  std::to_string(j + 1) + " is not finite");
    line += ',';
    appendDouble(line, theta[j]);
  }
  line += ',';
  appendDouble(line, sse);
  if (version_ >= 2) line += "," + lineChecksum(line);
  line += '\n';
  std::lock_guard<std::mutex> lock(mutex_);
  writeAll(fd_, line, path_);
  if (durable_ && ::fsync(fd_) != 0) {
    if (StorageError::isStorageFull(errno)) throw StorageError(path_, errno);  // delayed allocation
    throw std::runtime_error(systemError(path_ + ": fsync"));
  }
}

void writeDesignTableCsv(const std::string& path, const std::vector<std::string>& names,
                         const Eigen::MatrixXd& design, const std::vector<double>& sse,
                         const std::string& sse_name, const std::vector<DesignColumn>& extra) {
  if (names.size() != static_cast<std::size_t>(design.cols()))
    throw InputError(path, std::to_string(names.size()) + " column names for " +
                               std::to_string(design.cols()) + " design columns");
  if (sse.size() != static_cast<std::size_t>(design.rows()))
    throw InputError(path, std::to_string(sse.size()) + " SSE values for " +
                               std::to_string(design.rows()) + " design points");
  std::vector<std::string> header = names;
  header.push_back(sse_name);
  for (const auto& [name, values] : extra) {
    if (values.size() != sse.size())
      throw InputError(path, "column '" + name + "' has " + std::to_string(values.size()) +
                                 " values for " + std::to_string(design.rows()) + " design points");
    header.push_back(name);
  }
  for (const auto& n : header)
    if (n.empty() || n.find_first_of(",\"\r\n") != std::string::npos)
      throw InputError(
          path, "column name '" + n + "' must be non-empty without commas, quotes or line breaks");

  std::string text;
  for (std::size_t j = 0; j < header.size(); ++j) text += (j ? "," : "") + header[j];
  text += '\n';
  for (Eigen::Index i = 0; i < design.rows(); ++i) {
    for (Eigen::Index j = 0; j < design.cols(); ++j) {
      if (!std::isfinite(design(i, j)))
        throw InputError(path, "design point " + std::to_string(i) + ", column '" +
                                   names[static_cast<std::size_t>(j)] + "' is not finite");
      appendDouble(text, design(i, j));
      text += ',';
    }
    appendDouble(text, sse[static_cast<std::size_t>(i)]);
    for (const auto& col : extra) {
      text += ',';
      appendDouble(text, col.second[static_cast<std::size_t>(i)]);
    }
    text += '\n';
  }

  writeFileAtomic(path, text);
}

}  // namespace dtwin::calib
