// `twin import` of damaged MF4 logs (io/mdf_structure.hpp): good logs of the demonstration drive
// (mdflib's writer, writeMdfLog; and tests/io/write_mf4.py for a DZ block whose zlib stream holds
// the records' bytes as they are) damaged one way each: a link to a block of the wrong type, a
// chain that leads back to itself, a link past the end of the file, block ids that are not MDF 4
// ids, a DZ block whose stream fails its checksum, ends early or inflates to another size than
// declared, an MDF 3 version. Each is exit code 2, one line naming the file, the block and its
// offset, and the rule, and nothing written. The fuzzer's finds (tests/fuzz/seeds/mf4_import)
// are run here too.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/mdf_log.hpp"
#include "test_util.hpp"

using namespace dtwin;
namespace fs = std::filesystem;

namespace {

const std::string kDrives = std::string(DTWIN_SOURCE_DIR) + "/data/drives/";

/// The demonstration drive's first `rows` rows as one channel group "log" (the CSV's columns,
/// an empty cell NaN).
MdfWriteGroup demoGroup(std::size_t rows) {
  std::istringstream in(dtwin_test::slurp(kDrives + "stop_and_go.csv"));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream hs(line);
  for (std::string f; std::getline(hs, f, ',');) names.push_back(f);
  const char* units[] = {"s", "km/h", "mm", "mm", "g", "degC"};
  MdfWriteGroup g{"log", "Time", "s", {}, {}};
  for (std::size_t k = 1; k < names.size(); ++k) g.channels.push_back({names[k], units[k], {}, {}});
  while (std::getline(in, line) && g.time.size() < rows) {
    if (line.empty()) continue;
    std::stringstream ls(line);
    std::string cell;
    for (std::size_t k = 0; k < names.size(); ++k) {
      std::getline(ls, cell, ',');
      const double v = cell.empty() ? std::numeric_limits<double>::quiet_NaN()
                                    : std::strtod(cell.c_str(), nullptr);
      (k == 0 ? g.time : g.channels[k - 1].values).push_back(v);
    }
  }
  return g;
}

std::uint64_t get64(const std::string& b, std::uint64_t at) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(b.at(at + static_cast<std::uint64_t>(i)));
  return v;
}
void put64(std::string& b, std::uint64_t at, std::uint64_t v) {
  for (int i = 0; i < 8; ++i, v >>= 8)
    b.at(at + static_cast<std::uint64_t>(i)) = static_cast<char>(v & 0xff);
}
std::uint64_t link(const std::string& b, std::uint64_t at, int k) {
  return get64(b, at + 24 + 8 * static_cast<std::uint64_t>(k));
}
void setLink(std::string& b, std::uint64_t at, int k, std::uint64_t to) {
  put64(b, at + 24 + 8 * static_cast<std::uint64_t>(k), to);
}

std::string hex(std::uint64_t v) {
  std::ostringstream s;
  s << "0x" << std::hex << v;
  return s.str();
}

/// Where a log's blocks are: the header, the first data group, its channel group, its first two
/// channels, its data (the first DZ block when the data are compressed).
struct Blocks {
  std::uint64_t hd = 64, dg = 0, cg = 0, cn = 0, cn2 = 0, data = 0, dz = 0;
};
Blocks blocksOf(const std::string& b) {
  Blocks x;
  x.dg = link(b, x.hd, 0);
  x.cg = link(b, x.dg, 1);
  x.cn = link(b, x.cg, 1);
  x.cn2 = link(b, x.cn, 0);
  x.data = link(b, x.dg, 2);
  for (std::uint64_t at = x.data; at != 0 && x.dz == 0;) {
    const std::string id = b.substr(at, 4);
    if (id == "##DZ")
      x.dz = at;
    else if (id == "##HL")
      at = link(b, at, 0);
    else if (id == "##DL")
      at = link(b, at, 1);
    else
      at = 0;
  }
  return x;
}

struct ImportRun {
  int code;
  std::string err;
  bool wrote;
};

