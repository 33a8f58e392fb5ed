#include "io/zip_archive.hpp"

#include <cstdint>
#include <set>

#include <zlib.h>

#include "common/errors.hpp"

namespace dtwin {

namespace {

constexpr std::uint32_t kLocal = 0x04034b50, kCentral = 0x02014b50, kEndRecord = 0x06054b50;
constexpr std::uint16_t kDosDate = (0 << 9) | (1 << 5) | 1;  // 1980-01-01
constexpr std::uint16_t kZipVersion = 20;                    // 2.0: deflate, folders

void put16(std::string& o, std::uint32_t v) {
  o.push_back(static_cast<char>(v & 0xff));
  o.push_back(static_cast<char>((v >> 8) & 0xff));
}
void put32(std::string& o, std::uint32_t v) {
  put16(o, v & 0xffff);
  put16(o, v >> 16);
}

std::uint32_t crcOf(const std::string& d) {
  return static_cast<std::uint32_t>(
      crc32(0L, reinterpret_cast<const Bytef*>(d.data()), static_cast<uInt>(d.size())));
}

/// Raw deflate (no zlib header), as zip's method 8 holds it.
std::string deflateRaw(const std::string& in) {
  z_stream z{};
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw InputError("zip", "zlib could not start deflating");
  std::string out(deflateBound(&z, static_cast<uLong>(in.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw InputError("zip", "zlib could not deflate a member");
  return out;
}

std::string inflateRaw(const std::string& in, std::size_t size, const std::string& what) {
  std::string out(size, '\0');
  z_stream z{};
  if (inflateInit2(&z, -15) != Z_OK) throw InputError(what, "zlib could not start inflating");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = size == 0 ? Z_STREAM_END : inflate(&z, Z_FINISH);
  const std::size_t got = z.total_out;
  inflateEnd(&z);
  if (rc != Z_STREAM_END || got != size)
    throw InputError(what, "a deflated member does not inflate to its recorded size");
  return out;
}

void checkName(const std::string& n, std::set<std::string>& seen) {
  if (n.empty()) throw InputError("zip", "a member has an empty name");
  if (n.find('\\') != std::string::npos || n.front() == '/' || n.find("..") != std::string::npos)
    throw InputError("zip", "member name '" + n + "' must be relative, '/'-separated, without ..");
  if (!seen.insert(n).second) throw InputError("zip", "member '" + n + "' is given twice");
}

std::uint32_t get16(const std::string& b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8;
}
std::uint32_t get32(const std::string& b, std::size_t at) {
  return get16(b, at) | get16(b, at + 2) << 16;
}

}  // namespace

std::string zipArchive(const std::vector<ZipMember>& members) {
  std::string out, central;
  std::set<std::string> seen;
  for (const auto& m : members) {
    checkName(m.name, seen);
    if (m.data.size() >= 0xffffffffULL)
      throw InputError("zip", "member '" + m.name + "' is over 4 GB (no zip64)");
    const std::uint32_t crc = crcOf(m.data);
    std::string packed = m.data.empty() ? std::string() : deflateRaw(m.data);
    const bool deflated = !m.data.empty() && packed.size() < m.data.size();
    if (!deflated) packed = m.data;
    const auto offset = static_cast<std::uint32_t>(out.size());
    auto header = [&](std::string& o, bool central_record) {
      put32(o, central_record ? kCentral : kLocal);
      if (central_record) put16(o, (3 << 8) | kZipVersion);  // made by: Unix
      put16(o, kZipVersion);
      put16(o, 0x0800);  // UTF-8 names
      put16(o, deflated ? 8 : 0);
      put16(o, 0);  // time 00:00
      put16(o, kDosDate);
      put32(o, crc);
      put32(o, static_cast<std::uint32_t>(packed.size()));
      put32(o, static_cast<std::uint32_t>(m.data.size()));
      put16(o, static_cast<std::uint32_t>(m.name.size()));
      put16(o, 0);  // extra
      if (central_record) {
        put16(o, 0);  // comment
        put16(o, 0);  // disk
        put16(o, 0);  // internal attributes
        const bool folder = m.name.back() == '/';
        put32(o, (folder ? 040755U : 0100644U) << 16 | (folder ? 0x10U : 0U));
        put32(o, offset);
      }
      o += m.name;
    };
    header(out, false);
    out += packed;
    header(central, true);
  }
  const auto central_at = static_cast<std::uint32_t>(out.size());
  out += central;
  put32(out, kEndRecord);
  put16(out, 0);
  put16(out, 0);
  put16(out, static_cast<std::uint32_t>(members.size()));
  put16(out, static_cast<std::uint32_t>(members.size()));
  put32(out, static_cast<std::uint32_t>(central.size()));
  put32(out, central_at);
  put16(out, 0);
  return out;
}

std::vector<ZipMember> readZipArchive(const std::string& b, const std::string& what) {
  if (b.size() < 22) throw InputError(what, "too short for a zip archive");
  std::size_t end = b.size() - 22;
  while (get32(b, end) != kEndRecord) {
    if (end == 0 || b.size() - end > 22 + 0xffff)
      throw InputError(what, "no end-of-central-directory record: not a zip archive");
    --end;
  }
  const std::size_t count = get16(b, end + 10), cd = get32(b, end + 16);
  std::vector<ZipMember> out;
  std::size_t at = cd;
  for (std::size_t i = 0; i < count; ++i) {
    if (at + 46 > b.size() || get32(b, at) != kCentral)
      throw InputError(what, "a central directory record is damaged");
    const std::uint32_t method = get16(b, at + 10), crc = get32(b, at + 16);
    const std::size_t packed = get32(b, at + 20), size = get32(b, at + 24);
    const std::size_t nlen = get16(b, at + 28), xlen = get16(b, at + 30), clen = get16(b, at + 32);
    const std::size_t local = get32(b, at + 42);
    ZipMember m;
    m.name = b.substr(at + 46, nlen);
    at += 46 + nlen + xlen + clen;
    if (local + 30 > b.size() || get32(b, local) != kLocal)
      throw InputError(what, "member '" + m.name + "': damaged local header");
    const std::size_t data_at = local + 30 + get16(b, local + 26) + get16(b, local + 28);
    if (data_at + packed > b.size())
      throw InputError(what, "member '" + m.name + "' runs past the archive's end");
    const std::string raw = b.substr(data_at, packed);
    if (method == 0)
      m.data = raw;
    else if (method == 8)
      m.data = inflateRaw(raw, size, what + ": " + m.name);
    else
      throw InputError(what, "member '" + m.name + "': compression method " +
                                 std::to_string(method) + " (only stored and deflated are read)");
    if (m.data.size() != size || crcOf(m.data) != crc)
      throw InputError(what, "member '" + m.name + "': CRC-32 or size does not match");
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace dtwin
