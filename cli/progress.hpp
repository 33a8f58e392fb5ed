#pragma once
// A progress bar with an ETA on stderr, drawn only when stderr is a terminal (quiet in CI, in
// pipes and with --quiet). Thread-safe: workers call update() as tasks finish; redraws are
// limited to ten per second.
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace dtwin::cli {

class ProgressBar {
 public:
  ProgressBar(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled) {}
  ~ProgressBar() { finish(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Restarts the clock and the label (a new stage).
  void restart(std::string label) {
    std::lock_guard<std::mutex> lock(m_);
    endLine();
    label_ = std::move(label);
    start_ = Clock::now();
    last_ = {};
    first_done_ = npos;
  }

  void update(std::size_t done, std::size_t total) {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(m_);
    const auto now = Clock::now();
    if (first_done_ == npos) {
      first_done_ = done;  // resumed work does not count towards the rate
      start_ = now;
    }
    if (done < total && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const double frac = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
    const int width = 30, fill = static_cast<int>(frac * width + 0.5);
    std::string bar(static_cast<std::size_t>(fill), '#');
    bar.resize(width, '.');
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const std::size_t fresh = done > first_done_ ? done - first_done_ : 0;
    char eta[32] = "--";
    if (fresh > 0 && done < total) {
      const double rest = elapsed / static_cast<double>(fresh) * static_cast<double>(total - done);
      std::snprintf(eta, sizeof eta, "%dm%02ds", static_cast<int>(rest) / 60, static_cast<int>(rest) % 60);
    } else if (done >= total) {
      std::snprintf(eta, sizeof eta, "done in %.1fs", elapsed);
    }
    std::fprintf(stderr, "\r%-22s [%s] %zu/%zu %3.0f%% ETA %s   ", label_.c_str(), bar.c_str(), done, total, 100 * frac,
                 eta);
    std::fflush(stderr);
    drawn_ = true;
  }

  void finish() {
    std::lock_guard<std::mutex> lock(m_);
    endLine();
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  void endLine() {
    if (drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
  }
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::mutex m_;
  Clock::time_point start_ = Clock::now(), last_{};
  std::size_t first_done_ = npos;
};

}  // namespace dtwin::cli
