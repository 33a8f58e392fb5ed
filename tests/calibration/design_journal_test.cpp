// Design journal: exact round trip, a process killed mid-line, refusing a foreign design,
// concurrent appends, a line changed on disk (its checksum), version 1 journals, and the atomic
// design table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <thread>

#include "calibration/design_journal.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::calib;

namespace {
std::string tempPath(const std::string& name) {
  const std::string p = ::testing::TempDir() + "/dtwin_calib_" + name;
  std::remove(p.c_str());
  return p;
}
std::string readFile(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
const double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST(DesignJournal, WriteAndReloadRoundTripsExactly) {
  const std::string path = tempPath("roundtrip.journal");
  const std::vector<std::vector<double>> thetas = {
      {0.1, 1.0 / 3.0, 180000.0}, {1e-300, -2.5e17, std::nextafter(1.0, 2.0)}, {5e-324, 7.0, 0.0}};
  const std::vector<double> sses = {12345.678901234567, kInf, 0.0};
  {
    DesignJournal j(path, 3, "study=abc;assembly=M1;design=2000@7");
    EXPECT_TRUE(j.resumed().empty());
    for (std::size_t k = 0; k < thetas.size(); ++k)
      j.append(static_cast<std::int64_t>(10 * k + 1), thetas[k], sses[k]);
  }
  const JournalContents c = readDesignJournal(path);
  EXPECT_EQ(c.dim, 3);
  EXPECT_EQ(c.fingerprint, "study=abc;assembly=M1;design=2000@7");
  EXPECT_FALSE(c.discarded_truncated_line);
  ASSERT_EQ(c.entries.size(), 3u);
  for (std::size_t k = 0; k < thetas.size(); ++k) {
    EXPECT_EQ(c.entries[k].index, static_cast<std::int64_t>(10 * k + 1));
    EXPECT_EQ(c.entries[k].theta, thetas[k]);  // bit-exact
    EXPECT_EQ(c.entries[k].sse, sses[k]);
  }
  EXPECT_NE(readFile(path).find(",inf,"),
            std::string::npos);  // +inf written as "inf" (then the checksum)

  // Reopening resumes the same entries and keeps appending.
  {
    DesignJournal j(path, 3, "study=abc;assembly=M1;design=2000@7");
    ASSERT_EQ(j.resumed().size(), 3u);
    EXPECT_EQ(j.resumed()[1].theta, thetas[1]);
    j.append(99, {1.0, 2.0, 3.0}, 4.0);
  }
  EXPECT_EQ(readDesignJournal(path).entries.size(), 4u);
}

TEST(DesignJournal, TruncatedLastLineIsDiscardedAndCutOff) {
  const std::string path = tempPath("truncated.journal");
  {
    DesignJournal j(path, 2, "fp");
    j.append(0, {1.5, 2.5}, 10.0);
    j.append(1, {3.5, 4.5}, 20.0);
  }
  // A process killed in the middle of writing "2,5.5,6.5,30\n".
  { std::ofstream(path, std::ios::app | std::ios::binary) << "2,5.5,6.5,3"; }
  const JournalContents c = readDesignJournal(path);
  EXPECT_TRUE(c.discarded_truncated_line);
  ASSERT_EQ(c.entries.size(), 2u);  // "2,5.5,6.5,3" would parse, but it has no '\n'
  {
    DesignJournal j(path, 2, "fp");
    EXPECT_TRUE(j.discardedTruncatedLine());
    ASSERT_EQ(j.resumed().size(), 2u);
    EXPECT_EQ(j.resumed()[1].sse, 20.0);
    j.append(2, {5.5, 6.5}, 30.0);
  }
  const JournalContents after = readDesignJournal(path);
  EXPECT_FALSE(after.discarded_truncated_line);
  ASSERT_EQ(after.entries.size(), 3u);
  EXPECT_EQ(after.entries[2].index, 2);
  EXPECT_EQ(after.entries[2].sse, 30.0);

  // Killed while writing the header: the file is started afresh.
  const std::string p2 = tempPath("header_cut.journal");
  { std::ofstream(p2, std::ios::binary) << "# dtwin design jou"; }
  {
    DesignJournal j(p2, 2, "fp");
    EXPECT_TRUE(j.resumed().empty());
    j.append(0, {1.0, 2.0}, 3.0);
  }
  EXPECT_EQ(readDesignJournal(p2).entries.size(), 1u);
}

TEST(DesignJournal, ForeignDesignIsRefused) {
  const std::string path = tempPath("foreign.journal");
  {
    DesignJournal j(path, 4, "hash-A");
    j.append(0, {1, 2, 3, 4}, 5);
  }
  try {
    DesignJournal j(path, 4, "hash-B");
    FAIL() << "no throw";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find("fingerprint 'hash-A' in the file, 'hash-B' expected"), std::string::npos)
        << m;
    EXPECT_NE(m.find("refusing to resume"), std::string::npos) << m;
  }
  try {
    DesignJournal j(path, 3, "hash-A");
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dim 4 in the file, 3 expected"), std::string::npos)
        << e.what();
  }
  // The refused journal is untouched.
  EXPECT_EQ(readDesignJournal(path).entries.size(), 1u);
}

TEST(DesignJournal, CorruptCompleteLineIsAnErrorWithLineNumber) {
  // A journal of version 1 (no checksums): a malformed complete line is an error naming it.
  const std::string path = tempPath("corrupt.journal");
  {
    std::ofstream(path, std::ios::binary)
        << "# dtwin design journal v1; dim=2; fingerprint=fp\n0,1,2,3\n1,2.0,abc,4\n";
  }
  try {
    readDesignJournal(path);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3: parameter 2 must be a finite number, got 'abc'"),
              std::string::npos)
        << e.what();
  }
  const std::string p2 = tempPath("notajournal.csv");
  { std::ofstream(p2) << "a,b,c\n1,2,3\n"; }
  EXPECT_THROW(DesignJournal(p2, 2, "fp"), InputError);
}

