// The diagnosis report (report/diagnosis_report.hpp, `twin report --diagnosis DIR`) on a small
// hand-written diagnosis folder: the page is written, holds the verdict, one inline SVG per
// expected plot (the waterfall only with steps), unique ids, no external resource; missing or
// malformed files and a missing gnuplot give an InputError naming the file or the package.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>
#include <cmath>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "report/diagnosis_report.hpp"
#include "report/study_report.hpp"
#include "report/svg_plot.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path kTmp() { return fs::temp_directory_path() / "dtwin_diag_report_test"; }

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = 0; (pos = s.find(what, pos)) != std::string::npos; pos += what.size()) ++n;
  return n;
}

const char* kChannels[] = {"hub_force_fl_N", "hub_force_fr_N"};

/// A full comparison; `gain` scales the bump the model misses (1: base, 0.1: with the effect).
json comparison(double gain) {
  json c{{"draws", 8},
         {"failures", 0},
         {"systematic_rms_noise_sd", 4.0 * gain + 0.5},
         {"notes", json::array()}};
  c["lack_of_fit"] = {{"chi2", 900 * gain}, {"dof", 78}, {"z", 30 * gain}, {"p_value", 1e-20}};
  c["series"] = json::array();
  for (const char* ch : kChannels) {
    json s{{"data_set", "/data/diag_bump.csv"},
           {"scenario", "diag_bump"},
           {"channel", ch},
           {"unit", "N"},
           {"fitted", true},
           {"noise_variance", 25.0},
           {"rms", 40 * gain + 5},
           {"nrmse", 0.1 * gain + 0.01},
           {"coverage95", 0.95 - 0.5 * gain},
           {"systematic_rms", 38 * gain}};
    std::vector<double> t, m, p, lo, hi;
    for (int i = 0; i < 40; ++i) {
      const double ti = 0.05 * i, bump = 800.0 * std::exp(-std::pow((ti - 1.0) / 0.1, 2));
      t.push_back(ti);
      m.push_back(3500 + bump + 3 * std::sin(7 * ti));
      p.push_back(3500 + bump * (1 - gain));
      lo.push_back(p.back() - 12);
      hi.push_back(p.back() + 12);
    }
    m[5] = NAN;  // written as null: must be skipped, not fail
    s["t"] = t;
    s["measured_mean"] = m;
    s["predicted_mean"] = p;
    s["band_lo"] = lo;
    s["band_hi"] = hi;
    s["windows"] = json::array({{{"t_begin_s", 0.9},
                                 {"t_end_s", 1.1},
                                 {"peak_z", 9.0},
                                 {"share_of_chi2", 0.8},
                                 {"label", "bump"},
                                 {"speed_mps", 5.0}}});
    s["bands"] = json::array();
    const char* names[] = {"body 0.5-3 Hz", "wheel hop 8-20 Hz", "high 20-50 Hz"};
    for (int b = 0; b < 3; ++b)
      s["bands"].push_back({{"band", names[b]},
                            {"lo_hz", 1.0},
                            {"hi_hz", 2.0},
                            {"residual_power", 1.0},
                            {"noise_power", 1.0},
                            {"ratio", (b == 0 ? 40.0 : 2.0) * gain + 0.8},
                            {"coherence_with_road", 0.5},
                            {"significant", b == 0}});
    c["series"].push_back(s);
  }
  json maps = json::array();
  for (const char* state : {"susp_defl_fl_m", "susp_rate_fl_mps"}) {
    json m{{"state", state}, {"bins", json::array()}, {"fits", json::array()}};
    for (int b = 0; b < 10; ++b) {
      const double q = -0.02 + 0.005 * b;
      m["bins"].push_back({{"lo", q - 0.002},
                           {"hi", q + 0.002},
                           {"centre", q},
                           {"mean_residual", gain * 1e6 * std::pow(std::max(q - 0.01, 0.0), 2)},
                           {"se", 3.0},
                           {"count", 12}});
    }
    const bool defl = std::string(state) == "susp_defl_fl_m";
    m["fits"].push_back({{"feature", defl ? "knee" : "step"},
                         {"coefficient", 1e6},
                         {"explained_fraction", defl ? 0.9 : 0.2}});
    if (defl) m["fits"][0]["knee_at"] = 0.01;
    m["fits"].push_back({{"feature", "linear"},
                         {"coefficient", 1e3},
                         {"explained_fraction", 0.1},
                         {"knee_at", nullptr}});
    maps.push_back(m);
  }
  c["state_maps"] = json::array({{{"channel", "hub_force_fl_N"}, {"maps", maps}}});
  return c;
}

