// Fuzz harness: `twin import` (io/log_import.hpp) on an MF4 log, read through the vendored mdflib
// (io/mdf_log.hpp) after the import's own check of the file's block structure and compressed data
// (io/mdf_structure.hpp). The input is the whole file; the mapping is the demonstration drive's. An
// accepted log is written and its study read back, as the command does. The seeds
// (tests/fuzz/seeds/mf4_import) are the drive's first 200 rows written by tests/io/write_mf4.py:
// `head -201 data/drives/stop_and_go.csv > seed.csv`, then `write_mf4.py seed.csv plain.mf4
// --units ...` and `... transposed_split.mf4 --data transposed --split GPS_Speed --units ...` with
// the units GPS_Speed=km/h,Road_L=mm,Road_R=mm,AccZ_Seat=g,Cabin_Temp=degC; and those two damaged
// as users' files were (damaged_*.mf4: a link to the wrong block, a cycle, a renamed block, a DZ
// checksum; each crashed, hung or fooled the import before its structure check), also run by
// tests/io/mdf_damage_test.cpp.
//
// Its mutator (LLVMFuzzerCustomMutator) knows the blocks: besides libFuzzer's byte mutations, it
// renames a block (another MDF 4 id, or a letter changed), redirects a link to another block's
// offset (or to itself, into a block, past the end, to 0), changes a block's length or link count,
// and damages a DZ block: a byte of its stream, its sizes or zip type, or its records inflated,
// changed (a byte, or a value set to NaN, an infinity, a huge or a tiny number) and deflated again
// with a checksum that passes, so that mdflib reads them.
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io/log_import.hpp"
#include "tests/fuzz/fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace dtwin::fuzz;
  static const dtwin::ImportMapping mapping =
      dtwin::readImportMapping((sourceDir() / "data" / "drives" / "stop_and_go_map.toml").string());
  static const std::string study = (sourceDir() / "data" / "studies" / "demo.toml").string();
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::filesystem::path out = scratch() / "drive";
  std::filesystem::remove_all(out);
  guarded([&] {
    const auto r = dtwin::importLog(bytes, "log.mf4", mapping, study, "drive");
    dtwin::writeImport(r, out.string());
  });
  return 0;
}

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

/// A block found by its header: "##" and two capitals at an 8-byte boundary after the
/// identification block.
struct FoundBlock {
  size_t at;
  uint64_t length, links;
};

uint64_t get64(const uint8_t* d, size_t at) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | d[at + static_cast<size_t>(i)];
  return v;
}
void put64(uint8_t* d, size_t at, uint64_t v) {
  for (int i = 0; i < 8; ++i, v >>= 8)
    d[at + static_cast<size_t>(i)] = static_cast<uint8_t>(v & 0xff);
}

std::vector<FoundBlock> findBlocks(const uint8_t* d, size_t size) {
  std::vector<FoundBlock> out;
  for (size_t at = 64; at + 24 <= size; at += 8)
    if (d[at] == '#' && d[at + 1] == '#' && d[at + 2] >= 'A' && d[at + 2] <= 'Z' &&
        d[at + 3] >= 'A' && d[at + 3] <= 'Z')
      out.push_back({at, get64(d, at + 8), get64(d, at + 16)});
  return out;
}

const char* const kMdf4Ids[] = {"HD", "MD", "TX", "FH", "CH", "AT", "EV", "DG", "CG", "SI",
                                "CN", "CC", "CA", "DT", "SR", "RD", "SD", "DL", "DZ", "HL",
                                "DV", "DI", "RV", "RI", "LD", "DS", "CL", "CV", "CU"};

