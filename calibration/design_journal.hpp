#pragma once
// Persistence of design-point evaluations, so that an interrupted calibration can resume.
//
// \par Journal file format (text, append-only)
//     # dtwin design journal v2; dim=<d>; fingerprint=<caller's string>; check=<c>
//     <index>,<theta_1>,...,<theta_d>,<sse>,<c>
//     ...
// One line per finished design point, in completion order (any order under parallel runs). <c> is
// the 32-bit FNV-1a of the line's text before it (8 hex digits, common/checksum.hpp lineChecksum):
// a line changed on disk after it was written (a digit overwritten) fails it. Journals of version
// 1 (the same without the checksums) are read as before and appended to in their own version.
// Numbers are written with std::to_chars (the shortest text that reads back to the identical
// double, locale-independent); a non-finite SSE (failed simulation) is written as "inf".
// Each line goes to the file with a single write(2) and is then fsync'ed (unless disabled), so a
// killed process loses at most the line being written. A line counts only when its '\n' is on
// disk: on reading, a last line without one is discarded as truncated (and, when the journal is
// reopened for appending, cut off so the next line starts cleanly). A malformed line that IS
// terminated is corruption: in a v1 journal an error; in a v2 journal any complete line that
// fails its checksum (a malformed one included) makes the journal damaged: DesignJournal sets it
// aside (<path>.corrupt, one note on stderr) and starts a new one, so the points are computed
// again instead of trusted.
// The fingerprint identifies what the points belong to (e.g. a hash of study, assembly, box
// and design seed). Reopening a journal with a different d or fingerprint is refused with an
// InputError, so points of one design can never be resumed into another.
//
// \par Design table
// writeDesignTableCsv writes the complete table "name_1,...,name_d,sse" (one row per design
// point, in design order) to a temporary file in the same directory, fsyncs it and renames it
// over `path`: readers see either the old file or the complete new one, never a partial one.
#include <Eigen/Core>
#include <cstdint>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace dtwin::calib {

struct JournalEntry {
  std::int64_t index = 0;     ///< design-point index, >= 0
  std::vector<double> theta;  ///< d values (physical units)
  double sse = 0.0;           ///< +inf for a failed simulation
};

struct JournalContents {
  int version = 2;  ///< 1: lines without checksums
  int dim = 0;
  std::string fingerprint;
  std::vector<JournalEntry> entries;      ///< complete lines, in file order
  bool discarded_truncated_line = false;  ///< a last line without '\n' was dropped
  int corrupt_line =
      0;  ///< > 0: the first line (1 = the header) that fails its checksum; reading stopped there
};

/// Reads a journal. Throws InputError (naming the file and line) when the file cannot be read,
/// the header is missing or malformed, or a complete line is malformed or fails its checksum.
JournalContents readDesignJournal(const std::string& path);

/// An open journal: loads what is there, then appends. append() is thread-safe.
class DesignJournal {
 public:
  /// Creates `path` with a header if it does not exist (or holds not even a complete header
  /// line); otherwise checks that its d and fingerprint equal `dim` and `fingerprint` (InputError
  /// if not, saying which differs), loads its entries (see resumed()) and removes a truncated
  /// last line. A v2 journal with a line that fails its checksum is set aside (renamed to
  /// <path>.corrupt, with a note on stderr; setAside() true) and a new one is started.
  /// `fingerprint` must not contain line breaks. `durable` = fsync after each line.
  DesignJournal(const std::string& path, int dim, const std::string& fingerprint,
                bool durable = true);
  ~DesignJournal();
  DesignJournal(const DesignJournal&) = delete;
  DesignJournal& operator=(const DesignJournal&) = delete;

  /// Entries that were already in the file when it was opened, in file order.
  const std::vector<JournalEntry>& resumed() const { return resumed_; }
  bool discardedTruncatedLine() const { return discarded_; }
  /// The journal in the file failed its checksum and was set aside (resumed() is then empty).
  bool setAside() const { return set_aside_; }
  const std::string& path() const { return path_; }
  int dim() const { return dim_; }

  /// Appends one finished point (theta.size() == dim, finite; index >= 0). Throws InputError for
  /// a wrong size or a non-finite theta, std::runtime_error when the write fails.
  void append(std::int64_t index, const std::vector<double>& theta, double sse);

 private:
  std::string path_;
  int dim_ = 0;
  bool durable_ = true;
  int fd_ = -1;
  std::mutex mutex_;
  std::vector<JournalEntry> resumed_;
  bool discarded_ = false;
  bool set_aside_ = false;
  int version_ = 2;  ///< of the lines appended: the file's own
};

/// A further column of the design table: its name and one value per design point.
using DesignColumn = std::pair<std::string, std::vector<double>>;

/// Writes "names...,sse_name[,extra...]" and one row per design point atomically (temp file +
/// rename). design is N x d, names has d entries (no commas, quotes or line breaks), sse and every
/// extra column have N entries.
void writeDesignTableCsv(const std::string& path, const std::vector<std::string>& names,
                         const Eigen::MatrixXd& design, const std::vector<double>& sse,
                         const std::string& sse_name = "sse",
                         const std::vector<DesignColumn>& extra = {});

}  // namespace dtwin::calib