TEST(DesignJournal, VersionOneJournalsAreReadAndAppendedToInTheirVersion) {
  const std::string path = tempPath("v1.journal");
  {
    std::ofstream(path, std::ios::binary)
        << "# dtwin design journal v1; dim=2; fingerprint=fp\n0,1.5,2.5,10\n";
  }
  {
    DesignJournal j(path, 2, "fp");
    EXPECT_FALSE(j.setAside());
    ASSERT_EQ(j.resumed().size(), 1u);
    EXPECT_EQ(j.resumed()[0].theta, (std::vector<double>{1.5, 2.5}));
    j.append(1, {3.5, 4.5}, 20.0);
  }
  EXPECT_EQ(readFile(path),
            "# dtwin design journal v1; dim=2; fingerprint=fp\n0,1.5,2.5,10\n1,3.5,4.5,20\n");
  const JournalContents c = readDesignJournal(path);
  EXPECT_EQ(c.version, 1);
  ASSERT_EQ(c.entries.size(), 2u);
  EXPECT_EQ(c.entries[1].sse, 20.0);
}

TEST(DesignJournal, EveryLineCarriesTheChecksumOfItsText) {
  const std::string path = tempPath("checksum.journal");
  {
    DesignJournal j(path, 2, "fp");
    j.append(7, {1.25, -3.0}, 0.5);
  }
  const std::string text = readFile(path);
  const std::string header = "# dtwin design journal v2; dim=2; fingerprint=fp";
  const std::string line = "7,1.25,-3,0.5";
  // 32-bit FNV-1a, computed here from its definition.
  auto fnv = [](const std::string& s) {
    std::uint32_t h = 2166136261u;
    for (unsigned char c : s) h = (h ^ c) * 16777619u;
    char buf[9];
    std::snprintf(buf, sizeof buf, "%08x", static_cast<unsigned>(h));
    return std::string(buf);
  };
  EXPECT_EQ(text, header + "; check=" + fnv(header) + "\n" + line + "," + fnv(line) + "\n");
  EXPECT_EQ(fnv(""), "811c9dc5");   // the offset basis: FNV-1a of nothing
  EXPECT_EQ(fnv("a"), "e40c292c");  // the published test vector
}

