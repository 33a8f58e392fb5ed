// A corpus of broken inputs, generated from the project's own valid files: every number of the
// demo study and of the vehicle file replaced in turn by values no field accepts, and the lab
// CSV broken in the ways loggers and hand edits break files. Each case must give exit code 2,
// one line on stderr naming the broken file (and, where it has one, the field), and write
// nothing.
#include <gtest/gtest.h>

#include "test_util.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using dtwin_test::freshDir;
using dtwin_test::slurp;
using dtwin_test::writeText;

const std::string kSrc = DTWIN_SOURCE_DIR;

using Result = dtwin_test::TwinRun;

Result twin(const std::string& args, const fs::path& dir) { return dtwin_test::runTwin(args, dir); }

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& l : v) s += l + "\n";
  return s;
}

/// One mutation of a TOML file: line `line` with the number of `key = <number>` replaced.
struct TomlCase {
  std::size_t line;
  std::string key, bad, text;
};

/// Every `key = <number>` of a TOML text (plain or inside an inline table), each replaced by each
/// of `bad` in turn.
std::vector<TomlCase> numberMutations(const std::string& text,
                                      const std::vector<std::string>& bad) {
  static const std::regex kv(R"(([A-Za-z_][A-Za-z_0-9]*)\s*=\s*(-?[0-9][0-9.eE+\-]*))");
  std::vector<TomlCase> out;
  const auto ls = lines(text);
  for (std::size_t i = 0; i < ls.size(); ++i) {
    const std::string code = ls[i].substr(0, ls[i].find('#'));
    for (auto it = std::sregex_iterator(code.begin(), code.end(), kv); it != std::sregex_iterator();
         ++it) {
      for (const auto& b : bad) {
        auto copy = ls;
        copy[i] =
            code.substr(0, it->position(2)) + b + code.substr(it->position(2) + it->length(2));
        out.push_back({i + 1, (*it)[1].str(), b, join(copy)});
      }
    }
  }
  return out;
}

