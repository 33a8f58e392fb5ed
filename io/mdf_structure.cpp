// An MF4 log's block structure, checked before mdflib reads it (io/mdf_structure.hpp). The link
// tables are the MDF 4.1/4.2 standard's as mdflib reads them (third_party/mdflib/src/*4block.cpp:
// the link indexes of each block; datalistblock.cpp: the data blocks a list may hold).
#include "io/mdf_structure.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <set>
#include <unordered_map>
#include <vector>

#include "common/errors.hpp"

namespace dtwin {

namespace {

/// The ids of MDF 4 blocks (the two letters after "##").
constexpr std::array<const char*, 29> kIds = {
    "HD", "MD", "TX", "FH", "CH", "AT", "EV", "DG", "CG", "SI", "CN", "CC", "CA", "DT", "SR",
    "RD", "SD", "DL", "DZ", "HL", "DV", "DI", "RV", "RI", "LD", "DS", "CL", "CV", "CU"};
/// The blocks of no links: data, texts, and a DZ (whose header fields sit right after its 24
/// bytes).
constexpr const char* kLinkless = "MD TX DT SD RD DV DI RV RI DZ";
/// The data blocks a DL or an LD lists, and the original block types a DZ may hold.
constexpr const char* kListData = "DT SD RD DV DI RV RI DZ";
constexpr const char* kDataRoot = "DT DV DZ DL LD HL";  ///< what dg_data and a CA's data point to

/// The bytes of a block's fixed fields after its links (MDF 4.1), which a reader reads whatever the
/// block's length: HD, FH, CH, AT, EV, DG, CG, SI, CN, CC, CA, DL, LD, HL, SR, DZ; 0 for the
/// others.
std::uint64_t fixedFields(const char* id) {
  static const std::pair<const char*, std::uint64_t> sizes[] = {
      {"HD", 32}, {"FH", 16}, {"CH", 8},  {"AT", 40}, {"EV", 32}, {"DG", 8},
      {"CG", 32}, {"SI", 8},  {"CN", 72}, {"CC", 24}, {"CA", 16}, {"DL", 8},
      {"LD", 8},  {"HL", 8},  {"SR", 24}, {"DZ", 24}};
  for (const auto& [k, n] : sizes)
    if (k[0] == id[0] && k[1] == id[1]) return n;
  return 0;
}

/// True when `list` (ids separated by spaces) holds the two letters `id`.
bool among(const char* list, const char* id) {
  for (const char* p = list; *p != '\0'; p += p[2] == ' ' ? 3 : 2)
    if (p[0] == id[0] && p[1] == id[1]) return true;
  return false;
}

bool knownId(const char* id) {
  for (const char* k : kIds)
    if (k[0] == id[0] && k[1] == id[1]) return true;
  return false;
}

std::string hex(std::uint64_t v) {
  static const char* digits = "0123456789abcdef";
  std::string s;
  do {
    s.insert(s.begin(), digits[v & 15]);
    v >>= 4;
  } while (v != 0);
  return "0x" + s;
}

/// "##CN, ##CA" from "CN CA".
std::string idList(const char* list) {
  std::string out;
  for (const char* p = list; *p != '\0'; p += p[2] == ' ' ? 3 : 2)
    out += (out.empty() ? "##" : ", ##") + std::string(p, 2);
  return out.empty() ? "none" : out;
}

/// What link k of a block may point to: its name in the standard, the ids allowed, and the ids
/// of those a reader reads as a part of the block (a tree or a chain: a cycle among them never
/// ends); the others are references to blocks read elsewhere. name == nullptr: a link the standard
/// does not define for the block, not followed.
struct LinkRule {
  const char* name = nullptr;
  long index = -1;  ///< the element of a link array (cn_at_reference[2]), -1 for a single link
  const char* allowed = "";
  const char* follow = "";
};

/// A block on the walk: where, its id, its link count and the counts that split its link arrays.
struct BlockInfo {
  std::uint64_t at = 0, links = 0;
  char id[3] = {0, 0, 0};
  std::uint64_t count1 = 0, count2 = 0;  ///< CN: attachments; EV: scopes, attachments
};

LinkRule ruleOf(const BlockInfo& b, std::uint64_t k) {
  const std::string id(b.id, 2);
  auto one = [](const char* name, const char* allowed, bool follow = true) {
    return LinkRule{name, -1, allowed, follow ? allowed : ""};
  };
  auto many = [](const char* name, std::uint64_t i, const char* allowed, bool follow) {
    return LinkRule{name, static_cast<long>(i), allowed, follow ? allowed : ""};
  };
  auto triple = [&](const char* name, std::uint64_t i) {  // a channel named by its DG, CG and CN
    static const char* parts[] = {"DG", "CG", "CN"};
    return many(name, i, parts[i % 3], false);
  };
  if (id == "HD") {
    static const LinkRule t[] = {one("hd_dg_first", "DG"), one("hd_fh_first", "FH"),
                                 one("hd_ch_first", "CH"), one("hd_at_first", "AT"),
                                 one("hd_ev_first", "EV"), one("hd_md_comment", "TX MD")};
    return k < 6 ? t[k] : LinkRule{};
  }
  if (id == "FH")
    return k == 0 ? one("fh_fh_next", "FH") : k == 1 ? one("fh_md_comment", "MD") : LinkRule{};
  if (id == "CH") {
    static const LinkRule t[] = {one("ch_ch_next", "CH"), one("ch_ch_first", "CH"),
                                 one("ch_tx_name", "TX"), one("ch_md_comment", "TX MD")};
    return k < 4 ? t[k] : triple("ch_element", k - 4);
  }
  if (id == "AT") {
    static const LinkRule t[] = {one("at_at_next", "AT"), one("at_tx_filename", "TX"),
                                 one("at_tx_mimetype", "TX"), one("at_md_comment", "TX MD")};
    return k < 4 ? t[k] : LinkRule{};
  }
  if (id == "EV") {
    static const LinkRule t[] = {one("ev_ev_next", "EV"), one("ev_ev_parent", "EV", false),
                                 one("ev_ev_range", "EV", false), one("ev_tx_name", "TX"),
                                 one("ev_md_comment", "TX MD")};
    if (k < 5) return t[k];
    if (k - 5 < b.count1) return many("ev_scope", k - 5, "DG CG CN", false);
    if (k - 5 - b.count1 < b.count2) return many("ev_at_reference", k - 5 - b.count1, "AT", false);
    return k - 5 - b.count1 == b.count2 ? one("ev_tx_group_name", "TX") : LinkRule{};
  }
  if (id == "DG") {
    static const LinkRule t[] = {one("dg_dg_next", "DG"), one("dg_cg_first", "CG"),
                                 one("dg_data", kDataRoot), one("dg_md_comment", "TX MD")};
    return k < 4 ? t[k] : LinkRule{};
  }
  if (id == "CG") {
    static const LinkRule t[] = {one("cg_cg_next", "CG"),         one("cg_cn_first", "CN"),
                                 one("cg_tx_acq_name", "TX"),     one("cg_si_acq_source", "SI"),
                                 one("cg_sr_first", "SR"),        one("cg_md_comment", "TX MD"),
                                 one("cg_cg_master", "CG", false)};
    return k < 7 ? t[k] : LinkRule{};
  }
  if (id == "SI") {
    static const LinkRule t[] = {one("si_tx_name", "TX"), one("si_tx_path", "TX"),
                                 one("si_md_comment", "TX MD")};
    return k < 3 ? t[k] : LinkRule{};
  }
  if (id == "CN") {
    // cn_data: signal data (SD, or a DZ, DL, HL or LD of them) read with the channel, or a
    // reference: the channel group of its values (VLSC), the channel of its length (MLSD), an
    // attachment (a synchronisation stream).
    static const LinkRule t[] = {
        one("cn_cn_next", "CN"),
        one("cn_composition", "CA CN"),
        one("cn_tx_name", "TX"),
        one("cn_si_source", "SI"),
        one("cn_cc_conversion", "CC"),
        LinkRule{"cn_data", -1, "SD DZ DL HL LD CG CN AT", "SD DZ DL HL LD"},
        one("cn_md_unit", "TX MD"),
        one("cn_md_comment", "TX MD")};
    if (k < 8) return t[k];
    if (k - 8 < b.count1) return many("cn_at_reference", k - 8, "AT", false);
    return k - 8 - b.count1 < 3 ? triple("cn_default_x", k - 8 - b.count1) : LinkRule{};
  }
  if (id == "CC") {
    static const LinkRule t[] = {one("cc_tx_name", "TX"), one("cc_md_unit", "TX MD"),
                                 one("cc_md_comment", "TX MD"), one("cc_cc_inverse", "CC")};
    return k < 4 ? t[k] : many("cc_ref", k - 4, "TX MD CC", true);
  }
  if (id == "CA") {
    // After ca_composition: its data blocks, then channels (DG, CG, CN) and axis conversions (CC)
    // in arrays its flags size; the data are read with it, the rest are references.
    return k == 0 ? one("ca_composition", "CA CN")
                  : LinkRule{"ca_data/ca_quantity", static_cast<long>(k - 1),
                             "DT DV DZ DL LD HL DG CG CN CC", kDataRoot};
  }
  if (id == "DL") return k == 0 ? one("dl_dl_next", "DL") : many("dl_data", k - 1, kListData, true);
  if (id == "LD") return k == 0 ? one("ld_ld_next", "LD") : many("ld_data", k - 1, kListData, true);
  if (id == "HL") return k == 0 ? one("hl_dl_first", "DL LD") : LinkRule{};
  if (id == "SR")
    return k == 0   ? one("sr_sr_next", "SR")
           : k == 1 ? one("sr_data", "RD RV RI DZ DL HL LD")
                    : LinkRule{};
  return LinkRule{};
}

class MdfStructure {
 public:
  MdfStructure(const std::string& bytes, const std::string& name) : b_(bytes), name_(name) {}