/// The "figures" object of diagnosis.json for a model with `effects`.
json figures(const std::vector<std::string>& effects, double gain, double log_evidence) {
  json f{{"label", effects.empty() ? "base" : "with effects"},
         {"effects", effects},
         {"sse_min_weighted", 900 * gain},
         {"bic", -2 * log_evidence},
         {"log_evidence", log_evidence},
         {"parameters", json::object()},
         {"folder", "calibrations/x"},
         {"lack_of_fit_z", 30 * gain},
         {"lack_of_fit_p", 1e-20},
         {"systematic_rms_noise_sd", 4.0 * gain + 0.5}};
  f["effect_parameters"] = json::object();
  if (!effects.empty())
    f["effect_parameters"]["bump_stop.stiffness"] = {{"unit", "N/m"},
                                                     {"mean", 9.6e6},
                                                     {"sd", 4e5},
                                                     {"ci95", {8.9e6, 1.04e7}},
                                                     {"optimum", 9.7e6}};
  f["series"] = json::array();
  for (const char* ch : kChannels)
    f["series"].push_back({{"data_set", "/data/diag_bump.csv"},
                           {"scenario", "diag_bump"},
                           {"channel", ch},
                           {"rms", 40 * gain + 5},
                           {"nrmse", 0.1 * gain},
                           {"max_abs_error", 100 * gain},
                           {"coverage95", 0.95 - 0.5 * gain},
                           {"systematic_rms", 38 * gain},
                           {"band_power_ratio", {{"body 0.5-3 Hz", 40 * gain}}}});
  return f;
}

void writeJson(const fs::path& p, const json& j) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << j.dump(1);
}

/// A diagnosis folder naming bump_stop; with `steps`, --apply bump_stop,strut_friction was used.
fs::path makeDiagnosis(const std::string& name, bool steps) {
  const fs::path dir = kTmp() / name;
  fs::remove_all(dir);
  json d{{"assembly", "M1"},
         {"verdict", "effect"},
         {"effect", "bump_stop"},
         {"summary",
          "The residual grows with suspension deflection beyond 10 mm: a bump stop <is> missing."},
         {"ambiguous_with", json::array()},
         {"unexplained_location", "none"}};
  d["base"] = figures({}, 1.0, -5000);
  d["ranked"] =
      json::array({{{"effect", "bump_stop"},
                    {"log_evidence", -1200.0},
                    {"log_evidence_vs_base", 3800.0},
                    {"delta_bic", -7600.0},
                    {"explained_fraction", 0.93},
                    {"parameters", figures({"bump_stop"}, 0.1, -1200)["effect_parameters"]},
                    {"why", "knee in the force-deflection map"},
                    {"fit", figures({"bump_stop"}, 0.1, -1200)}}});
  d["screening"] = json::array({{{"effect", "bump_stop"},
                                 {"score", 812.0},
                                 {"score_dof", 2},
                                 {"p_value", 0.0},
                                 {"max_signal", 9.0},
                                 {"gate", "pass"},
                                 {"confirmed", true},
                                 {"why", "knee"},
                                 {"signature", "knee in susp_defl"}},
                                {{"effect", "strut_friction"},
                                 {"score", 1.2},
                                 {"score_dof", 2},
                                 {"p_value", 0.55},
                                 {"max_signal", 1.0},
                                 {"gate", "p > 0.01"},
                                 {"confirmed", false},
                                 {"why", "no step in the rate map"},
                                 {"signature", "step in susp_rate"}}});
  d["command"] = "twin diagnose --data diag_bump.csv --out " + dir.string();
  d["created_utc"] = "20240601T000000Z";
  writeJson(dir / "comparisons" / "base.json", comparison(1.0));
  writeJson(dir / "comparisons" / "bump_stop.json", comparison(0.1));
  if (steps) {
    d["steps"] = json::array({figures({}, 1.0, -5000), figures({"bump_stop"}, 0.1, -1200),
                              figures({"bump_stop", "strut_friction"}, 0.12, -1210)});
    d["before"] = d["steps"][0];
    d["after"] = d["steps"][2];
    writeJson(dir / "comparisons" / "bump_stop+strut_friction.json", comparison(0.12));
  }
  writeJson(dir / "diagnosis.json", d);
  return dir;
}