/// A DZ block's records inflated, changed and deflated again into the block's room: a stream
/// whose checksum passes. False when the block is not one to do this with.
bool rewriteDz(uint8_t* d, size_t size, const FoundBlock& b, std::minstd_rand& rng) {
  if (b.links != 0 || b.length < 48 || b.length > size - b.at) return false;
  const uint64_t original = get64(d, b.at + 32), packed = get64(d, b.at + 40), room = b.length - 48;
  if (original == 0 || original > (1u << 20) || packed > room) return false;
  std::vector<uint8_t> raw(original);
  uLongf raw_size = static_cast<uLongf>(original);
  if (uncompress(raw.data(), &raw_size, d + b.at + 48, static_cast<uLong>(packed)) != Z_OK)
    return false;
  raw.resize(raw_size);
  if (raw.empty()) return false;
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    const size_t at = rng() % raw.size();
    if (rng() % 2 == 0 || raw.size() < 8) {
      raw[at] = static_cast<uint8_t>(rng());
    } else {
      static const double special[] = {std::numeric_limits<double>::quiet_NaN(),
                                       std::numeric_limits<double>::infinity(),
                                       -std::numeric_limits<double>::infinity(),
                                       1e300,
                                       -1e300,
                                       5e-324,
                                       -0.0,
                                       0.0,
                                       1e9,
                                       -1.0};
      const double v = special[rng() % (sizeof special / sizeof special[0])];
      std::memcpy(raw.data() + (at / 8 * 8 + 8 <= raw.size() ? at / 8 * 8 : raw.size() - 8), &v, 8);
    }
  }
  std::vector<uint8_t> z(compressBound(static_cast<uLong>(raw.size())));
  uLongf z_size = static_cast<uLongf>(z.size());
  if (compress2(z.data(), &z_size, raw.data(), static_cast<uLong>(raw.size()),
                static_cast<int>(rng() % 10)) != Z_OK ||
      z_size > room)
    return false;
  std::memcpy(d + b.at + 48, z.data(), z_size);
  put64(d, b.at + 32, raw.size());
  put64(d, b.at + 40, z_size);
  return true;
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size,
                                          unsigned int seed) {
  std::minstd_rand rng(seed);
  const std::vector<FoundBlock> blocks = findBlocks(data, size);
  const unsigned kind = static_cast<unsigned>(rng() % 10);
  if (blocks.empty() || kind < 3) return LLVMFuzzerMutate(data, size, max_size);
  const FoundBlock& b = blocks[rng() % blocks.size()];
  switch (kind) {
    case 3: {  // the block's id: another MDF 4 id, or one letter changed (##CO for ##CN)
      if (rng() % 2 == 0) {
        std::memcpy(data + b.at + 2, kMdf4Ids[rng() % (sizeof kMdf4Ids / sizeof kMdf4Ids[0])], 2);
      } else {
        data[b.at + 2 + rng() % 2] = static_cast<uint8_t>('A' + rng() % 26);
      }
      return size;
    }
    case 4:
    case 5: {  // a link redirected: to another block, itself, into a block, past the end, to 0
      if (b.links == 0 || b.links > (size - b.at - 24) / 8)
        return LLVMFuzzerMutate(data, size, max_size);
      const size_t slot = b.at + 24 + 8 * static_cast<size_t>(rng() % b.links);
      const unsigned where = static_cast<unsigned>(rng() % 10);
      const uint64_t to = where < 6    ? blocks[rng() % blocks.size()].at
                          : where == 6 ? b.at
                          : where == 7 ? blocks[rng() % blocks.size()].at + 8 * (1 + rng() % 4)
                          : where == 8 ? size + 8 * (rng() % 16)
                                       : 0;
      put64(data, slot, to);
      return size;
    }
    case 6:
    case 7: {  // a DZ block: its records changed under a passing checksum, a stream byte, its
               // sizes, its zip type
      std::vector<FoundBlock> dz;
      for (const auto& x : blocks)
        if (data[x.at + 2] == 'D' && data[x.at + 3] == 'Z') dz.push_back(x);
      if (dz.empty()) return LLVMFuzzerMutate(data, size, max_size);
      const FoundBlock& z = dz[rng() % dz.size()];
      const unsigned how = static_cast<unsigned>(rng() % 6);
      if (how < 3 && rewriteDz(data, size, z, rng)) return size;
      if (z.at + 48 > size) return LLVMFuzzerMutate(data, size, max_size);
      if (how == 3 && z.at + 49 < size) {
        data[z.at + 48 +
             rng() % std::min<size_t>(size - z.at - 48, z.length > 48 ? z.length - 48 : 1)] ^=
            static_cast<uint8_t>(1 + rng() % 255);
      } else if (how == 4) {
        const size_t field =
            z.at + (rng() % 2 == 0 ? 32 : 40);  // the original or the compressed size
        const uint64_t v = get64(data, field);
        const uint64_t choices[] = {v + 8, v - 8, v * 2, v / 2, 0, v + 1};
        put64(data, field, choices[rng() % 6]);
      } else {
        data[z.at + 26] = static_cast<uint8_t>(rng() % 3);  // zip type
        if (rng() % 2 == 0)
          put64(data, z.at + 28,
                rng() % 3 == 0
                    ? 0
                    : rng() % 64);  // the transposition's columns (and the size's low bytes)
      }
      return size;
    }
    default: {  // the block's length or link count
      const size_t field = b.at + (rng() % 2 == 0 ? 8 : 16);
      const uint64_t v = get64(data, field);
      const uint64_t choices[] = {v + 8,
                                  v - 8,
                                  0,
                                  v * 2,
                                  std::numeric_limits<uint64_t>::max() - rng() % 64,
                                  static_cast<uint64_t>(rng() % 64)};
      put64(data, field, choices[rng() % 6]);
      return size;
    }
  }
}