  void run(bool inflate) {
    identification();
    walk();
    for (const std::uint64_t dz : dz_) {
      dzHeader(dz);
      if (inflate) inflated(dz);
    }
    for (std::uint64_t dg = link(64, 0); dg != 0; dg = link(dg, 0)) records(dg);
  }

 private:
  [[noreturn]] void fail(std::uint64_t at, const std::string& rule) const {
    const std::string id =
        at <= b_.size() && b_.size() - at >= 4 ? b_.substr(at, 4) : std::string("block");
    throw InputError(name_ + ": block " + id + " at " + hex(at), rule);
  }
  std::uint64_t u64(std::uint64_t at) const { return number(at, 8); }
  std::uint64_t u32(std::uint64_t at) const { return number(at, 4); }
  std::uint64_t number(std::uint64_t at, int bytes) const {
    if (at > b_.size() || b_.size() - at < static_cast<std::uint64_t>(bytes))
      throw InputError(
          name_, "is truncated or damaged: it ends inside a block, at byte " + std::to_string(at));
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i)
      v = (v << 8) | static_cast<unsigned char>(b_[at + static_cast<std::uint64_t>(i)]);
    return v;
  }
  std::string idAt(std::uint64_t at) const { return b_.substr(at, 4); }
  /// Link k of the block at `at`, 0 when the block has fewer links.
  std::uint64_t link(std::uint64_t at, std::uint64_t k) const {
    return k < u64(at + 16) ? u64(at + 24 + 8 * k) : 0;
  }