void checkPage(const std::string& page, std::size_t svgs) {
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("Verdict: effect — bump_stop"), std::string::npos);
  EXPECT_NE(page.find("&lt;is&gt;"), std::string::npos) << "summary escaped";
  EXPECT_NE(page.find("bump_stop.stiffness = 9.6e+06 ± 4e+05 N/m [8.9e+06, 1.04e+07]"),
            std::string::npos);
  EXPECT_NE(page.find("no step in the rate map"), std::string::npos);
  EXPECT_EQ(count(page, "<svg"), svgs);
  EXPECT_EQ(count(page, "</svg>"), svgs);
  for (const char* bad :
       {"<?xml", "<!DOCTYPE svg", "<script", "src=", "gnuplot>", "line 0:", "warnings:"})
    EXPECT_EQ(page.find(bad), std::string::npos) << bad;
  // No external resources: "http" only in the SVG namespace declarations.
  const std::string stripped =
      std::regex_replace(page, std::regex("xmlns(:[a-z]+)?=\"http[^\"]*\""), "");
  EXPECT_EQ(stripped.find("http"), std::string::npos);
  std::map<std::string, int> ids;
  const std::regex id_re("\\bid=(['\"])([^'\"]+)\\1");
  for (auto it = std::sregex_iterator(page.begin(), page.end(), id_re);
       it != std::sregex_iterator(); ++it)
    ++ids[(*it)[2]];
  for (const auto& [id, n] : ids) EXPECT_EQ(n, 1) << "duplicate id " << id;
}

bool haveGnuplot() { return !dtwin::report::findOnPath("gnuplot").empty(); }

}  // namespace

