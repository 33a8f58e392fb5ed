#pragma once
// The studies shipped in data/studies/, each read once per test process, and a scenario at rest.
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "io/study.hpp"

namespace dtwin_test {

/// data/studies/<name>.toml ("paper", "demo"), loaded on first use.
inline const dtwin::Study& shippedStudy(const std::string& name) {
  static std::mutex m;
  static std::map<std::string, std::unique_ptr<const dtwin::Study>> loaded;
  std::lock_guard<std::mutex> lock(m);
  auto& s = loaded[name];
  if (!s)
    s = std::make_unique<const dtwin::Study>(
        dtwin::loadStudy(std::string(DTWIN_SOURCE_DIR) + "/data/studies/" + name + ".toml"));
  return *s;
}

/// A scenario at rest on the flat road for `duration` s (the static closed forms' scenario).
inline dtwin::ScenarioSpec standstill(double duration) {
  dtwin::ScenarioSpec s;
  s.name = "standstill";
  s.duration_s = duration;
  s.speed.v_final_mps = 0.0;
  return s;
}

}  // namespace dtwin_test
