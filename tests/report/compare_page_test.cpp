// The interactive comparison page (report/compare_page.hpp): what it embeds, and, loaded in
// headless Chromium, that it draws a value and a residual chart per channel, lists every window
// the comparison listed, largest share first under the channel's count of windows in words,
// raises no script error, and that a zoom through uPlot's API moves every chart of the data set. A
// 117 000-row drive's page is loaded too and the time its charts are built printed (a figure, not
// an assertion: timing targets live in benchmarks).
#include <gtest/gtest.h>

#include "chromium_util.hpp"
#include "test_util.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "diagnosis/frequency_response.hpp"
#include "report/compare_page.hpp"

namespace fs = std::filesystem;
using namespace dtwin;

namespace {

fs::path kTmp() { return fs::temp_directory_path() / "dtwin_compare_page_test"; }

/// A comparison's JSON as `twin compare` writes it: two channels of one drive, `rows` samples at
/// 100 Hz, windows on the first.
nlohmann::json comparison(int rows, int windows) {
  nlohmann::json j{{"series", nlohmann::json::array()}};
  for (const std::string ch : {"seat_mps2", "pot_fl_m"}) {
    nlohmann::json s{{"data_set", "/abs/path/drive.csv"},
                     {"scenario", "drive"},
                     {"channel", ch},
                     {"unit", ch == "pot_fl_m" ? "m" : "mps2"},
                     {"fit_percent", 90.0},
                     {"rms", 0.03},
                     {"coverage95", 0.95},
                     {"noise_variance", 9e-4}};
    std::vector<double> t, y, p, lo, hi;
    for (int i = 0; i < rows; ++i) {
      t.push_back(0.01 * i);
      p.push_back(std::sin(0.05 * i));
      y.push_back(p.back() + 0.03 * std::sin(1.7 * i));
      lo.push_back(p.back() - 0.06);
      hi.push_back(p.back() + 0.06);
    }
    s["t"] = t;
    s["measured_mean"] = y;
    s["predicted_mean"] = p;
    s["band_lo"] = lo;
    s["band_hi"] = hi;
    s["windows"] = nlohmann::json::array();
    if (ch == "seat_mps2")
      for (int w = 0; w < windows; ++w)
        s["windows"].push_back({{"t_begin_s", 1.0 + w},
                                {"t_end_s", 1.1 + w},
                                {"peak_z", 4.5},
                                {"share_of_chi2", 0.02},
                                {"label", "braking </script>"}});
    s["bands"] = {{{"band", 1},
                   {"lo_hz", 0.5},
                   {"hi_hz", 1.0},
                   {"residual_power", 2.0},
                   {"noise_power", 1.0},
                   {"ratio", 2.0},
                   {"significant", true}}};
    j["series"].push_back(s);
  }
  return j;
}

/// The page loaded in headless Chromium with #selftest.
nlohmann::json selftest(const std::string& chromium, const fs::path& html) {
  return dtwin_test::pageSelftest(chromium, html, kTmp());
}

}  // namespace

TEST(ComparePage, EmbedsTheLibraryAndTheDataSafely) {
  const std::string html =
      comparePage(comparison(500, 3), "twin compare: demo, M1 against drive.csv");
  EXPECT_NE(html.find("uPlot"), std::string::npos);
  EXPECT_EQ(html.find("/abs/path"), std::string::npos) << "no absolute path on the page";
  // A label holding "</script>" cannot close the data element.
  const auto a = html.find("id=data>"), b = html.find("</script>", a);
  ASSERT_NE(a, std::string::npos);
  const auto data = nlohmann::json::parse(html.substr(a + 8, b - a - 8));
  ASSERT_EQ(data.at("sets").size(), 1u);
  EXPECT_EQ(data["sets"][0]["name"], "drive.csv");
  EXPECT_EQ(data["sets"][0]["channels"].size(), 2u);
  EXPECT_EQ(data["sets"][0]["channels"][0]["windows"][2]["label"], "braking </script>");
  EXPECT_EQ(data["sets"][0]["channels"][0]["t"].size(), 500u);
  EXPECT_EQ(data["sets"][0]["channels"][0]["models"].size(), 1u);
  EXPECT_THROW(comparePage(nlohmann::json{{"series", nlohmann::json::array()}}, "x"), InputError);
}

