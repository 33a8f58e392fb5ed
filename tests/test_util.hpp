#pragma once
// Small helpers shared by the tests that drive files and the `twin` CLI.
#include <sys/wait.h>
#include <filesystem>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

namespace dtwin_test {

/// The bytes of a file ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// What a run of the `twin` program gave: its exit code, standard error and standard output.
struct TwinRun {
  int code;
  std::string err, out;
};

/// Runs `twin ARGS` (DTWIN_TWIN_EXE), its standard output and error captured in DIR/out.txt and
/// DIR/err.txt; DIR defaults to the process's own temporary folder (tests/test_main.cpp).
inline TwinRun runTwin(const std::string& args,
                       const std::filesystem::path& dir = std::filesystem::temp_directory_path()) {
  const std::string out = (dir / "out.txt").string(), err = (dir / "err.txt").string();
  const std::string cmd = std::string(DTWIN_TWIN_EXE) + " " + args + " > " + out + " 2> " + err;
  const int st = std::system(cmd.c_str());
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, slurp(err), slurp(out)};
}

/// An empty folder `name` in the test's temporary folder (removed first if it exists).
inline std::filesystem::path freshDir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

/// Writes `text` to `p` as is (binary).
inline void writeText(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

/// Writes data/studies/demo.toml to `path` with its [sizes] table replaced by `sizes` (the text
/// of the table's lines, and anything that should follow it) and the vehicle file made absolute.
inline std::filesystem::path writeDemoStudy(const std::filesystem::path& path,
                                            const std::string& sizes) {
  namespace fs = std::filesystem;
  std::string s = slurp(fs::path(DTWIN_SOURCE_DIR) / "data" / "studies" / "demo.toml");
  s = std::regex_replace(
      s, std::regex("vehicle = \"[^\"]*\""),
      "vehicle = \"" +
          (fs::path(DTWIN_SOURCE_DIR) / "data" / "vehicle" / "midsize_sedan.toml").string() + "\"");
  s = s.substr(0, s.find("[sizes]")) + "[sizes]\n" + sizes;
  std::ofstream(path) << s;
  return path;
}

/// The tiny two-assembly study (M3 generates the data) the study-level tests run.
inline std::filesystem::path writeTinyStudy(const std::filesystem::path& path,
                                            int optimizer_starts = 1) {
  writeDemoStudy(path,
                 "lab_repetitions = 3\nfield_runs = 4\nlhs_points = 10\ngibbs_iterations = "
                 "300\ngibbs_burn_in = 100\n"
                 "posterior_draws = 4\nroads_per_draw = 2\nroad_library = 8\noptimizer_starts = " +
                     std::to_string(optimizer_starts) +
                     "\n\n[assemblies]\ninclude = [\"M3\", \"M4\"]\n");
  // Two design rounds (the demo's [calibration] table asks for three) and no ridge traces:
  // these tests check files, resumption and determinism, not the intervals (docs/calibration.md
  // and tests/calibration check those), and the traces are most of a calibration's simulations.
  std::string s = slurp(path);
  s = std::regex_replace(s, std::regex("\nmax_rounds = [0-9]+"),
                         "\nmax_rounds = 2\nridge_steps = 0");
  std::ofstream(path) << s;
  return path;
}

/// The calibrated parameters' truths of a study, in study order.
/// (A template so this header needs no twin/ include: StudyT is dtwin::Study.)
template <class StudyT>
std::vector<double> truthOf(const StudyT& s) {
  std::vector<double> t;
  for (const auto& c : s.calibrated) t.push_back(*c.truth);
  return t;
}

}  // namespace dtwin_test
