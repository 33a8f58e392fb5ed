#include "report/svg_plot.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"
#include "report/study_report.hpp"

namespace fs = std::filesystem;

namespace dtwin::report {
namespace {

std::string slurp(const fs::path& p) { return readTextFile(p.string()); }

std::string shq(const std::string& s) {
  std::string r = "'";
  for (char c : s) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return r + "'";
}

/// Drops the XML prolog and gnuplot's own title/desc, prefixes every id (several SVGs share a
/// page: ids must be unique) and names the figure.
std::string clean(std::string s, const std::string& prefix, const std::string& title) {
  const auto start = s.find("<svg");
  if (start == std::string::npos)
    throw std::runtime_error("gnuplot wrote no <svg> element for plot '" + title + "'");
  s = s.substr(start);
  s = std::regex_replace(s, std::regex("<desc>[^<]*</desc>\\s*"), "");
  const auto t = s.find("<title>");
  const auto te = s.find("</title>", t == std::string::npos ? 0 : t);
  if (t != std::string::npos && te != std::string::npos)
    s.replace(t, te + 8 - t, "<title>" + htmlEscape(title) + "</title>");
  std::set<std::string> ids;
  const std::regex id_re("\\bid=(['\"])([^'\"]+)\\1");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), id_re); it != std::sregex_iterator();
       ++it)
    ids.insert((*it)[2]);
  for (const auto& id : ids) {
    for (const char* q : {"'", "\""}) {
      const std::string qs(q);
      for (const std::string& pre : {std::string("id=") + qs, qs + "#"}) {
        const std::string from = pre + id + qs, to = pre + prefix + id + qs;
        for (std::size_t pos = 0; (pos = s.find(from, pos)) != std::string::npos; pos += to.size())
          s.replace(pos, from.size(), to);
      }
    }
    const std::string from = "url(#" + id + ")", to = "url(#" + prefix + id + ")";
    for (std::size_t pos = 0; (pos = s.find(from, pos)) != std::string::npos; pos += to.size())
      s.replace(pos, from.size(), to);
  }
  s.insert(4, " class=\"plot\" role=\"img\" aria-label=\"" + htmlEscape(title) + "\"");
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

const char* kCss =
    R"(body{font-family:sans-serif;margin:0 auto;max-width:1100px;padding:1em 2em;color:#222;background:#fff;line-height:1.4}
h1{font-size:1.6em;border-bottom:2px solid #446;padding-bottom:.2em}
h2{font-size:1.3em;margin-top:2em;border-bottom:1px solid #bbb}
h3{font-size:1.1em;margin-top:1.5em}
table{border-collapse:collapse;margin:.5em 0 1em 0;font-size:.9em}
th,td{border:1px solid #ccc;padding:.2em .6em;text-align:left;vertical-align:top}
th{background:#eef}
td.n{text-align:right;font-variant-numeric:tabular-nums}
figure{margin:1em 0}
figcaption{font-size:.9em;color:#444;max-width:900px}
svg.plot{width:100%;max-width:900px;height:auto;display:block}
.rec{font-weight:bold;background:#efe;border:1px solid #9c9;padding:.5em 1em}
.warn{background:#fee;border:1px solid #c99;padding:.5em 1em}
code{font-size:.95em;word-break:break-all})";

}  // namespace

std::string findOnPath(const std::string& exe) {
  const char* path = std::getenv("PATH");
  for (const auto& dir : splitOn(path ? path : "/usr/bin:/bin", ':')) {
    if (dir.empty()) continue;
    const fs::path p = fs::path(dir) / exe;
    if (::access(p.c_str(), X_OK) == 0 && !fs::is_directory(p)) return p.string();
  }
  return "";
}

std::string requireGnuplot(const std::string& who) {
  std::string exe = findOnPath("gnuplot");
  if (exe.empty())
    throw InputError("gnuplot",
                     "not found on PATH; " + who +
                         " draws its plots with it: install the Debian package gnuplot-nox "
                         "(apt-get install gnuplot-nox)");
  return exe;
}

std::string gnuplotQuote(const std::string& s) {
  std::string r = "'";
  for (char c : s) {
    if (c == '\'')
      r += "''";
    else if (c == '\n' || c == '\r')
      r += ' ';
    else
      r += c;
  }
  return r + "'";
}

std::string plotNumber(double v) { return formatPrintf("%.17g", v); }

const char* reportCss() { return kCss; }

GnuplotSvg::GnuplotSvg(std::string exe, std::string id_prefix)
    : exe_(std::move(exe)), prefix_(std::move(id_prefix)) {
  std::string templ = (fs::temp_directory_path() / "dtwin_report_XXXXXX").string();
  if (!::mkdtemp(templ.data())) throw InputError(templ, "cannot create a temporary folder");
  dir_ = templ;
}

GnuplotSvg::~GnuplotSvg() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

std::string GnuplotSvg::data(const std::string& content) {
  const fs::path p = fs::path(dir_) / ("data" + std::to_string(++files_) + ".dat");
  std::ofstream(p, std::ios::binary) << content;
  return gnuplotQuote(p.string());
}

std::string GnuplotSvg::plot(const std::string& body, int width, int height,
                             const std::string& title) {
  const int n = ++plots_;
  const fs::path dir(dir_);
  const fs::path svg = dir / ("plot" + std::to_string(n) + ".svg");
  const fs::path script = dir / ("plot" + std::to_string(n) + ".gp");
  const fs::path err = dir / ("plot" + std::to_string(n) + ".err");
  std::ofstream(script, std::ios::binary)
      << "set encoding utf8\n"
      << "set terminal svg size " << width << "," << height
      << " dynamic enhanced font 'sans,10' background rgb 'white'\n"
      << "set output " << gnuplotQuote(svg.string()) << "\n"
      << body << "\nunset multiplot\nunset output\n";
  const std::string cmd =
      shq(exe_) + " " + shq(script.string()) + " >" + shq(err.string()) + " 2>&1";
  const int rc = std::system(cmd.c_str());
  std::string messages = fs::exists(err) ? slurp(err) : "";
  while (!messages.empty() && (messages.back() == '\n' || messages.back() == ' '))
    messages.pop_back();
  if (rc != 0 || !fs::exists(svg) || fs::file_size(svg) == 0) {
    std::string first = messages.substr(0, 400);
    std::replace(first.begin(), first.end(), '\n', ' ');
    throw std::runtime_error("gnuplot failed on plot '" + title + "' (exit " + std::to_string(rc) +
                             "): " + first);
  }
  if (!messages.empty()) warnings_.push_back("gnuplot, plot '" + title + "': " + messages);
  return clean(slurp(svg), prefix_ + std::to_string(n) + "_", title);
}

}  // namespace dtwin::report