/// `twin import` of `bytes` as DIR/NAME.mf4 with the drive's mapping.
ImportRun importBytes(const fs::path& dir, const std::string& name, const std::string& bytes) {
  const fs::path log = dir / (name + ".mf4"), out = dir / ("out_" + name);
  dtwin_test::writeText(log, bytes);
  const auto r = dtwin_test::runTwin("import --log " + log.string() + " --map " + kDrives +
                                         "stop_and_go_map.toml --quiet --out " + out.string(),
                                     dir);
  return {r.code, r.err, fs::exists(out) || fs::exists(dir / ("out_" + name + ".import-tmp"))};
}

/// Exit code 2, one line "twin: error: DIR/NAME.mf4: <expect...>", nothing written.
void expectRefused(const fs::path& dir, const std::string& name, const std::string& bytes,
                   const std::string& expect) {
  SCOPED_TRACE(name);
  const ImportRun r = importBytes(dir, name, bytes);
  EXPECT_EQ(r.code, 2) << r.err;
  const std::string head = "twin: error: " + (dir / (name + ".mf4")).string() + ": ";
  EXPECT_EQ(r.err.rfind(head, 0), 0u) << r.err;
  EXPECT_NE(r.err.find(expect), std::string::npos) << "expected: " << expect << "\n got: " << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
  EXPECT_EQ(r.err.find("lab data"), std::string::npos) << r.err;
  EXPECT_FALSE(r.wrote);
}

/// The good logs, plain and compressed, written once per process.
const std::string& goodLog(bool compress) {
  static const std::string plain = [] {
    const fs::path p = dtwin_test::freshDir("mdf_damage_good") / "plain.mf4";
    writeMdfLog(p.string(), {demoGroup(600)}, false);
    return dtwin_test::slurp(p);
  }();
  static const std::string dz = [] {
    const fs::path p = dtwin_test::freshDir("mdf_damage_good_dz") / "dz.mf4";
    writeMdfLog(p.string(), {demoGroup(600)}, true);
    return dtwin_test::slurp(p);
  }();
  return compress ? dz : plain;
}

}  // namespace

// The good logs import (the damage alone makes a log fail below).
TEST(MdfDamage, TheGoodLogsImport) {
  const fs::path dir = dtwin_test::freshDir("mdf_damage_ok");
  for (bool compress : {false, true}) {
    const ImportRun r = importBytes(dir, compress ? "dz" : "plain", goodLog(compress));
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(r.wrote);
  }
  EXPECT_NE(blocksOf(goodLog(true)).dz, 0u);
}

// Links to a block of the wrong type (every link inside the file), a chain that leads back to a
// block on its own path, a link past the end of the file or into a block; a block too short for
// its fields.
TEST(MdfDamage, ALinkToTheWrongBlockIsNamed) {
  const fs::path dir = dtwin_test::freshDir("mdf_damage_links");
  const std::string good = goodLog(false);
  const Blocks x = blocksOf(good);
  std::string b = good;
  setLink(b, x.cn, 0, x.cg);  // cn_cn_next -> the channel group
  expectRefused(
      dir, "cn_next_to_cg", b,
      "block ##CN at " + hex(x.cn) + ": link 'cn_cn_next' points to a ##CG block (allowed: ##CN)");
  b = good;
  setLink(b, x.cg, 1, x.dg);  // cg_cn_first -> the data group
  expectRefused(
      dir, "cg_cn_to_dg", b,
      "block ##CG at " + hex(x.cg) + ": link 'cg_cn_first' points to a ##DG block (allowed: ##CN)");
  b = good;
  setLink(b, x.dg, 2, x.cn);  // dg_data -> a channel
  expectRefused(
      dir, "dg_data_to_cn", b,
      "block ##DG at " + hex(x.dg) +
          ": link 'dg_data' points to a ##CN block (allowed: ##DT, ##DV, ##DZ, ##DL, ##LD, ##HL)");
  b = good;
  setLink(b, x.cn, 4, x.cn2);  // cn_cc_conversion -> a channel
  expectRefused(dir, "cn_cc_to_cn", b,
                "block ##CN at " + hex(x.cn) +
                    ": link 'cn_cc_conversion' points to a ##CN block (allowed: ##CC)");
  b = good;
  setLink(b, x.cn, 2, x.hd);  // cn_tx_name -> the header
  expectRefused(dir, "cn_name_to_hd", b,
                "link 'cn_tx_name' points to a ##HD block (allowed: ##TX)");
  b = good;
  setLink(b, x.cn2, 0, x.cn);  // the second channel's next is the first: a cycle
  expectRefused(dir, "cn_cycle", b,
                "block ##CN at " + hex(x.cn2) +
                    ": link 'cn_cn_next' leads back to the ##CN block at " + hex(x.cn) +
                    " on its own path");
  b = good;
  setLink(b, x.cn, 1, x.cn);  // a channel composed of itself
  expectRefused(dir, "cn_composition_self", b,
                "link 'cn_composition' leads back to the ##CN block at " + hex(x.cn));
  b = good;
  setLink(b, x.cn, 0, good.size() + 64);
  expectRefused(dir, "cn_next_past_end", b,
                "block ##CN at " + hex(x.cn) + ": link 'cn_cn_next' points to byte " +
                    hex(good.size() + 64) + ", outside the file's blocks");
  b = good;
  put64(b, x.cn + 8,
        24 + 8 * 8 + 16);  // a channel's length: its links, but not its 72 bytes of fields
  expectRefused(
      dir, "cn_short", b,
      "block ##CN at " + hex(x.cn) +
          ": runs 104 bytes, too few for its 8 links and the 72 bytes of fields a ##CN block has");
  b = good;
  setLink(b, x.cn, 0, x.cn + 4);  // into the middle of a block
  expectRefused(dir, "cn_next_mid_block", b, "link 'cn_cn_next' points to '");
}

