// Private to io/ (not installed): the units a logger's columns may give, each with its SI unit and
// factor, shared by the column map reader (import_mapping.cpp) and the import (log_import.cpp).
#pragma once

#include <string>
#include <utility>

#include "common/statistics.hpp"

namespace dtwin {

struct Unit {
  const char* name;
  const char* si;
  double factor;
};
// Every unit a log may give, with the SI unit it converts to.
const Unit kUnits[] = {
    {"s", "s", 1.0},           {"ms", "s", 1e-3},          {"us", "s", 1e-6},         {"ns", "s", 1e-9},
    {"clock", "s", 1.0},  // HH:MM:SS[.fff], optionally after a date (parseClockTime)
    {"m/s", "m/s", 1.0},       {"mps", "m/s", 1.0},        {"km/h", "m/s", 1.0 / 3.6}, {"kmh", "m/s", 1.0 / 3.6},
    {"kph", "m/s", 1.0 / 3.6}, {"mph", "m/s", 0.44704},    {"kn", "m/s", 1852.0 / 3600.0}, {"ft/s", "m/s", 0.3048},
    {"mm/s", "m/s", 1e-3},
    {"m", "m", 1.0},           {"mm", "m", 1e-3},          {"cm", "m", 1e-2},         {"in", "m", 0.0254},
    {"m/s^2", "m/s^2", 1.0},   {"m/s2", "m/s^2", 1.0},     {"mps2", "m/s^2", 1.0},    {"g", "m/s^2", 9.80665},
    {"ft/s^2", "m/s^2", 0.3048},
    {"N", "N", 1.0},           {"kN", "N", 1e3},
    {"rad", "rad", 1.0},       {"deg", "rad", kPi / 180.0},
    {"rad/s^2", "rad/s^2", 1.0}, {"deg/s^2", "rad/s^2", kPi / 180.0},
    {"rad/s", "rad/s", 1.0},   {"deg/s", "rad/s", kPi / 180.0},
};

/// A mask's unit: its factor to SI and the SI unit (import_mapping.cpp).
std::pair<double, std::string> anyUnit(const std::string& unit, const std::string& where);

}  // namespace dtwin
