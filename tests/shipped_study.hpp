#pragma once
// The studies shipped in data/studies/, each read once per test process.
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "twin/study.hpp"

namespace dtwin_test {

/// data/studies/<name>.toml ("paper", "demo"), loaded on first use.
inline const dtwin::Study& shippedStudy(const std::string& name) {
  static std::mutex m;
  static std::map<std::string, std::unique_ptr<const dtwin::Study>> loaded;
  std::lock_guard<std::mutex> lock(m);
  auto& s = loaded[name];
  if (!s) s = std::make_unique<const dtwin::Study>(dtwin::loadStudy(std::string(DTWIN_SOURCE_DIR) + "/data/studies/" + name + ".toml"));
  return *s;
}

}  // namespace dtwin_test