TEST(ComparePage, DrawsEveryChannelListsEveryWindowAndZoomsInChromium) {
  const std::string chromium = dtwin_test::findChromium();
  if (chromium.empty())
    GTEST_SKIP()
        << "chromium is not installed (Debian package chromium): the page check is skipped";
  fs::remove_all(kTmp());
  fs::create_directories(kTmp());
  const fs::path small = kTmp() / "compare.html";
  std::ofstream(small) << comparePage(comparison(2000, 4), "small");
  const auto s = selftest(chromium, small);
  EXPECT_EQ(s.value("charts", 0), 4) << s.dump();  // value and residual per channel
  EXPECT_EQ(s.value("window_rows", 0), 4) << s.dump();
  EXPECT_TRUE(s.value("zoom_ok", false)) << s.dump();
  EXPECT_TRUE(s.value("errors", nlohmann::json::array()).empty()) << s.dump();
  EXPECT_EQ(s.value("frf_charts", -1), 0) << "no frequency response in the comparison: no chart";
  // The frequency response from a road (diagnosis/frequency_response.hpp) under the first channel:
  // its chart drawn, a band that differs shaded, no script error.
  auto with_frf = comparison(2000, 4);
  {
    auto& ser = with_frf["series"][0];
    const auto t = ser["t"].get<std::vector<double>>();
    std::vector<double> road(t.size()), measured(t.size()), predicted(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
      road[i] = 0.01 * (std::sin(7.1 * i) + std::sin(2.3 * i + 1) + std::sin(0.5 * i));
      predicted[i] = 40 * road[i] + (i ? 20 * road[i - 1] : 0.0);
      measured[i] = 1.3 * predicted[i] + 0.01 * std::sin(1.7 * i);
    }
    ser["frequency_response"] =
        diag::seriesResponse(t, road, "road_fl_m", measured, predicted).toJson();
  }
  const fs::path frf = kTmp() / "frf.html";
  std::ofstream(frf) << comparePage(with_frf, "with a frequency response");
  const auto f = selftest(chromium, frf);
  EXPECT_EQ(f.value("frf_charts", 0), 1) << f.dump();
  EXPECT_TRUE(f.value("errors", nlohmann::json::array()).empty()) << f.dump();
  // Two models (a diagnosis's base and "+ effect"): each adds its line and its residual.
  auto after = comparison(2000, 0);
  for (auto& ser : after["series"])
    for (auto& v : ser["predicted_mean"]) v = v.get<double>() + 0.01;
  const fs::path two = kTmp() / "two.html";
  std::ofstream(two) << comparePage(
      std::vector<PageModel>{{"base", comparison(2000, 4)}, {"+ effect", after}}, "two models");
  const auto t = selftest(chromium, two);
  EXPECT_EQ(t.value("charts", 0), 4) << t.dump();
  // value chart: t, 2 predictions, band low and high, measured; residual chart: t and 2 residuals.
  EXPECT_EQ(t.value("series", nlohmann::json::array()), nlohmann::json({6, 3, 6, 3})) << t.dump();
  EXPECT_EQ(t.value("window_rows", 0), 4) << "the first model's windows";
  EXPECT_TRUE(t.value("errors", nlohmann::json::array()).empty()) << t.dump();
  // A 117 000-row drive (two channels): it draws, zooms, and the time its charts are built is
  // printed.
  const fs::path big = kTmp() / "big.html";
  std::ofstream(big) << comparePage(comparison(117000, 40), "big");
  const auto g = selftest(chromium, big);
  EXPECT_EQ(g.value("charts", 0), 4) << g.dump();
  EXPECT_TRUE(g.value("zoom_ok", false)) << g.dump();
  EXPECT_TRUE(g.value("errors", nlohmann::json::array()).empty()) << g.dump();
  std::printf(
      "[ page ] 117 000 rows x 2 channels: charts built %d ms after navigation, a zoom redrawn in "
      "%d ms (headless Chromium)\n",
      g.value("ready_ms", -1), g.value("zoom_ms", -1));
  fs::remove_all(kTmp());
}

