#include "twin/trace.hpp"

#include <unistd.h>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"

namespace dtwin {

std::size_t gridIndex(double t, double rate, double duration, const std::string& where) {
  const double k = t * rate;
  if (!std::isfinite(t) || std::abs(k - std::round(k)) > 1e-6)
    throw InputError(where, formatExact(t) + " s is not on the output grid (multiples of " +
                                formatExact(1.0 / rate) + " s)");
  if (t < 0 || t > duration + 1e-9)
    throw InputError(where, formatExact(t) + " s lies outside the scenario (0 .. " +
                                formatExact(duration) + " s)");
  return static_cast<std::size_t>(std::llround(k));
}

bool onGrid(double t, double rate) {
  const double x = t * rate;
  return std::abs(x - std::round(x)) <= 1e-6;
}

GridSample gridSample(double t, double rate, std::size_t rows) {
  DTWIN_CHECK(rate > 0 && rows >= 1 && t >= -1e-6 / rate, "gridSample: bad grid or negative time");
  const double x = t * rate;
  const double last = static_cast<double>(rows - 1);
  DTWIN_CHECK(x <= last + 1e-6, "gridSample: time after the end of the grid");
  GridSample g;
  if (onGrid(t, rate)) {
    g.row = static_cast<std::size_t>(std::min(std::max(std::round(x), 0.0), last));
    return g;
  }
  if (rows < 4) {  // too short for a cubic: linear between the two rows around t
    const double k = std::floor(x);
    g.row = static_cast<std::size_t>(k);
    g.count = 2;
    g.weight = {1.0 - (x - k), x - k, 0.0, 0.0};
    return g;
  }
  const double start = std::clamp(std::floor(x) - 1.0, 0.0, static_cast<double>(rows - 4));
  g.row = static_cast<std::size_t>(start);
  g.count = 4;
  const double s = x - start;  // the time in rows from the stencil's first row, in (0, 3)
  for (int i = 0; i < 4; ++i) {
    double w = 1.0;
    for (int j = 0; j < 4; ++j)
      if (j != i) w *= (s - j) / static_cast<double>(i - j);
    g.weight[static_cast<std::size_t>(i)] = w;
  }
  return g;
}

int Trace::index(const std::string& name) const {
  for (std::size_t i = 0; i < channels_.size(); ++i)
    if (channels_[i].name == name) return static_cast<int>(i);
  return -1;
}

const std::vector<double>& Trace::column(const std::string& name) const {
  const int i = index(name);
  DTWIN_CHECK(i >= 0, "no channel " + name);
  return columns_[static_cast<std::size_t>(i)];
}

std::vector<std::size_t> Trace::selectedColumns(const std::vector<std::string>& selected) const {
  std::vector<std::size_t> cols;
  if (selected.empty())
    for (std::size_t i = 0; i < channels_.size(); ++i) cols.push_back(i);
  else
    for (auto& s : selected) {
      const int i = index(s);
      DTWIN_CHECK(i >= 0, "no channel " + s);
      cols.push_back(static_cast<std::size_t>(i));
    }
  return cols;
}

bool Trace::rowInWindow(int ti, std::size_t r, double t_lo, double t_hi) const {
  if (ti < 0) return true;
  const double t = columns_[static_cast<std::size_t>(ti)][r];
  return !(t < t_lo - 1e-12 || t > t_hi + 1e-12);
}

std::string Trace::toCsv(const std::vector<std::string>& selected, double t_lo, double t_hi) const {
  const std::vector<std::size_t> cols = selectedColumns(selected);
  std::string out;
  out.reserve(rows() * cols.size() * 14 + 256);
  for (std::size_t k = 0; k < cols.size(); ++k) out += (k ? "," : "") + channels_[cols[k]].name;
  out += '\n';
  const int ti = index("time_s");
  char buf[64];
  for (std::size_t r = 0; r < rows(); ++r) {
    if (!rowInWindow(ti, r, t_lo, t_hi)) continue;
    for (std::size_t k = 0; k < cols.size(); ++k) {
      if (k) out += ',';
      auto res = std::to_chars(buf, buf + sizeof buf, columns_[cols[k]][r]);
      out.append(buf, res.ptr);
    }
    out += '\n';
  }
  return out;
}

Trace Trace::select(const std::vector<std::string>& selected, double t_lo, double t_hi) const {
  const std::vector<std::size_t> cols = selectedColumns(selected);
  Trace out;
  for (const std::size_t c : cols) out.addChannel(channels_[c]);
  const int ti = index("time_s");
  for (std::size_t r = 0; r < rows(); ++r) {
    if (!rowInWindow(ti, r, t_lo, t_hi)) continue;
    for (std::size_t k = 0; k < cols.size(); ++k) out.columns_[k].push_back(columns_[cols[k]][r]);
  }
  return out;
}

}  // namespace dtwin
