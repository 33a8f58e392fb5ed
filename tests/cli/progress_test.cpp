// The CLI's progress display: a bar on a terminal, plain lines elsewhere (a batch job's log).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "cli/progress.hpp"

namespace {

using dtwin::cli::ProgressBar;
using namespace std::chrono_literals;

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  for (int c; (c = std::fgetc(f)) != EOF;) s += static_cast<char>(c);
  return s;
}

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(Progress, OffPrintsNothing) {
  std::FILE* f = std::tmpfile();
  {
    ProgressBar bar("calibrate", false, false, 0ms, f);
    for (std::size_t i = 0; i <= 10; ++i) bar.update(i, 10);
  }
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

TEST(Progress, AShortRunOffATerminalPrintsNothing) {
  std::FILE* f = std::tmpfile();
  {
    ProgressBar bar("calibrate", true, false, 1h, f);
    for (std::size_t i = 0; i <= 10; ++i) bar.update(i, 10);
  }
  EXPECT_EQ(contents(f), "")
      << "no line before the interval, and no closing line for a stage that printed none";
  std::fclose(f);
}

TEST(Progress, ALongRunOffATerminalPrintsPlainLinesAndAClosingLine) {
  std::FILE* f = std::tmpfile();
  {
    ProgressBar bar("design", true, false, 1ms, f);
    bar.update(0, 4);
    std::this_thread::sleep_for(5ms);
    bar.update(1, 4);
    std::this_thread::sleep_for(5ms);
    bar.update(2, 4);
    bar.update(4, 4);
    bar.restart("gibbs");
    bar.update(10, 10);  // a stage that printed nothing gets no closing line
  }
  const std::string s = contents(f);
  EXPECT_EQ(s.find('\r'), std::string::npos) << "no carriage returns in a log: " << s;
  EXPECT_NE(s.find("design: 1/4 25% ETA"), std::string::npos) << s;
  EXPECT_NE(s.find("design: 2/4 50% ETA"), std::string::npos) << s;
  EXPECT_NE(s.find("design: 4/4 100% done in"), std::string::npos) << s;
  EXPECT_EQ(s.find("gibbs"), std::string::npos) << s;
  EXPECT_EQ(lines(s), 3) << s;
  std::fclose(f);
}

TEST(Progress, OnATerminalItRedrawsOneLine) {
  std::FILE* f = std::tmpfile();
  {
    ProgressBar bar("lab", true, true, 0ms, f);
    bar.update(0, 2);
    bar.update(2, 2);
  }
  const std::string s = contents(f);
  EXPECT_NE(s.find('\r'), std::string::npos) << s;
  EXPECT_NE(s.find("2/2 100% ETA done in"), std::string::npos) << s;
  EXPECT_EQ(lines(s), 1) << "one line, ended when the bar finishes: " << s;
  std::fclose(f);
}

}  // namespace
