// `twin report` end to end: a tiny study folder made by `twin study`, its HTML report (one inline
// SVG per expected plot, valid skeleton, escaped text, no gnuplot error text), a clear error when
// gnuplot is missing, and a headless Chromium rendering without page errors.
#include <gtest/gtest.h>

#include "chromium_util.hpp"
#include "test_util.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace {
/// Evaluated at use, after main() has given this process its own TMPDIR (tests/test_main.cpp).
fs::path kTmp() { return fs::temp_directory_path() / "dtwin_report_test"; }

using dtwin_test::findOnPath;
using dtwin_test::slurp;

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = 0; (pos = s.find(what, pos)) != std::string::npos; pos += what.size()) ++n;
  return n;
}
}  // namespace

TEST(Report, TinyStudyReportRendersInChromium) {
  fs::remove_all(kTmp());
  fs::create_directories(kTmp());
  const fs::path study = dtwin_test::writeTinyStudy(kTmp() / "tiny.toml");
  const fs::path dir = kTmp() / "study";
  const std::string twin = DTWIN_TWIN_EXE;
  ASSERT_EQ(std::system(
                (twin + " study --study " + study.string() + " --out " + dir.string() + " --quiet")
                    .c_str()),
            0);

  // Without gnuplot: one clear line naming the package, exit code 2, nothing written.
  const fs::path err = kTmp() / "nognuplot.err";
  const int rc = std::system(("env PATH=/nonexistent " + twin + " report --study-dir " +
                              dir.string() + " 2>" + err.string())
                                 .c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  EXPECT_NE(slurp(err).find("gnuplot-nox"), std::string::npos) << slurp(err);
  EXPECT_FALSE(fs::exists(dir / "report.html"));

  if (findOnPath("gnuplot").empty())
    GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox): cannot draw the report";
  ASSERT_EQ(std::system((twin + " report --study-dir " + dir.string() + " --quiet").c_str()), 0);
  const fs::path html = dir / "report.html";
  ASSERT_TRUE(fs::exists(html));
  const std::string page = slurp(html);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("<html lang=\"en\">"), std::string::npos);
  EXPECT_NE(page.find("<meta charset=\"utf-8\">"), std::string::npos);
  EXPECT_NE(page.find("<title>"), std::string::npos);
  // 2 assemblies x 1 lab channel predictive plots, 2 posterior density figures, 2 pair plots,
  // boxplot, wins, evidence/cost.
  EXPECT_EQ(count(page, "<svg"), 9u);
  EXPECT_EQ(count(page, "</svg>"), 9u);
  // The continuous response: the band is drawn on the dense grid, not at the lab times alone.
  std::smatch grid;
  ASSERT_TRUE(std::regex_search(page, grid, std::regex("the band drawn on ([0-9]+) times")));
  EXPECT_GE(std::stoi(grid[1]), 400)
      << "400 through the scenario, 400 through the lab's span, the lab times";
  // Human ticks: no tick label in scientific form with a positive exponent (1.5397e+05).
  EXPECT_FALSE(std::regex_search(page, std::regex(">\\s*-?[0-9.]+e\\+[0-9]+\\s*<")))
      << "a tick like 1.5e+05";
  EXPECT_NE(page.find("[N/m]"), std::string::npos) << "units in the axis labels";
  // No absolute path: the title is the study's name, paths are relative to the page.
  const auto t0 = page.find("<title>"), t1 = page.find("</title>");
  EXPECT_EQ(page.substr(t0, t1 - t0).find(kTmp().string()), std::string::npos)
      << "an absolute path in the title";
  EXPECT_NE(page.find("<tr><th>study folder</th><td>.</td></tr>"), std::string::npos)
      << "the folder relative to the page";
  EXPECT_NE(page.find("pairs of calibrated values"), std::string::npos);
  EXPECT_NE(page.find("href=\"report_lab.html\""), std::string::npos);
  ASSERT_TRUE(fs::exists(dir / "report_lab.html"));
  EXPECT_EQ(page.find("<?xml"), std::string::npos);
  EXPECT_EQ(page.find("<!DOCTYPE svg"), std::string::npos);
  for (const char* bad : {"gnuplot>", "line 0:", "warning:", "Warnings:", "<script",
                          "http://www.w3.org/1999/xhtml", "src="})
    EXPECT_EQ(page.find(bad), std::string::npos) << bad;
  for (const char* must :
       {"M3", "M4", "recommended", "1/√τ", "Provenance", "tiny.toml", "20240601"})
    EXPECT_NE(page.find(must), std::string::npos) << must;
  // Every posterior histogram says, per calibrated parameter, whether its 95 % interval holds the
  // study's truth (2 assemblies x 4 parameters).
  EXPECT_EQ(count(page, "the 95 % interval ["), 8u);
  EXPECT_EQ(count(page, "the truth 180000 lies"), 2u);
  // Ids unique on the page (every inline SVG has its own).
  std::map<std::string, int> ids;
  const std::regex id_re("\\bid=(['\"])([^'\"]+)\\1");
  for (auto it = std::sregex_iterator(page.begin(), page.end(), id_re);
       it != std::sregex_iterator(); ++it)
    ++ids[(*it)[2]];
  for (const auto& [id, n] : ids) EXPECT_EQ(n, 1) << "duplicate id " << id;

  // --out elsewhere: a folder.
  ASSERT_EQ(std::system((twin + " report --study-dir " + dir.string() +
                         " --quiet --draws 5 --out " + (kTmp() / "r").string())
                            .c_str()),
            0);
  EXPECT_EQ(count(slurp(kTmp() / "r" / "report.html"), "<svg"), 9u);
  EXPECT_TRUE(fs::exists(kTmp() / "r" / "report_lab.html"));

  const std::string chromium = dtwin_test::findChromium();
  if (chromium.empty())
    GTEST_SKIP()
        << "chromium is not installed (Debian package chromium): the rendering check is skipped";
  const fs::path png = kTmp() / "report.png", log = kTmp() / "chromium.log";
  const std::string cmd = chromium +
                          " --headless --no-sandbox --disable-gpu --disable-background-networking "
                          "--enable-logging=stderr --v=0"
                          " --user-data-dir=" +
                          (kTmp() / "chromium-profile").string() + " --screenshot=" + png.string() +
                          " --window-size=1200,3000 file://" + fs::absolute(html).string() + " >" +
                          log.string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(log);
  ASSERT_TRUE(fs::exists(png)) << slurp(log);
  EXPECT_GT(fs::file_size(png), 10u * 1024u);
  std::istringstream lines(slurp(log));
  for (std::string line; std::getline(lines, line);) {
    const bool page_line = line.find("report.html") != std::string::npos;
    EXPECT_EQ(line.find("Uncaught"), std::string::npos) << line;
    EXPECT_FALSE(line.find("CONSOLE") != std::string::npos && page_line) << line;
    EXPECT_FALSE(line.find("ERROR") != std::string::npos && page_line) << line;
  }
  // The interactive lab view: a value and a residual chart per lab channel, no script error, and
  // a zoom through uPlot's API moves both.
  const auto st = dtwin_test::pageSelftest(chromium, dir / "report_lab.html", kTmp() / "lab_page");
  EXPECT_EQ(st.value("charts", 0), 2) << st.dump();
  EXPECT_TRUE(st.value("zoom_ok", false)) << st.dump();
  EXPECT_TRUE(st.value("errors", nlohmann::json::array()).empty()) << st.dump();
  fs::remove_all(kTmp());
}
