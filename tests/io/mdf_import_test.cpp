// `twin import` of MF4 logs. The demonstration drive (data/drives/stop_and_go.csv) is written into
// MF4 files by mdflib's writer (writeMdfLog, io/mdf_log.hpp): once plain, once with its data in DZ
// blocks, once split into two channel groups on two time bases. Each imports to the CSV import's
// files bit for bit (the resampled channel: to the interpolation rule's closed form). The file's
// conversions are applied, its units checked, and every bad file is one line, exit code 2, nothing
// written. A second writer, independent of mdflib (tests/io/write_mf4.py, Python's standard library
// only), writes the DZ forms mdflib's writer does not: transposition + deflate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "io/log_import.hpp"
#include "io/mdf_log.hpp"
#include "test_util.hpp"

using namespace dtwin;
namespace fs = std::filesystem;

namespace {

const std::string kDrives = std::string(DTWIN_SOURCE_DIR) + "/data/drives/";

/// The demonstration drive's columns as the CSV gives them (strtod: the nearest double, as the
/// CSV import reads them; an empty cell is NaN).
struct DemoLog {
  std::vector<std::string> names;
  std::vector<std::vector<double>> cols;  ///< cols[0]: Time
};

DemoLog readDemoCsv() {
  DemoLog d;
  std::istringstream in(dtwin_test::slurp(kDrives + "stop_and_go.csv"));
  std::string line;
  std::getline(in, line);
  std::stringstream hs(line);
  for (std::string f; std::getline(hs, f, ',');) d.names.push_back(f);
  d.cols.resize(d.names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::size_t b = 0;
    for (std::size_t k = 0; k < d.names.size(); ++k) {
      const std::size_t e = std::min(line.find(',', b), line.size());
      const std::string cell = line.substr(b, e - b);
      d.cols[k].push_back(cell.empty() ? std::numeric_limits<double>::quiet_NaN()
                                       : std::strtod(cell.c_str(), nullptr));
      b = e + 1;
    }
  }
  return d;
}

const char* kUnitsOfDemo[] = {"s", "km/h", "mm", "mm", "g", "degC"};

/// The drive as one channel group "log", or split: "chassis" (the accelerometer and the road, every
/// sample) and "gps" (the speed, every other sample and the last).
std::vector<MdfWriteGroup> demoGroups(const DemoLog& d, bool split) {
  MdfWriteGroup all{"log", "Time", "s", d.cols[0], {}};
  for (std::size_t k = 1; k < d.names.size(); ++k)
    all.channels.push_back({d.names[k], kUnitsOfDemo[k], d.cols[k], {}});
  if (!split) return {all};
  MdfWriteGroup chassis{"chassis", "Time", "s", d.cols[0], {}}, gps{"gps", "Time", "s", {}, {}};
  gps.channels.push_back({"GPS_Speed", "km/h", {}, {}});
  for (std::size_t i = 0; i < d.cols[0].size(); ++i)
    if (i % 2 == 0 || i + 1 == d.cols[0].size()) {
      gps.time.push_back(d.cols[0][i]);
      gps.channels[0].values.push_back(d.cols[1][i]);
    }
  for (const auto& c : all.channels)
    if (c.name != "GPS_Speed") chassis.channels.push_back(c);
  return {chassis, gps};
}

/// The study's text without its first comment lines (they name the log).
std::string studyBody(const fs::path& p) {
  const std::string s = dtwin_test::slurp(p);
  return s.substr(s.find("\n[") + 1);
}

std::string importArgs(const std::string& log, const std::string& map, const fs::path& out) {
  return "import --log " + log + " --map " + map + " --quiet --out " + out.string();
}

/// Imports the CSV once per process (the reference every MF4 import is held to).
const fs::path& csvImport() {
  static const fs::path out = [] {
    const fs::path dir = dtwin_test::freshDir("mdf_csv_ref");
    const auto r = dtwin_test::runTwin(
        importArgs(kDrives + "stop_and_go.csv", kDrives + "stop_and_go_map.toml", dir / "drive"),
        dir);
    EXPECT_EQ(r.code, 0) << r.err;
    return dir / "drive";
  }();
  return out;
}

void expectSameFiles(const fs::path& a, const fs::path& b, bool speed_too = true) {
  for (const char* f : {"measurements.csv", "road.csv", "speed.csv"}) {
    if (!speed_too && std::string(f) == "speed.csv") continue;
    SCOPED_TRACE(f);
    const std::string x = dtwin_test::slurp(a / f), y = dtwin_test::slurp(b / f);
    EXPECT_FALSE(x.empty());
    EXPECT_TRUE(x == y) << f << " differs";
  }
  EXPECT_EQ(studyBody(a / "study.toml"), studyBody(b / "study.toml"));
}

}  // namespace

