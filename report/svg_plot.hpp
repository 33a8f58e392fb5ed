#pragma once
// Inline-SVG plots for self-contained HTML reports (`twin report`, docs/classification.md): gnuplot
// (Debian package gnuplot-nox) runs as one subprocess per plot with the svg terminal, data reach it
// through files in a private temporary folder, and the SVG it writes is cleaned for inlining (XML
// prolog and gnuplot's <desc> dropped, <title> set, every id prefixed so that several plots, and
// several plotters, can share one page). Used by report/study_report.cpp and
// report/diagnosis_report.cpp.
//
//   const std::string exe = requireGnuplot("`twin report`");   // InputError naming gnuplot-nox
//   GnuplotSvg gp(exe);
//   const std::string f = gp.data("0 1\n1 2\n");                 // a gnuplot string: the file
//   std::string svg = gp.plot("plot " + f + " using 1:2 with lines notitle", 900, 400, "my plot");
#include <string>
#include <vector>

namespace dtwin::report {

/// Absolute path of the executable `exe` in a folder of $PATH (/usr/bin:/bin if unset), or "".
std::string findOnPath(const std::string& exe);

/// gnuplot on PATH, or InputError("gnuplot", "... install the Debian package gnuplot-nox ...");
/// `who` names what needs it in the message (e.g. "`twin report`").
std::string requireGnuplot(const std::string& who);

/// `s` as a gnuplot single-quoted string ('' stands for one quote; newlines become spaces).
std::string gnuplotQuote(const std::string& s);

/// `v` with 17 significant digits (round-trips a double), for gnuplot data files and commands.
std::string plotNumber(double v);

/// The style sheet of the reports (inline <style> content): same look for every twin page.
const char* reportCss();

/// Runs gnuplot on scripts and returns its SVG output, ready to inline. Not thread-safe.
class GnuplotSvg {
 public:
  /// `exe`: the gnuplot executable (requireGnuplot). `id_prefix`: plot n's SVG ids become
  /// "<id_prefix><n>_<id>"; plotters whose plots share a page need distinct prefixes.
  explicit GnuplotSvg(std::string exe, std::string id_prefix = "p");
  ~GnuplotSvg();
  GnuplotSvg(const GnuplotSvg&) = delete;
  GnuplotSvg& operator=(const GnuplotSvg&) = delete;

  /// Writes a data file into the temporary folder; returns its path as a gnuplot string.
  std::string data(const std::string& content);

  /// Draws `body` (gnuplot commands, after `set terminal svg size W,H dynamic enhanced` and
  /// `set output`) and returns the <svg> element with class="plot", role="img" and aria-label /
  /// <title> set to `title`. Throws std::runtime_error with gnuplot's first messages when gnuplot
  /// fails or writes no SVG; anything gnuplot printed on success goes to warnings().
  std::string plot(const std::string& body, int width, int height, const std::string& title);

  /// Plots drawn so far.
  int count() const { return plots_; }
  /// gnuplot messages of successful plots ("gnuplot, plot '<title>': ...").
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  std::string exe_, prefix_, dir_;
  int files_ = 0, plots_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace dtwin::report