// Block ids that are not MDF 4 ids: a renamed channel (##CO for ##CN), header, channel group and
// data group; an MDF 3 version number.
TEST(MdfDamage, BlockIdsThatAreNotMdf4AreNamed) {
  const fs::path dir = dtwin_test::freshDir("mdf_damage_ids");
  const std::string good = goodLog(false);
  const Blocks x = blocksOf(good);
  std::string b = good;
  b.replace(x.cn, 4, "##CO");
  expectRefused(dir, "cn_as_co", b,
                "block ##CG at " + hex(x.cg) + ": link 'cg_cn_first' points to '##CO' at " +
                    hex(x.cn) + ", not an MDF 4 block id (allowed: ##CN)");
  b = good;
  b.replace(x.cn2, 4, "##CO");
  expectRefused(dir, "cn2_as_co", b,
                "block ##CN at " + hex(x.cn) + ": link 'cn_cn_next' points to '##CO'");
  b = good;
  b.replace(x.hd, 4, "##HX");
  expectRefused(dir, "hd_renamed", b,
                "block ##HX at 0x40: the block after the identification must be the header, ##HD");
  b = good;
  b.replace(x.cg, 4, "##CX");
  expectRefused(dir, "cg_renamed", b,
                "block ##DG at " + hex(x.dg) + ": link 'dg_cg_first' points to '##CX'");
  b = good;
  b.replace(x.dg, 4, "##DX");
  expectRefused(dir, "dg_renamed", b, "block ##HD at 0x40: link 'hd_dg_first' points to '##DX'");
  b = good;
  b.replace(x.cg, 4, "##CN");  // an MDF 4 id, the wrong one
  expectRefused(dir, "cg_as_cn", b, "link 'dg_cg_first' points to a ##CN block (allowed: ##CG)");
  b = good;
  b.replace(8, 8, "3.30    ");
  b[28] = static_cast<char>(330 & 0xff);
  b[29] = static_cast<char>(330 >> 8);
  expectRefused(dir, "mdf3", b,
                "is MDF 3.30 (version number 330): only MDF 4 (.mf4) logs are read");
}

