#pragma once
// The block structure of an MF4 log, checked before mdflib reads it (io/mdf_log.cpp; mdflib reads
// every link as the block it expects there, whatever the file holds, and takes a DZ block's data
// without its checksum). docs/measurements.md, "MF4 logs", lists what is checked.
#include <string>

namespace dtwin {

/// Checks the log `bytes` (named `name` in errors) from its identification block:
///  * the version is MDF 4;
///  * every block reachable from the header (##HD at 64) has an MDF 4 id, a length and links
///    inside the file, and each of its links is 0 or points to a block of a type the standard
///    allows for that link (cn_cn_next: ##CN, dg_data: ##DT, ##DV, ##DZ, ##DL, ##LD, ##HL, ...);
///  * no chain or tree of blocks a reader follows leads back to a block on its own path (a cycle);
///  * each data group's data blocks hold the records its channel groups declare;
///  * every ##DZ block names an original block type and a zip type of the standard, and, when
///    `inflate`, inflates cleanly (zlib's stream end and checksum) to exactly the size it declares
///    (asked for where the data are read: the blocks alone need no inflating).
/// The first violation is an InputError: "NAME: block ##CN at 0x1a40", "link 'cn_cn_next' points
/// to a ##CG block (allowed: ##CN)".
void checkMdfStructure(const std::string& bytes, const std::string& name, bool inflate);

}  // namespace dtwin