// The drive in one channel group, plain and in DZ blocks: the same files as the CSV's import, and
// the sidecar names the MF4 file's hash, its groups and channels.
TEST(MdfImport, TheDemonstrationDriveImportsAsItsCsvDoes) {
  const DemoLog d = readDemoCsv();
  for (bool compress : {false, true}) {
    SCOPED_TRACE(compress ? "DZ" : "DT");
    const fs::path dir = dtwin_test::freshDir(compress ? "mdf_demo_dz" : "mdf_demo_dt");
    const std::string log = (dir / "drive.mf4").string();
    writeMdfLog(log, demoGroups(d, false), compress);
    const std::string bytes = dtwin_test::slurp(log);
    ASSERT_EQ(bytes.compare(0, 8, "MDF     "), 0);
    EXPECT_EQ(bytes.find("##DZ") != std::string::npos, compress)
        << "DZ blocks when compressed, none otherwise";
    EXPECT_LT(bytes.size(), compress ? 250000u : 400000u);
    const auto r =
        dtwin_test::runTwin(importArgs(log, kDrives + "stop_and_go_map.toml", dir / "drive"), dir);
    ASSERT_EQ(r.code, 0) << r.err;
    expectSameFiles(csvImport(), dir / "drive");
    const auto side = nlohmann::json::parse(dtwin_test::slurp(dir / "drive" / "measurements.json"));
    const auto& src = side.at("source");
    EXPECT_EQ(src.at("file"), log);
    EXPECT_EQ(src.at("rows"), 6001);
    EXPECT_EQ(src.at("mdf").at("groups_read").size(), 1u);
    EXPECT_EQ(src.at("mdf").at("groups_read")[0].at("group"), "log");
    EXPECT_EQ(src.at("mdf").at("groups_read")[0].at("channels").size(),
              4u);  // speed, two roads, seat: not the cabin's temperature
    EXPECT_EQ(src.at("mdf").at("samples_outside_other_groups"), 0);
    EXPECT_EQ(side.at("dropped_cells"),
              6);  // the accelerometer's NaN samples, as the CSV's empty cells
  }
}

