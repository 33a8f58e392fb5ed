#pragma once
// A sampled time history: named channels with units, stored column-wise.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "common/files.hpp"

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
  std::string toCsv(const std::vector<std::string>& selected = {}, double t_lo = -1e300,
                    double t_hi = 1e300) const;
  /// The rows and channels toCsv writes, as a trace: the same columns in the same order, the
  /// same rows, the same values (the Python module's simulate returns these).
  Trace select(const std::vector<std::string>& selected = {}, double t_lo = -1e300,
               double t_hi = 1e300) const;

 private:
  /// The column indices of `selected` (all when empty), and whether row `r` lies in [t_lo, t_hi]
  /// (`ti`: the column of time_s, -1 for none: every row).
  std::vector<std::size_t> selectedColumns(const std::vector<std::string>& selected) const;
  bool rowInWindow(int ti, std::size_t r, double t_lo, double t_hi) const;

  std::vector<Channel> channels_;
  std::vector<std::vector<double>> columns_;
};

/// Where a time falls on a uniform output grid (rows at k / rate, k = 0 .. rows - 1), and how to
/// read a column there: the local cubic (Lagrange) polynomial through four consecutive rows.
///
/// A time within 1e-6 rows of a grid row reads that row exactly (weight 1): data on the grid
/// give bit-for-bit the values they gave before off-grid times were allowed. Otherwise the
/// stencil is the rows k-1 .. k+2 around the interval [k, k+1] holding the time, shifted inward at
/// the ends of the trace. Error bound (docs/measurements.md, "Sample times"): with h = 1 / rate,
/// |f(t) - p(t)| <= (3/128) h^4 max|f| on interior intervals and (1/24) h^4 max|f| on the
/// first and last, the maximum taken over the four rows' span. For content at frequency f the
/// interior bound is 3/128 (2 pi f h)^4 of its amplitude: 6e-6 at 20 Hz and 1 kHz output.
struct GridSample {
  std::size_t row = 0;  ///< first row of the stencil
  int count = 1;        ///< rows used: 1 (on the grid) or 4
  std::array<double, 4> weight{1.0, 0.0, 0.0, 0.0};
  /// The value of `column` at the time (the column has the grid's rows).
  double of(const std::vector<double>& column) const {
    double v = 0.0;
    for (int i = 0; i < count; ++i)
      v += weight[static_cast<std::size_t>(i)] * column[row + static_cast<std::size_t>(i)];
    return v;
  }
};
/// The stencil of time `t` (seconds, >= 0) on a grid of `rows` rows at `rate` Hz. Precondition
/// (checked, std::logic_error): t lies within the grid (t <= (rows - 1) / rate + 1e-6 rows), rate >
/// 0, rows >= 1. With fewer than four rows an off-grid time is read linearly.
GridSample gridSample(double t, double rate, std::size_t rows);
/// True when `t` lies on the grid of `rate` Hz (within 1e-6 rows).
bool onGrid(double t, double rate);
/// The row of time `t` on the grid of `rate` Hz over [0, duration]; InputError(where, ...) when
/// `t` is not on the grid or lies outside.
std::size_t gridIndex(double t, double rate, double duration, const std::string& where);

}  // namespace dtwin