  /// The identification block: MDF 4, and the header block right after it.
  void identification() const {
    const std::uint64_t version = u32(28) & 0xffff;
    if (version < 400 || version >= 500) {
      std::string text = b_.substr(8, 8);
      while (!text.empty() && (text.back() == ' ' || text.back() == '\0')) text.pop_back();
      throw InputError(name_, "is MDF " + (text.empty() ? std::to_string(version) : text) +
                                  " (version number " + std::to_string(version) +
                                  "): only MDF 4 (.mf4) logs are read");
    }
    if (b_.size() < 64 + 24)
      throw InputError(name_, "is truncated or damaged: it ends inside its header block (" +
                                  std::to_string(b_.size()) + " bytes)");
    if (idAt(64) != "##HD") fail(64, "the block after the identification must be the header, ##HD");
    header(64);
  }

  /// A block's 24-byte header: its length inside the file, holding its links and its fixed fields.
  void header(std::uint64_t at) const {
    const std::uint64_t len = u64(at + 8), links = u64(at + 16);
    if (len < 24 || len > b_.size() - at)
      fail(at, "runs " + std::to_string(len) + " bytes, past the end of the file (" +
                   std::to_string(b_.size()) + " bytes): the file is truncated or damaged");
    if (links > (len - 24) / 8)
      fail(at, "declares " + std::to_string(links) + " links, more than its " +
                   std::to_string(len) + " bytes hold");
    if (among(kLinkless, b_.c_str() + at + 2) && links != 0)
      fail(at, "declares " + std::to_string(links) + " links; a " + idAt(at) + " block has none");
    const std::uint64_t fixed = fixedFields(b_.c_str() + at + 2);
    if (len - 24 - 8 * links < fixed)
      fail(at, "runs " + std::to_string(len) + " bytes, too few for its " + std::to_string(links) +
                   " links and the " + std::to_string(fixed) + " bytes of fields a " + idAt(at) +
                   " block has");
    // A data list's count (dl_count, ld_count: after 4 bytes of flags) is how many of its links a
    // reader walks, each with its offset in a DL of unequal lengths: no more than its links hold.
    if (const std::string id = idAt(at); id == "##DL" || id == "##LD") {
      const std::uint64_t count = dataField(at, links, 4, 4), held = links > 0 ? links - 1 : 0;
      if (count > held)
        fail(at, "lists " + std::to_string(count) + " data blocks but links to " +
                     std::to_string(held) + ": the file is damaged");
      if (id == "##DL" && (dataField(at, links, 0, 1) & 1) == 0 &&
          len - 24 - 8 * links < 8 + 8 * count)
        fail(at, "runs " + std::to_string(len) + " bytes, too few for the offsets of its " +
                     std::to_string(count) + " data blocks");
    }
  }