/// The checks every case must pass.
void expectRejected(const Result& r, const std::string& names_file, const std::string& names_field,
                    const fs::path& must_not_exist) {
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  EXPECT_EQ(r.err.rfind("twin: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(names_file), std::string::npos)
      << "names the file " << names_file << ": " << r.err;
  if (!names_field.empty()) {
    EXPECT_NE(r.err.find(names_field), std::string::npos)
        << "names the field " << names_field << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(must_not_exist)) << "nothing may be written: " << must_not_exist;
}

const std::vector<std::string> kBadNumbers = {"nan", "inf", "-inf", "\"12\"", "true"};

TEST(BrokenInputs, EveryNumberOfTheStudyFile) {
  const fs::path dir = freshDir("broken_study");
  const std::string base = slurp(kSrc + "/data/studies/demo.toml");
  auto cases = numberMutations(base, kBadNumbers);
  ASSERT_GT(cases.size(), 120u);
  // The vehicle path is relative to the study: keep it pointing at the project's vehicle file.
  const std::string vehicle = "vehicle = \"" + kSrc + "/data/vehicle/midsize_sedan.toml\"";
  int n = 0;
  for (const auto& c : cases) {
    SCOPED_TRACE("demo.toml line " + std::to_string(c.line) + ": " + c.key + " = " + c.bad);
    const fs::path study = dir / ("study_" + std::to_string(n++) + ".toml");
    writeText(study, std::regex_replace(c.text, std::regex(R"(vehicle = "[^"]*")"), vehicle));
    const fs::path out = dir / "out" / "lab.csv";
    const Result r =
        twin("generate lab --quiet --study " + study.string() + " --out " + out.string(), dir);
    expectRejected(r, study.string(), c.key, dir / "out");
  }
}

TEST(BrokenInputs, EveryNumberOfTheVehicleFile) {
  const fs::path dir = freshDir("broken_vehicle");
  const std::string base = slurp(kSrc + "/data/vehicle/midsize_sedan.toml");
  auto cases = numberMutations(base, {"nan", "inf", "\"12\""});
  ASSERT_GT(cases.size(), 60u);
  const std::string study_text = slurp(kSrc + "/data/studies/demo.toml");
  int n = 0;
  for (const auto& c : cases) {
    SCOPED_TRACE("midsize_sedan.toml line " + std::to_string(c.line) + ": " + c.key + " = " +
                 c.bad);
    const fs::path vehicle = dir / ("vehicle_" + std::to_string(n) + ".toml");
    const fs::path study = dir / ("study_" + std::to_string(n++) + ".toml");
    writeText(vehicle, c.text);
    writeText(study, std::regex_replace(study_text, std::regex(R"(vehicle = "[^"]*")"),
                                        "vehicle = \"" + vehicle.string() + "\""));
    const fs::path out = dir / "out" / "lab.csv";
    const Result r =
        twin("generate lab --quiet --study " + study.string() + " --out " + out.string(), dir);
    expectRejected(r, vehicle.string(), "", dir / "out");
  }
}

TEST(BrokenInputs, LabCsvBrokenAsLoggersAndEditorsBreakThem) {
  const fs::path dir = freshDir("broken_lab");
  const fs::path good = dir / "good.csv";
  const Result made = twin("generate lab --quiet --repetitions 2 --out " + good.string(), dir);
  ASSERT_EQ(made.code, 0) << made.err;
  const auto ls = lines(slurp(good));
  ASSERT_GT(ls.size(), 4u);
  const std::string header = ls[0];
  const std::string row = ls[2];
  const auto cells = [&](const std::string& r) {
    std::vector<std::string> v;
    std::stringstream s(r);
    for (std::string c; std::getline(s, c, ',');) v.push_back(c);
    return v;
  };
  const auto withCell = [&](std::size_t col, const std::string& value) {
    auto v = cells(row);
    v[col] = value;
    std::string r;
    for (std::size_t k = 0; k < v.size(); ++k) r += (k ? "," : "") + v[k];
    auto copy = ls;
    copy[2] = r;
    return join(copy);
  };
  const std::size_t ncol = cells(header).size();
  std::vector<std::pair<std::string, std::string>> cases;  // (what, text)
  for (std::size_t col = 0; col < ncol; ++col)
    for (const std::string bad :
         {"", "abc", "nan", "inf", "-inf", "1e308", "-1e308", "1,2", "0x10"})
      cases.push_back(
          {"column " + std::to_string(col + 1) + " = '" + bad + "'", withCell(col, bad)});
  {
    auto copy = ls;
    copy[2] = row + ",7";
    cases.push_back({"extra cell", join(copy)});
    copy = ls;
    copy[2] = row.substr(0, row.rfind(','));
    cases.push_back({"missing cell", join(copy)});
    copy = ls;
    copy[0] = "repetition,time,channel,value";
    cases.push_back({"renamed column", join(copy)});
    copy = ls;
    copy.erase(copy.begin());
    cases.push_back({"no header", join(copy)});
    cases.push_back({"header only", header + "\n"});
    cases.push_back({"empty file", ""});
    cases.push_back({"binary", std::string("\x00\x01\x02\xff\xfe", 5)});
  }
  int n = 0;
  for (const auto& [what, text] : cases) {
    SCOPED_TRACE(what);
    const fs::path lab = dir / ("lab_" + std::to_string(n++) + ".csv");
    writeText(lab, text);
    const Result r = twin("calibrate --quiet --assembly M1 --data " + lab.string() + " --out " +
                              (dir / "cal").string(),
                          dir);
    expectRejected(r, lab.string(), "", dir / "cal");
  }
}

// Values that are numbers of the right type, but would make the work unbounded (a grid of 1e-320 m,
// billions of repetitions) or a file that is a folder: refused when the study is read, before any
// work, with the field named.
TEST(BrokenInputs, UnboundedWorkIsRefusedBeforeItStarts) {
  const fs::path dir = freshDir("broken_unbounded");
  const std::string base = std::regex_replace(
      slurp(kSrc + "/data/studies/demo.toml"), std::regex(R"(vehicle = "[^"]*")"),
      "vehicle = \"" + kSrc + "/data/vehicle/midsize_sedan.toml\"");
  struct Case {
    std::string from, to, field;
  };
  const std::vector<Case> cases = {
      {"dx_m = 0.01, tracks", "dx_m = 1e-320, tracks", "dx_m"},
      // 8000 s at 15 m/s on a 0.01 m grid: each value fine alone, but 1.2e7 grid points a track
      {"duration_s = 3.0\nspeed = { v_final_mps = 15.0",
       "duration_s = 8000.0\nspeed = { v_final_mps = 15.0", "dx_m"},
      {"max_step_s = 0.2", "max_step_s = 1e-320", "max_step_s"},
      {"obstacle_max_step_s = 2e-3", "obstacle_max_step_s = 1e-9", "obstacle_max_step_s"},
      {"accuracy = 3e-4", "accuracy = 1e-300", "accuracy"},
      {"accuracy = 3e-4", "accuracy = 3e-4\nhub_motion = \"stiff\"", "hub_motion"},
      {"lab_repetitions = 10", "lab_repetitions = 5000000000", "lab_repetitions"},
      {"gibbs_iterations = 20000", "gibbs_iterations = 900000000", "gibbs_iterations"},
      {"duration_s = 3.0", "duration_s = 1e9", "duration_s"},
      {"v_final_mps = 4.0", "v_final_mps = 1e9", "v_final_mps"},
      {"output_rate_hz = 1000.0", "output_rate_hz = 900000.0",
       "duration_s"},  // 15 s x 9e5 Hz > 1e7 samples
      {R"(tire = ["pac2002", "fiala"])", R"(tire = ["pac2002", "fiala", "pac2002"])", "tire"},
      {"[noise]", "[simulation.extra]\nx = 1\n[noise]", "simulation"},
  };
  int n = 0;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.to);
    const std::size_t at = base.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    std::string text = base;
    text.replace(at, c.from.size(), c.to);
    const fs::path study = dir / ("study_" + std::to_string(n++) + ".toml");
    writeText(study, text);
    // generate lab runs one short simulation when a study is accepted: a case that slips through
    // fails the test quickly instead of running a study.
    const Result r = twin("generate lab --quiet --study " + study.string() + " --out " +
                              (dir / "out" / "lab.csv").string(),
                          dir);
    expectRejected(r, study.string(), c.field, dir / "out");
  }
  // Sizes that are each inside their limits but multiply up past the work limit: refused by the
  // commands that would run them, naming the study and --force.
  std::string big = base;
  big.replace(big.find("posterior_draws = 100"), 21, "posterior_draws = 900000");
  writeText(dir / "big.toml", big);
  Result r = twin(
      "study --study " + (dir / "big.toml").string() + " --quiet --out " + (dir / "out").string(),
      dir);
  expectRejected(r, (dir / "big.toml").string(), "estimated work", dir / "out");
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  r = twin("calibrate --study " + (dir / "big.toml").string() + " --data " + kSrc +
               "/tests/fuzz/seeds/lab/two_channels.csv" +
               " --assembly M1 --lhs-points 2000000 --out " + (dir / "out").string(),
           dir);
  expectRejected(r, "--lhs-points", "at most", dir / "out");
  // A vehicle path that is a folder, and a study path that is a folder.
  std::string folder = base;
  folder = std::regex_replace(folder, std::regex(R"(vehicle = "[^"]*")"),
                              "vehicle = \"" + dir.string() + "\"");
  writeText(dir / "folder_vehicle.toml", folder);
  r = twin("generate lab --quiet --study " + (dir / "folder_vehicle.toml").string() + " --out " +
               (dir / "out" / "l.csv").string(),
           dir);
  expectRejected(r, dir.string(), "is a folder", dir / "out");
  r = twin("list --study " + dir.string(), dir);
  expectRejected(r, dir.string(), "is a folder", dir / "out");
}

// Files are written only after every input was read and checked, and a run that fails leaves no
// trace behind.
TEST(BrokenInputs, FailuresWriteNothing) {
  const fs::path dir = freshDir("broken_nothing_written");
  const std::string base = std::regex_replace(
      slurp(kSrc + "/data/studies/demo.toml"), std::regex(R"(vehicle = "[^"]*")"),
      "vehicle = \"" + kSrc + "/data/vehicle/midsize_sedan.toml\"");
  writeText(dir / "bad_lab.csv",
            "repetition,time_s,channel,value\n1,6,hub_force_fl_N,1\n\n1,5,hub_force_fl_N,2\n");
  Result r = twin(
      "study --quiet --lab " + (dir / "bad_lab.csv").string() + " --out " + (dir / "out").string(),
      dir);
  expectRejected(r, "bad_lab.csv:4", "time_s", dir / "out");  // line 4: the blank line 3 is counted
  r = twin(
      "study --quiet --lab " + (dir / "missing.csv").string() + " --out " + (dir / "out").string(),
      dir);
  expectRejected(r, "missing.csv", "", dir / "out");
  r = twin("study --quiet --field " + (dir / "bad_lab.csv").string() + " --out " +
               (dir / "out").string(),
           dir);
  expectRejected(r, "bad_lab.csv", "", dir / "out");

  // A simulation that fails (step budget, wall-clock budget): exit 1, one line, no trace file.
  for (const std::string budget : {"max_internal_steps = 20", "max_wall_s = 1e-9"}) {
    SCOPED_TRACE(budget);
    std::string text = base;
    text.replace(text.find("output_rate_hz = 1000.0"), 23, "output_rate_hz = 1000.0\n" + budget);
    writeText(dir / "budget.toml", text);
    r = twin("simulate --quiet --study " + (dir / "budget.toml").string() +
                 " --assembly M1 --scenario lab --out " + (dir / "out" / "trace.csv").string(),
             dir);
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_NE(r.err.find("simulation failed"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "trace.csv"));
    EXPECT_FALSE(fs::exists(dir / "out" / "trace.json"));
  }
}

/// Every file under `dir`, path -> bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    m[fs::relative(e.path(), dir).string()] =
        e.is_regular_file() ? slurp(e.path()) : std::string("<dir>");
  return m;
}

// Every command that writes, failing on a broken input, leaves an output folder that already holds
// files byte-identical (nothing added, nothing changed, nothing removed).
TEST(BrokenInputs, EveryCommandLeavesItsOutputFolderByteIdenticalOnFailure) {
  const fs::path dir = freshDir("broken_identical");
  const fs::path out = dir / "out";
  fs::create_directories(out / "M1");
  writeText(out / "previous.csv", "a,b\n1,2\n");
  writeText(out / "M1" / "summary.json", "{\"assembly\": \"M1\"}\n");
  writeText(out / "report.html", "<html>earlier</html>\n");
  const std::string demo = std::regex_replace(
      slurp(kSrc + "/data/studies/demo.toml"), std::regex(R"(vehicle = "[^"]*")"),
      "vehicle = \"" + kSrc + "/data/vehicle/midsize_sedan.toml\"");
  std::string broken = demo;
  broken.replace(broken.find("variance_N2 = 18000.0"), 21, "variance_N2 = nan");
  writeText(dir / "broken.toml", broken);
  writeText(dir / "good.toml", demo);
  writeText(dir / "bad_lab.csv", "repetition,time_s,channel,value\n1,6,hub_force_fl_N,1e308\n");
  writeText(dir / "bad_field.csv", "run,t_10.000\n1,x\n");
  const std::string b = " --study " + (dir / "broken.toml").string();
  const std::string g = " --study " + (dir / "good.toml").string();
  const std::string o = out.string();
  const std::vector<std::string> commands = {
      "simulate" + b + " --out " + o + "/t.csv",
      "simulate" + b + " --assembly all --out " + o,
      "generate lab" + b + " --out " + o + "/lab.csv",
      "generate field" + b + " --out " + o + "/field.csv",
      "calibrate" + b + " --data " + (dir / "bad_lab.csv").string() + " --out " + o,
      "calibrate" + g + " --data " + (dir / "bad_lab.csv").string() + " --out " + o,
      "coverage" + b + " --out " + o,
      "synthesize" + b + " --calibration " + o + " --out " + o,
      "synthesize" + g + " --calibration " + o + " --out " + o,  // no posterior.csv in out/M1
      "classify" + g + " --field " + (dir / "bad_field.csv").string() + " --synthetic " + o +
          " --out " + o,
      "study --study " + (dir / "broken.toml").string() + " --out " + o,
      "study --study " + (dir / "good.toml").string() + " --lab " + (dir / "bad_lab.csv").string() +
          " --out " + o,
      "study --study " + (dir / "good.toml").string() + " --field " +
          (dir / "bad_field.csv").string() + " --out " + o,
      "compare" + g + " --calibration " + o + "/M1 --data " + (dir / "bad_lab.csv").string() +
          " --out " + o,
      "diagnose" + g + " --data " + (dir / "bad_lab.csv").string() + " --out " + o,
      "report --study-dir " + o + " --out " + o,  // not a study folder
  };
  const auto before = snapshot(dir);
  for (const auto& c : commands) {
    SCOPED_TRACE(c);
    const Result r = twin(c + " --quiet", dir / "..");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_EQ(r.err.find("--help)"), std::string::npos)
        << "an input error, not a command-line one: " << r.err;
    EXPECT_EQ(snapshot(dir), before) << "the folder changed";
  }
}

TEST(BrokenInputs, CommandLinesGetOneLineNamingTheCommand) {
  const fs::path dir = freshDir("broken_cli");
  struct Case {
    std::string args, expect;
  };
  const std::vector<Case> cases = {
      {"simulat", "unknown command 'simulat'"},
      {"simulat", "did you mean 'simulate'"},
      {"generate lb --out x.csv", "generate: unknown command 'lb'"},
      {"--bogus",
       "(see twin --help)"},  // `twin` alone prints the overview (tests/cli/help_examples_test.cpp)
      {"generate", "(see twin generate --help)"},
      {"simulate --bogus --out " + (dir / "o" / "x.csv").string(), "--bogus"},
      {"simulate --out", "--out"},
      {"simulate --seed -3 --out " + (dir / "o" / "x.csv").string(), "--seed: must be an integer"},
      {"simulate --seed 99999999999999999999999 --out " + (dir / "o" / "x.csv").string(),
       "--seed: must be an integer"},
      {"calibrate --seed 1e3 --data x.csv --out " + (dir / "o").string(), "--seed"},
      {"calibrate --threads -1 --data x.csv --out " + (dir / "o").string(),
       "(see twin calibrate --help)"},
      {"simulate --accuracy -1 --out " + (dir / "o" / "x.csv").string(), "--accuracy"},
      {"simulate --max-step 0 --out " + (dir / "o" / "x.csv").string(), "--max-step"},
      {"simulate --output-rate -1000 --out " + (dir / "o" / "x.csv").string(), "--output-rate"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const Result r = twin(c.args, dir);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "o"));
  }
}

}  // namespace