// A DZ block whose zlib stream fails its checksum, ends early, inflates to another size than it
// declares, or names no zip type of the standard.
TEST(MdfDamage, ACompressedBlockThatFailsItsCheckIsNamed) {
  const fs::path dir = dtwin_test::freshDir("mdf_damage_dz");
  const std::string good = goodLog(true);
  const std::uint64_t dz = blocksOf(good).dz;
  ASSERT_NE(dz, 0u);
  const std::uint64_t packed = get64(good, dz + 40), size = get64(good, dz + 32);
  const std::string where = "block ##DZ at " + hex(dz) + ": ";
  std::string b = good;
  b[dz + 48 + packed - 1] =
      static_cast<char>(b[dz + 48 + packed - 1] ^ 0x55);  // the adler-32 checksum
  expectRefused(dir, "dz_checksum", b,
                where + "compressed data fail their check (zlib: incorrect data check)");
  b = good;
  put64(b, dz + 40, packed / 2);  // the stream cut short
  expectRefused(dir, "dz_cut", b, where + "compressed data end before their zlib stream does");
  b = good;
  put64(b, dz + 32, size + 8);
  expectRefused(dir, "dz_size_larger", b,
                where + "compressed data inflate to " + std::to_string(size) +
                    " bytes; the block declares " + std::to_string(size + 8));
  b = good;
  put64(b, dz + 32,
        size - 8);  // the data group then holds less than its records: found before any inflating
  expectRefused(dir, "dz_size_smaller", b,
                "block ##DG at " + hex(blocksOf(good).dg) + ": its data blocks hold " +
                    std::to_string(size - 8) +
                    " bytes of records where its channel groups declare " + std::to_string(size));
  b = good;
  b[dz + 26] = 7;
  expectRefused(dir, "dz_zip_type", b,
                where + "zip type 7 is neither 0 (deflate) nor 1 (transposition + deflate)");
  b = good;
  b[dz + 48 + 2] = static_cast<char>(b[dz + 48 + 2] ^ 0xff);  // the first deflate block's header
  const ImportRun r = importBytes(dir, "dz_stream", b);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(where + "compressed data fail their check (zlib: "), std::string::npos)
      << r.err;
}

// The user's file: the records stored inside the zlib stream as they are (level 0), one byte of a
// value changed. Read without the checksum, the value is silently another; the import refuses it.
TEST(MdfDamage, AChangedValueInsideAStreamFailsItsChecksum) {
  if (std::system("python3 -c 'import zlib' > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3 is not installed";
  const fs::path dir = dtwin_test::freshDir("mdf_damage_stored");
  const fs::path log = dir / "stored.mf4";
  const std::string script = std::string(DTWIN_SOURCE_DIR) + "/tests/io/write_mf4.py";
  const std::string units =
      " --units GPS_Speed=km/h,Road_L=mm,Road_R=mm,AccZ_Seat=g,Cabin_Temp=degC";
  ASSERT_EQ(std::system(("python3 " + script + " " + kDrives + "stop_and_go.csv " + log.string() +
                         " --data deflate --level 0" + units)
                            .c_str()),
            0);
  const std::string good = dtwin_test::slurp(log);
  const ImportRun ok = importBytes(dir, "stored_good", good);
  ASSERT_EQ(ok.code, 0) << ok.err;
  const std::uint64_t dz = blocksOf(good).dz;
  ASSERT_NE(dz, 0u);
  std::string b = good;
  const std::uint64_t at = dz + 48 + 2 + 5 + 8 * 6 * 10 +
                           2;  // zlib's and the stored block's headers, then row 10's Time
  b[at] = static_cast<char>(b[at] ^ 0x01);
  expectRefused(dir, "stored_changed", b,
                "block ##DZ at " + hex(dz) +
                    ": compressed data fail their check (zlib: incorrect data check)");
}

// A value no sensor gives (the plausibility check of the imported measurements) names the log,
// the channel and the time, not the measurements file the import writes.
TEST(MdfDamage, AnImplausibleValueNamesTheLog) {
  const fs::path dir = dtwin_test::freshDir("mdf_damage_value");
  MdfWriteGroup g = demoGroup(600);
  for (auto& c : g.channels)
    if (c.name == "AccZ_Seat") c.values[400] = 1e200;
  writeMdfLog((dir / "value.mf4").string(), {g}, true);
  expectRefused(dir, "value", dtwin_test::slurp(dir / "value.mf4"),
                "channel 'AccZ_Seat' at " + formatNumber(g.time[400], 12) +
                    " s: value: must lie in the plausible range");
}

// The damaged seeds of the fuzzer (tests/fuzz/seeds/mf4_import/damaged_*.mf4; docs/fuzzing.md):
// the 200-row seed damaged as the user's files were, and three inputs the fuzzer found. Before the
// structure check, three crashed the import (SIGSEGV), the two cycles hung it, and the others
// imported without a word.
TEST(MdfDamage, TheFuzzersDamagedSeedsAreRefused) {
  const fs::path dir = dtwin_test::freshDir("mdf_damage_seeds");
  const fs::path seeds = fs::path(DTWIN_SOURCE_DIR) / "tests/fuzz/seeds/mf4_import";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"damaged_cn_next_to_cg",
       "block ##CN at 0x1d8: link 'cn_cn_next' points to a ##CG block (allowed: ##CN)"},
      {"damaged_cn_composition_self",
       "block ##CN at 0x1d8: link 'cn_composition' leads back to the ##CN block at 0x1d8"},
      {"damaged_cn_cycle",
       "block ##CN at 0x2c0: link 'cn_cn_next' leads back to the ##CN block at 0x1d8"},
      {"damaged_cn_as_co",
       "block ##CG at 0x710: link 'cg_cn_first' points to '##CO' at 0x1d8, not an MDF 4 block id "
       "(allowed: ##CN)"},
      {"damaged_hd_renamed",
       "block ##HX at 0x40: the block after the identification must be the header, ##HD"},
      {"damaged_dz_checksum",
       "block ##DZ at 0x690: compressed data fail their check (zlib: incorrect data check)"},
      // Found by the fuzzer's structure-aware mutations: a channel's name a renamed block (SIGSEGV
      // before the check), a data group's channel groups a file history (imported without a word),
      // a file history that is its own next (the import hung).
      {"damaged_found_cn_name_to_ri",
       "block ##CN at 0x568: link 'cn_tx_name' points to a ##RI block (allowed: ##TX)"},
      {"damaged_found_dg_cg_to_fh",
       "block ##DG at 0x1708: link 'dg_cg_first' points to a ##FH block (allowed: ##CG)"},
      {"damaged_found_fh_cycle",
       "block ##FH at 0x160: link 'fh_fh_next' leads back to the ##FH block at 0x160 on its own "
       "path"},
      // A data list whose count far exceeds its links (the reader walked billions of them: hung).
      {"damaged_found_dl_count",
       "block ##DL at 0x10e0: lists 2684354562 data blocks but links to 2: the file is damaged"},
  };
  for (const auto& [file, expect] : cases)
    expectRefused(dir, file, dtwin_test::slurp(seeds / (file + ".mf4")), expect);
  std::size_t damaged = 0;
  for (const auto& e : fs::directory_iterator(seeds))
    damaged += e.path().filename().string().rfind("damaged_", 0) == 0;
  EXPECT_EQ(damaged, cases.size()) << "a damaged seed without its case here";
}