  /// A count in a block's data section (after its links), 0 when the block is too short for it.
  std::uint64_t dataField(std::uint64_t at, std::uint64_t links, std::uint64_t offset,
                          int bytes) const {
    const std::uint64_t pos = at + 24 + 8 * links + offset;
    return pos + static_cast<std::uint64_t>(bytes) <= at + u64(at + 8) ? number(pos, bytes) : 0;
  }

  BlockInfo info(std::uint64_t at) const {
    BlockInfo b;
    b.at = at;
    b.links = u64(at + 16);
    b.id[0] = b_[at + 2];
    b.id[1] = b_[at + 3];
    if (b.id[0] == 'C' && b.id[1] == 'N')
      b.count1 = dataField(at, b.links, 22, 2);  // cn_attachment_count
    if (b.id[0] == 'E' && b.id[1] == 'V') {
      b.count1 = dataField(at, b.links, 8, 4);   // ev_scope_count
      b.count2 = dataField(at, b.links, 12, 2);  // ev_attachment_count
    }
    return b;
  }

  /// Link k of `from` points to `to`: a block inside the file of an id the rule allows.
  void target(const BlockInfo& from, const LinkRule& r, std::uint64_t to) const {
    const std::string what = "link '" + std::string(r.name) +
                             (r.index >= 0 ? "[" + std::to_string(r.index) + "]" : "") + "'";
    if (to < 64 || to >= b_.size() || b_.size() - to < 24)
      fail(from.at, what + " points to byte " + hex(to) + ", outside the file's blocks (" +
                        std::to_string(b_.size()) + " bytes): the file is truncated or damaged");
    const char* id = b_.c_str() + to + 2;
    if (b_[to] != '#' || b_[to + 1] != '#' || !knownId(id))
      fail(from.at, what + " points to '" + idAt(to) + "' at " + hex(to) +
                        ", not an MDF 4 block id (allowed: " + idList(r.allowed) + ")");
    if (!among(r.allowed, id)) {
      if (std::string(r.name) == "cn_composition" && among("DS CL CV CU", id))
        fail(from.at,
             what + " points to a " + idAt(to) +
                 " block, an MDF 4.2 composition this reader does not read (read: ##CA, ##CN)");
      fail(from.at,
           what + " points to a " + idAt(to) + " block (allowed: " + idList(r.allowed) + ")");
    }
    header(to);
  }

