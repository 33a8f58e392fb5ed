#pragma once
// What the time-road tests share: pi, and the one-line error of parsing a time road's text.
#include <string>

#include "common/errors.hpp"
#include "subsystems/time_road.hpp"

namespace dtwin_test {

constexpr double kPi = 3.14159265358979323846;

/// The InputError's text of parsing `text` as road.csv, "" when it parses.
inline std::string timeRoadError(const std::string& text) {
  try {
    dtwin::parseTimeRoadCsv(text, "road.csv");
  } catch (const dtwin::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace dtwin_test
