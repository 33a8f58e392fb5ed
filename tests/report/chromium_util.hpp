#pragma once
// Headless Chromium for the report tests: find it, and load an interactive page with #selftest
// to read what its script wrote into <pre id="selftest"> (report/compare_page.hpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "test_util.hpp"

namespace dtwin_test {

/// Absolute path of `exe` in a folder of $PATH, or "".
inline std::string findOnPath(const std::string& exe) {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(ss, dir, ':');)
    if (!dir.empty() && ::access((std::filesystem::path(dir) / exe).c_str(), X_OK) == 0)
      return (std::filesystem::path(dir) / exe).string();
  return "";
}

/// chromium or chromium-browser on PATH, or "".
inline std::string findChromium() {
  const std::string c = findOnPath("chromium");
  return c.empty() ? findOnPath("chromium-browser") : c;
}

/// The page `html` loaded in headless Chromium with #selftest: the JSON its script wrote into
/// <pre id="selftest"> (a test failure and {} when there is none). `scratch` holds the profile
/// and the dumped DOM.
inline nlohmann::json pageSelftest(const std::string& chromium, const std::filesystem::path& html,
                                   const std::filesystem::path& scratch) {
  std::filesystem::create_directories(scratch);
  const std::filesystem::path dom = scratch / "dom.html", log = scratch / "chromium.log";
  const std::string cmd = chromium +
                          " --headless --no-sandbox --disable-gpu --disable-background-networking "
                          "--window-size=1400,1200"
                          " --user-data-dir=" +
                          (scratch / "profile").string() + " --dump-dom 'file://" +
                          std::filesystem::absolute(html).string() + "#selftest' >" + dom.string() +
                          " 2>" + log.string();
  EXPECT_EQ(std::system(cmd.c_str()), 0) << slurp(log);
  const std::string text = slurp(dom);
  const auto a = text.find("<pre id=\"selftest\">"), b = text.find("</pre>", a);
  if (a == std::string::npos || b == std::string::npos) {
    ADD_FAILURE() << "no selftest output in the DOM; chromium said: " << slurp(log);
    return {};
  }
  const std::string body = text.substr(a + 19, b - a - 19);
  return nlohmann::json::parse(body.empty() ? "{}" : body);
}

}  // namespace dtwin_test