  /// Every block a reader reads, depth first from the header (a stack, not recursion: a chain of
  /// channels is as deep as it is long). A followed link to a block still open on the path is a
  /// cycle; a block reached twice is checked once.
  void walk() {
    enum : char { kOpen = 1, kDone = 2 };
    std::unordered_map<std::uint64_t, char> state;
    struct Frame {
      BlockInfo block;
      std::uint64_t next = 0;
    };
    std::vector<Frame> path;
    path.push_back({info(64), 0});
    state[64] = kOpen;
    while (!path.empty()) {
      if (path.back().next == path.back().block.links) {
        state[path.back().block.at] = kDone;
        path.pop_back();
        continue;
      }
      const BlockInfo from = path.back().block;
      const std::uint64_t k = path.back().next++;
      const std::uint64_t to = u64(from.at + 24 + 8 * k);
      const LinkRule r = ruleOf(from, k);
      if (to == 0 || r.name == nullptr) continue;
      target(from, r, to);
      if (!among(r.follow, b_.c_str() + to + 2)) continue;
      const char s = state[to];
      if (s == kOpen)
        fail(from.at, "link '" + std::string(r.name) +
                          (r.index >= 0 ? "[" + std::to_string(r.index) + "]" : "") +
                          "' leads back to the " + idAt(to) + " block at " + hex(to) +
                          " on its own path: a cycle, which a reader would follow for ever");
      if (s == kDone) continue;
      state[to] = kOpen;
      if (idAt(to) == "##DZ") dz_.push_back(to);
      path.push_back({info(to), 0});
    }
  }

  /// The bytes of records data block `at` holds (DT, DZ, or a list of them under DL/HL).
  std::uint64_t dataBytes(std::uint64_t at) const {
    if (at == 0) return 0;
    const std::string t = idAt(at);
    if (t == "##DT" || t == "##DV") return u64(at + 8) - 24;
    if (t == "##DZ")
      return u64(at + 32) < std::numeric_limits<std::uint64_t>::max() / 2 ? u64(at + 32) : 0;
    if (t == "##HL") return dataBytes(link(at, 0));
    if (t ==
        "##DL") {  // the walk left no cycle and checked every entry's type: no list under a list
      std::uint64_t sum = 0;
      for (std::uint64_t dl = at; dl != 0; dl = link(dl, 0))
        for (std::uint64_t k = 1; k < u64(dl + 16); ++k) {
          const std::uint64_t part = dataBytes(link(dl, k));
          sum = part > std::numeric_limits<std::uint64_t>::max() - sum
                    ? std::numeric_limits<std::uint64_t>::max()
                    : sum + part;
        }
      return sum;
    }
    return std::numeric_limits<std::uint64_t>::max();  // another layout (LD, ...): not sized here
  }

  /// A data group's data holds the records of its channel groups.
  void records(std::uint64_t dg) const {
    const std::uint64_t links = u64(dg + 16);
    if (links < 3)
      fail(dg, "declares " + std::to_string(links) +
                   " links; a data group has at least 3 (dg_dg_next, dg_cg_first, dg_data)");
    const std::uint64_t record_id = dataField(dg, links, 0, 1);  // the record id's size in bytes
    std::uint64_t need = 0;
    for (std::uint64_t cg = link(dg, 1); cg != 0; cg = link(cg, 0)) {
      const std::uint64_t cg_links = u64(cg + 16);
      if ((dataField(cg, cg_links, 16, 2) & 1) != 0)
        return;  // variable-length signal data: not sized here
      // A record of no bytes would keep a reader at the same place for ever (every group has its
      // master channel, so a real one has bytes).
      const std::uint64_t record = dataField(cg, cg_links, 24, 4) + dataField(cg, cg_links, 28, 4);
      if (record == 0) fail(cg, "declares records of 0 bytes");
      const std::uint64_t cycles = dataField(cg, cg_links, 8, 8);
      if (cycles > b_.size() * 1032ULL / (record_id + record))
        fail(cg, "declares " + std::to_string(cycles) + " records, more than the file's " +
                     std::to_string(b_.size()) + " bytes can hold");
      need = std::min(need + cycles * (record_id + record),
                      std::numeric_limits<std::uint64_t>::max() / 2);
    }
    const std::uint64_t have = dataBytes(link(dg, 2));
    if (have < need)
      fail(dg, "its data blocks hold " + std::to_string(have) +
                   " bytes of records where its channel groups declare " + std::to_string(need) +
                   ": the file is truncated or damaged");
  }