// Two channel groups on two time bases: every channel is read on the time base of the time
// channel's group (here the accelerometer's, the first mapped channel's), the GPS speed of the
// other group interpolated onto it: its own sample where the times meet, the straight line between
// its two neighbours elsewhere. The measurements and the road are the CSV's bit for bit.
TEST(MdfImport, TwoTimeBasesResampleOntoTheTimeChannelsGroup) {
  const DemoLog d = readDemoCsv();
  const fs::path dir = dtwin_test::freshDir("mdf_split");
  const std::string log = (dir / "drive.mf4").string();
  writeMdfLog(log, demoGroups(d, true), true);
  // Without the speed's low-pass, so the speed trace shows the interpolation itself.
  std::string map = dtwin_test::slurp(kDrives + "stop_and_go_map.toml");
  map.replace(map.find("speed_lowpass_hz"), 3, "#sp");
  dtwin_test::writeText(dir / "map.toml", map);
  auto r = dtwin_test::runTwin(importArgs(log, (dir / "map.toml").string(), dir / "drive"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  r = dtwin_test::runTwin(
      importArgs(kDrives + "stop_and_go.csv", (dir / "map.toml").string(), dir / "csv"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  expectSameFiles(dir / "csv", dir / "drive", /*speed_too=*/false);
  std::istringstream speed(dtwin_test::slurp(dir / "drive" / "speed.csv"));
  std::string line;
  std::getline(speed, line);
  const auto& t = d.cols[0];
  const auto& v = d.cols[1];
  std::size_t i = 0, exact = 0;
  for (; std::getline(speed, line); ++i) {
    const double got = std::stod(line.substr(line.find(',') + 1));
    double want_kmh = v[i];
    if (i % 2 == 1 && i + 1 < t.size()) {
      const double w = (t[i] - t[i - 1]) / (t[i + 1] - t[i - 1]);
      want_kmh = v[i - 1] + (v[i + 1] - v[i - 1]) * w;
    } else {
      ++exact;
    }
    ASSERT_NEAR(got, want_kmh / 3.6, 1e-12) << "row " << i;
  }
  EXPECT_EQ(i, t.size());
  EXPECT_EQ(exact, t.size() / 2 + 1);
  const auto side = nlohmann::json::parse(dtwin_test::slurp(dir / "drive" / "measurements.json"));
  EXPECT_EQ(side.at("source").at("mdf").at("groups_read").size(), 2u);
  EXPECT_EQ(side.at("source").at("mdf").at("time_base").at("group"), "chassis");
  // The speed's group as the time base (GROUP/NAME): the chassis channels are interpolated onto
  // the GPS times instead, and no sample lies outside the other group's span.
  map.replace(map.find("column = \"Time\""), 15, "column = \"gps/Time\"");
  dtwin_test::writeText(dir / "map_gps.toml", map);
  r = dtwin_test::runTwin(importArgs(log, (dir / "map_gps.toml").string(), dir / "gps"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto gside = nlohmann::json::parse(dtwin_test::slurp(dir / "gps" / "measurements.json"));
  EXPECT_EQ(gside.at("source").at("rows"), static_cast<long>(t.size() / 2 + 1));
  EXPECT_EQ(gside.at("source").at("mdf").at("time_base").at("group"), "gps");
}

// Conversions in the file are applied (linear, rational) before the mapping's unit, offset and
// scale; a channel with a value-to-text conversion cannot be mapped.
TEST(MdfImport, TheFilesConversionsAreApplied) {
  const fs::path dir = dtwin_test::freshDir("mdf_conv");
  MdfWriteGroup g{"log", "Time", "s", {}, {}};
  std::vector<double> raw_v, raw_a, raw_state;
  for (int k = 0; k < 200; ++k) {
    g.time.push_back(0.01 * k);
    raw_v.push_back(1000 + k);   // speed: 0.01 km/h per bit, from 0 at 0
    raw_a.push_back(k % 7);      // accelerometer: (2x + 1) / (x + 4) m/s^2, a rational
    raw_state.push_back(k % 2);  // a state as text
  }
  MdfWriteConversion lin{"linear", {0.0, 0.01, 0, 0, 0, 0}, {}};
  MdfWriteConversion rat{"rational", {0.0, 2.0, 1.0, 0.0, 1.0, 4.0}, {}};
  MdfWriteConversion txt{"value_to_text", {0.0, 1.0, 0, 0, 0, 0}, {"off", "on"}};
  g.channels.push_back({"v", "km/h", raw_v, lin});
  g.channels.push_back({"az", "m/s^2", raw_a, rat});
  g.channels.push_back({"state", "", raw_state, txt});
  const std::string log = (dir / "conv.mf4").string();
  writeMdfLog(log, {g}, false);
  const std::string args =
      "import --log " + log +
      " --time Time:s --speed v:km/h --channel az:chassis_heave_acc_mps2:m/s^2 --quiet --out ";
  auto r = dtwin_test::runTwin(args + (dir / "out").string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream speed(dtwin_test::slurp(dir / "out" / "speed.csv"));
  std::string line;
  std::getline(speed, line);
  for (int k = 0; std::getline(speed, line); ++k)
    ASSERT_NEAR(std::stod(line.substr(line.find(',') + 1)), (1000 + k) * 0.01 / 3.6, 1e-12) << line;
  std::istringstream meas(dtwin_test::slurp(dir / "out" / "measurements.csv"));
  std::getline(meas, line);
  int rows = 0;
  for (; std::getline(meas, line); ++rows) {
    const double x = static_cast<double>(rows % 7);
    ASSERT_NEAR(std::stod(line.substr(line.rfind(',') + 1)), (2 * x + 1) / (x + 4), 1e-12) << line;
  }
  EXPECT_EQ(rows, 200);
  r = dtwin_test::runTwin("import --log " + log +
                              " --time Time:s --speed v:km/h --channel "
                              "state:chassis_heave_acc_mps2:m/s^2 --quiet --out " +
                              (dir / "text").string(),
                          dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(
      r.err.find("channel 'state' (group 'log'): its values are text (a value-to-text conversion)"),
      std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "text"));
}

// A bad file is one line naming the file, where in it and the rule, exit code 2, and nothing is
// written: a truncated file, a mapped channel it lacks (the near names given), a unit that does
// not fit, a channel two groups share, a file that is not MDF.
TEST(MdfImport, BadFilesGiveOneLineErrorsAndWriteNothing) {
  const DemoLog d = readDemoCsv();
  const fs::path dir = dtwin_test::freshDir("mdf_bad");
  const fs::path good = dir / "good.mf4", good_dz = dir / "good_dz.mf4", split = dir / "split.mf4";
  writeMdfLog(good.string(), demoGroups(d, false), false);
  writeMdfLog(good_dz.string(), demoGroups(d, false), true);
  writeMdfLog(split.string(), demoGroups(d, true), false);
  const std::string bytes = dtwin_test::slurp(good), bytes_dz = dtwin_test::slurp(good_dz);
  const std::string map = kDrives + "stop_and_go_map.toml";
  std::string m = dtwin_test::slurp(map);
  m.replace(m.find("\"AccZ_Seat\""), 11, "\"AccZ_Seet\"");
  dtwin_test::writeText(dir / "missing.toml", m);
  m = dtwin_test::slurp(map);
  m.replace(m.find("unit = \"km/h\""), 13, "unit = \"mph\"");
  dtwin_test::writeText(dir / "unit.toml", m);
  m = dtwin_test::slurp(map);
  m.replace(m.find("column = \"Road_L\""), 17, "column = \"Time\"");
  dtwin_test::writeText(dir / "shared.toml", m);
  struct Case {
    std::string name, bytes, map, expect;
  };
  const std::vector<Case> cases = {
      {"cut_in_data", bytes.substr(0, bytes.size() * 2 / 3), map, "truncated or damaged"},
      {"cut_in_dz", bytes_dz.substr(0, bytes_dz.size() / 2), map, "truncated or damaged"},
      {"cut_in_header", bytes.substr(0, 100), map, "truncated or damaged"},
      {"cut_in_id", bytes.substr(0, 20), map, "is not an MDF file"},
      {"cut_before_data", bytes.substr(0, bytes.find("##DT") + 30), map, "block ##DT at 0x"},
      {"missing_channel", bytes, (dir / "missing.toml").string(),
       "no channel 'AccZ_Seet' (" + (dir / "missing.toml").string() + ":"},
      {"unit", bytes, (dir / "unit.toml").string(),
       "channel 'GPS_Speed' (group 'log'): the file gives its unit as 'km/h', the mapping declares "
       "'mph'"},
      {"shared", dtwin_test::slurp(split), (dir / "shared.toml").string(),
       "channel 'Time' (" + (dir / "shared.toml").string() +
           ":6: import.road_left) is in group 'chassis', group 'gps': name one as GROUP/Time"},
      {"not_mdf", dtwin_test::slurp(kDrives + "stop_and_go.csv"), map, "is not an MDF file"},
      // Two files the fuzzer made: records of 0 bytes (a reader would never move on) and a DZ block
      // that claims more data than deflate can pack into its bytes (a reader would reserve it).
      {"zero_size_records",
       dtwin_test::slurp(fs::path(DTWIN_SOURCE_DIR) /
                         "tests/fuzz/seeds/mf4_import/zero_size_records.mf4"),
       map, "declares records of 0 bytes"},
      {"dz_size_too_large",
       dtwin_test::slurp(fs::path(DTWIN_SOURCE_DIR) /
                         "tests/fuzz/seeds/mf4_import/dz_size_too_large.mf4"),
       map, "block ##DZ at 0x690: declares 26177172834095008 bytes from 1270 compressed ones"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path log = dir / (c.name + ".mf4");
    dtwin_test::writeText(log, c.bytes);
    const fs::path out = dir / ("out_" + c.name);
    const auto r = dtwin_test::runTwin(
        "import --log " + log.string() + " --map " + c.map + " --out " + out.string(), dir);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("twin: error: " + log.string() + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(dir / ("out_" + c.name + ".import-tmp")));
  }
  // The near names of a missing channel.
  const auto r =
      dtwin_test::runTwin("import --log " + good.string() + " --map " +
                              (dir / "missing.toml").string() + " --out " + (dir / "o").string(),
                          dir);
  EXPECT_NE(r.err.find("near: 'AccZ_Seat'"), std::string::npos) << r.err;
}

// The files of a second writer, independent of mdflib (tests/io/write_mf4.py): records in a DT
// block, or in two DZ blocks under a DL and an HL block, deflated or transposed and deflated, in
// one data group or in two with their own masters. Each imports as the CSV does.
TEST(MdfImport, AnIndependentWritersFilesImportAsTheCsvDoes) {
  if (std::system("python3 -c 'import zlib' > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3 is not installed";
  const fs::path dir = dtwin_test::freshDir("mdf_python");
  const std::string script = std::string(DTWIN_SOURCE_DIR) + "/tests/io/write_mf4.py";
  const std::string units =
      " --units GPS_Speed=km/h,Road_L=mm,Road_R=mm,AccZ_Seat=g,Cabin_Temp=degC";
  std::string map = dtwin_test::slurp(kDrives + "stop_and_go_map.toml");
  map.replace(map.find("speed_lowpass_hz"), 3, "#sp");
  dtwin_test::writeText(dir / "map.toml", map);
  auto r = dtwin_test::runTwin(
      importArgs(kDrives + "stop_and_go.csv", (dir / "map.toml").string(), dir / "csv_nolp"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const std::string data : {"dt", "deflate", "transposed"}) {
    SCOPED_TRACE(data);
    const fs::path log = dir / (data + ".mf4");
    ASSERT_EQ(std::system(("python3 " + script + " " + kDrives + "stop_and_go.csv " + log.string() +
                           " --data " + data + units)
                              .c_str()),
              0);
    r = dtwin_test::runTwin(importArgs(log.string(), kDrives + "stop_and_go_map.toml", dir / data),
                            dir);
    ASSERT_EQ(r.code, 0) << r.err;
    expectSameFiles(csvImport(), dir / data);
    if (data == "dt") continue;
    const std::string bytes = dtwin_test::slurp(log);
    EXPECT_NE(bytes.find("##HL"), std::string::npos);
    EXPECT_NE(bytes.find("##DZ"), std::string::npos);
    // Two data groups: the speed in its own, every other sample; read on the accelerometer's times.
    const fs::path split = dir / (data + "_split.mf4");
    ASSERT_EQ(std::system(("python3 " + script + " " + kDrives + "stop_and_go.csv " +
                           split.string() + " --data " + data + " --split GPS_Speed" + units)
                              .c_str()),
              0);
    r = dtwin_test::runTwin(
        importArgs(split.string(), (dir / "map.toml").string(), dir / (data + "_split")), dir);
    ASSERT_EQ(r.code, 0) << r.err;
    expectSameFiles(dir / "csv_nolp", dir / (data + "_split"), /*speed_too=*/false);
    const auto side =
        nlohmann::json::parse(dtwin_test::slurp(dir / (data + "_split") / "measurements.json"));
    EXPECT_EQ(side.at("source").at("mdf").at("groups_read").size(), 2u);
    EXPECT_EQ(side.at("source").at("mdf").at("time_base").at("group"), "log");
  }
}
