#pragma once
// Zip archives (PKWARE APPNOTE 6.3: local headers, central directory, end record; no zip64, no
// encryption), as an FMU is one (FMI 2.0, section 2.3): written with each member deflated by zlib
// (stored when deflating does not shrink it) and its CRC-32, and read back (stored or deflated
// members, CRC-32 checked). Members are written with a fixed time (1980-01-01 00:00), so the same
// members give the same bytes.
#include <string>
#include <vector>

namespace dtwin {

struct ZipMember {
  std::string name;  ///< the path inside the archive, '/'-separated; a folder's ends with '/'
  std::string data;
};

/// The archive's bytes. InputError ("zip: ...") for an empty or repeated name, a name with '\\', a
/// leading '/' or "..", or a member over 4 GB.
std::string zipArchive(const std::vector<ZipMember>& members);

/// The members of an archive (in the central directory's order). InputError naming `what` and the
/// rule for anything but a well-formed archive of stored or deflated members with matching CRCs.
std::vector<ZipMember> readZipArchive(const std::string& bytes, const std::string& what);

}  // namespace dtwin