// The comparison lists a few windows of many, each channel's count in words: the page tables them
// largest share first (across channels), shows the words above the table, and shades only them.
TEST(ComparePage, ListsTheWindowsLargestShareFirstUnderTheirCountInWords) {
  auto j = comparison(3000, 0);
  const std::string note =
      "2033 windows over 98 % of the record: the model misses throughout, not in a few places; "
      "merged to 187 "
      "(neighbours closer than 0.2 s), the 20 largest, listed, hold 61 % of the residual";
  auto& seat = j["series"][0];
  seat["windows_note"] = note;
  const double shares[] = {0.02, 0.30, 0.05, 0.12};
  for (int w = 0; w < 4; ++w)
    seat["windows"].push_back({{"t_begin_s", 1.0 + 5 * w},
                               {"t_end_s", 2.0 + 5 * w},
                               {"peak_z", 9.0},
                               {"share_of_chi2", shares[w]},
                               {"label", "x"}});
  j["series"][1]["windows"].push_back({{"t_begin_s", 3.0},
                                       {"t_end_s", 3.5},
                                       {"peak_z", 6.0},
                                       {"share_of_chi2", 0.2},
                                       {"label", "y"}});
  const std::string html = comparePage(j, "windows");
  const auto a = html.find("id=data>"), b = html.find("</script>", a);
  const auto data = nlohmann::json::parse(html.substr(a + 8, b - a - 8));
  EXPECT_EQ(data["sets"][0]["channels"][0]["windows_note"], note);
  EXPECT_EQ(data["sets"][0]["channels"][1]["windows_note"], "");
  const std::string chromium = dtwin_test::findChromium();
  if (chromium.empty())
    GTEST_SKIP()
        << "chromium is not installed (Debian package chromium): the page check is skipped";
  fs::remove_all(kTmp());
  fs::create_directories(kTmp());
  const fs::path page = kTmp() / "windows.html";
  std::ofstream(page) << html;
  const auto s = selftest(chromium, page);
  EXPECT_EQ(s.value("window_shares", nlohmann::json()),
            nlohmann::json({30.0, 20.0, 12.0, 5.0, 2.0}))
      << s.dump();
  ASSERT_EQ(s.value("windows_notes", nlohmann::json::array()).size(), 1u) << s.dump();
  EXPECT_EQ(s["windows_notes"][0], "seat_mps2: " + note) << s.dump();
  EXPECT_TRUE(s.value("errors", nlohmann::json::array()).empty()) << s.dump();
  fs::remove_all(kTmp());
}

// twin compare --discrepancy: a channel's discrepancy object is drawn under it, the three fit
// percentages side by side and the gain and phase of the car over the model in one chart.
TEST(ComparePage, DrawsTheDiscrepancyFilterAndTheThreeFits) {
  auto j = comparison(2000, 0);
  nlohmann::json d{{"physics_fit_percent", 61.2},
                   {"hybrid_fit_percent", 88.4},
                   {"baseline_fit_percent", 42.9},
                   {"share", 0.31},
                   {"none", false},
                   {"description", "FIR from the road's vertical velocity"},
                   {"summary", "at 0.5–2 Hz (body) the car responds <b>"},
                   {"response_note", "on the calibration drive"}};
  std::vector<double> f, g, p;
  for (int k = 1; k <= 100; ++k)
    f.push_back(0.2 * k), g.push_back(1 + 0.3 / k), p.push_back(40.0 / k);
  d["response"] = {{"freq_hz", f}, {"gain", g}, {"phase_deg", p}};
  d["bands"] = {{{"band", "body"},
                 {"lo_hz", 0.5},
                 {"hi_hz", 2.0},
                 {"gain", 1.3},
                 {"phase_deg", 40.0},
                 {"read", true},
                 {"words", "x"}},
                {{"band", "high"},
                 {"lo_hz", 20.0},
                 {"hi_hz", 50.0},
                 {"gain", 1.0},
                 {"phase_deg", 0.0},
                 {"read", false},
                 {"words", "y"}}};
  j["series"][0]["discrepancy"] = d;
  const std::string html = comparePage(j, "discrepancy");
  EXPECT_NE(html.find("88.4"), std::string::npos);
  const std::string chromium = dtwin_test::findChromium();
  if (chromium.empty())
    GTEST_SKIP()
        << "chromium is not installed (Debian package chromium): the page check is skipped";
  fs::create_directories(kTmp());
  const fs::path page = kTmp() / "discrepancy.html";
  std::ofstream(page) << html;
  const auto s = selftest(chromium, page);
  EXPECT_TRUE(s.value("errors", nlohmann::json::array()).empty()) << s.dump();
  ASSERT_EQ(s.value("discrepancy", nlohmann::json::array()).size(), 1u) << s.dump();
  EXPECT_EQ(s["discrepancy"][0]["charts"], 1) << s.dump();
  EXPECT_EQ(s["discrepancy"][0]["fits"], nlohmann::json({"61.2 %", "88.4 %", "42.9 %", "31 %"}))
      << s.dump();
  fs::remove_all(kTmp());
}
