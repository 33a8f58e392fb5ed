#pragma once
// Progress with an ETA on stderr. On a terminal it is a bar redrawn at most ten times a second.
// Elsewhere (a batch job's log, a pipe) it is a plain line at most every 30 s, so
// a run shorter than that prints nothing and a long one is never silent. --quiet turns both off.
// Thread-safe: workers call update() as tasks finish.
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace dtwin::cli {

class ProgressBar {
 public:
  enum class Mode { Off, Bar, Lines };

  /// `enabled` false: nothing; true: a bar on a terminal, else lines (see the header note).
  /// `line_every` and `out` are for tests.
  ProgressBar(std::string label, bool enabled, bool terminal,
              std::chrono::milliseconds line_every = std::chrono::seconds(30),
              std::FILE* out = stderr)
      : label_(std::move(label)),
        mode_(!enabled   ? Mode::Off
              : terminal ? Mode::Bar
                         : Mode::Lines),
        line_every_(line_every),
        out_(out) {}
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
    last_line_ = start_;
    lines_in_stage_ = 0;
    first_done_ = npos;
  }

  void update(std::size_t done, std::size_t total) {
    if (mode_ == Mode::Off) return;
    std::lock_guard<std::mutex> lock(m_);
    const auto now = Clock::now();
    if (first_done_ == npos) {
      first_done_ = done;  // resumed work does not count towards the rate
      start_ = now;
    }
    if (mode_ == Mode::Lines) {
      // A line when the interval has passed, and a closing line for a stage that printed one.
      const bool due = now - last_line_ >= line_every_;
      const bool closing = done >= total && lines_in_stage_ > 0;
      if (!due && !closing) return;
      if (closing)
        lines_in_stage_ = 0;
      else
        ++lines_in_stage_;
      last_line_ = now;
      std::fprintf(out_, "%s: %zu/%zu %.0f%% %s\n", label_.c_str(), done, total,
                   100 * (total ? static_cast<double>(done) / static_cast<double>(total) : 1.0),
                   eta(now, done, total).c_str());
      std::fflush(out_);
      return;
    }
    if (done < total && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const double frac = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
    // NOLINTNEXTLINE(bugprone-incorrect-roundings): frac >= 0, rounded half up, as the bar was
    const int width = 30, fill = static_cast<int>(frac * width + 0.5);
    std::string bar(static_cast<std::size_t>(fill), '#');
    bar.resize(width, '.');
    std::fprintf(out_, "\r%-22s [%s] %zu/%zu %3.0f%% ETA %s   ", label_.c_str(), bar.c_str(), done,
                 total, 100 * frac, eta(now, done, total).c_str());
    std::fflush(out_);
    drawn_ = true;
  }

  void finish() {
    std::lock_guard<std::mutex> lock(m_);
    endLine();
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  std::string eta(Clock::time_point now, std::size_t done, std::size_t total) const {
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const std::size_t fresh = done > first_done_ ? done - first_done_ : 0;
    char text[48] = "ETA --";
    if (fresh > 0 && done < total) {
      const double rest = elapsed / static_cast<double>(fresh) * static_cast<double>(total - done);
      std::snprintf(text, sizeof text, "ETA %dm%02ds", static_cast<int>(rest) / 60,
                    static_cast<int>(rest) % 60);
    } else if (done >= total) {
      std::snprintf(text, sizeof text, "done in %.1fs", elapsed);
    }
    return text;
  }

  void endLine() {
    if (drawn_) std::fprintf(out_, "\n");
    drawn_ = false;
  }
  std::string label_;
  Mode mode_;
  std::chrono::milliseconds line_every_;
  std::FILE* out_;
  int lines_in_stage_ = 0;
  Clock::time_point last_line_ = Clock::now();
  bool drawn_ = false;
  std::mutex m_;
  Clock::time_point start_ = Clock::now(), last_{};
  std::size_t first_done_ = npos;
};

}  // namespace dtwin::cli
