// Fuzz harness: `twin import` (io/log_import.hpp) on a logger's CSV. The first byte picks one of
// two mappings (seconds with two road-height tracks; clock times with a road velocity and a
// preamble); the rest is the log. An accepted log is written and its study read back, as the
// command does, so the road and speed files it makes are read too.
#include <filesystem>
#include <string>

#include "io/log_import.hpp"
#include "tests/fuzz/fuzz_common.hpp"

namespace {

const char* kSeconds = R"([import]
time = { column = "Time", unit = "s" }
speed = { column = "Speed", unit = "km/h" }
speed_lowpass_hz = 2.0
road_left = { column = "L", unit = "mm" }
road_right = { column = "R", unit = "mm" }
max_dropout_rows = 2

[[import.channels]]
column = "Acc"
channel = "seat_mps2"
unit = "g"
offset = 1.0

[sensors.seat]
position_m = [0.9, -0.4, 0.3]
quantity = "acceleration_z"
filter = { order = 2, cutoff_hz = 30.0 }
noise_sd = 0.03
)";

const char* kClock = R"([import]
time = { column = "Stamp", unit = "clock" }
speed = { column = "V", unit = "m/s" }
road = { column = "W", unit = "mm/s" }
highpass_hz = 0.2
separator = ";"
decimal_comma = true
header_line = 2
skip_rows = 1

[[import.channels]]
column = "Az"
channel = "chassis_heave_acc_mps2"
unit = "m/s^2"
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace dtwin::fuzz;
  if (size == 0) return 0;
  static const dtwin::ImportMapping mappings[2] = {
      [] {
        writeBytes(scratch() / "seconds.toml", reinterpret_cast<const uint8_t*>(kSeconds),
                   std::char_traits<char>::length(kSeconds));
        return dtwin::readImportMapping((scratch() / "seconds.toml").string());
      }(),
      [] {
        writeBytes(scratch() / "clock.toml", reinterpret_cast<const uint8_t*>(kClock),
                   std::char_traits<char>::length(kClock));
        return dtwin::readImportMapping((scratch() / "clock.toml").string());
      }()};
  static const std::string study = (sourceDir() / "data" / "studies" / "demo.toml").string();
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::filesystem::path out = scratch() / "drive";
  std::filesystem::remove_all(out);
  guarded([&] {
    const auto r = dtwin::importLog(text, "log.csv", mappings[data[0] & 1], study, "drive");
    dtwin::writeImport(r, out.string());
  });
  return 0;
}