// The same damaged seeds read in process (io/mdf_log.hpp): an InputError naming the file, from the
// directory for the blocks, from the group's data for the DZ checksum. The seeds are undamaged
// otherwise: plain.mf4 reads.
TEST(MdfDamage, TheReaderRefusesTheDamagedSeedsInProcess) {
  const fs::path seeds = fs::path(DTWIN_SOURCE_DIR) / "tests/fuzz/seeds/mf4_import";
  const std::string plain = dtwin_test::slurp(seeds / "plain.mf4");
  const MdfDirectory dir = readMdfDirectory(plain, "plain.mf4");
  ASSERT_EQ(dir.groups.size(), 1u);
  EXPECT_EQ(readMdfGroup(plain, "plain.mf4", 0, {"AccZ_Seat"}).time.size(), 200u);
  for (const char* f : {"damaged_cn_next_to_cg", "damaged_cn_composition_self", "damaged_cn_cycle",
                        "damaged_cn_as_co", "damaged_hd_renamed", "damaged_found_cn_name_to_ri",
                        "damaged_found_dg_cg_to_fh", "damaged_found_fh_cycle"}) {
    SCOPED_TRACE(f);
    const std::string bytes = dtwin_test::slurp(seeds / (std::string(f) + ".mf4"));
    try {
      (void)readMdfDirectory(bytes, "x.mf4");
      ADD_FAILURE() << "read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("x.mf4: block ##", 0), 0u) << e.what();
    }
  }
  const std::string dz = dtwin_test::slurp(seeds / "damaged_dz_checksum.mf4");
  EXPECT_EQ(readMdfDirectory(dz, "x.mf4").groups.size(),
            2u);  // the blocks are whole; the data are not
  try {
    (void)readMdfGroup(dz, "x.mf4", 0, {"AccZ_Seat"});
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "x.mf4: block ##DZ at 0x690: compressed data fail their check (zlib: incorrect data "
              "check)");
  }
}