TEST(DesignJournal, ALineChangedOnDiskIsDetectedAndTheJournalSetAside) {
  const std::string path = tempPath("changed.journal");
  std::remove((path + ".corrupt").c_str());
  {
    DesignJournal j(path, 2, "fp");
    for (int k = 0; k < 20; ++k) j.append(k, {1.0 + k, 2.0 * k}, 100.0 + k);
  }
  // One digit of line 17 (point 15: "15,16,30,115,<c>") changed in place: a well-formed line.
  std::string text = readFile(path);
  const std::size_t at = text.find("\n15,16,30,115,");
  ASSERT_NE(at, std::string::npos);
  text[at + 7] = '7';  // 30 -> 70
  { std::ofstream(path, std::ios::binary | std::ios::trunc) << text; }
  try {
    readDesignJournal(path);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": line 17: fails its checksum"), std::string::npos)
        << e.what();
  }
  {
    DesignJournal j(path, 2, "fp");
    EXPECT_TRUE(j.setAside());
    EXPECT_TRUE(j.resumed().empty());  // nothing of it is trusted
    j.append(0, {1.0, 0.0}, 100.0);
  }
  EXPECT_EQ(readFile(path + ".corrupt"), text);  // kept for a look, never read again
  const JournalContents c = readDesignJournal(path);
  ASSERT_EQ(c.entries.size(), 1u);
  EXPECT_EQ(c.entries[0].sse, 100.0);
  // A changed header (its fingerprint) fails its checksum too.
  std::string h = readFile(path);
  h[h.find("fingerprint=fp") + 12] = 'q';
  { std::ofstream(path, std::ios::binary | std::ios::trunc) << h; }
  DesignJournal again(path, 2, "fp");
  EXPECT_TRUE(again.setAside());
}

TEST(DesignJournal, ConcurrentAppendsKeepWholeLines) {
  const std::string path = tempPath("threads.journal");
  {
    DesignJournal j(path, 3, "fp", /*durable=*/false);
    std::vector<std::thread> pool;
    for (int t = 0; t < 4; ++t)
      pool.emplace_back([&j, t] {
        for (int i = 0; i < 250; ++i) {
          const int k = t * 250 + i;
          j.append(k, {k * 0.1, k * 1e5, -k / 3.0}, k * 7.0);
        }
      });
    for (auto& th : pool) th.join();
  }
  const JournalContents c = readDesignJournal(path);
  ASSERT_EQ(c.entries.size(), 1000u);
  std::set<std::int64_t> seen;
  for (const auto& e : c.entries) {
    const auto k = static_cast<double>(e.index);
    EXPECT_EQ(e.theta, (std::vector<double>{k * 0.1, k * 1e5, -k / 3.0}));
    EXPECT_EQ(e.sse, k * 7.0);
    seen.insert(e.index);
  }
  EXPECT_EQ(seen.size(), 1000u);
}

TEST(DesignJournal, AppendValidatesThePoint) {
  const std::string path = tempPath("validate.journal");
  DesignJournal j(path, 2, "fp");
  EXPECT_THROW(j.append(0, {1.0}, 1.0), InputError);
  EXPECT_THROW(j.append(-1, {1.0, 2.0}, 1.0), InputError);
  EXPECT_THROW(j.append(0, {1.0, kInf}, 1.0), InputError);
  EXPECT_THROW(DesignJournal(tempPath("bad.journal"), 2, "two\nlines"), InputError);
}

TEST(DesignTableCsv, WrittenAtomicallyAndReadsBack) {
  const std::string path = tempPath("design.csv");
  { std::ofstream(path) << "old content\n"; }
  Eigen::MatrixXd design(3, 2);
  design << 180000.0, 3000.0, 1.0 / 3.0, 0.1, 7e5, 6999.5;
  const std::vector<double> sse = {1.25, kInf, 1e-7};
  writeDesignTableCsv(path, {"tire_stiffness_N_per_m", "tire_damping_Ns_per_m"}, design, sse,
                      "sse_N2");
  const std::string text = readFile(path);
  EXPECT_EQ(text.substr(0, text.find('\n')), "tire_stiffness_N_per_m,tire_damping_Ns_per_m,sse_N2");
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(std::getline(in, line));
    double a, b;
    char c1, c2;
    std::string rest;
    std::istringstream ls(line);
    ls >> a >> c1 >> b >> c2 >> rest;
    EXPECT_EQ(a, design(i, 0));
    EXPECT_EQ(b, design(i, 1));
    if (i == 1) {
      EXPECT_EQ(rest, "inf");
    }
    EXPECT_EQ(std::stod(rest), sse[i]);
  }
  EXPECT_FALSE(std::getline(in, line));
  // No temporary file left behind.
  for (const auto& e :
       std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
    EXPECT_EQ(e.path().filename().string().find("dtwin_calib_design.csv.tmp"), std::string::npos);
  try {
    writeDesignTableCsv(path, {"a,b", "c"}, design, sse);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("column name 'a,b'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(readFile(path), text);  // a refused write leaves the old table intact
}