TEST(DiagnosisReport, WithStepsDrawsEveryPlotAndTheWaterfall) {
  if (!haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
  const fs::path dir = makeDiagnosis("steps", true);
  const fs::path html = kTmp() / "steps.html";
  const json r = dtwin::report::writeDiagnosisReport(dir.string(), html.string(), "test");
  ASSERT_TRUE(fs::exists(html));
  const std::string page = dtwin_test::slurp(html);
  // 2 series overlays, band power, state map, waterfall.
  checkPage(page, 5);
  EXPECT_EQ(r["svg_count"], 5);
  EXPECT_EQ(r["verdict"], "effect");
  EXPECT_NE(page.find("systematic RMS waterfall"), std::string::npos);
  EXPECT_NE(page.find("+ bump_stop+strut_friction"), std::string::npos);
  EXPECT_NE(page.find("susp_defl_fl_m"), std::string::npos) << "the best map (knee, 90 %)";
  EXPECT_TRUE(r["warnings"].empty()) << r["warnings"].dump();
}

TEST(DiagnosisReport, WithoutStepsHasNoWaterfall) {
  if (!haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
  const fs::path dir = makeDiagnosis("nosteps", false);
  const fs::path html = kTmp() / "nosteps.html";
  const json r = dtwin::report::writeDiagnosisReport(dir.string(), html.string(), "test");
  const std::string page = dtwin_test::slurp(html);
  checkPage(page, 4);
  EXPECT_EQ(page.find("waterfall"), std::string::npos);
  EXPECT_EQ(page.find("Before and after"), std::string::npos);
  // Section only (for the study report): the same plots, no page skeleton, its own id prefix.
  dtwin::report::DiagnosisSectionOptions o;
  o.id_prefix = "q";
  json drawn;
  const std::string sec = dtwin::report::diagnosisSectionHtml(dir.string(), o, &drawn);
  EXPECT_EQ(sec.find("<html"), std::string::npos);
  EXPECT_EQ(count(sec, "<svg"), 4u);
  EXPECT_EQ(drawn["svg_count"], 4);
  EXPECT_NE(sec.find("id=\"q1_"), std::string::npos);
}

TEST(DiagnosisReport, TwoFoldersOnOnePageViaCli) {
  if (!haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
  const fs::path a = makeDiagnosis("cli_a", true), b = makeDiagnosis("cli_b", false),
                 html = kTmp() / "cli.html";
  const std::string twin = DTWIN_TWIN_EXE;
  ASSERT_EQ(std::system((twin + " report --quiet --diagnosis " + a.string() + " --diagnosis " +
                         b.string() + " --out " + html.string())
                            .c_str()),
            0);
  const std::string page = dtwin_test::slurp(html);
  EXPECT_EQ(count(page, "<svg"), 9u);
  std::map<std::string, int> ids;
  const std::regex id_re("\\bid=(['\"])([^'\"]+)\\1");
  for (auto it = std::sregex_iterator(page.begin(), page.end(), id_re);
       it != std::sregex_iterator(); ++it)
    ++ids[(*it)[2]];
  for (const auto& [id, n] : ids) EXPECT_EQ(n, 1) << "duplicate id " << id;
  // Neither a study nor a diagnosis: one line, exit code 2.
  const int rc = std::system((twin + " report 2>/dev/null").c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 2);
}

TEST(DiagnosisReport, MissingOrMalformedFilesAreNamed) {
  const fs::path dir = makeDiagnosis("broken", false);
  if (!haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
  fs::remove(dir / "comparisons" / "base.json");
  try {
    dtwin::report::writeDiagnosisReport(dir.string(), (kTmp() / "broken.html").string(), "test");
    FAIL() << "no InputError";
  } catch (const dtwin::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("comparisons/base.json"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(kTmp() / "broken.html"));
  std::ofstream(dir / "diagnosis.json") << "{\"verdict\": ";
  try {
    dtwin::report::writeDiagnosisReport(dir.string(), (kTmp() / "broken.html").string(), "test");
    FAIL() << "no InputError";
  } catch (const dtwin::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("diagnosis.json"), std::string::npos) << e.what();
  }
  const fs::path dir2 = makeDiagnosis("broken2", false);
  writeJson(dir2 / "comparisons" / "bump_stop.json",
            json{{"series", {{{"channel", "x"}, {"t", {1, 2}}}}}});
  try {
    dtwin::report::writeDiagnosisReport(dir2.string(), (kTmp() / "broken2.html").string(), "test");
    FAIL() << "no InputError";
  } catch (const dtwin::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("comparisons/bump_stop.json"), std::string::npos)
        << e.what();
  }
}

TEST(DiagnosisReport, MissingGnuplotNamesThePackage) {
  const fs::path dir = makeDiagnosis("nognuplot", true);
  const std::string old = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", "/nonexistent", 1);
  try {
    dtwin::report::writeDiagnosisReport(dir.string(), (kTmp() / "nognuplot.html").string(), "test");
    ::setenv("PATH", old.c_str(), 1);
    FAIL() << "no InputError";
  } catch (const dtwin::InputError& e) {
    ::setenv("PATH", old.c_str(), 1);
    EXPECT_NE(std::string(e.what()).find("gnuplot-nox"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(kTmp() / "nognuplot.html"));
}

// Options errors name the field (common/validate.hpp): "diagnosis_section.<field>" and
// "report.<field>"; an empty folder list is "diagnosis_report.diag_dirs".
TEST(DiagnosisReport, OptionsNameTheField) {
  auto where = [](const auto& f) -> std::string {
    try {
      f();
    } catch (const dtwin::InputError& e) {
      return e.where();
    }
    return "no error";
  };
  dtwin::report::DiagnosisSectionOptions o;
  EXPECT_EQ(where([&] { o.validate(); }), "no error");
  o.anchor.clear();
  EXPECT_EQ(where([&] { o.validate(); }), "diagnosis_section.anchor");
  o = {};
  o.id_prefix.clear();
  EXPECT_EQ(where([&] { o.validate(); }), "diagnosis_section.id_prefix");
  dtwin::report::ReportOptions r;
  EXPECT_EQ(where([&] { r.validate(); }), "no error");
  r.appendix.push_back({"", "a section", "<section></section>", 0});
  EXPECT_EQ(where([&] { r.validate(); }), "report.appendix");
  if (!haveGnuplot()) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
  EXPECT_EQ(where([&] {
              dtwin::report::writeDiagnosisReport(std::vector<std::string>{},
                                                  (kTmp() / "x.html").string(), "t");
            }),
            "diagnosis_report.diag_dirs");
}