  /// A DZ block's header: an original block type and a zip type of the standard, sizes that fit.
  void dzHeader(std::uint64_t at) const {
    const std::uint64_t len = u64(at + 8);
    if (len < 48)
      fail(at, "runs " + std::to_string(len) + " bytes, less than a DZ block's 48 bytes of header");
    const std::string original = b_.substr(at + 24, 2);
    const unsigned zip_type = static_cast<unsigned char>(b_[at + 26]);
    const std::uint64_t parameter = u32(at + 28), size = u64(at + 32), packed = u64(at + 40);
    if (original.size() != 2 || !among(kListData, original.c_str()) || original == "DZ")
      fail(at, "holds a block of type '" + original +
                   "' (allowed: ##DT, ##SD, ##RD, ##DV, ##DI, ##RV, ##RI)");
    if (zip_type > 1)
      fail(at, "zip type " + std::to_string(zip_type) +
                   " is neither 0 (deflate) nor 1 (transposition + deflate)");
    if (zip_type == 1 && parameter == 0)
      fail(at, "transposes its data in records of 0 bytes (dz_zip_parameter)");
    if (packed > len - 48)
      fail(at, "its " + std::to_string(packed) + " bytes of compressed data run past the block's " +
                   std::to_string(len) + " bytes");
    // Deflate packs at most 1032 bytes into one: a larger claim is damage, not data.
    if (size / 1032 > packed + 1)
      fail(at, "declares " + std::to_string(size) + " bytes from " + std::to_string(packed) +
                   " compressed ones");
  }

  /// A DZ block's compressed data inflate to the original size it declares, the zlib stream ending
  /// there with its checksum (adler-32) right (its header checked).
  void inflated(std::uint64_t at) const {
    const std::uint64_t size = u64(at + 32), packed = u64(at + 40);
    z_stream z{};
    if (inflateInit(&z) != Z_OK) fail(at, "zlib cannot start inflating");
    struct End {
      z_stream& z;
      ~End() { inflateEnd(&z); }
    } end{z};
    std::array<unsigned char, 1 << 16> out{};
    const unsigned char* in = reinterpret_cast<const unsigned char*>(b_.data()) + at + 48;
    std::uint64_t left = packed;
    int ret = Z_OK;
    while (ret != Z_STREAM_END) {
      if (z.avail_in == 0 && left > 0) {
        const auto chunk = static_cast<uInt>(std::min<std::uint64_t>(left, 1U << 30));
        z.next_in = const_cast<Bytef*>(in);
        z.avail_in = chunk;
        in += chunk;
        left -= chunk;
      }
      z.next_out = out.data();
      z.avail_out = static_cast<uInt>(out.size());
      ret = inflate(&z, Z_NO_FLUSH);
      if (ret == Z_BUF_ERROR && z.avail_in == 0 && left == 0)
        fail(at, "compressed data end before their zlib stream does (" +
                     std::to_string(z.total_out) + " of " + std::to_string(size) +
                     " bytes inflated)");
      if (ret != Z_OK && ret != Z_STREAM_END && ret != Z_BUF_ERROR)
        fail(at, "compressed data fail their check (zlib: " +
                     std::string(z.msg != nullptr     ? z.msg
                                 : ret == Z_NEED_DICT ? "needs a dictionary"
                                                      : "error " + std::to_string(ret)) +
                     ")");
      if (z.total_out > size)
        fail(at, "compressed data inflate to more than the " + std::to_string(size) +
                     " bytes the block declares");
    }
    if (z.total_out != size)
      fail(at, "compressed data inflate to " + std::to_string(z.total_out) +
                   " bytes; the block declares " + std::to_string(size));
    if (z.avail_in + left != 0)
      fail(at, std::to_string(z.avail_in + left) +
                   " bytes follow the end of its zlib stream inside its declared compressed data");
  }

  const std::string& b_;
  const std::string& name_;
  std::vector<std::uint64_t> dz_;  ///< every DZ block the walk reached, in walk order
};

}  // namespace

void checkMdfStructure(const std::string& bytes, const std::string& name, bool inflate) {
  MdfStructure(bytes, name).run(inflate);
}

}  // namespace dtwin
