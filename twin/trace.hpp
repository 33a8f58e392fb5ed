#pragma once
// A sampled time history: named channels with units, stored column-wise.
#include <string>
#include <vector>

namespace dtwin {

struct Channel {
  std::string name;  ///< includes the unit suffix, e.g. "hub_force_fl_N"
  std::string unit;  ///< "N"
  std::string description;
};

class Trace {
 public:
  void addChannel(Channel c) {
    channels_.push_back(std::move(c));
    columns_.emplace_back();
  }
  const std::vector<Channel>& channels() const { return channels_; }
  std::size_t rows() const { return columns_.empty() ? 0 : columns_[0].size(); }
  /// Column index of `name`, or -1.
  int index(const std::string& name) const;
  const std::vector<double>& column(const std::string& name) const;
  std::vector<double>& column(std::size_t i) { return columns_[i]; }
  const std::vector<double>& column(std::size_t i) const { return columns_[i]; }
  /// CSV text: header of channel names, then rows; `selected` empty means all channels;
  /// rows with time outside [t_lo, t_hi] are skipped. Numbers use the shortest exact form.
  std::string toCsv(const std::vector<std::string>& selected = {}, double t_lo = -1e300, double t_hi = 1e300) const;

 private:
  std::vector<Channel> channels_;
  std::vector<std::vector<double>> columns_;
};

/// Writes `content` to `path` atomically: a temporary file in the same folder, then rename.
/// Creates parent folders. Throws InputError naming the path on failure.
void writeFileAtomic(const std::string& path, const std::string& content);
/// The bytes of a file. Throws InputError naming the path if it cannot be read.
std::string readFileBytes(const std::string& path);

}  // namespace dtwin
